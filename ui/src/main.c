/* The `tessera` program: the command line (app/src/cli/), with the planner window behind
 * `tessera open` and `tessera` alone. */
#include "app/cli/cli.h"
#include "ui/ui.h"

int main(int argc, char **argv)
{
    return app_cli_run(argc, argv, ui_open_window);
}
