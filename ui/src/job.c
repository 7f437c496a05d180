/* The worker thread of a long job (job.h). */
#define _GNU_SOURCE /* nftw's FTW_DEPTH and FTW_PHYS, pipe2 */

#include "job.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

#define MAX_ARGS 24
#define JOB_NICENESS 5

struct ui_job {
    pthread_t thread;
    pthread_mutex_t lock;
    ui_job_status status;
    pid_t pid;
    int cancel;
    double start;
    char label[64], command[1024], program[1024], project[1024], output[1024], partial[1100];
    char *args[MAX_ARGS];
    int is_folder, owns_project, open_result, folder_existed;
};

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double ui_job_parse_progress(const char *line)
{
    double best = -1;
    for (const char *s = line; (s = strchr(s, '/')) != NULL; s++) {
        const char *a = s;
        while (a > line && a[-1] >= '0' && a[-1] <= '9')
            a--;
        if (a == s || !(s[1] >= '0' && s[1] <= '9'))
            continue;
        long n = strtol(a, NULL, 10), m = strtol(s + 1, NULL, 10);
        if (m > 0 && n >= 0 && n <= m)
            best = (double)n / (double)m;
    }
    return best;
}

int ui_job_partial_name(const char *output, const char *tag, char *out, size_t size)
{
    const char *slash = strrchr(output, '/');
    const char *base = slash ? slash + 1 : output;
    const char *dot = strrchr(base, '.');
    int dir_len = slash ? (int)(slash - output + 1) : 0;
    int stem_len = dot ? (int)(dot - base) : (int)strlen(base);
    int n = snprintf(out, size, "%.*s.%.*s.partial-%s%s", dir_len, output, stem_len, base, tag,
                     dot ? dot : "");
    return n < 0 || (size_t)n >= size;
}

static void set_line(ui_job *j, const char *text, size_t len)
{
    while (len > 0 && (text[len - 1] == ' ' || text[len - 1] == '\t'))
        len--;
    if (len == 0)
        return;
    char line[256];
    snprintf(line, sizeof line, "%.*s", (int)(len < 255 ? len : 255), text);
    double f = ui_job_parse_progress(line);
    pthread_mutex_lock(&j->lock);
    memcpy(j->status.line, line, sizeof line);
    if (f >= 0)
        j->status.progress = f;
    pthread_mutex_unlock(&j->lock);
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st;
    (void)flag;
    (void)ftw;
    remove(path);
    return 0;
}

/* A folder command stopped midway (cancelled: SIGTERM) leaves the folder it was writing,
 * OUT.tmp-XXXXXX beside OUT (app/output/folder_swap.h): removed with the job. */
static void remove_folder_temps(const char *output)
{
    const char *slash = strrchr(output, '/');
    char dir[1100], prefix[1100];
    snprintf(dir, sizeof dir, "%.*s", slash ? (slash == output ? 1 : (int)(slash - output)) : 1,
             slash ? output : ".");
    int n = snprintf(prefix, sizeof prefix, "%s.tmp-", slash ? slash + 1 : output);
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && n > 0 && (size_t)n < sizeof prefix && (e = readdir(d))) {
        struct stat st;
        char path[2300];
        if (strncmp(e->d_name, prefix, (size_t)n) != 0 || strlen(e->d_name) != (size_t)n + 6)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (lstat(path, &st) == 0 && S_ISDIR(st.st_mode))
            nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
    }
    if (d)
        closedir(d);
}

/* Opens the result in the desktop's viewer without waiting for the viewer: sh starts the
 * opener in the background and returns at once (its child is then init's). */
static void open_result(const char *path)
{
    const char *opener = getenv("TESSERA_OPENER");
    if (opener && !*opener)
        return;
    char *argv[] = {"sh",
                    "-c",
                    "command -v \"$0\" >/dev/null 2>&1 && \"$0\" \"$1\" </dev/null >/dev/null "
                    "2>&1 &",
                    (char *)(opener ? opener : "xdg-open"),
                    (char *)path,
                    NULL};
    pid_t pid;
    if (posix_spawn(&pid, "/bin/sh", NULL, NULL, argv, environ) == 0)
        waitpid(pid, NULL, 0);
}

/* Starts program with argv, its standard output and error into out_fd; the child's pid, or -1.
 * fork rather than posix_spawn for what the child must set up itself: a process group of its
 * own (cancel stops the command and anything it started), a niceness below the window's
 * (where cores are few the frames come first; the render threads inherit it), and death with
 * the thread that started it (a window killed outright leaves no render running). Between fork
 * and exec only async-signal-safe calls (POSIX.1-2017, "fork"). */
static pid_t spawn_command(const char *program, char *const argv[], int out_fd)
{
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid != 0)
        return pid;
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) /* the window went before prctl took effect */
        _exit(127);
    (void)setpriority(PRIO_PROCESS, 0, JOB_NICENESS);
    dup2(out_fd, 1);
    dup2(out_fd, 2);
    execve(program, argv, environ);
    static const char msg[] = "the command cannot be run\n";
    (void)!write(2, msg, sizeof msg - 1);
    _exit(127);
}

