/* Tiling in the planner (tiles.h): the state behind the tile panel and the elevation view,
 * kept up to date with the document, the edit lines that change a tiling (docs/editing.md
 * `tile SURFACE ...`, one undo step each) and the tile script actions. */
#include "tiles.h"

#include "app/project/commands.h"
#include "app/design/room_surfaces.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

ui_tiles *planner_tiles(planner *p)
{
    if (!p->tiles) {
        p->tiles = calloc(1, sizeof *p->tiles);
        if (p->tiles) {
            snprintf(p->tiles->surface, sizeof p->tiles->surface, "wall:0");
            p->tiles->shown_tiling = -2;
            p->tiles->new_border_at = 1200;
            p->tiles->zoom = 1;
            p->tiles->plan_wall = -1;
        }
    }
    return p->tiles;
}

static void drop_derived(ui_tiles *t)
{
    free(t->surfaces);
    t->surfaces = NULL;
    t->surface_count = 0;
    free(t->boxes);
    t->boxes = NULL;
    t->box_count = 0;
    app_tile_layouts_free(t->layouts, t->layout_count);
    t->layouts = NULL;
    t->layout_count = 0;
    free(t->colours);
    t->colours = NULL;
    app_surface_region_free(&t->region);
    t->region_ok = 0;
    t->region_surface[0] = 0;
    t->valid = 0;
}

void planner_tiles_free(planner *p)
{
    if (!p->tiles)
        return;
    drop_derived(p->tiles);
    free(p->tiles);
    p->tiles = NULL;
}

cat_db *ui_tiles_db(planner *p)
{
    if (p->browser.db)
        return p->browser.db;
    app_lazy_catalog *l = &p->catalog;
    if (!l->db && !l->failed &&
        app_placement_open_catalog(l->db_path, &l->db, l->err, sizeof l->err) != APP_OK)
        l->failed = 1;
    return l->db;
}

/* FNV-1a over what the surfaces, covering boxes and layouts depend on: the plan, the
 * tilings, the objects (baths and trays cover walls) and the room box. Padding bytes take part
 * too; they only change when an element is rewritten, which is a change anyway. */
