/* Edit scripts: one command per line, replayed through an app_history (`tessera edit`). The
 * format is documented in docs/editing.md; every error names the script line. */
#include "app/design/snap_guides.h"
#include "app/project/commands.h"
#include "cmd_internal.h" /* cmd_probe_words */

#include "catalog/catalog.h"
#include "catalog/model_gen.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_TOKENS 48
#define MAX_LINE 4096
/* How far `snap wall` looks for a wall, and `snap corner` / `snap neighbour` for a corner or
 * a neighbour (mm); a neighbour is kept at the 200 mm of DOMAIN.md "Clearances". */
#define SNAP_WALL_MM 500.0
/* A dropped product looks for its carrier (a basin for its vanity) this far from the point. */
#define MOUNT_REACH_MM 300.0
/* A tap's hole: this far forward of the basin's back face (a one-hole furniture basin's hole
 * sits 50-60 mm in front of the back rim). */
#define TAP_HOLE_MM 50.0
/* A mirror's underside above the basin's rim: 300 mm leaves room for the tap and splashes
 * (the designed demo: rim 850, mirror from 1150). */
#define MIRROR_ABOVE_MM 300.0
#define SNAP_CORNER_MM 300.0
#define SNAP_NEIGHBOUR_MM 300.0
#define NEIGHBOUR_GAP_MM 200.0

typedef struct sctx {
    app_project *p;
    app_history *h;
    const app_script_env *env;
    app_script_stats *st;
    char *tok[MAX_TOKENS];
    int ntok;
    int used[MAX_TOKENS];
    char msg[1024];
} sctx;

static int fail(sctx *c, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static int fail(sctx *c, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->msg, sizeof c->msg, fmt, ap);
    va_end(ap);
    return 0;
}

/* Splits a line into words; "double quotes" hold spaces, # starts a comment. */
static int tokenize(sctx *c, char *line)
{
    c->ntok = 0;
    char *r = line;
    for (;;) {
        while (*r == ' ' || *r == '\t' || *r == '\r' || *r == '\n')
            r++;
        if (!*r || *r == '#')
            return 1;
        if (c->ntok == MAX_TOKENS)
            return fail(c, "more than %d words on a line", MAX_TOKENS);
        char *w = r;
        c->tok[c->ntok] = w;
        c->used[c->ntok++] = 0;
        if (*r == '"') {
            r++;
            c->tok[c->ntok - 1] = r;
            char *end = strchr(r, '"');
            if (!end)
                return fail(c, "a quote is not closed");
            *end = 0;
            r = end + 1;
            if (*r && *r != ' ' && *r != '\t' && *r != '\r' && *r != '\n')
                return fail(c, "expected a space after the closing quote");
            continue;
        }
        while (*r && *r != ' ' && *r != '\t' && *r != '\r' && *r != '\n')
            r++;
        if (*r)
            *r++ = 0;
    }
}

/* 1: s is a decimal number: [+-] digits [. digits] [e [+-] digits], with a digit somewhere
 * before the exponent. strtod alone would also take 0x100 (256), inf and nan, none of which a
 * hand-written script means as a size in millimetres. */
static int decimal_syntax(const char *s)
{
    const char *digits = "0123456789";
    if (*s == '+' || *s == '-')
        s++;
    size_t n = strspn(s, digits);
    s += n;
    if (*s == '.') {
        s++;
        size_t f = strspn(s, digits);
        s += f;
        n += f;
    }
    if (!n)
        return 0;
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-')
            s++;
        size_t e = strspn(s, digits);
        if (!e)
            return 0;
        s += e;
    }
    return *s == '\0';
}

static int number(sctx *c, int i, double *out)
{
    if (i >= c->ntok)
        return fail(c, "%s: a number is missing at the end", c->tok[0]);
    if (!decimal_syntax(c->tok[i]))
        return fail(c,
                    "%s: expected a number, got \"%s\" (decimal digits only, such as 12 or -0.5)",
                    c->tok[0], c->tok[i]);
    char *end;
    double v = strtod(c->tok[i], &end);
    if (end == c->tok[i] || *end || !isfinite(v))
        return fail(c, "%s: expected a number, got \"%s\"", c->tok[0], c->tok[i]);
    c->used[i] = 1;
    *out = v;
    return 1;
}

static int integer(sctx *c, int i, int *out)
{
    double v;
    if (!number(c, i, &v))
        return 0;
    if (v != floor(v) || fabs(v) > 1e6)
        return fail(c, "%s: expected a whole number, got \"%s\"", c->tok[0], c->tok[i]);
    *out = (int)v;
    return 1;
}

/* A wall number given as a number word: whole and in int range (the command checks it
 * names a wall). */
static int wall_index(sctx *c, double v, int *out)
{
    if (v != floor(v) || fabs(v) > 1e6)
        return fail(c, "%s: a wall is a whole number, not %g", c->tok[0], v);
    *out = (int)v;
    return 1;
}

static int word(sctx *c, int i, const char **out)
{
    if (i >= c->ntok)
        return fail(c, "%s: a word is missing at the end", c->tok[0]);
    c->used[i] = 1;
    *out = c->tok[i];
    return 1;
}

/* Index of the keyword `key` at or after `from`, or -1. */
static int keyword(sctx *c, int from, const char *key)
{
    for (int i = from; i < c->ntok; i++)
        if (!c->used[i] && !strcmp(c->tok[i], key)) {
            c->used[i] = 1;
            return i;
        }
    return -1;
}

/* `key N1 .. Nn` somewhere after `from`: returns 1 and fills vals, 0 on a bad number or when
 * required and absent (message set), -1 when absent and optional. */
static int kw_numbers(sctx *c, int from, const char *key, int n, double *vals, int required)
{
    int i = keyword(c, from, key);
    if (i < 0)
        return required ? fail(c, "%s: \"%s\" is missing", c->tok[0], key) : -1;
    for (int k = 0; k < n; k++)
        if (!number(c, i + 1 + k, &vals[k]))
            return 0;
    return 1;
}

static int kw_word(sctx *c, int from, const char *key, const char **out, int required)
{
    int i = keyword(c, from, key);
    if (i < 0)
        return required ? fail(c, "%s: \"%s\" is missing", c->tok[0], key) : -1;
    return word(c, i + 1, out);
}

static int all_used(sctx *c)
{
    for (int i = 1; i < c->ntok; i++)
        if (!c->used[i])
            return fail(c, "%s: unexpected word \"%s\"", c->tok[0], c->tok[i]);
    return 1;
}

static int copy_name(sctx *c, char *dst, size_t size, const char *src, const char *what)
{
    if (strlen(src) >= size)
        return fail(c, "%s: the %s \"%s\" is longer than %zu bytes", c->tok[0], what, src,
                    size - 1);
    memcpy(dst, src, strlen(src) + 1);
    return 1;
}

