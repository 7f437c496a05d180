/* Shaders compiled ahead of their first use (docs/ui.md, "Shader warm-up").
 *
 * llvmpipe compiles a program's shader variant at the program's first draw with a given state,
 * not at the link, and the still view's first climb to final (more lights, soft shadows,
 * probes) draws a dozen new variants in one strip: several seconds in one frame. Mesa keeps
 * what it compiles in its on-disk cache (XDG_CACHE_HOME/mesa_shader_cache), per kind of context:
 * EGL's, OSMesa's and a window's entries do not serve each other. So once the window's scene
 * and its baked light are ready, background processes, niced below the window, draw the
 * document's moving frame at interactive (the live programs of its light counts) and its still
 * at interactive in a hidden window's context (`--backend window`), then render it at final and
 * at print quality as the background render does (its default backend), at a thumbnail's size,
 * and the window's later moves and the background render read the compiled variants from the
 * cache. While the view moves the render is stopped (SIGSTOP), so
 * that the moving frames keep both cores. TESSERA_SHADER_WARMUP=off leaves it out. */
#include "planner.h"

#include "planner_actions.h"

#include <GLFW/glfw3.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

#define WARMUP_NICENESS 19

/* First the moving view's programs at interactive (render/src/programs.c's fixed-light ones,
 * which no still frame draws), by a one-frame live bench; then the still view's at
 * interactive, final's and print's. Each draws every object, in view or not (--prime), so
 * that no later view of the scene compiles a variant. */
static const char *const stages[] = {"moving", "interactive", "final", "print"};
enum { STAGE_COUNT = 4, LIVE_STAGE = 0, FIRST_STILL_WAIT = 2 };

static int warmup_wanted(void)
{
    const char *v = getenv("TESSERA_SHADER_WARMUP");
    return !(v && !strcmp(v, "off"));
}

/* The render of one stage, its output into /dev/null; the child's pid or -1. Between fork and
 * exec only async-signal-safe calls (POSIX.1-2017, "fork"). */
static pid_t spawn_render(const char *project, int stage, const char *image, int bake)
{
    /* The window's own draws (its moving frames, its still at interactive) in a context of the
     * window's kind; final's and print's in the background render's (the default backend). */
    int own = stage < FIRST_STILL_WAIT;
    char *argv[24];
    int n = 0;
    if (stage == LIVE_STAGE) {
        /* a frame to capture the probes, then the moving frame that draws their readers */
        char *live[] = {
            "tessera", "bench", (char *)project, "--quality", "interactive", "--live", "on",
            "--size",  "96x54", "--frames",      "1",         "--warmup",    "1"};
        for (size_t i = 0; i < sizeof live / sizeof live[0]; i++)
            argv[n++] = live[i];
    } else {
        char *still[] = {
            "tessera", "render", (char *)project, "--quality", (char *)stages[stage], "--size",
            "96x54",   "-o",     (char *)image};
        for (size_t i = 0; i < sizeof still / sizeof still[0]; i++)
            argv[n++] = still[i];
    }
    argv[n++] = "--prime";
    argv[n++] = "on";
    if (own) {
        argv[n++] = "--backend";
        argv[n++] = "window";
    }
    if (!bake) {
        argv[n++] = "--bake";
        argv[n++] = "off";
    }
    argv[n] = NULL;
    int null_fd = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null_fd < 0)
        return -1;
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid != 0) {
        close(null_fd);
        return pid;
    }
    prctl(PR_SET_PDEATHSIG, SIGKILL); /* it may be stopped: SIGTERM would wait for a SIGCONT */
    if (getppid() != parent)
        _exit(127);
    (void)setpriority(PRIO_PROCESS, 0, WARMUP_NICENESS);
    dup2(null_fd, 1);
    dup2(null_fd, 2);
    execve("/proc/self/exe", argv, environ);
    _exit(127);
}

static void remove_folder(ui_shader_warmup *w)
{
    if (!w->folder[0])
        return;
    char path[sizeof w->folder + 32];
    snprintf(path, sizeof path, "%s/project.json", w->folder);
    unlink(path);
    snprintf(path, sizeof path, "%s/warm.png", w->folder);
    unlink(path);
    rmdir(w->folder);
    w->folder[0] = 0;
}

/* The document as it is now, in a folder of its own. 0 ok. */
static int write_project(planner *p, ui_shader_warmup *w)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(w->folder, sizeof w->folder, "%s/tessera-warmup-XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(w->folder)) {
        w->folder[0] = 0;
        return 1;
    }
    char path[sizeof w->folder + 32], err[1024];
    snprintf(path, sizeof path, "%s/project.json", w->folder);
    if (app_project_write(path, &p->project, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: shader warm-up: %s\n", err);
        remove_folder(w);
        return 1;
    }
    return 0;
}

void planner_warmup_frame(planner *p)
{
    ui_shader_warmup *w = &p->warmup;
    if (w->finished)
        return;
    if (!warmup_wanted()) {
        w->finished = 1;
        return;
    }
    int moving = !p->live.still || p->dragging;
    if (w->pid > 0 && moving != w->paused) {
        kill(w->pid, moving ? SIGSTOP : SIGCONT);
        w->paused = moving;
    }
    if (w->pid > 0) {
        int status = 0;
        pid_t r = waitpid(w->pid, &status, WNOHANG);
        if (r == 0)
            return;
        w->pid = 0;
        int ok = r > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
        fprintf(stderr, "tessera: shader warm-up: %s %s in %.1f s\n", stages[w->stage],
                ok ? "compiled" : "failed", glfwGetTime() - w->started);
        if (!ok || ++w->stage >= STAGE_COUNT) {
            w->finished = 1;
            remove_folder(w);
            return;
        }
    }
    /* Its render reads the window's bake from the cache: start once the light has settled and
     * the view stands still, and leave the cores to a long job or the still view's own render
     * while one runs. */
    if (moving || !p->scene_ready || !planner_bake_settled(p) || planner_job_running(p) ||
        ui_still_render_busy(&p->live.still_render))
        return;
    if (!w->folder[0] && write_project(p, w)) {
        w->finished = 1;
        return;
    }
    char project[sizeof w->folder + 32], image[sizeof w->folder + 32];
    snprintf(project, sizeof project, "%s/project.json", w->folder);
    snprintf(image, sizeof image, "%s/warm.png", w->folder);
    w->started = glfwGetTime();
    w->pid = spawn_render(project, w->stage, image, p->bake != NULL);
    if (w->pid < 0) {
        w->pid = 0;
        w->finished = 1;
        remove_folder(w);
    }
}

int planner_warmup_done(const planner *p)
{
    return p->warmup.finished;
}

int planner_warmup_ready(const planner *p, int preset)
{
    for (int i = FIRST_STILL_WAIT; i < STAGE_COUNT; i++)
        if (!strcmp(ui_quality_names[preset], stages[i]))
            return p->warmup.finished || p->warmup.stage > i;
    return 1; /* draft and interactive: compiled by the window's first frames if need be */
}

void planner_warmup_stop(planner *p)
{
    ui_shader_warmup *w = &p->warmup;
    if (w->pid > 0) {
        kill(w->pid, SIGKILL); /* stopped or not; it writes nothing the window keeps */
        waitpid(w->pid, NULL, 0);
        w->pid = 0;
    }
    remove_folder(w);
    w->finished = 1;
}
