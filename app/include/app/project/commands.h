/* Edits of a project as commands with undo and redo: the one layer through which the UI and
 * `tessera edit` change an app_project (docs/editing.md).
 *
 * An edit is described by an app_command_desc (a type and the fields that type reads; fields
 * left zero take no part). app_history_do checks it against the project, applies it and
 * records exactly what it changed, element by element (the object, tiling, opening, corner
 * ... before and after), so undo restores the document bit for bit and redo re-applies the
 * same values. A command that fails its checks changes nothing.
 *
 *     app_history *h = app_history_create(100);
 *     app_command_desc d = {.type = APP_CMD_MOVE_OBJECT, .index = 3,
 *                           .position_mm = {1200, 0, 850}};
 *     if (app_history_do(h, &project, &d, err, sizeof err) != APP_OK) show(err);
 *     app_history_undo(h, &project, err, sizeof err);
 *
 * Groups: an object whose `parent` names another object is mounted on it (a basin on its
 * vanity, a tap on its basin, a mirror above the basin). Moving, rotating or removing an
 * object (APP_CMD_MOVE_OBJECT, APP_CMD_ROTATE_OBJECT, APP_CMD_SET_OBJECT, APP_CMD_REMOVE_OBJECT)
 * takes everything mounted on it, directly or through others, along in the same undo step:
 * moved by the same offset, turned about the object's position by the same angle, removed.
 *
 * Results: APP_OK; APP_ERR_NOT_FOUND for an index out of range or nothing to undo/redo;
 * APP_ERR_SCHEMA when the edit would make an invalid project (the message says which rule);
 * APP_ERR_OUT_OF_MEMORY. The project's arrays are reallocated with realloc/free, as
 * app_project_free expects. Not thread-safe: one history per document. */
#ifndef APP_COMMANDS_H
#define APP_COMMANDS_H

#include "app/design/placement.h"
#include "app/project/project.h"

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum app_command_type {
    APP_CMD_ADD_OBJECT = 0,    /* object; index = position to insert at, -1 = at the end */
    APP_CMD_REMOVE_OBJECT,     /* index */
    APP_CMD_MOVE_OBJECT,       /* index, position_mm (absolute) */
    APP_CMD_ROTATE_OBJECT,     /* index, rotation_deg (about Z, absolute) */
    APP_CMD_SET_OBJECT,        /* index, object: replaces it whole (property panels) */
    APP_CMD_SET_PRODUCT,       /* index, product (manufacturer, article, variant) */
    APP_CMD_SET_VARIANT,       /* index, variant (the object must have a product) */
    APP_CMD_SET_TILING,        /* index (-1 = add), tiling */
    APP_CMD_REMOVE_TILING,     /* index */
    APP_CMD_SET_TILE_PRODUCT,  /* index, product */
    APP_CMD_SET_TILE_PATTERN,  /* index, pattern */
    APP_CMD_SET_GROUT,         /* index, grout_mm, grout_color */
    APP_CMD_SET_TILE_START,    /* index, align, origin_mm */
    APP_CMD_SET_TILE_ROTATION, /* index, rotation_deg */
    APP_CMD_ADD_OPENING,       /* opening (index -1 = at the end) */
    APP_CMD_REMOVE_OPENING,    /* index */
    APP_CMD_MOVE_OPENING,      /* index, wall, offset_mm */
    APP_CMD_MOVE_CORNER,       /* index (the corner), corner */
    APP_CMD_ADD_PREWALL,       /* prewall */
    APP_CMD_REMOVE_PREWALL,    /* index; the tilings of its faces go with it */
    APP_CMD_ADD_NICHE,         /* niche */
    APP_CMD_REMOVE_NICHE,      /* index */
    APP_CMD_ADD_MATERIAL,      /* material (its name must be new) */
    APP_CMD_SET_REFLECTION,    /* index (material), reflectivity, glossiness, blend */
    APP_CMD_SET_PROBE,         /* index (material), probe_update, probe_every, probe_resolution,
                                  correction (cmd_probe.c) */
    APP_CMD_SET_PARENT,        /* index, parent (an object's name; "" = detach it) */
    APP_CMD_UNGROUP,           /* index: detaches it from its parent and its children from it */
    APP_CMD_SET_PATTERN,       /* index (material), material_pattern */
    APP_CMD_COUNT
} app_command_type;

