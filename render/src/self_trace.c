/* Self-reflections (docs/rendering.md, "Self-reflections").
 *
 * A probe sits at its product's centre and leaves the product out (rd_object_key): seen from
 * inside, the parts would cover its faces. So a tap's body shows the room where the tracer's
 * ray meets the tap's own lever and cap, a soap basket's rim the wall behind its far side, a
 * bath's inner side no bath. What a probe does hold, it holds as seen from its centre: the
 * basin beside a tap lands where the tap's ray would pass it (a silhouette the "depth" search
 * cannot tell from a hit). On the designed demo these carried most of the reflective error at
 * print (docs/accuracy.md, "Self-reflections").
 *
 * So each probe's readers trace their surroundings: the probe's own parts and the fixtures
 * nearest them (within a fifth of the room's diagonal, at most RD_MAX_SELF_PARTS objects; never
 * the room, whose box the corrections fit, nor glass, which the tracer's secondary rays do not
 * see) are gathered as world-space triangles into a bounding-volume hierarchy (binned SAH splits,
 * at most four triangles a leaf) in two buffer textures, and left out of the probe's capture.
 * The lookup (lit.frag, SELF_TRACE) traces the reflected ray, and through glass the refracted
 * one, against them; a hit is shaded as the tracer's secondary ray shades it (eqs. 1-7 seen
 * from the reflecting point, unshadowed), and a reflective part (chrome seen in chrome or
 * through a pane) adds a second bounce, its own reflection read from the probe and blended by
 * its k_r (section 6), where drawn plain it would be its dark diffuse colour; a miss reads the
 * probe, which now holds only what lies beyond. A blurred lookup traces
 * rd_reflection_defaults.self_reflections directions of its lobe a sample, stratified over the
 * pixel's samples. The tracer's rules hold: the ray leaves its own triangle out
 * (gl_PrimitiveID), starts a scene epsilon away and sees no back face of a closed mesh. */
#include "self_trace.h"
#include "gl_funcs.h"
#include "probe.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TRI_TEXELS 7  /* RGBA32F texels a triangle (see pack_triangle) */
#define NODE_TEXELS 2 /* bounds min + first/right, bounds max + count */
#define LEAF_SIZE 4
#define VERTEX_FLOATS 8        /* a mesh's vertex (resources.c): position, normal, uv */
#define BAKED_VERTEX_FLOATS 14 /* and the bake's light (4) and lightmap coordinates (2) */
#define MAX_SELF_TRIANGLES (1 << 20)
/* How far around its own parts a probe's trace takes neighbours, as a fraction of the room's
 * (the box proxy's) diagonal, so that a scene drawn at another scale traces the same: about a
 * metre in the designed demo. The own parts alone leave the neighbours' silhouettes wrong;
 * neighbours within about a metre (nearest first) find nearly all of what matters, and a
 * wider reach costs triangles for little (docs/accuracy.md, "Self-reflections"). */
#define RD_SELF_NEAR_FRACTION 0.2f

typedef struct tri_src {
    float p[3][3], n[3][3], uv[3][2];
    int part, index, double_sided;
    float centre[3], lo[3], hi[3];
} tri_src;

typedef struct builder {
    tri_src *tris;
    int count;
    float *nodes; /* NODE_TEXELS * 4 floats a node */
    int node_count;
} builder;

/* Whether an object alone can reflect part of itself: a convex unit shape cannot. */
static int can_see_itself(const rd_object_desc *o)
{
    return o->shape == RD_SHAPE_MESH;
}

int rd_self_traced(const rd_scene *s, const rd_probe *p)
{
    return s->reflection.self_reflections > 0 && p->self.tri_count > 0;
}

/* The world box of the probe's own objects. */
static void key_bounds(rd_context *ctx, const rd_scene *s, const rd_probe *p, float lo[3],
                       float hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (int i = 0; i < s->object_count; i++) {
        if (rd_object_key(s, i) != p->key)
            continue;
        float a[3], b[3];
        rd_object_world_bounds(ctx, &s->objects[i], a, b);
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], a[k]);
            hi[k] = fmaxf(hi[k], b[k]);
        }
    }
}

/* The gap between object i's world box and [lo, hi] (0 where they overlap). */
static float box_gap(rd_context *ctx, const rd_object_desc *o, const float lo[3], const float hi[3])
{
    float a[3], b[3], d2 = 0.0f;
    rd_object_world_bounds(ctx, o, a, b);
    for (int k = 0; k < 3; k++) {
        float g = fmaxf(fmaxf(a[k] - hi[k], lo[k] - b[k]), 0.0f);
        d2 += g * g;
    }
    return sqrtf(d2);
}

