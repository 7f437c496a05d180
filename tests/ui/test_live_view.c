/* The live view's schedule and running average (ui/src/live_view.h, live_accum.h), no GL:
 * the ladder climbs to the chosen preset with the passes its supersampling asks for, strips
 * keep to their budget and cover every row of every pass, a strip drawn with a probe
 * unfinished is drawn again, and the jittered average of a hard edge converges to its
 * coverage. */
#include "check.h"
#include "live_accum.h"
#include "live_view.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Runs a ladder to its end with strips costing ms_per_row each; returns the strips drawn. */
static int run_ladder(ui_live *l, int height, float ms_per_row, float budget, float *worst_ms,
                      int *rows_covered)
{
    int strips = 0;
    memset(rows_covered, 0, (size_t)height * sizeof *rows_covered);
    *worst_ms = 0;
    while (!ui_live_done(l) && strips < 100000) {
        int rows = ui_live_strip_rows(l, budget, height);
        float ms = (float)rows * ms_per_row;
        if (ms > *worst_ms)
            *worst_ms = ms;
        for (int r = l->row; r < l->row + rows; r++)
            rows_covered[r]++;
        ui_live_strip_done(l, rows, ms, height, 0);
        strips++;
    }
    return strips;
}

static void check_ladder(void)
{
    ui_live l;
    int covered[720];
    float worst;
    /* Interactive: eight passes of its own preset. */
    ui_live_begin(&l, 1, 2.0f);
    CHECK(l.step_count == 1 && l.steps[0].preset == 1 && l.steps[0].passes == 8);
    CHECK(ui_live_progress(&l) == 0);
    run_ladder(&l, 720, 2.0f, 50.0f, &worst, covered);
    CHECK(ui_live_done(&l) && ui_live_progress(&l) == 1);
    CHECK_MSG(worst <= 50.0f, "a strip cost %.1f ms", worst);
    int all8 = 1;
    for (int r = 0; r < 720; r++)
        all8 &= covered[r] == 8;
    CHECK_MSG(all8, "every row once a pass");

    /* Final: one interactive pass, then final's 2 x 2 as four offsets. */
    ui_live_begin(&l, 2, 2.0f);
    CHECK(l.step_count == 2 && l.steps[1].preset == 2 && l.steps[1].passes == 4);
    /* Print: final on the way, then 16 offsets of print. */
    ui_live_begin(&l, 3, 2.0f);
    CHECK(l.step_count == 3 && l.steps[2].preset == 3 && l.steps[2].passes == 16);
    CHECK(ui_live_moving_preset(3) == 1 && ui_live_moving_preset(0) == 0);

    /* A wrong first guess (10x too cheap) is over budget once, then learnt. */
    ui_live_begin(&l, 2, 0.2f);
    int rows = ui_live_strip_rows(&l, 50.0f, 720);
    ui_live_strip_done(&l, rows, (float)rows * 2.0f, 720, 0);
    CHECK(ui_live_strip_rows(&l, 50.0f, 720) * 2.0f <= 50.0f);

    /* While probes settle (the last strip waited for a capture) the strip is the thinnest: the
     * frame is the capture's; the next strip after them takes the budget again. */
    ui_live_begin(&l, 2, 1.0f);
    CHECK(ui_live_strip_rows(&l, 50.0f, 720) == 50);
    ui_live_strip_done(&l, 50, 50.0f, 720, 1);
    CHECK(ui_live_strip_rows(&l, 50.0f, 720) == UI_LIVE_MIN_ROWS);
    ui_live_strip_done(&l, UI_LIVE_MIN_ROWS, 4.0f, 720, 0);
    CHECK(ui_live_strip_rows(&l, 50.0f, 720) == 50);

    /* The first strip of a new step is thinner: its rows are guessed dearer. */
    ui_live_begin(&l, 2, 1.0f);
    CHECK(ui_live_strip_rows(&l, 50.0f, 100) == 50);
    ui_live_strip_done(&l, 50, 50.0f, 100, 0);
    CHECK(ui_live_strip_done(&l, 50, 50.0f, 100, 0) == 1);
    CHECK(ui_live_strip_rows(&l, 50.0f, 100) == (int)(50.0f / UI_LIVE_STEP_COST));

    /* A step change is reported once per step; a busy strip does not advance. */
    ui_live_begin(&l, 2, 1.0f);
    int changes = 0;
    while (!ui_live_done(&l)) {
        int r = ui_live_strip_rows(&l, 1000.0f, 100);
        int row = l.row, pass = l.pass, step = l.step;
        CHECK(ui_live_strip_done(&l, r, 1.0f, 100, 1) == 0);
        CHECK(l.row == row && l.pass == pass && l.step == step && l.settling);
        changes += ui_live_strip_done(&l, r, 1.0f, 100, 0);
        CHECK(!l.settling);
    }
    CHECK(changes == 1);
}

/* A hard vertical edge at x = 0.3 of each pixel: the pixel's true value is its coverage. */
static unsigned char edge_sample(float x_in_pixel)
{
    return x_in_pixel < 0.3f ? 255 : 0;
}

