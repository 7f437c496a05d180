/* The primitives' meshes (no GL): unit bounds, unit normals, outward winding (a positive
 * enclosed volume close to the analytic one for closed shapes), indices in range. */
#include "../common/check.h"
#include "render/primitives.h"

#include <math.h>

/* Signed volume by the divergence theorem: positive when triangles wind outward. */
static double signed_volume(const rd_mesh_data *m)
{
    double v = 0.0;
    for (int t = 0; t < m->index_count; t += 3) {
        const float *a = &m->positions[m->indices[t] * 3],
                    *b = &m->positions[m->indices[t + 1] * 3],
                    *c = &m->positions[m->indices[t + 2] * 3];
        v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0])) /
             6.0;
    }
    return v;
}

/* Every triangle's geometric normal agrees with its vertices' normals. */
static int normals_agree(const rd_mesh_data *m)
{
    for (int t = 0; t < m->index_count; t += 3) {
        const float *a = &m->positions[m->indices[t] * 3],
                    *b = &m->positions[m->indices[t + 1] * 3],
                    *c = &m->positions[m->indices[t + 2] * 3];
        float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        float e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                      e1[0] * e2[1] - e1[1] * e2[0]};
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len < 1e-9f)
            continue; /* degenerate pole triangles of the sphere */
        const float *vn = &m->normals[m->indices[t] * 3];
        if ((n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2]) / len < 0.0f)
            return 0;
    }
    return 1;
}

static void check_mesh(const char *name, rd_mesh_data *m, double expected_volume, double tol)
{
    CHECK_MSG(m->vertex_count > 0 && m->index_count % 3 == 0, "%s", name);
    float lo[3] = {1e9f, 1e9f, 1e9f}, hi[3] = {-1e9f, -1e9f, -1e9f};
    int unit = 1, in_range = 1;
    for (int i = 0; i < m->vertex_count; i++) {
        const float *n = &m->normals[i * 3];
        unit &= fabsf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0f) < 1e-5f;
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], m->positions[i * 3 + k]);
            hi[k] = fmaxf(hi[k], m->positions[i * 3 + k]);
        }
    }
    for (int i = 0; i < m->index_count; i++)
        in_range &= m->indices[i] < (uint32_t)m->vertex_count;
    CHECK_MSG(unit, "%s: normals are unit length", name);
    CHECK_MSG(in_range, "%s: indices in range", name);
    CHECK_MSG(fabsf(lo[0] + 0.5f) < 1e-5f && fabsf(hi[0] - 0.5f) < 1e-5f &&
                  fabsf(lo[1] + 0.5f) < 1e-3f && fabsf(hi[1] - 0.5f) < 1e-3f,
              "%s: x, y bounds %g..%g, %g..%g", name, lo[0], hi[0], lo[1], hi[1]);
    CHECK_MSG(normals_agree(m), "%s: winding agrees with the normals", name);
    if (expected_volume > 0.0) {
        double v = signed_volume(m);
        CHECK_MSG(fabs(v - expected_volume) < tol * expected_volume,
                  "%s: volume %g, expected %g (outward winding gives a positive volume)", name, v,
                  expected_volume);
    }
    rd_mesh_data_free(m);
}

int main(void)
{
    const double pi = 3.14159265358979;
    rd_mesh_data m;
    CHECK(rd_mesh_data_box(&m) == RD_OK);
    check_mesh("box", &m, 1.0, 1e-6);
    CHECK(rd_mesh_data_sphere(64, 32, &m) == RD_OK);
    check_mesh("sphere", &m, pi / 6.0, 0.01);
    CHECK(rd_mesh_data_cylinder(64, &m) == RD_OK);
    check_mesh("cylinder", &m, pi / 4.0, 0.01);
    CHECK(rd_mesh_data_torus(0.2f, 64, 24, &m) == RD_OK);
    /* Tube radius 0.1, ring radius 0.4: V = 2 pi^2 R r^2. */
    check_mesh("torus", &m, 2.0 * pi * pi * 0.4 * 0.01, 0.02);
    CHECK(rd_mesh_data_plane(&m) == RD_OK);
    check_mesh("plane", &m, 0.0, 0.0);

    CHECK(rd_mesh_data_sphere(2, 32, &m) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_mesh_data_torus(0.0f, 8, 8, &m) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_mesh_data_torus(NAN, 8, 8, &m) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_mesh_data_torus(0.6f, 8, 8, &m) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_mesh_data_cylinder(100000, &m) == RD_ERR_INVALID_ARGUMENT);
    rd_mesh_data zero = {0};
    rd_mesh_data_free(&zero);
    rd_mesh_data_free(NULL);
    return check_report("primitives");
}
