/* The tile layouts drawn (the renderer draws exactly the layout that is counted): for each
 * tiling, app_project_tile_layouts (the layout the quantities and the print set count, on the
 * regions of room_surfaces.c) becomes meshes added to the room geometry, so the GPU scene and
 * the reference tracer draw the same tiles:
 *  - each tile piece a polygon 2.5 mm in front of its surface, its texture mapped once onto the
 *    whole uncut tile's nominal cell (a cut tile shows the part of the image it keeps). A
 *    textured piece is grown by half a joint across its uncut edges, like the backing, and its
 *    joints are drawn in the grout colour by the shader from the texture coordinates
 *    (rd_material.joint_width, shaders/grout.glsl): antialiased at any distance, and the
 *    image's own border texels are never shown;
 *  - behind the tiles, 1 mm in front of the surface, a backing in the grout colour: every piece
 *    grown by half a joint across its uncut edges (not across cuts), so the joints show
 *    grout and nothing spills past the region's edges or into openings.
 * The catalog is opened only when the project has tilings. A problem (no catalog, a product
 * that is no tile) is a warning on stderr and the surface is drawn untiled. */
#include "room_mesh_internal.h"
#include "scene/scene_build_internal.h"

#include "app/design/placement.h"
#include "app/design/quantities.h"
#include "app/design/room_surfaces.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define TILE_OFFSET_MM 2.5
#define GROUT_OFFSET_MM 1.0

static app_material plain_material(const char *name, const float rgb[3], float specular,
                                   float shininess)
{
    app_material m;
    memset(&m, 0, sizeof m);
    snprintf(m.name, sizeof m.name, "%.63s", name);
    for (int k = 0; k < 3; k++) {
        m.diffuse[k] = m.ambient[k] = rgb[k];
        m.specular[k] = specular;
    }
    m.shininess = shininess;
    m.texture_size_mm[0] = m.texture_size_mm[1] = 1000;
    m.glossiness = 1;
    m.ior = 1.5f;
    return m;
}

static void frame_point(const app_surface_frame *f, double s, double t, double off, double out[3])
{
    app_surface_frame_point(f, s, t, out);
    for (int k = 0; k < 3; k++)
        out[k] += off * f->normal[k];
}

/* A convex counter-clockwise polygon with edges of kind APP_EDGE_TILE moved out by d. */
static void grow_piece(const app_point2 *pt, const unsigned char *edge, int n, double d,
                       app_point2 *out)
{
    for (int i = 0; i < n; i++) {
        int h = (i + n - 1) % n;
        app_point2 p0 = pt[h], p1 = pt[i], p2 = pt[(i + 1) % n];
        double ax = p1.x - p0.x, ay = p1.y - p0.y, bx = p2.x - p1.x, by = p2.y - p1.y;
        double la = hypot(ax, ay), lb = hypot(bx, by);
        if (la == 0 || lb == 0) {
            out[i] = p1;
            continue;
        }
        ax /= la, ay /= la, bx /= lb, by /= lb;
        double da = edge[h] == APP_EDGE_TILE ? d : 0, db = edge[i] == APP_EDGE_TILE ? d : 0;
        /* outward normals of a counter-clockwise polygon: (dy, -dx) */
        double nax = ay * da, nay = -ax * da, nbx = by * db, nby = -bx * db;
        double cr = ax * by - ay * bx;
        if (fabs(cr) < 1e-9) {
            out[i] = (app_point2){p1.x + nbx, p1.y + nby};
            continue;
        }
        double a = ((nbx - nax) * by - (nby - nay) * bx) / cr;
        out[i] = (app_point2){p1.x + nax + a * ax, p1.y + nay + a * ay};
    }
}

/* A fan of the polygon pts in the frame's plane at offset off; uv per point (may be NULL). */
static void emit_polygon(rm_build *b, app_room_mesh *m, const app_surface_frame *f,
                         const app_point2 *pts, int n, double off, const double (*uv)[2])
{
    int first = -1;
    for (int i = 0; i < n; i++) {
        double pos[3], zero[2] = {0, 0};
        frame_point(f, pts[i].x, pts[i].y, off, pos);
        int v = rm_vertex(b, m, pos, f->normal, uv ? uv[i] : zero);
        if (i == 0)
            first = v;
        if (i >= 2)
            rm_triangle(b, m, first, v - 1, v, f->normal);
    }
}