/* The objects probe p's lookups trace, into list: its own parts, then the fixtures nearest
 * them within RD_SELF_NEAR_FRACTION of the room's diagonal while the lookups' part uniforms
 * hold them; never glass (the tracer's secondary rays do not see it) nor the room. The count,
 * -1 when there is nothing a trace would add (a lone convex shape) or too much (its own parts
 * alone overflow). */
static int members(rd_context *ctx, const rd_scene *s, const rd_probe *p,
                   int list[RD_MAX_SELF_PARTS])
{
    float lo[3], hi[3], room_lo[3], room_hi[3];
    key_bounds(ctx, s, p, lo, hi);
    rd_effective_proxy(s, room_lo, room_hi);
    float margin = RD_SELF_NEAR_FRACTION * glm_vec3_distance(room_lo, room_hi);
    int n = 0, textures = 0, any_mesh = 0;
    for (int i = 0; i < s->object_count; i++) {
        const rd_object_desc *o = &s->objects[i];
        if (rd_object_key(s, i) != p->key || o->material.transparency > 0.0f)
            continue;
        if (n == RD_MAX_SELF_PARTS)
            return -1;
        list[n++] = i;
        textures += o->material.diffuse_texture.id != 0;
        any_mesh |= can_see_itself(o);
    }
    if (textures > RD_MAX_SELF_TEXTURES)
        return -1;
    any_mesh |= n >= 2; /* parts of one product see each other (a spout its body) */
    /* Neighbours, nearest first (selection by repeated minimum: scenes hold tens of objects). */
    while (n < RD_MAX_SELF_PARTS && margin > 0.0f) {
        int best = -1;
        float best_gap = margin;
        for (int i = 0; i < s->object_count; i++) {
            const rd_object_desc *o = &s->objects[i];
            if (o->background || o->material.transparency > 0.0f || rd_object_key(s, i) == p->key)
                continue;
            int taken = 0;
            for (int j = 0; j < n && !taken; j++)
                taken = list[j] == i;
            int textured = o->material.diffuse_texture.id != 0;
            if (taken || textures + textured > RD_MAX_SELF_TEXTURES)
                continue;
            float gap = box_gap(ctx, o, lo, hi);
            if (gap <= best_gap) {
                best = i;
                best_gap = gap;
            }
        }
        if (best < 0)
            break;
        list[n++] = best;
        textures += s->objects[best].material.diffuse_texture.id != 0;
        any_mesh = 1;
    }
    return any_mesh ? n : -1;
}

static void grow_bounds(float lo[3], float hi[3], const float p[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = fminf(lo[k], p[k]);
        hi[k] = fmaxf(hi[k], p[k]);
    }
}

/* Object o's triangles in world space, as lit.vert places them (u_model, u_normal_matrix),
 * read back from its mesh's buffers (resources.c: position, normal, uv interleaved, then the
 * bake's light and lightmap coordinates in a baked mesh's wider vertex). */