static int find_object(sctx *c, const char *name)
{
    for (int i = 0; i < c->p->object_count; i++)
        if (!strcmp(c->p->objects[i].name, name))
            return i;
    return fail(c, "%s: no object named \"%s\"", c->tok[0], name) - 1;
}

static int find_named(sctx *c, const char *name, const char *what, int count, const char *first,
                      size_t stride)
{
    for (int i = 0; i < count; i++)
        if (!strcmp(first + (size_t)i * stride, name))
            return i;
    return fail(c, "%s: no %s named \"%s\"", c->tok[0], what, name) - 1;
}

#define FIND_OPENING(c, n)                                                                         \
    find_named(c, n, "opening", (c)->p->plan.opening_count,                                        \
               (c)->p->plan.openings ? (c)->p->plan.openings[0].name : NULL, sizeof(app_opening))
#define FIND_PREWALL(c, n)                                                                         \
    find_named(c, n, "pre-wall", (c)->p->plan.prewall_count,                                       \
               (c)->p->plan.prewalls ? (c)->p->plan.prewalls[0].name : NULL, sizeof(app_prewall))
#define FIND_NICHE(c, n)                                                                           \
    find_named(c, n, "niche", (c)->p->plan.niche_count,                                            \
               (c)->p->plan.niches ? (c)->p->plan.niches[0].name : NULL, sizeof(app_niche))

/* The tiling on `surface` (the first), or the tiling named so; -1 if none. */
static int find_tiling(sctx *c, const char *surface)
{
    for (int i = 0; i < c->p->tiling_count; i++)
        if (!strcmp(c->p->tilings[i].surface, surface))
            return i;
    for (int i = 0; i < c->p->tiling_count; i++)
        if (!strcmp(c->p->tilings[i].name, surface))
            return i;
    return -1;
}

static int run(sctx *c, app_command_desc *d)
{
    char err[1024];
    if (app_history_do(c->h, c->p, d, err, sizeof err) != APP_OK)
        return fail(c, "%s: %s", c->tok[0], err);
    c->st->commands++;
    return 1;
}

static int lookup(sctx *c, const app_product_ref *ref, app_product_info *info)
{
    if (!c->env || !c->env->lookup)
        return fail(c, "%s: no catalog to look products up in", c->tok[0]);
    char err[1024];
    if (c->env->lookup(c->env->user, ref, info, err, sizeof err) != APP_OK)
        return fail(c, "%s: %s", c->tok[0], err);
    return 1;
}

/* Product words: MANUFACTURER ARTICLE [VARIANT] in tokens [from, to). */
static int product_ref(sctx *c, int from, int to, app_product_ref *ref)
{
    memset(ref, 0, sizeof *ref);
    if (to - from < 2 || to - from > 3)
        return fail(c, "%s: expected MANUFACTURER ARTICLE [VARIANT]", c->tok[0]);
    for (int i = from; i < to; i++)
        c->used[i] = 1;
    return copy_name(c, ref->manufacturer, sizeof ref->manufacturer, c->tok[from],
                     "manufacturer") &&
           copy_name(c, ref->article, sizeof ref->article, c->tok[from + 1], "article") &&
           (to - from < 3 ||
            copy_name(c, ref->variant, sizeof ref->variant, c->tok[from + 2], "variant"));
}

/* Width and depth of object i for snapping (catalog box or primitive size). */
static int object_size(sctx *c, int i, double *w, double *d)
{
    const app_object *o = &c->p->objects[i];
    if (o->has_product) {
        app_product_info info;
        if (!lookup(c, &o->product, &info))
            return 0;
        *w = info.width_mm;
        *d = info.depth_mm;
    } else {
        *w = o->size_mm[0];
        *d = o->size_mm[1];
    }
    return 1;
}

/* Applies the `snap ...` words after index `from` to pose; self = the object being placed
 * (-1 for a new one). *wall_only (may be NULL) = 1 when the words were just `snap wall`, the
 * drop rule of the window (docs/editing.md "Mounting heights"). */
static int snap(sctx *c, int from, double width, double depth, int self, app_pose *pose,
                int *wall_only)
{
    int i = keyword(c, from, "snap");
    if (wall_only)
        *wall_only = i >= 0 && i + 1 < c->ntok && !strcmp(c->tok[i + 1], "wall") &&
                     (i + 2 == c->ntok || c->used[i + 2]);
    if (i < 0)
        return 1;
    int any = 0;
    for (int k = i + 1; k < c->ntok && !c->used[k]; k++) {
        const char *w = c->tok[k];
        app_pose out;
        if (!strcmp(w, "wall")) {
            if (app_snap_to_wall(&c->p->plan, width, *pose, SNAP_WALL_MM, &out) < 0)
                return fail(c, "%s: no wall within %.0f mm of (%.0f, %.0f) to snap to", c->tok[0],
                            SNAP_WALL_MM, pose->x, pose->y);
        } else if (!strcmp(w, "corner")) {
            app_snap_to_corner(&c->p->plan, width, *pose, SNAP_CORNER_MM, 0, &out);
        } else if (!strcmp(w, "neighbour") || !strcmp(w, "neighbor")) {
            app_fixture *fx = NULL;
            int n = 0;
            char err[1024];
            if (app_placement_fixtures(c->p, c->env ? c->env->lookup : NULL,
                                       c->env ? c->env->user : NULL, &fx, &n, err,
                                       sizeof err) != APP_OK)
                return fail(c, "%s: %s", c->tok[0], err);
            n = app_fixtures_without_group(c->p, self, fx, n); /* it moves with them */
            app_snap_to_neighbour(fx, n, self, width, depth, *pose, SNAP_NEIGHBOUR_MM,
                                  NEIGHBOUR_GAP_MM, &out);
            free(fx);
        } else if (!strcmp(w, "none")) {
            out = *pose;
        } else {
            return fail(c, "%s: snap to wall, corner, neighbour or none, not \"%s\"", c->tok[0], w);
        }
        c->used[k] = 1;
        *pose = out;
        any = 1;
    }
    return any ? 1 : fail(c, "%s: snap to what? (wall, corner, neighbour)", c->tok[0]);
}

static void unique_name(const app_project *p, const char *base, char *out, size_t size)
{
    snprintf(out, size, "%s", base);
    for (int n = 2;; n++) {
        int taken = 0;
        for (int i = 0; i < p->object_count && !taken; i++)
            taken = !strcmp(p->objects[i].name, out);
        if (!taken)
            return;
        snprintf(out, size, "%.50s-%d", base, n);
    }
}

