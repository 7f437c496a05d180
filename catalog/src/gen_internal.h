/* Internals of the procedural model generators (gen_*.c): a builder that grows one mesh per
 * part, coordinate frames, and the three primitives every product is made of. Lengths in mm,
 * Z up; product generators build near their final size and gen_finish() scales the result to
 * the catalog row's exact bounding box and computes normals. */
#ifndef CATALOG_GEN_INTERNAL_H
#define CATALOG_GEN_INTERNAL_H

#include "catalog/model_gen.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GEN_PI 3.14159265358979323846

typedef struct gen_builder {
    cat_gen_model *gm;
    int *vcap, *icap; /* capacity of each part's arrays */
    int part_cap;
    int failed;      /* an allocation failed: every later call does nothing */
    char error[256]; /* a failure other than memory (subdivision refused a cage), or "" */
} gen_builder;

/* Fixed materials of parts that do not take the variant (values as make_catalog_csv.c). */
typedef enum gen_mat {
    GEN_MAT_FINISH = 0, /* the product's variant (req->finish or the category's default) */
    GEN_MAT_CHROME,
    GEN_MAT_CERAMIC,
    GEN_MAT_GLASS,
    GEN_MAT_MIRROR,
    GEN_MAT_LIGHT, /* an emissive diffuser */
    GEN_MAT_BLACK, /* rubber, plastic */
    GEN_MAT_STEEL, /* brushed metal */
    GEN_MAT_WOOD
} gen_mat;

typedef struct gen_ctx {
    gen_builder *b;
    const cat_gen_request *req;
    cat_render_material finish;
    int square; /* a square series (Quadro, Kubik, Piano, ...) */
} gen_ctx;

/* Adds a part (a mesh with its own material) and returns its index, or -1 after a failure. */
int gen_part(gen_ctx *c, const char *name, gen_mat mat);
unsigned gen_vertex(gen_builder *b, int part, double x, double y, double z);
void gen_triangle(gen_builder *b, int part, unsigned i0, unsigned i1, unsigned i2);

/* A frame: a point p = o + x u + y v + z w. */
typedef struct gen_frame {
    double o[3], u[3], v[3], w[3];
} gen_frame;

gen_frame gen_frame_at(double x, double y, double z);                      /* world axes */
gen_frame gen_frame_axis(double x, double y, double z, const double w[3]); /* w = unit(w) */

/* A ring of a loft: a rounded rectangle of half sizes hx, hy centred at (cx, cy) in the frame's
 * u, v plane at height z along w; r[k] is the corner radius of corner k (0: +u+v, 1: -u+v,
 * 2: -u-v, 3: +u-v), clamped to min(hx, hy). hx = hy = 0 is a pole (one point). */
typedef struct gen_ring {
    double hx, hy, z, r[4], cx, cy;
} gen_ring;

gen_ring gen_ring_round(double hx, double hy, double z, double r); /* equal corners */

/* A loft through rings (in order; the surface faces right of the profile's direction: a
 * profile going up the outside faces out). corner_segs: segments per quarter arc (>= 1).
 * subdivide > 0 smooths it with that many Catmull-Clark steps (OpenMesh) before it is added. */
void gen_loft(gen_ctx *c, int part, const gen_frame *f, const gen_ring *rings, int n,
              int corner_segs, int subdivide);

/* A tube of radius r along a polyline path (n points, 3 each); caps close its ends. */
void gen_tube(gen_ctx *c, int part, const double *path, int n, double r, int segs, int closed);

/* A profile (np points (x, y), counter-clockwise) swept along a path; the profile's x follows
 * the `side` direction (projected off the path's tangent), y = tangent x side. */
void gen_sweep(gen_ctx *c, int part, const double *path, int n, const double *profile, int np,
               const double side[3], int cap);

/* An axis-aligned box with flat faces. */
void gen_box(gen_ctx *c, int part, double x0, double y0, double z0, double x1, double y1,
             double z1);
/* A box with bevelled (rounded-looking) edges of size e, axis-aligned. */
void gen_rbox(gen_ctx *c, int part, double x0, double y0, double z0, double x1, double y1,
              double z1, double e);
/* A cylinder along axis w from point p, radius r, length len, capped (lathe of 2 rings). */
void gen_cylinder(gen_ctx *c, int part, double x, double y, double z, const double w[3], double r,
                  double len, int segs);
/* A sphere / ellipsoid of radii rx, ry, rz centred at (x, y, z). */
void gen_ellipsoid(gen_ctx *c, int part, double x, double y, double z, double rx, double ry,
                   double rz);

/* Polygon-mesh subdivision (mesh_subdivide.cpp): faces of 3 or more vertices (fstart has nf + 1
 * offsets into fidx), iterations Catmull-Clark steps; out: triangles. Returns 0 on failure
 * (message in err). Outputs are malloc'ed. */
int cat_mesh_subdivide(const double *pos, int nv, const int *fstart, const int *fidx, int nf,
                       int iterations, double **out_pos, int *out_nv, int **out_tri, int *out_nt,
                       char *err, size_t err_size);

/* Product generators (gen_fixtures.c, gen_ceramics.c, gen_glass.c, gen_furniture.c). */
void gen_tap(gen_ctx *c);
void gen_shower(gen_ctx *c);
void gen_basin(gen_ctx *c);
void gen_wc(gen_ctx *c);
void gen_bath(gen_ctx *c);
void gen_tray(gen_ctx *c);
void gen_screen(gen_ctx *c);
void gen_mirror(gen_ctx *c);
void gen_cabinet(gen_ctx *c);
void gen_lamp(gen_ctx *c);
void gen_radiator(gen_ctx *c);
void gen_vanity(gen_ctx *c);
void gen_accessory(gen_ctx *c);

/* 1 when the product's name contains word (ASCII case-insensitive). */
int gen_has(const gen_ctx *c, const char *word);
/* The number of doors or drawers the name gives ("2 doors", "3 drawers"), else 1. */
int gen_count(const gen_ctx *c);

#ifdef __cplusplus
}
#endif

#endif
