#ifndef RENDER_PREFILTER_H
#define RENDER_PREFILTER_H

#include "render_internal.h"

/* Fills mip `level` of the cube map `dest` (dest_size at level 0, `levels` levels) with the
 * convolution of `source` by the normalised Phong lobe of that level's exponent
 * (RENDERING.md section 5), by importance sampling on the GPU; level 0 is a plain copy. */
rd_result rd_prefilter_level(rd_context *ctx, unsigned source, int source_size, unsigned dest,
                             int dest_size, int level, int levels, float hdr_clamp);

#endif
