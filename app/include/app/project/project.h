/* Tessera project document: the in-memory model of a project file and its JSON reader/writer.
 *
 * The file format (version 2) is described in docs/project-format.md. Units: millimetres,
 * right-handed, Z up; the room is the floor plan polygon (app/design/room.h) from z = 0 up to its
 * height; app_room's width and depth are the size of its bounding box.
 *
 * Every call that can fail returns an app_result and writes a one-line message into err
 * (when err is non-NULL and err_size > 0) of the form
 *     FILE: $.objects[2].position[1]: expected a finite number, got string
 * Nothing here aborts or exits. The functions keep no global state except the test hooks at
 * the end of this header, which are per thread. */
#ifndef APP_PROJECT_H
#define APP_PROJECT_H

#include "app/daylight/daylight.h"
#include "app/design/room.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define APP_PROJECT_VERSION 2

/* Limits a file must respect; larger inputs are refused with a message, never truncated. */
#define APP_PROJECT_MAX_FILE_BYTES (64L * 1024 * 1024)
#define APP_PROJECT_MAX_ITEMS 100000 /* per list: materials, objects, lights, cameras */
#define APP_PROJECT_MAX_ROOM_MM 1e7  /* 10 km */
#define APP_PROJECT_MAX_IMAGE_SIDE 16384

typedef enum app_result {
    APP_OK = 0,
    APP_ERR_IO,      /* cannot open/read/write the file, or it is too large */
    APP_ERR_PARSE,   /* not well-formed JSON */
    APP_ERR_SCHEMA,  /* well-formed JSON that is not a valid project */
    APP_ERR_VERSION, /* "version" missing, not an integer >= 1, or newer than this build */
    APP_ERR_OUT_OF_MEMORY,
    APP_ERR_NOT_FOUND, /* a referenced file (model, texture) does not exist */
    APP_ERR_CANCELLED, /* the caller stopped it (a superseded background bake) */
} app_result;

/* "APP_OK", "APP_ERR_IO", ... (never NULL). */
const char *app_result_name(app_result r);

typedef struct app_material {
    char name[64];
    float ambient[3], diffuse[3], specular[3], emissive[3]; /* linear RGB, 0..(large) */
    float shininess;                                        /* Blinn-Phong exponent n, 0 .. 1e6 */
    char texture[1024];       /* resolved absolute path of the diffuse texture, "" = none */
    float texture_size_mm[2]; /* real-world size one texture repeat covers (default 1000x1000) */

    /* Reflections (docs/project-format.md "Reflections"; RENDERING.md sections 3-8). */
    float reflectivity;    /* k_r in [0, 1]; 0 = none (default) */
    float glossiness;      /* g in [0, 1]; 1 = mirror (default) */
    int blend;             /* APP_BLEND_* */
    int correction;        /* APP_CORRECTION_* */
    int probe_update;      /* APP_PROBE_* */
    int probe_every;       /* APP_PROBE_EVERY_FRAME: every n-th frame; 0/1 = every frame */
    int probe_resolution;  /* texels per face side; 0 = auto */
    float proxy_radius_mm; /* sphere proxy radius; 0 = 4 x the object's bounding radius */
    char probe_map[1024];  /* APP_PROBE_STATIC: six images, * for the face name */
    int probe_sphere_map;  /* 1: look reflections up in a sphere map (seed 000) */
    int probe_per_vertex;  /* 1: reflection vector per vertex (seed 003) */
    /* Glass (RENDERING.md section 9). */
    float transparency; /* 0 opaque .. 1 clear */
    float ior;          /* index of refraction, default 1.5 */
    float dispersion;   /* IOR spread between red and blue, 0 = none */
    int pattern;        /* APP_PATTERN_*: a procedural albedo pattern ("pattern": "wood") */
    /* The wood grain's direction on the object's front (its x-z plane), degrees from x towards
     * z, 0 .. 180 ("grain": "horizontal" (0, default), "vertical" (90) or the degrees). */
    float grain_deg;
    /* Tile joints drawn from the layout (rd_material.joint_width); set by the room's tile
     * meshes (room_tiles.c), not read from files. */
    float joint_width[2];
    float joint_color[3];
} app_material;

enum { APP_BLEND_MIX = 0, APP_BLEND_ADD, APP_BLEND_FRESNEL };
enum { APP_PATTERN_NONE = 0, APP_PATTERN_WOOD }; /* as rd_pattern */
enum {
    APP_CORRECTION_DEFAULT = 0,
    APP_CORRECTION_NONE,
    APP_CORRECTION_BOX,
    APP_CORRECTION_SPHERE,
    APP_CORRECTION_DEPTH
};
enum {
    APP_PROBE_DEFAULT = 0,
    APP_PROBE_EVERY_FRAME,
    APP_PROBE_ONCE,
    APP_PROBE_ON_CHANGE,
    APP_PROBE_TIME_SLICED,
    APP_PROBE_STATIC
};

