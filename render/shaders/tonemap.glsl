// White balance, exposure, the tone curves and sRGB encoding (RENDERING.md section 9, HDR;
// docs/rendering.md "Tone curve, exposure and white balance"), shared by the resolve
// (tonemap.frag), the adaptive-supersampling edge mask (edge_mask.frag) and its accumulation,
// so a pixel is judged and averaged in the values it is shown in. The CPU twin, line for line,
// is render/src/tonemap_ref.c.
uniform float u_exposure; // 2^ev
uniform float u_white;    // L_white
uniform int u_mode;       // rd_tonemap: 0 photographic, 1 clamp, 2 neutral, 3 agx
uniform mat3 u_wb;        // white balance (rd_white_balance_matrix)

vec3 exposed(vec3 c)
{
    c = u_wb * c * u_exposure;
    c = vec3(isnan(c.r) ? 0.0 : c.r, isnan(c.g) ? 0.0 : c.g, isnan(c.b) ? 0.0 : c.b);
    return clamp(c, vec3(0.0), vec3(1e30));
}

// Khronos PBR Neutral (Khronos 3D Commerce, "PBR Neutral" tone mapper specification, 2024).
vec3 tone_neutral(vec3 c)
{
    const float start = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(c.r, min(c.g, c.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    c -= offset;
    float peak = max(c.r, max(c.g, c.b));
    if (peak >= start) {
        const float d = 1.0 - start;
        float new_peak = 1.0 - d * d / (peak + d - start);
        float g = 1.0 - 1.0 / (desaturation * (peak - new_peak) + 1.0);
        c = c * (new_peak / peak) * (1.0 - g) + new_peak * g;
    }
    return clamp(c, 0.0, 1.0);
}

// AgX (Sobotka), the minimal version of Wrensch ("Minimal AgX implementation", 2023): inset,
// log2 over [-12.47, 4.03] EV, the contrast sigmoid's polynomial fit, outset, 2.2 power back
// to linear (sRGB-encoded after).
vec3 tone_agx(vec3 c)
{
    const mat3 inset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051,
                            0.0784335999999992, 0.878468636469772, 0.0784336,
                            0.0792237451477643, 0.0791661274605434, 0.879142973793104);
    const mat3 outset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438,
                             -0.0980208811401368, 1.15190312990417, -0.0980434501171241,
                             -0.0990297440797205, -0.0989611768448433, 1.15107367264116);
    const float min_ev = -12.47393;
    const float max_ev = 4.026069;
    vec3 v = inset * c;
    vec3 e = vec3(v.r > 0.0 ? log2(v.r) : min_ev, v.g > 0.0 ? log2(v.g) : min_ev,
                  v.b > 0.0 ? log2(v.b) : min_ev);
    vec3 x = (clamp(e, min_ev, max_ev) - min_ev) / (max_ev - min_ev);
    vec3 x2 = x * x;
    vec3 x4 = x2 * x2;
    v = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 +
        0.1191 * x - 0.00232;
    v = outset * v;
    return pow(clamp(v, 0.0, 1.0), vec3(2.2));
}

// Reinhard, Stark, Shirley, Ferwerda 2002, eq. 4, applied to luminance so hue is kept.
vec3 tone_photographic(vec3 c)
{
    float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
    if (!(y > 0.0))
        return vec3(0.0);
    float ratio = (1.0 + y / (u_white * u_white)) / (1.0 + y);
    return clamp(c * ratio, 0.0, 1.0);
}

vec3 tonemap(vec3 c)
{
    c = exposed(c);
    if (u_mode == 1)
        return clamp(c, 0.0, 1.0);
    if (u_mode == 2)
        return tone_neutral(c);
    if (u_mode == 3)
        return tone_agx(c);
    return tone_photographic(c);
}

vec3 srgb_encode(vec3 x)
{
    vec3 lo = 12.92 * x;
    vec3 hi = 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), x));
}
