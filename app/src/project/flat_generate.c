/* The synthetic flat (app/project/flat_generate.h): rectangular rooms in two rows, each with a
 * door and a window, its kind's tiles and fixtures placed against the walls, a grid of recessed
 * downlights, a row of hooks, one light and one camera. Every product is a shipped catalog
 * product (assets/catalog), with the placements of the designed bathroom
 * (assets/projects/designed-bathroom.json): a product's origin is the middle of its back at the
 * wall, rotation 0 faces +y. */
#include "project_internal.h"

#include "app/project/flat.h"
#include "app/project/flat_generate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct gen_product {
    const char *manufacturer, *article, *variant;
} gen_product;

static const gen_product BATH = {"Nordkeram", "NK-51258.00", "WH"};
static const gen_product BATH_MIXER = {"Aquavera", "31011000", "CP"};
static const gen_product TRAY = {"Nordkeram", "NK-51296.00", "WH"};
static const gen_product SHOWER = {"Aquavera", "31060000", "CP"};
static const gen_product BASKET = {"Aquavera", "31109000", "CP"};
static const gen_product WC = {"Cerana", "CE415701", "WH"};
static const gen_product ROLL = {"Aquavera", "31078000", "CP"};
static const gen_product BRUSH = {"Aquavera", "31106000", "CP"};
static const gen_product VANITY = {"Cerana", "CE419501", "OK"};
static const gen_product BASIN = {"Cerana", "CE410401", "WH"};
static const gen_product BASIN_MIXER = {"Aquavera", "31003000", "CP"};
static const gen_product MIRROR = {"Vitrelux", "VX20051", "MI"};
static const gen_product MIRROR_LAMP = {"Lumetta", "LU-313.10", "WW"};
static const gen_product RADIATOR = {"Calorix", "CX7107-0", "CP"};
static const gen_product CEILING_LAMP = {"Lumetta", "LU-322.10", "WW"};
static const gen_product DOWNLIGHT = {"Lumetta", "LU-342.10", "WW"};
static const gen_product HOOK = {"Aquavera", "31089000", "CP"};

/* Wall and floor tiles: small formats (100 x 100, 75 x 150), as bathrooms and kitchens have
 * them, walls tiled to the ceiling. */
static const gen_product WALL_TILES[] = {{"Azulejos Solara", "SOL3100", "GL"},
                                         {"Fliesenwerk Altena", "FA-10100", "GL"},
                                         {"Fliesenwerk Altena", "FA-10125", "GL"},
                                         {"Azulejos Solara", "SOL3104", "GL"}};
static const gen_product FLOOR_TILES[] = {{"Azulejos Solara", "SOL3106", "GL"},
                                          {"Azulejos Solara", "SOL3103", "GL"},
                                          {"Fliesenwerk Altena", "FA-10100", "GL"},
                                          {"Azulejos Solara", "SOL3100", "GL"}};

typedef enum room_kind {
    KIND_BATHROOM,
    KIND_KITCHEN,
    KIND_WC,
    KIND_HALL,
    KIND_SHOWER,
    KIND_UTILITY,
    KIND_ENSUITE,
    KIND_GUEST_WC,
    KIND_COUNT
} room_kind;

static const char *const KIND_NAMES[KIND_COUNT] = {
    "Bathroom", "Kitchen", "WC", "Hall", "Shower room", "Utility", "En-suite", "Guest WC"};
/* Width, depth (mm) before the seed's variation; the wall tiling's top (0 = full height). */
static const double KIND_SIZE[KIND_COUNT][3] = {{3600, 4000, 0}, {4200, 4600, 0}, {2500, 2400, 0},
                                                {2200, 6400, 0}, {2800, 3600, 0}, {3000, 3800, 0},
                                                {3300, 3600, 0}, {2500, 2400, 0}};

typedef struct gen {
    unsigned long long state;
    int fixtures, tilings;
} gen;

