/* Writes one texture per tile of the catalog into ASSETS/textures/tiles/ (committed; rerun after
 * a change to the tiles):
 *   build/app/make_tile_textures assets
 * The tiles are read from the shipped catalog (the CSV files in ASSETS/catalog, through a temporary
 * catalog file), so the names are exactly the `texture` column's. Each image is the tile's
 * nominal cell: the tile as made (work size) with half a grout joint on every side, in the
 * tile's real aspect ratio, so a wall of them repeats seamlessly at the joints. The colour is
 * the variant's diffuse colour (linear in the catalog, sRGB in the PNG), so the texture's mean
 * is the glaze's colour; the pattern comes from the series (stone, concrete, marble veins, oak
 * grain, encaustic motifs, hand-made glaze), the structure from the surface column: glossy
 * glazes vary slowly and little, matt ones carry a fine grain, structured ones a relief lit
 * from the top left. Every tile gets its own seed (its article number), so no two are alike. */
#define _XOPEN_SOURCE 700 /* mkdtemp */
#include "catalog/catalog.h"
#include "render/image_io.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define PI 3.14159265358979323846f

/* ---- noise: tileable value noise (as app/tools/make_textures.c) ---------------------------- */

static unsigned hash(unsigned x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

static float lattice(int x, int y, int px, int py, unsigned seed)
{
    x = ((x % px) + px) % px;
    y = ((y % py) + py) % py;
    return (float)(hash((unsigned)x * 73856093U ^ (unsigned)y * 19349663U ^ seed) & 0xffff) /
           65535.0f;
}

/* u, v in [0, 1) over the image; cells per side; wraps with the image. */
/* Detail finer than three pixels would only add per-pixel noise (aliasing, and bytes that PNG
 * cannot compress): cells are capped at a third of the image's pixels per side. */
static int g_max_cells_x = 1 << 20, g_max_cells_y = 1 << 20;

static float noise(float u, float v, int cx, int cy, unsigned seed)
{
    cx = cx < 1 ? 1 : cx > g_max_cells_x ? g_max_cells_x : cx;
    cy = cy < 1 ? 1 : cy > g_max_cells_y ? g_max_cells_y : cy;
    float x = u * (float)cx, y = v * (float)cy;
    int x0 = (int)floorf(x), y0 = (int)floorf(y);
    float fx = x - (float)x0, fy = y - (float)y0;
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    float a = lattice(x0, y0, cx, cy, seed), b = lattice(x0 + 1, y0, cx, cy, seed);
    float c = lattice(x0, y0 + 1, cx, cy, seed), d = lattice(x0 + 1, y0 + 1, cx, cy, seed);
    float top = a + (b - a) * fx, bottom = c + (d - c) * fx;
    return top + (bottom - top) * fy;
}

/* Fractal sum of octaves with cells of `cell_mm` and smaller, 0..1 around 0.5. */
static float fbm(float u, float v, float w_mm, float h_mm, float cell_mm, int octaves, unsigned s)
{
    float sum = 0, amp = 0.5f, norm = 0;
    for (int o = 0; o < octaves; o++) {
        int cx = (int)lroundf(w_mm / cell_mm), cy = (int)lroundf(h_mm / cell_mm);
        sum += amp * noise(u, v, cx, cy, s + 101u * (unsigned)o);
        norm += amp;
        amp *= 0.5f;
        cell_mm *= 0.5f;
    }
    return sum / norm;
}

/* ---- colours ------------------------------------------------------------------------------ */

static float to_srgb(float c)
{
    c = fminf(fmaxf(c, 0.0f), 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * powf(c, 1.0f / 2.4f) - 0.055f;
}

static void mix3(float *out, const float *a, const float *b, float t)
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] + (b[k] - a[k]) * t;
}

/* ---- the patterns ------------------------------------------------------------------------- */

