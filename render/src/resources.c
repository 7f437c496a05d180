/* Meshes and textures behind generation-counted handles (sokol's idea): id = generation << 16
 * | (slot index + 1), so id 0 is never valid and a destroyed handle is caught as stale. */
#include "gl_funcs.h"
#include "render_internal.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#define SLOT_BITS 16
#define MAX_SLOTS ((1 << SLOT_BITS) - 1)

static uint32_t make_id(uint32_t generation, int index)
{
    return (generation << SLOT_BITS) | (uint32_t)(index + 1);
}

static int id_index(uint32_t id)
{
    return (int)(id & MAX_SLOTS) - 1;
}

static int grow(void **array, int *capacity, size_t elem)
{
    int cap = *capacity ? *capacity * 2 : 64;
    if (cap > MAX_SLOTS)
        cap = MAX_SLOTS;
    if (cap <= *capacity)
        return 0;
    void *p = realloc(*array, (size_t)cap * elem);
    if (!p)
        return 0;
    memset((char *)p + (size_t)*capacity * elem, 0, (size_t)(cap - *capacity) * elem);
    *array = p;
    *capacity = cap;
    return 1;
}

rd_mesh_slot *rd_mesh_lookup(rd_context *ctx, rd_mesh mesh)
{
    int i = id_index(mesh.id);
    if (!ctx || i < 0 || i >= ctx->mesh_capacity)
        return NULL;
    rd_mesh_slot *s = &ctx->meshes[i];
    return (s->live && s->generation == (mesh.id >> SLOT_BITS)) ? s : NULL;
}

rd_texture_slot *rd_texture_lookup(rd_context *ctx, rd_texture tex)
{
    int i = id_index(tex.id);
    if (!ctx || i < 0 || i >= ctx->texture_capacity)
        return NULL;
    rd_texture_slot *s = &ctx->textures[i];
    return (s->live && s->generation == (tex.id >> SLOT_BITS)) ? s : NULL;
}

static const char *mesh_desc_problem(const rd_mesh_desc *d)
{
    if (!d || !d->positions || !d->normals || !d->indices)
        return "positions, normals and indices are required";
    if (d->vertex_count <= 0 || d->index_count <= 0 || d->index_count % 3)
        return "vertex count must be > 0 and index count a positive multiple of 3";
    if (d->vertex_count > (1 << 26) || d->index_count > (1 << 28))
        return "too many vertices or indices";
    for (int i = 0; i < d->index_count; i++)
        if (d->indices[i] >= (uint32_t)d->vertex_count)
            return "an index is out of range";
    for (int i = 0; i < d->vertex_count * 3; i++)
        if (!isfinite(d->positions[i]) || !isfinite(d->normals[i]))
            return "a position or normal is not finite";
    return NULL;
}

