/* From a command description to element edits: checks the edit against the project (indices,
 * finite numbers, openings inside their walls, a simple plan polygon, ...) and records the
 * elements it changes, before and after. The project is not changed here. */
#include "cmd_internal.h"

#include "app/design/room_surfaces.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_COORD_MM 1e7 /* app/project/project.h: APP_PROJECT_MAX_ROOM_MM */

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

static int finite_in(double v, double lo, double hi)
{
    return isfinite(v) && v >= lo && v <= hi;
}

static int terminated(const char *s, size_t size)
{
    return memchr(s, 0, size) != NULL;
}

static double wall_length(const app_point2 *c, int n, int wall)
{
    app_point2 a = c[wall], b = c[(wall + 1) % n];
    return hypot(b.x - a.x, b.y - a.y);
}

static double cross3(app_point2 o, app_point2 a, app_point2 b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

static int segments_touch(app_point2 a, app_point2 b, app_point2 c, app_point2 d)
{
    double d1 = cross3(c, d, a), d2 = cross3(c, d, b), d3 = cross3(a, b, c), d4 = cross3(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 1;
    /* Collinear overlaps and touching endpoints of non-adjacent walls count too. */
    if (d1 == 0 && fmin(c.x, d.x) <= a.x && a.x <= fmax(c.x, d.x) && fmin(c.y, d.y) <= a.y &&
        a.y <= fmax(c.y, d.y))
        return 1;
    if (d2 == 0 && fmin(c.x, d.x) <= b.x && b.x <= fmax(c.x, d.x) && fmin(c.y, d.y) <= b.y &&
        b.y <= fmax(c.y, d.y))
        return 1;
    return 0;
}

/* app/design/room.h: a simple counter-clockwise polygon without zero-length walls. */
static app_result check_polygon(const app_point2 *c, int n, char *err, size_t err_size)
{
    if (n < 3)
        return fail(err, err_size, APP_ERR_SCHEMA, "the plan needs at least 3 corners");
    double area2 = 0;
    for (int i = 0; i < n; i++) {
        if (!finite_in(c[i].x, -MAX_COORD_MM, MAX_COORD_MM) ||
            !finite_in(c[i].y, -MAX_COORD_MM, MAX_COORD_MM))
            return fail(err, err_size, APP_ERR_SCHEMA, "corner %d is not a finite position", i);
        if (wall_length(c, n, i) < 1.0)
            return fail(err, err_size, APP_ERR_SCHEMA, "wall %d would be shorter than 1 mm", i);
        app_point2 a = c[i], b = c[(i + 1) % n];
        area2 += a.x * b.y - b.x * a.y;
    }
    if (area2 <= 0)
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "the plan would no longer run counter-clockwise (its walls would cross)");
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            if (j == i + 1 || (i == 0 && j == n - 1))
                continue; /* neighbours share a corner */
            if (segments_touch(c[i], c[(i + 1) % n], c[j], c[(j + 1) % n]))
                return fail(err, err_size, APP_ERR_SCHEMA, "walls %d and %d would cross", i, j);
        }
    return APP_OK;
}

/* Openings, pre-walls and niches must lie within their walls (app/design/room.h). */
static app_result check_wall_items(const app_room_plan *plan, const app_point2 *c, int n, char *err,
                                   size_t err_size)
{
    for (int k = 0; k < plan->opening_count; k++) {
        const app_opening *o = &plan->openings[k];
        if (o->wall < 0 || o->wall >= n ||
            o->offset_mm + o->width_mm > wall_length(c, n, o->wall) + 1e-6)
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "the opening \"%s\" would no longer fit in wall %d", o->name, o->wall);
    }
    for (int k = 0; k < plan->prewall_count; k++) {
        const app_prewall *w = &plan->prewalls[k];
        if (w->wall < 0 || w->wall >= n ||
            w->offset_mm + w->width_mm > wall_length(c, n, w->wall) + 1e-6)
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "the pre-wall \"%s\" would no longer fit on wall %d", w->name, w->wall);
    }
    for (int k = 0; k < plan->niche_count; k++) {
        const app_niche *w = &plan->niches[k];
        if (w->wall < 0 || w->wall >= n ||
            w->offset_mm + w->width_mm > wall_length(c, n, w->wall) + 1e-6)
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "the niche \"%s\" would no longer fit in wall %d", w->name, w->wall);
    }
    return APP_OK;
}

