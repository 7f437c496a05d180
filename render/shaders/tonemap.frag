// Exposure, photographic tone map and sRGB encoding; resolves s x s supersamples per pixel.
// RENDERING.md section 9 (HDR). The CPU twin is rd_ref_tonemap in render/src/tonemap_ref.c.
uniform sampler2D u_source; // radiance at s times the output size
uniform int u_samples;      // s
uniform float u_exposure;   // 2^ev
uniform float u_white;      // L_white
uniform int u_mode;         // 0 photographic, 1 clamp
uniform int u_linear_out;   // 1: write the averaged exposed radiance instead

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
    ivec2 base = ivec2(gl_FragCoord.xy) * u_samples;
    vec3 sum = vec3(0.0);
    for (int y = 0; y < u_samples; y++)
        for (int x = 0; x < u_samples; x++) {
            vec3 c = texelFetch(u_source, base + ivec2(x, y), 0).rgb;
            sum += u_linear_out == 1 ? clamp(c * u_exposure, vec3(0.0), vec3(1e30)) : tonemap(c);
        }
    vec3 avg = sum / float(u_samples * u_samples);
    frag_color = u_linear_out == 1 ? vec4(avg, 1.0) : vec4(srgb_encode(avg), 1.0);
}
