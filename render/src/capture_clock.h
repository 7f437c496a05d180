/* A frame's probe captures kept within a time (rd_scene_set_capture_time): before each face or
 * blur, the time already spent and the step's predicted cost must fit; the first step of a
 * frame always goes, so captures progress. A face's cost is predicted from its texels and the
 * cost of the faces measured so far (each waited for with glFinish while the clock runs). */
#ifndef RENDER_CAPTURE_CLOCK_H
#define RENDER_CAPTURE_CLOCK_H

#include "scene_internal.h"

typedef struct rd_capture_clock {
    double start_ms;
    int steps; /* faces and blurs done this frame */
} rd_capture_clock;

void rd_capture_clock_start(rd_capture_clock *c);
/* 1 when `faces` faces of a probe of `size` texels (a blur counts SPLIT_BLUR_FACES) fit. */
int rd_capture_clock_allows(const rd_capture_clock *c, const rd_scene *s, int size, double faces);
/* The clock's reading to pass to rd_capture_clock_done, taken before a step. */
double rd_capture_clock_now(void);
/* A step done: with the clock on, waits for it and learns a face's cost from a face. */
void rd_capture_clock_done(rd_capture_clock *c, rd_scene *s, int face_size, double started_ms);

#endif