static void *work(void *arg)
{
    ui_job *j = arg;
    const char *target = j->is_folder ? j->output : j->partial;
    char *argv[MAX_ARGS + 6];
    int n = 0;
    argv[n++] = "tessera";
    argv[n++] = j->command;
    argv[n++] = j->project;
    argv[n++] = "-o";
    argv[n++] = (char *)target;
    for (int i = 0; j->args[i]; i++)
        argv[n++] = j->args[i];
    argv[n] = NULL;

    int fds[2] = {-1, -1};
    int started = 0;
    if (pipe2(fds, O_CLOEXEC) == 0) {
        pthread_mutex_lock(&j->lock);
        pid_t pid = j->cancel ? -1 : spawn_command(j->program, argv, fds[1]);
        if (pid > 0) {
            j->pid = pid;
            started = 1;
        }
        pthread_mutex_unlock(&j->lock);
        close(fds[1]);
    }

    int status = 1;
    if (started) {
        char buf[4096];
        size_t have = 0;
        for (;;) {
            ssize_t r = read(fds[0], buf + have, sizeof buf - 1 - have);
            if (r < 0 && errno == EINTR)
                continue;
            if (r <= 0)
                break;
            have += (size_t)r;
            size_t start = 0;
            for (size_t i = 0; i < have; i++)
                if (buf[i] == '\n' || buf[i] == '\r') {
                    set_line(j, buf + start, i - start);
                    start = i + 1;
                }
            if (start == 0 && have == sizeof buf - 1) /* a line longer than the buffer */
                start = have;
            memmove(buf, buf + start, have - start);
            have -= start;
        }
        set_line(j, buf, have);
        while (waitpid(j->pid, &status, 0) < 0 && errno == EINTR)
            ;
    } else {
        set_line(j, "the command did not start", 25);
    }
    if (fds[0] >= 0)
        close(fds[0]);

    pthread_mutex_lock(&j->lock);
    int cancelled = j->cancel;
    j->pid = 0;
    pthread_mutex_unlock(&j->lock);
    ui_job_state state = cancelled ? UI_JOB_CANCELLED
                         : started && WIFEXITED(status) && WEXITSTATUS(status) == 0 ? UI_JOB_DONE
                                                                                    : UI_JOB_FAILED;
    if (state == UI_JOB_DONE && !j->is_folder && rename(j->partial, j->output) != 0) {
        char why[1200];
        snprintf(why, sizeof why, "cannot rename the result to %.1024s: %.100s", j->output,
                 strerror(errno));
        set_line(j, why, strlen(why));
        state = UI_JOB_FAILED;
    }
    if (state != UI_JOB_DONE) {
        if (!j->is_folder)
            unlink(j->partial);
        else if (!j->folder_existed)
            nftw(j->output, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
        if (j->is_folder)
            remove_folder_temps(j->output);
    }
    if (j->owns_project) {
        char bak[1100], *slash;
        snprintf(bak, sizeof bak, "%s.bak", j->project);
        unlink(j->project);
        unlink(bak);
        if ((slash = strrchr(j->project, '/')) != NULL) {
            *slash = 0;
            rmdir(j->project);
        }
    }
    if (state == UI_JOB_DONE && j->open_result)
        open_result(j->output);
    pthread_mutex_lock(&j->lock);
    if (state == UI_JOB_DONE)
        j->status.progress = 1;
    j->status.state = state;
    pthread_mutex_unlock(&j->lock);
    return NULL;
}

ui_job *ui_job_start(const ui_job_desc *d, char *err, size_t err_size)
{
    ui_job *j = calloc(1, sizeof *j);
    if (!j) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    snprintf(j->label, sizeof j->label, "%s", d->label ? d->label : d->command);
    snprintf(j->command, sizeof j->command, "%s", d->command);
    snprintf(j->program, sizeof j->program, "%s", d->program ? d->program : "/proc/self/exe");
    snprintf(j->project, sizeof j->project, "%s", d->project);
    snprintf(j->output, sizeof j->output, "%s", d->output);
    j->is_folder = d->is_folder;
    j->owns_project = d->owns_project;
    j->open_result = d->open_result;
    struct stat st;
    j->folder_existed = d->is_folder && stat(d->output, &st) == 0;
    char tag[32];
    snprintf(tag, sizeof tag, "%ld", (long)getpid());
    int bad = !j->is_folder && ui_job_partial_name(d->output, tag, j->partial, sizeof j->partial);
    for (int i = 0; !bad && d->args && d->args[i]; i++) {
        if (i + 1 >= MAX_ARGS || !(j->args[i] = strdup(d->args[i])))
            bad = 1;
    }
    if (bad) {
        snprintf(err, err_size, "%s: the path or the arguments are too long", d->output);
        ui_job_free(j);
        return NULL;
    }
    pthread_mutex_init(&j->lock, NULL);
    j->status.state = UI_JOB_RUNNING;
    j->status.progress = -1;
    snprintf(j->status.line, sizeof j->status.line, "starting");
    j->start = now_s();
    int e = pthread_create(&j->thread, NULL, work, j);
    if (e) {
        snprintf(err, err_size, "cannot start a worker thread: %s", strerror(e));
        pthread_mutex_destroy(&j->lock);
        for (int i = 0; j->args[i]; i++)
            free(j->args[i]);
        free(j);
        return NULL;
    }
    return j;
}

void ui_job_status_get(ui_job *j, ui_job_status *out)
{
    pthread_mutex_lock(&j->lock);
    *out = j->status;
    pthread_mutex_unlock(&j->lock);
    out->seconds = now_s() - j->start;
}

void ui_job_cancel(ui_job *j)
{
    pthread_mutex_lock(&j->lock);
    j->cancel = 1;
    if (j->pid > 0)
        kill(-j->pid, SIGTERM);
    pthread_mutex_unlock(&j->lock);
}

void ui_job_free(ui_job *j)
{
    if (!j)
        return;
    if (j->start > 0) {
        pthread_join(j->thread, NULL);
        pthread_mutex_destroy(&j->lock);
    }
    for (int i = 0; j->args[i]; i++)
        free(j->args[i]);
    free(j);
}
