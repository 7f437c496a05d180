/* The command engine behind app/project/commands.h: a command is a list of element edits (insert,
 * remove or replace one element of one of the project's arrays), each holding the element's
 * value before and after, so undo and redo are exact and need no knowledge of the command. */
#ifndef APP_CMD_INTERNAL_H
#define APP_CMD_INTERNAL_H

#include "app/project/commands.h"

typedef enum cmd_target {
    CMD_T_CORNER = 0,
    CMD_T_OPENING,
    CMD_T_PREWALL,
    CMD_T_NICHE,
    CMD_T_TILING,
    CMD_T_MATERIAL,
    CMD_T_OBJECT,
    CMD_T_ROOM, /* the single app_room (index 0) */
    CMD_T_COUNT
} cmd_target;

typedef enum cmd_op { CMD_OP_INSERT = 0, CMD_OP_REMOVE, CMD_OP_REPLACE } cmd_op;

typedef struct cmd_edit {
    cmd_target target;
    cmd_op op;
    int index;
    void *before; /* REMOVE, REPLACE: the element as it was */
    void *after;  /* INSERT, REPLACE: the element as it becomes */
} cmd_edit;

typedef struct cmd_command {
    char label[160];
    cmd_edit *edits; /* applied in order; undone in reverse */
    int count, capacity;
} cmd_command;

size_t cmd_elem_size(cmd_target t);
/* Appends an edit, copying the values. before/after may be NULL where the op has none. */
app_result cmd_add_edit(cmd_command *c, cmd_target t, cmd_op op, int index, const void *before,
                        const void *after);
/* Moves every edit of src to the end of dst (src is left empty). */
app_result cmd_append(cmd_command *dst, cmd_command *src);
/* Applies the edits in order (forward) or undoes them in reverse; all or nothing. */
app_result cmd_run(const cmd_command *c, app_project *p, int forward);
void cmd_free(cmd_command *c);

/* Checks d against p and fills *out (zeroed first) with the edits it makes; p is unchanged. */
app_result cmd_build(const app_project *p, const app_command_desc *d, cmd_command *out, char *err,
                     size_t err_size);

/* cmd_probe.c: APP_CMD_SET_PROBE's checks and edit; the `probe` line's option words
 * (count words after the material's name) into d, starting from m's policy: 1, or 0 and why;
 * the names of the APP_PROBE_* and APP_CORRECTION_* values as the project file writes them. */
app_result cmd_build_probe(const app_project *p, const app_command_desc *d, cmd_command *c,
                           char *err, size_t err_size);
int cmd_probe_words(const app_material *m, int count, const char *const *words, app_command_desc *d,
                    char *why, size_t why_size);
const char *cmd_probe_update_name(int update);

/* cmd_group.c: objects mounted on others (app_object.parent). cmd_group_members lists the
 * objects mounted on object `index`, directly or through others (out has room for
 * p->object_count entries; returns how many). cmd_group_follow adds the edits that carry them
 * along when object `index` becomes `moved` (same offset, turned about its position by the
 * same angle). cmd_group_remove adds the edits that remove the object and them. */
int cmd_group_members(const app_project *p, int index, int *out);
app_result cmd_group_follow(const app_project *p, int index, const app_object *moved,
                            cmd_command *c);
app_result cmd_group_remove(const app_project *p, int index, cmd_command *c);
/* APP_CMD_SET_PARENT and APP_CMD_UNGROUP. */
app_result cmd_build_parent(const app_project *p, const app_command_desc *d, cmd_command *c,
                            char *err, size_t err_size);
const char *cmd_correction_name(int correction);

#endif
