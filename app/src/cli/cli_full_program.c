/* The lean `tessera` hands every command it does not link (IN_FULL, cli_table.h) to the full
 * program: tessera-full in the same folder as the running executable, so the pair works from
 * the build tree and from an install alike. argv goes over unchanged, so the full program
 * parses, reports errors and prints usage exactly as if it had been started itself. */
#include "cli_table.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define FULL_PROGRAM_NAME "tessera-full"

int cli_command_in_full(const cli_command *c)
{
    return c && !c->run && !c->subcommands;
}

/* DIR/tessera-full for the DIR of /proc/self/exe (the executable itself, symbolic links
 * resolved, whatever argv[0] says). 0 if that path cannot be found or does not fit. */
static int full_program_path(char *buf, size_t size)
{
    char self[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0)
        return 0;
    self[n] = 0;
    char *slash = strrchr(self, '/');
    if (!slash)
        return 0;
    slash[1] = 0;
    int m = snprintf(buf, size, "%s%s", self, FULL_PROGRAM_NAME);
    return m > 0 && (size_t)m < size;
}

int cli_run_full_program(int argc, char **argv)
{
    (void)argc; /* argv is NULL-terminated, as main received it */
    char path[PATH_MAX + sizeof FULL_PROGRAM_NAME];
    if (!full_program_path(path, sizeof path)) {
        fprintf(stderr,
                "tessera: %s needs the full program (%s), which cannot be found: "
                "/proc/self/exe is unreadable\n",
                argv[1] ? argv[1] : "the planner window", FULL_PROGRAM_NAME);
        return CLI_FAILED;
    }
    fflush(NULL); /* nothing printed so far may be lost or doubled by exec */
    execv(path, argv);
    fprintf(stderr, "tessera: %s needs the full program %s: %s\n",
            argv[1] ? argv[1] : "the planner window", path, strerror(errno));
    return CLI_FAILED;
}
