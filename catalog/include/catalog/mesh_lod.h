/* catalog/mesh_lod.h: checking a loaded model's meshes, and coarser levels of detail of it.
 *
 * Validation looks at what the glTF rules do not forbid but a renderer or a decimator trips
 * over: triangles of zero area or with a repeated corner (degenerate), edges shared by more
 * than two triangles (non-manifold), open edges (one triangle: sheets and planes are open on
 * purpose, so these are only counted). What no mesh may hold is refused: NaN or infinite
 * numbers, indices past the vertex count, an index count that is not a multiple of 3.
 *
 * Levels of detail: quadric error decimation (Garland and Heckbert 1997) through OpenMesh's
 * Decimater (ModQuadric, with ModNormalFlipping so that no face turns over), one mesh at a time,
 * down to a fraction of its triangles. Collapses are half-edge collapses: every vertex of the
 * result is a vertex of the input, so the bounding box can only shrink, and open edges are
 * locked so that sheets keep their outline. Used for probe captures and far objects
 * (RENDERING.md section 8: probes may draw lower-detail geometry).
 *
 * Every call that can fail returns a cat_result and writes "WHAT: what went wrong" into err.
 */
#ifndef CATALOG_MESH_LOD_H
#define CATALOG_MESH_LOD_H

#include "catalog/model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cat_mesh_report {
    long triangles;            /* triangles looked at */
    long degenerate_triangles; /* a repeated corner or zero area (removed by a repair) */
    long non_manifold_edges;   /* edges of three or more triangles (counted, kept) */
    long open_edges;           /* edges of one triangle (counted, kept) */
    long removed_triangles;    /* by cat_model_validate with repair = 1 */
} cat_mesh_report;

/* Checks one mesh and adds its counts to *report (which the caller zeroes). `what` names the
 * mesh in messages (e.g. "tap.glb: mesh 3"). CAT_ERR_INVALID for NaN/Inf positions, normals
 * or UVs, an index past vertex_count, an index count not a multiple of 3 or a negative
 * count. */
cat_result cat_mesh_validate(const cat_mesh *mesh, const char *what, cat_mesh_report *report,
                             char *err, size_t err_size);

/* Checks every mesh of *m (report zeroed here; may be NULL). repair = 1 also drops degenerate
 * triangles in place (a mesh may end up with no triangles; it stays in the list so that mesh
 * numbers keep matching the file). `what` names the model (its file) in messages. */
cat_result cat_model_validate(cat_model *m, const char *what, int repair, cat_mesh_report *report,
                              char *err, size_t err_size);

/* Smallest triangle count a mesh is decimated to (a part with fewer keeps all of its). */
#define CAT_LOD_MIN_TRIANGLES 8

/* A coarser copy of *in with about fraction x its triangles per mesh (0 < fraction <= 1;
 * 1 = a plain copy), same meshes in the same order, same materials. Vertices are welded by
 * position before decimation; each corner of the result takes the normal and UV of the input
 * vertex at that position whose normal is closest to the face's, so hard edges and UV seams
 * survive. *out is zeroed first and left zeroed on failure; free it with cat_model_free. The
 * input is validated first (cat_mesh_validate) and refused with its message if broken. */
cat_result cat_model_make_lod(const cat_model *in, float fraction, cat_model *out, char *err,
                              size_t err_size);

/* Triangles of all meshes of *m. */
long cat_model_triangle_count(const cat_model *m);

#ifdef __cplusplus
}
#endif

#endif