/* Ends the open group; when it failed halfway, takes back what it did. */
static int end_group(sctx *c, int ok)
{
    char err[256];
    if (ok)
        app_history_end_group(c->h, err, sizeof err);
    else
        app_history_abort_group(c->h, c->p, err, sizeof err);
    return ok;
}

/* The material of a product's variant: its index, and in *add an ADD_MATERIAL command to run
 * first when the project does not have it yet (add->type stays 0 otherwise). Products without
 * a material use "default" (or the first material). */
static int variant_material(const app_project *p, const app_product_ref *ref,
                            const app_product_info *info, app_command_desc *add)
{
    memset(add, 0, sizeof *add);
    add->type = APP_CMD_COUNT; /* none */
    char mat_name[64];
    snprintf(mat_name, sizeof mat_name, "%.24s %.24s %.12s", ref->manufacturer, ref->article,
             info->variant[0] ? info->variant : ref->variant);
    int mat = info->has_material ? app_project_find_material(p, mat_name) : -1;
    if (info->has_material && mat < 0) {
        add->type = APP_CMD_ADD_MATERIAL;
        app_material *m = &add->material;
        snprintf(m->name, sizeof m->name, "%s", mat_name);
        memcpy(m->ambient, info->ambient, sizeof info->ambient);
        memcpy(m->diffuse, info->diffuse, sizeof info->diffuse);
        memcpy(m->specular, info->specular, sizeof info->specular);
        memcpy(m->emissive, info->emissive, sizeof info->emissive);
        m->shininess = info->shininess;
        m->reflectivity = info->reflectivity;
        m->glossiness = info->glossiness;
        m->blend = info->blend;
        m->transparency = info->transparency;
        m->ior = info->ior > 0 ? info->ior : 1.5f;
        m->pattern = info->pattern;
        m->grain_deg = info->grain_deg;
        m->texture_size_mm[0] = m->texture_size_mm[1] = 1000;
        return p->material_count;
    }
    if (mat < 0) {
        mat = app_project_find_material(p, "default");
        if (mat < 0)
            mat = 0;
    }
    return mat;
}

/* A dropped product's carrier and height (docs/editing.md "Mounting heights"): the object
 * named `on`, else (without a height) the nearest product it mounts onto within
 * MOUNT_REACH_MM of the drop point. On a carrier it takes the carrier's plan position and
 * turn (a basin on its vanity, a tap on the basin's tap hole, a mirror above the basin) and
 * is mounted on it; without one it lands at its category's mounting height. */
static int mount(sctx *c, const app_product_info *info, const char *on, int has_z, app_pose *pose,
                 char *parent, size_t parent_size)
{
    app_fixture *fx = NULL;
    int n = 0, carrier = -1;
    char err[1024];
    if (app_placement_fixtures(c->p, c->env ? c->env->lookup : NULL, c->env ? c->env->user : NULL,
                               &fx, &n, err, sizeof err) != APP_OK)
        return fail(c, "%s: %s", c->tok[0], err);
    if (on) {
        int i = find_object(c, on);
        for (int k = 0; k < n && i >= 0; k++)
            if (fx[k].object == i)
                carrier = k;
        if (i < 0 || carrier < 0) {
            free(fx);
            return i < 0 ? 0 : fail(c, "place: \"%s\" has no footprint to mount on", on);
        }
    } else {
        double at[2] = {pose->x, pose->y};
        carrier = app_mounting_support(fx, n, info->category, at, MOUNT_REACH_MM);
    }
    if (carrier >= 0) {
        const app_object *o = &c->p->objects[fx[carrier].object];
        const double rad = o->rotation_deg[2] * 3.14159265358979323846 / 180.0;
        /* Forward from the carrier's back face (local +y turned into the plan). */
        double ahead = 0, above = 0;
        if (info->category == CAT_CATEGORY_TAPS_MIXERS)
            ahead = TAP_HOLE_MM;
        else if (info->category == CAT_CATEGORY_MIRRORS ||
                 info->category == CAT_CATEGORY_MIRROR_CABINETS)
            above = MIRROR_ABOVE_MM;
        pose->x = o->position_mm[0] - sin(rad) * ahead;
        pose->y = o->position_mm[1] + cos(rad) * ahead;
        pose->rotation_deg = o->rotation_deg[2];
        if (!has_z)
            pose->z = fx[carrier].z1 + above;
        snprintf(parent, parent_size, "%s", o->name);
    } else if (!has_z) {
        double room = c->p->plan.height_mm;
        if (info->has_mounting && room > 0 && info->mounting_height_mm > room) {
            free(fx);
            return fail(c,
                        "%s: the catalog mounts this product at %.0f mm, above the room's "
                        "ceiling at %.0f mm",
                        c->tok[0], info->mounting_height_mm, room);
        }
        pose->z = app_product_mounting_z(info);
    }
    free(fx);
    return 1;
}

/* A product dropped against a wall (`snap wall` alone, and not on a carrier) is slid along
 * that wall out of a door's swing when a clear position exists there; else it stays and the
 * `opening` check reports it (docs/editing.md "Mounting heights"). */
static int slide_out_of_swing(sctx *c, const app_product_info *info, app_pose *pose)
{
    app_fixture *fx = NULL;
    int n = 0;
    char err[1024];
    if (app_placement_fixtures(c->p, c->env ? c->env->lookup : NULL, c->env ? c->env->user : NULL,
                               &fx, &n, err, sizeof err) != APP_OK)
        return fail(c, "%s: %s", c->tok[0], err);
    app_pose out;
    int moved =
        app_slide_out_of_swing(&c->p->plan, fx, n, info->category, info->width_mm, info->depth_mm,
                               pose->z, pose->z + info->height_mm, *pose, &out);
    free(fx);
    if (moved > 0 && c->env && c->env->log)
        fprintf(c->env->log, "place: out of a door swing: (%.0f, %.0f) -> (%.0f, %.0f)\n", pose->x,
                pose->y, out.x, out.y);
    else if (moved < 0 && c->env && c->env->log)
        fprintf(c->env->log,
                "place: no position on that wall is clear of the door swing; left at (%.0f, "
                "%.0f)\n",
                pose->x, pose->y);
    *pose = out;
    return 1;
}

/* Adds the object of a placed product at pose, with its variant's material when the project
 * lacks it, mounted on `parent` ("" = none), in the caller's undo group; its name into name. */
