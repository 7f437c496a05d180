// Auto exposure, the measurement (exposure_meter.c): log(delta + L) of the white-balanced
// radiance at one sample of the main pass per texel of a small grid (Reinhard et al. 2002,
// eq. 1; summed on the CPU). Exposure is left out: it is what is being chosen.
uniform sampler2D u_source; // the main pass's radiance
uniform ivec2 u_samples;    // the grid's size

out vec4 frag_log_luminance;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy * vec2(textureSize(u_source, 0)) / vec2(u_samples));
    vec3 c = u_wb * texelFetch(u_source, p, 0).rgb;
    float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
    y = isnan(y) ? 0.0 : clamp(y, 0.0, 1e30);
    frag_log_luminance = vec4(log(1e-4 + y), 0.0, 0.0, 1.0);
}