static rd_result append_object(rd_context *ctx, const rd_object_desc *o, int part, tri_src **tris,
                               int *count, int *capacity)
{
    const rd_mesh_slot *m = rd_mesh_lookup(ctx, o->mesh);
    if (!m || m->index_count < 3)
        return RD_OK;
    GLint vbytes = 0;
    glBindBuffer(GL_ARRAY_BUFFER, m->vbo);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &vbytes);
    int stride = m->bake ? BAKED_VERTEX_FLOATS : VERTEX_FLOATS;
    int vertices = vbytes / (int)(stride * (int)sizeof(float));
    int tri_count = m->index_count / 3;
    if (*count + tri_count > MAX_SELF_TRIANGLES)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "self-reflections: more than %d triangles",
                       MAX_SELF_TRIANGLES);
    float *v = malloc((size_t)(vertices > 0 ? vertices : 1) * (size_t)stride * sizeof *v);
    uint32_t *idx = malloc((size_t)m->index_count * sizeof *idx);
    tri_src *grown = *tris;
    if (v && idx && *count + tri_count > *capacity) {
        grown = realloc(*tris, (size_t)(*count + tri_count) * sizeof *grown);
        if (grown) {
            *tris = grown;
            *capacity = *count + tri_count;
        }
    }
    if (!v || !idx || !grown) {
        free(v);
        free(idx);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "self-reflections: out of memory");
    }
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)vertices * stride * (GLsizeiptr)sizeof *v,
                       v);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    /* The element buffer belongs to the mesh's vertex array: read it through a plain binding. */
    glBindVertexArray(0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
    glGetBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0,
                       (GLsizeiptr)m->index_count * (GLsizeiptr)sizeof *idx, idx);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    mat4 model;
    mat3 normal;
    memcpy(model, o->transform, sizeof model);
    glm_mat4_pick3(model, normal);
    glm_mat3_inv(normal, normal);
    glm_mat3_transpose(normal);
    for (int t = 0; t < tri_count; t++) {
        tri_src *d = &(*tris)[(*count)++];
        d->part = part;
        d->index = t;
        d->double_sided = o->double_sided != 0;
        for (int k = 0; k < 3; k++) {
            d->lo[k] = INFINITY;
            d->hi[k] = -INFINITY;
        }
        for (int c = 0; c < 3; c++) {
            uint32_t i = idx[3 * t + c];
            const float *src = i < (uint32_t)vertices ? v + (size_t)stride * i : NULL;
            vec4 pos = {0.0f, 0.0f, 0.0f, 1.0f}, world;
            vec3 n = {0.0f, 0.0f, 0.0f};
            if (src) {
                memcpy(pos, src, 3 * sizeof(float));
                memcpy(n, src + 3, 3 * sizeof(float));
                memcpy(d->uv[c], src + 6, 2 * sizeof(float));
            } else {
                d->uv[c][0] = d->uv[c][1] = 0.0f;
            }
            glm_mat4_mulv(model, pos, world);
            glm_mat3_mulv(normal, n, d->n[c]);
            memcpy(d->p[c], world, 3 * sizeof(float));
            grow_bounds(d->lo, d->hi, d->p[c]);
        }
        for (int k = 0; k < 3; k++)
            d->centre[k] = (d->p[0][k] + d->p[1][k] + d->p[2][k]) / 3.0f;
    }
    free(v);
    free(idx);
    return RD_OK;
}

static int compare_axis;
static int by_centre(const void *a, const void *b)
{
    float x = ((const tri_src *)a)->centre[compare_axis];
    float y = ((const tri_src *)b)->centre[compare_axis];
    return (x > y) - (x < y);
}

/* Buckets of the binned surface area heuristic (sah_split). */
#define SAH_BINS 16

static float half_area(const float lo[3], const float hi[3])
{
    float e[3];
    for (int k = 0; k < 3; k++)
        e[k] = hi[k] - lo[k];
    return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
}

static int sah_bin(float c, float lo, float extent)
{
    int b = (int)((c - lo) * (float)SAH_BINS / extent);
    return b < 0 ? 0 : b >= SAH_BINS ? SAH_BINS - 1 : b;
}

/* A split of the `count` triangles at t by the surface area heuristic over centroid bins
 * (Wald 2007, "On fast construction of SAH-based bounding volume hierarchies"): of the bin
 * borders on the three axes, the one that minimises area(left) n(left) + area(right) n(right),
 * the expected cost of a ray that meets the node. A walk then enters fewer boxes than with
 * median splits, which on a fixture's mesh (dense rims beside large flat faces) leave wide,
 * overlapping children. Partitions t in place and returns the left part's size; 0 when no
 * border separates the centroids. */
