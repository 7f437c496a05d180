/* APP_CMD_SET_PROBE: a material's reflection probe policy (for power users):
 * how often its probe is captured, at what resolution, and how its lookups are corrected
 * (RENDERING.md section 8; render/render.h rd_probe_desc, rd_correction). Like
 * APP_CMD_SET_REFLECTION it edits the material, so every object that shares the material
 * follows. The checks are the project reader's (app/src/project/project_read_reflection.c), so
 * every policy a command sets can be saved and read back. Also the words of the `probe` edit line
 * (docs/editing.md). */
#include "cmd_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The project file's names (project_read_reflection.c), in APP_PROBE_* / APP_CORRECTION_*
 * order. */
static const char *const update_names[6] = {"default",   "every-frame", "once",
                                            "on-change", "time-sliced", "static"};
static const char *const correction_names[5] = {"default", "none", "box", "sphere", "depth"};

static app_result fail(char *err, size_t err_size, app_result r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static app_result fail(char *err, size_t err_size, app_result r, const char *fmt, ...)
{
    if (err && err_size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, err_size, fmt, ap);
        va_end(ap);
    }
    return r;
}

const char *cmd_probe_update_name(int update)
{
    return update >= 0 && update < 6 ? update_names[update] : "?";
}

const char *cmd_correction_name(int correction)
{
    return correction >= 0 && correction < 5 ? correction_names[correction] : "?";
}

static int is_power_of_two(int n)
{
    return n > 0 && (n & (n - 1)) == 0;
}

app_result cmd_build_probe(const app_project *p, const app_command_desc *d, cmd_command *c,
                           char *err, size_t err_size)
{
    if (d->index < 0 || d->index >= p->material_count)
        return fail(err, err_size, APP_ERR_NOT_FOUND, "no material %d (there are %d)", d->index,
                    p->material_count);
    const app_material *old = &p->materials[d->index];
    if (d->probe_update < APP_PROBE_DEFAULT || d->probe_update > APP_PROBE_STATIC)
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "material \"%s\": probe update %d is not a policy (0-5)", old->name,
                    d->probe_update);
    /* A static probe shows a prepared cube map; only the project file can name one. */
    if (d->probe_update == APP_PROBE_STATIC && !old->probe_map[0])
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "material \"%s\": update static needs a prepared map (\"probe\": {\"map\": "
                    "...} in the project file)",
                    old->name);
    if (d->probe_every < 0 || d->probe_every > 1000000)
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "material \"%s\": probe every %d: 0 to 1000000 frames", old->name,
                    d->probe_every);
    if (d->probe_resolution != 0 &&
        (!is_power_of_two(d->probe_resolution) || d->probe_resolution > 4096))
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "material \"%s\": probe resolution %d: auto (0) or a power of two from 1 "
                    "to 4096",
                    old->name, d->probe_resolution);
    if (d->correction < APP_CORRECTION_DEFAULT || d->correction > APP_CORRECTION_DEPTH)
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "material \"%s\": correction %d is not one of default, none, box, sphere, "
                    "depth",
                    old->name, d->correction);
    app_material m = *old;
    m.probe_update = d->probe_update;
    m.probe_every = d->probe_every;
    m.probe_resolution = d->probe_resolution;
    m.correction = d->correction;
    /* The reader takes a prepared map to mean a static probe (project_read_reflection.c), so
     * a live policy drops the map, or the file would read back static; undo restores it. */
    if (m.probe_update != APP_PROBE_STATIC)
        memset(m.probe_map, 0, sizeof m.probe_map);
    snprintf(c->label, sizeof c->label, "set the probe of \"%s\"", m.name);
    return cmd_add_edit(c, CMD_T_MATERIAL, CMD_OP_REPLACE, d->index, old, &m);
}

static int name_index(const char *word, const char *const *names, int count)
{
    for (int i = 0; i < count; i++)
        if (!strcmp(word, names[i]))
            return i;
    return -1;
}

/* A whole number in [lo, hi] written as digits (no sign, fraction or exponent). */
static int whole(const char *word, int lo, int hi, int *out)
{
    if (!*word || strspn(word, "0123456789") != strlen(word) || strlen(word) > 9)
        return 0;
    long v = strtol(word, NULL, 10);
    if (v < lo || v > hi)
        return 0;
    *out = (int)v;
    return 1;
}

int cmd_probe_words(const app_material *m, int count, const char *const *words, app_command_desc *d,
                    char *why, size_t why_size)
{
    d->type = APP_CMD_SET_PROBE;
    d->probe_update = m->probe_update;
    d->probe_every = m->probe_every;
    d->probe_resolution = m->probe_resolution;
    d->correction = m->correction;
    if (count == 0) {
        snprintf(why, why_size,
                 "probe: nothing to set (update POLICY, every N, resolution auto|N, correction "
                 "KIND)");
        return 0;
    }
    int have_update = 0, have_every = 0;
    for (int i = 0; i < count; i += 2) {
        const char *key = words[i], *value = i + 1 < count ? words[i + 1] : NULL;
        if (strcmp(key, "update") && strcmp(key, "every") && strcmp(key, "resolution") &&
            strcmp(key, "correction")) {
            snprintf(why, why_size,
                     "probe: unexpected word \"%s\" (update, every, resolution, correction)", key);
            return 0;
        }
        if (!value) {
            snprintf(why, why_size, "probe: %s needs a value", key);
            return 0;
        }
        if (!strcmp(key, "update")) {
            if ((d->probe_update = name_index(value, update_names, 6)) < 0) {
                snprintf(why, why_size,
                         "probe: update is default, every-frame, once, on-change, time-sliced or "
                         "static, not \"%s\"",
                         value);
                return 0;
            }
            have_update = 1;
        } else if (!strcmp(key, "every")) {
            if (!whole(value, 1, 1000000, &d->probe_every)) {
                snprintf(why, why_size,
                         "probe: every is a whole number of frames from 1 to "
                         "1000000, not \"%s\"",
                         value);
                return 0;
            }
            have_every = 1;
        } else if (!strcmp(key, "resolution")) {
            if (!strcmp(value, "auto"))
                d->probe_resolution = 0;
            else if (!whole(value, 1, 4096, &d->probe_resolution) ||
                     !is_power_of_two(d->probe_resolution)) {
                snprintf(why, why_size,
                         "probe: resolution is auto or a power of two from 1 to 4096, not "
                         "\"%s\"",
                         value);
                return 0;
            }
        } else if ((d->correction = name_index(value, correction_names, 5)) < 0) {
            snprintf(why, why_size,
                     "probe: correction is default, none, box, sphere or depth, not \"%s\"", value);
            return 0;
        }
    }
    /* "every N" is the every-frame policy's period: alone it selects that policy; with
     * another policy it would mean nothing, which is refused rather than stored. */
    if (have_every && !have_update)
        d->probe_update = APP_PROBE_EVERY_FRAME;
    if (have_every && d->probe_update != APP_PROBE_EVERY_FRAME) {
        snprintf(why, why_size, "probe: every N goes with update every-frame, not %s",
                 update_names[d->probe_update]);
        return 0;
    }
    if (have_update && !have_every && d->probe_update != APP_PROBE_EVERY_FRAME)
        d->probe_every = 0; /* the period of another policy is dropped */
    return 1;
}
