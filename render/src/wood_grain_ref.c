/* CPU twin of shaders/wood.glsl: a procedural wood grain as a scale on the albedo. Both sides
 * use the same integer hash (exact in GLSL 3.30's 32-bit uint arithmetic) and the same float
 * steps, so they agree to rounding. docs/rendering.md "Wood grain" gives the model. */
#include "render/shade_ref.h"

#include <math.h>
#include <stdint.h>

/* A lattice value in [-1, 1) from a 32-bit integer hash of the cell (an xor of the coordinates
 * times large odd constants, then the "lowbias32" finaliser of Chris Wellons' hash-prospector,
 * which GLSL computes bit for bit). */
static float lattice(int x, int y, int z)
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u ^ (uint32_t)z * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return (float)(h >> 8) * (2.0f / 16777216.0f) - 1.0f;
}

static float lerp(float a, float b, float t) /* GLSL mix */
{
    return a + (b - a) * t;
}

/* Trilinear value noise with a smoothstep fade, in [-1, 1], mean 0. */
static float value_noise(float x, float y, float z)
{
    float fx = floorf(x), fy = floorf(y), fz = floorf(z);
    int ix = (int)fx, iy = (int)fy, iz = (int)fz;
    float tx = x - fx, ty = y - fy, tz = z - fz;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    tz = tz * tz * (3.0f - 2.0f * tz);
    float c[2][2];
    for (int j = 0; j < 2; j++)
        for (int k = 0; k < 2; k++)
            c[j][k] = lerp(lattice(ix, iy + j, iz + k), lattice(ix + 1, iy + j, iz + k), tx);
    return lerp(lerp(c[0][0], c[1][0], ty), lerp(c[0][1], c[1][1], ty), tz);
}

static float clamp01(float v)
{
    return fminf(fmaxf(v, 0.0f), 1.0f);
}

void rd_ref_wood_grain_dir(float angle_deg, float dir[2])
{
    double a = isfinite(angle_deg) ? (double)angle_deg * (3.14159265358979323846 / 180.0) : 0.0;
    /* Exact at the two named directions: at 0 degrees the point stays as it is, bit for bit. */
    dir[0] = angle_deg == 90.0f ? 0.0f : (float)cos(a);
    dir[1] = angle_deg == 0.0f ? 0.0f : angle_deg == 90.0f ? 1.0f : (float)sin(a);
}

void rd_ref_wood_grain_point(const float p[3], const float dir[2], float q[3])
{
    /* A rotation by -angle about y takes the direction (cos, 0, sin) to (1, 0, 0). */
    float x = dir[0] * p[0] + dir[1] * p[2], z = -dir[1] * p[0] + dir[0] * p[2];
    q[0] = x;
    q[1] = p[1];
    q[2] = z;
}

float rd_ref_wood_grain(const float p[3], float footprint)
{
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
        return 1.0f;
    /* Growth rings: cylinders around a log axis parallel to x, off to the side of the board so
     * a face cut along it shows long, gently curved bands; their radius wobbles with a
     * low-frequency noise (stretched along the axis), so the bands meander as real ones do. */
    float dy = p[1] - RD_WOOD_AXIS_Y, dz = p[2] - RD_WOOD_AXIS_Z;
    float wobble = RD_WOOD_WOBBLE * value_noise(p[0] * 2.0f, p[1] * 7.0f, p[2] * 7.0f) +
                   0.3f * RD_WOOD_WOBBLE * value_noise(p[0] * 5.0f, p[1] * 23.0f, p[2] * 23.0f);
    float r = sqrtf(dy * dy + dz * dz) + wobble;
    float f = r / RD_WOOD_RING_SPACING;
    f = f - floorf(f);
    /* The late wood, darker, at the ring's outer end: f^4 has mean 1/5 over a ring. */
    float late = f * f * f * f - 0.2f;
    /* Bands: runs of lighter and darker years, noise over the ring radius (1.7 cm cells), so
     * they follow the rings' arcs and carry the grain where a pixel spans a ring or more. */
    float bands = value_noise(p[0] * 1.5f, r * 60.0f, 0.5f);
    /* Pores and streaks: noise fine across the grain and long along it. */
    float pores = value_noise(p[0] * 12.0f, p[1] * 900.0f, p[2] * 900.0f);
    /* Figure: broad, slow changes of tone between boards' regions. */
    float figure = value_noise(p[0] * 3.0f, p[1] * 11.0f, p[2] * 11.0f);
    /* Fade what a pixel cannot resolve to its mean (0), so the grain never aliases into noise:
     * the rings from a footprint of a quarter ring to half a ring (their Nyquist limit), the
     * pores likewise from 0.56 mm to 1.1 mm (a cell of their noise). */
    float fade_rings = clamp01(2.0f - 4.0f * footprint / RD_WOOD_RING_SPACING);
    float fade_pores = clamp01(2.0f - footprint * 1800.0f);
    float fade_bands = clamp01(2.0f - footprint * 240.0f);
    return 1.0f - RD_WOOD_RING_CONTRAST * fade_rings * late +
           RD_WOOD_BAND_CONTRAST * fade_bands * bands + RD_WOOD_PORE_CONTRAST * fade_pores * pores +
           RD_WOOD_FIGURE_CONTRAST * figure;
}
