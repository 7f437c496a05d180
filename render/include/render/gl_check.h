/* Counting OpenGL errors in a context that is not the renderer's own (the planner window's,
 * where Dear ImGui's backend draws too): KHR_debug's callback (GL 4.3 core, or the KHR_debug
 * extension) counts every error at the call that made it, even one the renderer's own checks
 * drain with glGetError afterwards; without KHR_debug, glGetError is polled once a frame.
 * The window's soak runs with it (TESSERA_GL_CHECK=1, docs/ui.md). One context per process:
 * the count is global, as the debug callback is. */
#ifndef RENDER_GL_CHECK_H
#define RENDER_GL_CHECK_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rd_gl_check_mode {
    RD_GL_CHECK_OFF = 0,      /* not started, or the context has no GL */
    RD_GL_CHECK_CALLBACK = 1, /* KHR_debug: every error counted where it happened */
    RD_GL_CHECK_POLL = 2      /* glGetError at each rd_gl_check_poll */
} rd_gl_check_mode;

/* Starts counting in the current context through its loader. prefer_poll = 1 skips KHR_debug
 * (tests of the fallback). Returns the mode in effect. */
rd_gl_check_mode rd_gl_check_begin(void *(*get_proc_address)(const char *name), int prefer_poll);
/* Once a frame, after the frame's GL work: takes the pending error flags (counted in POLL mode;
 * in CALLBACK mode the callback has counted them already). */
void rd_gl_check_poll(void);
/* Errors counted since rd_gl_check_begin. The first few are printed to stderr as they come
 * ("tessera: GL error: ..."). */
unsigned long rd_gl_check_errors(void);
/* Stops counting (the callback is removed; the context must still be current). */
void rd_gl_check_end(void);

#ifdef __cplusplus
}
#endif
#endif
