/* Undo and redo stacks of commands (app/project/commands.h). */
#include "cmd_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct app_history {
    cmd_command *undo; /* oldest first */
    int undo_count;
    cmd_command *redo; /* the next redo last */
    int redo_count;
    int limit;
    int grouping;
    cmd_command group;
    unsigned last_changed;
};

static unsigned changed_mask(const cmd_command *c)
{
    unsigned m = 0;
    for (int i = 0; i < c->count; i++) {
        switch (c->edits[i].target) {
        case CMD_T_OBJECT:
            m |= APP_CHANGED_OBJECTS;
            break;
        case CMD_T_TILING:
            m |= APP_CHANGED_TILINGS;
            break;
        case CMD_T_MATERIAL:
            m |= APP_CHANGED_MATERIALS;
            break;
        default:
            m |= APP_CHANGED_PLAN;
            break;
        }
    }
    return m;
}

unsigned app_history_last_changed(const app_history *h)
{
    return h ? h->last_changed : 0;
}

app_result app_command_check(const app_project *p, const app_command_desc *d, char *err,
                             size_t err_size)
{
    cmd_command c;
    app_result r = cmd_build(p, d, &c, err, err_size);
    cmd_free(&c);
    return r;
}

app_history *app_history_create(int limit)
{
    if (limit <= 0)
        limit = 1000;
    app_history *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    h->limit = limit;
    h->undo = calloc((size_t)limit, sizeof *h->undo);
    h->redo = calloc((size_t)limit, sizeof *h->redo);
    if (!h->undo || !h->redo) {
        free(h->undo);
        free(h->redo);
        free(h);
        return NULL;
    }
    return h;
}

static void clear_redo(app_history *h)
{
    for (int i = 0; i < h->redo_count; i++)
        cmd_free(&h->redo[i]);
    h->redo_count = 0;
}

void app_history_clear(app_history *h)
{
    if (!h)
        return;
    clear_redo(h);
    for (int i = 0; i < h->undo_count; i++)
        cmd_free(&h->undo[i]);
    h->undo_count = 0;
    cmd_free(&h->group);
    h->grouping = 0;
}

void app_history_destroy(app_history *h)
{
    if (!h)
        return;
    app_history_clear(h);
    free(h->undo);
    free(h->redo);
    free(h);
}

/* Pushes c (taken over) on the undo stack, dropping the oldest step when full. */
static void push_undo(app_history *h, cmd_command *c)
{
    if (h->undo_count == h->limit) {
        cmd_free(&h->undo[0]);
        memmove(h->undo, h->undo + 1, (size_t)(h->limit - 1) * sizeof *h->undo);
        h->undo_count--;
    }
    h->undo[h->undo_count++] = *c;
    memset(c, 0, sizeof *c);
}

app_result app_history_do(app_history *h, app_project *p, const app_command_desc *d, char *err,
                          size_t err_size)
{
    cmd_command c;
    app_result r = cmd_build(p, d, &c, err, err_size);
    if (r != APP_OK)
        return r;
    if ((r = cmd_run(&c, p, 1)) != APP_OK) {
        cmd_free(&c);
        if (err && err_size)
            snprintf(err, err_size, "out of memory applying the edit");
        return r;
    }
    h->last_changed = changed_mask(&c);
    if (h->grouping) {
        if ((r = cmd_append(&h->group, &c)) != APP_OK) {
            cmd_run(&c, p, 0);
            cmd_free(&c);
            if (err && err_size)
                snprintf(err, err_size, "out of memory recording the edit");
            return r;
        }
        cmd_free(&c);
        return APP_OK;
    }
    clear_redo(h);
    push_undo(h, &c);
    return APP_OK;
}

app_result app_history_undo(app_history *h, app_project *p, char *err, size_t err_size)
{
    if (h->grouping && (app_history_end_group(h, err, err_size)) != APP_OK)
        return APP_ERR_OUT_OF_MEMORY;
    if (h->undo_count == 0) {
        if (err && err_size)
            snprintf(err, err_size, "nothing to undo");
        return APP_ERR_NOT_FOUND;
    }
    cmd_command *c = &h->undo[h->undo_count - 1];
    app_result r = cmd_run(c, p, 0);
    if (r != APP_OK) {
        if (err && err_size)
            snprintf(err, err_size, "undo \"%s\" failed: out of memory", c->label);
        return r;
    }
    h->last_changed = changed_mask(c);
    h->redo[h->redo_count++] = *c;
    h->undo_count--;
    return APP_OK;
}

app_result app_history_redo(app_history *h, app_project *p, char *err, size_t err_size)
{
    if (h->redo_count == 0) {
        if (err && err_size)
            snprintf(err, err_size, "nothing to redo");
        return APP_ERR_NOT_FOUND;
    }
    cmd_command *c = &h->redo[h->redo_count - 1];
    app_result r = cmd_run(c, p, 1);
    if (r != APP_OK) {
        if (err && err_size)
            snprintf(err, err_size, "redo \"%s\" failed: out of memory", c->label);
        return r;
    }
    h->last_changed = changed_mask(c);
    cmd_command moved = *c;
    h->redo_count--;
    /* push_undo never drops a step here: an undone step freed its slot. */
    push_undo(h, &moved);
    return APP_OK;
}

int app_history_undo_count(const app_history *h)
{
    return h ? h->undo_count : 0;
}

int app_history_redo_count(const app_history *h)
{
    return h ? h->redo_count : 0;
}

const char *app_history_undo_label(const app_history *h)
{
    return h && h->undo_count ? h->undo[h->undo_count - 1].label : "";
}

const char *app_history_redo_label(const app_history *h)
{
    return h && h->redo_count ? h->redo[h->redo_count - 1].label : "";
}

void app_history_begin_group(app_history *h, const char *label)
{
    if (h->grouping)
        app_history_end_group(h, NULL, 0);
    cmd_free(&h->group);
    h->grouping = 1;
    snprintf(h->group.label, sizeof h->group.label, "%s", label ? label : "edit");
}

app_result app_history_end_group(app_history *h, char *err, size_t err_size)
{
    (void)err;
    (void)err_size;
    if (!h->grouping)
        return APP_OK;
    h->grouping = 0;
    if (h->group.count == 0) {
        cmd_free(&h->group);
        return APP_OK;
    }
    clear_redo(h);
    push_undo(h, &h->group);
    return APP_OK;
}

app_result app_history_abort_group(app_history *h, app_project *p, char *err, size_t err_size)
{
    if (!h->grouping)
        return APP_OK;
    h->grouping = 0;
    app_result r = cmd_run(&h->group, p, 0);
    if (r == APP_OK)
        h->last_changed = changed_mask(&h->group);
    else if (err && err_size)
        snprintf(err, err_size, "cancelling \"%s\" failed: out of memory", h->group.label);
    cmd_free(&h->group);
    return r;
}
