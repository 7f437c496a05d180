/* The lean `tessera`: the command line of app/src/cli/ built with TESSERA_CLI_LEAN. It runs the
 * catalog commands, check, generate-flat, help and --version itself, and hands everything else, the
 * planner window included, to tessera-full beside it (app/src/cli/cli_full_program.c). */
#include "app/cli/cli.h"

int main(int argc, char **argv)
{
    return app_cli_main(argc, argv);
}
