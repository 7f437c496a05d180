/* Reading glTF accessors with every byte range checked against its buffer view and buffer.
 * (glTF 2.0 specification, sections 3.6.2 "Accessors" and 3.6.2.3 "Sparse Accessors".) */
#include "model_internal.h"

#include <string.h>

static size_t component_size(int type)
{
    switch (type) {
    case CAT_GLTF_BYTE:
    case CAT_GLTF_UNSIGNED_BYTE:
        return 1;
    case CAT_GLTF_SHORT:
    case CAT_GLTF_UNSIGNED_SHORT:
        return 2;
    case CAT_GLTF_UNSIGNED_INT:
    case CAT_GLTF_FLOAT:
        return 4;
    default:
        return 0;
    }
}

/* Raw value of one component (little-endian, as glTF stores it). */
static double fetch(const unsigned char *p, int type)
{
    switch (type) {
    case CAT_GLTF_BYTE:
        return (double)(signed char)p[0];
    case CAT_GLTF_UNSIGNED_BYTE:
        return (double)p[0];
    case CAT_GLTF_SHORT: {
        unsigned v = (unsigned)p[0] | (unsigned)p[1] << 8;
        return (double)(v >= 0x8000u ? (int)v - 0x10000 : (int)v);
    }
    case CAT_GLTF_UNSIGNED_SHORT:
        return (double)((unsigned)p[0] | (unsigned)p[1] << 8);
    case CAT_GLTF_UNSIGNED_INT:
        return (double)((unsigned long)p[0] | (unsigned long)p[1] << 8 | (unsigned long)p[2] << 16 |
                        (unsigned long)p[3] << 24);
    case CAT_GLTF_FLOAT: {
        unsigned long bits = (unsigned long)p[0] | (unsigned long)p[1] << 8 |
                             (unsigned long)p[2] << 16 | (unsigned long)p[3] << 24;
        unsigned u = (unsigned)bits;
        float f;
        memcpy(&f, &u, sizeof f);
        return (double)f;
    }
    default:
        return 0.0;
    }
}

/* Normalized integers, glTF 2.0 section 3.11 "Animations" / KHR_mesh_quantization formulas. */
static double normalize(double v, int type)
{
    double r;
    switch (type) {
    case CAT_GLTF_BYTE:
        r = v / 127.0;
        break;
    case CAT_GLTF_UNSIGNED_BYTE:
        r = v / 255.0;
        break;
    case CAT_GLTF_SHORT:
        r = v / 32767.0;
        break;
    case CAT_GLTF_UNSIGNED_SHORT:
        r = v / 65535.0;
        break;
    case CAT_GLTF_UNSIGNED_INT:
        r = v / 4294967295.0;
        break;
    default:
        return v;
    }
    return r < -1.0 ? -1.0 : r;
}

/* The bytes [offset, offset + length) of a buffer view, checked against its buffer. */
static cat_result view_range(const cat_msg *msg, const char *where, const cat_gltf_doc *doc,
                             int accessor, int view, const unsigned char **data, size_t *length,
                             size_t *stride)
{
    if (view < 0 || view >= doc->view_count)
        return cat_fail(msg, CAT_ERR_INVALID, "%saccessor %d: buffer view %d does not exist", where,
                        accessor, view);
    const cat_gltf_view *v = &doc->views[view];
    if (v->buffer < 0 || v->buffer >= doc->buffer_count)
        return cat_fail(msg, CAT_ERR_INVALID,
                        "%saccessor %d: buffer view %d names buffer %d, which does not exist",
                        where, accessor, view, v->buffer);
    const cat_gltf_buffer *b = &doc->buffers[v->buffer];
    if (v->offset > b->size || v->length > b->size - v->offset)
        return cat_fail(msg, CAT_ERR_INVALID,
                        "%saccessor %d: buffer view %d reads past the end of buffer %d", where,
                        accessor, view, v->buffer);
    *data = b->data + v->offset;
    *length = v->length;
    *stride = v->stride;
    return CAT_OK;
}

