/* The live view's schedule. See live_view.h. */
#include "live_view.h"

#include <string.h>

enum { DRAFT = 0, INTERACTIVE = 1, FINAL = 2, PRINT = 3 };

int ui_live_moving_preset(int chosen)
{
    return chosen == DRAFT ? DRAFT : INTERACTIVE;
}

void ui_live_begin(ui_live *l, int chosen, float ms_per_row)
{
    memset(l, 0, sizeof *l);
    l->ms_per_row = ms_per_row > 0 ? ms_per_row : 1.0f;
    /* Passes per step: a still at the live presets averages 8 offsets (sharper than 2 x 2 at
     * no cost while the user looks); final's 2 x 2 and print's 4 x 4 supersampling become 4
     * and 16 offsets. Above interactive, one interactive pass first: a sharp picture at once,
     * before the dearer settings' first pass. */
    if (chosen <= INTERACTIVE) {
        l->steps[l->step_count++] = (ui_live_step){chosen < 0 ? INTERACTIVE : chosen, 8, 0};
        return;
    }
    l->steps[l->step_count++] = (ui_live_step){INTERACTIVE, 1, 0};
    l->steps[l->step_count++] = (ui_live_step){FINAL, 4, 0};
    if (chosen >= PRINT)
        l->steps[l->step_count++] = (ui_live_step){PRINT, 16, 0};
}

void ui_live_begin_background(ui_live *l, int chosen, float ms_per_row)
{
    ui_live_begin(l, chosen, ms_per_row);
    for (int i = 0; i < l->step_count; i++)
        l->steps[i].background = l->steps[i].preset >= FINAL;
}

int ui_live_next_background(const ui_live *l)
{
    for (int i = l->step; i < l->step_count; i++)
        if (l->steps[i].background)
            return i;
    return -1;
}

int ui_live_on_background(const ui_live *l)
{
    return !ui_live_done(l) && l->steps[l->step].background;
}

int ui_live_background_done(ui_live *l, int index)
{
    if (index < l->step || index >= l->step_count || !l->steps[index].background)
        return !ui_live_done(l);
    l->step = index + 1;
    l->pass = l->row = l->settling = 0;
    l->background_fraction = 0.0f;
    return !ui_live_done(l);
}

int ui_live_strip_rows(const ui_live *l, float budget_ms, int height)
{
    int rows = (int)(budget_ms / (l->ms_per_row > 1e-3f ? l->ms_per_row : 1e-3f));
    int left = height - l->row;
    /* While probes are captured a probe a frame, the strip is most likely drawn again: the
     * fewest rows leave the frame to the capture. */
    if (rows < UI_LIVE_MIN_ROWS || l->settling)
        rows = UI_LIVE_MIN_ROWS;
    return rows > left ? left : rows;
}

int ui_live_strip_done(ui_live *l, int rows, float ms, int height, int probes_busy)
{
    if (ui_live_done(l))
        return 0;
    l->settling = probes_busy;
    if (probes_busy)
        return 0; /* drawn with a probe unfinished: the same strip again, not averaged */
    if (rows > 0 && ms > 0) {
        /* Smoothed, but quick to learn a dearer step's cost (its first strip may be far over). */
        float m = ms / (float)rows;
        l->ms_per_row = m > l->ms_per_row ? m : l->ms_per_row + 0.3f * (m - l->ms_per_row);
    }
    l->row += rows;
    if (l->row < height)
        return 0;
    l->row = 0;
    if (++l->pass < l->steps[l->step].passes)
        return 0;
    l->pass = 0;
    l->step++;
    /* A dearer preset's rows cost more (soft shadows, planar mirrors; print's traces): its
     * first strip starts from a guess above the last step's, and learns from there. */
    l->ms_per_row *= UI_LIVE_STEP_COST;
    return !ui_live_done(l);
}

int ui_live_done(const ui_live *l)
{
    return l->step >= l->step_count;
}

float ui_live_progress(const ui_live *l)
{
    int all = 0, done = 0;
    for (int i = 0; i < l->step_count; i++) {
        all += l->steps[i].passes;
        if (i < l->step)
            done += l->steps[i].passes;
    }
    if (l->step < l->step_count) {
        const ui_live_step *s = &l->steps[l->step];
        float f = l->background_fraction < 0.0f   ? 0.0f
                  : l->background_fraction > 1.0f ? 1.0f
                                                  : l->background_fraction;
        if (!s->background)
            return (float)(done + l->pass) / (float)all;
        return ((float)done + f * (float)s->passes) / (float)all;
    }
    return all > 0 ? (float)done / (float)all : 1.0f;
}