static app_result check_opening(const app_project *p, const app_opening *o, int self, char *err,
                                size_t err_size)
{
    const app_room_plan *plan = &p->plan;
    if (!terminated(o->name, sizeof o->name) || !o->name[0])
        return fail(err, err_size, APP_ERR_SCHEMA, "an opening needs a name");
    if (o->wall < 0 || o->wall >= plan->corner_count)
        return fail(err, err_size, APP_ERR_NOT_FOUND, "no wall %d (the plan has %d)", o->wall,
                    plan->corner_count);
    if ((unsigned)o->type > APP_OPENING_WINDOW || (unsigned)o->swing > APP_SWING_SLIDING)
        return fail(err, err_size, APP_ERR_SCHEMA, "opening \"%s\": unknown type or swing",
                    o->name);
    double len = wall_length(plan->corners, plan->corner_count, o->wall);
    if (!finite_in(o->offset_mm, 0, len) || !finite_in(o->width_mm, 1, len) ||
        o->offset_mm + o->width_mm > len + 1e-6)
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "opening \"%s\": %.0f + %.0f mm does not fit in wall %d (%.0f mm long)",
                    o->name, o->offset_mm, o->width_mm, o->wall, len);
    if (!finite_in(o->sill_mm, 0, MAX_COORD_MM) || !finite_in(o->height_mm, 1, MAX_COORD_MM) ||
        (plan->height_mm > 0 && o->sill_mm + o->height_mm > plan->height_mm + 1e-6))
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "opening \"%s\": sill %.0f + height %.0f mm must fit below the ceiling "
                    "(%.0f mm)",
                    o->name, o->sill_mm, o->height_mm, plan->height_mm);
    for (int k = 0; k < 3; k++)
        if (!finite_in(o->light[k], 0, 1e6))
            return fail(err, err_size, APP_ERR_SCHEMA, "opening \"%s\": light must be >= 0",
                        o->name);
    for (int k = 0; k < plan->opening_count; k++) {
        const app_opening *b = &plan->openings[k];
        if (k == self)
            continue;
        if (!strcmp(b->name, o->name))
            return fail(err, err_size, APP_ERR_SCHEMA, "an opening is already named \"%s\"",
                        o->name);
        if (b->wall == o->wall && o->offset_mm < b->offset_mm + b->width_mm &&
            b->offset_mm < o->offset_mm + o->width_mm)
            return fail(err, err_size, APP_ERR_SCHEMA, "opening \"%s\" would overlap \"%s\"",
                        o->name, b->name);
    }
    return APP_OK;
}

static app_result check_along_wall(const app_project *p, const char *what, const char *name,
                                   int wall, double offset, double width, char *err,
                                   size_t err_size)
{
    const app_room_plan *plan = &p->plan;
    if (!name[0])
        return fail(err, err_size, APP_ERR_SCHEMA, "a %s needs a name", what);
    if (wall < 0 || wall >= plan->corner_count)
        return fail(err, err_size, APP_ERR_NOT_FOUND, "%s \"%s\": no wall %d (the plan has %d)",
                    what, name, wall, plan->corner_count);
    double len = wall_length(plan->corners, plan->corner_count, wall);
    if (!finite_in(offset, 0, len) || !finite_in(width, 1, len) || offset + width > len + 1e-6)
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "%s \"%s\": %.0f + %.0f mm does not fit on wall %d (%.0f mm long)", what, name,
                    offset, width, wall, len);
    return APP_OK;
}

static app_result check_prewall(const app_project *p, const app_prewall *w, char *err,
                                size_t err_size)
{
    if (!terminated(w->name, sizeof w->name))
        return fail(err, err_size, APP_ERR_SCHEMA, "pre-wall name too long");
    app_result r =
        check_along_wall(p, "pre-wall", w->name, w->wall, w->offset_mm, w->width_mm, err, err_size);
    if (r != APP_OK)
        return r;
    if (!finite_in(w->depth_mm, 1, MAX_COORD_MM) || !finite_in(w->height_mm, 1, MAX_COORD_MM))
        return fail(err, err_size, APP_ERR_SCHEMA, "pre-wall \"%s\": depth and height must be > 0",
                    w->name);
    if (strchr(w->name, ':'))
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "pre-wall \"%s\": a name with ':' cannot name its surfaces", w->name);
    for (int k = 0; k < p->plan.prewall_count; k++)
        if (!strcmp(p->plan.prewalls[k].name, w->name))
            return fail(err, err_size, APP_ERR_SCHEMA, "a pre-wall is already named \"%s\"",
                        w->name);
    return APP_OK;
}

