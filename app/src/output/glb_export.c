/* tessera export-glb: a whole project as one GLB file (app/output/project_glb.h). Assembles the
 * scene (the room's surfaces and tiles as the renderers see them, then every object) into a
 * cat_scene and hands it to the catalog's writer (catalog/scene_write.h). */
#include "glb_export_internal.h"

#include "app/design/room_mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

cat_scene_node *pg_add_node(pg_build *b, const char *name, int parent)
{
    if (b->node_count == b->node_cap) {
        int cap = b->node_cap ? 2 * b->node_cap : 32;
        cat_scene_node *n = realloc(b->nodes, (size_t)cap * sizeof *n);
        if (!n) {
            snprintf(b->err, b->err_size, "%s: out of memory exporting nodes", b->p->path);
            return NULL;
        }
        b->nodes = n;
        b->node_cap = cap;
    }
    cat_scene_node *n = &b->nodes[b->node_count++];
    memset(n, 0, sizeof *n);
    snprintf(n->name, sizeof n->name, "%s", name);
    n->parent = parent;
    cat_scene_identity(n->matrix);
    return n;
}

cat_model *pg_keep_model(pg_build *b, cat_model *m)
{
    if (b->owned_count == b->owned_cap) {
        int cap = b->owned_cap ? 2 * b->owned_cap : 16;
        cat_model *o = realloc(b->owned, (size_t)cap * sizeof *o);
        if (!o) {
            cat_model_free(m);
            snprintf(b->err, b->err_size, "%s: out of memory exporting meshes", b->p->path);
            return NULL;
        }
        b->owned = o;
        b->owned_cap = cap;
    }
    cat_model *kept = &b->owned[b->owned_count++];
    *kept = *m;
    memset(m, 0, sizeof *m);
    return kept;
}

/* The room's meshes (metres) as parts in mm, one node each under `parent` (no texture
 * coordinates: textures are not exported). */
static app_result add_room(pg_build *b, const app_room_geometry *g, int parent)
{
    for (int i = 0; i < g->mesh_count; i++) {
        const app_room_mesh *rm = &g->meshes[i];
        if (rm->vertex_count <= 0 || rm->index_count < 3)
            continue;
        int mat = rm->material >= 0 ? pg_project_material(b, rm->material)
                                    : pg_add_app_material(b, &rm->inline_material);
        cat_model m = {0};
        cat_mesh *c = calloc(1, sizeof *c);
        size_t nv = (size_t)rm->vertex_count, ni = (size_t)rm->index_count;
        m.meshes = c;
        m.mesh_count = c ? 1 : 0;
        if (c) {
            c->positions = malloc(nv * 3 * sizeof(float));
            c->normals = rm->normals ? malloc(nv * 3 * sizeof(float)) : NULL;
            c->indices = malloc(ni * sizeof(unsigned));
        }
        if (mat < 0 || !c || !c->positions || !c->indices || (rm->normals && !c->normals)) {
            cat_model_free(&m);
            snprintf(b->err, b->err_size, "%s: out of memory exporting the room", b->p->path);
            return APP_ERR_OUT_OF_MEMORY;
        }
        for (size_t k = 0; k < nv * 3; k++)
            c->positions[k] = (float)(rm->positions[k] * 1000.0);
        if (rm->normals)
            memcpy(c->normals, rm->normals, nv * 3 * sizeof(float));
        for (size_t k = 0; k < ni; k++)
            c->indices[k] = rm->indices[k];
        c->vertex_count = rm->vertex_count;
        c->index_count = rm->index_count;
        c->material = mat;
        cat_model *kept = pg_keep_model(b, &m);
        cat_scene_node *n = kept ? pg_add_node(b, rm->surface, parent) : NULL;
        if (!n)
            return APP_ERR_OUT_OF_MEMORY;
        n->parts = kept->meshes;
        n->part_count = 1;
        b->stats->part_count++;
        b->stats->vertex_count += c->vertex_count;
        b->stats->triangle_count += c->index_count / 3;
        for (size_t v = 0; v < nv; v++)
            for (int k = 0; k < 3; k++) {
                double w = c->positions[3 * v + (size_t)k]; /* the room's nodes: identity */
                b->stats->bounds_min_mm[k] = fmin(b->stats->bounds_min_mm[k], w);
                b->stats->bounds_max_mm[k] = fmax(b->stats->bounds_max_mm[k], w);
            }
    }
    return APP_OK;
}