/* splitmix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", 2014). */
static double gen_unit(gen *g)
{
    unsigned long long z = (g->state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static cJSON *vec(int n, const double *v)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; a && i < n; i++)
        cJSON_AddItemToArray(a, cJSON_CreateNumber(v[i]));
    return a;
}

static cJSON *product_ref(const gen_product *p)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "manufacturer", p->manufacturer);
    cJSON_AddStringToObject(o, "article", p->article);
    cJSON_AddStringToObject(o, "variant", p->variant);
    return o;
}

/* A product against wall `wall` (0: y = 0, 1: x = w, 2: y = d, 3: x = 0) at `along` mm from the
 * wall's lower x or y, its origin `out` mm into the room, at height z. */
static void place(gen *g, cJSON *objects, const char *name, const gen_product *p, int wall,
                  double along, double out, double z, double w, double d)
{
    static const double rot[4] = {0, 90, 180, -90};
    double pos[3] = {along, out, z};
    if (wall == 1)
        pos[0] = w - out, pos[1] = along;
    else if (wall == 2)
        pos[1] = d - out;
    else if (wall == 3)
        pos[0] = out, pos[1] = along;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "name", name);
    cJSON_AddItemToObject(o, "product", product_ref(p));
    cJSON_AddItemToObject(o, "position", vec(3, pos));
    double r[3] = {0, 0, rot[wall]};
    cJSON_AddItemToObject(o, "rotation", vec(3, r));
    cJSON_AddItemToArray(objects, o);
    g->fixtures++;
}

static void tiling(gen *g, cJSON *tilings, const char *surface, const gen_product *p,
                   const char *pattern, double to)
{
    cJSON *t = cJSON_CreateObject();
    cJSON_AddStringToObject(t, "name", surface);
    cJSON_AddStringToObject(t, "surface", surface);
    cJSON_AddItemToObject(t, "product", product_ref(p));
    cJSON_AddStringToObject(t, "pattern", pattern);
    cJSON_AddNumberToObject(t, "grout", 3);
    cJSON_AddStringToObject(t, "align", "centred");
    if (to > 0) {
        cJSON_AddNumberToObject(t, "from", 0);
        cJSON_AddNumberToObject(t, "to", to);
    }
    cJSON_AddItemToArray(tilings, t);
    g->tilings++;
}

/* The WC on a pre-wall of wall 3 centred at y = yc, with its roll holder and brush. */
static void wc_block(gen *g, cJSON *plan, cJSON *objects, double yc, double w, double d,
                     const char *prefix)
{
    cJSON *prewalls = cJSON_AddArrayToObject(plan, "prewalls");
    cJSON *pw = cJSON_CreateObject();
    cJSON_AddStringToObject(pw, "name", "wc-wall");
    cJSON_AddNumberToObject(pw, "wall", 3);
    cJSON_AddNumberToObject(pw, "offset", d - yc - 600); /* wall 3 runs from y = d to y = 0 */
    cJSON_AddNumberToObject(pw, "width", 1200);
    cJSON_AddNumberToObject(pw, "depth", 200);
    cJSON_AddNumberToObject(pw, "height", 1150);
    cJSON_AddItemToArray(prewalls, pw);
    char name[64];
    snprintf(name, sizeof name, "%swc", prefix);
    place(g, objects, name, &WC, 3, yc, 200, 80, w, d);
    snprintf(name, sizeof name, "%sroll-holder", prefix);
    place(g, objects, name, &ROLL, 3, yc + 380, 200, 700, w, d);
    snprintf(name, sizeof name, "%swc-brush", prefix);
    place(g, objects, name, &BRUSH, 3, yc + 520, 200, 80, w, d);
}

/* Vanity, basin, mixer, mirror and mirror light on wall 1 at y = yc. */
static void basin_block(gen *g, cJSON *objects, double yc, double w, double d)
{
    place(g, objects, "vanity", &VANITY, 1, yc, 0, 160, w, d);
    place(g, objects, "basin", &BASIN, 1, yc, 0, 680, w, d);
    place(g, objects, "basin-mixer", &BASIN_MIXER, 1, yc, 50, 850, w, d);
    place(g, objects, "mirror", &MIRROR, 1, yc, 0, 1150, w, d);
    place(g, objects, "mirror-light", &MIRROR_LAMP, 1, yc, 0, 1880, w, d);
}

