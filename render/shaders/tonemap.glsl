// Exposure, the photographic tone map and sRGB encoding (RENDERING.md section 9, HDR), shared
// by the resolve (tonemap.frag), the adaptive-supersampling edge mask (edge_mask.frag) and its
// accumulation (accumulate.frag), so a pixel is judged and averaged in the values it is shown
// in. The CPU twin is rd_ref_tonemap in render/src/tonemap_ref.c.
uniform float u_exposure; // 2^ev
uniform float u_white;    // L_white
uniform int u_mode;       // 0 photographic, 1 clamp

vec3 exposed(vec3 c)
{
    return clamp(c * u_exposure, vec3(0.0), vec3(1e30));
}

// Reinhard, Stark, Shirley, Ferwerda 2002, eq. 4, applied to luminance so hue is kept.
vec3 tonemap(vec3 c)
{
    c = exposed(c);
    if (u_mode == 1)
        return clamp(c, 0.0, 1.0);
    float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
    if (!(y > 0.0))
        return vec3(0.0);
    float ratio = (1.0 + y / (u_white * u_white)) / (1.0 + y);
    return clamp(c * ratio, 0.0, 1.0);
}

vec3 srgb_encode(vec3 x)
{
    vec3 lo = 12.92 * x;
    vec3 hi = 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), x));
}