rd_mesh rd_mesh_create(rd_context *ctx, const rd_mesh_desc *d)
{
    rd_mesh invalid = {0};
    const char *problem = ctx ? mesh_desc_problem(d) : "no context";
    if (problem) {
        rd_set_error("rd_mesh_create: %s", problem);
        return invalid;
    }
    int index = -1;
    for (int i = 0; i < ctx->mesh_capacity; i++)
        if (!ctx->meshes[i].live) {
            index = i;
            break;
        }
    if (index < 0) {
        index = ctx->mesh_capacity;
        if (!grow((void **)&ctx->meshes, &ctx->mesh_capacity, sizeof *ctx->meshes)) {
            rd_set_error("rd_mesh_create: out of mesh slots or memory");
            return invalid;
        }
    }
    /* Interleave position, normal, uv (8 floats per vertex), then the bake's light and
     * lightmap coordinates when there are any (6 more). */
    size_t n = (size_t)d->vertex_count;
    int baked = d->baked_light || d->lightmap_uvs;
    size_t stride = baked ? 14 : 8;
    float *v = malloc(n * stride * sizeof *v);
    if (!v) {
        rd_set_error("rd_mesh_create: out of memory");
        return invalid;
    }
    rd_mesh_slot *s = &ctx->meshes[index];
    for (int k = 0; k < 3; k++) {
        s->bounds_min[k] = FLT_MAX;
        s->bounds_max[k] = -FLT_MAX;
    }
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) {
            float p = d->positions[i * 3 + k];
            v[i * stride + k] = p;
            v[i * stride + 3 + k] = d->normals[i * 3 + k];
            s->bounds_min[k] = fminf(s->bounds_min[k], p);
            s->bounds_max[k] = fmaxf(s->bounds_max[k], p);
        }
        v[i * stride + 6] = d->uvs ? d->uvs[i * 2] : 0.0f;
        v[i * stride + 7] = d->uvs ? d->uvs[i * 2 + 1] : 0.0f;
        if (baked) {
            for (int k = 0; k < 4; k++)
                v[i * stride + 8 + k] = d->baked_light ? d->baked_light[i * 4 + k] : 0.0f;
            v[i * stride + 12] = d->lightmap_uvs ? d->lightmap_uvs[i * 2] : 0.0f;
            v[i * stride + 13] = d->lightmap_uvs ? d->lightmap_uvs[i * 2 + 1] : 0.0f;
        }
    }
    glGenVertexArrays(1, &s->vao);
    glBindVertexArray(s->vao);
    glGenBuffers(1, &s->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, s->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * stride * sizeof *v), v, GL_STATIC_DRAW);
    glGenBuffers(1, &s->ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s->ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)((size_t)d->index_count * sizeof(uint32_t)),
                 d->indices, GL_STATIC_DRAW);
    for (int a = 0; a < 3; a++)
        glEnableVertexAttribArray((GLuint)a);
    GLsizei bytes = (GLsizei)(stride * sizeof(float));
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, bytes, (void *)0);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, bytes, (void *)(3 * sizeof(float)));
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, bytes, (void *)(6 * sizeof(float)));
    if (baked) {
        glEnableVertexAttribArray(3);
        glEnableVertexAttribArray(4);
        glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, bytes, (void *)(8 * sizeof(float)));
        glVertexAttribPointer(4, 2, GL_FLOAT, GL_FALSE, bytes, (void *)(12 * sizeof(float)));
    }
    glBindVertexArray(0);
    free(v);
    if (rd_gl_drain_errors() != GL_NO_ERROR) {
        glDeleteBuffers(1, &s->vbo);
        glDeleteBuffers(1, &s->ibo);
        glDeleteVertexArrays(1, &s->vao);
        rd_set_error("rd_mesh_create: OpenGL could not store the mesh (%d vertices)",
                     d->vertex_count);
        return invalid;
    }
    s->index_count = d->index_count;
    s->bake = d->lightmap_uvs ? 2 : d->baked_light ? 1 : 0;
    s->live = true;
    s->generation = (s->generation + 1) & 0xffff;
    if (!s->generation)
        s->generation = 1;
    return (rd_mesh){make_id(s->generation, index)};
}

void rd_mesh_destroy(rd_context *ctx, rd_mesh mesh)
{
    rd_mesh_slot *s = rd_mesh_lookup(ctx, mesh);
    if (!s)
        return;
    glDeleteBuffers(1, &s->vbo);
    glDeleteBuffers(1, &s->ibo);
    glDeleteVertexArrays(1, &s->vao);
    s->vao = s->vbo = s->ibo = 0;
    s->live = false;
}

