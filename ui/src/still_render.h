/* The still view's dearer pictures rendered by another process (docs/ui.md, "The live
 * view"): final and print quality need shadow maps, probes, an exposure render and, at print,
 * the self-reflections' hierarchies, each of them one job of 100 ms to seconds on llvmpipe. The
 * window writes the document into a folder of its own and keeps `tessera render --serve` running
 * on it, asking it for each still view; so those jobs run beside the window's frames instead of
 * inside one, the renderer keeps its probes and shadow maps from one still view to the next
 * (they do not depend on the view), and the picture is the CLI's render of the same view. The
 * server is started again when the document or its light changes. No GL here. */
#ifndef UI_STILL_RENDER_H
#define UI_STILL_RENDER_H

#include "app/project/project.h"

#include <stddef.h>
#include <stdint.h>

typedef struct ui_still_render {
    int pid;     /* the server, 0 for none */
    int to_fd;   /* its standard input: the requests */
    int from_fd; /* its standard output: the answers (non-blocking) */
    int bake;    /* its document is rendered with the baked light */
    int queued;  /* requests sent and not yet answered */
    int discard; /* of them, the first ones: asked for views no longer shown */
    int paused;  /* the server is stopped (SIGSTOP) while the view moves */
    void (*wake)(void);
    int served;        /* requests this server has answered */
    int preset;        /* the request's quality preset (0 draft .. 3 print) */
    int width, height; /* its picture's size */
    int warm;          /* 1: the request came to a server that had answered one already */
    double started;    /* the request's start, seconds (CLOCK_MONOTONIC) */
    char folder[512];  /* the document's copy and the pictures; removed with the server */
    char answer[1024]; /* the answer line read so far */
    size_t answer_len;
    /* What the last request of each preset took, seconds a megapixel, to a server starting
     * (the scene's set-up in it) and to one running (0: none yet): the progress shown. */
    double seconds_per_mpx[4][2];
} ui_still_render;

/* Asks for `project` seen from eye towards target (mm, vertical field of view fov_deg) at the
 * quality named `quality` (index preset), width x height pixels; `bake` 0 renders without the
 * baked light. A running server with the same document and light takes the request; otherwise
 * one is started. `wake`, when not NULL, is called from another thread when the answer comes
 * (the window then polls at once instead of at its idle wait's timeout). 0 ok, else 1 with err. */
int ui_still_render_start(ui_still_render *s, const app_project *project, const double eye[3],
                          const double target[3], double fov_deg, int preset, const char *quality,
                          int width, int height, int bake, void (*wake)(void), char *err,
                          size_t err_size);
/* 0: the request is under way (or there is none); 1: done, its picture (width x height RGBA8,
 * sRGB) written into rgba; -1: failed, err says why (the server's last words). */
int ui_still_render_poll(ui_still_render *s, uint8_t *rgba, char *err, size_t err_size);
/* 1 while a request for the view shown is under way. */
int ui_still_render_busy(const ui_still_render *s);
/* How far the request under way is, 0..0.95: its time over the last one's at its preset;
 * 0 when nothing is known yet. */
float ui_still_render_fraction(const ui_still_render *s);
/* Seconds since the request under way started. */
double ui_still_render_elapsed(const ui_still_render *s);
/* The view moved: a request under way is of no use. A server that has answered before is
 * stopped (its render cannot be cut short, and at print it takes seconds); one still on its
 * first request, which is mostly the scene's set-up that the next view needs too, is paused
 * (SIGSTOP, so that the moving frames keep the cores) and its answer discarded; an idle server
 * stays, with its scene. */
void ui_still_render_cancel(ui_still_render *s);
/* Stops the server and removes its folder. */
void ui_still_render_stop(ui_still_render *s);

#endif
