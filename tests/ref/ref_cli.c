/* A stand-in for `tessera reference` and `tessera compare` for the tests: the same entry points
 * app_cli_main dispatches to (argv[1] is the sub-command). */
#include "app/measure/cli_ref.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "reference"))
        return app_cli_reference(argc, argv);
    if (argc >= 2 && !strcmp(argv[1], "compare"))
        return app_cli_compare(argc, argv);
    fprintf(stderr, "usage: ref_cli reference|compare ...\n");
    return 2;
}