static int sah_split(tri_src *t, int count, const float clo[3], const float chi[3])
{
    float best_cost = INFINITY;
    int best_axis = -1, best_bin = 0;
    for (int axis = 0; axis < 3; axis++) {
        float extent = chi[axis] - clo[axis];
        if (!(extent > 0.0f))
            continue;
        int n[SAH_BINS] = {0};
        float lo[SAH_BINS][3], hi[SAH_BINS][3];
        for (int b = 0; b < SAH_BINS; b++)
            for (int k = 0; k < 3; k++) {
                lo[b][k] = INFINITY;
                hi[b][k] = -INFINITY;
            }
        for (int i = 0; i < count; i++) {
            int b = sah_bin(t[i].centre[axis], clo[axis], extent);
            n[b]++;
            grow_bounds(lo[b], hi[b], t[i].lo);
            grow_bounds(lo[b], hi[b], t[i].hi);
        }
        /* The right side of each border, swept from the far end. */
        float right_area[SAH_BINS], alo[3] = {INFINITY, INFINITY, INFINITY},
                                    ahi[3] = {-INFINITY, -INFINITY, -INFINITY};
        int right_n[SAH_BINS], acc = 0;
        for (int b = SAH_BINS - 1; b > 0; b--) {
            if (n[b]) {
                grow_bounds(alo, ahi, lo[b]);
                grow_bounds(alo, ahi, hi[b]);
            }
            acc += n[b];
            right_n[b] = acc;
            right_area[b] = acc ? half_area(alo, ahi) : 0.0f;
        }
        float llo[3] = {INFINITY, INFINITY, INFINITY}, lhi[3] = {-INFINITY, -INFINITY, -INFINITY};
        int left_n = 0;
        for (int b = 0; b < SAH_BINS - 1; b++) {
            if (n[b]) {
                grow_bounds(llo, lhi, lo[b]);
                grow_bounds(llo, lhi, hi[b]);
            }
            left_n += n[b];
            if (left_n == 0 || right_n[b + 1] == 0)
                continue;
            float cost =
                half_area(llo, lhi) * (float)left_n + right_area[b + 1] * (float)right_n[b + 1];
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best_bin = b;
            }
        }
    }
    if (best_axis < 0)
        return 0;
    float extent = chi[best_axis] - clo[best_axis];
    int i = 0, j = count - 1;
    while (i <= j) {
        if (sah_bin(t[i].centre[best_axis], clo[best_axis], extent) <= best_bin) {
            i++;
        } else {
            tri_src tmp = t[i];
            t[i] = t[j];
            t[j--] = tmp;
        }
    }
    return i;
}

/* Node layout (lit.frag's self_trace): nodes in depth-first order, so a node's subtree is the
 * run of nodes from it up to its skip index; texel 0 = bounds min, w = first triangle of a
 * leaf or an inner node's skip index (the node after its subtree: where a ray that misses its
 * box goes on; a leaf's is the next node); texel 1 = bounds max, w = the leaf's triangle
 * count, 0 for an inner node. Indices are stored as floats: exact to 2^24. */
static int build_node(builder *b, int first, int count)
{
    int node = b->node_count++;
    float *out = b->nodes + (size_t)node * NODE_TEXELS * 4;
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    float clo[3] = {INFINITY, INFINITY, INFINITY}, chi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = first; i < first + count; i++) {
        grow_bounds(lo, hi, b->tris[i].lo);
        grow_bounds(lo, hi, b->tris[i].hi);
        grow_bounds(clo, chi, b->tris[i].centre);
    }
    memcpy(out, lo, sizeof lo);
    memcpy(out + 4, hi, sizeof hi);
    if (count <= LEAF_SIZE) {
        out[3] = (float)first;
        out[7] = (float)count;
        return node;
    }
    int half = sah_split(b->tris + first, count, clo, chi);
    if (half <= 0 || half >= count) { /* coincident centroids: halves along the longest axis */
        int axis = 0;
        for (int k = 1; k < 3; k++)
            if (chi[k] - clo[k] > chi[axis] - clo[axis])
                axis = k;
        compare_axis = axis;
        qsort(b->tris + first, (size_t)count, sizeof *b->tris, by_centre);
        half = count / 2;
    }
    build_node(b, first, half);
    build_node(b, first + half, count - half);
    out = b->nodes + (size_t)node * NODE_TEXELS * 4; /* b->nodes does not move: sized up front */
    out[3] = (float)b->node_count;
    out[7] = 0.0f;
    return node;
}

/* Triangle layout (lit.frag's self_trace): p0 + part, p1 - p0 + index in its part's mesh,
 * p2 - p0 + double-sided, then the three normals with u0, v0, u1, and (v1, u2, v2). */
static void pack_triangle(const tri_src *t, float out[TRI_TEXELS * 4])
{
    for (int k = 0; k < 3; k++) {
        out[k] = t->p[0][k];
        out[4 + k] = t->p[1][k] - t->p[0][k];
        out[8 + k] = t->p[2][k] - t->p[0][k];
        out[12 + k] = t->n[0][k];
        out[16 + k] = t->n[1][k];
        out[20 + k] = t->n[2][k];
    }
    out[3] = (float)t->part;
    out[7] = (float)t->index;
    out[11] = (float)t->double_sided;
    out[15] = t->uv[0][0];
    out[19] = t->uv[0][1];
    out[23] = t->uv[1][0];
    out[24] = t->uv[1][1];
    out[25] = t->uv[2][0];
    out[26] = t->uv[2][1];
    out[27] = 0.0f;
}