/* Does [offset, offset + (count - 1) * stride + elem) fit in length? count >= 1. */
static int fits(size_t offset, size_t count, size_t stride, size_t elem, size_t length)
{
    if (offset > length || elem > length - offset)
        return 0;
    size_t room = length - offset - elem;
    return stride == 0 ? 1 : (count - 1) <= room / stride;
}

cat_result cat_accessor_check(const cat_msg *msg, const char *where, const cat_gltf_doc *doc,
                              int accessor, int components)
{
    if (accessor < 0 || accessor >= doc->accessor_count)
        return cat_fail(msg, CAT_ERR_INVALID, "%saccessor %d does not exist", where, accessor);
    const cat_gltf_accessor *a = &doc->accessors[accessor];
    size_t csize = component_size(a->component_type);
    if (csize == 0)
        return cat_fail(msg, CAT_ERR_INVALID, "%saccessor %d has unknown component type %d", where,
                        accessor, a->component_type);
    if (a->is_matrix || a->components != components)
        return cat_fail(msg, CAT_ERR_INVALID, "%saccessor %d has %d components%s, expected %d",
                        where, accessor, a->components, a->is_matrix ? " (a matrix)" : "",
                        components);
    if (a->count == 0)
        return cat_fail(msg, CAT_ERR_INVALID, "%saccessor %d has count 0", where, accessor);
    size_t elem = csize * (size_t)components;
    if (a->view >= 0) {
        const unsigned char *data;
        size_t length, stride;
        cat_result r = view_range(msg, where, doc, accessor, a->view, &data, &length, &stride);
        if (r != CAT_OK)
            return r;
        if (stride == 0)
            stride = elem;
        if (stride < elem)
            return cat_fail(msg, CAT_ERR_INVALID,
                            "%saccessor %d: buffer view %d has byte stride %zu, less than the "
                            "element size %zu",
                            where, accessor, a->view, stride, elem);
        if (!fits(a->offset, a->count, stride, elem, length))
            return cat_fail(msg, CAT_ERR_INVALID,
                            "%saccessor %d reads past the end of buffer view %d (buffer %d)", where,
                            accessor, a->view, doc->views[a->view].buffer);
    } else if (!a->sparse) {
        /* No view and not sparse: all zeros (glTF 2.0, 3.6.2.1). Allowed, nothing to check. */
    }
    if (a->sparse) {
        if (a->sparse_count < 1 || (unsigned long long)a->sparse_count > a->count)
            return cat_fail(msg, CAT_ERR_INVALID,
                            "%saccessor %d: sparse count %lld is not in 1..%zu", where, accessor,
                            a->sparse_count, a->count);
        size_t isize = component_size(a->sparse_indices_type);
        if (isize == 0 || a->sparse_indices_type == CAT_GLTF_BYTE ||
            a->sparse_indices_type == CAT_GLTF_SHORT || a->sparse_indices_type == CAT_GLTF_FLOAT)
            return cat_fail(msg, CAT_ERR_INVALID,
                            "%saccessor %d: sparse indices have component type %d, expected an "
                            "unsigned integer type",
                            where, accessor, a->sparse_indices_type);
        if (a->sparse_indices_offset < 0 || a->sparse_values_offset < 0)
            return cat_fail(msg, CAT_ERR_INVALID, "%saccessor %d: negative sparse byte offset",
                            where, accessor);
        const unsigned char *data;
        size_t length, stride;
        cat_result r =
            view_range(msg, where, doc, accessor, a->sparse_indices_view, &data, &length, &stride);
        if (r != CAT_OK)
            return r;
        if (!fits((size_t)a->sparse_indices_offset, (size_t)a->sparse_count, isize, isize, length))
            return cat_fail(msg, CAT_ERR_INVALID,
                            "%saccessor %d: sparse indices read past the end of buffer view %d",
                            where, accessor, a->sparse_indices_view);
        r = view_range(msg, where, doc, accessor, a->sparse_values_view, &data, &length, &stride);
        if (r != CAT_OK)
            return r;
        if (!fits((size_t)a->sparse_values_offset, (size_t)a->sparse_count, elem, elem, length))
            return cat_fail(msg, CAT_ERR_INVALID,
                            "%saccessor %d: sparse values read past the end of buffer view %d",
                            where, accessor, a->sparse_values_view);
    }
    return CAT_OK;
}

