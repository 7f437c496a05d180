/* Internals shared by the project_*.c files: the reading context (file name, JSON path,
 * error buffer), typed JSON value readers, path resolution and allocation. Not installed. */
#ifndef APP_PROJECT_INTERNAL_H
#define APP_PROJECT_INTERNAL_H

/* realpath is an X/Open extension of POSIX; this header comes before any system header in
 * every project_*.c file. */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700
#endif

#include "app/project/project.h"

#include <cjson/cJSON.h>
#include <stdarg.h>
#include <stddef.h>

/* ---- context: where we are, and where the message goes (project_context.c) -------------- */

typedef struct pj_ctx {
    const char *file; /* shown at the start of every message */
    const char *base; /* relative files resolve against this file's folder; NULL = cwd */
    char *err;
    size_t err_size;
    char json_path[512]; /* "$.objects[2].position" */
    size_t json_path_len;
    int path_truncated;
    app_project *p;
    int material_capacity;
    int check_files;     /* 0: "model"/"texture" are taken as written (the writer's check) */
    int *material_slots; /* hash of material names: index + 1, 0 = empty */
    size_t material_slot_count;
} pj_ctx;

void pj_ctx_init(pj_ctx *c, const char *file, const char *base, char *err, size_t err_size);
/* Frees what the context owns (not the project). */
void pj_ctx_release(pj_ctx *c);

/* Append ".key" / "[i]" to the JSON path; return a mark to restore it with pj_path_restore. */
size_t pj_path_key(pj_ctx *c, const char *key);
size_t pj_path_index(pj_ctx *c, int index);
void pj_path_restore(pj_ctx *c, size_t mark);