typedef enum pattern {
    PLAIN,      /* an even glaze: wall tiles */
    STONE,      /* limestone: clouds, speckles, faint layers */
    MOSAIC,     /* 50 x 50 mm chips on the net */
    CONCRETE,   /* clouds and pores */
    MARBLE,     /* white with grey veins */
    GOLD_VEINS, /* marble decor: gold veins */
    OAK,        /* planks: grain along the long side */
    BORDER,     /* a raised rim and a groove */
    LEAVES,     /* printed decor: leaves */
    LINES,      /* printed decor: lines */
    WAVES,      /* printed decor: waves */
    GLASS,      /* glass insert */
    ZELLIGE,    /* hand glazed: strong variation, pooled glaze */
    STAR,       /* encaustic: an eight-pointed star */
    FLOWER,     /* encaustic: a rosette */
    GEOMETRIC,  /* encaustic: quarter circles and diamonds */
    CEMENT,     /* encaustic plain: fine speckles */
    CLAY,       /* terracotta: warm clouds, sand, dark spots */
} pattern;

static pattern pattern_of(const cat_product *p)
{
    const char *s = p->series, *v = p->variant_count ? p->variants[0].name : "";
    if (!strncmp(s, "Pietra Mosaico", 14))
        return MOSAIC;
    if (!strncmp(s, "Pietra", 6))
        return STONE;
    if (!strcmp(s, "Cemento"))
        return CONCRETE;
    if (!strcmp(s, "Calacatta Decoro"))
        return GOLD_VEINS;
    if (!strcmp(s, "Calacatta"))
        return MARBLE;
    if (!strcmp(s, "Rovere"))
        return OAK;
    if (!strcmp(s, "Bordure") || p->tile.type == CAT_TILE_BOR)
        return BORDER;
    if (!strcmp(s, "Dekor"))
        return strstr(v, "Blatt") ? LEAVES : strstr(v, "Welle") ? WAVES : LINES;
    if (!strcmp(s, "Einleger"))
        return GLASS;
    if (!strcmp(s, "Zellige"))
        return ZELLIGE;
    if (!strcmp(s, "Hidraulico"))
        return strstr(v, "Estrella") ? STAR
               : strstr(v, "Flor")   ? FLOWER
               : strstr(v, "Geom")   ? GEOMETRIC
                                     : CEMENT;
    if (!strncmp(s, "Terracota", 9))
        return CLAY;
    return PLAIN;
}

typedef struct tile_job {
    const cat_product *p;
    pattern pat;
    float w_mm, h_mm, grout_mm; /* nominal cell and joint */
    float base[3], grout[3];    /* sRGB */
    unsigned seed;
    int width, height; /* pixels */
} tile_job;

/* Height of the relief (structured surfaces, hand-made tiles), 0..1. */
static float relief(const tile_job *j, float u, float v)
{
    switch (j->pat) {
    case OAK:
        return 0.6f * fbm(u, v, j->w_mm * 8, j->h_mm * 0.25f, 6, 3, j->seed + 7) +
               0.4f * noise(u, v, 4, 4, j->seed);
    case ZELLIGE:
    case CLAY:
        return fbm(u, v, j->w_mm, j->h_mm, 25, 3, j->seed + 11);
    default:
        return fbm(u, v, j->w_mm, j->h_mm, 10, 2, j->seed + 13);
    }
}

/* Distance (mm) from (x, y) to the nearest point of an n-pointed star around (cx, cy). */
static float star_dist(float x, float y, float cx, float cy, float r_out, float r_in, int n)
{
    float dx = x - cx, dy = y - cy, r = sqrtf(dx * dx + dy * dy), a = atan2f(dy, dx);
    float seg = 2 * PI / (float)n, t = fabsf(fmodf(a + 2 * PI, seg) / seg - 0.5f) * 2; /* 0..1 */
    float edge = r_in + (r_out - r_in) * t;
    return r - edge;
}