static unsigned long long mix(unsigned long long h, const void *data, size_t size)
{
    const unsigned char *b = data;
    for (size_t i = 0; b && i < size; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static unsigned long long document_hash(const app_project *p)
{
    unsigned long long h = 1469598103934665603ull;
    const app_room_plan *pl = &p->plan;
    h = mix(h, &pl->corner_count, sizeof pl->corner_count);
    h = mix(h, pl->corners, (size_t)pl->corner_count * sizeof *pl->corners);
    h = mix(h, &pl->height_mm, sizeof pl->height_mm);
    h = mix(h, &pl->slope, sizeof pl->slope);
    h = mix(h, &pl->opening_count, sizeof pl->opening_count);
    h = mix(h, pl->openings, (size_t)pl->opening_count * sizeof *pl->openings);
    h = mix(h, &pl->prewall_count, sizeof pl->prewall_count);
    h = mix(h, pl->prewalls, (size_t)pl->prewall_count * sizeof *pl->prewalls);
    h = mix(h, &pl->niche_count, sizeof pl->niche_count);
    h = mix(h, pl->niches, (size_t)pl->niche_count * sizeof *pl->niches);
    h = mix(h, &p->tiling_count, sizeof p->tiling_count);
    h = mix(h, p->tilings, (size_t)p->tiling_count * sizeof *p->tilings);
    h = mix(h, &p->object_count, sizeof p->object_count);
    h = mix(h, p->objects, (size_t)p->object_count * sizeof *p->objects);
    h = mix(h, &p->room, sizeof p->room);
    return h;
}

/* A tile product's colour for the elevation: its variant's diffuse (linear) made sRGB, as the
 * printed elevations colour them (print_elevation.c). */
static void tile_colour(cat_db *db, const app_product_ref *ref, float rgb[3])
{
    rgb[0] = rgb[1] = rgb[2] = 0.85f;
    cat_product prod;
    char err[256];
    if (!db ||
        cat_product_find(db, ref->manufacturer, ref->article, &prod, err, sizeof err) != CAT_DB_OK)
        return;
    const cat_variant *var = prod.variant_count ? &prod.variants[0] : NULL;
    for (int i = 0; i < prod.variant_count; i++)
        if (ref->variant[0] && !strcmp(prod.variants[i].code, ref->variant))
            var = &prod.variants[i];
    for (int k = 0; var && k < 3; k++)
        rgb[k] = (float)pow(fmin(fmax(var->material.diffuse[k], 0.0), 1.0), 1.0 / 2.2);
    cat_product_free(&prod);
}

static int refresh_region(planner *p, ui_tiles *t)
{
    if (t->region_ok && !strcmp(t->region_surface, t->surface))
        return 0;
    app_surface_region_free(&t->region);
    t->region_ok = 0;
    char err[1024];
    if (app_room_surface_region(&p->project, t->surface, t->boxes, t->box_count, &t->region,
                                &t->frame, err, sizeof err) != APP_OK) {
        snprintf(t->error, sizeof t->error, "%.1000s", err);
        return 1;
    }
    snprintf(t->region_surface, sizeof t->region_surface, "%s", t->surface);
    t->region_ok = 1;
    return 0;
}

static int recompute(planner *p, ui_tiles *t);

int ui_tiles_refresh(planner *p, ui_tiles *t)
{
    unsigned long long h = document_hash(&p->project);
    if (t->valid && h == t->hash)
        return refresh_region(p, t);
    drop_derived(t);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int rc = recompute(p, t);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    t->refresh_ms =
        (double)(t1.tv_sec - t0.tv_sec) * 1e3 + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-6;
    t->hash = h;
    t->valid = 1; /* even when it failed: the error stays until the document changes */
    /* Another document (new, open) may not have the surface shown: its first wall then. */
    int known = 0;
    for (int k = 0; k < t->surface_count && !known; k++)
        known = !strcmp(t->surfaces[k].surface, t->surface);
    if (!known && t->surface_count > 0) {
        int k = t->surface_count > 2 ? 2 : 0; /* floor, ceiling, wall:0, ... */
        snprintf(t->surface, sizeof t->surface, "%s", t->surfaces[k].surface);
        t->pick = 0;
    }
    return rc ? rc : refresh_region(p, t);
}

static int recompute(planner *p, ui_tiles *t)
{
    t->error[0] = 0;
    char err[1024];
    cat_db *db = ui_tiles_db(p);
    if (app_room_surface_list(&p->project, &t->surfaces, &t->surface_count, err, sizeof err) !=
            APP_OK ||
        app_room_fixture_boxes(&p->project, db ? app_placement_catalog_lookup : NULL, db, &t->boxes,
                               &t->box_count, err, sizeof err) != APP_OK) {
        snprintf(t->error, sizeof t->error, "%.1000s", err);
        return 1;
    }
    if (!db && p->project.tiling_count > 0) {
        snprintf(t->error, sizeof t->error, "no catalog for the tiles: %.900s", p->catalog.err);
        return 1;
    }
    if (p->project.tiling_count > 0 &&
        app_room_tile_layouts(&p->project, db, &t->layouts, &t->layout_count, err, sizeof err) !=
            APP_OK) {
        snprintf(t->error, sizeof t->error, "%.1000s", err);
        return 1;
    }
    t->colours = calloc((size_t)(t->layout_count + 1), sizeof *t->colours);
    for (int i = 0; t->colours && i < t->layout_count; i++)
        for (int k = 0; k < t->layouts[i].spec_count; k++)
            tile_colour(db, &t->layouts[i].specs[k].product, t->colours[i][k]);
    return 0;
}

int ui_tiles_find(const app_project *p, const char *surface_or_name)
{
    for (int i = 0; i < p->tiling_count; i++)
        if (!strcmp(p->tilings[i].surface, surface_or_name))
            return i;
    for (int i = 0; i < p->tiling_count; i++)
        if (!strcmp(p->tilings[i].name, surface_or_name))
            return i;
    return -1;
}

int ui_tiles_on_surface(const app_project *p, const char *surface, int k)
{
    for (int i = 0; i < p->tiling_count; i++)
        if (!strcmp(p->tilings[i].surface, surface) && k-- == 0)
            return i;
    return -1;
}

static void copy_text(char *dst, size_t size, const char *src)
{
    size_t n = strlen(src);
    n = n < size ? n : size - 1;
    memcpy(dst, src, n);
    dst[n] = 0;
}

void ui_tiles_ref_of(const cat_product *prod, int variant, app_product_ref *ref)
{
    memset(ref, 0, sizeof *ref);
    copy_text(ref->manufacturer, sizeof ref->manufacturer, prod->manufacturer);
    copy_text(ref->article, sizeof ref->article, prod->article);
    if (variant >= 0 && variant < prod->variant_count)
        copy_text(ref->variant, sizeof ref->variant, prod->variants[variant].code);
}

void ui_tiles_show(planner *p, const char *surface)
{
    ui_tiles *t = planner_tiles(p);
    if (!t || !strcmp(t->surface, surface))
        return;
    snprintf(t->surface, sizeof t->surface, "%s", surface);
    t->pick = 0;
    t->zoom = 1;
    t->pan[0] = t->pan[1] = 0;
    t->valid = 0; /* everything afresh, so no message of the last surface stays */
}

/* How an edit line names tiling i: by its surface when it is the first there (the edit
 * line's own lookup), else by its name. */
static int address(planner *p, int i, char *out, size_t size)
{
    if (i < 0 || i >= p->project.tiling_count) {
        planner_status(p, "no such tiling");
        return 0;
    }
    const app_tiling *t = &p->project.tilings[i];
    const char *a = ui_tiles_find(&p->project, t->surface) == i ? t->surface : t->name;
    if (strchr(a, '"') || ui_tiles_find(&p->project, a) != i) {
        planner_status(p, "the tiling \"%s\" cannot be named in an edit line", t->name);
        return 0;
    }
    snprintf(out, size, "\"%s\"", a);
    return 1;
}

int planner_tile_pattern(planner *p, int tiling, app_tile_pattern pattern)
{
    char a[128], line[256];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    snprintf(line, sizeof line, "tile %s pattern %s", a, app_tile_pattern_name(pattern));
    return planner_edit(p, line);
}

int planner_tile_grout(planner *p, int tiling, double mm, const float rgb[3])
{
    char a[128], line[256];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    snprintf(line, sizeof line, "tile %s grout %.2f colour %.3f %.3f %.3f", a, mm, rgb[0], rgb[1],
             rgb[2]);
    return planner_edit(p, line);
}

int planner_tile_start(planner *p, int tiling, app_tile_align align, double s, double t)
{
    char a[128], line[256];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    if (align == APP_ALIGN_LINE)
        snprintf(line, sizeof line, "tile %s start line %.1f %.1f", a, s, t);
    else
        snprintf(line, sizeof line, "tile %s start %s", a, app_tile_align_name(align));
    return planner_edit(p, line);
}

int planner_tile_rotation(planner *p, int tiling, double deg)
{
    char a[128], line[256];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    snprintf(line, sizeof line, "tile %s rotate %.2f", a, deg);
    return planner_edit(p, line);
}

int planner_tile_band(planner *p, int tiling, double from, double to)
{
    char a[128], line[256];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    snprintf(line, sizeof line, "tile %s band %.1f %.1f", a, from, to);
    return planner_edit(p, line);
}

int planner_tile_border_add(planner *p, int tiling, const app_product_ref *ref, double bottom)
{
    char a[128], line[512];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    snprintf(line, sizeof line, "tile %s border add \"%s\" \"%s\" %s at %.1f", a, ref->manufacturer,
             ref->article, ref->variant, bottom);
    return planner_edit(p, line);
}

int planner_tile_border_move(planner *p, int tiling, int k, double bottom)
{
    char a[128], line[256];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    snprintf(line, sizeof line, "tile %s border %d at %.1f", a, k + 1, bottom);
    return planner_edit(p, line);
}

int planner_tile_border_remove(planner *p, int tiling, int k)
{
    char a[128], line[256];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    snprintf(line, sizeof line, "tile %s border remove %d", a, k + 1);
    return planner_edit(p, line);
}

int planner_tile_product(planner *p, const char *surface, const app_product_ref *ref)
{
    char line[512];
    int i = ui_tiles_on_surface(&p->project, surface, planner_tiles(p) ? p->tiles->pick : 0);
    char a[128];
    if (i >= 0) {
        if (!address(p, i, a, sizeof a))
            return 1;
    } else {
        snprintf(a, sizeof a, "\"%s\"", surface);
    }
    snprintf(line, sizeof line, "tile %s with \"%s\" \"%s\" %s", a, ref->manufacturer, ref->article,
             ref->variant);
    return planner_edit(p, line);
}

int planner_untile(planner *p, int tiling)
{
    char a[128], line[256];
    if (!address(p, tiling, a, sizeof a))
        return 1;
    snprintf(line, sizeof line, "untile %s", a);
    return planner_edit(p, line);
}

int planner_elevation_click(planner *p, double s, double t)
{
    ui_tiles *ts = planner_tiles(p);
    if (!ts)
        return 1;
    int i = ui_tiles_on_surface(&p->project, ts->surface, ts->pick);
    if (i < 0)
        i = ui_tiles_on_surface(&p->project, ts->surface, 0);
    if (i < 0) {
        planner_status(p, "%s is not tiled: pick a tile first", ts->surface);
        return 1;
    }
    double ss, tt;
    ui_elev_snap_point(s, t, 10.0, &ss, &tt);
    return planner_tile_start(p, i, APP_ALIGN_LINE, ss, tt);
}

/* ---- script actions ------------------------------------------------------------------------- */

static int words(const char *text, char copy[512], char *w[8])
{
    char *save = NULL;
    int n = 0;
    snprintf(copy, 512, "%s", text);
    for (char *t = strtok_r(copy, " \t", &save); t && n < 8; t = strtok_r(NULL, " \t", &save))
        w[n++] = t;
    return n;
}

static int tiling_of(planner *p, const char *surface)
{
    int i = ui_tiles_find(&p->project, surface);
    if (i < 0)
        planner_status(p, "no tiling on \"%s\"", surface);
    return i;
}

int planner_tile_action(planner *p, const ui_action *a)
{
    static char none[1]; /* missing words read as "" (the script reader counted them) */
    char copy[512], *w[8] = {none, none, none, none, none, none, none, none};
    int n = words(a->text, copy, w), i = -1;
    ui_tiles *ts = planner_tiles(p);
    if (!ts) {
        planner_status(p, "out of memory");
        return 1;
    }
    if (a->kind != UI_ACT_ELEVATION_WALL && a->kind != UI_ACT_ELEVATION_CLICK &&
        a->kind != UI_ACT_TILE_SURFACE && a->kind != UI_ACT_TILE_BORDER &&
        a->kind != UI_ACT_TILE_PANEL && n > 0 && (i = tiling_of(p, w[0])) < 0)
        return 1;
    switch (a->kind) {
    case UI_ACT_ELEVATION_WALL: {
        /* The surface list knows the walls of a plan and of a version 1 room box alike. */
        char s[32];
        snprintf(s, sizeof s, "wall:%d", (int)a->a);
        ui_tiles_refresh(p, ts);
        int walls = 0, known = 0;
        for (int k = 0; k < ts->surface_count; k++) {
            walls += ts->surfaces[k].kind == APP_SURFACE_WALL;
            known |= !strcmp(ts->surfaces[k].surface, s);
        }
        if (!known) {
            planner_status(p, "the room has %d walls, no wall %d", walls, (int)a->a);
            return 1;
        }
        ui_tiles_show(p, s);
        p->view = UI_VIEW_ELEVATION;
        return 0;
    }
    case UI_ACT_TILE_SURFACE: {
        ui_tiles_refresh(p, ts);
        int known = 0;
        for (int k = 0; k < ts->surface_count && !known; k++)
            known = !strcmp(ts->surfaces[k].surface, a->text);
        if (!known) {
            planner_status(p, "no surface \"%s\" in this room", a->text);
            return 1;
        }
        ui_tiles_show(p, a->text);
        ui_tiles_refresh(p, ts);
        if (!ts->region_ok) {
            planner_status(p, "%s", ts->error);
            return 1;
        }
        return 0;
    }
    case UI_ACT_TILE_PATTERN: {
        app_tile_pattern pat;
        if (n != 2 || !app_tile_pattern_parse(w[1], &pat))
            return 1;
        return planner_tile_pattern(p, i, pat);
    }
    case UI_ACT_TILE_GROUT: {
        const app_tiling *t = &p->project.tilings[i];
        float rgb[3] = {t->grout_color[0], t->grout_color[1], t->grout_color[2]};
        for (int k = 0; k < 3 && n == 5; k++)
            rgb[k] = (float)atof(w[2 + k]);
        return planner_tile_grout(p, i, atof(w[1]), rgb);
    }
    case UI_ACT_TILE_START: {
        app_tile_align al;
        if (n == 2 && app_tile_align_parse(w[1], &al))
            return planner_tile_start(p, i, al, 0, 0);
        return planner_tile_start(p, i, APP_ALIGN_LINE, atof(w[1]), atof(w[2]));
    }
    case UI_ACT_TILE_ROTATE:
        return planner_tile_rotation(p, i, atof(w[1]));
    case UI_ACT_TILE_BAND:
        return planner_tile_band(p, i, atof(w[1]), atof(w[2]));
    case UI_ACT_TILE_BORDER: {
        const cat_product *prod = &p->browser.product;
        if (p->browser.selected < 0 || !prod->has_tile) {
            planner_status(p, "select a tile in the catalog first");
            return 1;
        }
        if ((i = tiling_of(p, w[0])) < 0)
            return 1;
        app_product_ref ref;
        ui_tiles_ref_of(prod, p->browser.variant, &ref);
        return planner_tile_border_add(p, i, &ref, atof(w[1]));
    }
    case UI_ACT_ELEVATION_CLICK:
        return planner_elevation_click(p, a->a, a->b);
    case UI_ACT_TILE_PANEL:
        ts->in_3d = !strcmp(a->text, "on");
        return 0;
    case UI_ACT_EXPECT_PATTERN: {
        app_tile_pattern pat;
        if (n != 2 || !app_tile_pattern_parse(w[1], &pat))
            return 1;
        if (p->project.tilings[i].pattern != pat) {
            planner_status(p, "the tiling on %s is %s, expected %s", w[0],
                           app_tile_pattern_name(p->project.tilings[i].pattern), w[1]);
            return 1;
        }
        return 0;
    }
    case UI_ACT_EXPECT_TILES: {
        ui_tiles_refresh(p, ts);
        int need = atoi(w[1]);
        if (i >= ts->layout_count) {
            planner_status(p, "no layout for %s: %s", w[0], ts->error);
            return 1;
        }
        fprintf(stderr, "tessera: %s: %d tiles; the layouts of %d tilings took %.1f ms\n", w[0],
                ts->layouts[i].tile_count, ts->layout_count, ts->refresh_ms);
        if (ts->layouts[i].tile_count < need) {
            planner_status(p, "the layout on %s has %d tiles, expected at least %d", w[0],
                           ts->layouts[i].tile_count, need);
            return 1;
        }
        return 0;
    }
    default:
        return 1;
    }
}
