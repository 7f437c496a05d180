#include "render/primitives.h"
#include "render_internal.h"

#include <math.h>
#include <stdlib.h>

#define PI_F 3.14159265358979f

static rd_result alloc_mesh(rd_mesh_data *m, int vertices, int indices)
{
    memset(m, 0, sizeof *m);
    m->positions = calloc((size_t)vertices * 3, sizeof(float));
    m->normals = calloc((size_t)vertices * 3, sizeof(float));
    m->uvs = calloc((size_t)vertices * 2, sizeof(float));
    m->indices = calloc((size_t)indices, sizeof(uint32_t));
    if (!m->positions || !m->normals || !m->uvs || !m->indices) {
        rd_mesh_data_free(m);
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory for a primitive mesh");
    }
    return RD_OK;
}

static void put_vertex(rd_mesh_data *m, float px, float py, float pz, float nx, float ny, float nz,
                       float u, float v)
{
    int i = m->vertex_count++;
    float *p = &m->positions[i * 3], *n = &m->normals[i * 3];
    p[0] = px, p[1] = py, p[2] = pz;
    n[0] = nx, n[1] = ny, n[2] = nz;
    m->uvs[i * 2] = u;
    m->uvs[i * 2 + 1] = v;
}

static void put_triangle(rd_mesh_data *m, int a, int b, int c)
{
    m->indices[m->index_count++] = (uint32_t)a;
    m->indices[m->index_count++] = (uint32_t)b;
    m->indices[m->index_count++] = (uint32_t)c;
}

/* A grid of (cols+1) x (rows+1) vertices already put from index base, two triangles a cell. */
static void put_grid(rd_mesh_data *m, int base, int cols, int rows)
{
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < cols; c++) {
            int a = base + r * (cols + 1) + c, b = a + 1, d = a + cols + 1, e = d + 1;
            put_triangle(m, a, b, e);
            put_triangle(m, a, e, d);
        }
}

rd_result rd_mesh_data_box(rd_mesh_data *m)
{
    if (alloc_mesh(m, 24, 36) != RD_OK)
        return RD_ERR_OUT_OF_MEMORY;
    /* Each face: normal axis, sign; u and v axes chosen so that u x v = normal. */
    static const int faces[6][3] = {{0, 1, 2},  {0, -1, 2}, {1, 1, 2},
                                    {1, -1, 2}, {2, 1, 0},  {2, -1, 0}};
    for (int f = 0; f < 6; f++) {
        int axis = faces[f][0], sign = faces[f][1];
        int ua = (axis + 1) % 3, va = (axis + 2) % 3;
        int base = m->vertex_count;
        for (int j = 0; j < 2; j++)
            for (int i = 0; i < 2; i++) {
                float p[3], n[3] = {0, 0, 0};
                p[axis] = 0.5f * (float)sign;
                p[ua] = (float)i - 0.5f;
                p[va] = (float)j - 0.5f;
                n[axis] = (float)sign;
                put_vertex(m, p[0], p[1], p[2], n[0], n[1], n[2], (float)i, (float)j);
            }
        /* ua x va = +axis for the cyclic order; flip the winding on the negative side. */
        if (sign > 0) {
            put_triangle(m, base, base + 1, base + 3);
            put_triangle(m, base, base + 3, base + 2);
        } else {
            put_triangle(m, base, base + 3, base + 1);
            put_triangle(m, base, base + 2, base + 3);
        }
    }
    return RD_OK;
}

rd_result rd_mesh_data_plane(rd_mesh_data *m)
{
    if (alloc_mesh(m, 4, 6) != RD_OK)
        return RD_ERR_OUT_OF_MEMORY;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++)
            put_vertex(m, (float)i - 0.5f, (float)j - 0.5f, 0, 0, 0, 1, (float)i, (float)j);
    put_grid(m, 0, 1, 1);
    return RD_OK;
}