typedef struct app_command_desc {
    app_command_type type;
    int index;
    app_object object;
    double position_mm[3];
    double rotation_deg;
    app_product_ref product;
    char variant[16];
    app_tiling tiling;
    app_tile_pattern pattern;
    double grout_mm;
    float grout_color[3];
    app_tile_align align;
    double origin_mm[2];
    app_opening opening;
    int wall;
    double offset_mm;
    app_point2 corner;
    app_prewall prewall;
    app_niche niche;
    app_material material;
    float reflectivity, glossiness;
    int blend; /* APP_BLEND_* */
    /* APP_CMD_SET_PROBE: the material's reflection probe policy (app_material's fields of
     * the same names; RENDERING.md section 8). */
    int probe_update, probe_every, probe_resolution, correction;
    char parent[64];          /* APP_CMD_SET_PARENT */
    int material_pattern;     /* APP_CMD_SET_PATTERN: APP_PATTERN_* */
    float material_grain_deg; /* APP_CMD_SET_PATTERN: app_material.grain_deg */
} app_command_desc;

/* The objects mounted on object `index`, directly or through others (app_object.parent),
 * written to out (room for p->object_count); returns how many. A live drag moves them with
 * the object it drags, as the move edit on release will. */
int app_group_members(const app_project *p, int index, int *out);

/* "add-object", "move-object", ... (never NULL). */
const char *app_command_type_name(app_command_type t);

typedef struct app_history app_history;

/* limit: the most undo steps kept (older ones are dropped), >= 1; 0 = 1000. NULL when out
 * of memory. */
app_history *app_history_create(int limit);
void app_history_destroy(app_history *h);
/* Forgets every step (after loading another document). */
void app_history_clear(app_history *h);

/* Checks and applies d to p; on success pushes it on the undo stack and clears the redo
 * stack. On failure p is unchanged. */
app_result app_history_do(app_history *h, app_project *p, const app_command_desc *d, char *err,
                          size_t err_size);
app_result app_history_undo(app_history *h, app_project *p, char *err, size_t err_size);
app_result app_history_redo(app_history *h, app_project *p, char *err, size_t err_size);

/* Checks d against p as app_history_do would, without applying it (a UI greys out or
 * rejects a drag with the message). */
app_result app_command_check(const app_project *p, const app_command_desc *d, char *err,
                             size_t err_size);

/* What the last successful do, undo or redo changed, so a view refreshes only that (a tile
 * re-layout only after plan or tiling edits). */
enum {
    APP_CHANGED_OBJECTS = 1u << 0,
    APP_CHANGED_PLAN = 1u << 1, /* corners, openings, pre-walls, niches, the room box */
    APP_CHANGED_TILINGS = 1u << 2,
    APP_CHANGED_MATERIALS = 1u << 3
};
unsigned app_history_last_changed(const app_history *h);

int app_history_undo_count(const app_history *h);
int app_history_redo_count(const app_history *h);
/* What the next undo/redo does, e.g. "move \"basin\"" (for menus); "" when nothing. */
const char *app_history_undo_label(const app_history *h);
const char *app_history_redo_label(const app_history *h);

/* Everything done between begin and end is one undo step (a drag, a "place and snap"),
 * labelled `label`. Groups do not nest: a second begin ends the first. */
void app_history_begin_group(app_history *h, const char *label);
app_result app_history_end_group(app_history *h, char *err, size_t err_size);
/* Takes back everything done since begin and forgets it (a drag cancelled with Escape, a
 * compound edit whose second half failed); the redo stack is left as it was. */
app_result app_history_abort_group(app_history *h, app_project *p, char *err, size_t err_size);

/* Deep comparison of two documents, every field of every element (the file path and the
 * version fields included). Returns 1 when equal; else 0 and the first difference in diff. */
int app_project_equal(const app_project *a, const app_project *b, char *diff, size_t diff_size);

/* A deep copy of src into *dst (overwritten, not freed first). */
app_result app_project_copy(app_project *dst, const app_project *src, char *err, size_t err_size);

/* Frees what app_project_free frees and the plan's and tilings' arrays; safe whichever of
 * the two releases the version 2 arrays. */
void app_project_free_all(app_project *p);

/* ---- edit scripts (`tessera edit`; the line format is in docs/editing.md) ------------------ */

typedef struct app_script_env {
    app_product_lookup lookup; /* products for place/product/variant/tile and snapping; NULL:
                                  those lines fail */
    void *user;
    const char *assets_dir; /* resolves a product's model path; NULL = leave it "" */
    FILE *log;              /* one line per command done, or NULL */
} app_script_env;

typedef struct app_script_stats {
    int lines, commands, undone, redone;
} app_script_stats;

/* Runs the script `text` (len bytes, `name` in messages) against p through h. Stops at the
 * first line that fails, with "NAME:LINE: message" in err; the lines before it stay applied
 * (the caller decides whether to save). stats may be NULL. */
app_result app_script_run(app_project *p, app_history *h, const char *text, size_t len,
                          const char *name, const app_script_env *env, app_script_stats *stats,
                          char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
