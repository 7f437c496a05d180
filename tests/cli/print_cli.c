/* The `tessera` command line without the planner window (ui/), for the print tests and the
 * benchmarks: app_cli_main, as ui/src/main.c runs it when given arguments. */
#include "app/cli/cli.h"

int main(int argc, char **argv)
{
    return app_cli_main(argc, argv);
}
