/* Element edits on the arrays of an app_project: the only code that changes a document on
 * behalf of a command, forward and backward. */
#include "cmd_internal.h"

#include <stdlib.h>
#include <string.h>

size_t cmd_elem_size(cmd_target t)
{
    switch (t) {
    case CMD_T_CORNER:
        return sizeof(app_point2);
    case CMD_T_OPENING:
        return sizeof(app_opening);
    case CMD_T_PREWALL:
        return sizeof(app_prewall);
    case CMD_T_NICHE:
        return sizeof(app_niche);
    case CMD_T_TILING:
        return sizeof(app_tiling);
    case CMD_T_MATERIAL:
        return sizeof(app_material);
    case CMD_T_OBJECT:
        return sizeof(app_object);
    case CMD_T_ROOM:
        return sizeof(app_room);
    default:
        return 0;
    }
}

/* The array of target t: its base and count. */
static void array_get(app_project *p, cmd_target t, void **base, int *count)
{
    switch (t) {
    case CMD_T_CORNER:
        *base = p->plan.corners, *count = p->plan.corner_count;
        break;
    case CMD_T_OPENING:
        *base = p->plan.openings, *count = p->plan.opening_count;
        break;
    case CMD_T_PREWALL:
        *base = p->plan.prewalls, *count = p->plan.prewall_count;
        break;
    case CMD_T_NICHE:
        *base = p->plan.niches, *count = p->plan.niche_count;
        break;
    case CMD_T_TILING:
        *base = p->tilings, *count = p->tiling_count;
        break;
    case CMD_T_MATERIAL:
        *base = p->materials, *count = p->material_count;
        break;
    case CMD_T_OBJECT:
        *base = p->objects, *count = p->object_count;
        break;
    default:
        *base = &p->room, *count = 1;
        break;
    }
}

static void array_set(app_project *p, cmd_target t, void *base, int count)
{
    switch (t) {
    case CMD_T_CORNER:
        p->plan.corners = base, p->plan.corner_count = count;
        break;
    case CMD_T_OPENING:
        p->plan.openings = base, p->plan.opening_count = count;
        break;
    case CMD_T_PREWALL:
        p->plan.prewalls = base, p->plan.prewall_count = count;
        break;
    case CMD_T_NICHE:
        p->plan.niches = base, p->plan.niche_count = count;
        break;
    case CMD_T_TILING:
        p->tilings = base, p->tiling_count = count;
        break;
    case CMD_T_MATERIAL:
        p->materials = base, p->material_count = count;
        break;
    case CMD_T_OBJECT:
        p->objects = base, p->object_count = count;
        break;
    default:
        break;
    }
}

static app_result do_insert(app_project *p, cmd_target t, int index, const void *value)
{
    void *base;
    int count;
    array_get(p, t, &base, &count);
    size_t es = cmd_elem_size(t);
    if (t == CMD_T_ROOM || index < 0 || index > count)
        return APP_ERR_NOT_FOUND;
    char *grown = realloc(base, (size_t)(count + 1) * es);
    if (!grown)
        return APP_ERR_OUT_OF_MEMORY;
    memmove(grown + (size_t)(index + 1) * es, grown + (size_t)index * es,
            (size_t)(count - index) * es);
    memcpy(grown + (size_t)index * es, value, es);
    array_set(p, t, grown, count + 1);
    return APP_OK;
}

static app_result do_remove(app_project *p, cmd_target t, int index)
{
    void *base;
    int count;
    array_get(p, t, &base, &count);
    size_t es = cmd_elem_size(t);
    if (t == CMD_T_ROOM || index < 0 || index >= count)
        return APP_ERR_NOT_FOUND;
    char *b = base;
    memmove(b + (size_t)index * es, b + (size_t)(index + 1) * es, (size_t)(count - index - 1) * es);
    /* The block keeps its size, so undoing this remove (an insert) never needs memory. */
    array_set(p, t, base, count - 1);
    return APP_OK;
}

static app_result do_replace(app_project *p, cmd_target t, int index, const void *value)
{
    void *base;
    int count;
    array_get(p, t, &base, &count);
    if (index < 0 || index >= count)
        return APP_ERR_NOT_FOUND;
    size_t es = cmd_elem_size(t);
    memcpy((char *)base + (size_t)index * es, value, es);
    return APP_OK;
}

static app_result run_one(const cmd_edit *e, app_project *p, int forward)
{
    switch (e->op) {
    case CMD_OP_INSERT:
        return forward ? do_insert(p, e->target, e->index, e->after)
                       : do_remove(p, e->target, e->index);
    case CMD_OP_REMOVE:
        return forward ? do_remove(p, e->target, e->index)
                       : do_insert(p, e->target, e->index, e->before);
    default:
        return do_replace(p, e->target, e->index, forward ? e->after : e->before);
    }
}

app_result cmd_run(const cmd_command *c, app_project *p, int forward)
{
    int n = c->count;
    for (int k = 0; k < n; k++) {
        const cmd_edit *e = &c->edits[forward ? k : n - 1 - k];
        app_result r = run_one(e, p, forward);
        if (r != APP_OK) {
            /* Put back what this run already did, so the document is as before. */
            for (int j = k - 1; j >= 0; j--)
                run_one(&c->edits[forward ? j : n - 1 - j], p, !forward);
            return r;
        }
    }
    return APP_OK;
}

static void *dup_value(const void *v, size_t size)
{
    if (!v)
        return NULL;
    void *d = malloc(size);
    if (d)
        memcpy(d, v, size);
    return d;
}

app_result cmd_add_edit(cmd_command *c, cmd_target t, cmd_op op, int index, const void *before,
                        const void *after)
{
    if (c->count == c->capacity) {
        int cap = c->capacity ? 2 * c->capacity : 4;
        cmd_edit *e = realloc(c->edits, (size_t)cap * sizeof *e);
        if (!e)
            return APP_ERR_OUT_OF_MEMORY;
        c->edits = e;
        c->capacity = cap;
    }
    size_t es = cmd_elem_size(t);
    cmd_edit e = {t, op, index, NULL, NULL};
    e.before = op != CMD_OP_INSERT ? dup_value(before, es) : NULL;
    e.after = op != CMD_OP_REMOVE ? dup_value(after, es) : NULL;
    if ((op != CMD_OP_INSERT && !e.before) || (op != CMD_OP_REMOVE && !e.after)) {
        free(e.before);
        free(e.after);
        return APP_ERR_OUT_OF_MEMORY;
    }
    c->edits[c->count++] = e;
    return APP_OK;
}

app_result cmd_append(cmd_command *dst, cmd_command *src)
{
    if (dst->count + src->count > dst->capacity) {
        int cap = dst->count + src->count + 4;
        cmd_edit *e = realloc(dst->edits, (size_t)cap * sizeof *e);
        if (!e)
            return APP_ERR_OUT_OF_MEMORY;
        dst->edits = e;
        dst->capacity = cap;
    }
    memcpy(dst->edits + dst->count, src->edits, (size_t)src->count * sizeof *src->edits);
    dst->count += src->count;
    src->count = 0;
    return APP_OK;
}

void cmd_free(cmd_command *c)
{
    if (!c)
        return;
    for (int i = 0; i < c->count; i++) {
        free(c->edits[i].before);
        free(c->edits[i].after);
    }
    free(c->edits);
    memset(c, 0, sizeof *c);
}