rd_texture rd_texture_create(rd_context *ctx, const rd_texture_desc *d)
{
    rd_texture invalid = {0};
    if (!ctx || !d || !d->rgba || d->width <= 0 || d->height <= 0) {
        rd_set_error("rd_texture_create: width, height and pixels are required");
        return invalid;
    }
    if (d->width > ctx->max_size || d->height > ctx->max_size) {
        rd_set_error("rd_texture_create: %dx%d exceeds this context's limit of %d", d->width,
                     d->height, ctx->max_size);
        return invalid;
    }
    int index = -1;
    for (int i = 0; i < ctx->texture_capacity; i++)
        if (!ctx->textures[i].live) {
            index = i;
            break;
        }
    if (index < 0) {
        index = ctx->texture_capacity;
        if (!grow((void **)&ctx->textures, &ctx->texture_capacity, sizeof *ctx->textures)) {
            rd_set_error("rd_texture_create: out of texture slots or memory");
            return invalid;
        }
    }
    /* sRGB display values go in as GL_SRGB8_ALPHA8 so the sampler decodes them to linear;
     * linear data stays float. Non-finite texels are zeroed on the way in. */
    size_t count = (size_t)d->width * (size_t)d->height * 4;
    rd_texture_slot *s = &ctx->textures[index];
    glGenTextures(1, &s->name);
    glBindTexture(GL_TEXTURE_2D, s->name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (d->srgb_encoded) {
        unsigned char *bytes = malloc(count);
        if (!bytes) {
            glDeleteTextures(1, &s->name);
            rd_set_error("rd_texture_create: out of memory");
            return invalid;
        }
        for (size_t i = 0; i < count; i++) {
            float x = d->rgba[i];
            x = isfinite(x) ? fminf(fmaxf(x, 0.0f), 1.0f) : 0.0f;
            bytes[i] = (unsigned char)(x * 255.0f + 0.5f);
        }
        glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, d->width, d->height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, bytes);
        free(bytes);
    } else {
        float *clean = malloc(count * sizeof *clean);
        if (!clean) {
            glDeleteTextures(1, &s->name);
            rd_set_error("rd_texture_create: out of memory");
            return invalid;
        }
        for (size_t i = 0; i < count; i++)
            clean[i] = isfinite(d->rgba[i]) ? d->rgba[i] : 0.0f;
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, d->width, d->height, 0, GL_RGBA, GL_FLOAT,
                     clean);
        free(clean);
    }
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    /* Floors and walls are mostly seen at grazing angles: without anisotropic filtering their
     * tile joints blur away. Core in GL 4.6, an extension before; ignored where missing. */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, 8.0f);
    rd_gl_drain_errors();
    glBindTexture(GL_TEXTURE_2D, 0);
    if (rd_gl_drain_errors() != GL_NO_ERROR) {
        glDeleteTextures(1, &s->name);
        rd_set_error("rd_texture_create: OpenGL could not store a %dx%d texture", d->width,
                     d->height);
        return invalid;
    }
    s->live = true;
    s->generation = (s->generation + 1) & 0xffff;
    if (!s->generation)
        s->generation = 1;
    return (rd_texture){make_id(s->generation, index)};
}

void rd_texture_destroy(rd_context *ctx, rd_texture tex)
{
    rd_texture_slot *s = rd_texture_lookup(ctx, tex);
    if (!s)
        return;
    glDeleteTextures(1, &s->name);
    s->name = 0;
    s->live = false;
}

rd_texture_slot *rd_cubemap_lookup(rd_context *ctx, rd_cubemap map)
{
    int i = id_index(map.id);
    if (!ctx || i < 0 || i >= ctx->cubemap_capacity)
        return NULL;
    rd_texture_slot *s = &ctx->cubemaps[i];
    return (s->live && s->generation == (map.id >> SLOT_BITS)) ? s : NULL;
}

/* A static cube map (RENDERING.md section 8): six faces in GL order, CMCS, linear RGBA. */
rd_cubemap rd_cubemap_create(rd_context *ctx, const rd_cubemap_desc *d)
{
    rd_cubemap invalid = {0};
    if (!ctx || !d || d->size <= 0 || d->size > ctx->max_size) {
        rd_set_error("rd_cubemap_create: size must be 1..%d", ctx ? ctx->max_size : 0);
        return invalid;
    }
    for (int f = 0; f < 6; f++)
        if (!d->faces[f]) {
            rd_set_error("rd_cubemap_create: face %d is missing", f);
            return invalid;
        }
    int index = -1;
    for (int i = 0; i < ctx->cubemap_capacity; i++)
        if (!ctx->cubemaps[i].live) {
            index = i;
            break;
        }
    if (index < 0) {
        index = ctx->cubemap_capacity;
        if (!grow((void **)&ctx->cubemaps, &ctx->cubemap_capacity, sizeof *ctx->cubemaps)) {
            rd_set_error("rd_cubemap_create: out of slots or memory");
            return invalid;
        }
    }
    size_t count = (size_t)d->size * (size_t)d->size * 4;
    float *clean = malloc(count * sizeof *clean);
    if (!clean) {
        rd_set_error("rd_cubemap_create: out of memory");
        return invalid;
    }
    int levels = 1;
    while ((d->size >> levels) > 0)
        levels++;
    rd_texture_slot *s = &ctx->cubemaps[index];
    glGenTextures(1, &s->name);
    glBindTexture(GL_TEXTURE_CUBE_MAP, s->name);
    for (int f = 0; f < 6; f++) {
        for (size_t i = 0; i < count; i++)
            clean[i] = isfinite(d->faces[f][i]) ? d->faces[f][i] : 0.0f; /* section 11 */
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA16F, d->size, d->size, 0,
                     GL_RGBA, GL_FLOAT, clean);
    }
    free(clean);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    if (rd_gl_drain_errors() != GL_NO_ERROR) {
        glDeleteTextures(1, &s->name);
        rd_set_error("rd_cubemap_create: OpenGL could not store a %d cube map", d->size);
        return invalid;
    }
    s->size = d->size;
    s->live = true;
    s->generation = (s->generation + 1) & 0xffff;
    if (!s->generation)
        s->generation = 1;
    return (rd_cubemap){make_id(s->generation, index)};
}