rd_result rd_mesh_data_sphere(int segments, int rings, rd_mesh_data *m)
{
    if (segments < 3 || rings < 2 || segments > 4096 || rings > 4096)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "sphere needs 3..4096 segments and 2..4096 rings");
    if (alloc_mesh(m, (segments + 1) * (rings + 1), segments * rings * 6) != RD_OK)
        return RD_ERR_OUT_OF_MEMORY;
    for (int r = 0; r <= rings; r++) {
        float theta = PI_F * (float)r / (float)rings; /* from the south pole up */
        float z = -cosf(theta), rho = sinf(theta);
        for (int s = 0; s <= segments; s++) {
            float phi = 2.0f * PI_F * (float)s / (float)segments;
            float x = rho * cosf(phi), y = rho * sinf(phi);
            put_vertex(m, 0.5f * x, 0.5f * y, 0.5f * z, x, y, z, (float)s / (float)segments,
                       (float)r / (float)rings);
        }
    }
    put_grid(m, 0, segments, rings);
    return RD_OK;
}

rd_result rd_mesh_data_cylinder(int segments, rd_mesh_data *m)
{
    if (segments < 3 || segments > 4096)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "cylinder needs 3..4096 segments");
    int side = (segments + 1) * 2, cap = segments + 2;
    if (alloc_mesh(m, side + 2 * cap, segments * 6 + 2 * segments * 3) != RD_OK)
        return RD_ERR_OUT_OF_MEMORY;
    for (int j = 0; j < 2; j++)
        for (int s = 0; s <= segments; s++) {
            float phi = 2.0f * PI_F * (float)s / (float)segments;
            float x = cosf(phi), y = sinf(phi);
            put_vertex(m, 0.5f * x, 0.5f * y, (float)j - 0.5f, x, y, 0, (float)s / (float)segments,
                       (float)j);
        }
    put_grid(m, 0, segments, 1);
    for (int top = 0; top < 2; top++) {
        float z = top ? 0.5f : -0.5f, nz = top ? 1.0f : -1.0f;
        int centre = m->vertex_count;
        put_vertex(m, 0, 0, z, 0, 0, nz, 0.5f, 0.5f);
        for (int s = 0; s <= segments; s++) {
            float phi = 2.0f * PI_F * (float)s / (float)segments;
            float x = cosf(phi), y = sinf(phi);
            put_vertex(m, 0.5f * x, 0.5f * y, z, 0, 0, nz, 0.5f + 0.5f * x, 0.5f + 0.5f * y);
        }
        for (int s = 0; s < segments; s++) {
            if (top)
                put_triangle(m, centre, centre + 1 + s, centre + 2 + s);
            else
                put_triangle(m, centre, centre + 2 + s, centre + 1 + s);
        }
    }
    return RD_OK;
}

rd_result rd_mesh_data_torus(float minor_ratio, int segments, int sides, rd_mesh_data *m)
{
    if (!(minor_ratio > 0.0f && minor_ratio <= 0.5f))
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "torus tube ratio %g must be in (0, 0.5]",
                       (double)minor_ratio);
    if (segments < 3 || sides < 3 || segments > 4096 || sides > 4096)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "torus needs 3..4096 segments and sides");
    if (alloc_mesh(m, (segments + 1) * (sides + 1), segments * sides * 6) != RD_OK)
        return RD_ERR_OUT_OF_MEMORY;
    float tube = 0.5f * minor_ratio, ring = 0.5f - tube;
    for (int j = 0; j <= sides; j++) {
        float psi = 2.0f * PI_F * (float)j / (float)sides;
        for (int i = 0; i <= segments; i++) {
            float phi = 2.0f * PI_F * (float)i / (float)segments;
            float nx = cosf(psi) * cosf(phi), ny = cosf(psi) * sinf(phi), nz = sinf(psi);
            float cx = ring * cosf(phi), cy = ring * sinf(phi);
            put_vertex(m, cx + tube * nx, cy + tube * ny, tube * nz, nx, ny, nz,
                       (float)i / (float)segments, (float)j / (float)sides);
        }
    }
    put_grid(m, 0, segments, sides);
    return RD_OK;
}

void rd_mesh_data_free(rd_mesh_data *m)
{
    if (!m)
        return;
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->indices);
    memset(m, 0, sizeof *m);
}

rd_mesh_desc rd_mesh_data_desc(const rd_mesh_data *m)
{
    return (rd_mesh_desc){.positions = m->positions,
                          .normals = m->normals,
                          .uvs = m->uvs,
                          .indices = m->indices,
                          .vertex_count = m->vertex_count,
                          .index_count = m->index_count};
}
