/* Temporal supersampling of the planner's still view: renders at sub-pixel offsets of the
 * projection (rd_view.jitter), each averaged into a full-resolution image as it arrives, in
 * strips, so a still view sharpens frame by frame without one long frame. Pure C, no GL:
 * tested in tests/ui. */
#ifndef UI_LIVE_ACCUM_H
#define UI_LIVE_ACCUM_H

#include <stdint.h>

typedef struct ui_accum {
    int width, height;
    float *sum;      /* 3 per pixel: the running sum of tone-mapped linear colour */
    uint16_t *count; /* samples summed per pixel */
    uint8_t *image;  /* RGBA8, top row first: what the view shows (base where count is 0) */
} ui_accum;

/* Sizes the image to width x height (keeping nothing); 0 ok, 1 out of memory. */
int ui_accum_resize(ui_accum *a, int width, int height);
void ui_accum_free(ui_accum *a);
/* Shows a smaller render (w x h RGBA8, top row first) scaled up bilinearly until samples
 * arrive, and forgets every sample: the moving view's last frame becomes the still's start. */
void ui_accum_start_from(ui_accum *a, const uint8_t *rgba, int w, int h);
/* Forgets the samples but keeps showing the image as it is, until new samples replace it
 * (the settings changed: older samples would mix two different pictures). */
void ui_accum_restart(ui_accum *a);
/* Adds a w x h strip rendered at (x, y) of the full image (RGBA8 sRGB, top row first) to the
 * running average, and updates those pixels of the image. */
void ui_accum_add(ui_accum *a, int x, int y, int w, int h, const uint8_t *rgba);

/* The projection offset of pass `index`, in pixels within (-0.5, 0.5): pass 0 is the pixel
 * centre, then the Halton (2, 3) sequence, which covers the pixel evenly at any count
 * (Halton 1964; the usual temporal antialiasing pattern). */
void ui_jitter(int index, float out[2]);

#endif
