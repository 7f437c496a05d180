/* The command and option tables (app/src/cli/cli_table.h) hold together, and the parser they
 * drive accepts good values and refuses unknown options, missing values and values out of range
 * with the usage exit code. */
#include "../common/check.h"
#include "app/cli/cli.h"
#include "app/scene/quality.h"
#include "cli/cli_table.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Calls fn(key) for each key of a command's space-separated option list. */
static void each_key(const char *keys, void (*fn)(const cli_command *, const char *),
                     const cli_command *c)
{
    while (keys && *keys) {
        size_t n = strcspn(keys, " ");
        if (n) {
            char key[64];
            snprintf(key, sizeof key, "%.*s", (int)n, keys);
            fn(c, key);
        }
        keys += n;
        while (*keys == ' ')
            keys++;
    }
}

static void check_key(const cli_command *c, const char *key)
{
    const cli_option_spec *s = cli_option_find(key);
    CHECK_MSG(s != NULL, "%s declares --%s, which the option table lacks", c->name, key);
    if (!s)
        return;
    CHECK_MSG(s->hint && s->hint[0], "--%s has no hint", key);
    CHECK_MSG(s->kind != CLI_ENUM || (s->names && s->names[1]), "--%s has no names", key);
    CHECK_MSG(s->kind != CLI_CUSTOM || (s->parse && s->expect), "--%s: no parser", key);
    CHECK_MSG(s->lo <= s->hi, "--%s: range %g..%g", key, s->lo, s->hi);
}

/* No two options of one command are spelled alike. */
static void check_unique(const cli_command *c)
{
    const char *names[64];
    char shorts[64];
    int n = 0;
    const char *keys = c->options ? c->options : "";
    while (*keys && n < 64) {
        size_t len = strcspn(keys, " ");
        char key[64];
        snprintf(key, sizeof key, "%.*s", (int)len, keys);
        const cli_option_spec *s = cli_option_find(key);
        if (s) {
            names[n] = s->name ? s->name : s->key;
            shorts[n] = s->short_name;
            for (int i = 0; i < n; i++) {
                CHECK_MSG(strcmp(names[i], names[n]) != 0, "%s: --%s twice", c->name, names[n]);
                CHECK_MSG(!shorts[n] || shorts[i] != shorts[n], "%s: -%c twice", c->name,
                          shorts[n]);
            }
            n++;
        }
        keys += len;
        while (*keys == ' ')
            keys++;
    }
}

static void check_commands(const cli_command *table)
{
    int count = 0;
    for (const cli_command *c = table; c->name; c++, count++) {
        CHECK_MSG(c->summary && c->summary[0], "%s has no summary", c->name);
        CHECK_MSG(c->synopsis != NULL, "%s has no synopsis", c->name);
        CHECK_MSG((c->run != NULL) != (c->subcommands != NULL), "%s: run or sub-commands", c->name);
        CHECK_MSG(c->min_args <= c->max_args, "%s: %d..%d arguments", c->name, c->min_args,
                  c->max_args);
        CHECK_MSG(cli_command_find(table, c->name) == c, "%s is in the table twice", c->name);
        each_key(c->options, check_key, c);
        check_unique(c);
        if (c->subcommands)
            check_commands(c->subcommands);
    }
    CHECK(count > 0);
}

/* Parses `args` (NULL-terminated, after the command's name) for command `name`. */
static int parse(const char *name, cli_options *o, const char *const *args)
{
    char *argv[32] = {"tessera", (char *)name};
    int argc = 2;
    while (*args && argc < 31)
        argv[argc++] = (char *)*args++;
    memset(o, 0, sizeof *o);
    const cli_command *c = cli_command_find(cli_commands, name);
    CHECK_MSG(c != NULL, "no command %s", name);
    return c ? cli_parse_args(c, argc, argv, 2, o) : CLI_USAGE;
}

