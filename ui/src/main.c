/* The full `tessera` program, tessera-full: the command line (app/src/cli/) with every command
 * and the planner window behind `tessera open` and `tessera` alone. The lean `tessera`
 * (app/lean/main.c) runs it for everything but the catalog commands. */
#include "app/cli/cli.h"
#include "ui/ui.h"

int main(int argc, char **argv)
{
    app_cli_set_window_context(ui_hidden_window_context);
    return app_cli_run(argc, argv, ui_open_window);
}
