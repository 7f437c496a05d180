// Resolves a render into output pixels: s x s supersamples per pixel averaged after the tone
// map, or (ADAPTIVE) the pixel's one centre sample except where the edge mask had its s x s
// samples rendered (renderer_adaptive.c), which are averaged as in the plain resolve.
// Compiled per variant (programs.c): SAMPLES (s, 1..4), LINEAR_OUT (write the averaged
// exposed radiance instead of display values) and ADAPTIVE, so the loops unroll and nothing
// branches on a uniform.
uniform sampler2D u_source; // radiance at s times the output size (ADAPTIVE: at output size)
#if ADAPTIVE
// The refined pixels' s x s samples; alpha is 1 where the refinement drew (only marked pixels
// are drawn), 0 where it cleared.
uniform sampler2D u_refined;
#endif

out vec4 frag_color;

vec3 display_or_linear(vec3 c)
{
#if LINEAR_OUT
    return exposed(c);
#else
    return tonemap(c);
#endif
}

void main()
{
    ivec2 base = ivec2(gl_FragCoord.xy) * SAMPLES;
    vec3 sum = vec3(0.0);
    float drawn = 0.0;
    for (int y = 0; y < SAMPLES; y++)
        for (int x = 0; x < SAMPLES; x++) {
#if ADAPTIVE
            vec4 c = texelFetch(u_refined, base + ivec2(x, y), 0);
            drawn = max(drawn, c.a);
#else
            vec4 c = texelFetch(u_source, base + ivec2(x, y), 0);
#endif
            sum += display_or_linear(c.rgb);
        }
    vec3 avg = sum / float(SAMPLES * SAMPLES);
#if ADAPTIVE
    // A pixel none of whose samples was drawn was not refined (or shows only the background,
    // black in both): its centre sample.
    if (!(drawn > 0.5))
        avg = display_or_linear(texelFetch(u_source, ivec2(gl_FragCoord.xy), 0).rgb);
#endif
#if LINEAR_OUT
    frag_color = vec4(avg, 1.0);
#else
    frag_color = vec4(srgb_encode(avg), 1.0);
#endif
}