static void upload(unsigned *buffer, unsigned *texture, const float *data, size_t floats)
{
    if (!*buffer)
        glGenBuffers(1, buffer);
    if (!*texture)
        glGenTextures(1, texture);
    glBindBuffer(GL_TEXTURE_BUFFER, *buffer);
    glBufferData(GL_TEXTURE_BUFFER, (GLsizeiptr)(floats * sizeof(float)), data, GL_STATIC_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glBindTexture(GL_TEXTURE_BUFFER, *texture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, *buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
}

static rd_result build_bvh(rd_context *ctx, rd_scene *s, rd_probe *p, const int *list, int n)
{
    rd_self_bvh *b = &p->self;
    tri_src *tris = NULL;
    int count = 0, capacity = 0;
    b->part_count = 0;
    rd_result r = RD_OK;
    for (int j = 0; r == RD_OK && j < n; j++) {
        int part = b->part_count++;
        b->part_object[part] = list[j];
        b->part_base[part] = count;
        r = append_object(ctx, &s->objects[list[j]], part, &tris, &count, &capacity);
    }
    if (r != RD_OK || count == 0) {
        free(tris);
        b->tri_count = 0;
        return r;
    }
    /* The triangle's number within its part's mesh is what gl_PrimitiveID gives its own
     * fragments; the stored index is the part's base plus it. */
    for (int t = 0; t < count; t++)
        tris[t].index += b->part_base[tris[t].part];
    builder bd = {.tris = tris, .count = count};
    bd.nodes = malloc((size_t)(2 * count) * NODE_TEXELS * 4 * sizeof(float));
    float *packed = malloc((size_t)count * TRI_TEXELS * 4 * sizeof(float));
    if (!bd.nodes || !packed) {
        free(bd.nodes);
        free(packed);
        free(tris);
        b->tri_count = 0;
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "self-reflections: out of memory");
    }
    build_node(&bd, 0, count);
    for (int t = 0; t < count; t++)
        pack_triangle(&tris[t], packed + (size_t)t * TRI_TEXELS * 4);
    upload(&b->node_buffer, &b->node_texture, bd.nodes, (size_t)bd.node_count * NODE_TEXELS * 4);
    upload(&b->tri_buffer, &b->tri_texture, packed, (size_t)count * TRI_TEXELS * 4);
    b->node_count = bd.node_count;
    b->tri_count = count;
    free(bd.nodes);
    free(packed);
    free(tris);
    return RD_OK;
}

rd_result rd_self_trace_update(rd_context *ctx, rd_scene *s)
{
    for (int i = 0; i < s->probe_count; i++) {
        rd_probe *p = &s->probes[i];
        int list[RD_MAX_SELF_PARTS];
        /* A planar mirror sees what lies in front of its plane through its capture. */
        int n = s->reflection.self_reflections > 0 && !p->planar ? members(ctx, s, p, list) : -1;
        if (n <= 0) {
            if (p->self.tri_count) { /* its capture left parts out that it must now show */
                p->faces_valid = 0;
                p->next_face = 0;
            }
            rd_self_trace_free(&p->self);
            continue;
        }
        /* Rebuilt when a member changed or the members did. */
        long long stamp = 0;
        int same = n == p->self.part_count;
        for (int j = 0; j < n; j++) {
            if (s->object_stamps[list[j]] > stamp)
                stamp = s->object_stamps[list[j]];
            same = same && p->self.part_object[j] == list[j];
        }
        if (same && p->self.stamp == stamp && stamp != 0)
            continue;
        if (!same) { /* the capture leaves the parts out (probe.c): capture it again */
            p->faces_valid = 0;
            p->next_face = 0;
        }
        rd_result r = build_bvh(ctx, s, p, list, n);
        if (r != RD_OK)
            return r;
        p->self.stamp = stamp;
    }
    return RD_OK;
}

void rd_set_self_trace_uniforms(rd_context *ctx, const rd_program *prog, const rd_scene *s,
                                const rd_probe *p, int index, int sample_grid)
{
    const rd_self_bvh *b = &p->self;
    float amb[RD_MAX_SELF_PARTS][3], dif[RD_MAX_SELF_PARTS][3], spec[RD_MAX_SELF_PARTS][3],
        emis[RD_MAX_SELF_PARTS][3], shin[RD_MAX_SELF_PARTS], kr[RD_MAX_SELF_PARTS],
        uv_scale[RD_MAX_SELF_PARTS][2];
    /* An object outside the hierarchy (glass, which the trace leaves out) owns none of its
     * triangles: -1 keeps its gl_PrimitiveID from naming a member's triangle of that number. */
    int slot[RD_MAX_SELF_PARTS], blend[RD_MAX_SELF_PARTS], textures = 0, base = -1;
    for (int i = 0; i < b->part_count; i++) {
        const rd_object_desc *o = &s->objects[b->part_object[i]];
        const rd_material *m = &o->material;
        memcpy(amb[i], m->ambient, sizeof amb[i]);
        memcpy(dif[i], m->diffuse, sizeof dif[i]);
        memcpy(spec[i], m->specular, sizeof spec[i]);
        memcpy(emis[i], m->emissive, sizeof emis[i]);
        shin[i] = m->shininess;
        kr[i] = fminf(fmaxf(m->reflectivity, 0.0f), 1.0f);
        blend[i] = (int)m->blend;
        uv_scale[i][0] = m->uv_scale[0] > 0.0f ? m->uv_scale[0] : 1.0f;
        uv_scale[i][1] = m->uv_scale[1] > 0.0f ? m->uv_scale[1] : 1.0f;
        slot[i] = -1;
        const rd_texture_slot *t = rd_texture_lookup(ctx, m->diffuse_texture);
        if (t && textures < RD_MAX_SELF_TEXTURES) {
            glActiveTexture((GLenum)(GL_TEXTURE11 + textures));
            glBindTexture(GL_TEXTURE_2D, t->name);
            slot[i] = textures++;
        }
        if (b->part_object[i] == index)
            base = b->part_base[i];
    }
    glActiveTexture(GL_TEXTURE9);
    glBindTexture(GL_TEXTURE_BUFFER, b->node_texture);
    glUniform1i(prog->u_self_nodes, 9);
    glActiveTexture(GL_TEXTURE10);
    glBindTexture(GL_TEXTURE_BUFFER, b->tri_texture);
    glUniform1i(prog->u_self_tris, 10);
    glActiveTexture(GL_TEXTURE0);
    int units[RD_MAX_SELF_TEXTURES] = {11, 12, 13, 14};
    glUniform1iv(prog->u_self_textures, RD_MAX_SELF_TEXTURES, units);
    glUniform1i(prog->u_self_base, base);
    int n = b->part_count;
    glUniform3fv(prog->u_self_ambient, n, &amb[0][0]);
    glUniform3fv(prog->u_self_diffuse, n, &dif[0][0]);
    glUniform3fv(prog->u_self_specular, n, &spec[0][0]);
    glUniform3fv(prog->u_self_emissive, n, &emis[0][0]);
    glUniform1fv(prog->u_self_shininess, n, shin);
    glUniform1fv(prog->u_self_kr, n, kr);
    glUniform1iv(prog->u_self_blend, n, blend);
    glUniform1iv(prog->u_self_slot, n, slot);
    glUniform2fv(prog->u_self_uv_scale, n, &uv_scale[0][0]);
    /* The tracer's ray offset, 1e-5 of the scene's diagonal (ref_scene.c): here the proxy's,
     * the room that holds the scene. */
    float lo[3], hi[3];
    rd_effective_proxy(s, lo, hi);
    /* A mirror traces its one reflected ray; a blurred lookup that many of its lobe's. */
    glUniform1i(prog->u_self_rays, s->reflection.self_reflections);
    glUniform1i(prog->u_self_grid, sample_grid);
    glUniform1f(prog->u_self_epsilon, 1e-5f * glm_vec3_distance(lo, hi));
}

int rd_self_bvh_holds(const rd_self_bvh *b, int index)
{
    for (int i = 0; i < b->part_count && b->tri_count > 0; i++)
        if (b->part_object[i] == index)
            return 1;
    return 0;
}

void rd_self_trace_free(rd_self_bvh *b)
{
    if (b->node_texture)
        glDeleteTextures(1, &b->node_texture);
    if (b->tri_texture)
        glDeleteTextures(1, &b->tri_texture);
    if (b->node_buffer)
        glDeleteBuffers(1, &b->node_buffer);
    if (b->tri_buffer)
        glDeleteBuffers(1, &b->tri_buffer);
    *b = (rd_self_bvh){0};
}
