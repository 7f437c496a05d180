/* The `tessera` program: the planner window with no arguments or `open`, the command line
 * (app/src/cli/cli_main.c) otherwise. */
#include "app/cli/cli.h"
#include "ui/ui.h"

#include <string.h>

int main(int argc, char **argv)
{
    if (argc < 2 || !strcmp(argv[1], "open"))
        return ui_cli_open(argc, argv);
    return app_cli_main(argc, argv);
}
