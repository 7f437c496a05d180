// Adaptive supersampling, step 2 (renderer_adaptive.c; Whitted 1980, "An improved
// illumination model for shaded display", section 4: sample once per pixel, subdivide where
// neighbouring samples differ). A pixel is refined when any of its eight neighbours differs
// from it by more than u_threshold in a display (sRGB-encoded) channel: object edges, tile
// joints, shadow penumbrae and highlights all show as such steps, while on a smooth surface
// the samples of a pixel agree with its centre. Writes 1 for a pixel to refine, else 0.
uniform sampler2D u_source; // the once-per-pixel radiance
uniform float u_threshold;  // in display units, 0..1

out vec4 frag_mask;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(u_source, 0) - 1;
    vec3 centre = srgb_encode(tonemap(texelFetch(u_source, p, 0).rgb));
    float step_max = 0.0;
    for (int y = -1; y <= 1; y++)
        for (int x = -1; x <= 1; x++) {
            vec3 c = texelFetch(u_source, clamp(p + ivec2(x, y), ivec2(0), last), 0).rgb;
            vec3 d = abs(srgb_encode(tonemap(c)) - centre);
            step_max = max(step_max, max(d.r, max(d.g, d.b)));
        }
    frag_mask = vec4(step_max > u_threshold ? 1.0 : 0.0);
}