/* Texture coordinates that put the whole image on the uncut tile: u along cell[0] -> cell[1],
 * v up along cell[0] -> cell[3] (negative, the room's convention: image rows run down). */
static void tile_uv(const app_placed_tile *t, app_point2 q, double uv[2])
{
    double ux = t->cell[1].x - t->cell[0].x, uy = t->cell[1].y - t->cell[0].y;
    double vx = t->cell[3].x - t->cell[0].x, vy = t->cell[3].y - t->cell[0].y;
    double px = q.x - t->cell[0].x, py = q.y - t->cell[0].y;
    double uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
    uv[0] = uu > 0 ? (px * ux + py * uy) / uu : 0;
    uv[1] = vv > 0 ? -(px * vx + py * vy) / vv : 0;
}

/* The texture coordinate over the nominal cell (the tile grown by half the joint g on every
 * side) from tile_uv's over the tile at work size ww x wh: the cell's edges are whole numbers. */
static void cell_uv(const double uv[2], double ww, double wh, double g, double out[2])
{
    out[0] = (uv[0] * ww + 0.5 * g) / (ww + g);
    out[1] = (uv[1] * wh - 0.5 * g) / (wh + g); /* v runs negative (tile_uv) */
}

static void add_layout(rm_build *b, const app_tiling *tiling, const app_tile_layout *l,
                       const app_surface_frame *f)
{
    char name[200];
    snprintf(name, sizeof name, "tiles:%.64s:grout", tiling->name);
    app_room_mesh *grout = rm_mesh(b, name, -1);
    if (!grout)
        return;
    grout->inline_material = plain_material(name, tiling->grout_color, 0.05f, 8);
    int grout_index = (int)(grout - b->g->meshes);
    int spec_mesh[1 + APP_TILING_MAX_BORDERS];
    for (int k = 0; k < l->spec_count && k < 1 + APP_TILING_MAX_BORDERS; k++) {
        snprintf(name, sizeof name, "tiles:%.64s:%d", tiling->name, k);
        app_room_mesh *m = rm_mesh(b, name, -1);
        if (!m)
            return;
        const float white[3] = {0.9f, 0.9f, 0.9f}, grey[3] = {0.75f, 0.75f, 0.73f};
        char path[2048] = "";
        if (l->specs[k].texture[0])
            snprintf(path, sizeof path, "%s/%s", app_placement_assets_dir(), l->specs[k].texture);
        int textured =
            path[0] && access(path, R_OK) == 0 && strlen(path) < sizeof m->inline_material.texture;
        /* A glossy glaze's highlight (and its reflection of the room: render's glaze.h), or the
         * catalog's matt surfaces' broad, faint one. */
        int matt = l->specs[k].matt;
        m->inline_material =
            plain_material(name, textured ? white : grey, matt ? 0.1f : 0.25f, matt ? 16 : 64);
        if (textured) {
            memcpy(m->inline_material.texture, path, strlen(path) + 1); /* fits: checked above */
            double g = l->grout_mm, ww = l->specs[k].work_w_mm, wh = l->specs[k].work_h_mm;
            if (g > 0 && ww > 0 && wh > 0) {
                m->inline_material.joint_width[0] = (float)(g / (ww + g));
                m->inline_material.joint_width[1] = (float)(g / (wh + g));
                memcpy(m->inline_material.joint_color, tiling->grout_color,
                       sizeof m->inline_material.joint_color);
            }
        }
        spec_mesh[k] = (int)(m - b->g->meshes);
    }
    double half = 0.5 * l->grout_mm;
    for (int ti = 0; ti < l->tile_count && !b->oom; ti++) {
        const app_placed_tile *t = &l->tiles[ti];
        if (t->product < 0 || t->product >= l->spec_count)
            continue;
        for (int pi = 0; pi < t->piece_count && !b->oom; pi++) {
            const app_tile_piece *pc = &l->pieces[t->first_piece + pi];
            if (pc->count < 3 || pc->count > 64)
                continue;
            const app_point2 *pts = &l->points[pc->first];
            app_point2 grown[64];
            double uv[64][2];
            grow_piece(pts, &l->edges[pc->first], pc->count, half, grown);
            emit_polygon(b, &b->g->meshes[grout_index], f, grown, pc->count, GROUT_OFFSET_MM, NULL);
            app_room_mesh *tm = &b->g->meshes[spec_mesh[t->product]];
            /* Joints drawn by the shader: the piece covers its half of them. */
            int joints = tm->inline_material.joint_width[0] > 0.0f;
            const app_point2 *shape = joints ? grown : pts;
            double ww = hypot(t->cell[1].x - t->cell[0].x, t->cell[1].y - t->cell[0].y);
            double wh = hypot(t->cell[3].x - t->cell[0].x, t->cell[3].y - t->cell[0].y);
            for (int k = 0; k < pc->count; k++) {
                tile_uv(t, shape[k], uv[k]);
                if (joints)
                    cell_uv(uv[k], ww, wh, l->grout_mm, uv[k]);
            }
            emit_polygon(b, tm, f, shape, pc->count, TILE_OFFSET_MM, (const double(*)[2])uv);
        }
    }
}

