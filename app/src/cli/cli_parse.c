/* The table-driven parser and usage printer: argv against the options a command declares
 * (cli_table.h). */
#include "cli_table.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int cli_parse_size(const char *text, int *w, int *h)
{
    char *end;
    errno = 0;
    long a = strtol(text, &end, 10);
    if (end == text || (*end != 'x' && *end != 'X') || errno)
        return 0;
    const char *second = end + 1;
    long b = strtol(second, &end, 10);
    if (end == second || *end || errno)
        return 0;
    if (a < 1 || b < 1 || a > 1000000 || b > 1000000)
        return 0;
    *w = (int)a;
    *h = (int)b;
    return 1;
}

static const char *option_name(const cli_option_spec *s)
{
    return s->name ? s->name : s->key;
}

static int in_range(const cli_option_spec *s, double v)
{
    return (s->above_lo ? v > s->lo : v >= s->lo) && v <= s->hi;
}

void cli_option_expect(const cli_option_spec *s, char *buf, size_t size)
{
    buf[0] = 0;
    switch (s->kind) {
    case CLI_INT:
    case CLI_LONG:
        snprintf(buf, size, "%.0f to %.0f", s->lo, s->hi);
        break;
    case CLI_FLOAT:
        snprintf(buf, size, "%s %g, at most %g", s->above_lo ? "more than" : "at least", s->lo,
                 s->hi);
        break;
    case CLI_SIZE:
        snprintf(buf, size, "WIDTHxHEIGHT, each side %.0f to %.0f, e.g. 1280x720", s->lo, s->hi);
        break;
    case CLI_SWITCH:
        snprintf(buf, size, "on or off");
        break;
    case CLI_ENUM: {
        int n = 0;
        while (s->names[n + 1])
            n++;
        size_t used = 0;
        for (int i = 1; i <= n && used < size; i++)
            used += (size_t)snprintf(buf + used, size - used, "%s%s",
                                     i == 1   ? ""
                                     : i == n ? " or "
                                              : ", ",
                                     s->names[i]);
        break;
    }
    case CLI_CUSTOM:
        snprintf(buf, size, "%s", s->expect);
        break;
    case CLI_FLAG:
    case CLI_STRING:
        break;
    }
}

/* Stores `v` into the field of `s`; 0 if it is not an allowed value. */
static int store(const cli_option_spec *s, const char *v, cli_options *o)
{
    char *field = (char *)o + s->offset;
    char *end;
    errno = 0;
    switch (s->kind) {
    case CLI_FLAG:
        *(int *)field = 1;
        return 1;
    case CLI_STRING:
        *(const char **)field = v;
        return 1;
    case CLI_INT:
    case CLI_LONG: {
        long long n = strtoll(v, &end, 10);
        if (end == v || *end || errno || !in_range(s, (double)n))
            return 0;
        if (s->kind == CLI_INT)
            *(int *)field = (int)n;
        else
            *(long long *)field = n;
        return 1;
    }
    case CLI_FLOAT: {
        double x = strtod(v, &end);
        if (end == v || *end || errno || !isfinite(x) || !in_range(s, x))
            return 0;
        *(double *)field = x;
        return 1;
    }
    case CLI_SIZE: {
        int w, h;
        if (!cli_parse_size(v, &w, &h) || !in_range(s, w) || !in_range(s, h))
            return 0;
        *(int *)field = w;
        *(int *)((char *)o + s->offset2) = h;
        return 1;
    }
    case CLI_SWITCH:
        if (strcmp(v, "on") && strcmp(v, "off"))
            return 0;
        *(rd_switch *)field = !strcmp(v, "on") ? RD_SWITCH_ON : RD_SWITCH_OFF;
        return 1;
    case CLI_ENUM:
        for (int i = 1; s->names[i]; i++)
            if (!strcmp(v, s->names[i])) {
                *(int *)field = i;
                return 1;
            }
        return 0;
    case CLI_CUSTOM:
        return s->parse && s->parse(v, o);
    }
    return 0;
}

static void command_path(const cli_command *c, char *buf, size_t size)
{
    snprintf(buf, size, "%s%s%s", c->parent ? c->parent : "", c->parent ? " " : "", c->name);
}

/* The option of `c` spelled `arg` ("--size", "-o"), or NULL. */
static const cli_option_spec *declared(const cli_command *c, const char *arg)
{
    const char *keys = c->options ? c->options : "";
    while (*keys) {
        while (*keys == ' ')
            keys++;
        size_t n = strcspn(keys, " ");
        if (!n)
            break;
        char key[64];
        snprintf(key, sizeof key, "%.*s", (int)n, keys);
        keys += n;
        const cli_option_spec *s = cli_option_find(key);
        if (!s)
            continue;
        if (arg[0] == '-' && arg[1] == '-' && !strcmp(arg + 2, option_name(s)))
            return s;
        if (arg[0] == '-' && s->short_name && arg[1] == s->short_name && !arg[2])
            return s;
    }
    return NULL;
}