static int add_product(sctx *c, const app_product_ref *ref, const app_product_info *info,
                       const app_pose *pose, const char *as, const char *parent, char *name,
                       size_t name_size)
{
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.type = APP_CMD_ADD_OBJECT;
    d.index = -1;
    app_object *o = &d.object;
    if (as) {
        if (!copy_name(c, o->name, sizeof o->name, as, "name"))
            return 0;
    } else {
        unique_name(c->p, ref->article, o->name, sizeof o->name);
    }
    o->shape = APP_SHAPE_MODEL;
    /* "models/..." lives where the build generated it (cat_models_dir), not under assets/ */
    if (info->model[0] && c->env && c->env->assets_dir &&
        !cat_model_resolve(info->model, c->env->assets_dir, o->model, sizeof o->model))
        o->model[0] = '\0';
    o->position_mm[0] = pose->x;
    o->position_mm[1] = pose->y;
    o->position_mm[2] = pose->z;
    o->rotation_deg[2] = pose->rotation_deg;
    o->scale[0] = o->scale[1] = o->scale[2] = 1;
    o->has_product = 1;
    o->product = *ref;
    snprintf(o->parent, sizeof o->parent, "%s", parent);
    snprintf(name, name_size, "%s", o->name);

    app_command_desc m;
    o->material = variant_material(c->p, ref, info, &m);
    return (m.type != APP_CMD_ADD_MATERIAL || run(c, &m)) && run(c, &d);
}

/* The companions the catalog names for a placed product (a vanity's basin, tap and mirror),
 * in their order, each dropped at the product's place without a height: each lands on its
 * carrier (the basin on the vanity, the tap and the mirror on the basin) or, without one, at
 * its mounting height (docs/editing.md "Companions"). */
static int add_companions(sctx *c, const app_product_ref *of, const app_product_info *info,
                          const app_pose *at)
{
    char maker[CAT_MANUFACTURER_BYTES + 1], article[CAT_ARTICLE_BYTES + 1];
    int r;
    for (int k = 0; (r = cat_companion_get(info->companions, k, maker, sizeof maker, article,
                                           sizeof article)) != 0;
         k++) {
        app_product_ref ref;
        memset(&ref, 0, sizeof ref);
        if (r < 0 ||
            !copy_name(c, ref.manufacturer, sizeof ref.manufacturer,
                       maker[0] ? maker : of->manufacturer, "manufacturer") ||
            !copy_name(c, ref.article, sizeof ref.article, article, "article"))
            return r < 0 ? fail(c, "place: companion %d of %s %s is not an article", k + 1,
                                of->manufacturer, of->article)
                         : 0;
        app_product_info ci;
        if (!lookup(c, &ref, &ci))
            return 0;
        if (ci.variant[0])
            memcpy(ref.variant, ci.variant, sizeof ref.variant);
        app_pose pose = *at;
        char parent[64] = "", name[64];
        if (!mount(c, &ci, NULL, 0, &pose, parent, sizeof parent) ||
            !add_product(c, &ref, &ci, &pose, NULL, parent, name, sizeof name))
            return 0;
        if (c->env && c->env->log)
            fprintf(c->env->log, "place: companion %s %s as \"%s\"%s%s at z %.0f\n",
                    ref.manufacturer, ref.article, name, parent[0] ? " on " : "", parent, pose.z);
    }
    return 1;
}

static int do_place(sctx *c)
{
    int at = keyword(c, 1, "at");
    if (at < 0)
        return fail(c, "place: expected place MANUFACTURER ARTICLE [VARIANT] at X Y Z");
    app_product_ref ref;
    if (!product_ref(c, 1, at, &ref))
        return 0;
    double pos[3] = {0, 0, 0}, rot = 0;
    /* Without a height the product lands at its mounting height (or on its carrier). */
    int has_z = at + 3 < c->ntok && decimal_syntax(c->tok[at + 3]);
    int opt = at + 3 + has_z;
    for (int k = 0; k < 2 + has_z; k++)
        if (!number(c, at + 1 + k, &pos[k]))
            return 0;
    if (kw_numbers(c, opt, "rot", 1, &rot, 0) == 0)
        return 0;
    const char *as = NULL, *on = NULL;
    if (kw_word(c, opt, "as", &as, 0) == 0 || kw_word(c, opt, "on", &on, 0) == 0)
        return 0;
    int with_companions = keyword(c, opt, "with-companions") >= 0;
    app_product_info info;
    if (!lookup(c, &ref, &info))
        return 0;
    if (info.category == CAT_CATEGORY_TILES)
        return fail(c, "place: %s %s is a tile; tiles are laid with `tile SURFACE with ...`",
                    ref.manufacturer, ref.article);
    if (with_companions && !info.companions[0])
        return fail(c, "place: %s %s has no companions in the catalog", ref.manufacturer,
                    ref.article);
    if (!ref.variant[0] && info.variant[0])
        memcpy(ref.variant, info.variant, sizeof ref.variant);
    app_pose pose = {pos[0], pos[1], pos[2], rot};
    int dropped = 0;
    if (!snap(c, opt, info.width_mm, info.depth_mm, -1, &pose, &dropped) || !all_used(c))
        return 0;
    char parent[64] = "";
    if ((on || !has_z) && !mount(c, &info, on, has_z, &pose, parent, sizeof parent))
        return 0;
    if (dropped && !parent[0] && !slide_out_of_swing(c, &info, &pose))
        return 0;

    char label[160], name[64];
    snprintf(label, sizeof label, "place \"%s\"%s", as ? as : ref.article,
             with_companions ? " with its companions" : "");
    int before = c->st->commands;
    app_history_begin_group(c->h, label);
    int ok = add_product(c, &ref, &info, &pose, as, parent, name, sizeof name) &&
             (!with_companions || add_companions(c, &ref, &info, &pose));
    c->st->commands = before + (ok ? 1 : 0);
    return end_group(c, ok);
}

static int do_add_primitive(sctx *c)
{
    static const char *const shapes[] = {"box", "sphere", "cylinder", "plane", "torus"};
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.type = APP_CMD_ADD_OBJECT;
    d.index = -1;
    const char *shape = NULL, *name = NULL;
    if (!word(c, 1, &shape) || !word(c, 2, &name))
        return 0;
    int s = -1;
    for (int i = 0; i < 5; i++)
        if (!strcmp(shape, shapes[i]))
            s = i;
    if (s < 0)
        return fail(c, "add: the shape is box, sphere, cylinder, plane or torus, not \"%s\"",
                    shape);
    app_object *o = &d.object;
    o->shape = (app_shape)s;
    o->scale[0] = o->scale[1] = o->scale[2] = 1;
    double rot = 0;
    const char *mat = NULL, *group = NULL;
    if (!copy_name(c, o->name, sizeof o->name, name, "name") ||
        !kw_numbers(c, 3, "at", 3, o->position_mm, 1) ||
        !kw_numbers(c, 3, "size", 3, o->size_mm, 1) || !kw_numbers(c, 3, "rot", 1, &rot, 0) ||
        !kw_word(c, 3, "material", &mat, 0) || !kw_word(c, 3, "group", &group, 0) || !all_used(c))
        return 0;
    o->rotation_deg[2] = rot;
    if (group && !copy_name(c, o->group, sizeof o->group, group, "group"))
        return 0;
    if (mat) {
        o->material = app_project_find_material(c->p, mat);
        if (o->material < 0)
            return fail(c, "add: no material named \"%s\"", mat);
    }
    return run(c, &d);
}