typedef enum app_shape {
    APP_SHAPE_BOX,
    APP_SHAPE_SPHERE,
    APP_SHAPE_CYLINDER,
    APP_SHAPE_PLANE,
    APP_SHAPE_TORUS,
    APP_SHAPE_MODEL
} app_shape;

typedef struct app_object {
    char name[64];
    app_shape shape;
    char model[1024];       /* resolved absolute path for APP_SHAPE_MODEL */
    double position_mm[3];  /* centre of the primitive's bounding box (for a model: its origin) */
    double rotation_deg[3]; /* Euler angles about X, then Y, then Z (R = Rz*Ry*Rx) */
    double scale[3];        /* default 1,1,1 */
    double size_mm[3];      /* primitive bounding box: box w,d,h; sphere/cylinder diameter x,y
                               and height z; plane x,y (z unused); torus outer diameter x,y,
                               tube thickness z. All zero for a model. */
    int material;           /* index into app_project.materials */
    char group[64];         /* parts of one fixture share a group name ("" = none): one
                               reflection probe for all of them, none of them in it */
    char parent[64];        /* the name of the object this one is mounted on ("" = none): a
                               basin on its vanity, a tap on its basin. Moving, rotating or
                               removing the parent takes it along (app/project/commands.h) */
    int has_product; /* version 2: 1 = a placed catalog product (app/design/room.h); its model,
                        size and material come from the catalog */
    app_product_ref product;
} app_object;

typedef enum app_light_type {
    APP_LIGHT_POINT,
    APP_LIGHT_SPOT,
    APP_LIGHT_DIRECTIONAL,
    APP_LIGHT_RECT /* an emitting rectangle: mirror light, LED strip, panel, window pane */
} app_light_type;

typedef struct app_light {
    char name[64];
    app_light_type type;
    double position_mm[3];      /* point and spot; 0,0,0 for directional */
    double direction[3];        /* spot and directional: the direction light travels, unit length;
                                   0,0,-1 for point */
    float color[3];             /* linear RGB */
    float intensity;            /* multiplies color for diffuse I_d */
    float specular[3];          /* I_s colour; default = color */
    float attenuation[3];       /* constant, linear (per metre), quadratic (per metre^2); default
                                   1,0,1; att = 1/(c + l d + q d^2) with d in metres */
    float inner_deg, outer_deg; /* spot cone half-angles from the axis: full intensity inside
                                   inner, smooth falloff to 0 at outer; defaults 25, 35 */
    double width_mm, height_mm; /* rect: its size (width along `axis`), each > 0. A directional
                                   light with both > 0 comes in only through that rectangle
                                   around position_mm (a window; set by the room, not read) */
    double axis[3];             /* rect: the direction of its width, unit, square to direction;
                                   default horizontal (direction x Z), or X for a vertical light */
    double height_axis[3];      /* the direction of its height (rect: direction x axis) */
    /* The object whose glowing (emissive) parts show this light: a pendant's shade, a mirror
       light's strip. They glow but light nothing; the light is this record, in the GPU, the
       bake and the tracer alike (docs/project-format.md, "Lights"). Unnamed (emitter_named 0):
       the emissive object nearest the light within APP_LIGHT_EMITTER_REACH_MM of its box;
       named "": none, so a glowing shape there stays an area light of the tracer. */
    char emitter[64];
    int emitter_named;
} app_light;

/* How far a light may sit outside the box of the lamp that shows it to be found by position. */
#define APP_LIGHT_EMITTER_REACH_MM 250.0

typedef struct app_camera {
    char name[64];
    double position_mm[3], target_mm[3];
    double up[3];   /* default 0,0,1 */
    double fov_deg; /* vertical field of view, default 60, in (1,179) */
} app_camera;

typedef struct app_room {
    double width_mm, depth_mm, height_mm;                /* each > 0 and <= 1e7 (10 km) */
    int floor_material, wall_material, ceiling_material; /* indices into materials */
} app_room;

/* $.render.tone: the tone curve (the renderer's rd_tonemap, named here so the document needs
 * no renderer). */
