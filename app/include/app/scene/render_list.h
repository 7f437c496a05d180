/* A project as a list of things to draw, built once for both renderers (ARCHITECTURE.md: app
 * joins the document and the renderers). Two small adapters turn it into a renderer's scene:
 * app_scene_build (scene_build.h) uploads it to the GPU, app_ref_scene_build (ref_scene_build.h)
 * hands it to the reference tracer, so both see the same triangles, transforms, materials and
 * lights (RENDERING.md section 10).
 *
 * The list is plain data in the renderers' units (metres, linear colours): it holds no GPU or
 * Embree handle. Textures and static probe maps are named by file, each file once; the
 * adapters load them. rd_material, rd_light, rd_shape and rd_probe_desc are the value types
 * both renderers read; their handle fields (diffuse_texture, static_map) stay zero here.
 * Millimetres become metres here and nowhere else. */
#ifndef APP_RENDER_LIST_H
#define APP_RENDER_LIST_H

#include "app/project/project.h"
#include "render/render.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A triangle mesh in its own space; the list owns the arrays. */
typedef struct app_render_mesh {
    const float *positions, *normals, *uvs; /* 3, 3, 2 per vertex; uvs may be NULL */
    const uint32_t *indices;
    int vertex_count, index_count;
} app_render_mesh;

/* One placed mesh: a room surface, a primitive object, or one part of a model. */
typedef struct app_render_item {
    int mesh;             /* index into app_render_list.meshes */
    int probe_mesh;       /* the coarser mesh probe captures draw (RENDERING.md section 8),
                             -1 = the mesh itself */
    float transform[16];  /* column-major, metres */
    rd_material material; /* diffuse_texture is unset: see texture */
    int texture;          /* index into app_render_list.textures, -1 = none */
    rd_shape shape;       /* the unit shape the mesh approximates (MESH when none) */
    int double_sided;     /* an open sheet or a model: both sides drawn */
    int background;       /* a room surface: drawn after the rest, casts no shadow */
    int light_stand_in;   /* emits through lights of the list (a window's exterior panel, a
                             lamp's glowing shade: render_list_glow.c) */
    int group;            /* parts of one fixture share a group > 0: one probe for them */
    rd_probe_desc probe;  /* static_map is unset: see probe_map */
    int probe_map;        /* index into app_render_list.probe_maps, -1 = none */
    int object;           /* the project object drawn, -1 = the room */
    char label[192];      /* names it in messages: "room surface floor", "$.objects[3] (...)" */
} app_render_item;

/* A file an item needs, and the material that named it (for messages). */
typedef struct app_render_file {
    char path[1024];
    char material[64];
} app_render_file;

typedef struct app_render_light {
    rd_light light;
    char label[96]; /* "$.lights[2]", "window light \"window:0\"" */
} app_render_light;

typedef struct app_render_list_store app_render_list_store;

typedef struct app_render_list {
    char path[1024]; /* the project file, for messages */
    app_render_mesh *meshes;
    int mesh_count;
    app_render_item *items; /* the room's surfaces first, then the objects in project order */
    int item_count;
    app_render_file *textures; /* image files, each once */
    int texture_count;
    app_render_file *probe_maps; /* six-file patterns of static probe maps, each once */
    int probe_map_count;
    app_render_light *lights; /* the project's lights, then daylight through the windows */
    int light_count;
    float ambient[3];                /* I_a */
    rd_ambient_model ambient_model;  /* RENDERING.md section 7 */
    double room_min[3], room_max[3]; /* the room's interior (the box proxy), metres */
    double (*object_offsets_mm)[3];  /* per project object: drawn minus document
                                        position (a catalog box stands on its origin) */
    int object_count;
    app_render_list_store *store; /* owns the mesh data */
} app_render_list;

/* Probe-capture meshes (coarse primitives, decimated models) are made only when asked for:
 * the reference tracer has no probes. */
enum { APP_RENDER_LIST_PROBE_MESHES = 1 };

/* Builds the list of p: catalog products resolved (a warning for one the catalog does not
 * know), the room with its tiles, the objects, the lights. On failure *out is zeroed and err
 * names the file and the object. */
app_result app_render_list_build(const app_project *p, int flags, app_render_list *out, char *err,
                                 size_t err_size);
void app_render_list_free(app_render_list *l);

#ifdef __cplusplus
}
#endif
#endif
