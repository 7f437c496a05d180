/* A stand-in for `tessera reference` and `tessera compare` for the tests: the same command line
 * (argv[1] is the sub-command) without the window. */
#include "app/cli/cli.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc >= 2 && (!strcmp(argv[1], "reference") || !strcmp(argv[1], "compare")))
        return app_cli_main(argc, argv);
    fprintf(stderr, "usage: ref_cli reference|compare ...\n");
    return 2;
}