int cli_parse_args(const cli_command *c, int argc, char **argv, int first, cli_options *o)
{
    char cmd[64], expect[160];
    command_path(c, cmd, sizeof cmd);
    o->command = c;
    for (int i = first; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h"))
            return CLI_HELP;
        if (a[0] != '-' || !a[1]) { /* "-" alone is an argument: standard input */
            if (o->arg_count >= c->max_args) {
                fprintf(stderr, "tessera %s: unexpected argument \"%s\"\n", cmd, a);
                return cli_usage_error(o);
            }
            o->args[o->arg_count++] = a;
            continue;
        }
        const cli_option_spec *s = declared(c, a);
        if (!s) {
            fprintf(stderr, "tessera %s: unknown option \"%s\"\n", cmd, a);
            return cli_usage_error(o);
        }
        cli_option_expect(s, expect, sizeof expect);
        if (s->kind == CLI_FLAG) {
            store(s, NULL, o);
            continue;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "tessera %s: option %s needs a value%s%s%s\n", cmd, a,
                    expect[0] ? " (expected " : "", expect, expect[0] ? ")" : "");
            return CLI_USAGE;
        }
        const char *v = argv[++i];
        if (!store(s, v, o)) {
            fprintf(stderr, "tessera %s: bad value \"%s\" for --%s (expected %s)\n", cmd, v,
                    option_name(s), expect);
            return CLI_USAGE;
        }
    }
    o->project = o->arg_count ? o->args[0] : NULL;
    if (o->arg_count < c->min_args) {
        fprintf(stderr, "tessera %s: missing %s\n", cmd, c->synopsis);
        return cli_usage_error(o);
    }
    return CLI_OK;
}

int cli_usage_error(const cli_options *o)
{
    if (o->command)
        cli_print_usage(o->command, stderr);
    return CLI_USAGE;
}

static void print_option(const cli_option_spec *s, FILE *f)
{
    char left[224], expect[160];
    cli_option_expect(s, expect, sizeof expect);
    const char *value = s->value;
    char enum_value[96];
    if (s->kind == CLI_ENUM) { /* "a|b|c" from the names */
        size_t used = 0;
        enum_value[0] = 0;
        for (int i = 1; s->names[i] && used < sizeof enum_value; i++)
            used += (size_t)snprintf(enum_value + used, sizeof enum_value - used, "%s%s",
                                     i > 1 ? "|" : "", s->names[i]);
        value = enum_value;
    }
    if (s->short_name)
        snprintf(left, sizeof left, "-%c, --%s %s", s->short_name, option_name(s),
                 value ? value : "");
    else
        snprintf(left, sizeof left, "--%s%s%s", option_name(s), value ? " " : "",
                 value ? value : "");
    if (strlen(left) > 30) /* the hint on a line of its own */
        fprintf(f, "  %s\n  %-30s %s", left, "", s->hint);
    else
        fprintf(f, "  %-30s %s", left, s->hint);
    if ((s->kind == CLI_INT || s->kind == CLI_LONG || s->kind == CLI_FLOAT) && expect[0])
        fprintf(f, " [%s]", expect);
    fputc('\n', f);
}

void cli_print_usage(const cli_command *c, FILE *f)
{
    char cmd[64];
    command_path(c, cmd, sizeof cmd);
    int has_options = c->options && c->options[0];
    fprintf(f, "usage: tessera %s%s%s%s\n", cmd, c->synopsis[0] ? " " : "", c->synopsis,
            c->subcommands ? " ..."
            : has_options  ? " [options]"
                           : "");
    fprintf(f, "  %s\n", c->summary);
    if (c->help)
        fprintf(f, "%s", c->help);
    if (c->subcommands) {
        fprintf(f, "commands (tessera %s COMMAND --help):\n", cmd);
        for (const cli_command *s = c->subcommands; s->name; s++)
            fprintf(f, "  %-12s %s\n", s->name, s->summary);
    }
    if (has_options) {
        fprintf(f, "options:\n");
        const char *keys = c->options;
        while (*keys) {
            size_t n = strcspn(keys, " ");
            if (n) {
                char key[64];
                snprintf(key, sizeof key, "%.*s", (int)n, keys);
                const cli_option_spec *s = cli_option_find(key);
                if (s)
                    print_option(s, f);
            }
            keys += n;
            while (*keys == ' ')
                keys++;
        }
    }
}

const cli_command *cli_command_find(const cli_command *table, const char *name)
{
    for (const cli_command *c = table; name && c->name; c++)
        if (!strcmp(c->name, name))
            return c;
    return NULL;
}
