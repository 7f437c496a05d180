/* The planner's state folder, recent-files list, autosave names (user_state.h) and the long
 * jobs' worker (job.h) with a shell script standing in for the `tessera` command. */
#define _DEFAULT_SOURCE /* mkdtemp, setenv */

#include "check.h"
#include "job.h"
#include "user_state.h"

#include <dirent.h>
#include <signal.h>
#include <sys/resource.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char root[] = "/tmp/tessera-user-state-XXXXXX";

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* Entries of dir whose name contains part. */
static int count_entries(const char *dir, const char *part)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d)) != NULL;)
        n += strstr(e->d_name, part) != NULL;
    if (d)
        closedir(d);
    return n;
}

static void test_state_dir(void)
{
    char dir[1024], want[1100];
    setenv("XDG_STATE_HOME", root, 1);
    CHECK(ui_state_dir(dir, sizeof dir) == 0);
    snprintf(want, sizeof want, "%s/tessera", root);
    CHECK_MSG(!strcmp(dir, want), "%s", dir);
    CHECK(exists(want));
    /* A relative XDG_STATE_HOME is invalid (XDG Base Directory Specification): HOME decides. */
    char home[1100];
    snprintf(home, sizeof home, "%s/home", root);
    setenv("HOME", home, 1);
    setenv("XDG_STATE_HOME", "relative/state", 1);
    CHECK(ui_state_dir(dir, sizeof dir) == 0);
    snprintf(want, sizeof want, "%s/home/.local/state/tessera", root);
    CHECK_MSG(!strcmp(dir, want), "%s", dir);
    setenv("XDG_STATE_HOME", root, 1);
}

static void test_recent(void)
{
    ui_recent r = {0};
    ui_recent_add(&r, "/a.json");
    ui_recent_add(&r, "/b.json");
    ui_recent_add(&r, "/c.json");
    ui_recent_add(&r, "/a.json"); /* again: moves first, once */
    CHECK(r.count == 3);
    CHECK(!strcmp(r.paths[0], "/a.json") && !strcmp(r.paths[1], "/c.json") &&
          !strcmp(r.paths[2], "/b.json"));
    for (int i = 0; i < 12; i++) {
        char p[32];
        snprintf(p, sizeof p, "/p%d.json", i);
        ui_recent_add(&r, p);
    }
    CHECK(r.count == UI_RECENT_MAX);
    CHECK(!strcmp(r.paths[0], "/p11.json") && !strcmp(r.paths[UI_RECENT_MAX - 1], "/p2.json"));

    char file[1100], err[1200];
    CHECK(ui_recent_file(file, sizeof file) == 0);
    CHECK(ui_recent_save(&r, file, err, sizeof err) == 0);
    ui_recent back;
    CHECK(ui_recent_load(&back, file) == 0);
    CHECK(back.count == r.count);
    for (int i = 0; i < r.count && i < back.count; i++)
        CHECK_MSG(!strcmp(back.paths[i], r.paths[i]), "%d: %s vs %s", i, back.paths[i], r.paths[i]);
    char dir[1100];
    snprintf(dir, sizeof dir, "%s/tessera", root);
    CHECK_MSG(count_entries(dir, ".tmp-") == 0, "a temporary file was left in %s", dir);

    /* Atomic: a write that cannot finish leaves the old list whole and no temporary file. A
     * file size limit stands in for a full disk (it stops root too). */
    ui_recent small = {0};
    ui_recent_add(&small, "/s.json");
    CHECK(ui_recent_save(&small, file, err, sizeof err) == 0);
    struct rlimit old_limit, limit;
    getrlimit(RLIMIT_FSIZE, &old_limit);
    limit = old_limit;
    limit.rlim_cur = 64; /* the ten-path list is longer */
    signal(SIGXFSZ, SIG_IGN);
    setrlimit(RLIMIT_FSIZE, &limit);
    int failed = ui_recent_save(&r, file, err, sizeof err) != 0;
    setrlimit(RLIMIT_FSIZE, &old_limit);
    CHECK_MSG(failed, "a write past the size limit succeeded");
    CHECK_MSG(strstr(err, file) != NULL, "%s", err);
    CHECK(ui_recent_load(&back, file) == 0);
    CHECK_MSG(back.count == 1 && !strcmp(back.paths[0], "/s.json"), "the old list was damaged");
    CHECK_MSG(count_entries(dir, ".tmp-") == 0, "the failed write left a temporary file");

    /* A missing list is empty; lines too long for a path are skipped. */
    char missing[1200];
    snprintf(missing, sizeof missing, "%s/none", root);
    CHECK(ui_recent_load(&back, missing) == 0 && back.count == 0);
    FILE *f = fopen(file, "w");
    fprintf(f, "/ok.json\n\n");
    for (int i = 0; i < 1500; i++)
        fputc('x', f);
    fprintf(f, "\n/ok2.json\n");
    fclose(f);
    CHECK(ui_recent_load(&back, file) == 0);
    CHECK_MSG(back.count == 2 && !strcmp(back.paths[1], "/ok2.json"), "%d", back.count);
}

static void test_autosave_names(void)
{
    char a[1100], b[1100], u[1100];
    CHECK(ui_project_state_file("autosave", "/x/one/bath.json", a, sizeof a) == 0);
    CHECK(ui_project_state_file("autosave", "/x/two/bath.json", b, sizeof b) == 0);
    CHECK(ui_project_state_file("autosave", "", u, sizeof u) == 0);
    CHECK_MSG(strcmp(a, b) != 0, "two projects named bath share %s", a);
    CHECK(strstr(a, "/tessera/autosave/bath-") != NULL);
    CHECK(strncmp(a, root, strlen(root)) == 0); /* in the state folder, not beside /x/one */
    CHECK(strstr(u, "/autosave/untitled.json") != NULL);
}

