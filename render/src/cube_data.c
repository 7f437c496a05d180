/* Cube maps on the CPU: M_rot (seed 000 eq. 7), GL's face selection (seed 000 section 2, GL 4.5
 * section 8.13), float storage and nearest / seamless bilinear sampling. */
#include "render/cube_data.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void rd_ref_world_to_cmcs(const float w[3], float c[3])
{
    float x = w[0], y = w[1], z = w[2]; /* w and c may alias */
    c[0] = x;
    c[1] = -z;
    c[2] = y;
}

void rd_ref_cmcs_to_world(const float c[3], float w[3])
{
    float x = c[0], y = c[1], z = c[2];
    w[0] = x;
    w[1] = z;
    w[2] = -y;
}

int rd_ref_cube_face_st(const float cmcs[3], float *s, float *t)
{
    float x = cmcs[0], y = cmcs[1], z = cmcs[2];
    float ax = fabsf(x), ay = fabsf(y), az = fabsf(z);
    *s = 0.5f;
    *t = 0.5f;
    if (!isfinite(x) || !isfinite(y) || !isfinite(z) || (ax == 0.0f && ay == 0.0f && az == 0.0f))
        return -1;
    int face;
    float sc, tc, ma;
    /* Mesa's order of the comparisons: X wins ties over Y, Y over Z. */
    if (ax >= ay && ax >= az) {
        ma = ax;
        face = x >= 0.0f ? RD_CUBE_POS_X : RD_CUBE_NEG_X;
        sc = x >= 0.0f ? -z : z;
        tc = -y;
    } else if (ay >= az) {
        ma = ay;
        face = y >= 0.0f ? RD_CUBE_POS_Y : RD_CUBE_NEG_Y;
        sc = x;
        tc = y >= 0.0f ? z : -z;
    } else {
        ma = az;
        face = z >= 0.0f ? RD_CUBE_POS_Z : RD_CUBE_NEG_Z;
        sc = z >= 0.0f ? x : -x;
        tc = -y;
    }
    /* |sc|, |tc| <= ma, so the quotients are in [-1, 1] after rounding too. */
    *s = 0.5f * (sc / ma + 1.0f);
    *t = 0.5f * (tc / ma + 1.0f);
    return face;
}

void rd_ref_cube_face_direction(int face, float s, float t, float cmcs[3])
{
    float sc = 2.0f * s - 1.0f, tc = 2.0f * t - 1.0f;
    float x = 0.0f, y = 0.0f, z = 0.0f;
    /* The table of rd_ref_cube_face_st solved for (x, y, z) with |ma| = 1. */
    switch (face) {
    case RD_CUBE_POS_X:
        x = 1.0f, z = -sc, y = -tc;
        break;
    case RD_CUBE_NEG_X:
        x = -1.0f, z = sc, y = -tc;
        break;
    case RD_CUBE_POS_Y:
        y = 1.0f, x = sc, z = tc;
        break;
    case RD_CUBE_NEG_Y:
        y = -1.0f, x = sc, z = -tc;
        break;
    case RD_CUBE_POS_Z:
        z = 1.0f, x = sc, y = -tc;
        break;
    case RD_CUBE_NEG_Z:
        z = -1.0f, x = -sc, y = -tc;
        break;
    default:
        break;
    }
    cmcs[0] = x;
    cmcs[1] = y;
    cmcs[2] = z;
}

rd_result rd_cube_data_alloc(int size, rd_cube_data *out)
{
    if (out == NULL)
        return RD_ERR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    if (size < 1)
        return RD_ERR_INVALID_ARGUMENT;
    if (size > RD_CUBE_MAX_SIZE)
        return RD_ERR_TOO_LARGE;
    size_t count = (size_t)size * (size_t)size * 4;
    for (int f = 0; f < 6; f++) {
        out->faces[f] = calloc(count, sizeof(float));
        if (out->faces[f] == NULL) {
            rd_cube_data_free(out);
            return RD_ERR_OUT_OF_MEMORY;
        }
    }
    out->size = size;
    return RD_OK;
}

void rd_cube_data_free(rd_cube_data *c)
{
    if (c == NULL)
        return;
    for (int f = 0; f < 6; f++)
        free(c->faces[f]);
    memset(c, 0, sizeof *c);
}

