/* Writes the demo's tile textures into assets/textures/ (committed; rerun after a change):
 *   build/app/make_textures assets/textures
 * Each image is one tile with half a grout joint on every side, so it repeats seamlessly;
 * the glaze varies slowly so that a wall of them does not look like a flat colour. */
#include "render/image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct tile_style {
    const char *name;
    int width_px, height_px;
    float tile_mm_w, tile_mm_h, grout_mm;
    float glaze[3], grout[3]; /* sRGB display values */
    float variation;          /* amplitude of the glaze's mottling */
    float veins;              /* 0: plain glaze; > 0: stone-like veining */
} tile_style;

static unsigned hash(unsigned x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

static float lattice(int x, int y, int period_x, int period_y, unsigned seed)
{
    x = ((x % period_x) + period_x) % period_x;
    y = ((y % period_y) + period_y) % period_y;
    return (float)(hash((unsigned)x * 73856093U ^ (unsigned)y * 19349663U ^ seed) & 0xffff) /
           65535.0f;
}

/* Tileable value noise: the lattice wraps with the image, so the texture repeats cleanly. */
static float noise(float u, float v, int cells_x, int cells_y, unsigned seed)
{
    float x = u * (float)cells_x, y = v * (float)cells_y;
    int x0 = (int)floorf(x), y0 = (int)floorf(y);
    float fx = x - (float)x0, fy = y - (float)y0;
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    float a = lattice(x0, y0, cells_x, cells_y, seed),
          b = lattice(x0 + 1, y0, cells_x, cells_y, seed);
    float c = lattice(x0, y0 + 1, cells_x, cells_y, seed),
          d = lattice(x0 + 1, y0 + 1, cells_x, cells_y, seed);
    return (a + (b - a) * fx) + ((c + (d - c) * fx) - (a + (b - a) * fx)) * fy;
}

static int write_tile(const char *dir, const tile_style *s)
{
    int w = s->width_px, h = s->height_px;
    unsigned char *px = malloc((size_t)w * (size_t)h * 4);
    if (!px)
        return 1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float u = ((float)x + 0.5f) / (float)w, v = ((float)y + 0.5f) / (float)h;
            float mx = u * s->tile_mm_w, my = v * s->tile_mm_h;
            float edge = fminf(fminf(mx, s->tile_mm_w - mx), fminf(my, s->tile_mm_h - my));
            float n = 0.6f * noise(u, v, 4, 4 * h / w, 1) + 0.4f * noise(u, v, 16, 16 * h / w, 2);
            float shade = 1.0f + s->variation * (n - 0.5f);
            if (s->veins > 0.0f) {
                float vein =
                    fabsf(sinf(6.0f * (u + 0.7f * v) + 5.0f * noise(u, v, 3, 3 * h / w, 3)));
                shade *= 1.0f - s->veins * powf(1.0f - vein, 12.0f);
            }
            /* A soft bevel: the glaze darkens a little over the last millimetre before the joint.
             */
            float bevel = fminf(fmaxf((edge - 0.5f * s->grout_mm) / 1.5f, 0.0f), 1.0f);
            float in_grout = edge < 0.5f * s->grout_mm ? 1.0f : 0.0f;
            for (int k = 0; k < 3; k++) {
                float glaze = s->glaze[k] * shade * (0.85f + 0.15f * bevel);
                float c = in_grout ? s->grout[k] * (0.95f + 0.1f * n) : glaze;
                c = fminf(fmaxf(c, 0.0f), 1.0f);
                px[((size_t)y * (size_t)w + (size_t)x) * 4 + (size_t)k] =
                    (unsigned char)(c * 255.0f + 0.5f);
            }
            px[((size_t)y * (size_t)w + (size_t)x) * 4 + 3] = 255;
        }
    char path[1024], err[512];
    snprintf(path, sizeof path, "%s/%s.png", dir, s->name);
    rd_image_result r = rd_image_write_rgba8(path, w, h, px, err, sizeof err);
    free(px);
    if (r != RD_IMAGE_OK) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    printf("wrote %s (%dx%d px for %gx%g mm)\n", path, w, h, (double)s->tile_mm_w,
           (double)s->tile_mm_h);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: make_textures OUTPUT_FOLDER\n");
        return 2;
    }
    const tile_style styles[] = {
        {"wall-tile-white-300x600",
         160,
         320,
         300,
         600,
         3,
         {0.93f, 0.93f, 0.91f},
         {0.72f, 0.72f, 0.70f},
         0.06f,
         0.0f},
        {"floor-tile-stone-600x600",
         256,
         256,
         600,
         600,
         3,
         {0.46f, 0.44f, 0.41f},
         {0.30f, 0.29f, 0.28f},
         0.25f,
         0.35f},
        {"accent-tile-teal-100x100",
         64,
         64,
         100,
         100,
         2,
         {0.16f, 0.42f, 0.45f},
         {0.80f, 0.80f, 0.78f},
         0.12f,
         0.0f},
    };
    int failures = 0;
    for (size_t i = 0; i < sizeof styles / sizeof styles[0]; i++)
        failures += write_tile(argv[1], &styles[i]);
    return failures ? 1 : 0;
}
