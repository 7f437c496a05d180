// Adaptive supersampling, step 2b (renderer_adaptive.c): drawn over the s x s sample grid with
// the stencil set to 1 where it passes, it keeps the samples of the pixels the edge mask
// (edge_mask.frag) marked, so the refinement pass shades those alone.
uniform sampler2D u_source; // the edge mask, one texel a pixel
uniform int u_samples;      // s

void main()
{
    if (texelFetch(u_source, ivec2(gl_FragCoord.xy) / u_samples, 0).r < 0.5)
        discard;
}
