/* The tracer's scene: meshes baked into world space (as the vertex shader places them),
 * textures with their mip chains, lights, and the Embree scene built over the triangles. */
#include "ref_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

ref_scene *ref_scene_create(void)
{
    ref_scene *s = calloc(1, sizeof *s);
    if (!s) {
        ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_scene_create: out of memory");
        return NULL;
    }
    for (int k = 0; k < 3; k++) {
        s->bounds_min[k] = INFINITY;
        s->bounds_max[k] = -INFINITY;
    }
    s->epsilon = 1e-6f;
    return s;
}

static void mesh_free(ref_mesh *m)
{
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->object_positions);
    free(m->indices);
    free(m->tri_normals);
    memset(m, 0, sizeof *m);
}

void ref_scene_destroy(ref_scene *s)
{
    if (!s)
        return;
    if (s->rtc)
        rtcReleaseScene(s->rtc);
    if (s->device)
        rtcReleaseDevice(s->device);
    for (int i = 0; i < s->mesh_count; i++)
        mesh_free(&s->meshes[i]);
    for (int i = 0; i < s->texture_count; i++)
        ref_texture_free(&s->textures[i]);
    ref_emitters_free(&s->emitters);
    free(s->meshes);
    free(s->textures);
    free(s);
}

int ref_scene_add_texture(ref_scene *s, const ref_texture_desc *d)
{
    if (!s) {
        ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_add_texture: no scene");
        return 0;
    }
    if (s->texture_count == s->texture_capacity) {
        int cap = s->texture_capacity ? 2 * s->texture_capacity : 8;
        ref_texture *t = realloc(s->textures, (size_t)cap * sizeof *t);
        if (!t) {
            ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_scene_add_texture: out of memory");
            return 0;
        }
        s->textures = t;
        s->texture_capacity = cap;
    }
    if (ref_texture_build(d, &s->textures[s->texture_count]) != REF_OK)
        return 0;
    return ++s->texture_count;
}

static int is_zero_matrix(const float m[16])
{
    for (int i = 0; i < 16; i++)
        if (m[i] != 0.0f)
            return 0;
    return 1;
}

/* The normal matrix: the inverse transpose of the upper 3x3 (as draw.c gives the shader), or
 * the cofactor matrix when the transform is singular (a zero-size object: no area to hit). */
static void normal_matrix(const double m[16], double out[3][3], double *det)
{
    /* a[r][c] = m[c * 4 + r] (column-major) */
    double a[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            a[r][c] = m[c * 4 + r];
    double cof[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[r][c] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
        }
    *det = a[0][0] * cof[0][0] + a[0][1] * cof[0][1] + a[0][2] * cof[0][2];
    /* inverse transpose = cofactor / det */
    double k = *det != 0.0 ? 1.0 / *det : 1.0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            out[r][c] = cof[r][c] * k;
}

static ref_result validate_mesh(const ref_mesh_desc *d)
{
    if (!d->positions || !d->normals || (!d->indices && d->index_count > 0))
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_add_mesh: positions, normals and "
                                                  "indices are required");
    if (d->vertex_count <= 0 || d->index_count < 0 || d->index_count % 3 != 0)
        return ref_fail(REF_ERR_INVALID_ARGUMENT,
                        "ref_scene_add_mesh: %d vertices and %d indices (need >= 1 vertex and a "
                        "multiple of 3 indices)",
                        d->vertex_count, d->index_count);
    if (d->vertex_count > (1 << 26) || d->index_count > 3 * (1 << 26))
        return ref_fail(REF_ERR_TOO_LARGE, "ref_scene_add_mesh: %d vertices, %d indices: too large",
                        d->vertex_count, d->index_count);
    for (int i = 0; i < d->index_count; i++)
        if (d->indices[i] >= (uint32_t)d->vertex_count)
            return ref_fail(REF_ERR_INVALID_ARGUMENT,
                            "ref_scene_add_mesh: index %d is %u, past the %d vertices", i,
                            d->indices[i], d->vertex_count);
    for (int i = 0; i < 16; i++)
        if (!isfinite(d->transform[i]))
            return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_add_mesh: transform not finite");
    for (int i = 0; i < 3 * d->vertex_count; i++)
        if (!isfinite(d->positions[i]))
            return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_add_mesh: vertex %d is not finite",
                            i / 3);
    return REF_OK;
}

