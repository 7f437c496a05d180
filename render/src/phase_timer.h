/* Where a render's time goes (to find what to speed up): with TESSERA_PHASES=1 in the
 * environment, the renderer waits for the GPU (glFinish) at the borders of its phases and adds
 * each phase's wall time to a named total; rd_render_tiled prints the totals to stderr. Without
 * the variable every call is a no-op and nothing waits. */
#ifndef RENDER_PHASE_TIMER_H
#define RENDER_PHASE_TIMER_H

/* 1 when TESSERA_PHASES is set to something other than 0 (read once). */
int rd_phase_enabled(void);
/* Waits for the GPU and adds the time since the previous mark to phase `name` (a literal). */
void rd_phase_mark(const char *name);
/* Starts the clock without charging anything (the previous mark's time is dropped). */
void rd_phase_restart(void);
/* Prints the totals ("phases: name 1234 ms, ...") to stderr and clears them. */
void rd_phase_report(const char *title);

#endif