static int do_move(sctx *c, int relative)
{
    const char *name = NULL;
    double v[3];
    if (!word(c, 1, &name))
        return 0;
    int i = find_object(c, name);
    if (i < 0)
        return 0;
    for (int k = 0; k < 3; k++)
        if (!number(c, 2 + k, &v[k]))
            return 0;
    const app_object *o = &c->p->objects[i];
    app_pose pose = {v[0], v[1], v[2], o->rotation_deg[2]};
    if (relative) {
        pose.x += o->position_mm[0];
        pose.y += o->position_mm[1];
        pose.z += o->position_mm[2];
    }
    double w = 0, dep = 0;
    int si = keyword(c, 5, "snap");
    if (si >= 0) {
        c->used[si] = 0; /* snap() looks for it again */
        if (!object_size(c, i, &w, &dep) || !snap(c, 5, w, dep, i, &pose, NULL))
            return 0;
    }
    if (!all_used(c))
        return 0;
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.type = APP_CMD_MOVE_OBJECT;
    d.index = i;
    d.position_mm[0] = pose.x;
    d.position_mm[1] = pose.y;
    d.position_mm[2] = pose.z;
    if (pose.rotation_deg == o->rotation_deg[2])
        return run(c, &d);
    char label[160];
    snprintf(label, sizeof label, "move \"%s\"", name);
    int before = c->st->commands;
    app_history_begin_group(c->h, label);
    app_command_desc r;
    memset(&r, 0, sizeof r);
    r.type = APP_CMD_ROTATE_OBJECT;
    r.index = i;
    r.rotation_deg = pose.rotation_deg;
    int ok = run(c, &d) && run(c, &r);
    c->st->commands = before + (ok ? 1 : 0);
    return end_group(c, ok);
}

static int do_object_edit(sctx *c)
{
    const char *cmd = c->tok[0], *name = NULL;
    if (!word(c, 1, &name))
        return 0;
    int i = find_object(c, name);
    if (i < 0)
        return 0;
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.index = i;
    if (!strcmp(cmd, "remove")) {
        d.type = APP_CMD_REMOVE_OBJECT;
    } else if (!strcmp(cmd, "rotate")) {
        d.type = APP_CMD_ROTATE_OBJECT;
        if (!number(c, 2, &d.rotation_deg))
            return 0;
    } else if (!strcmp(cmd, "variant")) {
        d.type = APP_CMD_SET_VARIANT;
        const char *code = NULL;
        if (!word(c, 2, &code) || !copy_name(c, d.variant, sizeof d.variant, code, "variant"))
            return 0;
        if (c->p->objects[i].has_product) {
            /* A new finish brings its own render material (added once). */
            app_product_ref ref = c->p->objects[i].product;
            memcpy(ref.variant, d.variant, sizeof ref.variant);
            app_product_info info;
            if (!lookup(c, &ref, &info) || !all_used(c))
                return 0;
            app_command_desc m;
            app_command_desc set;
            memset(&set, 0, sizeof set);
            set.type = APP_CMD_SET_OBJECT;
            set.index = i;
            set.object = c->p->objects[i];
            set.object.product = ref;
            set.object.material = variant_material(c->p, &ref, &info, &m);
            char label[160];
            snprintf(label, sizeof label, "set the finish of \"%s\"", name);
            int before = c->st->commands;
            app_history_begin_group(c->h, label);
            int ok = (m.type != APP_CMD_ADD_MATERIAL || run(c, &m)) && run(c, &set);
            c->st->commands = before + (ok ? 1 : 0);
            return end_group(c, ok);
        }
    } else { /* product */
        d.type = APP_CMD_SET_PRODUCT;
        if (!product_ref(c, 2, c->ntok, &d.product))
            return 0;
        app_product_info info;
        if (!lookup(c, &d.product, &info))
            return 0;
    }
    return all_used(c) && run(c, &d);
}

static int pattern_of(sctx *c, const char *w, app_tile_pattern *out)
{
    static const char *const names[] = {"straight",       "half-offset", "third-offset",
                                        "vertical-stack", "diagonal",    "herringbone"};
    for (int i = 0; i < 6; i++)
        if (!strcmp(w, names[i])) {
            *out = (app_tile_pattern)i;
            return 1;
        }
    return fail(c,
                "tile: the pattern is straight, half-offset, third-offset, vertical-stack, "
                "diagonal or herringbone, not \"%s\"",
                w);
}

/* `tile SURFACE band FROM TO`: the heights a wall tiling covers (TO 0 = up to the ceiling). */
static int tile_band(sctx *c, app_tiling *t)
{
    return number(c, 3, &t->from_mm) && number(c, 4, &t->to_mm);
}

/* `tile SURFACE border add MAKER ARTICLE [VARIANT] at BOTTOM`, `tile SURFACE border K at
 * BOTTOM` (K from 1: moves border row K), `tile SURFACE border remove K`. */
static int tile_border(sctx *c, app_tiling *t)
{
    const char *how = NULL;
    if (!word(c, 3, &how))
        return 0;
    if (!strcmp(how, "add")) {
        int at = keyword(c, 4, "at");
        if (at < 0)
            return fail(c, "tile: border add MANUFACTURER ARTICLE [VARIANT] at BOTTOM");
        app_product_ref ref;
        app_product_info info;
        double bottom = 0;
        if (!product_ref(c, 4, at, &ref) || !number(c, at + 1, &bottom) || !lookup(c, &ref, &info))
            return 0;
        if (info.category != CAT_CATEGORY_TILES)
            return fail(c, "tile: %s %s is not a tile", ref.manufacturer, ref.article);
        if (t->border_count >= APP_TILING_MAX_BORDERS)
            return fail(c, "tile: \"%s\" has %d border rows already", t->name, t->border_count);
        t->borders[t->border_count].product = ref;
        t->borders[t->border_count++].bottom_mm = bottom;
        return 1;
    }
    int remove = !strcmp(how, "remove"), k = 0;
    if (!integer(c, remove ? 4 : 3, &k))
        return 0;
    if (k < 1 || k > t->border_count)
        return fail(c, "tile: \"%s\" has %d border rows, no row %d", t->name, t->border_count, k);
    if (!remove)
        return kw_numbers(c, 4, "at", 1, &t->borders[k - 1].bottom_mm, 1) == 1;
    memmove(&t->borders[k - 1], &t->borders[k],
            (size_t)(t->border_count - k) * sizeof t->borders[0]);
    memset(&t->borders[--t->border_count], 0, sizeof t->borders[0]);
    return 1;
}

