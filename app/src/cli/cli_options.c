#include "cli_options.h"

#include "app/scene/quality.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

double cli_now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

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

static int parse_int(const char *text, int lo, int hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end || errno || v < lo || v > hi)
        return 0;
    *out = (int)v;
    return 1;
}

/* Names by enum value; index 0 (the default) is not accepted on the command line. */
static const char *const probe_names[5] = {"", "every-frame", "once", "on-change", "time-sliced"};
static const char *const blur_names[4] = {"", "prefiltered", "box-mips", "reference"};
static const char *const ambient_names[3] = {"", "constant", "sh9"};

static int parse_name(const char *text, const char *const *names, int count, int *out)
{
    for (int i = 1; i < count; i++)
        if (!strcmp(text, names[i])) {
            *out = i;
            return 1;
        }
    return 0;
}

static int allowed_option(const char *allowed, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = allowed; (p = strstr(p, name)); p += n)
        if ((p == allowed || p[-1] == ' ') && (p[n] == ' ' || p[n] == 0))
            return 1;
    return 0;
}

int cli_parse(int argc, char **argv, int first, const char *command, const char *allowed,
              cli_options *o)
{
    for (int i = first; i < argc; i++) {
        const char *a = argv[i];
        const char *name = NULL;
        if (!strcmp(a, "-o"))
            name = "output";
        else if (!strncmp(a, "--", 2))
            name = a + 2;
        if (!name) {
            if (o->project) {
                fprintf(stderr, "tessera %s: unexpected argument \"%s\"\n", command, a);
                return CLI_USAGE;
            }
            o->project = a;
            continue;
        }
        if (!allowed_option(allowed, name)) {
            fprintf(stderr, "tessera %s: unknown option \"%s\"\n", command, a);
            return CLI_USAGE;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "tessera %s: option %s needs a value\n", command, a);
            return CLI_USAGE;
        }
        const char *v = argv[++i];
        int ok = 1;
        if (!strcmp(name, "output"))
            o->output = v;
        else if (!strcmp(name, "camera"))
            o->camera = v;
        else if (!strcmp(name, "csv"))
            o->csv = v;
        else if (!strcmp(name, "quality"))
            ok = (o->quality = app_quality_find(v)) != NULL;
        else if (!strcmp(name, "plot"))
            o->plot = v;
        else if (!strcmp(name, "markdown"))
            o->markdown = v;
        else if (!strcmp(name, "animate"))
            o->animate = v;
        else if (!strcmp(name, "samples"))
            ok = parse_int(v, 1, 1 << 20, &o->samples);
        else if (!strcmp(name, "size"))
            ok = cli_parse_size(v, &o->width, &o->height);
        else if (!strcmp(name, "supersample"))
            ok = parse_int(v, 1, 4, &o->supersample);
        else if (!strcmp(name, "self-reflections") && strcmp(v, "on") && strcmp(v, "off")) {
            /* a number: the lobe directions a sample (rd_reflection_defaults) */
            ok = parse_int(v, 1, 16, &o->self_rays);
            o->self_reflections = 1;
        } else if (!strcmp(name, "probe-resolution"))
            ok = parse_int(v, 16, 2048, &o->probe_resolution);
        else if (!strcmp(name, "adaptive") || !strcmp(name, "planar-mirrors") ||
                 !strcmp(name, "room-probe") || !strcmp(name, "exact-lamps") ||
                 !strcmp(name, "self-reflections")) {
            ok = !strcmp(v, "on") || !strcmp(v, "off");
            *(!strcmp(name, "adaptive")         ? &o->adaptive
              : !strcmp(name, "planar-mirrors") ? &o->planar_mirrors
              : !strcmp(name, "room-probe")     ? &o->room_probe
              : !strcmp(name, "exact-lamps")    ? &o->exact_lamps
                                                : &o->self_reflections) = !strcmp(v, "on") ? 1 : 2;
        } else if (!strcmp(name, "frames"))
            ok = parse_int(v, 1, 100000, &o->frames);
        else if (!strcmp(name, "warmup"))
            ok = parse_int(v, 0, 100000, &o->warmup);
        else if (!strcmp(name, "probes"))
            ok = parse_name(v, probe_names, 5, (int *)&o->probes);
        else if (!strcmp(name, "ambient"))
            ok = parse_name(v, ambient_names, 3, &o->ambient);
        else if (!strcmp(name, "blur"))
            ok = parse_name(v, blur_names, 4, (int *)&o->blur);
        else if (!strcmp(name, "shadows")) {
            rd_shadow_mode m;
            ok = rd_shadow_mode_parse(v, &m) == RD_OK;
            o->shadows = ok ? (int)m + 1 : 0;
        } else if (!strcmp(name, "dpi"))
            ok = parse_int(v, 1, 100000, &o->dpi);
        else if (!strcmp(name, "tile"))
            ok = parse_int(v, 16, 65536, &o->tile);
        else if (!strcmp(name, "faces"))
            o->faces = v;
        else if (!strcmp(name, "fps"))
            ok = parse_int(v, 1, 240, &o->fps);
        else if (!strcmp(name, "seconds")) {
            char *end;
            o->seconds = strtod(v, &end);
            ok = end != v && !*end && o->seconds > 0.0 && o->seconds <= 3600.0;
        } else if (!strcmp(name, "backend"))
            ok = rd_backend_parse(v, &o->backend) == RD_OK && o->backend != RD_BACKEND_ADOPT;
        if (!ok) {
            fprintf(stderr, "tessera %s: bad value \"%s\" for --%s%s\n", command, v, name,
                    !strcmp(name, "size")               ? " (expected WIDTHxHEIGHT, e.g. 1280x720)"
                    : !strcmp(name, "backend")          ? " (expected egl or osmesa)"
                    : !strcmp(name, "supersample")      ? " (expected 1 to 4)"
                    : !strcmp(name, "self-reflections") ? " (expected on, off or 1 to 16)"
                    : !strcmp(name, "probe-resolution") ? " (expected 16 to 2048 texels)"
                    : !strcmp(name, "adaptive") || !strcmp(name, "planar-mirrors") ||
                            !strcmp(name, "room-probe") || !strcmp(name, "exact-lamps")
                        ? " (expected on or off)"
                    : !strcmp(name, "probes")
                        ? " (expected every-frame, once, on-change or time-sliced)"
                    : !strcmp(name, "blur")    ? " (expected prefiltered, box-mips or reference)"
                    : !strcmp(name, "ambient") ? " (expected constant or sh9)"
                    : !strcmp(name, "quality") ? " (expected draft, interactive, final or print)"
                    : !strcmp(name, "shadows") ? " (expected off, hard or soft)"
                    : !strcmp(name, "tile")    ? " (expected 16 to 65536 pixels)"
                    : !strcmp(name, "seconds") ? " (expected more than 0, at most 3600)"
                                               : "");
            return CLI_USAGE;
        }
    }
    return CLI_OK;
}