static app_result check_niche(const app_project *p, const app_niche *w, char *err, size_t err_size)
{
    if (!terminated(w->name, sizeof w->name))
        return fail(err, err_size, APP_ERR_SCHEMA, "niche name too long");
    app_result r =
        check_along_wall(p, "niche", w->name, w->wall, w->offset_mm, w->width_mm, err, err_size);
    if (r != APP_OK)
        return r;
    double thick = p->plan.wall_thickness_mm > 0 ? p->plan.wall_thickness_mm
                                                 : APP_ROOM_DEFAULT_WALL_THICKNESS_MM;
    if (!finite_in(w->depth_mm, 1, thick - 1e-6) || !finite_in(w->sill_mm, 0, MAX_COORD_MM) ||
        !finite_in(w->height_mm, 1, MAX_COORD_MM))
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "niche \"%s\": depth must be > 0 and less than the wall (%.0f mm), sill >= 0, "
                    "height > 0",
                    w->name, thick);
    for (int k = 0; k < p->plan.niche_count; k++)
        if (!strcmp(p->plan.niches[k].name, w->name))
            return fail(err, err_size, APP_ERR_SCHEMA, "a niche is already named \"%s\"", w->name);
    return APP_OK;
}

/* "floor", "ceiling", "wall:I", "prewall:NAME:front|top|left|right" (app/design/room.h). */
static int surface_exists(const app_project *p, const char *s)
{
    if (!strcmp(s, "floor") || !strcmp(s, "ceiling") || app_room_reveal_find(&p->plan, s, NULL))
        return 1;
    if (!strncmp(s, "wall:", 5)) {
        char *end;
        long i = strtol(s + 5, &end, 10);
        return end != s + 5 && !*end && i >= 0 && i < p->plan.corner_count;
    }
    if (!strncmp(s, "prewall:", 8)) {
        const char *name = s + 8, *colon = strrchr(name, ':');
        if (!colon)
            return 0;
        const char *face = colon + 1;
        if (strcmp(face, "front") && strcmp(face, "top") && strcmp(face, "left") &&
            strcmp(face, "right"))
            return 0;
        for (int k = 0; k < p->plan.prewall_count; k++)
            if (strlen(p->plan.prewalls[k].name) == (size_t)(colon - name) &&
                !strncmp(p->plan.prewalls[k].name, name, (size_t)(colon - name)))
                return 1;
    }
    return 0;
}

static app_result check_tiling(const app_project *p, const app_tiling *t, char *err,
                               size_t err_size)
{
    if (!terminated(t->name, sizeof t->name) || !terminated(t->surface, sizeof t->surface) ||
        !terminated(t->product.manufacturer, sizeof t->product.manufacturer) ||
        !terminated(t->product.article, sizeof t->product.article) ||
        !terminated(t->product.variant, sizeof t->product.variant))
        return fail(err, err_size, APP_ERR_SCHEMA, "tiling: a text field is too long");
    if (!surface_exists(p, t->surface))
        return fail(err, err_size, APP_ERR_NOT_FOUND,
                    "no surface \"%s\" (floor, ceiling, wall:0..%d, prewall:NAME:front|top|left|"
                    "right, reveal:OPENING:FACE, niche:NAME:FACE)",
                    t->surface, p->plan.corner_count - 1);
    if (!t->product.manufacturer[0] || !t->product.article[0])
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "tiling \"%s\": the tile needs a manufacturer and an article number", t->name);
    for (int k = 0; k < t->border_count && k < APP_TILING_MAX_BORDERS; k++)
        if (!t->borders[k].product.manufacturer[0] || !t->borders[k].product.article[0] ||
            !finite_in(t->borders[k].bottom_mm, 0, MAX_COORD_MM))
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "tiling \"%s\": border %d needs a product and a height >= 0", t->name, k);
    if ((unsigned)t->pattern > APP_PATTERN_HERRINGBONE || (unsigned)t->align > APP_ALIGN_AUTO)
        return fail(err, err_size, APP_ERR_SCHEMA, "tiling \"%s\": unknown pattern or alignment",
                    t->name);
    if (!finite_in(t->grout_mm, 0, 100))
        return fail(err, err_size, APP_ERR_SCHEMA, "tiling \"%s\": grout %g mm (0 to 100)", t->name,
                    t->grout_mm);
    for (int k = 0; k < 3; k++)
        if (!finite_in(t->grout_color[k], 0, 1))
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "tiling \"%s\": grout colour components are 0 to 1", t->name);
    if (!finite_in(t->origin_mm[0], -MAX_COORD_MM, MAX_COORD_MM) ||
        !finite_in(t->origin_mm[1], -MAX_COORD_MM, MAX_COORD_MM) ||
        !finite_in(t->rotation_deg, -360, 360) || !finite_in(t->from_mm, 0, MAX_COORD_MM) ||
        !finite_in(t->to_mm, 0, MAX_COORD_MM) || (t->to_mm > 0 && t->to_mm <= t->from_mm))
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "tiling \"%s\": origin, rotation (-360..360) or band (from < to) out of range",
                    t->name);
    if (t->border_count < 0 || t->border_count > APP_TILING_MAX_BORDERS)
        return fail(err, err_size, APP_ERR_SCHEMA, "tiling \"%s\": 0 to %d borders", t->name,
                    APP_TILING_MAX_BORDERS);
    return APP_OK;
}