static double srgb_to_linear(double c)
{
    c /= 255.0;
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static void check_accumulation(void)
{
    float j[2];
    ui_jitter(0, j);
    CHECK(j[0] == 0 && j[1] == 0);
    int in_range = 1;
    double mean[2] = {0, 0};
    for (int i = 1; i <= 64; i++) {
        ui_jitter(i, j);
        in_range &= fabsf(j[0]) < 0.5f && fabsf(j[1]) < 0.5f;
        mean[0] += j[0] / 64.0;
        mean[1] += j[1] / 64.0;
    }
    CHECK(in_range);
    CHECK_MSG(fabs(mean[0]) < 0.03 && fabs(mean[1]) < 0.03, "mean offset (%g, %g)", mean[0],
              mean[1]);

    ui_accum a = {0};
    CHECK(ui_accum_resize(&a, 4, 2) == 0);
    unsigned char strip[4 * 2 * 4];
    double first = -1, err = 0;
    for (int pass = 0; pass < 32; pass++) {
        ui_jitter(pass, j);
        /* Sampled at the pixel centre shifted by the jitter, as the renderer would. */
        for (int i = 0; i < 8; i++) {
            unsigned char v = edge_sample(0.5f + j[0]);
            strip[i * 4 + 0] = strip[i * 4 + 1] = strip[i * 4 + 2] = v;
            strip[i * 4 + 3] = 255;
        }
        ui_accum_add(&a, 0, 0, 4, 1, strip);
        ui_accum_add(&a, 0, 1, 4, 1, strip + 16);
        err = fabs(srgb_to_linear(a.image[0]) - 0.3);
        if (pass == 0)
            first = err;
    }
    CHECK_MSG(first > 0.25 && err < 0.03, "coverage error %.3f after one pass, %.3f after 32",
              first, err);
    CHECK(a.count[7] == 32);
    /* Restart keeps the picture until new samples arrive. */
    unsigned char before = a.image[0];
    ui_accum_restart(&a);
    CHECK(a.image[0] == before && a.count[0] == 0);
    /* The start image is the small render scaled up: a 1 x 1 grey fills every pixel. */
    unsigned char grey[4] = {128, 128, 128, 255};
    ui_accum_start_from(&a, grey, 1, 1);
    CHECK(a.image[0] == 128 && a.image[4 * 7] == 128);
    /* Out-of-range strips are ignored. */
    ui_accum_add(&a, 2, 1, 4, 1, strip);
    CHECK(a.count[6] == 0);
    ui_accum_free(&a);
    CHECK(a.image == NULL);
}

/* Final's and print's steps from the background render (still_render.h): the window's strips
 * draw the interactive pass alone, the background steps come whole, a background picture that
 * arrives early skips what is left of the steps before it, and the progress counts a background
 * step by its render's fraction. */
static void check_background_ladder(void)
{
    ui_live l;
    int covered[100];
    float worst;
    ui_live_begin_background(&l, 1, 1.0f); /* interactive: nothing in the background */
    CHECK(l.step_count == 1 && ui_live_next_background(&l) < 0 && !ui_live_on_background(&l));

    ui_live_begin_background(&l, 2, 1.0f);
    CHECK(l.step_count == 2 && !l.steps[0].background && l.steps[1].background);
    CHECK(ui_live_next_background(&l) == 1 && !ui_live_on_background(&l));
    /* The interactive pass in strips; the ladder then waits on the background step. */
    int strips = 0;
    while (!ui_live_on_background(&l) && strips++ < 1000) {
        int rows = ui_live_strip_rows(&l, 20.0f, 100);
        ui_live_strip_done(&l, rows, (float)rows, 100, 0);
    }
    CHECK(ui_live_on_background(&l) && !ui_live_done(&l) && l.step == 1);
    CHECK_MSG(fabsf(ui_live_progress(&l) - 0.2f) < 1e-6f, "progress %.3f", ui_live_progress(&l));
    l.background_fraction = 0.5f; /* (1 pass + half of final's 4) of 5 */
    CHECK_MSG(fabsf(ui_live_progress(&l) - 0.6f) < 1e-6f, "progress %.3f", ui_live_progress(&l));
    l.background_fraction = 7.0f; /* clamped */
    CHECK(ui_live_progress(&l) <= 1.0f);
    CHECK(ui_live_background_done(&l, 1) == 0 && ui_live_done(&l) && ui_live_progress(&l) == 1);

    /* Print: final's picture arrives before the interactive pass is through. */
    ui_live_begin_background(&l, 3, 1.0f);
    CHECK(l.step_count == 3 && l.steps[1].background && l.steps[2].background);
    ui_live_strip_done(&l, 10, 10.0f, 100, 0);
    CHECK(l.step == 0 && l.row == 10);
    CHECK(ui_live_background_done(&l, 1) == 1);
    CHECK(l.step == 2 && l.row == 0 && l.pass == 0 && ui_live_on_background(&l));
    CHECK(ui_live_next_background(&l) == 2);
    /* A step that is not in the background, or one already passed, is no picture's. */
    CHECK(ui_live_background_done(&l, 0) == 1 && l.step == 2);
    CHECK(ui_live_background_done(&l, 2) == 0 && ui_live_done(&l));

    /* The window's own climb (a failed background render turns the steps back): strips again. */
    ui_live_begin_background(&l, 2, 1.0f);
    l.steps[1].background = 0;
    run_ladder(&l, 100, 1.0f, 20.0f, &worst, covered);
    CHECK(ui_live_done(&l));
    int all4 = 1;
    for (int r = 0; r < 100; r++)
        all4 &= covered[r] == 5; /* one interactive pass and final's four */
    CHECK_MSG(all4, "every row once a pass of both steps");
}

int main(void)
{
    check_ladder();
    check_background_ladder();
    check_accumulation();
    return check_report("ui_live_view");
}