void app_room_add_tiles(const app_project *p, const app_fixture_box *covers, int cover_count,
                        app_lazy_catalog *catalog, app_room_geometry *g)
{
    if (p->tiling_count <= 0)
        return;
    char err[1024];
    if (!catalog->db && !catalog->failed &&
        app_placement_open_catalog(catalog->db_path, &catalog->db, catalog->err,
                                   sizeof catalog->err) != APP_OK)
        catalog->failed = 1;
    if (catalog->failed || !catalog->db) {
        fprintf(stderr, "tessera: warning: %s: tiles not drawn: %s\n", p->path, catalog->err);
        return;
    }
    cat_db *db = catalog->db;
    app_room_regions regions = {covers, cover_count};
    app_tile_layout *layouts = NULL;
    int count = 0;
    app_tiling *room = NULL;
    app_result r = app_room_setout_tilings(p, db, covers, cover_count, &room, err, sizeof err);
    app_project set_out = *p; /* shallow: the room's set-out as fixed starts */
    if (room)
        set_out.tilings = room;
    if (r == APP_OK)
        r = app_project_tile_layouts(&set_out, db, app_room_region_provider, &regions, &layouts,
                                     &count, err, sizeof err);
    free(room);
    if (r != APP_OK) {
        fprintf(stderr, "tessera: warning: %s: tiles not drawn: %s\n", p->path, err);
        return;
    }
    app_surface_frame *frames = NULL;
    int frame_count = 0;
    if (app_room_surface_list(p, &frames, &frame_count, err, sizeof err) != APP_OK) {
        app_tile_layouts_free(layouts, count);
        return;
    }
    rm_build b = {p, &p->plan, g, 0};
    for (int i = 0; i < count && i < p->tiling_count && !b.oom; i++) {
        const app_surface_frame *f = NULL;
        for (int k = 0; k < frame_count && !f; k++)
            if (!strcmp(frames[k].surface, layouts[i].surface))
                f = &frames[k];
        if (!f)
            continue;
        if (f->kind == APP_SURFACE_CEILING && p->plan.slope.present) {
            fprintf(
                stderr,
                "tessera: warning: %s: tiling \"%s\": tiles on a sloped ceiling are not drawn\n",
                p->path, p->tilings[i].name);
            continue;
        }
        add_layout(&b, &p->tilings[i], &layouts[i], f);
    }
    if (b.oom)
        fprintf(stderr, "tessera: warning: %s: out of memory drawing the tiles\n", p->path);
    free(frames);
    app_tile_layouts_free(layouts, count);
}
