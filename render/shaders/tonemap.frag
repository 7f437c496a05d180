// Exposure, photographic tone map and sRGB encoding; resolves s x s supersamples per pixel.
// RENDERING.md section 9 (HDR). The CPU twin is rd_ref_tonemap in render/src/tonemap_ref.c.
// Compiled per variant (programs.c): SAMPLES (s, 1..4) and LINEAR_OUT (write the averaged
// exposed radiance instead of display values), so the loops unroll and nothing branches.
uniform sampler2D u_source; // radiance at s times the output size
uniform float u_exposure;   // 2^ev
uniform float u_white;      // L_white
uniform int u_mode;         // 0 photographic, 1 clamp

out vec4 frag_color;

// Reinhard, Stark, Shirley, Ferwerda 2002, eq. 4, applied to luminance so hue is kept.
vec3 tonemap(vec3 c)
{
    c = clamp(c * u_exposure, vec3(0.0), vec3(1e30));
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

void main()
{
    ivec2 base = ivec2(gl_FragCoord.xy) * SAMPLES;
    vec3 sum = vec3(0.0);
    for (int y = 0; y < SAMPLES; y++)
        for (int x = 0; x < SAMPLES; x++) {
            vec3 c = texelFetch(u_source, base + ivec2(x, y), 0).rgb;
#if LINEAR_OUT
            sum += clamp(c * u_exposure, vec3(0.0), vec3(1e30));
#else
            sum += tonemap(c);
#endif
        }
    vec3 avg = sum / float(SAMPLES * SAMPLES);
#if LINEAR_OUT
    frag_color = vec4(avg, 1.0);
#else
    frag_color = vec4(srgb_encode(avg), 1.0);
#endif
}