static app_result check_object(const app_project *p, const app_object *o, int self, char *err,
                               size_t err_size)
{
    if (!terminated(o->name, sizeof o->name) || !o->name[0])
        return fail(err, err_size, APP_ERR_SCHEMA, "an object needs a name (up to 63 bytes)");
    if (!terminated(o->model, sizeof o->model) || !terminated(o->group, sizeof o->group) ||
        !terminated(o->parent, sizeof o->parent))
        return fail(err, err_size, APP_ERR_SCHEMA, "object \"%s\": a text field is too long",
                    o->name);
    if ((unsigned)o->shape > APP_SHAPE_MODEL)
        return fail(err, err_size, APP_ERR_SCHEMA, "object \"%s\": unknown shape", o->name);
    for (int k = 0; k < 3; k++) {
        if (!finite_in(o->position_mm[k], -MAX_COORD_MM, MAX_COORD_MM) ||
            !finite_in(o->rotation_deg[k], -1e6, 1e6) || !finite_in(o->scale[k], -1000, 1000) ||
            !finite_in(o->size_mm[k], 0, MAX_COORD_MM))
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "object \"%s\": position, rotation, scale (-1000..1000) and size must be "
                        "finite",
                        o->name);
    }
    /* The reader's rules for the object's kind (app/src/project/project_read_objects.c). */
    for (int k = 0; k < 3; k++)
        if (o->scale[k] == 0)
            return fail(err, err_size, APP_ERR_SCHEMA, "object \"%s\": a scale must not be 0",
                        o->name);
    if (o->has_product) {
        if (!o->product.manufacturer[0] || !o->product.article[0] ||
            !terminated(o->product.manufacturer, sizeof o->product.manufacturer) ||
            !terminated(o->product.article, sizeof o->product.article) ||
            !terminated(o->product.variant, sizeof o->product.variant))
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "object \"%s\": a product needs a manufacturer and an article number",
                        o->name);
    } else if (o->shape == APP_SHAPE_MODEL) {
        if (!o->model[0])
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "object \"%s\": a model needs a file or a catalog product", o->name);
    } else {
        int plane = o->shape == APP_SHAPE_PLANE;
        if (o->size_mm[0] <= 0 || o->size_mm[1] <= 0 || (!plane && o->size_mm[2] <= 0))
            return fail(err, err_size, APP_ERR_SCHEMA, "object \"%s\": sizes must be > 0", o->name);
        if (o->shape == APP_SHAPE_TORUS && 2 * o->size_mm[2] > fmin(o->size_mm[0], o->size_mm[1]))
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "object \"%s\": a torus tube (%g) cannot be thicker than half its "
                        "outer diameter (%g)",
                        o->name, o->size_mm[2], fmin(o->size_mm[0], o->size_mm[1]));
    }
    if (o->material < 0 || o->material >= p->material_count)
        return fail(err, err_size, APP_ERR_NOT_FOUND, "object \"%s\": no material %d (%d exist)",
                    o->name, o->material, p->material_count);
    for (int k = 0; k < p->object_count; k++)
        if (k != self && !strcmp(p->objects[k].name, o->name))
            return fail(err, err_size, APP_ERR_SCHEMA, "an object is already named \"%s\"",
                        o->name);
    return APP_OK;
}

static app_result need_index(int index, int count, const char *what, char *err, size_t err_size)
{
    if (index < 0 || index >= count)
        return fail(err, err_size, APP_ERR_NOT_FOUND, "no %s %d (there are %d)", what, index,
                    count);
    return APP_OK;
}

static int insert_at(int index, int count)
{
    return index < 0 || index > count ? count : index;
}

/* The room box follows the plan's bounding box (app/project/project.h). */
static void room_of_corners(const app_project *p, const app_point2 *c, int n, app_room *room)
{
    *room = p->room;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int i = 0; i < n; i++) {
        x0 = fmin(x0, c[i].x), x1 = fmax(x1, c[i].x);
        y0 = fmin(y0, c[i].y), y1 = fmax(y1, c[i].y);
    }
    room->width_mm = x1 - x0;
    room->depth_mm = y1 - y0;
}

