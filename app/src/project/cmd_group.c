/* Objects mounted on others: a basin on its vanity, a tap on its basin, a mirror above the
 * basin (app_object.parent). The edits that carry them along when the object they hang on
 * moves, turns or goes, and setting or clearing the parent (docs/editing.md "Groups"). */
#include "cmd_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int find_name(const app_project *p, const char *name)
{
    for (int i = 0; name[0] && i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, name))
            return i;
    return -1;
}

/* 1 when object i hangs on object `root` through its chain of parents. The chain is followed
 * at most object_count steps, so a cycle written by hand into a file ends. */
static int mounted_on(const app_project *p, int i, int root)
{
    int at = i;
    for (int step = 0; step < p->object_count; step++) {
        at = find_name(p, p->objects[at].parent);
        if (at < 0)
            return 0;
        if (at == root)
            return 1;
    }
    return 0;
}

int cmd_group_members(const app_project *p, int index, int *out)
{
    int n = 0;
    for (int i = 0; i < p->object_count; i++)
        if (i != index && mounted_on(p, i, index))
            out[n++] = i;
    return n;
}

int app_group_members(const app_project *p, int index, int *out)
{
    return index >= 0 && index < p->object_count ? cmd_group_members(p, index, out) : 0;
}

app_result cmd_group_follow(const app_project *p, int index, const app_object *moved,
                            cmd_command *c)
{
    const app_object *old = &p->objects[index];
    double turn = moved->rotation_deg[2] - old->rotation_deg[2];
    double dz = moved->position_mm[2] - old->position_mm[2];
    if (turn == 0 && dz == 0 && moved->position_mm[0] == old->position_mm[0] &&
        moved->position_mm[1] == old->position_mm[1] && !strcmp(moved->name, old->name))
        return APP_OK;
    int *members = malloc(sizeof *members * (size_t)(p->object_count ? p->object_count : 1));
    if (!members)
        return APP_ERR_OUT_OF_MEMORY;
    int n = cmd_group_members(p, index, members);
    /* A rigid motion of the plan: the offset from the old position turned by `turn`, added
     * to the new position. */
    const double rad = turn * 3.14159265358979323846 / 180.0;
    const double cs = cos(rad), sn = sin(rad);
    app_result r = APP_OK;
    for (int k = 0; k < n && r == APP_OK; k++) {
        const app_object *m = &p->objects[members[k]];
        app_object o = *m;
        double rx = m->position_mm[0] - old->position_mm[0];
        double ry = m->position_mm[1] - old->position_mm[1];
        o.position_mm[0] = moved->position_mm[0] + cs * rx - sn * ry;
        o.position_mm[1] = moved->position_mm[1] + sn * rx + cs * ry;
        o.position_mm[2] = m->position_mm[2] + dz;
        o.rotation_deg[2] = m->rotation_deg[2] + turn;
        /* A renamed parent keeps its children. */
        if (!strcmp(o.parent, old->name))
            snprintf(o.parent, sizeof o.parent, "%s", moved->name);
        r = cmd_add_edit(c, CMD_T_OBJECT, CMD_OP_REPLACE, members[k], m, &o);
    }
    free(members);
    return r;
}

static int descending(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x < y) - (x > y);
}

app_result cmd_group_remove(const app_project *p, int index, cmd_command *c)
{
    int *gone = malloc(sizeof *gone * (size_t)p->object_count);
    if (!gone)
        return APP_ERR_OUT_OF_MEMORY;
    int n = cmd_group_members(p, index, gone);
    gone[n++] = index;
    /* From the highest index down, so each removal leaves the indices still to go in place
     * (and undo inserts them back from the lowest up). */
    qsort(gone, (size_t)n, sizeof *gone, descending);
    app_result r = APP_OK;
    for (int k = 0; k < n && r == APP_OK; k++)
        r = cmd_add_edit(c, CMD_T_OBJECT, CMD_OP_REMOVE, gone[k], &p->objects[gone[k]], NULL);
    free(gone);
    return r;
}

static app_result set_parent(const app_project *p, int i, const char *parent, cmd_command *c)
{
    app_object o = p->objects[i];
    if (!strcmp(o.parent, parent))
        return APP_OK;
    snprintf(o.parent, sizeof o.parent, "%s", parent);
    return cmd_add_edit(c, CMD_T_OBJECT, CMD_OP_REPLACE, i, &p->objects[i], &o);
}

app_result cmd_build_parent(const app_project *p, const app_command_desc *d, cmd_command *c,
                            char *err, size_t err_size)
{
    if (d->index < 0 || d->index >= p->object_count) {
        snprintf(err, err_size, "no object %d (there are %d)", d->index, p->object_count);
        return APP_ERR_NOT_FOUND;
    }
    const app_object *o = &p->objects[d->index];
    if (d->type == APP_CMD_UNGROUP) {
        snprintf(c->label, sizeof c->label, "ungroup \"%s\"", o->name);
        app_result r = set_parent(p, d->index, "", c);
        for (int i = 0; i < p->object_count && r == APP_OK; i++)
            if (!strcmp(p->objects[i].parent, o->name))
                r = set_parent(p, i, "", c);
        return r;
    }
    if (!memchr(d->parent, 0, sizeof d->parent)) {
        snprintf(err, err_size, "object \"%s\": the parent's name is too long", o->name);
        return APP_ERR_SCHEMA;
    }
    if (d->parent[0]) {
        int at = find_name(p, d->parent);
        if (at < 0) {
            snprintf(err, err_size, "object \"%s\": no object named \"%s\" to mount it on", o->name,
                     d->parent);
            return APP_ERR_NOT_FOUND;
        }
        if (at == d->index || mounted_on(p, at, d->index)) {
            snprintf(err, err_size,
                     "object \"%s\" cannot be mounted on \"%s\": \"%s\" hangs on \"%s\" already",
                     o->name, d->parent, d->parent, o->name);
            return APP_ERR_SCHEMA;
        }
        snprintf(c->label, sizeof c->label, "mount \"%s\" on \"%s\"", o->name, d->parent);
    } else {
        snprintf(c->label, sizeof c->label, "detach \"%s\"", o->name);
    }
    return set_parent(p, d->index, d->parent, c);
}