typedef enum app_tone {
    APP_TONE_NEUTRAL = 0,
    APP_TONE_AGX,
    APP_TONE_REINHARD,
    APP_TONE_CLAMP
} app_tone;
/* "neutral", "agx", "reinhard", "clamp"; parse returns 0 for anything else. */
const char *app_tone_name(app_tone t);
int app_tone_parse(const char *name, app_tone *out);

typedef struct app_render_settings {
    float ambient[3];      /* I_a, default 0.1,0.1,0.1 */
    float exposure_ev;     /* "exposure": EV when exposure_auto is 0; default 0 */
    int exposure_auto;     /* "exposure": "auto" (the default): chosen from the scene by its
                              log-average luminance (rd_view.auto_exposure) */
    app_tone tone;         /* "tone": default APP_TONE_NEUTRAL */
    float white;           /* photographic tone map L_white, default 4 */
    float white_balance_k; /* "white_balance": colour temperature shown as white, K; 0 (the
                              default) = none */
    int width, height;     /* default 1280 x 720 */
    int supersample;       /* 1..4, default 1 */
    int ambient_model;     /* 0 "constant" (I_a), 1 "sh9" (irradiance from a probe, section 7) */
} app_render_settings;

/* Whom the quotation is made out to ($.customer) and its number and validity ($.quote);
 * docs/project-format.md "Customer and quote". */
#define APP_CUSTOMER_ADDRESS_LINES 4
typedef struct app_customer {
    int present; /* 1: the file has $.customer or $.quote (written back only then) */
    char name[128];
    char address[APP_CUSTOMER_ADDRESS_LINES][128];
    int address_lines;
    char email[128], phone[64];
    char quote_number[64]; /* "" = made from the date (app/output/quote.h) */
    int valid_days;        /* 0 = the default, 30 */
} app_customer;

typedef struct app_project {
    int version;      /* always APP_PROJECT_VERSION after a read (the model is current) */
    int file_version; /* the "version" found in the file, before migration */
    char name[128];
    char path[1024];    /* the file it was read from, absolute ("" after app_project_parse
                           without a path) */
    app_room room;      /* version 1 box; kept in step with plan's bounding box */
    app_room_plan plan; /* version 2 floor plan (a v1 file migrates to 4 corners) */
    app_tiling *tilings;
    int tiling_count;
    app_material *materials;
    int material_count;
    app_object *objects;
    int object_count;
    app_light *lights;
    int light_count;
    app_camera *cameras;
    int camera_count;
    app_render_settings render;
    app_daylight daylight; /* the sky and sun through the windows */
    app_customer customer; /* the quotation's addressee and number ($.customer, $.quote) */
} app_project;

/* Reads and validates a project file. *out is overwritten (not freed first): on success it
 * owns arrays to release with app_project_free; on failure it is all zero. */
app_result app_project_read(const char *path, app_project *out, char *err, size_t err_size);

/* The same from memory. path_for_messages_and_relative_files names the file in messages and
 * is the file whose folder relative "model"/"texture" paths resolve against; NULL means
 * "<memory>" in messages and the current directory for relative paths. json_text need not
 * be NUL-terminated; len bytes are read. */
app_result app_project_parse(const char *json_text, size_t len,
                             const char *path_for_messages_and_relative_files, app_project *out,
                             char *err, size_t err_size);

/* Writes p as a version APP_PROJECT_VERSION file. Atomic: writes PATH.tmp-XXXXXX in the same
 * folder, fsyncs it, renames it over PATH; on any failure the old file is untouched and the
 * temporary file is removed. Model and texture paths are written relative to PATH's folder.
 * p is checked first: its structure (material indices in range, finite numbers, terminated
 * names), then every rule of the reader on the text about to be written (but not whether the
 * model and texture files still exist), so a file it writes always reads back. */
app_result app_project_write(const char *path, const app_project *p, char *err, size_t err_size);

/* Frees the arrays and zeroes *p. Safe on a zeroed or partially filled project and on NULL. */
void app_project_free(app_project *p);

/* NULL if none; name NULL = first camera. */
const app_camera *app_project_find_camera(const app_project *p, const char *name);
/* Index into p->materials, -1 if none. */
int app_project_find_material(const app_project *p, const char *name);

/* ---- test hooks (per thread; for tests that prove the failure paths) ---------------------- */

/* The next writes fail after `bytes` bytes of the temporary file have been written (0 = the
 * first write fails). Stays armed until called again with -1. */
void app_project_test_fail_write_after(long bytes);
/* The allocations this module makes itself (not cJSON's) fail after `count` successful ones.
 * Stays armed until called again with -1. */
void app_project_test_fail_alloc_after(long count);

#ifdef __cplusplus
}
#endif
#endif
