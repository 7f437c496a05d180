#ifndef RENDER_PREFILTER_H
#define RENDER_PREFILTER_H

#include "render_internal.h"

/* Fills mip `level` of the cube map `dest` (dest_size at level 0, `levels` levels) with the
 * convolution of `source` by the normalised Phong lobe of that level's exponent
 * (RENDERING.md section 5), by importance sampling on the GPU; level 0 is a plain copy. */
rd_result rd_prefilter_level(rd_context *ctx, unsigned source, int source_size, unsigned dest,
                             int dest_size, int level, int levels, float hdr_clamp);

/* The blur chain's levels are matched to their resolution (rd_ref_level_exponent, the CPU
 * twin): level k >= 1 of a probe of `size` texels holds the Phong lobe whose half-width spans
 * RD_LOBE_TEXELS texels of that level; level 0 is the capture (the mirror). */
#define RD_LOBE_TEXELS 2.0f
float rd_level_exponent(int level, int size);
/* The (fractional) level whose lobe is glossiness g's, n(g) = 2^(13 g): 0 for g >= 1. */
float rd_lobe_level(float glossiness, int size, int levels);

#endif