static int cube_usable(const rd_cube_data *c)
{
    if (c == NULL || c->size < 1 || c->size > RD_CUBE_MAX_SIZE)
        return 0;
    for (int f = 0; f < 6; f++)
        if (c->faces[f] == NULL)
            return 0;
    return 1;
}

static int texel_index(float st, int size)
{
    float u = floorf(st * (float)size);
    if (!(u >= 0.0f))
        return 0;
    if (u > (float)(size - 1))
        return size - 1;
    return (int)u;
}

static const float *texel(const rd_cube_data *c, int face, int i, int j)
{
    return c->faces[face] + ((size_t)j * (size_t)c->size + (size_t)i) * 4;
}

void rd_cube_sample_nearest(const rd_cube_data *c, const float world_dir[3], float out[4])
{
    float d[3], s, t;
    memset(out, 0, 4 * sizeof(float));
    if (!cube_usable(c))
        return;
    rd_ref_world_to_cmcs(world_dir, d);
    int face = rd_ref_cube_face_st(d, &s, &t);
    if (face < 0)
        return;
    memcpy(out, texel(c, face, texel_index(s, c->size), texel_index(t, c->size)),
           4 * sizeof(float));
}

/* Texel (i, j) of `face` where i or j (not both) may be one step off the face: the tap is
 * re-projected through the direction of its centre onto the neighbouring face. That direction
 * has |sc| or |tc| = 1 + 1/size > 1 = |ma|, so the neighbour wins the face selection, and the
 * shift of the other coordinate towards the centre (by less than half a texel) keeps it in the
 * matching row or column. */
static const float *tap(const rd_cube_data *c, int face, int i, int j)
{
    int n = c->size;
    if (i >= 0 && i < n && j >= 0 && j < n)
        return texel(c, face, i, j);
    float d[3], s, t;
    rd_ref_cube_face_direction(face, ((float)i + 0.5f) / (float)n, ((float)j + 0.5f) / (float)n, d);
    int f2 = rd_ref_cube_face_st(d, &s, &t);
    if (f2 < 0)
        f2 = face; /* unreachable: d has a component of magnitude 1 */
    return texel(c, f2, texel_index(s, n), texel_index(t, n));
}

void rd_cube_sample_bilinear(const rd_cube_data *c, const float world_dir[3], float out[4])
{
    float d[3], s, t;
    memset(out, 0, 4 * sizeof(float));
    if (!cube_usable(c))
        return;
    rd_ref_world_to_cmcs(world_dir, d);
    int face = rd_ref_cube_face_st(d, &s, &t);
    if (face < 0)
        return;
    int n = c->size;
    /* GL_LINEAR: u = s size - 1/2, taps floor(u) and floor(u) + 1; u is in [-1/2, n - 1/2], so
     * a tap is at most one texel off the face. */
    float u = s * (float)n - 0.5f, v = t * (float)n - 0.5f;
    float fu = floorf(u), fv = floorf(v);
    int i0 = (int)fu, j0 = (int)fv;
    float a = u - fu, b = v - fv;
    int ii[4] = {i0, i0 + 1, i0, i0 + 1};
    int jj[4] = {j0, j0, j0 + 1, j0 + 1};
    float w[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
    const float *p[4];
    int corner = -1;
    for (int k = 0; k < 4; k++) {
        int off_i = ii[k] < 0 || ii[k] >= n, off_j = jj[k] < 0 || jj[k] >= n;
        if (off_i && off_j) {
            corner = k;
            p[k] = NULL;
        } else {
            p[k] = tap(c, face, ii[k], jj[k]);
        }
    }
    float corner_value[4];
    if (corner >= 0) {
        /* ARB_seamless_cube_map: the missing corner texel is the mean of the three others. */
        for (int ch = 0; ch < 4; ch++) {
            float sum = 0.0f;
            for (int k = 0; k < 4; k++)
                if (k != corner)
                    sum += p[k][ch];
            corner_value[ch] = sum / 3.0f;
        }
        p[corner] = corner_value;
    }
    for (int ch = 0; ch < 4; ch++)
        out[ch] = w[0] * p[0][ch] + w[1] * p[1][ch] + w[2] * p[2][ch] + w[3] * p[3][ch];
}