static ref_result bake_mesh(ref_scene *s, const ref_mesh_desc *d, ref_mesh *m)
{
    size_t nv = (size_t)d->vertex_count, nt = (size_t)d->index_count / 3;
    /* Embree reads the last vertex with a 16-byte load: one float of padding. */
    m->positions = malloc((3 * nv + 1) * sizeof *m->positions);
    m->normals = malloc(3 * nv * sizeof *m->normals);
    m->uvs = calloc(2 * nv, sizeof *m->uvs);
    m->indices = malloc((3 * nt + 1) * sizeof *m->indices);
    m->tri_normals = malloc((3 * nt + 1) * sizeof *m->tri_normals);
    if (!m->positions || !m->normals || !m->uvs || !m->indices || !m->tri_normals)
        return ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_scene_add_mesh: out of memory");
    if (d->material.pattern != RD_PATTERN_NONE) { /* the grain is fixed to the object */
        m->object_positions = malloc(3 * nv * sizeof *m->object_positions);
        if (!m->object_positions)
            return ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_scene_add_mesh: out of memory");
    }
    double t[16];
    int identity = is_zero_matrix(d->transform);
    for (int i = 0; i < 16; i++)
        t[i] = identity ? (i % 5 == 0 ? 1.0 : 0.0) : (double)d->transform[i];
    double nm[3][3], det;
    normal_matrix(t, nm, &det);
    for (size_t v = 0; v < nv; v++) {
        const float *p = d->positions + 3 * v, *n = d->normals + 3 * v;
        for (int r = 0; r < 3; r++) {
            double w = t[r] * p[0] + t[4 + r] * p[1] + t[8 + r] * p[2] + t[12 + r];
            m->positions[3 * v + (size_t)r] = (float)w;
            double nn = nm[r][0] * n[0] + nm[r][1] * n[1] + nm[r][2] * n[2];
            m->normals[3 * v + (size_t)r] = isfinite(nn) ? (float)nn : 0.0f;
            s->bounds_min[r] = fminf(s->bounds_min[r], (float)w);
            s->bounds_max[r] = fmaxf(s->bounds_max[r], (float)w);
        }
        if (m->object_positions) /* the object's axes in metres, as lit.vert's v_object */
            for (int r = 0; r < 3; r++)
                m->object_positions[3 * v + (size_t)r] =
                    (float)(p[r] * sqrt(t[4 * r] * t[4 * r] + t[4 * r + 1] * t[4 * r + 1] +
                                        t[4 * r + 2] * t[4 * r + 2]));
        if (d->uvs) {
            m->uvs[2 * v] = isfinite(d->uvs[2 * v]) ? d->uvs[2 * v] : 0.0f;
            m->uvs[2 * v + 1] = isfinite(d->uvs[2 * v + 1]) ? d->uvs[2 * v + 1] : 0.0f;
        }
    }
    m->positions[3 * nv] = 0.0f;
    /* A mirroring transform turns counter-clockwise triangles clockwise; the GPU then calls
     * clockwise the front (glFrontFace). Reordering keeps "front = counter-clockwise" here. */
    for (size_t i = 0; i < nt; i++) {
        uint32_t a = d->indices[3 * i], b = d->indices[3 * i + 1], c = d->indices[3 * i + 2];
        m->indices[3 * i] = a;
        m->indices[3 * i + 1] = det < 0.0 ? c : b;
        m->indices[3 * i + 2] = det < 0.0 ? b : c;
        const float *p0 = m->positions + 3 * (size_t)m->indices[3 * i];
        const float *p1 = m->positions + 3 * (size_t)m->indices[3 * i + 1];
        const float *p2 = m->positions + 3 * (size_t)m->indices[3 * i + 2];
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)p1[k] - p0[k];
            e2[k] = (double)p2[k] - p0[k];
        }
        m->tri_normals[3 * i] = (float)(e1[1] * e2[2] - e1[2] * e2[1]);
        m->tri_normals[3 * i + 1] = (float)(e1[2] * e2[0] - e1[0] * e2[2]);
        m->tri_normals[3 * i + 2] = (float)(e1[0] * e2[1] - e1[1] * e2[0]);
    }
    m->indices[3 * nt] = 0;
    m->tri_normals[3 * nt] = 0.0f;
    m->vertex_count = (int)nv;
    m->triangle_count = (int)nt;
    return REF_OK;
}

ref_result ref_scene_add_mesh(ref_scene *s, const ref_mesh_desc *d)
{
    if (!s || !d)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_add_mesh: scene and desc required");
    ref_result r = validate_mesh(d);
    if (r != REF_OK)
        return r;
    if (d->texture < 0 || d->texture > s->texture_count)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_add_mesh: no texture %d", d->texture);
    if (s->mesh_count == s->mesh_capacity) {
        int cap = s->mesh_capacity ? 2 * s->mesh_capacity : 32;
        ref_mesh *m = realloc(s->meshes, (size_t)cap * sizeof *m);
        if (!m)
            return ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_scene_add_mesh: out of memory");
        s->meshes = m;
        s->mesh_capacity = cap;
    }
    ref_mesh *m = &s->meshes[s->mesh_count];
    memset(m, 0, sizeof *m);
    r = bake_mesh(s, d, m);
    if (r != REF_OK) {
        mesh_free(m);
        return r;
    }
    m->material = d->material;
    m->material.diffuse_texture = (rd_texture){0};
    m->texture = d->texture;
    m->double_sided = d->double_sided ? 1 : 0;
    /* The GPU's rules (render/src/probe.c, draw.c): a probe for k_r > 0 or transparency > 0,
     * and probes do not see glass. */
    m->reflective = d->material.reflectivity > 0.0f || d->material.transparency > 0.0f;
    m->glass = d->material.transparency > 0.0f;
    m->background = d->background != 0;
    m->light_stand_in = d->light_stand_in != 0;
    for (int k = 0; k < 3; k++) {
        float e = d->material.emissive[k];
        m->emission[k] = isfinite(e) && e > 0.0f ? e : 0.0f;
    }
    for (int k = 0; k < 2; k++)
        m->uv_scale[k] = d->material.uv_scale[k] > 0.0f ? d->material.uv_scale[k] : 1.0f;
    s->mesh_count++;
    s->dirty = true;
    if (s->sh9_state == 3)
        s->sh9_state = 1; /* the SH capture saw the scene without this mesh */
    float diag = 0.0f;
    for (int k = 0; k < 3; k++) {
        float e = s->bounds_max[k] - s->bounds_min[k];
        diag += e * e;
    }
    diag = sqrtf(diag);
    s->epsilon = isfinite(diag) && diag > 0.0f ? 1e-5f * diag : 1e-6f;
    return REF_OK;
}

