/* The speed/accuracy plot of `tessera sweep`: milliseconds per frame against PSNR, one point
 * per setting, the Pareto front joined (Cairo, PNG). */
#ifndef APP_SWEEP_PLOT_H
#define APP_SWEEP_PLOT_H

typedef struct app_sweep_point {
    const char *factor; /* which setting this point varies ("resolution", "blur", ...) */
    const char *label;  /* its value ("256", "box-mips", ...) */
    double ms;          /* mean milliseconds per frame */
    double psnr;        /* dB over the reflective pixels */
    int on_front;       /* 1 when no other point is both faster and more accurate */
} app_sweep_point;

/* Marks the Pareto front (minimal ms, maximal psnr) in points[].on_front. */
void app_sweep_mark_front(app_sweep_point *points, int count);

/* Writes the plot; returns 0, or -1 with a message in err. */
int app_sweep_plot(const char *path, const app_sweep_point *points, int count, const char *title,
                   char *err, int err_size);

#endif