/* The glaze's colour at (x, y) mm inside the work area (sRGB). */
static void glaze(const tile_job *j, float u, float v, float x, float y, float out[3])
{
    const float *b = j->base;
    float w = j->w_mm, h = j->h_mm;
    float shade = 1, tint[3] = {b[0], b[1], b[2]};
    float white[3] = {0.95f, 0.94f, 0.91f}, dark[3];
    for (int k = 0; k < 3; k++)
        dark[k] = b[k] * 0.45f;
    switch (j->pat) {
    case PLAIN:
        shade = 1 + 0.05f * (fbm(u, v, w, h, 120, 2, j->seed) - 0.5f);
        break;
    case STONE: {
        float c = fbm(u, v, w, h, 90, 4, j->seed);
        float layers = sinf(y * 0.05f + 6 * fbm(u, v, w, h, 200, 2, j->seed + 3));
        float speck = noise(u, v, (int)(w / 1.2f), (int)(h / 1.2f), j->seed + 5);
        shade = 1 + 0.22f * (c - 0.5f) + 0.03f * layers + (speck > 0.93f ? -0.12f : 0);
        break;
    }
    case MOSAIC: {
        float cell = 50, joint = 2;
        float cx = fmodf(x, cell), cy = fmodf(y, cell);
        if (cx < joint / 2 || cx > cell - joint / 2 || cy < joint / 2 || cy > cell - joint / 2) {
            memcpy(out, j->grout, sizeof j->grout);
            return;
        }
        unsigned chip = (unsigned)(x / cell) * 31u + (unsigned)(y / cell) * 17u;
        float chip_shade = (float)(hash(chip ^ j->seed) & 0xff) / 255.0f;
        shade = 0.85f + 0.3f * chip_shade + 0.15f * (fbm(u, v, w, h, 20, 3, j->seed) - 0.5f);
        break;
    }
    case CONCRETE: {
        float c = fbm(u, v, w, h, 160, 5, j->seed);
        float pore = noise(u, v, (int)(w / 1.5f), (int)(h / 1.5f), j->seed + 9);
        shade = 1 + 0.28f * (c - 0.5f) + (pore > 0.95f ? -0.25f * (pore - 0.95f) / 0.05f : 0);
        break;
    }
    case MARBLE:
    case GOLD_VEINS: {
        float warp = 4.5f * fbm(u, v, w, h, 150, 4, j->seed);
        float vein = fabsf(sinf((x * 0.6f + y) / 90.0f + warp));
        float fine = fabsf(sinf((x - 0.4f * y) / 35.0f + 3 * warp));
        float strong = powf(1 - vein, 18), weak = powf(1 - fine, 30) * 0.5f;
        float gold[3] = {0.80f, 0.63f, 0.30f}, grey[3] = {0.45f, 0.45f, 0.47f};
        const float *vc = j->pat == GOLD_VEINS ? gold : grey;
        mix3(tint, b, vc, fminf(1, strong + weak));
        shade = 1 + 0.04f * (fbm(u, v, w, h, 60, 3, j->seed + 2) - 0.5f);
        break;
    }
    case OAK: {
        /* grain runs along the long side; growth rings bent by slow noise, pores as streaks */
        int along_x = w > h;
        float a = along_x ? y : x, l = along_x ? x : y;
        float bend = 70 * fbm(u, v, w, h, 250, 3, j->seed);
        float ring = 0.5f + 0.5f * sinf((a + bend) * 0.3f + 4 * sinf(l * 0.003f + a * 0.02f));
        float streak = noise(along_x ? u * 4 : u, along_x ? v : v * 4,
                             along_x ? (int)(w / 40) : (int)(w / 0.8f),
                             along_x ? (int)(h / 0.8f) : (int)(h / 40), j->seed + 4);
        float plank = (float)(hash(j->seed) & 0xff) / 255.0f;
        shade = 0.95f + 0.1f * plank - 0.35f * powf(ring, 3.0f) + 0.12f * (streak - 0.5f);
        float knot = star_dist(x, y, w * 0.3f, h * 0.65f, 9, 9, 4);
        if (knot < 0)
            shade *= 0.7f + 0.3f * (-knot / 9 < 1 ? 1 + knot / 9 : 0);
        break;
    }
    case BORDER: {
        /* a rounded rim (lighter) along both long edges, a groove in the middle */
        float across = w < h ? x / w : y / h;
        float rim =
            expf(-powf((across - 0.18f) / 0.07f, 2)) + expf(-powf((across - 0.82f) / 0.07f, 2));
        float groove = expf(-powf((across - 0.5f) / 0.04f, 2));
        shade = 1 + 0.25f * rim - 0.3f * groove + 0.05f * (fbm(u, v, w, h, 40, 2, j->seed) - 0.5f);
        break;
    }
    case LEAVES: {
        float leaf = 0;
        for (int i = 0; i < 9; i++) {
            unsigned r = hash(j->seed + 977u * (unsigned)i);
            float cx = w * (float)(r & 0xff) / 255, cy = h * (float)((r >> 8) & 0xff) / 255;
            float ang = PI * (float)((r >> 16) & 0xff) / 255, len = 40 + (float)(r >> 24) / 8;
            float dx = x - cx, dy = y - cy;
            float s = dx * cosf(ang) + dy * sinf(ang), t = -dx * sinf(ang) + dy * cosf(ang);
            float half = len * 0.28f * sqrtf(fmaxf(0, 1 - (s / len) * (s / len)));
            if (fabsf(s) < len && fabsf(t) < half)
                leaf = fmaxf(leaf, fabsf(t) < 0.8f ? 0.6f : 1.0f); /* the midrib lighter */
        }
        float green[3] = {0.36f, 0.50f, 0.34f};
        mix3(tint, white, green, leaf * 0.85f);
        shade = 1 + 0.03f * (fbm(u, v, w, h, 80, 2, j->seed) - 0.5f);
        break;
    }
    case LINES: {
        float pos = fmodf(y, 40);
        float line = pos < 1.5f ? 1 : (pos > 6 && pos < 7 ? 0.6f : 0);
        float grey[3] = {0.42f, 0.42f, 0.44f};
        mix3(tint, b, grey, line);
        break;
    }
    case WAVES: {
        float wave = y + 12 * sinf(x / 30.0f * 2 * PI / 3);
        float band = fmodf(wave + 1000, 45);
        float blue[3] = {0.25f, 0.42f, 0.60f};
        mix3(tint, white, blue, band < 8 ? 1 : band < 11 ? 0.4f : 0);
        break;
    }
    case GLASS: {
        float streak = powf(fabsf(sinf((x + y) / 18.0f)), 8);
        shade = 0.85f + 0.25f * (y / h) + 0.15f * streak;
        break;
    }
    case ZELLIGE: {
        float c = fbm(u, v, w, h, 30, 4, j->seed);
        float pool = powf(fbm(u, v, w, h, 15, 2, j->seed + 21), 3);
        float pit = noise(u, v, (int)(w / 2), (int)(h / 2), j->seed + 23);
        float tile_shift = 0.85f + 0.3f * (float)(hash(j->seed * 7u) & 0xff) / 255.0f;
        shade = tile_shift * (1 + 0.4f * (c - 0.5f)) * (1 - 0.35f * pool) *
                (pit > 0.97f ? 1.25f : 1.0f);
        break;
    }
    case STAR:
    case FLOWER:
    case GEOMETRIC: {
        float cx = w / 2, cy = h / 2;
        float d, ink = 0, second = 0;
        if (j->pat == STAR) {
            d = star_dist(x, y, cx, cy, 0.42f * w, 0.2f * w, 8);
            ink = d < 0 ? 1 : 0;
            second = star_dist(x, y, cx, cy, 0.16f * w, 0.08f * w, 8) < 0 ? 1 : 0;
        } else if (j->pat == FLOWER) {
            float dx = x - cx, dy = y - cy, r = sqrtf(dx * dx + dy * dy), a = atan2f(dy, dx);
            float petal = 0.3f * w * (0.55f + 0.45f * fabsf(cosf(3 * a)));
            ink = r < petal ? 1 : 0;
            second = r < 0.07f * w ? 1 : 0;
            /* leaves in the corners */
            float cr = fminf(fminf(hypotf(x, y), hypotf(w - x, y)),
                             fminf(hypotf(x, h - y), hypotf(w - x, h - y)));
            if (cr < 0.22f * w && cr > 0.16f * w)
                second = 1;
        } else {
            float qx = fabsf(x - cx) / w, qy = fabsf(y - cy) / h;
            ink = qx + qy < 0.32f ? 1 : 0;
            second = fabsf(qx + qy - 0.42f) < 0.03f ? 1 : 0;
            float cr = fminf(fminf(hypotf(x, y), hypotf(w - x, y)),
                             fminf(hypotf(x, h - y), hypotf(w - x, h - y)));
            if (cr < 0.25f * w)
                ink = 1;
        }
        mix3(tint, white, b, ink);
        if (second)
            memcpy(tint, dark, sizeof dark);
        /* encaustic pigment is a little uneven */
        shade = 1 + 0.08f * (fbm(u, v, w, h, 25, 3, j->seed) - 0.5f);
        break;
    }
    case CEMENT: {
        float speck = noise(u, v, (int)(w / 1.0f), (int)(h / 1.0f), j->seed + 31);
        shade = 1 + 0.08f * (fbm(u, v, w, h, 50, 3, j->seed) - 0.5f) +
                (speck > 0.9f    ? 0.06f
                 : speck < 0.08f ? -0.06f
                                 : 0);
        break;
    }
    case CLAY: {
        float c = fbm(u, v, w, h, 60, 4, j->seed);
        float sand = noise(u, v, (int)(w / 2.0f), (int)(h / 2.0f), j->seed + 41);
        float spot = fbm(u, v, w, h, 12, 2, j->seed + 43);
        shade = 1 + 0.3f * (c - 0.5f) + 0.08f * (sand - 0.5f) + (spot > 0.72f ? -0.18f : 0);
        break;
    }
    }
    /* The surface: matt glazes carry a fine grain; glossy ones stay smooth. */
    if (j->p->tile.surface == CAT_SURFACE_MATT)
        shade += 0.035f * (noise(u, v, (int)(w / 0.7f), (int)(h / 0.7f), j->seed + 51) - 0.5f);
    for (int k = 0; k < 3; k++)
        out[k] = tint[k] * shade;
}