/* Recessed downlights on a grid of about `pitch` mm, and hooks at 120 mm along wall 2 clear of
 * the door (which takes [w - 1100, w - 300] of that wall) and the radiator. */
static void fill(gen *g, cJSON *objects, double w, double d, double h, double pitch)
{
    int nx = (int)(w / pitch), ny = (int)(d / pitch);
    nx = nx < 1 ? 1 : nx;
    ny = ny < 1 ? 1 : ny;
    char name[64];
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            double pos[3] = {w * (i + 0.5) / nx, d * (j + 0.5) / ny, h - 60};
            cJSON *o = cJSON_CreateObject();
            snprintf(name, sizeof name, "downlight-%d-%d", j + 1, i + 1);
            cJSON_AddStringToObject(o, "name", name);
            cJSON_AddItemToObject(o, "product", product_ref(&DOWNLIGHT));
            cJSON_AddItemToObject(o, "position", vec(3, pos));
            cJSON_AddItemToArray(objects, o);
            g->fixtures++;
        }
    int k = 0;
    for (double x = 1000; x <= w - 1300; x += 120) {
        snprintf(name, sizeof name, "hook-%d", ++k);
        place(g, objects, name, &HOOK, 2, x, 0, 1700, w, d);
    }
}

static cJSON *make_room(gen *g, int index, double offset_x, double offset_y, double *w_out)
{
    room_kind kind = (room_kind)(index % KIND_COUNT);
    double vary = 1.0 + 0.1 * gen_unit(g); /* rooms only grow: the layouts fit the least */
    double w = (double)(long)(KIND_SIZE[kind][0] * vary / 10) * 10;
    double d = (double)(long)(KIND_SIZE[kind][1] * (1.0 + 0.1 * gen_unit(g)) / 10) * 10;
    double h = 2600, wall_top = KIND_SIZE[kind][2];
    *w_out = w;
    cJSON *room = cJSON_CreateObject();
    char name[64];
    if (index < KIND_COUNT)
        snprintf(name, sizeof name, "%s", KIND_NAMES[kind]);
    else
        snprintf(name, sizeof name, "%s %d", KIND_NAMES[kind], index / KIND_COUNT + 1);
    cJSON_AddStringToObject(room, "name", name);
    double off[2] = {offset_x, offset_y};
    cJSON_AddItemToObject(room, "offset", vec(2, off));
    cJSON *mats = cJSON_AddObjectToObject(room, "room");
    cJSON_AddStringToObject(mats, "floor", "screed");
    cJSON_AddStringToObject(mats, "walls", "wall-paint");
    cJSON_AddStringToObject(mats, "ceiling", "ceiling-paint");

    cJSON *plan = cJSON_AddObjectToObject(room, "plan");
    double corners[4][2] = {{0, 0}, {w, 0}, {w, d}, {0, d}};
    cJSON *cs = cJSON_AddArrayToObject(plan, "corners");
    for (int i = 0; i < 4; i++)
        cJSON_AddItemToArray(cs, vec(2, corners[i]));
    cJSON_AddNumberToObject(plan, "height", h);
    cJSON_AddNumberToObject(plan, "wall_thickness", 175);
    cJSON *ops = cJSON_AddArrayToObject(plan, "openings");
    cJSON *win = cJSON_CreateObject();
    cJSON_AddStringToObject(win, "name", "window");
    cJSON_AddStringToObject(win, "type", "window");
    cJSON_AddNumberToObject(win, "wall", 0);
    cJSON_AddNumberToObject(win, "offset", 450);
    cJSON_AddNumberToObject(win, "width", 800);
    cJSON_AddNumberToObject(win, "height", 900);
    cJSON_AddNumberToObject(win, "sill", 1350);
    cJSON_AddItemToArray(ops, win);
    cJSON *door = cJSON_CreateObject();
    cJSON_AddStringToObject(door, "name", "door");
    cJSON_AddStringToObject(door, "type", "door");
    cJSON_AddNumberToObject(door, "wall", 2);
    cJSON_AddNumberToObject(door, "offset", 300);
    cJSON_AddNumberToObject(door, "width", 800);
    cJSON_AddNumberToObject(door, "height", 2010);
    cJSON_AddStringToObject(door, "swing", "in-right");
    cJSON_AddItemToArray(ops, door);

    cJSON *objects = cJSON_AddArrayToObject(room, "objects");
    int has_wc = kind == KIND_BATHROOM || kind == KIND_WC || kind == KIND_SHOWER ||
                 kind == KIND_ENSUITE || kind == KIND_GUEST_WC;
    if (kind == KIND_BATHROOM || kind == KIND_ENSUITE) {
        place(g, objects, "bath", &BATH, 0, 900, 0, 0, w, d);
        place(g, objects, "bath-mixer", &BATH_MIXER, 0, 900, 0, 620, w, d);
    }
    if (kind == KIND_BATHROOM || kind == KIND_SHOWER || kind == KIND_ENSUITE) {
        place(g, objects, "shower-tray", &TRAY, 0, w - 500, 0, 0, w, d);
        place(g, objects, "shower-system", &SHOWER, 0, w - 500, 0, 1000, w, d);
        place(g, objects, "shower-basket", &BASKET, 0, w - 150, 0, 1150, w, d);
    }
    if (has_wc)
        wc_block(g, plan, objects, d * 0.45, w, d, "");
    /* The basin clear of the shower's free area (900 mm deep) and of the door's swing. */
    if (kind != KIND_HALL)
        basin_block(g, objects,
                    kind == KIND_WC || kind == KIND_GUEST_WC       ? d * 0.3
                    : kind == KIND_KITCHEN || kind == KIND_UTILITY ? d * 0.5
                                                                   : d * 0.62,
                    w, d);
    place(g, objects, "towel-radiator", &RADIATOR, 2, 500, 0, 150, w, d);
    double lamp[3] = {w / 2, d / 2, h - 95};
    cJSON *cl = cJSON_CreateObject();
    cJSON_AddStringToObject(cl, "name", "ceiling-light");
    cJSON_AddItemToObject(cl, "product", product_ref(&CEILING_LAMP));
    cJSON_AddItemToObject(cl, "position", vec(3, lamp));
    cJSON_AddItemToArray(objects, cl);
    g->fixtures++;
    fill(g, objects, w, d, h, 650);

    cJSON *tilings = cJSON_AddArrayToObject(room, "tilings");
    int pick = (int)(gen_unit(g) * 4) % 4;
    for (int i = 0; i < 4; i++) {
        char s[16];
        snprintf(s, sizeof s, "wall:%d", i);
        tiling(g, tilings, s, &WALL_TILES[pick], "straight", wall_top);
    }
    if (has_wc) {
        static const char *const faces[] = {"front", "top", "left", "right"};
        for (int i = 0; i < 4; i++) {
            char s[64];
            snprintf(s, sizeof s, "prewall:wc-wall:%s", faces[i]);
            tiling(g, tilings, s, &WALL_TILES[pick], "straight", 0);
        }
    }
    tiling(g, tilings, "floor", &FLOOR_TILES[(int)(gen_unit(g) * 4) % 4], "straight", 0);

    cJSON *lights = cJSON_AddArrayToObject(room, "lights");
    cJSON *l = cJSON_CreateObject();
    cJSON_AddStringToObject(l, "name", "ceiling");
    cJSON_AddStringToObject(l, "type", "point");
    double lp[3] = {w / 2, d / 2, h - 150};
    cJSON_AddItemToObject(l, "position", vec(3, lp));
    double col[3] = {1, 0.93, 0.84}, att[3] = {1, 0, 0.35};
    cJSON_AddItemToObject(l, "color", vec(3, col));
    cJSON_AddNumberToObject(l, "intensity", 2.5);
    cJSON_AddItemToObject(l, "attenuation", vec(3, att));
    cJSON_AddItemToArray(lights, l);

    cJSON *cams = cJSON_AddArrayToObject(room, "cameras");
    cJSON *cam = cJSON_CreateObject();
    char cname[80];
    snprintf(cname, sizeof cname, "%s view", name);
    for (char *c = cname; *c; c++)
        *c = *c == ' ' ? '-' : (char)(*c >= 'A' && *c <= 'Z' ? *c - 'A' + 'a' : *c);
    cJSON_AddStringToObject(cam, "name", cname);
    double eye[3] = {w - 400, d - 300, 1600}, at[3] = {w * 0.3, d * 0.2, 900};
    cJSON_AddItemToObject(cam, "position", vec(3, eye));
    cJSON_AddItemToObject(cam, "target", vec(3, at));
    cJSON_AddNumberToObject(cam, "fov", 70);
    cJSON_AddItemToArray(cams, cam);
    return room;
}