void rd_cubemap_destroy(rd_context *ctx, rd_cubemap map)
{
    rd_texture_slot *s = rd_cubemap_lookup(ctx, map);
    if (!s)
        return;
    glDeleteTextures(1, &s->name);
    s->name = 0;
    s->live = false;
}

void rd_float_texture_2d(unsigned *name, int w, int h, int mipmapped)
{
    if (!*name)
        glGenTextures(1, name);
    glBindTexture(GL_TEXTURE_2D, *name);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, w, h, 0, GL_RGBA, GL_FLOAT, NULL);
    if (!mipmapped)
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                    mipmapped ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
}

/* Makes *rb at least (or, exact, just) w x h and attaches it to the bound framebuffer. */
static rd_result depth_ensure(unsigned *rb, int *rb_w, int *rb_h, int w, int h, int exact)
{
    int small = *rb_w < w || *rb_h < h;
    if (!*rb || small || (exact && (*rb_w != w || *rb_h != h))) {
        if (!*rb)
            glGenRenderbuffers(1, rb);
        glBindRenderbuffer(GL_RENDERBUFFER, *rb);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
        *rb_w = w;
        *rb_h = h;
    }
    /* Attached on every capture: the prefilter pass detaches it. */
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *rb);
    unsigned e = rd_gl_drain_errors();
    return e == GL_NO_ERROR
               ? RD_OK
               : rd_fail(RD_ERR_OUT_OF_MEMORY, "cannot make a %dx%d probe depth buffer", w, h);
}

rd_result rd_probe_depth_ensure(rd_context *ctx, int size)
{
    int side = ctx->probe_depth_size; /* square: one size stands for both sides */
    return depth_ensure(&ctx->probe_depth, &ctx->probe_depth_size, &side, size, size, 0);
}

rd_result rd_planar_depth_ensure(rd_context *ctx, int w, int h)
{
    return depth_ensure(&ctx->planar_depth, &ctx->planar_depth_w, &ctx->planar_depth_h, w, h, 1);
}

void rd_resources_destroy_all(rd_context *ctx)
{
    for (int i = 0; i < ctx->cubemap_capacity; i++)
        if (ctx->cubemaps[i].live)
            rd_cubemap_destroy(ctx, (rd_cubemap){make_id(ctx->cubemaps[i].generation, i)});
    if (ctx->probe_depth)
        glDeleteRenderbuffers(1, &ctx->probe_depth);
    if (ctx->planar_depth)
        glDeleteRenderbuffers(1, &ctx->planar_depth);
    ctx->planar_depth = 0;
    ctx->planar_depth_w = ctx->planar_depth_h = 0;
    if (ctx->probe_fbo)
        glDeleteFramebuffers(1, &ctx->probe_fbo);
    if (ctx->blit_fbo)
        glDeleteFramebuffers(1, &ctx->blit_fbo);
    ctx->blit_fbo = 0;
    ctx->probe_depth = ctx->probe_fbo = 0;
    for (int i = 0; i < ctx->mesh_capacity; i++)
        if (ctx->meshes[i].live)
            rd_mesh_destroy(ctx, (rd_mesh){make_id(ctx->meshes[i].generation, i)});
    for (int i = 0; i < ctx->texture_capacity; i++)
        if (ctx->textures[i].live)
            rd_texture_destroy(ctx, (rd_texture){make_id(ctx->textures[i].generation, i)});
}