static int structured(const tile_job *j)
{
    return j->p->tile.surface == CAT_SURFACE_STRUCTURED || j->pat == ZELLIGE || j->pat == CLAY;
}

/* One pixel: grout, the tile's edge bevel, the glaze and, where structured, the relief. */
static void pixel(const tile_job *j, int px, int py, unsigned char *out)
{
    float u = ((float)px + 0.5f) / (float)j->width, v = ((float)py + 0.5f) / (float)j->height;
    float x = u * j->w_mm, y = v * j->h_mm, g = 0.5f * j->grout_mm;
    float edge = fminf(fminf(x, j->w_mm - x), fminf(y, j->h_mm - y));
    float c[3];
    if (edge < g) {
        float n = noise(u, v, (int)(j->w_mm / 1.5f), (int)(j->h_mm / 1.5f), j->seed + 61);
        for (int k = 0; k < 3; k++)
            c[k] = j->grout[k] * (0.94f + 0.12f * n);
    } else {
        glaze(j, u, v, x - g, y - g, c);
        float lit = 1;
        if (structured(j)) { /* light from the top left: the slope along (-1, -1) */
            float du = 1.0f / (float)j->width, dv = 1.0f / (float)j->height;
            float hx = relief(j, u + du, v) - relief(j, u - du, v);
            float hy = relief(j, u, v + dv) - relief(j, u, v - dv);
            float scale = j->pat == OAK       ? 0.15f
                          : j->pat == ZELLIGE ? 1.5f
                          : j->pat == CLAY    ? 2.5f
                                              : 1.0f;
            lit = 1 - scale * (hx + hy);
        }
        /* a soft bevel: the glaze rounds off over the last 1.5 mm before the joint (Metro: 4) */
        float bevel_mm = strstr(j->p->series, "Metro") ? 4.0f : 1.5f;
        float bevel = fminf((edge - g) / bevel_mm, 1.0f);
        /* the lit side of the bevel (top, left) brighter, the other darker */
        float side = (x < j->w_mm - x ? 1.0f : -1.0f) * (x < y ? 1.0f : 0.5f);
        lit *= 0.88f + 0.12f * bevel + (1 - bevel) * 0.05f * side;
        for (int k = 0; k < 3; k++)
            c[k] *= lit;
    }
    for (int k = 0; k < 3; k++)
        out[k] = (unsigned char)(fminf(fmaxf(c[k], 0.0f), 1.0f) * 255.0f + 0.5f);
    out[3] = 255;
}