/* A project camera as a glTF one; the aspect of the project's render size. */
static cat_scene_camera camera_of(const app_project *p, const app_camera *c,
                                  const app_glb_stats *st)
{
    cat_scene_camera k;
    memset(&k, 0, sizeof k);
    snprintf(k.name, sizeof k.name, "%s", c->name);
    memcpy(k.eye_mm, c->position_mm, sizeof k.eye_mm);
    memcpy(k.target_mm, c->target_mm, sizeof k.target_mm);
    memcpy(k.up, c->up, sizeof k.up);
    k.yfov_deg = c->fov_deg;
    /* far plane: past the farthest corner of everything written, with a margin */
    double far2 = 0;
    for (int corner = 0; corner < 8; corner++) {
        double d2 = 0;
        for (int a = 0; a < 3; a++) {
            double v = (corner >> a & 1) ? st->bounds_max_mm[a] : st->bounds_min_mm[a];
            d2 += (v - c->position_mm[a]) * (v - c->position_mm[a]);
        }
        far2 = fmax(far2, d2);
    }
    k.zfar_mm = isfinite(far2) ? 1.5 * sqrt(far2) + 1000.0 : 0.0;
    if (p->render.width > 0 && p->render.height > 0)
        k.aspect = (double)p->render.width / p->render.height;
    return k;
}

/* The project's name for the root node: its "name", else its file name. */
static void root_name(const app_project *p, char *out, size_t size)
{
    const char *slash = strrchr(p->path, '/');
    snprintf(out, size, "%.100s",
             p->name[0]   ? p->name
             : slash      ? slash + 1
             : p->path[0] ? p->path
                          : "project");
}

static app_result build_scene(pg_build *b, app_scene_products *res)
{
    char name[128];
    root_name(b->p, name, sizeof name);
    if (!pg_add_node(b, name, -1) || !pg_add_node(b, "room", 0))
        return APP_ERR_OUT_OF_MEMORY;
    app_room_geometry g;
    app_result r = app_room_geometry_build(b->p, &g, b->err, b->err_size);
    if (r != APP_OK)
        return r;
    app_room_add_tiles(b->p, res->covers, res->cover_count, &res->catalog, &g);
    r = add_room(b, &g, 1);
    app_room_geometry_free(&g);
    for (int i = 0; r == APP_OK && i < b->q->object_count; i++)
        r = pg_add_object(b, i, 0);
    return r;
}

app_result app_project_export_glb(const app_project *p, const char *out_path, app_glb_stats *stats,
                                  char *err, size_t err_size)
{
    app_glb_stats local;
    if (!stats)
        stats = &local;
    memset(stats, 0, sizeof *stats);
    for (int k = 0; k < 3; k++) {
        stats->bounds_min_mm[k] = HUGE_VAL;
        stats->bounds_max_mm[k] = -HUGE_VAL;
    }
    if (!out_path || !*out_path) {
        snprintf(err, err_size, "%s: no output file given", p->path);
        return APP_ERR_IO;
    }
    app_scene_products res;
    app_result r = app_scene_resolve_products(p, &res, err, err_size);
    if (r != APP_OK)
        return r;
    pg_build b = {.p = p,
                  .q = &res.q,
                  .catalog = &res.catalog,
                  .stats = stats,
                  .err = err,
                  .err_size = err_size};
    b.project_material = malloc((size_t)(res.q.material_count + 1) * sizeof *b.project_material);
    if (!b.project_material) {
        snprintf(err, err_size, "%s: out of memory", p->path);
        r = APP_ERR_OUT_OF_MEMORY;
    } else {
        for (int i = 0; i < res.q.material_count; i++)
            b.project_material[i] = -1;
        r = build_scene(&b, &res);
    }
    if (r == APP_OK) {
        cat_scene_camera *cams = calloc((size_t)p->camera_count + 1, sizeof *cams);
        int cam_count = 0;
        for (int i = 0; cams && i < p->camera_count; i++) {
            const app_camera *c = &p->cameras[i];
            if (c->position_mm[0] == c->target_mm[0] && c->position_mm[1] == c->target_mm[1] &&
                c->position_mm[2] == c->target_mm[2])
                fprintf(stderr,
                        "tessera: warning: %s: camera \"%s\" looks at its own position; "
                        "left out\n",
                        p->path, c->name);
            else
                cams[cam_count++] = camera_of(p, c, stats);
        }
        cat_scene s = {b.nodes,          b.node_count, b.materials, b.extras,
                       b.material_count, cams,         cam_count};
        char cerr[2048];
        cat_result cr = cat_scene_write_glb(out_path, &s, cerr, sizeof cerr);
        if (cr != CAT_OK) {
            snprintf(err, err_size, "%s", cerr);
            r = cr == CAT_ERR_OUT_OF_MEMORY ? APP_ERR_OUT_OF_MEMORY : APP_ERR_IO;
        }
        free(cams);
        stats->node_count = b.node_count + s.camera_count;
        stats->camera_count = s.camera_count;
        stats->material_count = b.material_count;
        for (int i = 0; i < b.node_count; i++)
            stats->mesh_count += b.nodes[i].part_count > 0;
    }
    for (int i = 0; i < b.owned_count; i++)
        cat_model_free(&b.owned[i]);
    free(b.owned);
    free(b.nodes);
    free(b.materials);
    free(b.extras);
    free(b.model_material);
    free(b.project_material);
    app_scene_resolved_free(&res);
    return r;
}