ref_result ref_scene_add_light(ref_scene *s, const rd_light *light)
{
    if (!s || !light)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_add_light: scene and light required");
    if (s->light_count >= RD_MAX_LIGHTS)
        return ref_fail(REF_ERR_TOO_LARGE, "a scene holds at most %d lights", RD_MAX_LIGHTS);
    rd_light l = *light;
    if (l.type != RD_LIGHT_POINT) {
        float len = sqrtf(ref_dot(l.direction, l.direction));
        if (!(len > 0.0f) || !isfinite(len))
            return ref_fail(REF_ERR_INVALID_ARGUMENT,
                            "a spot or directional light needs a direction");
        for (int k = 0; k < 3; k++)
            l.direction[k] /= len;
    }
    s->lights[s->light_count++] = l;
    if (s->sh9_state == 3)
        s->sh9_state = 1;
    return REF_OK;
}

void ref_scene_set_ambient(ref_scene *s, const float intensity[3])
{
    if (s && intensity)
        memcpy(s->ambient, intensity, sizeof s->ambient);
}

void ref_scene_set_ambient_sh9(ref_scene *s, const float centre[3])
{
    if (!s)
        return;
    s->sh9_state = centre ? 1 : 0;
    if (centre)
        memcpy(s->sh9_centre, centre, sizeof s->sh9_centre);
}

int ref_scene_ambient_sh9(const ref_scene *s, rd_sh9 *out)
{
    if (!s || s->sh9_state != 3 || !out)
        return 0;
    *out = s->sh9;
    return 1;
}

int ref_scene_mesh_count(const ref_scene *s)
{
    return s ? s->mesh_count : 0;
}

static void embree_error(void *user, enum RTCError code, const char *text)
{
    (void)user;
    ref_fail(REF_ERR_EMBREE, "Embree error %d: %s", (int)code, text ? text : "");
}

ref_result ref_scene_commit(ref_scene *s)
{
    if (!s)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_commit: no scene");
    if (s->rtc && !s->dirty)
        return REF_OK;
    if (!s->device) {
        s->device = rtcNewDevice(NULL);
        if (!s->device)
            return ref_fail(REF_ERR_EMBREE, "cannot make an Embree device (error %d)",
                            (int)rtcGetDeviceError(NULL));
        rtcSetDeviceErrorFunction(s->device, embree_error, NULL);
    }
    if (s->rtc)
        rtcReleaseScene(s->rtc);
    s->rtc = rtcNewScene(s->device);
    if (!s->rtc)
        return ref_fail(REF_ERR_EMBREE, "cannot make an Embree scene");
    /* Robust: watertight edges, as a rasteriser's; the context filter applies the culling and
     * the secondary rays' rules (ref_trace.c). */
    rtcSetSceneFlags(s->rtc, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(s->rtc, RTC_BUILD_QUALITY_HIGH);
    for (int i = 0; i < s->mesh_count; i++) {
        ref_mesh *m = &s->meshes[i];
        if (m->triangle_count == 0)
            continue;
        RTCGeometry g = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        if (!g)
            return ref_fail(REF_ERR_EMBREE, "cannot make an Embree geometry");
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, m->positions, 0,
                                   3 * sizeof(float), (size_t)m->vertex_count);
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m->indices, 0,
                                   3 * sizeof(uint32_t), (size_t)m->triangle_count);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(s->rtc, g, (unsigned)i);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(s->rtc);
    enum RTCError e = rtcGetDeviceError(s->device);
    if (e != RTC_ERROR_NONE) {
        rtcReleaseScene(s->rtc);
        s->rtc = NULL;
        return e == RTC_ERROR_OUT_OF_MEMORY
                   ? ref_fail(REF_ERR_OUT_OF_MEMORY, "Embree: out of memory building the scene")
                   : ref_fail(REF_ERR_EMBREE, "Embree could not build the scene (error %d)",
                              (int)e);
    }
    s->dirty = false;
    return REF_OK;
}
