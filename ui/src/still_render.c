/* The still view's background renders. See still_render.h. */
#include "still_render.h"

#include "render/image_io.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

/* Below the window, so that its frames (the interactive pass, the panels) come first; the
 * server has the cores to itself once the window waits for input. */
#define STILL_NICENESS 4

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static void folder_path(const ui_still_render *s, const char *name, char *out, size_t size)
{
    snprintf(out, size, "%s/%s", s->folder, name);
}

/* The folder and what is in it: the copies of the document (and the .bak a save keeps), the
 * picture, the server's log. Nothing else writes there. */
static void remove_folder(ui_still_render *s)
{
    if (!s->folder[0])
        return;
    DIR *d = opendir(s->folder);
    struct dirent *e;
    char path[sizeof s->folder + 300];
    while (d && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            snprintf(path, sizeof path, "%s/%s", s->folder, e->d_name);
            unlink(path);
        }
    if (d)
        closedir(d);
    rmdir(s->folder);
    s->folder[0] = 0;
}

static void stop_server(ui_still_render *s)
{
    if (s->pid > 0) {
        kill(s->pid, SIGKILL); /* a render cannot be cut short otherwise */
        waitpid(s->pid, NULL, 0);
    }
    if (s->to_fd > 0)
        close(s->to_fd);
    if (s->from_fd > 0)
        close(s->from_fd);
    s->pid = s->to_fd = s->from_fd = 0;
    s->queued = s->discard = s->paused = s->served = 0;
    s->answer_len = 0;
}

void ui_still_render_stop(ui_still_render *s)
{
    stop_server(s);
    remove_folder(s);
}

void ui_still_render_cancel(ui_still_render *s)
{
    if (!ui_still_render_busy(s))
        return;
    if (s->served > 0) {
        stop_server(s);
        return;
    }
    s->discard = s->queued;
    if (!s->paused && kill(s->pid, SIGSTOP) == 0)
        s->paused = 1;
}

int ui_still_render_busy(const ui_still_render *s)
{
    return s->queued > s->discard;
}

/* A whole file into memory (NUL-terminated); NULL when it cannot be read. */
static char *read_all(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = NULL;
    long n = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (n >= 0 && fseek(f, 0, SEEK_SET) == 0 && (buf = malloc((size_t)n + 1))) {
        *size = fread(buf, 1, (size_t)n, f);
        buf[*size] = 0;
    }
    fclose(f);
    return buf;
}

/* The document as the window has it into next.json; *same gets 1 when it is the copy the server
 * renders. 0 ok. */
static int write_document(ui_still_render *s, const app_project *project, int *same, char *err,
                          size_t err_size)
{
    char next[sizeof s->folder + 32], current[sizeof s->folder + 32];
    folder_path(s, "next.json", next, sizeof next);
    folder_path(s, "project.json", current, sizeof current);
    if (app_project_write(next, project, err, err_size) != APP_OK)
        return 1;
    size_t a = 0, b = 0;
    char *x = read_all(next, &a), *y = read_all(current, &b);
    *same = x && y && a == b && !memcmp(x, y, a);
    free(x);
    free(y);
    return 0;
}

/* Between fork and exec only async-signal-safe calls (POSIX.1-2017, "fork"). */
static int spawn_server(ui_still_render *s, const char *quality, int bake, char *err,
                        size_t err_size)
{
    char project[sizeof s->folder + 32], log[sizeof s->folder + 32];
    folder_path(s, "project.json", project, sizeof project);
    folder_path(s, "server.log", log, sizeof log);
    char *argv[] = {"tessera",
                    "render",
                    project,
                    "--serve",
                    "--quality",
                    (char *)quality,
                    bake ? NULL : "--bake",
                    "off",
                    NULL};
    int in[2], out[2];
    int log_fd = open(log, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (log_fd < 0) {
        snprintf(err, err_size, "%s: %s", log, strerror(errno));
        return 1;
    }
    if (pipe(in) != 0 || (pipe(out) != 0 && (close(in[0]), close(in[1]), 1))) {
        snprintf(err, err_size, "the still view's render: %s", strerror(errno));
        close(log_fd);
        return 1;
    }
    /* The window forks only from this thread: no other fork sees these before the flags. */
    for (int i = 0; i < 2; i++) {
        fcntl(in[i], F_SETFD, FD_CLOEXEC);
        fcntl(out[i], F_SETFD, FD_CLOEXEC);
    }
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGKILL); /* the window gone, the pictures have no viewer */
        if (getppid() != parent)
            _exit(127);
        (void)setpriority(PRIO_PROCESS, 0, STILL_NICENESS);
        dup2(in[0], 0);
        dup2(out[1], 1);
        dup2(log_fd, 2);
        execve("/proc/self/exe", argv, environ);
        _exit(127);
    }
    close(log_fd);
    close(in[0]);
    close(out[1]);
    if (pid < 0) {
        snprintf(err, err_size, "cannot start the still view's render: %s", strerror(errno));
        close(in[1]);
        close(out[0]);
        return 1;
    }
    fcntl(out[0], F_SETFL, fcntl(out[0], F_GETFL) | O_NONBLOCK);
    signal(SIGPIPE, SIG_IGN); /* a server that died answers the next request's write with EPIPE */
    s->pid = (int)pid;
    s->to_fd = in[1];
    s->from_fd = out[0];
    s->bake = bake;
    s->served = 0;
    s->answer_len = 0;
    return 0;
}