static app_result build_object(const app_project *p, const app_command_desc *d, cmd_command *c,
                               char *err, size_t err_size)
{
    app_result r;
    if (d->type == APP_CMD_ADD_OBJECT) {
        if ((r = check_object(p, &d->object, -1, err, err_size)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "add \"%s\"", d->object.name);
        return cmd_add_edit(c, CMD_T_OBJECT, CMD_OP_INSERT, insert_at(d->index, p->object_count),
                            NULL, &d->object);
    }
    if ((r = need_index(d->index, p->object_count, "object", err, err_size)) != APP_OK)
        return r;
    const app_object *old = &p->objects[d->index];
    if (d->type == APP_CMD_REMOVE_OBJECT) {
        snprintf(c->label, sizeof c->label, "remove \"%s\"", old->name);
        return cmd_group_remove(p, d->index, c);
    }
    app_object o = *old;
    switch (d->type) {
    case APP_CMD_MOVE_OBJECT:
        memcpy(o.position_mm, d->position_mm, sizeof o.position_mm);
        snprintf(c->label, sizeof c->label, "move \"%s\"", o.name);
        break;
    case APP_CMD_ROTATE_OBJECT:
        o.rotation_deg[2] = d->rotation_deg;
        snprintf(c->label, sizeof c->label, "rotate \"%s\"", o.name);
        break;
    case APP_CMD_SET_OBJECT:
        o = d->object;
        snprintf(c->label, sizeof c->label, "change \"%s\"", o.name);
        break;
    case APP_CMD_SET_PRODUCT:
        if (!terminated(d->product.manufacturer, sizeof d->product.manufacturer) ||
            !terminated(d->product.article, sizeof d->product.article) ||
            !terminated(d->product.variant, sizeof d->product.variant) ||
            !d->product.manufacturer[0] || !d->product.article[0])
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "a product needs a manufacturer and an article number");
        o.has_product = 1;
        o.product = d->product;
        snprintf(c->label, sizeof c->label, "set the product of \"%s\"", o.name);
        break;
    default: /* APP_CMD_SET_VARIANT */
        if (!o.has_product)
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "\"%s\" is not a catalog product: it has no variants", o.name);
        if (!terminated(d->variant, sizeof d->variant))
            return fail(err, err_size, APP_ERR_SCHEMA, "variant code too long");
        memcpy(o.product.variant, d->variant, sizeof o.product.variant);
        snprintf(c->label, sizeof c->label, "set the finish of \"%s\"", o.name);
        break;
    }
    if ((r = check_object(p, &o, d->index, err, err_size)) != APP_OK)
        return r;
    if ((r = cmd_add_edit(c, CMD_T_OBJECT, CMD_OP_REPLACE, d->index, old, &o)) != APP_OK)
        return r;
    return cmd_group_follow(p, d->index, &o, c);
}

static app_result build_tiling(const app_project *p, const app_command_desc *d, cmd_command *c,
                               char *err, size_t err_size)
{
    app_result r;
    if (d->type == APP_CMD_SET_TILING && d->index < 0) {
        if ((r = check_tiling(p, &d->tiling, err, err_size)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "tile %s", d->tiling.surface);
        return cmd_add_edit(c, CMD_T_TILING, CMD_OP_INSERT, p->tiling_count, NULL, &d->tiling);
    }
    if ((r = need_index(d->index, p->tiling_count, "tiling", err, err_size)) != APP_OK)
        return r;
    const app_tiling *old = &p->tilings[d->index];
    if (d->type == APP_CMD_REMOVE_TILING) {
        snprintf(c->label, sizeof c->label, "remove the tiles of %s", old->surface);
        return cmd_add_edit(c, CMD_T_TILING, CMD_OP_REMOVE, d->index, old, NULL);
    }
    app_tiling t = *old;
    const char *what = "tiling";
    switch (d->type) {
    case APP_CMD_SET_TILING:
        t = d->tiling;
        break;
    case APP_CMD_SET_TILE_PRODUCT:
        if (!d->product.manufacturer[0] || !d->product.article[0])
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "a tile product needs a manufacturer and an article number");
        t.product = d->product;
        what = "tile";
        break;
    case APP_CMD_SET_TILE_PATTERN:
        t.pattern = d->pattern;
        what = "pattern";
        break;
    case APP_CMD_SET_GROUT:
        t.grout_mm = d->grout_mm;
        memcpy(t.grout_color, d->grout_color, sizeof t.grout_color);
        what = "grout";
        break;
    case APP_CMD_SET_TILE_START:
        t.align = d->align;
        memcpy(t.origin_mm, d->origin_mm, sizeof t.origin_mm);
        what = "start point";
        break;
    default: /* APP_CMD_SET_TILE_ROTATION */
        t.rotation_deg = d->rotation_deg;
        what = "tile rotation";
        break;
    }
    if ((r = check_tiling(p, &t, err, err_size)) != APP_OK)
        return r;
    snprintf(c->label, sizeof c->label, "set the %s of %s", what, t.surface);
    return cmd_add_edit(c, CMD_T_TILING, CMD_OP_REPLACE, d->index, old, &t);
}