/* Where read_values puts what it reads: floats (normalized if asked) or unsigned indices. */
typedef struct sink {
    float *floats;
    unsigned *uints;
    int components;
    int normalized;
} sink;

static void put(const sink *s, size_t i, int c, double v, int type)
{
    if (s->floats)
        s->floats[i * (size_t)s->components + (size_t)c] =
            (float)(s->normalized ? normalize(v, type) : v);
    else
        s->uints[i] = (unsigned)v;
}

static cat_result read_values(const cat_msg *msg, const char *where, const cat_gltf_doc *doc,
                              int accessor, const sink *s)
{
    const cat_gltf_accessor *a = &doc->accessors[accessor];
    size_t csize = component_size(a->component_type);
    size_t elem = csize * (size_t)s->components;
    if (a->view >= 0) {
        const cat_gltf_view *v = &doc->views[a->view];
        const unsigned char *base = doc->buffers[v->buffer].data + v->offset + a->offset;
        size_t stride = v->stride ? v->stride : elem;
        for (size_t i = 0; i < a->count; i++)
            for (int c = 0; c < s->components; c++)
                put(s, i, c, fetch(base + i * stride + (size_t)c * csize, a->component_type),
                    a->component_type);
    } else {
        for (size_t i = 0; i < a->count; i++)
            for (int c = 0; c < s->components; c++)
                put(s, i, c, 0.0, a->component_type);
    }
    if (a->sparse) {
        const cat_gltf_view *iv = &doc->views[a->sparse_indices_view];
        const cat_gltf_view *vv = &doc->views[a->sparse_values_view];
        const unsigned char *ib =
            doc->buffers[iv->buffer].data + iv->offset + (size_t)a->sparse_indices_offset;
        const unsigned char *vb =
            doc->buffers[vv->buffer].data + vv->offset + (size_t)a->sparse_values_offset;
        size_t isize = component_size(a->sparse_indices_type);
        for (size_t j = 0; j < (size_t)a->sparse_count; j++) {
            double idx = fetch(ib + j * isize, a->sparse_indices_type);
            if (idx >= (double)a->count)
                return cat_fail(msg, CAT_ERR_INVALID,
                                "%saccessor %d: sparse index %.0f is out of range (count %zu)",
                                where, accessor, idx, a->count);
            for (int c = 0; c < s->components; c++)
                put(s, (size_t)idx, c, fetch(vb + j * elem + (size_t)c * csize, a->component_type),
                    a->component_type);
        }
    }
    return CAT_OK;
}

cat_result cat_accessor_read_floats(const cat_msg *msg, const char *where, const cat_gltf_doc *doc,
                                    int accessor, int components, float *out)
{
    cat_result r = cat_accessor_check(msg, where, doc, accessor, components);
    if (r != CAT_OK)
        return r;
    const cat_gltf_accessor *a = &doc->accessors[accessor];
    sink s = {out, NULL, components, a->normalized && a->component_type != CAT_GLTF_FLOAT};
    return read_values(msg, where, doc, accessor, &s);
}

cat_result cat_accessor_read_indices(const cat_msg *msg, const char *where, const cat_gltf_doc *doc,
                                     int accessor, unsigned *out)
{
    cat_result r = cat_accessor_check(msg, where, doc, accessor, 1);
    if (r != CAT_OK)
        return r;
    const cat_gltf_accessor *a = &doc->accessors[accessor];
    if (a->component_type != CAT_GLTF_UNSIGNED_BYTE &&
        a->component_type != CAT_GLTF_UNSIGNED_SHORT && a->component_type != CAT_GLTF_UNSIGNED_INT)
        return cat_fail(msg, CAT_ERR_INVALID,
                        "%sindex accessor %d has component type %d, expected an unsigned integer "
                        "type",
                        where, accessor, a->component_type);
    sink s = {NULL, out, 1, 0};
    return read_values(msg, where, doc, accessor, &s);
}