static int do_tile(sctx *c)
{
    const char *surface = NULL, *what = NULL;
    if (!word(c, 1, &surface) || !word(c, 2, &what))
        return 0;
    int t = find_tiling(c, surface);
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.index = t;
    if (!strcmp(what, "with")) {
        app_product_ref ref;
        app_product_info info;
        if (!product_ref(c, 3, c->ntok, &ref) || !lookup(c, &ref, &info))
            return 0;
        if (info.category != CAT_CATEGORY_TILES)
            return fail(c, "tile: %s %s is not a tile", ref.manufacturer, ref.article);
        if (t >= 0) {
            d.type = APP_CMD_SET_TILE_PRODUCT;
            d.product = ref;
        } else {
            d.type = APP_CMD_SET_TILING;
            d.index = -1;
            app_tiling *n = &d.tiling;
            if (!copy_name(c, n->surface, sizeof n->surface, surface, "surface"))
                return 0;
            snprintf(n->name, sizeof n->name, "%s", surface);
            n->product = ref;
            n->pattern = APP_PATTERN_STRAIGHT;
            /* Centred, as scripts have always started a tiling (saved files replay the same);
             * the reader's defaults (project_defaults.c) for the rest: an edge joint of the joint
             * width, a light grey cement grout. */
            n->align = APP_ALIGN_CENTRED;
            n->edge_joint_mm = -1;
            n->grout_color[0] = n->grout_color[1] = 0.6f;
            n->grout_color[2] = 0.58f;
        }
        return all_used(c) && run(c, &d);
    }
    if (t < 0)
        return fail(c, "tile: no tiling on \"%s\"; start with: tile %s with MANUFACTURER ARTICLE",
                    surface, surface);
    const app_tiling *cur = &c->p->tilings[t];
    if (!strcmp(what, "pattern")) {
        const char *w = NULL;
        d.type = APP_CMD_SET_TILE_PATTERN;
        if (!word(c, 3, &w) || !pattern_of(c, w, &d.pattern))
            return 0;
    } else if (!strcmp(what, "grout")) {
        d.type = APP_CMD_SET_GROUT;
        if (!number(c, 3, &d.grout_mm))
            return 0;
        memcpy(d.grout_color, cur->grout_color, sizeof d.grout_color);
        double rgb[3];
        int r = kw_numbers(c, 4, "colour", 3, rgb, 0);
        if (r < 0)
            r = kw_numbers(c, 4, "color", 3, rgb, 0);
        if (r == 0)
            return 0;
        if (r > 0)
            for (int k = 0; k < 3; k++)
                d.grout_color[k] = (float)rgb[k];
    } else if (!strcmp(what, "start")) {
        const char *how = NULL;
        d.type = APP_CMD_SET_TILE_START;
        if (!word(c, 3, &how))
            return 0;
        memcpy(d.origin_mm, cur->origin_mm, sizeof d.origin_mm);
        if (!strcmp(how, "centred") || !strcmp(how, "centered"))
            d.align = APP_ALIGN_CENTRED;
        else if (!strcmp(how, "corner"))
            d.align = APP_ALIGN_CORNER;
        else if (!strcmp(how, "auto"))
            d.align = APP_ALIGN_AUTO;
        else if (!strcmp(how, "line")) {
            d.align = APP_ALIGN_LINE;
            if (!number(c, 4, &d.origin_mm[0]) || !number(c, 5, &d.origin_mm[1]))
                return 0;
        } else
            return fail(c, "tile: start centred, corner, auto or line S U, not \"%s\"", how);
    } else if (!strcmp(what, "rotate")) {
        d.type = APP_CMD_SET_TILE_ROTATION;
        if (!number(c, 3, &d.rotation_deg))
            return 0;
    } else if (!strcmp(what, "trim")) {
        /* The trim profile along the surface's outside edges (app/design/trims.h), or none. */
        d.type = APP_CMD_SET_TILING;
        d.tiling = *cur;
        const char *none = NULL;
        if (c->ntok == 4 && !strcmp(c->tok[3], "none") && word(c, 3, &none)) {
            memset(&d.tiling.trim, 0, sizeof d.tiling.trim);
        } else {
            app_product_info info;
            if (!product_ref(c, 3, c->ntok, &d.tiling.trim) || !lookup(c, &d.tiling.trim, &info))
                return 0;
        }
    } else if (!strcmp(what, "setout")) {
        /* No command type of its own: the tiling replaced whole (one undo step). */
        const char *how = NULL;
        d.type = APP_CMD_SET_TILING;
        d.tiling = *cur;
        if (!word(c, 3, &how))
            return 0;
        if (strcmp(how, "room") && strcmp(how, "surface"))
            return fail(c, "tile: setout room or surface, not \"%s\"", how);
        d.tiling.setout_room = !strcmp(how, "room");
    } else if (!strcmp(what, "band") || !strcmp(what, "border")) {
        /* No command type of their own: the tiling replaced whole (one undo step). */
        d.type = APP_CMD_SET_TILING;
        d.tiling = *cur;
        if (!(!strcmp(what, "band") ? tile_band(c, &d.tiling) : tile_border(c, &d.tiling)))
            return 0;
    } else {
        return fail(c,
                    "tile: with, pattern, grout, start, setout, trim, rotate, band or border, not "
                    "\"%s\"",
                    what);
    }
    return all_used(c) && run(c, &d);
}

static int swing_of(sctx *c, const char *w, app_door_swing *out)
{
    static const char *const names[] = {"in-left", "in-right", "out-left", "out-right", "sliding"};
    for (int i = 0; i < 5; i++)
        if (!strcmp(w, names[i])) {
            *out = (app_door_swing)i;
            return 1;
        }
    return fail(c, "door: swing in-left, in-right, out-left, out-right or sliding, not \"%s\"", w);
}

static int do_opening(sctx *c, int window)
{
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.type = APP_CMD_ADD_OPENING;
    d.index = -1;
    app_opening *o = &d.opening;
    o->type = window ? APP_OPENING_WINDOW : APP_OPENING_DOOR;
    const char *name = NULL, *swing = NULL;
    double wall;
    if (!word(c, 1, &name) || !copy_name(c, o->name, sizeof o->name, name, "name") ||
        !kw_numbers(c, 2, "wall", 1, &wall, 1) || !kw_numbers(c, 2, "at", 1, &o->offset_mm, 1) ||
        !kw_numbers(c, 2, "width", 1, &o->width_mm, 1) ||
        !kw_numbers(c, 2, "height", 1, &o->height_mm, 1))
        return 0;
    if (!wall_index(c, wall, &o->wall))
        return 0;
    if (window) {
        double light[3];
        int r = kw_numbers(c, 2, "light", 3, light, 0);
        if (!kw_numbers(c, 2, "sill", 1, &o->sill_mm, 1) || r == 0)
            return 0;
        for (int k = 0; r > 0 && k < 3; k++)
            o->light[k] = (float)light[k];
    } else if (kw_word(c, 2, "swing", &swing, 0) == 0 ||
               (swing && !swing_of(c, swing, &o->swing))) {
        return 0;
    }
    return all_used(c) && run(c, &d);
}

