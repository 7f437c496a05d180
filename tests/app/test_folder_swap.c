/* A folder replaced whole (app/output/folder_swap.h): a new folder, an old one replaced with
 * nothing of it left, a discarded write leaving the old folder as it was, a file in the way,
 * a symbolic link to a folder kept a link, and a file system without RENAME_EXCHANGE. */
#define _GNU_SOURCE /* mkdtemp, symlink, renameat2, syscall */
#include "../common/check.h"
#include "app/output/folder_swap.h"

#include <dirent.h>
#include <errno.h>
#include <sys/syscall.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* This definition takes the place of glibc's for the whole program (the executable's symbols
 * come first), so a file system that refuses RENAME_EXCHANGE can be played. */
static int no_exchange;
int renameat2(int olddirfd, const char *oldpath, int newdirfd, const char *newpath,
              unsigned int flags)
{
    if (no_exchange && (flags & RENAME_EXCHANGE)) {
        errno = EINVAL;
        return -1;
    }
    return (int)syscall(SYS_renameat2, olddirfd, oldpath, newdirfd, newpath, flags);
}

static void put(const char *dir, const char *name, const char *text)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static int has(const char *dir, const char *name, const char *text)
{
    char path[4096], buf[256] = "";
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    return !strcmp(buf, text);
}

static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
    if (d)
        closedir(d);
    return d ? n : -1;
}

int main(void)
{
    char root[] = "/tmp/test_folder_swap-XXXXXX", target[4200], err[1024];
    CHECK(mkdtemp(root) != NULL);
    snprintf(target, sizeof target, "%s/share", root);
    app_folder_swap s;

    /* A new folder: made by the commit, with the permissions mkdir gives. */
    CHECK(app_folder_swap_begin(&s, target, err, sizeof err) == APP_OK);
    CHECK(access(target, F_OK) != 0);
    put(s.temp, "index.html", "one");
    CHECK_MSG(app_folder_swap_commit(&s, err, sizeof err) == APP_OK, "%s", err);
    CHECK(has(target, "index.html", "one"));
    CHECK(entries(root) == 1);
    struct stat st;
    CHECK(stat(target, &st) == 0 && (st.st_mode & 0700) == 0700);

    /* An old folder replaced: only the new content, and nothing beside it. */
    put(target, "old.png", "stale");
    CHECK(app_folder_swap_begin(&s, target, err, sizeof err) == APP_OK);
    put(s.temp, "index.html", "two");
    CHECK(has(target, "index.html", "one")); /* untouched until the commit */
    CHECK_MSG(app_folder_swap_commit(&s, err, sizeof err) == APP_OK, "%s", err);
    CHECK(has(target, "index.html", "two"));
    CHECK(entries(target) == 1);
    CHECK(entries(root) == 1);

    /* A discarded write: the old folder as it was, the temporary one gone. */
    CHECK(app_folder_swap_begin(&s, target, err, sizeof err) == APP_OK);
    put(s.temp, "index.html", "three");
    app_folder_swap_discard(&s);
    CHECK(has(target, "index.html", "two"));
    CHECK(entries(root) == 1);

    /* A file in the way. */
    char file[4300];
    snprintf(file, sizeof file, "%s/file", root);
    put(root, "file", "x");
    CHECK(app_folder_swap_begin(&s, file, err, sizeof err) != APP_OK);
    CHECK(strstr(err, "file") != NULL);
    CHECK(entries(root) == 2);

    /* A link to a folder stays a link; the folder it names is replaced. */
    char link[4300];
    snprintf(link, sizeof link, "%s/link", root);
    CHECK(symlink("share", link) == 0);
    CHECK(app_folder_swap_begin(&s, link, err, sizeof err) == APP_OK);
    put(s.temp, "index.html", "four");
    CHECK_MSG(app_folder_swap_commit(&s, err, sizeof err) == APP_OK, "%s", err);
    CHECK(lstat(link, &st) == 0 && S_ISLNK(st.st_mode));
    CHECK(has(target, "index.html", "four"));
    CHECK(entries(root) == 3);

    /* No RENAME_EXCHANGE: the old folder moved aside, the new one in, the old one removed. */
    no_exchange = 1;
    CHECK(app_folder_swap_begin(&s, target, err, sizeof err) == APP_OK);
    put(s.temp, "index.html", "five");
    CHECK_MSG(app_folder_swap_commit(&s, err, sizeof err) == APP_OK, "%s", err);
    CHECK(has(target, "index.html", "five"));
    CHECK(entries(target) == 1);
    CHECK(entries(root) == 3);
    no_exchange = 0;

    CHECK(app_remove_tree(root) == 0);
    CHECK(access(root, F_OK) != 0);
    return check_report("folder_swap");
}