/* The tilings of the faces of an opening's reveals or a niche (KIND:NAME:FACE) go with it, from
 * the last so the indices stay valid. */
static app_result remove_face_tilings(cmd_command *c, const app_project *p, const char *kind,
                                      const char *name)
{
    char prefix[96];
    snprintf(prefix, sizeof prefix, "%s:%.64s:", kind, name);
    app_result r = APP_OK;
    for (int k = p->tiling_count - 1; k >= 0 && r == APP_OK; k--)
        if (!strncmp(p->tilings[k].surface, prefix, strlen(prefix)))
            r = cmd_add_edit(c, CMD_T_TILING, CMD_OP_REMOVE, k, &p->tilings[k], NULL);
    return r;
}

static app_result build_plan(const app_project *p, const app_command_desc *d, cmd_command *c,
                             char *err, size_t err_size)
{
    const app_room_plan *plan = &p->plan;
    app_result r;
    switch (d->type) {
    case APP_CMD_ADD_OPENING:
        if ((r = check_opening(p, &d->opening, -1, err, err_size)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "add the %s \"%s\"",
                 d->opening.type == APP_OPENING_DOOR ? "door" : "window", d->opening.name);
        return cmd_add_edit(c, CMD_T_OPENING, CMD_OP_INSERT,
                            insert_at(d->index, plan->opening_count), NULL, &d->opening);
    case APP_CMD_REMOVE_OPENING:
        if ((r = need_index(d->index, plan->opening_count, "opening", err, err_size)) != APP_OK ||
            (r = remove_face_tilings(c, p, "reveal", plan->openings[d->index].name)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "remove \"%s\"", plan->openings[d->index].name);
        return cmd_add_edit(c, CMD_T_OPENING, CMD_OP_REMOVE, d->index, &plan->openings[d->index],
                            NULL);
    case APP_CMD_MOVE_OPENING: {
        if ((r = need_index(d->index, plan->opening_count, "opening", err, err_size)) != APP_OK)
            return r;
        app_opening o = plan->openings[d->index];
        o.wall = d->wall;
        o.offset_mm = d->offset_mm;
        if ((r = check_opening(p, &o, d->index, err, err_size)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "move \"%s\"", o.name);
        return cmd_add_edit(c, CMD_T_OPENING, CMD_OP_REPLACE, d->index, &plan->openings[d->index],
                            &o);
    }
    case APP_CMD_MOVE_CORNER: {
        if ((r = need_index(d->index, plan->corner_count, "corner", err, err_size)) != APP_OK)
            return r;
        int n = plan->corner_count;
        app_point2 *moved = malloc((size_t)n * sizeof *moved);
        if (!moved)
            return fail(err, err_size, APP_ERR_OUT_OF_MEMORY, "out of memory");
        memcpy(moved, plan->corners, (size_t)n * sizeof *moved);
        moved[d->index] = d->corner;
        r = check_polygon(moved, n, err, err_size);
        if (r == APP_OK)
            r = check_wall_items(plan, moved, n, err, err_size);
        app_room room;
        room_of_corners(p, moved, n, &room);
        free(moved);
        if (r != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "move corner %d", d->index);
        if ((r = cmd_add_edit(c, CMD_T_CORNER, CMD_OP_REPLACE, d->index, &plan->corners[d->index],
                              &d->corner)) != APP_OK)
            return r;
        return cmd_add_edit(c, CMD_T_ROOM, CMD_OP_REPLACE, 0, &p->room, &room);
    }
    case APP_CMD_ADD_PREWALL:
        if ((r = check_prewall(p, &d->prewall, err, err_size)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "add the pre-wall \"%s\"", d->prewall.name);
        return cmd_add_edit(c, CMD_T_PREWALL, CMD_OP_INSERT,
                            insert_at(d->index, plan->prewall_count), NULL, &d->prewall);
    case APP_CMD_REMOVE_PREWALL: {
        if ((r = need_index(d->index, plan->prewall_count, "pre-wall", err, err_size)) != APP_OK)
            return r;
        const app_prewall *w = &plan->prewalls[d->index];
        char prefix[96];
        snprintf(prefix, sizeof prefix, "prewall:%s:", w->name);
        /* Its faces' tilings go first, from the last so the indices stay valid. */
        for (int k = p->tiling_count - 1; k >= 0; k--)
            if (!strncmp(p->tilings[k].surface, prefix, strlen(prefix)) &&
                (r = cmd_add_edit(c, CMD_T_TILING, CMD_OP_REMOVE, k, &p->tilings[k], NULL)) !=
                    APP_OK)
                return r;
        snprintf(c->label, sizeof c->label, "remove the pre-wall \"%s\"", w->name);
        return cmd_add_edit(c, CMD_T_PREWALL, CMD_OP_REMOVE, d->index, w, NULL);
    }
    case APP_CMD_ADD_NICHE:
        if ((r = check_niche(p, &d->niche, err, err_size)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "add the niche \"%s\"", d->niche.name);
        return cmd_add_edit(c, CMD_T_NICHE, CMD_OP_INSERT, insert_at(d->index, plan->niche_count),
                            NULL, &d->niche);
    default: /* APP_CMD_REMOVE_NICHE */
        if ((r = need_index(d->index, plan->niche_count, "niche", err, err_size)) != APP_OK ||
            (r = remove_face_tilings(c, p, "niche", plan->niches[d->index].name)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "remove the niche \"%s\"", plan->niches[d->index].name);
        return cmd_add_edit(c, CMD_T_NICHE, CMD_OP_REMOVE, d->index, &plan->niches[d->index], NULL);
    }
}

/* The reader's ranges for a material (docs/project-format.md), so that whatever a command
 * adds can be saved. */
static app_result check_material(const app_material *m, char *err, size_t err_size)
{
    if (!terminated(m->texture, sizeof m->texture) ||
        !terminated(m->probe_map, sizeof m->probe_map))
        return fail(err, err_size, APP_ERR_SCHEMA, "material \"%s\": a path is too long", m->name);
    const float *colours[4] = {m->ambient, m->diffuse, m->specular, m->emissive};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++)
            if (!finite_in(colours[i][k], 0, 1e6))
                return fail(err, err_size, APP_ERR_SCHEMA,
                            "material \"%s\": colours are finite and >= 0", m->name);
    if (!finite_in(m->shininess, 0, 1e6) || !finite_in(m->texture_size_mm[0], 1e-6, MAX_COORD_MM) ||
        !finite_in(m->texture_size_mm[1], 1e-6, MAX_COORD_MM))
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "material \"%s\": shininess 0 to 1e6, texture size > 0", m->name);
    if (!finite_in(m->reflectivity, 0, 1) || !finite_in(m->glossiness, 0, 1) ||
        !finite_in(m->transparency, 0, 1) || !finite_in(m->ior, 1, 3) ||
        !finite_in(m->dispersion, 0, 0.2) || !finite_in(m->grain_deg, 0, 180) ||
        m->blend < APP_BLEND_MIX || m->blend > APP_BLEND_FRESNEL ||
        !finite_in(m->proxy_radius_mm, 0, MAX_COORD_MM))
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "material \"%s\": reflectivity, glossiness and transparency 0 to 1, ior 1 "
                    "to 3, dispersion 0 to 0.2, grain 0 to 180",
                    m->name);
    return APP_OK;
}

static app_result build_material(const app_project *p, const app_command_desc *d, cmd_command *c,
                                 char *err, size_t err_size)
{
    app_result r;
    if (d->type == APP_CMD_ADD_MATERIAL) {
        const app_material *m = &d->material;
        if (!terminated(m->name, sizeof m->name) || !m->name[0])
            return fail(err, err_size, APP_ERR_SCHEMA, "a material needs a name");
        if (app_project_find_material(p, m->name) >= 0)
            return fail(err, err_size, APP_ERR_SCHEMA, "a material is already named \"%s\"",
                        m->name);
        if ((r = check_material(m, err, err_size)) != APP_OK)
            return r;
        snprintf(c->label, sizeof c->label, "add the material \"%s\"", m->name);
        return cmd_add_edit(c, CMD_T_MATERIAL, CMD_OP_INSERT, p->material_count, NULL, m);
    }
    if ((r = need_index(d->index, p->material_count, "material", err, err_size)) != APP_OK)
        return r;
    if (d->type == APP_CMD_SET_PATTERN) {
        if (d->material_pattern < APP_PATTERN_NONE || d->material_pattern > APP_PATTERN_WOOD)
            return fail(err, err_size, APP_ERR_SCHEMA, "a material's pattern is none or wood");
        if (!finite_in(d->material_grain_deg, 0, 180))
            return fail(err, err_size, APP_ERR_SCHEMA, "a wood grain's angle is 0 to 180 degrees");
        app_material m = p->materials[d->index];
        m.pattern = d->material_pattern;
        m.grain_deg = d->material_grain_deg;
        snprintf(c->label, sizeof c->label, "set the pattern of \"%s\"", m.name);
        return cmd_add_edit(c, CMD_T_MATERIAL, CMD_OP_REPLACE, d->index, &p->materials[d->index],
                            &m);
    }
    if (!finite_in(d->reflectivity, 0, 1) || !finite_in(d->glossiness, 0, 1) ||
        d->blend < APP_BLEND_MIX || d->blend > APP_BLEND_FRESNEL)
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "reflectivity and glossiness are 0 to 1; blend is mix, add or fresnel");
    app_material m = p->materials[d->index];
    m.reflectivity = d->reflectivity;
    m.glossiness = d->glossiness;
    m.blend = d->blend;
    snprintf(c->label, sizeof c->label, "set the reflection of \"%s\"", m.name);
    return cmd_add_edit(c, CMD_T_MATERIAL, CMD_OP_REPLACE, d->index, &p->materials[d->index], &m);
}

app_result cmd_build(const app_project *p, const app_command_desc *d, cmd_command *out, char *err,
                     size_t err_size)
{
    memset(out, 0, sizeof *out);
    if (err && err_size)
        err[0] = 0;
    app_result r;
    switch (d->type) {
    case APP_CMD_ADD_OBJECT:
    case APP_CMD_REMOVE_OBJECT:
    case APP_CMD_MOVE_OBJECT:
    case APP_CMD_ROTATE_OBJECT:
    case APP_CMD_SET_OBJECT:
    case APP_CMD_SET_PRODUCT:
    case APP_CMD_SET_VARIANT:
        r = build_object(p, d, out, err, err_size);
        break;
    case APP_CMD_SET_TILING:
    case APP_CMD_REMOVE_TILING:
    case APP_CMD_SET_TILE_PRODUCT:
    case APP_CMD_SET_TILE_PATTERN:
    case APP_CMD_SET_GROUT:
    case APP_CMD_SET_TILE_START:
    case APP_CMD_SET_TILE_ROTATION:
        r = build_tiling(p, d, out, err, err_size);
        break;
    case APP_CMD_ADD_OPENING:
    case APP_CMD_REMOVE_OPENING:
    case APP_CMD_MOVE_OPENING:
    case APP_CMD_MOVE_CORNER:
    case APP_CMD_ADD_PREWALL:
    case APP_CMD_REMOVE_PREWALL:
    case APP_CMD_ADD_NICHE:
    case APP_CMD_REMOVE_NICHE:
        r = build_plan(p, d, out, err, err_size);
        break;
    case APP_CMD_ADD_MATERIAL:
    case APP_CMD_SET_REFLECTION:
    case APP_CMD_SET_PATTERN:
        r = build_material(p, d, out, err, err_size);
        break;
    case APP_CMD_SET_PROBE:
        r = cmd_build_probe(p, d, out, err, err_size);
        break;
    case APP_CMD_SET_PARENT:
    case APP_CMD_UNGROUP:
        r = cmd_build_parent(p, d, out, err, err_size);
        break;
    default:
        r = fail(err, err_size, APP_ERR_SCHEMA, "unknown command type %d", (int)d->type);
        break;
    }
    if (r == APP_ERR_OUT_OF_MEMORY && err && err_size && !err[0])
        snprintf(err, err_size, "out of memory");
    if (r != APP_OK)
        cmd_free(out);
    return r;
}

const char *app_command_type_name(app_command_type t)
{
    static const char *const names[APP_CMD_COUNT] = {
        "add-object",     "remove-object",     "move-object",      "rotate-object",
        "set-object",     "set-product",       "set-variant",      "set-tiling",
        "remove-tiling",  "set-tile-product",  "set-tile-pattern", "set-grout",
        "set-tile-start", "set-tile-rotation", "add-opening",      "remove-opening",
        "move-opening",   "move-corner",       "add-prewall",      "remove-prewall",
        "add-niche",      "remove-niche",      "add-material",     "set-reflection",
        "set-probe",      "set-parent",        "ungroup",          "set-pattern"};
    return (unsigned)t < APP_CMD_COUNT ? names[t] : "unknown";
}