/* Waits for the answer on its own copy of the server's output and wakes the window. */
typedef struct watcher {
    int fd;
    void (*wake)(void);
} watcher;

static void *watch(void *arg)
{
    watcher w = *(watcher *)arg;
    free(arg);
    struct pollfd p = {.fd = w.fd, .events = POLLIN};
    while (poll(&p, 1, -1) < 0 && errno == EINTR)
        ;
    close(w.fd);
    w.wake();
    return NULL;
}

static void start_watcher(const ui_still_render *s)
{
    void (*wake)(void) = s->wake;
    if (!wake)
        return; /* unwatched: the window polls at its idle wait's timeout */
    watcher *w = malloc(sizeof *w);
    int fd = w ? fcntl(s->from_fd, F_DUPFD_CLOEXEC, 3) : -1;
    pthread_t t;
    pthread_attr_t attr;
    int ok = fd >= 0 && pthread_attr_init(&attr) == 0;
    if (ok) {
        *w = (watcher){fd, wake};
        pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
        ok = pthread_create(&t, &attr, watch, w) == 0;
        pthread_attr_destroy(&attr);
    }
    if (!ok) {
        if (fd >= 0)
            close(fd);
        free(w);
    }
}

int ui_still_render_start(ui_still_render *s, const app_project *project, const double eye[3],
                          const double target[3], double fov_deg, int preset, const char *quality,
                          int width, int height, int bake, void (*wake)(void), char *err,
                          size_t err_size)
{
    if (preset < 0 || preset > 3 || width <= 0 || height <= 0) {
        snprintf(err, err_size, "the still view's render: no such preset or size");
        return 1;
    }
    if (!s->folder[0]) {
        const char *tmp = getenv("TMPDIR");
        snprintf(s->folder, sizeof s->folder, "%s/tessera-still-XXXXXX",
                 tmp && *tmp ? tmp : "/tmp");
        if (!mkdtemp(s->folder)) {
            snprintf(err, err_size, "the still view's render has no folder (%s): %s", s->folder,
                     strerror(errno));
            s->folder[0] = 0;
            return 1;
        }
    }
    int same = 0;
    if (write_document(s, project, &same, err, err_size))
        return 1;
    /* A server paused on its first request goes on with it, then takes this one. */
    int reuse = s->pid > 0 && same && s->bake == bake && !ui_still_render_busy(s) &&
                (s->queued == 0 || s->served == 0);
    if (!reuse) {
        stop_server(s);
        char next[sizeof s->folder + 32], current[sizeof s->folder + 32];
        folder_path(s, "next.json", next, sizeof next);
        folder_path(s, "project.json", current, sizeof current);
        if (rename(next, current) != 0) {
            snprintf(err, err_size, "%s: %s", current, strerror(errno));
            return 1;
        }
        if (spawn_server(s, quality, bake, err, err_size))
            return 1;
    }
    if (s->paused && kill(s->pid, SIGCONT) == 0)
        s->paused = 0;
    char picture[sizeof s->folder + 32], line[sizeof picture + 256];
    folder_path(s, "still.png", picture, sizeof picture);
    int n = snprintf(line, sizeof line, "%.3f %.3f %.3f %.3f %.3f %.3f %.4f %s %d %d %s\n", eye[0],
                     eye[1], eye[2], target[0], target[1], target[2], fov_deg, quality, width,
                     height, picture);
    if (n <= 0 || (size_t)n >= sizeof line || write(s->to_fd, line, (size_t)n) != n) {
        snprintf(err, err_size, "the still view's render did not take the view: %s",
                 strerror(errno));
        stop_server(s);
        return 1;
    }
    s->queued++;
    s->wake = wake;
    s->warm = s->served > 0;
    s->preset = preset;
    s->width = width;
    s->height = height;
    s->started = now_s();
    if (s->queued == 1)
        start_watcher(s); /* else the one waiting for the discarded answer */
    return 0;
}

