/* The `tessera` entry point: finds the command in the command table (cli_command_table.c),
 * parses its options by the option table and runs it; `--help` anywhere prints the usage
 * generated from the same tables. */
#include "app/cli/cli.h"
#include "app/scene/quality.h"
#include "cli_commands.h"
#include "cli_table.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

static void print_overview(FILE *f)
{
    fprintf(f, "tessera: a bathroom and interior-design planner\n"
               "\n"
               "usage: tessera COMMAND [options]   (tessera help COMMAND, tessera COMMAND --help)\n"
               "       tessera                     (the planner window, as tessera open)\n"
               "\n");
    for (const cli_command *c = cli_commands; c->name; c++) {
        fprintf(f, "  tessera %s", c->name);
        if (c->subcommands) {
            for (const cli_command *s = c->subcommands; s->name; s++)
                fprintf(f, "%c%s", s == c->subcommands ? ' ' : '|', s->name);
            fprintf(f, " ...\n");
        } else
            fprintf(f, "%s%s\n", c->synopsis[0] ? " " : "", c->synopsis);
        fprintf(f, "      %s\n", c->summary);
    }
    fprintf(f,
            "\nThe OpenGL backend is EGL (Mesa surfaceless) unless --backend or TESSERA_GL says\n"
            "otherwise; OSMesa is the fallback.\n");
}

static int run(const cli_command *c, int argc, char **argv, int first, app_open_fn open_window);

static int run_subcommand(const cli_command *c, int argc, char **argv, int first,
                          app_open_fn open_window)
{
    if (first >= argc) {
        cli_print_usage(c, stderr);
        return CLI_USAGE;
    }
    const char *name = argv[first];
    if (!strcmp(name, "--help") || !strcmp(name, "-h") || !strcmp(name, "help")) {
        const cli_command *s =
            first + 1 < argc ? cli_command_find(c->subcommands, argv[first + 1]) : NULL;
        cli_print_usage(s ? s : c, stdout);
        return CLI_OK;
    }
    const cli_command *s = cli_command_find(c->subcommands, name);
    if (!s) {
        fprintf(stderr, "tessera %s: unknown sub-command \"%s\" (try tessera %s --help)\n", c->name,
                name, c->name);
        return CLI_USAGE;
    }
    return run(s, argc, argv, first + 1, open_window);
}

/* What a command printed to standard output (a table, CSV, JSON) must have arrived: a
 * redirect to a full disk is a failure with the system's reason, not a silent exit 0. */
static int check_stdout(int rc)
{
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "tessera: standard output: cannot write: %s\n",
                strerror(errno ? errno : EIO));
        return rc == CLI_OK ? CLI_FAILED : rc;
    }
    return rc;
}

static int run(const cli_command *c, int argc, char **argv, int first, app_open_fn open_window)
{
    if (cli_command_in_full(c))
        return cli_run_full_program(argc, argv);
    if (c->subcommands)
        return run_subcommand(c, argc, argv, first, open_window);
    cli_options o = {0};
    if (c->defaults)
        c->defaults(&o);
    o.open_window = open_window;
    int rc = cli_parse_args(c, argc, argv, first, &o);
    if (rc == CLI_HELP) {
        cli_print_usage(c, stdout);
        return CLI_OK;
    }
    return check_stdout(rc == CLI_OK ? c->run(&o) : rc);
}

/* tessera help [COMMAND [SUB-COMMAND]], tessera help --list */
int cli_cmd_help(const cli_options *o)
{
    if (o->list) {
        for (const cli_command *c = cli_commands; c->name; c++) {
            if (!c->subcommands)
                printf("%s\n", c->name);
            else
                for (const cli_command *s = c->subcommands; s->name; s++)
                    printf("%s %s\n", c->name, s->name);
        }
        return CLI_OK;
    }
    if (o->arg_count == 0) {
        print_overview(stdout);
        return CLI_OK;
    }
    const cli_command *c = cli_command_find(cli_commands, o->args[0]);
    if (c && o->arg_count == 2)
        c = c->subcommands ? cli_command_find(c->subcommands, o->args[1]) : NULL;
    if (!c) {
        fprintf(stderr, "tessera help: no command \"%s%s%s\" (tessera --help lists them)\n",
                o->args[0], o->arg_count == 2 ? " " : "", o->arg_count == 2 ? o->args[1] : "");
        return CLI_USAGE;
    }
    cli_print_usage(c, stdout);
    return CLI_OK;
}

int cli_cmd_open(const cli_options *o)
{
    if (!o->open_window) {
        fprintf(stderr, "tessera open: this program has no planner window\n");
        return CLI_FAILED;
    }
    app_open_request r = {.project = o->project,
                          .script = o->script,
                          .quality = o->quality ? o->quality->name : NULL,
                          .frame_log = o->frame_log,
                          .width = o->width,
                          .height = o->height,
                          .fullscreen = o->fullscreen};
    return o->open_window(&r);
}

int app_cli_run(int argc, char **argv, app_open_fn open_window)
{
    const cli_command *open = cli_command_find(cli_commands, "open");
    if (argc < 2 && (open_window || cli_command_in_full(open)))
        return run(open, argc, argv, 1, open_window);
    if (argc < 2) {
        print_overview(stderr);
        return CLI_USAGE;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        print_overview(stdout);
        return CLI_OK;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("tessera 0.1.0\n");
        return CLI_OK;
    }
    const cli_command *c = cli_command_find(cli_commands, argv[1]);
    if (!c) {
        fprintf(stderr, "tessera: unknown command \"%s\" (try tessera --help)\n", argv[1]);
        return CLI_USAGE;
    }
    return run(c, argc, argv, 2, open_window);
}

int app_cli_main(int argc, char **argv)
{
    return app_cli_run(argc, argv, NULL);
}