/* Pixel size: the long side 288 px (432 for strips of aspect 3 and more), the short side in
 * proportion: enough for a thumbnail or a wall seen from across the room, and 71 of them stay
 * under 3 MB. */
static void pixel_size(float w_mm, float h_mm, int *w, int *h)
{
    float lng = fmaxf(w_mm, h_mm), shrt = fminf(w_mm, h_mm);
    int long_px = lng / shrt >= 3 ? 432 : 288;
    int short_px = (int)lroundf((float)long_px * shrt / lng);
    *w = w_mm >= h_mm ? long_px : short_px;
    *h = w_mm >= h_mm ? short_px : long_px;
}

static int write_texture(const char *assets, const cat_product *p, long *bytes)
{
    tile_job j;
    memset(&j, 0, sizeof j);
    j.p = p;
    j.pat = pattern_of(p);
    j.w_mm = (float)p->tile.nominal_w_mm;
    j.h_mm = (float)p->tile.nominal_h_mm;
    j.grout_mm = (float)p->tile.grout_mm;
    const float *d = p->variant_count ? p->variants[0].material.diffuse : NULL;
    float lum = 0;
    for (int k = 0; k < 3; k++) {
        j.base[k] = to_srgb(d ? d[k] : 0.8f);
        lum += j.base[k] / 3;
    }
    /* grout: light grey, dark grey for dark tiles */
    for (int k = 0; k < 3; k++)
        j.grout[k] = lum < 0.45f ? 0.30f : 0.80f - 0.01f * (float)k;
    unsigned s = 2166136261u;
    for (const char *c = p->article; *c; c++)
        s = (s ^ (unsigned char)*c) * 16777619u;
    j.seed = s;
    pixel_size(j.w_mm, j.h_mm, &j.width, &j.height);
    g_max_cells_x = j.width / 3;
    g_max_cells_y = j.height / 3;
    unsigned char *px = malloc((size_t)j.width * (size_t)j.height * 4);
    if (!px) {
        fprintf(stderr, "make_tile_textures: out of memory\n");
        return 1;
    }
    for (int y = 0; y < j.height; y++)
        for (int x = 0; x < j.width; x++)
            pixel(&j, x, y, px + ((size_t)y * (size_t)j.width + (size_t)x) * 4);
    char path[1024], err[1024];
    snprintf(path, sizeof path, "%s/%s", assets, p->tile.texture);
    rd_image_result r = rd_image_write_rgba8(path, j.width, j.height, px, err, sizeof err);
    free(px);
    if (r != RD_IMAGE_OK) {
        fprintf(stderr, "make_tile_textures: %s\n", err);
        return 1;
    }
    struct stat st;
    if (stat(path, &st) == 0)
        *bytes += (long)st.st_size;
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: make_tile_textures ASSETS_FOLDER   (e.g. assets)\n");
        return 2;
    }
    char tmp[] = "/tmp/tessera-tile-textures-XXXXXX", db_path[256], src[4096], dir[4200], err[2048];
    if (!mkdtemp(tmp)) {
        fprintf(stderr, "make_tile_textures: cannot make a temporary folder: %s\n",
                strerror(errno));
        return 1;
    }
    snprintf(db_path, sizeof db_path, "%s/catalog.sqlite", tmp);
    snprintf(src, sizeof src, "%s/catalog", argv[1]);
    snprintf(dir, sizeof dir, "%s/textures/tiles", argv[1]);
    char parent[4200];
    snprintf(parent, sizeof parent, "%s/textures", argv[1]);
    mkdir(parent, 0755); /* existing folders are fine; a failure shows on the first write */
    mkdir(dir, 0755);
    cat_db *db = NULL;
    int failures = 0, count = 0;
    long bytes = 0;
    if (cat_catalog_open(db_path, src, &db, err, sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "make_tile_textures: %s\n", err);
        failures = 1;
    }
    static cat_search_hit hits[10000];
    int n = 0;
    cat_search_filter filter = {CAT_CATEGORY_TILES, 0, NULL};
    if (db && cat_search(db, "", &filter, 10000, hits, &n, err, sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "make_tile_textures: %s\n", err);
        failures = 1;
    }
    for (int i = 0; i < n; i++) {
        cat_product p;
        if (cat_product_get(db, hits[i].product_id, &p, err, sizeof err) != CAT_DB_OK) {
            fprintf(stderr, "make_tile_textures: %s\n", err);
            failures++;
            continue;
        }
        if (p.has_tile && p.tile.texture[0]) {
            failures += write_texture(argv[1], &p, &bytes);
            count++;
        }
        cat_product_free(&p);
    }
    cat_db_close(db);
    const char *const suffixes[] = {"", "-wal", "-shm", "-journal"};
    for (int i = 0; i < 4; i++) {
        char f[300];
        snprintf(f, sizeof f, "%s%s", db_path, suffixes[i]);
        unlink(f);
    }
    rmdir(tmp);
    printf("make_tile_textures: %d textures, %.2f MB in %s\n", count, (double)bytes / 1e6, dir);
    return failures ? 1 : 0;
}