static int do_plan_edit(sctx *c)
{
    const char *cmd = c->tok[0], *name = NULL;
    app_command_desc d;
    memset(&d, 0, sizeof d);
    if (!strcmp(cmd, "corner")) {
        d.type = APP_CMD_MOVE_CORNER;
        if (!integer(c, 1, &d.index) || !number(c, 2, &d.corner.x) || !number(c, 3, &d.corner.y))
            return 0;
        return all_used(c) && run(c, &d);
    }
    if (!word(c, 1, &name))
        return 0;
    if (!strcmp(cmd, "move-opening")) {
        d.type = APP_CMD_MOVE_OPENING;
        if ((d.index = FIND_OPENING(c, name)) < 0)
            return 0;
        double wall = c->p->plan.openings[d.index].wall;
        if (kw_numbers(c, 2, "wall", 1, &wall, 0) == 0 ||
            !kw_numbers(c, 2, "at", 1, &d.offset_mm, 1))
            return 0;
        if (!wall_index(c, wall, &d.wall))
            return 0;
    } else if (!strcmp(cmd, "remove-opening")) {
        d.type = APP_CMD_REMOVE_OPENING;
        if ((d.index = FIND_OPENING(c, name)) < 0)
            return 0;
    } else if (!strcmp(cmd, "remove-prewall")) {
        d.type = APP_CMD_REMOVE_PREWALL;
        if ((d.index = FIND_PREWALL(c, name)) < 0)
            return 0;
    } else if (!strcmp(cmd, "remove-niche")) {
        d.type = APP_CMD_REMOVE_NICHE;
        if ((d.index = FIND_NICHE(c, name)) < 0)
            return 0;
    } else if (!strcmp(cmd, "prewall")) {
        d.type = APP_CMD_ADD_PREWALL;
        d.index = -1;
        app_prewall *w = &d.prewall;
        double wall;
        if (!copy_name(c, w->name, sizeof w->name, name, "name") ||
            !kw_numbers(c, 2, "wall", 1, &wall, 1) ||
            !kw_numbers(c, 2, "at", 1, &w->offset_mm, 1) ||
            !kw_numbers(c, 2, "width", 1, &w->width_mm, 1) ||
            !kw_numbers(c, 2, "depth", 1, &w->depth_mm, 1) ||
            !kw_numbers(c, 2, "height", 1, &w->height_mm, 1))
            return 0;
        if (!wall_index(c, wall, &w->wall))
            return 0;
    } else { /* niche */
        d.type = APP_CMD_ADD_NICHE;
        d.index = -1;
        app_niche *w = &d.niche;
        double wall;
        if (!copy_name(c, w->name, sizeof w->name, name, "name") ||
            !kw_numbers(c, 2, "wall", 1, &wall, 1) ||
            !kw_numbers(c, 2, "at", 1, &w->offset_mm, 1) ||
            !kw_numbers(c, 2, "width", 1, &w->width_mm, 1) ||
            !kw_numbers(c, 2, "sill", 1, &w->sill_mm, 1) ||
            !kw_numbers(c, 2, "height", 1, &w->height_mm, 1) ||
            !kw_numbers(c, 2, "depth", 1, &w->depth_mm, 1))
            return 0;
        if (!wall_index(c, wall, &w->wall))
            return 0;
    }
    return all_used(c) && run(c, &d);
}

static int do_reflect(sctx *c)
{
    const char *name = NULL, *blend = NULL;
    if (!word(c, 1, &name))
        return 0;
    int m = app_project_find_material(c->p, name);
    if (m < 0)
        return fail(c, "reflect: no material named \"%s\"", name);
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.type = APP_CMD_SET_REFLECTION;
    d.index = m;
    double r, g = c->p->materials[m].glossiness;
    if (!number(c, 2, &r) || kw_numbers(c, 3, "gloss", 1, &g, 0) == 0 ||
        kw_word(c, 3, "blend", &blend, 0) == 0)
        return 0;
    d.reflectivity = (float)r;
    d.glossiness = (float)g;
    d.blend = c->p->materials[m].blend;
    if (blend) {
        if (!strcmp(blend, "mix"))
            d.blend = APP_BLEND_MIX;
        else if (!strcmp(blend, "add"))
            d.blend = APP_BLEND_ADD;
        else if (!strcmp(blend, "fresnel"))
            d.blend = APP_BLEND_FRESNEL;
        else
            return fail(c, "reflect: blend mix, add or fresnel, not \"%s\"", blend);
    }
    return all_used(c) && run(c, &d);
}

/* `pattern MATERIAL none|wood [grain horizontal|vertical|DEG]`: a procedural pattern on the
 * material's colour (the wood grain, docs/rendering.md "Wood grain") and the grain's direction
 * on the object's front (kept when not given). */
static int do_pattern(sctx *c)
{
    const char *name = NULL, *kind = NULL, *grain = NULL;
    if (!word(c, 1, &name) || !word(c, 2, &kind))
        return 0;
    int m = app_project_find_material(c->p, name);
    if (m < 0)
        return fail(c, "pattern: no material named \"%s\"", name);
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.type = APP_CMD_SET_PATTERN;
    d.index = m;
    d.material_grain_deg = c->p->materials[m].grain_deg;
    int has_grain = kw_word(c, 3, "grain", &grain, 0);
    if (!has_grain)
        return 0;
    if (has_grain > 0) {
        char *end = NULL;
        double deg = strtod(grain, &end);
        if (!strcmp(grain, "horizontal") || !strcmp(grain, "vertical"))
            d.material_grain_deg = grain[0] == 'h' ? 0.0f : 90.0f;
        else if (end != grain && !*end && deg >= 0.0 && deg <= 180.0)
            d.material_grain_deg = (float)deg;
        else
            return fail(c, "pattern: grain horizontal, vertical or 0 to 180 degrees, not \"%s\"",
                        grain);
    }
    if (!strcmp(kind, "wood"))
        d.material_pattern = APP_PATTERN_WOOD;
    else if (!strcmp(kind, "none"))
        d.material_pattern = APP_PATTERN_NONE;
    else
        return fail(c, "pattern: none or wood, not \"%s\"", kind);
    return all_used(c) && run(c, &d);
}

