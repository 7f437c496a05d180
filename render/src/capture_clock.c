/* The time a frame's probe captures may take (capture_clock.h). */
#include "capture_clock.h"

#include "gl_funcs.h"

#include <time.h>

/* A face's cost before one was measured: a 256-texel face of a furnished bathroom takes
 * 16-24 ms on llvmpipe with two threads (TESSERA_PHASES=1, "probe captures"). */
#define DEFAULT_MS_PER_UNIT 300.0
/* What every face costs whatever its size (the scene's vertices, the draws), as texels: about
 * a 64-texel face's raster. */
#define FACE_OVERHEAD_TEXELS 4096.0

static double face_units(int size)
{
    return ((double)size * (double)size + FACE_OVERHEAD_TEXELS) * 1e-6;
}

double rd_capture_clock_now(void)
{
    struct timespec t;
    timespec_get(&t, TIME_UTC);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

void rd_capture_clock_start(rd_capture_clock *c)
{
    c->start_ms = rd_capture_clock_now();
    c->steps = 0;
}

int rd_capture_clock_allows(const rd_capture_clock *c, const rd_scene *s, int size, double faces)
{
    if (!(s->capture_ms > 0.0f) || c->steps == 0)
        return 1;
    double per = s->capture_ms_per_unit > 0.0f ? s->capture_ms_per_unit : DEFAULT_MS_PER_UNIT;
    double spent = rd_capture_clock_now() - c->start_ms;
    return spent + faces * face_units(size) * per <= (double)s->capture_ms;
}

void rd_capture_clock_done(rd_capture_clock *c, rd_scene *s, int face_size, double started_ms)
{
    c->steps++;
    if (!(s->capture_ms > 0.0f) || face_size <= 0)
        return;
    glFinish(); /* llvmpipe draws when flushed: the face's cost is known once it is done */
    double per = (rd_capture_clock_now() - started_ms) / face_units(face_size);
    float *learnt = &s->capture_ms_per_unit;
    /* Quick to learn a dearer cost, slow to trust a cheaper one: a face that sees little is
     * no promise for the next. */
    *learnt =
        *learnt <= 0.0f || per > *learnt ? (float)per : *learnt + 0.3f * ((float)per - *learnt);
}