static void test_progress(void)
{
    CHECK_NEAR(ui_job_parse_progress("rendering [###   ] 3/10 1.2 s"), 0.3, 1e-9);
    CHECK_NEAR(ui_job_parse_progress("tessera print: [2/5] rendering view \"door\""), 0.4, 1e-9);
    CHECK(ui_job_parse_progress("tessera share: 360-degree panorama") < 0);
    CHECK(ui_job_parse_progress("a path /tmp/x/7") < 0);
    CHECK(ui_job_parse_progress("12/5 is no progress") < 0);
    char part[256];
    CHECK(ui_job_partial_name("/d/print.pdf", "42", part, sizeof part) == 0);
    CHECK_MSG(!strcmp(part, "/d/.print.partial-42.pdf"), "%s", part);
}

/* Runs a job whose "command" is a shell script; returns its end state. */
static ui_job_state run_job(const char *script_body, const char *out, int cancel_after_ms,
                            double *progress)
{
    char script[1200], err[256];
    snprintf(script, sizeof script, "%s/job.sh", root);
    FILE *f = fopen(script, "w");
    fprintf(f, "%s", script_body);
    fclose(f);
    /* argv: tessera COMMAND PROJECT -o OUT; sh runs COMMAND as its script, $3 is OUT. */
    ui_job_desc d = {.label = "test",
                     .command = script,
                     .project = "none.json",
                     .output = out,
                     .program = "/bin/sh",
                     .open_result = 1};
    ui_job *j = ui_job_start(&d, err, sizeof err);
    CHECK_MSG(j != NULL, "%s", err);
    if (!j)
        return UI_JOB_FAILED;
    ui_job_status s;
    int waited = 0;
    do {
        usleep(10000);
        waited += 10;
        if (cancel_after_ms > 0 && waited == cancel_after_ms)
            ui_job_cancel(j);
        ui_job_status_get(j, &s);
        if (s.progress > *progress)
            *progress = s.progress;
    } while (s.state == UI_JOB_RUNNING && waited < 20000);
    ui_job_free(j);
    if (s.state == UI_JOB_FAILED)
        fprintf(stderr, "the job failed: %s\n", s.line);
    return s.state;
}

static void test_jobs(void)
{
    setenv("TESSERA_OPENER", "", 1); /* set and empty: nothing is opened */
    char out[1200], part_dir[1200];
    snprintf(out, sizeof out, "%s/jobs/result.pdf", root);
    snprintf(part_dir, sizeof part_dir, "%s/jobs", root);
    mkdir(part_dir, 0700);
    double progress = -1;
    ui_job_state s = run_job("echo 'step 1/2'; sleep 0.3; echo 'step 2/2'; echo done > \"$3\"\n",
                             out, 0, &progress);
    CHECK(s == UI_JOB_DONE);
    CHECK(exists(out));
    CHECK_NEAR(progress, 1.0, 1e-9);
    CHECK(count_entries(part_dir, "partial") == 0);

    unlink(out);
    progress = -1;
    s = run_job("echo 'step 1/4'; echo half > \"$3\"; sleep 30; echo x > \"$3\"\n", out, 300,
                &progress);
    CHECK_MSG(s == UI_JOB_CANCELLED, "state %d", s);
    CHECK_MSG(!exists(out), "a cancelled job left %s", out);
    CHECK_MSG(count_entries(part_dir, "partial") == 0, "a cancelled job left its partial file");

    s = run_job("echo half > \"$3\"; echo 'it broke' >&2; exit 3\n", out, 0, &progress);
    CHECK(s == UI_JOB_FAILED);
    CHECK(!exists(out) && count_entries(part_dir, "partial") == 0);

    /* A cancelled folder job (tessera share): the folder it was writing beside OUT goes,
     * another folder of a like name stays. */
    char share[1300], other[1400];
    snprintf(share, sizeof share, "%s/share", part_dir);
    snprintf(other, sizeof other, "%s.tmp-kept", share);
    mkdir(other, 0700);
    ui_job_desc d = {.label = "share",
                     .command = "",
                     .project = "none.json",
                     .output = share,
                     .program = "/bin/sh",
                     .is_folder = 1};
    char script[1200], err[256];
    snprintf(script, sizeof script, "%s/job.sh", root);
    FILE *f = fopen(script, "w");
    fprintf(f, "mkdir \"$3.tmp-Ab12Cd\" && echo x > \"$3.tmp-Ab12Cd/index.html\"; sleep 30\n");
    fclose(f);
    d.command = script;
    ui_job *j = ui_job_start(&d, err, sizeof err);
    CHECK_MSG(j != NULL, "%s", err);
    ui_job_status st = {0};
    for (int waited = 0; j && waited < 20000; waited += 10) {
        usleep(10000);
        if (waited == 300)
            ui_job_cancel(j);
        ui_job_status_get(j, &st);
        if (st.state != UI_JOB_RUNNING)
            break;
    }
    ui_job_free(j);
    CHECK_MSG(st.state == UI_JOB_CANCELLED, "state %d", st.state);
    CHECK_MSG(count_entries(part_dir, "share.tmp-") == 1, "the cancelled share left its folder");
    CHECK(exists(other));
    rmdir(other);
}

int main(void)
{
    if (!mkdtemp(root)) {
        perror("mkdtemp");
        return 1;
    }
    test_state_dir();
    test_recent();
    test_autosave_names();
    test_progress();
    test_jobs();
    char cmd[256];
    snprintf(cmd, sizeof cmd, "rm -rf %s", root);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", root);
    return check_report("ui.user_state");
}