/* `probe MATERIAL [update POLICY] [every N] [resolution auto|N] [correction KIND]`: the
 * material's reflection probe policy (cmd_probe.c); words not given keep their values. */
static int do_probe(sctx *c)
{
    const char *name = NULL;
    if (!word(c, 1, &name))
        return 0;
    int m = app_project_find_material(c->p, name);
    if (m < 0)
        return fail(c, "probe: no material named \"%s\"", name);
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.index = m;
    char why[512];
    if (!cmd_probe_words(&c->p->materials[m], c->ntok - 2, (const char *const *)c->tok + 2, &d, why,
                         sizeof why))
        return fail(c, "%s", why);
    for (int i = 2; i < c->ntok; i++)
        c->used[i] = 1;
    return run(c, &d);
}

static int do_undo_redo(sctx *c, int redo)
{
    int n = 1;
    if (c->ntok > 1 && !integer(c, 1, &n))
        return 0;
    if (n < 1)
        return fail(c, "%s: the count must be at least 1", c->tok[0]);
    if (!all_used(c))
        return 0;
    for (int i = 0; i < n; i++) {
        char err[512];
        app_result r = redo ? app_history_redo(c->h, c->p, err, sizeof err)
                            : app_history_undo(c->h, c->p, err, sizeof err);
        if (r != APP_OK)
            return fail(c, "%s: %s (after %d of %d)", c->tok[0], err, i, n);
        if (redo)
            c->st->redone++;
        else
            c->st->undone++;
    }
    return 1;
}

/* mount CHILD on PARENT | ungroup NAME (docs/editing.md "Groups"). */
static int do_group(sctx *c, int ungroup)
{
    const char *name = NULL, *on = NULL, *parent = NULL;
    if (!word(c, 1, &name))
        return 0;
    app_command_desc d;
    memset(&d, 0, sizeof d);
    if ((d.index = find_object(c, name)) < 0)
        return 0;
    if (ungroup) {
        d.type = APP_CMD_UNGROUP;
    } else {
        if (!word(c, 2, &on) || !word(c, 3, &parent))
            return 0;
        if (strcmp(on, "on"))
            return fail(c, "mount: write \"mount %s on OBJECT\"", name);
        d.type = APP_CMD_SET_PARENT;
        if (!copy_name(c, d.parent, sizeof d.parent, parent, "parent"))
            return 0;
    }
    return all_used(c) && run(c, &d);
}

static int dispatch(sctx *c)
{
    const char *cmd = c->tok[0];
    c->used[0] = 1;
    if (!strcmp(cmd, "place"))
        return do_place(c);
    if (!strcmp(cmd, "add"))
        return do_add_primitive(c);
    if (!strcmp(cmd, "move"))
        return do_move(c, 0);
    if (!strcmp(cmd, "nudge"))
        return do_move(c, 1);
    if (!strcmp(cmd, "remove") || !strcmp(cmd, "rotate") || !strcmp(cmd, "variant") ||
        !strcmp(cmd, "product"))
        return do_object_edit(c);
    if (!strcmp(cmd, "mount") || !strcmp(cmd, "ungroup"))
        return do_group(c, !strcmp(cmd, "ungroup"));
    if (!strcmp(cmd, "tile"))
        return do_tile(c);
    if (!strcmp(cmd, "untile")) {
        const char *surface = NULL;
        if (!word(c, 1, &surface))
            return 0;
        app_command_desc d;
        memset(&d, 0, sizeof d);
        d.type = APP_CMD_REMOVE_TILING;
        if ((d.index = find_tiling(c, surface)) < 0)
            return fail(c, "untile: no tiling on \"%s\"", surface);
        return all_used(c) && run(c, &d);
    }
    if (!strcmp(cmd, "door") || !strcmp(cmd, "window"))
        return do_opening(c, !strcmp(cmd, "window"));
    if (!strcmp(cmd, "corner") || !strcmp(cmd, "move-opening") || !strcmp(cmd, "remove-opening") ||
        !strcmp(cmd, "prewall") || !strcmp(cmd, "remove-prewall") || !strcmp(cmd, "niche") ||
        !strcmp(cmd, "remove-niche"))
        return do_plan_edit(c);
    if (!strcmp(cmd, "reflect"))
        return do_reflect(c);
    if (!strcmp(cmd, "probe"))
        return do_probe(c);
    if (!strcmp(cmd, "pattern"))
        return do_pattern(c);
    if (!strcmp(cmd, "undo") || !strcmp(cmd, "redo"))
        return do_undo_redo(c, !strcmp(cmd, "redo"));
    return fail(c, "unknown command \"%s\" (see docs/editing.md)", cmd);
}

app_result app_script_run(app_project *p, app_history *h, const char *text, size_t len,
                          const char *name, const app_script_env *env, app_script_stats *stats,
                          char *err, size_t err_size)
{
    app_script_stats local;
    memset(&local, 0, sizeof local);
    sctx c;
    memset(&c, 0, sizeof c);
    c.p = p;
    c.h = h;
    c.env = env;
    c.st = &local;
    char line[MAX_LINE + 1];
    size_t pos = 0;
    int line_no = 0;
    app_result result = APP_OK;
    while (pos < len) {
        size_t end = pos;
        while (end < len && text[end] != '\n')
            end++;
        line_no++;
        size_t n = end - pos;
        if (n > MAX_LINE) {
            snprintf(err, err_size, "%s:%d: the line is longer than %d bytes", name, line_no,
                     MAX_LINE);
            result = APP_ERR_PARSE;
            break;
        }
        memcpy(line, text + pos, n);
        line[n] = 0;
        pos = end + 1;
        if (memchr(line, 0, n)) {
            snprintf(err, err_size, "%s:%d: a NUL byte in the script", name, line_no);
            result = APP_ERR_PARSE;
            break;
        }
        if (!tokenize(&c, line)) {
            snprintf(err, err_size, "%s:%d: %s", name, line_no, c.msg);
            result = APP_ERR_PARSE;
            break;
        }
        if (c.ntok == 0)
            continue;
        local.lines++;
        if (!dispatch(&c)) {
            snprintf(err, err_size, "%s:%d: %s", name, line_no, c.msg);
            result = APP_ERR_SCHEMA;
            break;
        }
        if (env && env->log) {
            if (!strcmp(c.tok[0], "undo") || !strcmp(c.tok[0], "redo"))
                fprintf(env->log, "%s:%d: %s (next undo: %s)\n", name, line_no, c.tok[0],
                        app_history_undo_label(h)[0] ? app_history_undo_label(h) : "none");
            else
                fprintf(env->log, "%s:%d: %s\n", name, line_no, app_history_undo_label(h));
        }
    }
    if (stats)
        *stats = local;
    return result;
}