static cJSON *material(const double diffuse[3], double specular, double shininess)
{
    cJSON *m = cJSON_CreateObject();
    cJSON_AddItemToObject(m, "diffuse", vec(3, diffuse));
    double s[3] = {specular, specular, specular};
    cJSON_AddItemToObject(m, "specular", vec(3, s));
    cJSON_AddNumberToObject(m, "shininess", shininess);
    return m;
}

app_result app_flat_generate(int rooms, unsigned long long seed, const char *path,
                             app_flat_generate_report *report, char *err, size_t err_size)
{
    pj_ctx c;
    pj_ctx_init(&c, path, path, err, err_size);
    if (report)
        memset(report, 0, sizeof *report);
    if (!path || !*path)
        return pj_fail_file(&c, APP_ERR_IO, "no file name given");
    if (rooms < 1 || rooms > APP_FLAT_MAX_ROOMS)
        return pj_fail_file(&c, APP_ERR_SCHEMA, "a flat has 1 to %d rooms, not %d",
                            APP_FLAT_MAX_ROOMS, rooms);
    gen g = {.state = seed};
    cJSON *root = cJSON_CreateObject();
    cJSON_AddNumberToObject(root, "version", APP_PROJECT_VERSION);
    char name[128];
    snprintf(name, sizeof name, "Generated flat, %d room%s (seed %llu)", rooms,
             rooms == 1 ? "" : "s", seed);
    cJSON_AddStringToObject(root, "name", name);
    cJSON *mats = cJSON_AddObjectToObject(root, "materials");
    cJSON_AddItemToObject(mats, "wall-paint", material((double[3]){0.85, 0.84, 0.8}, 0.05, 8));
    cJSON_AddItemToObject(mats, "ceiling-paint", material((double[3]){0.92, 0.92, 0.9}, 0, 1));
    cJSON_AddItemToObject(mats, "screed", material((double[3]){0.5, 0.48, 0.45}, 0.1, 16));
    cJSON *list = cJSON_AddArrayToObject(root, "rooms");
    double x = 0, y = 0;
    int per_row = (rooms + 1) / 2;
    for (int i = 0; i < rooms; i++) {
        if (i == per_row)
            x = 0, y = 6000; /* the second row, across the corridor */
        double w = 0;
        cJSON_AddItemToArray(list, make_room(&g, i, x, y, &w));
        x += w + 175; /* one wall thickness between neighbours */
    }
    cJSON *render = cJSON_AddObjectToObject(root, "render");
    double amb[3] = {0.24, 0.24, 0.25};
    cJSON_AddItemToObject(render, "ambient", vec(3, amb));
    cJSON_AddStringToObject(render, "exposure", "auto");
    cJSON_AddItemToObject(render, "size", vec(2, (double[2]){1280, 720}));
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text)
        return pj_fail_file(&c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    app_result r = pj_write_atomic(&c, path, text, strlen(text));
    cJSON_free(text);
    if (r == APP_OK && report) {
        report->rooms = rooms;
        report->fixtures = g.fixtures;
        report->tilings = g.tilings;
    }
    return r;
}