static void check_parser(void)
{
    cli_options o;
    CHECK(parse("render", &o,
                (const char *const[]){"p.json", "-o", "x.png", "--size", "320x180", "--supersample",
                                      "2", "--quality", "print", "--room-probe", "off",
                                      "--exact-lamps", "on", "--self-reflections", "5", "--shadows",
                                      "hard", "--all-views", NULL}) == CLI_OK);
    CHECK(o.project && !strcmp(o.project, "p.json"));
    CHECK(o.output && !strcmp(o.output, "x.png"));
    CHECK(o.width == 320 && o.height == 180 && o.supersample == 2);
    CHECK(o.quality == app_quality_find("print"));
    CHECK(o.room_probe == RD_SWITCH_OFF && o.exact_lamps == RD_SWITCH_ON);
    CHECK(o.planar_mirrors == RD_SWITCH_UNSET && o.adaptive == RD_SWITCH_UNSET);
    CHECK(o.self_reflections == RD_SWITCH_ON && o.self_rays == 5);
    CHECK(o.shadows == (int)RD_SHADOWS_HARD + 1);
    CHECK(o.all_views == 1);

    /* Refused, each with the usage exit code. */
    CHECK(parse("render", &o, (const char *const[]){"p.json", "--frobnicate", "1", NULL}) ==
          CLI_USAGE);
    CHECK(parse("render", &o, (const char *const[]){"p.json", "--size", NULL}) == CLI_USAGE);
    CHECK(parse("render", &o, (const char *const[]){"p.json", "--supersample", "9", NULL}) ==
          CLI_USAGE);
    CHECK(parse("render", &o, (const char *const[]){"p.json", "--size", "0x10", NULL}) ==
          CLI_USAGE);
    CHECK(parse("render", &o, (const char *const[]){"p.json", "--room-probe", "maybe", NULL}) ==
          CLI_USAGE);
    CHECK(parse("render", &o, (const char *const[]){"a.json", "b.json", NULL}) == CLI_USAGE);
    CHECK(parse("render", &o, (const char *const[]){NULL}) == CLI_USAGE); /* no project */
    CHECK(parse("compare", &o, (const char *const[]){"a.png", "--heat-max", "0", NULL}) ==
          CLI_USAGE);
    /* An option another command takes is unknown here. */
    CHECK(parse("compare", &o, (const char *const[]){"a.png", "b.png", "--size", "4x4", NULL}) ==
          CLI_USAGE);

    /* Help anywhere; the same spelling as another kind in another command. */
    CHECK(parse("render", &o, (const char *const[]){"p.json", "-h", NULL}) == CLI_HELP);
    CHECK(parse("quantities", &o, (const char *const[]){"p.json", "--csv", NULL}) == CLI_OK);
    CHECK(o.csv_table == 1 && o.csv == NULL);
    CHECK(parse("bench", &o, (const char *const[]){"p.json", "--csv", "t.csv", NULL}) == CLI_OK);
    CHECK(o.csv && !strcmp(o.csv, "t.csv") && o.csv_table == 0);
    CHECK(parse("reference", &o, (const char *const[]){"p.json", "--seed", "4294967295", NULL}) ==
          CLI_OK);
    CHECK(o.seed == 4294967295LL);
}

static void check_expect(void)
{
    char buf[160];
    cli_option_expect(cli_option_find("supersample"), buf, sizeof buf);
    CHECK_MSG(!strcmp(buf, "1 to 4"), "%s", buf);
    cli_option_expect(cli_option_find("room-probe"), buf, sizeof buf);
    CHECK_MSG(!strcmp(buf, "on or off"), "%s", buf);
    cli_option_expect(cli_option_find("probes"), buf, sizeof buf);
    CHECK_MSG(!strcmp(buf, "every-frame, once, on-change or time-sliced"), "%s", buf);
}

/* Runs `tessera ARGS...` in this process with standard output in `out`; the exit code. */
static int run_captured(int argc, char **argv, char *out, size_t size)
{
    fflush(stdout);
    FILE *tmp = tmpfile();
    int saved = dup(1);
    if (!tmp || saved < 0 || dup2(fileno(tmp), 1) < 0) {
        CHECK_MSG(0, "cannot capture standard output");
        return -1;
    }
    int rc = app_cli_main(argc, argv);
    fflush(stdout);
    dup2(saved, 1);
    close(saved);
    rewind(tmp);
    size_t n = fread(out, 1, size - 1, tmp);
    out[n] = 0;
    fclose(tmp);
    return rc;
}

/* `CMD --help`, `CMD -h` and `tessera help CMD` (CMD one or two words): exit 0 and the usage
 * on standard output; `tessera --help` names it. */
static void check_help(const char *parent, const char *name, const char *overview)
{
    static char out[16384];
    char path[64];
    snprintf(path, sizeof path, "%s%s%s", parent ? parent : "", parent ? " " : "", name);
    char usage[96];
    snprintf(usage, sizeof usage, "usage: tessera %s", path);
    static const char *const flags[3] = {"--help", "-h", NULL};
    for (int f = 0; f < 3; f++) {
        char *argv[5] = {"tessera"};
        int argc = 1;
        if (!flags[f])
            argv[argc++] = "help";
        if (parent)
            argv[argc++] = (char *)parent;
        argv[argc++] = (char *)name;
        if (flags[f])
            argv[argc++] = (char *)flags[f];
        int rc = run_captured(argc, argv, out, sizeof out);
        const char *form = flags[f] ? flags[f] : "(tessera help)";
        CHECK_MSG(rc == 0, "tessera %s %s: exit code %d", path, form, rc);
        CHECK_MSG(strstr(out, usage) != NULL, "tessera %s %s: no \"%s\" on stdout", path, form,
                  usage);
    }
    char line[96];
    snprintf(line, sizeof line, "  tessera %s", parent ? parent : name);
    CHECK_MSG(strstr(overview, line) != NULL, "tessera --help does not name %s", path);
}

static void check_every_help(void)
{
    static char overview[16384];
    CHECK(run_captured(2, (char *[]){"tessera", "--help", NULL}, overview, sizeof overview) == 0);
    for (const cli_command *c = cli_commands; c->name; c++) {
        check_help(NULL, c->name, overview);
        for (const cli_command *s = c->subcommands; s && s->name; s++)
            check_help(c->name, s->name, overview);
    }
}

int main(void)
{
    check_commands(cli_commands);
    check_parser();
    check_expect();
    check_every_help();
    return check_report("test_cli_table");
}
