/* The command line as data: one table of options (cli_option_table.c) and one of commands
 * (cli_command_table.c). Dispatch, `tessera --help`, `tessera help CMD`, `CMD --help`, the
 * parser's checks and its error messages are all generated from them (docs/cli.md). */
#ifndef APP_CLI_TABLE_H
#define APP_CLI_TABLE_H

#include "cli_options.h"

#include <stddef.h>
#include <stdio.h>

typedef enum cli_kind {
    CLI_FLAG,   /* no value: sets an int to 1 */
    CLI_INT,    /* a whole number in [lo, hi] into an int */
    CLI_LONG,   /* a whole number in [lo, hi] into a long long */
    CLI_FLOAT,  /* a number in [lo, hi] into a double */
    CLI_STRING, /* any text into a const char * */
    CLI_SIZE,   /* WxH, each side in [lo, hi], into the ints at offset and offset2 */
    CLI_ENUM,   /* one of `names` (from index 1) into an int: its index */
    CLI_SWITCH, /* on or off into an rd_switch */
    CLI_CUSTOM, /* `parse` decides (a preset, a backend, a paper size, ...) */
} cli_kind;

typedef struct cli_option_spec {
    const char *key;  /* unique in the table; what a command lists */
    const char *name; /* on the command line after "--"; NULL = key */
    char short_name;  /* a one-letter alias ('o' for -o), or 0 */
    cli_kind kind;
    double lo, hi;            /* CLI_INT, CLI_LONG, CLI_FLOAT, CLI_SIZE */
    const char *const *names; /* CLI_ENUM: NULL-terminated, index 0 unused (not given) */
    int above_lo;             /* 1: the range is (lo, hi], lo itself excluded */
    size_t offset, offset2;   /* into cli_options; offset2 only for CLI_SIZE */
    int (*parse)(const char *value, cli_options *o); /* CLI_CUSTOM: 1 if accepted */
    const char *value;  /* the value's placeholder in usage lines: "WxH", "FILE" */
    const char *expect; /* CLI_CUSTOM: the accepted values, for errors ("egl or osmesa") */
    const char *hint;   /* one line of help */
} cli_option_spec;

/* The spec for `key`, NULL if there is none. */
const cli_option_spec *cli_option_find(const char *key);

/* A command function that only the full program links (the renderer, the window, image files,
 * models, print). `tessera` itself is the lean program (TESSERA_CLI_LEAN: the command line, the
 * app core and the catalog, no renderer): there such a command has no function, and the lean
 * program runs the full one beside it with the same arguments (cli_full_program.c). */
#ifdef TESSERA_CLI_LEAN
#define IN_FULL(fn) NULL
#else
#define IN_FULL(fn) fn
#endif

typedef struct cli_command {
    const char *name;
    int (*run)(const cli_options *o); /* NULL: has sub-commands, or is IN_FULL in the lean one */
    const char *synopsis; /* positional arguments and required options: "PROJECT -o OUT" */
    int min_args, max_args;
    const char *options;                   /* the option keys it takes, space-separated */
    const char *summary;                   /* one line for `tessera --help` */
    const char *help;                      /* more lines for `tessera help CMD` (may be NULL) */
    const struct cli_command *subcommands; /* NULL-name terminated, or NULL */
    const char *parent;                    /* "catalog" for its sub-commands, else NULL */
    void (*defaults)(cli_options *o);      /* presets fields before parsing (may be NULL) */
} cli_command;

/* The top-level commands, terminated by an entry with a NULL name. */
extern const cli_command cli_commands[];

/* 1 if `c` runs in the full program only (its function is IN_FULL and this is the lean one). */
int cli_command_in_full(const cli_command *c);

/* Runs the full program beside this one (tessera-full, found next to /proc/self/exe) with the
 * same argv; returns only when it cannot be run, with CLI_FAILED after saying why. */
int cli_run_full_program(int argc, char **argv);

/* The command called `name` in `table` (NULL-name terminated), or NULL. */
const cli_command *cli_command_find(const cli_command *table, const char *name);

/* Fills `o` from argv[first..] by the options `c` declares. Returns CLI_OK, CLI_USAGE (after
 * naming the problem on stderr) or CLI_HELP (--help or -h was given). */
enum { CLI_HELP = -1 };
int cli_parse_args(const cli_command *c, int argc, char **argv, int first, cli_options *o);

/* `tessera [PARENT] NAME SYNOPSIS [options]`, the summary and help, one line per option. */
void cli_print_usage(const cli_command *c, FILE *f);

/* The allowed values of an option as the errors and help name them ("1 to 4",
 * "on or off", "draft, interactive, final or print"). */
void cli_option_expect(const cli_option_spec *s, char *buf, size_t size);

#endif