/* "FILE: $.path: message"; returns r. */
app_result pj_fail(pj_ctx *c, app_result r, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* "FILE: message" (no JSON path: file-level problems). */
app_result pj_fail_file(pj_ctx *c, app_result r, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* "string", "number", "array", ... */
const char *pj_type_name(const cJSON *item);

/* ---- typed readers (project_json_values.c) -------------------------------------------------
 * Each looks `key` up in the JSON object `obj` (case-sensitive; the first occurrence wins),
 * checks it, and stores it in *out. An absent key is an error when `required`, otherwise
 * *out is left as it was (the caller sets the default first). On failure the message names
 * the full JSON path, down to the array element. */

typedef struct pj_range {
    double min, max;
    int min_open, max_open; /* 1: the bound itself is excluded */
    int as_interval;        /* 1: messages say "must be in (min, max)", else the broken side */
} pj_range;

extern const pj_range PJ_ANY;          /* any finite number */
extern const pj_range PJ_FLOAT_ANY;    /* any finite number a float can hold */
extern const pj_range PJ_FLOAT_NONNEG; /* [0, FLT_MAX]: colours, intensities */
extern const pj_range PJ_POSITIVE;     /* (0, inf) */

/* Finds the member and checks its type. type_mask: cJSON_Object, cJSON_Array, ... or'ed;
 * 0 = any. *out NULL = absent (and not required). The path is unchanged on success. */
app_result pj_member(pj_ctx *c, const cJSON *obj, const char *key, int type_mask, int required,
                     const cJSON **out);

/* Checks a value already found (path already pushed). */
app_result pj_check_number(pj_ctx *c, const cJSON *item, pj_range range, double *out);

app_result pj_get_number(pj_ctx *c, const cJSON *obj, const char *key, int required, pj_range range,
                         double *out);
app_result pj_get_float(pj_ctx *c, const cJSON *obj, const char *key, int required, pj_range range,
                        float *out);
app_result pj_get_int(pj_ctx *c, const cJSON *obj, const char *key, int required, int min, int max,
                      int *out);
app_result pj_get_vec(pj_ctx *c, const cJSON *obj, const char *key, int required, int n,
                      pj_range range, double *out);
app_result pj_get_vecf(pj_ctx *c, const cJSON *obj, const char *key, int required, int n,
                       pj_range range, float *out);
/* 3 finite numbers >= 0 */
app_result pj_get_color(pj_ctx *c, const cJSON *obj, const char *key, int required, float out[3]);
/* A string that fits in out_size bytes with its NUL; allow_empty 0 refuses "". */
app_result pj_get_string(pj_ctx *c, const cJSON *obj, const char *key, int required,
                         int allow_empty, char *out, size_t out_size);
/* The number of elements of an array checked against APP_PROJECT_MAX_ITEMS. */
app_result pj_check_count(pj_ctx *c, const cJSON *array, const char *what, int *count);
/* Reads array member `key` of root (absent: no items) into a zeroed array of a->size-byte
 * elements, item i by a->read(c, item, i, element) under the path key[i]. a->items and
 * a->count (the items read whole) are set also on failure, for the caller to keep and free. */
typedef struct pj_array {
    size_t size;
    app_result (*read)(pj_ctx *c, const cJSON *item, int index, void *out);
    void *items;
    int count;
} pj_array;
app_result pj_read_array(pj_ctx *c, const cJSON *root, const char *key, pj_array *a);

/* ---- defaults (project_defaults.c) ---------------------------------------------------------- */

void pj_default_material(app_material *m);
void pj_default_object(app_object *o);
void pj_default_light(app_light *l);
void pj_default_camera(app_camera *cam);
void pj_default_render(app_render_settings *r);
void pj_default_plan(app_room_plan *plan);
void pj_default_opening(app_opening *o, app_opening_type type);
void pj_default_tiling(app_tiling *t);

/* ---- sections (project_read_*.c); each reads one top-level member of the root -------------- */

app_result pj_read_materials(pj_ctx *c, const cJSON *root);
/* A material's reflection and glass members (project_read_reflection.c). */
app_result pj_read_reflection_fields(pj_ctx *c, const cJSON *item, app_material *m);
/* The names of the APP_BLEND_*, APP_CORRECTION_* and APP_PROBE_* values in the file. */
extern const char *const pj_blend_names[3];
extern const char *const pj_material_pattern_names[2];
extern const char *const pj_correction_names[5];
extern const char *const pj_probe_update_names[6];
app_result pj_read_room(pj_ctx *c, const cJSON *root);
app_result pj_read_objects(pj_ctx *c, const cJSON *root);
app_result pj_read_lights(pj_ctx *c, const cJSON *root);
app_result pj_read_cameras(pj_ctx *c, const cJSON *root);
app_result pj_read_render(pj_ctx *c, const cJSON *root);
app_result pj_read_daylight(pj_ctx *c, const cJSON *root);
app_result pj_read_customer(pj_ctx *c, const cJSON *root); /* project_read_customer.c */
/* Version 2: $.plan (project_read_plan.c, checked by project_plan_check.c), $.tilings
 * (project_read_tilings.c), a product reference {"manufacturer","article","variant"} (the
 * member `key` of obj; project_read_tilings.c). */
app_result pj_read_plan(pj_ctx *c, const cJSON *root);
app_result pj_read_tilings(pj_ctx *c, const cJSON *root);
app_result pj_read_product_ref(pj_ctx *c, const cJSON *obj, const char *key, int required,
                               app_product_ref *out);
/* The plan's geometric rules: a simple counter-clockwise polygon without zero-length walls;
 * openings, pre-walls and niches inside their wall; openings not overlapping; the slope
 * inside the room; pre-wall names unique. The message names the path below $.plan. */
app_result pj_check_plan(pj_ctx *c, const app_room_plan *plan);
/* Sets p->room's width, depth and height from the plan's bounding box and height. */
void pj_room_from_plan(app_project *p);
/* A string member that must be one of names[0..count-1]; *out = its index. */
app_result pj_get_enum(pj_ctx *c, const cJSON *obj, const char *key, int required,
                       const char *const *names, int count, int *out);
extern const char *const pj_opening_type_names[2];
extern const char *const pj_swing_names[5];
extern const char *const pj_pattern_names[6];
extern const char *const pj_align_names[4];

/* A material reference (the member `key` of obj): a name, or an inline material object which
 * is added as `inline_name`. Absent: the material "default" (added if the file has none).
 * Stores the index in *index. (project_read_materials.c) */
app_result pj_material_ref(pj_ctx *c, const cJSON *obj, const char *key, const char *inline_name,
                           int *index);
/* Appends *m to the project's materials and its name to the name index; *index is where.
 * The name must not be in use. Fails past APP_PROJECT_MAX_ITEMS materials in all (inline
 * ones included) or out of memory, with a message at the current path.
 * (project_material_index.c) */
app_result pj_add_material(pj_ctx *c, const app_material *m, int *index);
/* Index of the material with this name, -1 if none. (project_material_index.c) */
int pj_lookup_material(const pj_ctx *c, const char *name);
/* Reads the fields of one material object into *m (name not touched). */
app_result pj_read_material_fields(pj_ctx *c, const cJSON *item, app_material *m);

/* app_project_parse with a choice: check_files 0 takes "model"/"texture" values as written,
 * without resolving them or looking for the files (project_parse.c). */
app_result pj_parse_text(const char *text, size_t len, const char *path, int check_files,
                         app_project *out, char *err, size_t err_size);

/* ---- validation (project_validate_text.c, project_validate.c) ------------------------------ */

/* Byte offset of the first byte of s that breaks UTF-8 (RFC 3629), -1 when s is valid. */
long pj_utf8_invalid_at(const char *s);
/* Every string and member name in the tree is valid UTF-8. */
app_result pj_check_text(pj_ctx *c, const cJSON *root);
/* The rules across sections, after all are read: lights with the windows' daylight within
 * the renderer's, $.render.size within the image writer's (app/project/job_limits.h). */
app_result pj_validate_project(pj_ctx *c, const app_project *p);

/* ---- versions (project_migrate.c) ---------------------------------------------------------- */

/* Checks $.version and upgrades the tree in place to APP_PROJECT_VERSION. */
app_result pj_migrate(pj_ctx *c, cJSON *root, int *file_version);
/* The whole text of a file (the size limit and the messages of app_project_read); *text is
 * malloc'ed. */
app_result pj_read_file(pj_ctx *c, const char *path, char **text, size_t *len);
/* JSON text -> a cJSON tree, or a message with the line and column (project_parse.c). */
app_result pj_parse_json(pj_ctx *c, const char *text, size_t len, cJSON **out);
/* Every section of one room's project from root (an object), into p (zeroed). */
app_result pj_read_root(pj_ctx *c, cJSON *root, app_project *p);

/* ---- files (project_paths.c) ---------------------------------------------------------------- */

/* Resolves a "model"/"texture" value against the folder of c->base and checks that a regular
 * file is there; writes the canonical absolute path. Path already pushed. */
app_result pj_resolve_file(pj_ctx *c, const char *value, char *out, size_t out_size);
/* The folder part of a path ("." when it has none). malloc'ed; NULL when out of memory. */
char *pj_dirname(const char *path);
/* `target` relative to the folder `from_dir` (both absolute, canonical). malloc'ed. */
char *pj_relative_path(const char *from_dir, const char *target);

/* ---- memory (project_alloc.c): malloc/realloc with the test hook ---------------------------- */

void *pj_malloc(size_t size);
void *pj_calloc(size_t count, size_t size);
void *pj_realloc(void *ptr, size_t size);

/* ---- writing (project_to_json.c, project_json_numbers.c, project_write.c) ------------------ */

/* Checks p and builds the JSON tree; paths relative to dest_dir (absolute) when non-NULL. */
app_result pj_project_to_json(pj_ctx *c, const app_project *p, const char *dest_dir, cJSON **out);
/* Adds "plan" and "tilings" to root (project_plan_to_json.c). A project without a plan
 * (corner_count 0, built in memory by version 1 code) is written with its room box as four
 * corners. */
app_result pj_plan_to_json(pj_ctx *c, const app_project *p, cJSON *root);
app_result pj_tilings_to_json(pj_ctx *c, const app_project *p, cJSON *root);
cJSON *pj_product_ref_to_json(const app_product_ref *ref);
/* Numbers printed with the fewest digits that read back to exactly the same value. */
cJSON *pj_json_double(double v);
cJSON *pj_json_float(float v);
/* Writes len bytes to path atomically (temporary file, fsync, rename). */
app_result pj_write_atomic(pj_ctx *c, const char *path, const char *data, size_t len);

#endif