/* The server's last line on its terminal (progress bars redraw with carriage returns). */
static void last_words(const ui_still_render *s, char *out, size_t size)
{
    char path[sizeof s->folder + 32];
    folder_path(s, "server.log", path, sizeof path);
    out[0] = 0;
    size_t n = 0;
    char *buf = read_all(path, &n);
    if (!buf)
        return;
    while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == '\r' || buf[n - 1] == ' '))
        n--;
    buf[n] = 0;
    char *start = buf;
    for (char *c = buf; *c; c++)
        if (*c == '\n' || *c == '\r')
            start = c + 1;
    size_t len = strlen(start);
    len = len < size ? len : size - 1;
    memcpy(out, start, len);
    out[len] = 0;
    free(buf);
}

static int read_picture(ui_still_render *s, uint8_t *rgba, char *err, size_t err_size)
{
    char path[sizeof s->folder + 32];
    folder_path(s, "still.png", path, sizeof path);
    rd_image img;
    if (rd_image_read(path, &img, NULL, err, err_size) != RD_IMAGE_OK)
        return -1;
    int ok = img.width == s->width && img.height == s->height && img.channels >= 3;
    if (!ok)
        snprintf(err, err_size, "%s: %dx%d, not the %dx%d asked for", path, img.width, img.height,
                 s->width, s->height);
    for (size_t i = 0; ok && i < (size_t)s->width * (size_t)s->height; i++)
        for (int c = 0; c < 4; c++) {
            float v = c < 3 ? img.pixels[i * (size_t)img.channels + (size_t)c] : 1.0f;
            v = v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v;
            rgba[i * 4 + (size_t)c] = (uint8_t)lroundf(v * 255.0f);
        }
    rd_image_free(&img);
    unlink(path);
    return ok ? 1 : -1;
}

/* The server is gone or talks nonsense: its last words into err, and it is stopped. */
static int server_failed(ui_still_render *s, const char *what, char *err, size_t err_size)
{
    char words[512];
    last_words(s, words, sizeof words);
    snprintf(err, err_size, "the %dx%d still's render %s%s%s", s->width, s->height, what,
             words[0] ? ": " : "", words);
    stop_server(s);
    return -1;
}

int ui_still_render_poll(ui_still_render *s, uint8_t *rgba, char *err, size_t err_size)
{
    if (s->queued == 0 || s->paused)
        return 0;
    for (;;) {
        char c;
        ssize_t r = read(s->from_fd, &c, 1);
        if (r < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            return 0;
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            return server_failed(s, "stopped", err, err_size);
        if (c != '\n') {
            if (s->answer_len + 1 < sizeof s->answer)
                s->answer[s->answer_len++] = c;
            continue;
        }
        s->answer[s->answer_len] = 0;
        s->answer_len = 0;
        s->queued--;
        s->served++;
        if (s->discard > 0) { /* a view no longer shown: wait for the next answer */
            s->discard--;
            if (s->queued > 0)
                start_watcher(s);
            continue;
        }
        if (strncmp(s->answer, "done ", 5) != 0)
            return server_failed(s, "failed", err, err_size);
        int result = read_picture(s, rgba, err, err_size);
        if (result == 1)
            s->seconds_per_mpx[s->preset][s->warm] =
                (now_s() - s->started) / ((double)s->width * (double)s->height * 1e-6);
        return result;
    }
}

double ui_still_render_elapsed(const ui_still_render *s)
{
    return ui_still_render_busy(s) ? now_s() - s->started : 0.0;
}

float ui_still_render_fraction(const ui_still_render *s)
{
    double per = ui_still_render_busy(s) ? s->seconds_per_mpx[s->preset][s->warm] : 0.0;
    if (per <= 0.0)
        return 0.0f;
    double f = ui_still_render_elapsed(s) / (per * (double)s->width * (double)s->height * 1e-6);
    return (float)(f > 0.95 ? 0.95 : f);
}
