/* fsize_limit BYTES PROGRAM [ARGS...]: runs PROGRAM with no file allowed to grow past BYTES
 * (RLIMIT_FSIZE, POSIX setrlimit). SIGXFSZ is ignored, so a write past the limit fails with
 * EFBIG ("File too large") as a write to a full disk fails with ENOSPC: a full disk for one
 * process, without root, a loop device or a small tmpfs. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: fsize_limit BYTES PROGRAM [ARGS...]\n");
        return 2;
    }
    char *end = NULL;
    unsigned long long bytes = strtoull(argv[1], &end, 10);
    if (end == argv[1] || *end != '\0') {
        fprintf(stderr, "fsize_limit: '%s' is not a byte count\n", argv[1]);
        return 2;
    }
    struct rlimit limit = {(rlim_t)bytes, (rlim_t)bytes};
    if (signal(SIGXFSZ, SIG_IGN) == SIG_ERR || setrlimit(RLIMIT_FSIZE, &limit) != 0) {
        fprintf(stderr, "fsize_limit: cannot set the limit: %s\n", strerror(errno));
        return 2;
    }
    execvp(argv[2], argv + 2); /* an ignored signal stays ignored across exec (POSIX) */
    fprintf(stderr, "fsize_limit: cannot run %s: %s\n", argv[2], strerror(errno));
    return 2;
}
