/* make_catalog_csv: writes the shipped catalog's source data (the CSV files in assets/catalog), and
 * on request a large synthetic catalog for benchmarks. Deterministic: the same program writes the
 * same bytes, so the committed CSV files can be checked against it.
 *
 *   make_catalog_csv OUT_DIR                    OUT_DIR/fixtures.csv and OUT_DIR/tiles.csv
 *   make_catalog_csv --synthetic N FILE.csv     N invented products, one row each
 *
 * Every manufacturer, series and article here is invented. Sizes follow DOMAIN.md (basins
 * 600 x 550, hand basins 450 x 350, baths 1700 x 750, WCs 360-430 wide and 480-770 deep, shower
 * trays from 800 x 800; tiles nominal = work + grout); prices are plausible euro list prices;
 * materials follow RENDERING.md (chrome k_r 0.8 g 0.9, ceramic k_r 0.1 g 0.6 fresnel, mirror
 * k_r 0.95 g 1, glass transparency 0.9 IOR 1.5). The CSV files are the source of truth: edit
 * them directly, or change this program and run it again. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- output ---------------------------------------------------------------------------------- */

static const char header[] =
    "manufacturer,article,gtin,category,series,name,short_text,long_text,width_mm,depth_mm,"
    "height_mm,list_price,currency,vat_percent,unit,discount_group,model,variant_code,"
    "variant_name,variant_surcharge,ambient,diffuse,specular,emissive,shininess,reflectivity,"
    "glossiness,blend,transparency,ior,tile_type,nominal_w_mm,nominal_h_mm,work_w_mm,work_h_mm,"
    "grout_mm,thickness_mm,calibre,surface,m2_per_box,pieces_per_box,texture,mounting_height_mm,"
    "mounting_to,companions,pattern,grain\n";

static void put_text(FILE *f, const char *s)
{
    int quote = strpbrk(s, ",\"\n") != NULL;
    if (!quote) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"')
            fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

/* Shortest text of v that reads back as the same double, as the catalog's export writes it. */
static void put_num(FILE *f, double v)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.15g", v);
    if (strtod(buf, NULL) != v)
        snprintf(buf, sizeof buf, "%.17g", v);
    fputs(buf, f);
}

static void put_money(FILE *f, long cents)
{
    fprintf(f, "%ld.%02ld", cents / 100, cents % 100);
}

static void put_rgb(FILE *f, const double c[3])
{
    for (int i = 0; i < 3; i++) {
        if (i)
            fputc(' ', f);
        put_num(f, c[i]);
    }
}

/* ---- a deterministic generator (splitmix64) ---------------------------------------------------
 */

static uint64_t rng_state = 0x7e55e7a2024ull;

static uint64_t rng_next(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static int rng_int(int n) /* 0 .. n-1 */
{
    return (int)(rng_next() % (uint64_t)n);
}

/* ---- materials (RENDERING.md parameters) -------------------------------------------------- */

typedef struct material {
    const char *code, *name;
    double diffuse[3], specular[3], emissive[3];
    double shininess, kr, gloss;
    const char *blend;
    double transparency, ior;
    int surcharge_pct;   /* of the product's list price */
    const char *pattern; /* "wood" for veneers (the renderer's grain); NULL: none */
} material;

#define GREY(x)                                                                                    \
    {                                                                                              \
        x, x, x                                                                                    \
    }
/* One material a row: code, name, diffuse, specular, emissive, shininess, k_r, glossiness,
 * blend, transparency, IOR, surcharge in percent, pattern. The veneers' grain runs along the
 * product's longer side (an empty grain column). */
/* clang-format off */
static const material M_CHROME =           {"CP", "Chrome", GREY(0.05), GREY(0.95), GREY(0), 2000, 0.8, 0.9, "mix", 0, 1.5, 0, NULL};
static const material M_BLACK_MATT =       {"BM", "Black matt", GREY(0.03), GREY(0.15), GREY(0), 40, 0.04, 0.3, "fresnel", 0, 1.5, 30, NULL};
static const material M_BRUSHED_STEEL =    {"BS", "Brushed stainless steel", {0.35, 0.35, 0.36}, GREY(0.6), GREY(0), 300, 0.45, 0.55, "mix", 0, 1.5, 40, NULL};
static const material M_BRUSHED_GOLD =     {"BG", "Brushed gold", {0.45, 0.33, 0.12}, {0.8, 0.65, 0.35}, GREY(0), 400, 0.55, 0.6, "mix", 0, 1.5, 60, NULL};
static const material M_CERAMIC_WHITE =    {"WH", "White alpine, glossy", {0.92, 0.92, 0.9}, GREY(0.6), GREY(0), 256, 0.1, 0.6, "fresnel", 0, 1.5, 0, NULL};
static const material M_CERAMIC_MATT =     {"WM", "White matt", {0.9, 0.9, 0.88}, GREY(0.15), GREY(0), 24, 0.04, 0.3, "fresnel", 0, 1.5, 25, NULL};
static const material M_CERAMIC_BLACK =    {"BK", "Black matt", GREY(0.05), GREY(0.12), GREY(0), 24, 0.04, 0.3, "fresnel", 0, 1.5, 35, NULL};
static const material M_ACRYLIC_WHITE =    {"WH", "White, glossy acrylic", {0.94, 0.94, 0.93}, GREY(0.5), GREY(0), 200, 0.1, 0.65, "fresnel", 0, 1.5, 0, NULL};
static const material M_ACRYLIC_MATT =     {"WM", "White matt, solid surface", {0.93, 0.93, 0.91}, GREY(0.12), GREY(0), 20, 0.03, 0.25, "fresnel", 0, 1.5, 20, NULL};
static const material M_ENAMEL_WHITE =     {"WH", "White enamel", {0.93, 0.93, 0.92}, GREY(0.7), GREY(0), 400, 0.15, 0.7, "fresnel", 0, 1.5, 0, NULL};
static const material M_STONE_WHITE =      {"WH", "White, stone texture", {0.9, 0.9, 0.88}, GREY(0.1), GREY(0), 16, 0.03, 0.25, "fresnel", 0, 1.5, 0, NULL};
static const material M_STONE_ANTHRACITE = {"AN", "Anthracite, stone texture", {0.18, 0.18, 0.19}, GREY(0.1), GREY(0), 16, 0.03, 0.25, "fresnel", 0, 1.5, 10, NULL};
static const material M_STONE_CONCRETE =   {"CG", "Concrete grey, stone texture", {0.45, 0.45, 0.43}, GREY(0.1), GREY(0), 16, 0.03, 0.25, "fresnel", 0, 1.5, 10, NULL};
static const material M_GLASS_CLEAR =      {"CL", "Clear glass, chrome profiles", {0.9, 0.95, 0.93}, GREY(0.9), GREY(0), 1000, 0.1, 1, "fresnel", 0.9, 1.5, 0, NULL};
static const material M_GLASS_SATIN =      {"SA", "Satin glass, chrome profiles", GREY(0.85), GREY(0.3), GREY(0), 60, 0.05, 0.3, "fresnel", 0.6, 1.5, 15, NULL};
static const material M_GLASS_GREY =       {"GR", "Grey glass, black profiles", GREY(0.2), GREY(0.9), GREY(0), 1000, 0.1, 1, "fresnel", 0.7, 1.5, 20, NULL};
static const material M_MIRROR =           {"MI", "Silver mirror", GREY(0.02), GREY(1), GREY(0), 5000, 0.95, 1, "mix", 0, 1.5, 0, NULL};
static const material M_MIRROR_BRONZE =    {"MB", "Bronze mirror", {0.05, 0.035, 0.02}, {0.9, 0.7, 0.5}, GREY(0), 5000, 0.95, 1, "mix", 0, 1.5, 25, NULL};
static const material M_CAB_WHITE =        {"MW", "Mirror doors, white body", GREY(0.02), GREY(1), GREY(0), 5000, 0.95, 1, "mix", 0, 1.5, 0, NULL};
static const material M_CAB_ALU =          {"MA", "Mirror doors, aluminium body", GREY(0.02), GREY(1), GREY(0), 5000, 0.95, 1, "mix", 0, 1.5, 10, NULL};
static const material M_CAB_OAK =          {"MO", "Mirror doors, oak body", GREY(0.02), GREY(1), GREY(0), 5000, 0.95, 1, "mix", 0, 1.5, 20, NULL};
static const material M_LAMP_WARM =        {"WW", "Warm white 3000 K", GREY(0.95), GREY(0.3), {4, 3.6, 3}, 64, 0, 0.5, "mix", 0, 1.5, 0, NULL};
static const material M_LAMP_NEUTRAL =     {"NW", "Neutral white 4000 K", GREY(0.95), GREY(0.3), {4, 4, 3.8}, 64, 0, 0.5, "mix", 0, 1.5, 0, NULL};
static const material M_PAINT_WHITE =      {"WH", "Traffic white RAL 9016", {0.93, 0.93, 0.91}, GREY(0.3), GREY(0), 64, 0.05, 0.5, "fresnel", 0, 1.5, 0, NULL};
static const material M_PAINT_ANTHRACITE = {"AN", "Anthracite RAL 7016", {0.12, 0.13, 0.14}, GREY(0.2), GREY(0), 48, 0.04, 0.4, "fresnel", 0, 1.5, 15, NULL};
static const material M_PAINT_BLACK =      {"BM", "Black matt", GREY(0.03), GREY(0.1), GREY(0), 24, 0.03, 0.3, "fresnel", 0, 1.5, 20, NULL};
static const material M_LACQUER_WHITE =    {"WG", "White high-gloss lacquer", {0.92, 0.92, 0.91}, GREY(0.5), GREY(0), 200, 0.2, 0.8, "fresnel", 0, 1.5, 0, NULL};
static const material M_GRAPHITE =         {"GM", "Graphite matt", {0.15, 0.15, 0.16}, GREY(0.08), GREY(0), 16, 0.03, 0.3, "fresnel", 0, 1.5, 0, NULL};
static const material M_OAK =              {"OK", "Natural oak veneer", {0.55, 0.4, 0.26}, GREY(0.1), GREY(0), 20, 0.03, 0.35, "mix", 0, 1.5, 15, "wood"};
static const material M_WALNUT =           {"WN", "American walnut veneer", {0.3, 0.2, 0.13}, GREY(0.1), GREY(0), 20, 0.03, 0.35, "mix", 0, 1.5, 25, "wood"};
/* clang-format on */

/* Variant sets by kind of product, at most 4. */
typedef struct variant_set {
    const material *m[4];
} variant_set;

static const variant_set V_METAL4 = {{&M_CHROME, &M_BLACK_MATT, &M_BRUSHED_STEEL, &M_BRUSHED_GOLD}};
static const variant_set V_METAL2 = {{&M_CHROME, &M_BLACK_MATT}};
static const variant_set V_METAL3 = {{&M_CHROME, &M_BLACK_MATT, &M_BRUSHED_STEEL}};
static const variant_set V_CERAMIC3 = {{&M_CERAMIC_WHITE, &M_CERAMIC_MATT, &M_CERAMIC_BLACK}};
static const variant_set V_CERAMIC1 = {{&M_CERAMIC_WHITE}};
static const variant_set V_CERAMIC2 = {{&M_CERAMIC_WHITE, &M_CERAMIC_MATT}};
static const variant_set V_ACRYLIC = {{&M_ACRYLIC_WHITE}};
static const variant_set V_SOLID = {{&M_ACRYLIC_WHITE, &M_ACRYLIC_MATT}};
static const variant_set V_ENAMEL = {{&M_ENAMEL_WHITE}};
static const variant_set V_STONE = {{&M_STONE_WHITE, &M_STONE_ANTHRACITE, &M_STONE_CONCRETE}};
static const variant_set V_GLASS = {{&M_GLASS_CLEAR, &M_GLASS_SATIN, &M_GLASS_GREY}};
static const variant_set V_MIRROR = {{&M_MIRROR, &M_MIRROR_BRONZE}};
static const variant_set V_MIRROR1 = {{&M_MIRROR}};
static const variant_set V_CABINET = {{&M_CAB_WHITE, &M_CAB_ALU, &M_CAB_OAK}};
static const variant_set V_LAMP = {{&M_LAMP_WARM, &M_LAMP_NEUTRAL}};
static const variant_set V_RADIATOR = {
    {&M_PAINT_WHITE, &M_CHROME, &M_PAINT_ANTHRACITE, &M_PAINT_BLACK}};
static const variant_set V_FURNITURE = {{&M_LACQUER_WHITE, &M_GRAPHITE, &M_OAK, &M_WALNUT}};

/* ---- product types ------------------------------------------------------------------------ */

typedef struct ptype {
    const char *name; /* after the series name */
    const char *short_text;
    int w, d, h; /* mm */
    int price;   /* euro, before the series' price factor */
    const variant_set *variants;
    const char *long_text; /* the type's own sentence; the category adds more */
} ptype;

static const ptype TAPS[] = {
    {"single-lever basin mixer 100", "Single-lever basin mixer, pop-up waste, 5 l/min", 50, 135,
     165, 149, &V_METAL4, "A compact mixer for washbasins up to 600 mm."},
    {"single-lever basin mixer 190", "Single-lever basin mixer for countertop basins, 5 l/min", 50,
     170, 265, 229, &V_METAL4, "Its raised body suits countertop and semi-recessed basins."},
    {"single-lever basin mixer 260 for bowls", "Tall single-lever mixer for bowls, 5 l/min", 50,
     190, 335, 289, &V_METAL2, "Tall enough for countertop bowls up to 150 mm high."},
    {"wall-mounted basin mixer, spout 195", "Wall-mounted basin mixer, finish set, spout 195 mm",
     180, 195, 70, 259, &V_METAL4,
     "Finish set for the universal concealed body (ordered separately)."},
    {"three-hole basin mixer", "Two-handle three-hole basin mixer with pop-up waste", 160, 155, 95,
     349, &V_METAL2, "Classic three-hole installation with quarter-turn ceramic valves."},
    {"single-lever bidet mixer", "Single-lever bidet mixer with ball joint aerator", 50, 120, 140,
     169, &V_METAL2, "The swivelling aerator directs the water where it is needed."},
    {"single-lever bath mixer, exposed", "Exposed single-lever bath and shower mixer", 300, 170, 95,
     219, &V_METAL2, "Automatic diverter between bath spout and hand shower."},
    {"thermostatic bath mixer, exposed", "Exposed thermostatic bath mixer, safety stop at 38 C",
     300, 195, 110, 329, &V_METAL4,
     "The thermostat holds the temperature within 0.5 K and stops at 38 C for safety."},
    {"thermostatic shower mixer, exposed", "Exposed thermostatic shower mixer, 38 C stop", 300, 140,
     85, 269, &V_METAL4, "Cool-touch body: the surface stays below 40 C."},
    {"floor-standing bath mixer", "Floor-standing bath mixer with hand shower and holder", 220, 260,
     900, 1190, &V_METAL2, "For freestanding baths; needs the floor-mounted body."},
    {"basin tap for cold water", "Pillar tap for cold water, 4 l/min", 45, 110, 150, 99, &V_METAL2,
     "For cloakrooms and hand basins fed with cold water only."},
    {"concealed thermostat trim, 2 valves", "Finish set for the concealed thermostat, 2 outlets",
     160, 75, 160, 399, &V_METAL4, "Round plate 160 mm; the concealed body is ordered apart."},
    {"single-lever shower mixer, exposed", "Exposed single-lever shower mixer", 160, 115, 85, 179,
     &V_METAL2, "Ceramic cartridge with temperature limiter."},
    {"wall-mounted bath spout 180", "Bath spout for wall mounting, projection 180 mm", 60, 180, 60,
     119, &V_METAL4, "Matches the concealed bath mixers of the series."},
};

static const ptype SHOWERS[] = {
    {"shower rail set 650", "Shower rail 650 mm with hand shower 100 and hose 1600", 110, 130, 700,
     149, &V_METAL2, "Slider adjustable in height and angle."},
    {"shower rail set 900", "Shower rail 900 mm with hand shower 120, 3 sprays, hose 1750", 120,
     140, 950, 219, &V_METAL3, "Three sprays: rain, massage and a soft mist."},
    {"thermostatic shower system 250", "Shower system, thermostat, overhead shower 250 mm", 300,
     450, 1150, 749, &V_METAL3,
     "Overhead shower 250 mm, hand shower 120 mm and a thermostat with two valves."},
    {"thermostatic shower system 300 square", "Shower system, thermostat, overhead 300 x 300", 300,
     480, 1180, 949, &V_METAL2, "Square overhead shower 300 mm with anti-limescale nozzles."},
    {"overhead shower 300 with wall arm 390", "Overhead shower 300 mm with wall arm 390 mm", 300,
     410, 60, 339, &V_METAL3, "Self-cleaning silicone nozzles."},
    {"hand shower 120, 3 sprays", "Hand shower 120 mm, 3 sprays, 9 l/min", 120, 60, 270, 59,
     &V_METAL3, "Fits every standard shower hose (G 1/2)."},
};

static const ptype BASINS[] = {
    {"washbasin 600 x 480", "Washbasin 600 x 480 mm, one tap hole, with overflow", 600, 480, 165,
     229, &V_CERAMIC3, "For wall mounting or a vanity unit of 600 mm."},
    {"washbasin 600 x 550", "Washbasin 600 x 550 mm, one tap hole, with overflow", 600, 550, 175,
     259, &V_CERAMIC3, "The classic size: 900 x 550 mm free area in front (VDI 6000)."},
    {"washbasin 800 x 480 for furniture", "Furniture washbasin 800 x 480 mm, ground underside", 800,
     480, 170, 389, &V_CERAMIC3, "Ground underside for a flush fit on vanity units."},
    {"washbasin 1000 x 480 for furniture", "Furniture washbasin 1000 x 480 mm, shelf areas", 1000,
     480, 170, 489, &V_CERAMIC2, "Generous shelf areas left and right of the bowl."},
    {"double washbasin 1200 x 550", "Double washbasin 1200 x 550 mm, two tap holes", 1200, 550, 175,
     689, &V_CERAMIC2, "Two bowls for two users: 1500 x 550 mm free area in front."},
    {"hand basin 450 x 350", "Hand basin 450 x 350 mm, tap hole right", 450, 350, 140, 139,
     &V_CERAMIC3, "For cloakrooms and guest WCs."},
    {"compact hand basin 360 x 250", "Compact hand basin 360 x 250 mm", 360, 250, 130, 119,
     &V_CERAMIC1, "Fits a niche beside the WC."},
    {"countertop bowl 420 round", "Round countertop bowl 420 mm without overflow", 420, 420, 140,
     249, &V_CERAMIC3, "Thin rim of 6 mm; use a non-closable waste valve."},
    {"countertop bowl 600 x 380 oval", "Oval countertop bowl 600 x 380 mm", 600, 380, 140, 329,
     &V_CERAMIC3, "Pairs with the tall basin mixers of 260 mm."},
    {"semi-recessed basin 550 x 450", "Semi-recessed washbasin 550 x 450 mm", 550, 450, 180, 279,
     &V_CERAMIC2, "Sits half in the worktop, saving depth in small bathrooms."},
};

static const ptype WCS[] = {
    {"wall-hung WC, rimless", "Wall-hung washdown WC, rimless, 4.5/3 l", 360, 530, 340, 349,
     &V_CERAMIC3, "Rimless bowl: nothing for dirt to hide under."},
    {"wall-hung WC compact, rimless", "Compact wall-hung WC (toilet) 490 mm, rimless", 360, 490,
     340, 299, &V_CERAMIC2, "Short projection of 490 mm for small bathrooms."},
    {"wall-hung WC 700, accessible", "Wall-hung WC with extended projection 700 mm (DIN 18040)",
     380, 700, 400, 549, &V_CERAMIC1,
     "Seat height 460-480 mm when mounted; for wheelchair transfer."},
    {"close-coupled WC with cistern", "Floor-standing close-coupled WC (toilet), dual flush", 365,
     670, 790, 459, &V_CERAMIC1, "Horizontal or vertical outlet, cistern 4.5/3 l."},
    {"back-to-wall WC, rimless", "Floor-standing back-to-wall WC (toilet), rimless", 360, 560, 400,
     399, &V_CERAMIC3, "Concealed cistern; the bowl sits flush against the wall."},
    {"wall-hung bidet", "Wall-hung bidet with overflow, one tap hole", 360, 530, 300, 279,
     &V_CERAMIC3, "Matches the wall-hung WC of the series."},
    {"floor-standing bidet, back-to-wall", "Floor-standing bidet, back-to-wall", 360, 560, 400, 299,
     &V_CERAMIC2, "Matches the back-to-wall WC of the series."},
    {"wall-hung WC 430, generous width", "Wall-hung WC (toilet) 430 x 560 mm, rimless", 430, 560,
     360, 419, &V_CERAMIC2, "Wider bowl for comfort."},
};

static const ptype BATHS[] = {
    {"bath 1700 x 750", "Rectangular bath 1700 x 750 mm, 185 l", 1700, 750, 460, 449, &V_ACRYLIC,
     "Reinforced sanitary acrylic, backrest at one end."},
    {"bath 1600 x 700", "Rectangular bath 1600 x 700 mm, 160 l", 1600, 700, 450, 399, &V_ACRYLIC,
     "For small bathrooms."},
    {"bath 1800 x 800", "Rectangular bath 1800 x 800 mm, 230 l", 1800, 800, 470, 549, &V_ACRYLIC,
     "Central waste: room for two."},
    {"bath 1900 x 900, double-ended", "Double-ended bath 1900 x 900 mm, 290 l", 1900, 900, 480, 799,
     &V_ACRYLIC, "Backrests at both ends and a central waste."},
    {"freestanding bath 1700 x 800", "Freestanding bath 1700 x 800 mm, solid surface", 1700, 800,
     600, 1890, &V_SOLID, "Cast solid surface with a seamless outer shell."},
    {"freestanding bath 1800 x 850, oval", "Oval freestanding bath 1800 x 850 mm", 1800, 850, 620,
     2490, &V_SOLID, "Thin-edged oval shell, waste and overflow included."},
    {"corner bath 1400 x 1400", "Corner bath 1400 x 1400 mm, 240 l", 1400, 1400, 480, 899,
     &V_ACRYLIC, "Symmetric corner bath with seat."},
    {"offset corner bath 1600 x 1000", "Offset corner bath 1600 x 1000 mm, left", 1600, 1000, 470,
     749, &V_ACRYLIC, "Space-saving offset shape; a right-hand version is available."},
};

static const ptype STEEL_BATHS[] = {
    {"steel bath 1700 x 750", "Enamelled steel bath 1700 x 750 mm, 3.5 mm", 1700, 750, 420, 339,
     &V_ENAMEL, "Titanium steel 3.5 mm with a scratch-resistant enamel."},
    {"steel bath 1600 x 700", "Enamelled steel bath 1600 x 700 mm, 3.5 mm", 1600, 700, 410, 299,
     &V_ENAMEL, "Titanium steel 3.5 mm with a scratch-resistant enamel."},
    {"steel bath 1800 x 800", "Enamelled steel bath 1800 x 800 mm, 3.5 mm", 1800, 800, 430, 429,
     &V_ENAMEL, "Titanium steel 3.5 mm with a scratch-resistant enamel."},
};

static const ptype TRAYS[] = {
    {"shower tray 800 x 800", "Flat shower tray 800 x 800 x 40 mm", 800, 800, 40, 229, &V_STONE,
     "The minimum size for a shower (DOMAIN: 800 x 800)."},
    {"shower tray 900 x 900", "Flat shower tray 900 x 900 x 40 mm", 900, 900, 40, 259, &V_STONE,
     "The most common size."},
    {"shower tray 1000 x 800", "Flat shower tray 1000 x 800 x 40 mm", 1000, 800, 40, 289, &V_STONE,
     "Rectangular, waste on the short side."},
    {"shower tray 1200 x 900", "Flat shower tray 1200 x 900 x 40 mm", 1200, 900, 40, 389, &V_STONE,
     "Room for a walk-in screen."},
    {"shower tray 1400 x 900", "Flat shower tray 1400 x 900 x 40 mm", 1400, 900, 40, 459, &V_STONE,
     "Walk-in size."},
    {"shower tray 1600 x 900", "Flat shower tray 1600 x 900 x 40 mm", 1600, 900, 40, 549, &V_STONE,
     "Replaces a bath 1600 x 700 with room to spare."},
    {"shower tray 900 x 900, quadrant R550", "Quadrant shower tray 900 x 900 mm, radius 550", 900,
     900, 40, 299, &V_STONE, "For quadrant enclosures of 900 mm."},
    {"shower tray 1200 x 800, cut to size", "Shower tray 1200 x 800 x 30 mm, can be cut", 1200, 800,
     30, 429, &V_STONE, "Can be cut on site to the room's size."},
};

static const ptype SCREENS[] = {
    {"walk-in screen 900", "Walk-in screen 900 mm, 8 mm safety glass", 900, 40, 2000, 499, &V_GLASS,
     "Fixed panel with wall profile and stabiliser bar."},
    {"walk-in screen 1200", "Walk-in screen 1200 mm, 8 mm safety glass", 1200, 40, 2000, 599,
     &V_GLASS, "Fixed panel with wall profile and stabiliser bar."},
    {"walk-in screen 1400", "Walk-in screen 1400 mm, 8 mm safety glass", 1400, 40, 2000, 699,
     &V_GLASS, "Fixed panel with wall profile and stabiliser bar."},
    {"corner entry 800 x 800", "Corner entry enclosure 800 x 800 mm, sliding doors", 800, 800, 1950,
     799, &V_GLASS, "Two sliding doors open the whole corner."},
    {"corner entry 900 x 900", "Corner entry enclosure 900 x 900 mm, sliding doors", 900, 900, 1950,
     849, &V_GLASS, "Two sliding doors open the whole corner."},
    {"pivot door 900 for a niche", "Pivot door 900 mm for a niche, 6 mm glass", 900, 40, 1950, 649,
     &V_GLASS, "Opens outwards and inwards; lift-and-lower hinges."},
    {"sliding door 1200", "Sliding door 1200 mm for a niche", 1200, 60, 2000, 899, &V_GLASS,
     "Soft-close rollers, removable for cleaning."},
    {"sliding door 1400", "Sliding door 1400 mm for a niche", 1400, 60, 2000, 999, &V_GLASS,
     "Soft-close rollers, removable for cleaning."},
    {"quadrant enclosure 900 x 900", "Quadrant enclosure 900 x 900 mm, R550", 900, 900, 1950, 1090,
     &V_GLASS, "Curved sliding doors in toughened glass."},
    {"bath screen 800, two panels", "Bath screen 800 mm, two folding panels", 800, 30, 1400, 429,
     &V_GLASS, "Folds flat against the wall."},
};

static const ptype MIRRORS[] = {
    {"mirror 600 x 700", "Mirror 600 x 700 mm, polished edges", 600, 25, 700, 79, &V_MIRROR,
     "Copper-free silver mirror 5 mm on a mounting plate."},
    {"mirror 800 x 700", "Mirror 800 x 700 mm, polished edges", 800, 25, 700, 99, &V_MIRROR,
     "Copper-free silver mirror 5 mm on a mounting plate."},
    {"mirror 1000 x 700", "Mirror 1000 x 700 mm, polished edges", 1000, 25, 700, 129, &V_MIRROR,
     "Copper-free silver mirror 5 mm on a mounting plate."},
    {"mirror 1200 x 700", "Mirror 1200 x 700 mm, polished edges", 1200, 25, 700, 159, &V_MIRROR,
     "Copper-free silver mirror 5 mm on a mounting plate."},
    {"round mirror 600 with black frame", "Round mirror 600 mm, black metal frame", 600, 30, 600,
     149, &V_MIRROR, "Thin powder-coated frame."},
    {"illuminated mirror 800 x 700", "LED mirror 800 x 700 mm, anti-fog pad, IP44", 800, 45, 700,
     429, &V_MIRROR1, "LED light around the edge, touch switch and anti-fog heating."},
    {"illuminated mirror 1200 x 700", "LED mirror 1200 x 700 mm, anti-fog pad, IP44", 1200, 45, 700,
     589, &V_MIRROR1, "LED light around the edge, touch switch and anti-fog heating."},
    {"illuminated round mirror 800", "Round LED mirror 800 mm, IP44", 800, 45, 800, 499, &V_MIRROR1,
     "Indirect LED halo, dimmable."},
};

static const ptype CABINETS[] = {
    {"mirror cabinet 600, 1 door", "Mirror cabinet 600 mm, one door, 2 glass shelves", 600, 150,
     700, 299, &V_CABINET, "Mirrored inside and out; soft-close hinges."},
    {"mirror cabinet 800, 2 doors", "Mirror cabinet 800 mm, two doors, 2 glass shelves", 800, 150,
     700, 389, &V_CABINET, "Mirrored inside and out; soft-close hinges."},
    {"mirror cabinet 1000, 2 doors, LED", "Mirror cabinet 1000 mm, LED light, socket", 1000, 160,
     700, 649, &V_CABINET, "LED light above and below, socket inside."},
    {"mirror cabinet 1200, 3 doors, LED", "Mirror cabinet 1200 mm, three doors, LED light", 1200,
     160, 700, 789, &V_CABINET, "LED light above and below, socket inside."},
    {"mirror cabinet 1300, 3 doors, LED", "Mirror cabinet 1300 mm, three doors, LED light", 1300,
     160, 740, 899, &V_CABINET, "LED light above and below, socket and USB inside."},
    {"recessed mirror cabinet 900", "Recessed mirror cabinet 900 mm, two doors", 900, 100, 700, 990,
     &V_CABINET, "Built into the wall: only 25 mm stand proud."},
    {"mirror cabinet 1400, 3 doors, LED", "Mirror cabinet 1400 mm, three doors, LED, socket", 1400,
     170, 740, 1290, &V_CABINET, "LED light above and below, socket and USB inside."},
};

static const ptype LAMPS[] = {
    {"mirror light LED 600", "LED mirror light 600 mm, 8 W, IP44", 600, 80, 40, 119, &V_LAMP,
     "Mounts on the mirror or the wall above it."},
    {"mirror light LED 900", "LED mirror light 900 mm, 12 W, IP44", 900, 80, 40, 149, &V_LAMP,
     "Mounts on the mirror or the wall above it."},
    {"mirror light LED 1200", "LED mirror light 1200 mm, 16 W, IP44", 1200, 80, 40, 179, &V_LAMP,
     "Mounts on the mirror or the wall above it."},
    {"ceiling light 300", "LED ceiling light 300 mm, 18 W, IP44", 300, 300, 90, 139, &V_LAMP,
     "Opal diffuser, for bathroom zones 1 and 2."},
    {"ceiling light 400, dimmable", "LED ceiling light 400 mm, 24 W, IP44, dimmable", 400, 400, 95,
     219, &V_LAMP, "Opal diffuser, dimmable on a trailing-edge dimmer."},
    {"wall light, two lights", "LED wall light with two shades, 2 x 5 W, IP44", 350, 110, 120, 169,
     &V_LAMP, "Glass shades; mounts beside or above a mirror."},
    {"wall light cylinder, up and down", "LED wall light, up and down, 2 x 4 W, IP44", 80, 100, 300,
     129, &V_LAMP, "Throws light up and down the wall."},
    {"pendant light, opal globe 200", "Pendant light, opal glass globe 200 mm, IP44", 200, 200,
     1200, 249, &V_LAMP, "Suspension adjustable up to 1500 mm."},
    {"recessed downlight IP65", "LED recessed downlight 85 mm, 6 W, IP65", 85, 85, 60, 59, &V_LAMP,
     "For showers: IP65, cut-out 68 mm."},
};

static const ptype RADIATORS[] = {
    {"towel radiator 500 x 800", "Towel radiator 500 x 800 mm, 390 W", 500, 90, 800, 189,
     &V_RADIATOR, "Round tubes; heat output to EN 442 at 75/65/20 C."},
    {"towel radiator 500 x 1200", "Towel radiator 500 x 1200 mm, 590 W", 500, 90, 1200, 249,
     &V_RADIATOR, "Round tubes; heat output to EN 442 at 75/65/20 C."},
    {"towel radiator 600 x 1200", "Towel radiator 600 x 1200 mm, 690 W", 600, 90, 1200, 279,
     &V_RADIATOR, "Round tubes; heat output to EN 442 at 75/65/20 C."},
    {"towel radiator 600 x 1775", "Towel radiator 600 x 1775 mm, 1010 W", 600, 90, 1775, 389,
     &V_RADIATOR, "Round tubes; heat output to EN 442 at 75/65/20 C."},
    {"electric towel radiator 450 x 800", "Electric towel radiator 450 x 800 mm, 300 W, timer", 450,
     110, 800, 349, &V_RADIATOR, "Plug-in heating element with a 2-hour timer."},
    {"flat panel radiator 500 x 1500", "Flat panel radiator 500 x 1500 mm, 720 W", 500, 100, 1500,
     690, &V_RADIATOR, "A smooth front panel with a towel rail."},
    {"designer radiator 600 x 1800", "Designer radiator 600 x 1800 mm, vertical tubes, 980 W", 600,
     100, 1800, 1190, &V_RADIATOR, "Vertical flat tubes, centre connection."},
};

static const ptype VANITIES[] = {
    {"vanity unit 600, 1 drawer", "Vanity unit 600 mm, one drawer, for basins of 600 mm", 600, 460,
     520, 449, &V_FURNITURE, "Full-extension drawer with soft close and siphon cut-out."},
    {"vanity unit 800, 2 drawers", "Vanity unit 800 mm, two drawers", 800, 460, 520, 599,
     &V_FURNITURE, "Full-extension drawers with soft close and siphon cut-out."},
    {"vanity unit 1000, 2 drawers", "Vanity unit 1000 mm, two drawers", 1000, 460, 520, 749,
     &V_FURNITURE, "Full-extension drawers with soft close and siphon cut-out."},
    {"vanity unit 1200 for a double basin", "Vanity unit 1200 mm, two drawers, double basin", 1200,
     460, 520, 949, &V_FURNITURE, "Two siphon cut-outs for a double washbasin."},
    {"tall cabinet 350", "Tall cabinet 350 x 330 x 1700 mm, one door, laundry basket", 350, 330,
     1700, 529, &V_FURNITURE, "Door hinged left or right; four glass shelves."},
    {"mid-height cabinet 400", "Mid-height cabinet 400 x 330 x 800 mm, one door", 400, 330, 800,
     349, &V_FURNITURE, "Door hinged left or right."},
    {"wall cabinet 350", "Wall cabinet 350 x 200 x 700 mm, glass shelves", 350, 200, 700, 279,
     &V_FURNITURE, "Hangs beside the mirror."},
    {"washstand 1000 with metal frame", "Washstand 1000 mm, metal frame with towel bar", 1000, 500,
     850, 1290, &V_FURNITURE, "Open frame, shelf below, for countertop bowls."},
};

static const ptype ACCESSORIES[] = {
    {"toilet roll holder", "Toilet roll holder without cover", 150, 80, 80, 39, &V_METAL3,
     "Solid brass, concealed fixing."},
    {"spare toilet roll holder", "Spare toilet roll holder for one roll", 60, 100, 150, 35,
     &V_METAL3, "Solid brass, concealed fixing."},
    {"towel bar 600", "Towel bar 600 mm", 600, 75, 50, 59, &V_METAL3,
     "Solid brass, concealed fixing."},
    {"towel bar 800", "Towel bar 800 mm", 800, 75, 50, 69, &V_METAL3,
     "Solid brass, concealed fixing."},
    {"towel ring", "Towel ring 200 mm", 200, 60, 180, 45, &V_METAL3,
     "Solid brass, concealed fixing."},
    {"robe hook", "Single robe hook", 40, 50, 40, 19, &V_METAL3, "Solid brass, concealed fixing."},
    {"soap dispenser, glass", "Soap dispenser, satin glass, 200 ml", 90, 110, 180, 49, &V_METAL3,
     "Wall-mounted; the glass lifts out for refilling."},
    {"toothbrush tumbler, glass", "Toothbrush tumbler, satin glass", 90, 110, 110, 39, &V_METAL3,
     "Wall-mounted; the glass lifts out for cleaning."},
    {"glass shelf 600", "Glass shelf 600 mm, 8 mm safety glass", 600, 130, 40, 79, &V_METAL3,
     "Metal brackets in the finish of the series."},
    {"WC brush set, wall-mounted", "Wall-mounted WC brush set, satin glass", 100, 130, 380, 69,
     &V_METAL3, "Replacement brush heads available."},
    {"grab bar 600", "Grab bar 600 mm, 32 mm, to DIN 18040", 600, 80, 80, 89, &V_METAL2,
     "Carries 150 kg when fixed to a solid wall."},
    {"shower basket, corner", "Corner shower basket 230 mm", 230, 230, 60, 59, &V_METAL3,
     "Drains freely; fixed with screws or glue."},
    {"folding shower seat", "Folding shower seat 400 x 400 mm, 150 kg", 400, 400, 80, 249,
     &V_METAL2, "Folds up against the wall when not needed."},
};

static const ptype SEATS[] = {
    {"WC seat with soft close", "WC seat with soft close, quick release", 370, 450, 50, 89,
     &V_CERAMIC1, "Duroplast seat and lid; lift off for cleaning."},
};

/* ---- manufacturers and their ranges -------------------------------------------------------- */

typedef struct maker {
    const char *name;
    const char *gs1; /* 7-digit (invented) GS1 company prefix */
    const char *article_fmt;
    int next_item;
    int next_article;
} maker;

enum {
    AQUAVERA,
    BRUNNHOFF,
    CERANA,
    NORDKERAM,
    VITRELUX,
    LUMETTA,
    CALORIX,
    HOLMWOOD,
    TERRAZZA,
    ALTENA,
    SOLARA,
    MAKER_COUNT
};

static maker makers[MAKER_COUNT] = {
    [AQUAVERA] = {"Aquavera", "4051234", "%05d000", 0, 31000},
    [BRUNNHOFF] = {"Brunnhoff", "4062345", "BH-%04d", 0, 2100},
    [CERANA] = {"Cerana", "8031234", "CE%04d01", 0, 4100},
    [NORDKERAM] = {"Nordkeram", "7351234", "NK-%d.00", 0, 51200},
    [VITRELUX] = {"Vitrelux", "3661234", "VX%05d", 0, 20010},
    [LUMETTA] = {"Lumetta", "8056789", "LU-%03d.10", 0, 300},
    [CALORIX] = {"Calorix", "8712345", "CX%04d-0", 0, 7100},
    [HOLMWOOD] = {"Holmwood", "5051234", "HW%04d", 0, 1500},
    [TERRAZZA] = {"Terrazza Ceramiche", "8019876", "TZ%05d", 0, 61000},
    [ALTENA] = {"Fliesenwerk Altena", "4045678", "FA-%05d", 0, 10100},
    [SOLARA] = {"Azulejos Solara", "8431234", "SOL%04d", 0, 3100},
};

static void gtin13(const maker *m, int item, char out[14])
{
    snprintf(out, 14, "%s%05d", m->gs1, item);
    int sum = 0;
    for (int i = 0; i < 12; i++)
        sum += (out[i] - '0') * (i % 2 ? 3 : 1);
    out[12] = (char)('0' + (10 - sum % 10) % 10);
    out[13] = 0;
}

/* ---- writing a product --------------------------------------------------------------------- */

typedef struct tile_data {
    const char *type, *surface, *calibre;
    int nominal_w, nominal_h;
    double grout, thickness;
    int pieces;
    char texture[160];
} tile_data;

typedef struct product {
    const maker *m;
    char article[48], gtin[16];
    const char *category, *series;
    char name[200], short_text[420], long_text[1200];
    double w, d, h;
    long price_cents;
    const char *unit;
    char discount_group[8];
    const material *variants[4];
    int variant_count;
    const tile_data *tile;
    int has_model;        /* 1: the model column names the generated GLB (make_models.c) */
    double mount_h;       /* mounting_height_mm, when mount_to is set */
    const char *mount_to; /* "bottom", "top", "rim", "seat" or NULL */
    char companions[200];
} product;

/* The model path, as cat_model_file_name() in catalog/src/gen_path.c makes it (the test
 * catalog.test_model_shipped checks that both agree): "models/<maker>/<article>.glb", each
 * lower-cased with every run of other characters than a-z, 0-9 turned into one '-'. */
static void put_slug(FILE *f, const char *s)
{
    int dash = 0, any = 0;
    for (; *s; s++) {
        char ch = (char)(*s >= 'A' && *s <= 'Z' ? *s - 'A' + 'a' : *s);
        if ((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9')) {
            if (dash && any)
                fputc('-', f);
            fputc(ch, f);
            dash = 0;
            any = 1;
        } else {
            dash = 1;
        }
    }
}

static void write_rows(FILE *f, const product *p)
{
    int rows = p->variant_count ? p->variant_count : 1;
    for (int v = 0; v < rows; v++) {
        put_text(f, p->m->name);
        fputc(',', f);
        put_text(f, p->article);
        fputc(',', f);
        fputs(p->gtin, f);
        fprintf(f, ",%s,", p->category);
        put_text(f, p->series);
        fputc(',', f);
        put_text(f, p->name);
        fputc(',', f);
        put_text(f, p->short_text);
        fputc(',', f);
        put_text(f, p->long_text);
        fputc(',', f);
        put_num(f, p->w);
        fputc(',', f);
        put_num(f, p->d);
        fputc(',', f);
        put_num(f, p->h);
        fputc(',', f);
        put_money(f, p->price_cents);
        fprintf(f, ",EUR,19,%s,%s,", p->unit, p->discount_group);
        if (p->has_model) {
            fputs("models/", f);
            put_slug(f, p->m->name);
            fputc('/', f);
            put_slug(f, p->article);
            fputs(".glb", f);
        }
        if (p->variant_count) {
            const material *m = p->variants[v];
            fprintf(f, ",%s,", m->code);
            put_text(f, m->name);
            fputc(',', f);
            /* Surcharges round to whole euros. */
            long surcharge = (p->price_cents * m->surcharge_pct / 100 + 50) / 100 * 100;
            put_money(f, surcharge);
            fputc(',', f);
            put_rgb(f, m->diffuse); /* ambient = diffuse */
            fputc(',', f);
            put_rgb(f, m->diffuse);
            fputc(',', f);
            put_rgb(f, m->specular);
            fputc(',', f);
            put_rgb(f, m->emissive);
            fputc(',', f);
            put_num(f, m->shininess);
            fputc(',', f);
            put_num(f, m->kr);
            fputc(',', f);
            put_num(f, m->gloss);
            fprintf(f, ",%s,", m->blend);
            put_num(f, m->transparency);
            fputc(',', f);
            put_num(f, m->ior);
        } else {
            fputs(",,,,,,,,,,,,,", f);
        }
        const tile_data *t = p->tile;
        if (t) {
            double area = t->nominal_w * (double)t->nominal_h / 1e6;
            fprintf(f, ",%s,%d,%d,", t->type, t->nominal_w, t->nominal_h);
            put_num(f, t->nominal_w - t->grout);
            fputc(',', f);
            put_num(f, t->nominal_h - t->grout);
            fputc(',', f);
            put_num(f, t->grout);
            fputc(',', f);
            put_num(f, t->thickness);
            fprintf(f, ",%s,%s,", t->calibre, t->surface);
            put_num(f, round(t->pieces * area * 1000) / 1000);
            fprintf(f, ",%d,%s,", t->pieces, t->texture);
        } else {
            fputs(",,,,,,,,,,,,,", f); /* 12 empty tile columns */
        }
        if (p->mount_to) {
            put_num(f, p->mount_h);
            fprintf(f, ",%s,", p->mount_to);
        } else {
            fputs(",,", f);
        }
        put_text(f, p->companions);
        /* pattern, grain */
        const char *pattern = p->variant_count ? p->variants[v]->pattern : NULL;
        fprintf(f, ",%s,\n", pattern ? pattern : "");
    }
}

static void new_article(maker *m, product *p)
{
    snprintf(p->article, sizeof p->article, m->article_fmt, m->next_article);
    m->next_article += 1 + rng_int(3);
    gtin13(m, ++m->next_item, p->gtin);
    p->m = m;
}

/* List price: base x factor, rounded to whole euros ending in 9 above 100, to 0.90 below. */
static long list_price(double euro)
{
    if (euro >= 100)
        return ((long)(euro / 10 + 0.5) * 10 - 1) * 100;
    if (euro >= 20)
        return (long)(euro + 0.5) * 100 - 10;
    return (long)(euro * 10 + 0.5) * 10;
}

static const char *const category_text[] = {
    "taps_mixers",     "Made of brass with a multilayer finish; tested to EN 817.",
    "shower_sets",     "Easy-clean nozzles; flow limiter included.",
    "basins",          "Vitreous china, fired at 1250 C; fixings included.",
    "wcs_bidets",      "Vitreous china; fixings included.",
    "baths",           "Feet and waste ordered separately; 10-year warranty on the shell.",
    "shower_trays",    "Slip resistance class C (DIN 51097); waste 90 mm ordered separately.",
    "shower_screens",  "Safety glass to EN 12150 with an easy-clean coating.",
    "mirrors",         "Moisture-resistant edge sealing.",
    "mirror_cabinets", "Aluminium body, moisture-resistant.",
    "lamps",           "Class II, IP rating for bathroom zones per IEC 60364-7-701.",
    "towel_radiators", "Connections 1/2 inch, 50 mm centres; brackets included.",
    "vanity_units",    "Moisture-resistant MDF, 20 mm fronts; wall fixings included.",
    "accessories",     "Fixings included.",
};

static const char *category_sentence(const char *category)
{
    for (size_t i = 0; i + 1 < sizeof category_text / sizeof category_text[0]; i += 2)
        if (!strcmp(category_text[i], category))
            return category_text[i + 1];
    return "";
}

/* Writes `count` products of the types (picked from `first`, cycling) for one series. */
/* ---- mounting heights and companions (docs/catalog.md "Mounting heights and companions") ---- */

/* The products written so far, for a vanity unit's companions. */
#define N_MADE 512
typedef struct made {
    const char *maker, *category, *series;
    char article[48], name[200];
    double w, h;
} made;
static made made_list[N_MADE];
static int made_count;

static void remember(const product *p)
{
    if (made_count < N_MADE) {
        made *m = &made_list[made_count++];
        m->maker = p->m->name;
        m->category = p->category;
        m->series = p->series;
        snprintf(m->article, sizeof m->article, "%s", p->article);
        snprintf(m->name, sizeof m->name, "%s", p->name);
        m->w = p->w;
        m->h = p->h;
    }
}

/* The first product written of a category whose name holds `word` and, when w > 0, of that
 * width; one of maker and series first when given. */
static const made *find_made(const char *category, const char *word, double w, const char *maker,
                             const char *series)
{
    for (int pass = maker ? 0 : 1; pass < 2; pass++)
        for (int i = 0; i < made_count; i++) {
            const made *m = &made_list[i];
            if (strcmp(m->category, category) || !strstr(m->name, word) || (w > 0 && m->w != w))
                continue;
            if (pass == 0 && (strcmp(m->maker, maker) || strcmp(m->series, series)))
                continue;
            return m;
        }
    return NULL;
}

static void add_companion(product *p, const made *m)
{
    size_t n = strlen(p->companions);
    if (m)
        snprintf(p->companions + n, sizeof p->companions - n, "%s%s%s%s", n ? ";" : "",
                 strcmp(m->maker, p->m->name) ? m->maker : "",
                 strcmp(m->maker, p->m->name) ? ":" : "", m->article);
}

/* The trade's heights (DOMAIN.md "Typical sizes"): a basin's rim at 850, a WC's seat at 420
 * (460-480 accessible: 470), a floor-standing WC on the floor, a mirror's underside at 1150, a
 * towel radiator's at 150. A vanity unit for a basin comes with the series' basin of its width
 * (else any maker's), a basin mixer and a mirror of its width, and its top where that basin's
 * rim is at 850. */
static void mounting(product *p)
{
    const char *c = p->category;
    if (!strcmp(c, "basins")) {
        p->mount_to = "rim";
        p->mount_h = 850;
    } else if (!strcmp(c, "wcs_bidets")) {
        int floor = strstr(p->name, "close-coupled") || strstr(p->name, "back-to-wall");
        p->mount_to = floor ? "bottom" : "seat";
        p->mount_h = floor ? 0 : strstr(p->name, "accessible") ? 470 : 420;
    } else if (!strcmp(c, "mirrors") || !strcmp(c, "mirror_cabinets")) {
        p->mount_to = "bottom";
        p->mount_h = 1150;
    } else if (!strcmp(c, "towel_radiators")) {
        p->mount_to = "bottom";
        p->mount_h = 150;
    } else if (!strcmp(c, "vanity_units") && strstr(p->name, "vanity unit")) {
        int twin = strstr(p->name, "double") != NULL;
        const made *basin = find_made("basins", twin ? "double washbasin" : "washbasin", p->w,
                                      p->m->name, p->series);
        add_companion(p, basin);
        add_companion(p, find_made("taps_mixers", "basin mixer", 0, NULL, NULL));
        add_companion(p, find_made("mirrors", "mirror", p->w, NULL, NULL));
        if (basin) {
            p->mount_to = "top";
            p->mount_h = 850 - basin->h;
        }
    }
}

static int series_products(FILE *f, int maker_id, const char *category, const char *series,
                           double price_factor, const ptype *types, int type_count, int first,
                           int count, const char *series_text)
{
    maker *m = &makers[maker_id];
    for (int i = 0; i < count; i++) {
        const ptype *t = &types[(first + i) % type_count];
        product p;
        memset(&p, 0, sizeof p);
        new_article(m, &p);
        p.category = category;
        p.series = series;
        snprintf(p.name, sizeof p.name, "%s %s", series, t->name);
        snprintf(p.short_text, sizeof p.short_text, "%s", t->short_text);
        snprintf(p.long_text, sizeof p.long_text, "%s %s %s", series_text, t->long_text,
                 category_sentence(category));
        p.w = t->w;
        p.d = t->d;
        p.h = t->h;
        p.price_cents = list_price(t->price * price_factor);
        p.unit = "piece";
        snprintf(p.discount_group, sizeof p.discount_group, "%c%d", 'A' + maker_id % 4,
                 1 + (int)(price_factor * 2) % 3);
        for (int v = 0; v < 4 && t->variants->m[v]; v++)
            p.variants[p.variant_count++] = t->variants->m[v];
        p.has_model = 1;
        mounting(&p);
        write_rows(f, &p);
        remember(&p);
    }
    return count;
}

typedef struct range {
    int maker;
    const char *category, *series, *text;
    double factor;
    const ptype *types;
    int type_count, first, count;
} range;

#define N(a) (int)(sizeof a / sizeof a[0])

static const range fixture_ranges[] = {
    /* taps: 56 */
    {AQUAVERA, "taps_mixers", "Linea", "Linea: slim cylindrical bodies with a flat lever.", 1.0,
     TAPS, N(TAPS), 0, 7},
    {AQUAVERA, "taps_mixers", "Orbis", "Orbis: round forms, soft edges.", 1.25, TAPS, N(TAPS), 3,
     7},
    {AQUAVERA, "taps_mixers", "Quadro", "Quadro: square profiles, precise edges.", 1.4, TAPS,
     N(TAPS), 6, 7},
    {AQUAVERA, "taps_mixers", "Sereno", "Sereno: a timeless classic with cross handles.", 1.1, TAPS,
     N(TAPS), 9, 7},
    {BRUNNHOFF, "taps_mixers", "Solano", "Solano: the value range for every bathroom.", 0.8, TAPS,
     N(TAPS), 1, 7},
    {BRUNNHOFF, "taps_mixers", "Kubik", "Kubik: cubic bodies, flat spouts.", 1.05, TAPS, N(TAPS), 4,
     7},
    {BRUNNHOFF, "taps_mixers", "Alster", "Alster: tapered spouts, knurled levers.", 1.3, TAPS,
     N(TAPS), 8, 7},
    {BRUNNHOFF, "taps_mixers", "Merano", "Merano: Italian styling, long levers.", 1.15, TAPS,
     N(TAPS), 11, 7},
    /* shower sets: 24 */
    {AQUAVERA, "shower_sets", "Linea", "Linea: slim cylindrical bodies with a flat lever.", 1.0,
     SHOWERS, N(SHOWERS), 0, 6},
    {AQUAVERA, "shower_sets", "Quadro", "Quadro: square profiles, precise edges.", 1.4, SHOWERS,
     N(SHOWERS), 0, 6},
    {BRUNNHOFF, "shower_sets", "Solano", "Solano: the value range for every bathroom.", 0.8,
     SHOWERS, N(SHOWERS), 0, 6},
    {BRUNNHOFF, "shower_sets", "Kubik", "Kubik: cubic bodies, flat spouts.", 1.05, SHOWERS,
     N(SHOWERS), 0, 6},
    /* basins: 31 */
    {CERANA, "basins", "Arco", "Arco: arched bowls with thin rims.", 1.2, BASINS, N(BASINS), 0, 6},
    {CERANA, "basins", "Piano", "Piano: flat, geometric forms.", 1.0, BASINS, N(BASINS), 2, 5},
    {CERANA, "basins", "Vela", "Vela: soft, sail-like curves.", 1.5, BASINS, N(BASINS), 5, 5},
    {NORDKERAM, "basins", "Fjord", "Fjord: Scandinavian simplicity.", 0.9, BASINS, N(BASINS), 0, 5},
    {NORDKERAM, "basins", "Stilla", "Stilla: quiet lines, generous bowls.", 1.1, BASINS, N(BASINS),
     4, 5},
    {NORDKERAM, "basins", "Vik", "Vik: compact solutions for small rooms.", 0.8, BASINS, N(BASINS),
     5, 5},
    /* WCs and bidets: 30 */
    {CERANA, "wcs_bidets", "Arco", "Arco: arched bowls with thin rims.", 1.2, WCS, N(WCS), 0, 6},
    {CERANA, "wcs_bidets", "Piano", "Piano: flat, geometric forms.", 1.0, WCS, N(WCS), 1, 6},
    {CERANA, "wcs_bidets", "Vela", "Vela: soft, sail-like curves.", 1.5, WCS, N(WCS), 4, 6},
    {NORDKERAM, "wcs_bidets", "Fjord", "Fjord: Scandinavian simplicity.", 0.9, WCS, N(WCS), 0, 6},
    {NORDKERAM, "wcs_bidets", "Stilla", "Stilla: quiet lines, generous bowls.", 1.1, WCS, N(WCS), 3,
     6},
    /* baths: 22 */
    {NORDKERAM, "baths", "Fjord", "Fjord: Scandinavian simplicity.", 0.9, BATHS, N(BATHS), 0, 6},
    {NORDKERAM, "baths", "Stilla", "Stilla: quiet lines, generous bowls.", 1.1, BATHS, N(BATHS), 3,
     5},
    {NORDKERAM, "baths", "Stal", "Stal: enamelled titanium steel.", 1.0, STEEL_BATHS,
     N(STEEL_BATHS), 0, 3},
    {CERANA, "baths", "Arco", "Arco: arched bowls with thin rims.", 1.2, BATHS, N(BATHS), 0, 4},
    {CERANA, "baths", "Vela", "Vela: soft, sail-like curves.", 1.5, BATHS, N(BATHS), 4, 4},
    /* shower trays: 20 */
    {NORDKERAM, "shower_trays", "Plan", "Plan: mineral cast, flush with the floor.", 1.0, TRAYS,
     N(TRAYS), 0, 6},
    {NORDKERAM, "shower_trays", "Stone", "Stone: a slate-like surface.", 1.2, TRAYS, N(TRAYS), 3,
     4},
    {CERANA, "shower_trays", "Piano", "Piano: flat, geometric forms.", 1.0, TRAYS, N(TRAYS), 0, 5},
    {CERANA, "shower_trays", "Vela", "Vela: soft, sail-like curves.", 1.5, TRAYS, N(TRAYS), 2, 5},
    /* shower screens: 20 */
    {VITRELUX, "shower_screens", "Clara", "Clara: frameless 8 mm glass.", 1.0, SCREENS, N(SCREENS),
     0, 10},
    {VITRELUX, "shower_screens", "Nivo", "Nivo: slim framed profiles.", 0.85, SCREENS, N(SCREENS),
     0, 10},
    /* mirrors: 16 */
    {VITRELUX, "mirrors", "Clara", "Clara: frameless 8 mm glass.", 1.0, MIRRORS, N(MIRRORS), 0, 5},
    {VITRELUX, "mirrors", "Reflex", "Reflex: mirrors and cabinets with bevelled edges.", 1.2,
     MIRRORS, N(MIRRORS), 0, 3},
    {LUMETTA, "mirrors", "Aura", "Aura: warm, even light.", 1.0, MIRRORS, N(MIRRORS), 5, 3},
    {LUMETTA, "mirrors", "Luna", "Luna: round forms, indirect light.", 1.2, MIRRORS, N(MIRRORS), 4,
     5},
    /* mirror cabinets: 14 */
    {VITRELUX, "mirror_cabinets", "Reflex", "Reflex: mirrors and cabinets with bevelled edges.",
     1.0, CABINETS, N(CABINETS), 0, 7},
    {HOLMWOOD, "mirror_cabinets", "Kensington", "Kensington: panelled fronts, brass details.", 1.3,
     CABINETS, N(CABINETS), 0, 4},
    {HOLMWOOD, "mirror_cabinets", "Ashby", "Ashby: plain fronts, push-to-open.", 1.1, CABINETS,
     N(CABINETS), 3, 3},
    /* lamps: 20 */
    {LUMETTA, "lamps", "Aura", "Aura: warm, even light.", 1.0, LAMPS, N(LAMPS), 0, 5},
    {LUMETTA, "lamps", "Luna", "Luna: round forms, indirect light.", 1.2, LAMPS, N(LAMPS), 3, 5},
    {LUMETTA, "lamps", "Stella", "Stella: crystal-clear glass.", 1.4, LAMPS, N(LAMPS), 5, 5},
    {LUMETTA, "lamps", "Orbita", "Orbita: opal globes and rings.", 1.1, LAMPS, N(LAMPS), 7, 5},
    /* towel radiators: 17 */
    {CALORIX, "towel_radiators", "Ladder", "Ladder: round tubes, the classic.", 1.0, RADIATORS,
     N(RADIATORS), 0, 5},
    {CALORIX, "towel_radiators", "Plano", "Plano: flat tubes and panels.", 1.2, RADIATORS,
     N(RADIATORS), 3, 4},
    {CALORIX, "towel_radiators", "Tubo", "Tubo: slender vertical tubes.", 1.35, RADIATORS,
     N(RADIATORS), 5, 4},
    {BRUNNHOFF, "towel_radiators", "Alster", "Alster: tapered spouts, knurled levers.", 1.1,
     RADIATORS, N(RADIATORS), 0, 4},
    /* vanity units: 22 */
    {CERANA, "vanity_units", "Arco", "Arco: arched bowls with thin rims.", 1.2, VANITIES,
     N(VANITIES), 0, 4},
    {CERANA, "vanity_units", "Vela", "Vela: soft, sail-like curves.", 1.5, VANITIES, N(VANITIES), 0,
     4},
    {HOLMWOOD, "vanity_units", "Kensington", "Kensington: panelled fronts, brass details.", 1.3,
     VANITIES, N(VANITIES), 0, 7},
    {HOLMWOOD, "vanity_units", "Ashby", "Ashby: plain fronts, push-to-open.", 1.1, VANITIES,
     N(VANITIES), 1, 7},
    /* accessories: 34 */
    {AQUAVERA, "accessories", "Linea", "Linea: slim cylindrical bodies with a flat lever.", 1.0,
     ACCESSORIES, N(ACCESSORIES), 0, 8},
    {AQUAVERA, "accessories", "Orbis", "Orbis: round forms, soft edges.", 1.25, ACCESSORIES,
     N(ACCESSORIES), 4, 8},
    {BRUNNHOFF, "accessories", "Kubik", "Kubik: cubic bodies, flat spouts.", 0.9, ACCESSORIES,
     N(ACCESSORIES), 0, 8},
    {HOLMWOOD, "accessories", "Kensington", "Kensington: panelled fronts, brass details.", 1.3,
     ACCESSORIES, N(ACCESSORIES), 2, 8},
    {CERANA, "accessories", "Arco", "Arco: arched bowls with thin rims.", 1.2, SEATS, N(SEATS), 0,
     1},
    {CERANA, "accessories", "Piano", "Piano: flat, geometric forms.", 1.0, SEATS, N(SEATS), 0, 1},
};

/* ---- tiles ------------------------------------------------------------------------------- */

typedef struct colour {
    const char *name, *code;
    double rgb[3];
} colour;

typedef struct tile_series {
    int maker;
    const char *series, *kind; /* kind: "porcelain", "wall", "handmade" */
    const char *type, *surface;
    const colour *colours;
    int colour_count;
    const int (*formats)[2];
    int format_count;
    double euro_per_unit; /* per m2 for UNI, per piece otherwise, per box for unit box */
    const char *unit;
    double grout; /* 0: 2 mm up to 150 mm edges, else 3 mm */
    const char *text;
} tile_series;

static const colour PIETRA[] = {{"Grigio", "GR", {0.52, 0.52, 0.5}},
                                {"Antracite", "AN", {0.2, 0.2, 0.21}},
                                {"Beige", "BE", {0.72, 0.65, 0.55}},
                                {"Bianco", "BI", {0.86, 0.85, 0.82}}};
static const colour PIETRA_R11[] = {{"Grigio", "GR", {0.5, 0.5, 0.48}},
                                    {"Antracite", "AN", {0.19, 0.19, 0.2}}};
static const colour PIETRA_MOSAIC[] = {{"Grigio", "GR", {0.52, 0.52, 0.5}}};
static const colour CEMENTO[] = {{"Grigio chiaro", "GC", {0.66, 0.66, 0.64}},
                                 {"Grigio scuro", "GS", {0.36, 0.36, 0.35}},
                                 {"Sabbia", "SA", {0.7, 0.64, 0.55}}};
static const colour CALACATTA[] = {{"Bianco", "BI", {0.9, 0.89, 0.87}}};
static const colour CALACATTA_DEK[] = {{"Oro", "OR", {0.88, 0.84, 0.75}}};
static const colour ROVERE[] = {{"Naturale", "NA", {0.62, 0.47, 0.32}},
                                {"Miele", "MI", {0.7, 0.52, 0.3}},
                                {"Grigio", "GR", {0.5, 0.47, 0.43}}};
static const colour WEISS[] = {{"Weiss", "WS", {0.93, 0.93, 0.92}}};
static const colour PASTELL[] = {{"Salbei", "SB", {0.66, 0.73, 0.63}},
                                 {"Taubenblau", "TB", {0.58, 0.65, 0.72}},
                                 {"Rose", "RO", {0.86, 0.72, 0.7}},
                                 {"Sand", "SD", {0.82, 0.77, 0.68}}};
static const colour PASTELL2[] = {{"Salbei", "SB", {0.66, 0.73, 0.63}},
                                  {"Taubenblau", "TB", {0.58, 0.65, 0.72}}};
static const colour METRO[] = {{"Weiss", "WS", {0.93, 0.93, 0.92}},
                               {"Schwarz", "SW", {0.06, 0.06, 0.06}},
                               {"Mint", "MT", {0.68, 0.83, 0.76}}};
static const colour BORDERS[] = {{"Silber", "SI", {0.75, 0.75, 0.76}},
                                 {"Salbei", "SB", {0.66, 0.73, 0.63}},
                                 {"Taubenblau", "TB", {0.58, 0.65, 0.72}}};
static const colour DECORS[] = {{"Blatt", "BL", {0.8, 0.84, 0.78}},
                                {"Linie", "LI", {0.88, 0.88, 0.86}},
                                {"Welle", "WE", {0.7, 0.76, 0.8}}};
static const colour INSERTS[] = {{"Glas klar", "GK", {0.8, 0.88, 0.9}},
                                 {"Glas gold", "GG", {0.85, 0.7, 0.4}}};
static const colour ZELLIGE[] = {{"Blanco", "BL", {0.9, 0.89, 0.85}},
                                 {"Verde", "VE", {0.25, 0.45, 0.38}},
                                 {"Azul", "AZ", {0.18, 0.32, 0.55}},
                                 {"Terracota", "TE", {0.66, 0.38, 0.26}}};
static const colour HIDRAULICO_DEK[] = {{"Estrella", "ES", {0.55, 0.55, 0.55}},
                                        {"Flor", "FL", {0.6, 0.5, 0.45}},
                                        {"Geometrico", "GE", {0.45, 0.5, 0.55}}};
static const colour HIDRAULICO[] = {{"Liso gris", "LG", {0.55, 0.55, 0.54}},
                                    {"Liso blanco", "LB", {0.88, 0.87, 0.84}}};
static const colour TERRACOTA[] = {{"Natural", "NA", {0.7, 0.42, 0.28}},
                                   {"Rojo", "RO", {0.6, 0.3, 0.22}}};
static const colour TERRACOTA_RUSTIC[] = {{"Natural", "NA", {0.7, 0.42, 0.28}}};
static const colour MAR[] = {{"Blanco", "BL", {0.92, 0.92, 0.9}},
                             {"Celeste", "CE", {0.62, 0.76, 0.86}},
                             {"Turquesa", "TU", {0.25, 0.6, 0.62}}};
static const colour MAR_BOR[] = {{"Cenefa azul", "CA", {0.2, 0.35, 0.6}}};
static const colour MAR_EIN[] = {{"Taco azul", "TA", {0.2, 0.35, 0.6}}};

static const int F_PORCELAIN[][2] = {{300, 600}, {600, 600}, {600, 1200}};
static const int F_300[][2] = {{300, 300}};
static const int F_CEMENTO[][2] = {{600, 600}, {600, 1200}, {800, 800}};
static const int F_CALACATTA[][2] = {{300, 600}, {600, 1200}, {1200, 1200}};
static const int F_DEK_300_600[][2] = {{300, 600}};
static const int F_WOOD[][2] = {{200, 1200}};
static const int F_WEISS[][2] = {{100, 100}, {150, 150}, {200, 200}, {200, 333}, {300, 600}};
static const int F_200[][2] = {{200, 200}};
static const int F_300_600[][2] = {{300, 600}};
static const int F_METRO[][2] = {{75, 150}};
static const int F_BORDER[][2] = {{50, 300}};
static const int F_100[][2] = {{100, 100}};
static const int F_150[][2] = {{150, 150}};
static const int F_MAR_BOR[][2] = {{50, 150}};
static const int F_50[][2] = {{50, 50}};

#define C(a) a, N(a)
static const tile_series tile_ranges[] = {
    {TERRAZZA, "Pietra", "porcelain", "UNI", "matt", C(PIETRA), C(F_PORCELAIN), 39.9, "m2", 0,
     "Pietra: a quiet limestone look."},
    {TERRAZZA, "Pietra R11", "porcelain", "UNI", "structured", C(PIETRA_R11), C(F_300), 36.9, "m2",
     0, "Pietra R11: the anti-slip version for showers and terraces."},
    {TERRAZZA, "Pietra Mosaico", "porcelain", "UNI", "matt", C(PIETRA_MOSAIC), C(F_300), 89.9,
     "box", 0, "Pietra Mosaico: 50 x 50 mm chips on a 300 x 300 mm net."},
    {TERRAZZA, "Cemento", "porcelain", "UNI", "matt", C(CEMENTO), C(F_CEMENTO), 44.9, "m2", 0,
     "Cemento: the look of polished concrete."},
    {TERRAZZA, "Calacatta", "porcelain", "UNI", "glossy", C(CALACATTA), C(F_CALACATTA), 74.9, "m2",
     0, "Calacatta: white marble with grey veins, polished."},
    {TERRAZZA, "Calacatta Decoro", "porcelain", "DEK", "glossy", C(CALACATTA_DEK), C(F_DEK_300_600),
     29.9, "piece", 0, "Calacatta Decoro: gold veins for accents."},
    {TERRAZZA, "Rovere", "porcelain", "UNI", "structured", C(ROVERE), C(F_WOOD), 54.9, "m2", 0,
     "Rovere: oak planks in porcelain, for floors with underfloor heating."},
    {ALTENA, "Weiss", "wall", "UNI", "glossy", C(WEISS), C(F_WEISS), 21.9, "m2", 0,
     "Weiss: the white wall tile, glossy."},
    {ALTENA, "Weiss matt", "wall", "UNI", "matt", C(WEISS), C(F_300_600), 24.9, "m2", 0,
     "Weiss matt: the white wall tile with a silk-matt glaze."},
    {ALTENA, "Pastell", "wall", "UNI", "glossy", C(PASTELL), C(F_200), 27.9, "m2", 0,
     "Pastell: soft colours for walls."},
    {ALTENA, "Pastell", "wall", "UNI", "matt", C(PASTELL2), C(F_300_600), 32.9, "m2", 0,
     "Pastell: soft colours for walls."},
    {ALTENA, "Metro", "wall", "UNI", "glossy", C(METRO), C(F_METRO), 39.9, "box", 0,
     "Metro: bevelled subway tiles."},
    {ALTENA, "Bordure", "wall", "BOR", "glossy", C(BORDERS), C(F_BORDER), 8.9, "piece", 0,
     "Bordure: borders for the 300 x 600 mm wall tiles."},
    {ALTENA, "Dekor", "wall", "DEK", "glossy", C(DECORS), C(F_300_600), 18.9, "piece", 0,
     "Dekor: printed decors for the 300 x 600 mm wall tiles."},
    {ALTENA, "Einleger", "wall", "EIN", "glossy", C(INSERTS), C(F_100), 5.9, "piece", 0,
     "Einleger: glass inserts for the 100 x 100 mm grid."},
    {SOLARA, "Zellige", "handmade", "UNI", "glossy", C(ZELLIGE), C(F_100), 69.9, "m2", 0,
     "Zellige: hand-glazed, every tile a little different."},
    {SOLARA, "Hidraulico", "handmade", "DEK", "matt", C(HIDRAULICO_DEK), C(F_200), 4.9, "piece", 0,
     "Hidraulico: encaustic patterns from the Mediterranean."},
    {SOLARA, "Hidraulico", "handmade", "UNI", "matt", C(HIDRAULICO), C(F_200), 49.9, "m2", 0,
     "Hidraulico: encaustic patterns from the Mediterranean."},
    {SOLARA, "Terracota", "handmade", "UNI", "matt", C(TERRACOTA), C(F_150), 34.9, "m2", 0,
     "Terracota: fired clay with a natural finish."},
    {SOLARA, "Terracota Rustica", "handmade", "UNI", "structured", C(TERRACOTA_RUSTIC), C(F_200),
     39.9, "m2", 6, "Terracota Rustica: wide joints of 6 mm for a rustic floor."},
    {SOLARA, "Mar", "handmade", "UNI", "glossy", C(MAR), C(F_150), 29.9, "m2", 0,
     "Mar: sea colours for bathroom walls."},
    {SOLARA, "Mar", "handmade", "BOR", "glossy", C(MAR_BOR), C(F_MAR_BOR), 6.9, "piece", 0,
     "Mar: sea colours for bathroom walls."},
    {SOLARA, "Mar", "handmade", "EIN", "glossy", C(MAR_EIN), C(F_50), 3.9, "piece", 0,
     "Mar: sea colours for bathroom walls."},
};

static const char *const type_words[] = {"UNI", "field tile", "BOR", "border",
                                         "DEK", "decor",      "EIN", "insert"};

static const char *type_word(const char *type)
{
    for (int i = 0; i < 8; i += 2)
        if (!strcmp(type_words[i], type))
            return type_words[i + 1];
    return "tile";
}

/* Pieces per box: about 1.44 m2 for large field tiles, about 1 m2 for small ones, fixed counts
 * for borders, decors and inserts. */
static int pieces_per_box(const char *type, const char *unit, int w, int h)
{
    double area = w * (double)h / 1e6;
    if (!strcmp(type, "BOR"))
        return 20;
    if (!strcmp(type, "DEK"))
        return w * h >= 180000 ? 2 : 12;
    if (!strcmp(type, "EIN"))
        return 10;
    if (!strcmp(unit, "box") && area >= 0.09)
        return 10; /* mosaic nets */
    double target = area >= 0.18 ? 1.44 : 1.0;
    int n = (int)(target / area + 0.5);
    return n < 1 ? 1 : n;
}

static void slug(const char *text, char *out, size_t size)
{
    size_t o = 0;
    for (; *text && o + 1 < size; text++) {
        char c = *text;
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))
            out[o++] = c;
        else if (o > 0 && out[o - 1] != '-')
            out[o++] = '-';
    }
    while (o > 0 && out[o - 1] == '-')
        o--;
    out[o] = 0;
}

static int tile_products(FILE *f)
{
    int count = 0;
    for (int s = 0; s < N(tile_ranges); s++) {
        const tile_series *ts = &tile_ranges[s];
        maker *m = &makers[ts->maker];
        for (int fi = 0; fi < ts->format_count; fi++) {
            for (int ci = 0; ci < ts->colour_count; ci++) {
                const colour *col = &ts->colours[ci];
                int w = ts->formats[fi][0], h = ts->formats[fi][1];
                int big = w > h ? w : h;
                tile_data t;
                memset(&t, 0, sizeof t);
                t.type = ts->type;
                t.surface = ts->surface;
                t.nominal_w = w;
                t.nominal_h = h;
                t.grout = ts->grout > 0 ? ts->grout : big <= 150 ? 2 : 3;
                int porcelain = !strcmp(ts->kind, "porcelain");
                t.calibre = porcelain ? "R"
                                      : (count % 3 == 0   ? "C1"
                                         : count % 3 == 1 ? "C2"
                                                          : "C3");
                t.thickness = porcelain                       ? (big >= 1200  ? (w == h ? 11 : 10)
                                                                 : big >= 600 ? 10
                                                                              : 9)
                              : !strcmp(ts->kind, "handmade") ? (big <= 100 ? 9 : 12)
                                                              : (big <= 150 ? 7 : 8);
                if (!strcmp(ts->series, "Pietra Mosaico"))
                    t.thickness = 6;
                t.pieces = pieces_per_box(ts->type, ts->unit, w, h);
                char sl[120];
                char full[160];
                snprintf(full, sizeof full, "%s %s %s %dx%d", m->name, ts->series, col->name, w, h);
                slug(full, sl, sizeof sl);
                snprintf(t.texture, sizeof t.texture, "textures/tiles/%s.png", sl);

                product p;
                memset(&p, 0, sizeof p);
                new_article(m, &p);
                p.category = "tiles";
                p.series = ts->series;
                /* A colour named as its series ("Weiss" in Weiss) is said once. */
                if (!strcmp(ts->series, col->name))
                    snprintf(p.name, sizeof p.name, "%s %s %d x %d", ts->series,
                             type_word(ts->type), w, h);
                else
                    snprintf(p.name, sizeof p.name, "%s %s %s %d x %d", ts->series, col->name,
                             type_word(ts->type), w, h);
                snprintf(p.short_text, sizeof p.short_text, "%s %s %d x %d mm, %s, %g mm",
                         porcelain                   ? "Porcelain stoneware"
                         : !strcmp(ts->kind, "wall") ? "Wall tile"
                                                     : "Ceramic tile",
                         type_word(ts->type), w, h, ts->surface, t.thickness);
                snprintf(p.long_text, sizeof p.long_text,
                         "%s Work size %g x %g mm for a %g mm joint. %s", ts->text, w - t.grout,
                         h - t.grout, t.grout,
                         porcelain ? "Frost-resistant, for walls and floors indoors and out."
                         : !strcmp(ts->kind, "wall")
                             ? "For walls indoors; not for floors."
                             : "Each firing varies in shade; mix tiles from several boxes.");
                p.w = w - t.grout;
                p.d = t.thickness;
                p.h = h - t.grout;
                double area_box = t.pieces * w * (double)h / 1e6;
                if (!strcmp(ts->unit, "box"))
                    p.price_cents = list_price(ts->euro_per_unit * area_box);
                else
                    p.price_cents = list_price(ts->euro_per_unit * (1 + 0.08 * (fi + ci % 2)));
                p.unit = ts->unit;
                snprintf(p.discount_group, sizeof p.discount_group, "F%d", 1 + fi % 3);
                p.tile = &t;
                /* One variant: the glaze, with the tile's colour. */
                material glaze;
                memset(&glaze, 0, sizeof glaze);
                int glossy = !strcmp(ts->surface, "glossy");
                int matt = !strcmp(ts->surface, "matt");
                glaze.code = glossy ? "GL" : matt ? "MT" : "ST";
                char gname[96];
                snprintf(gname, sizeof gname, "%s, %s", col->name, ts->surface);
                glaze.name = gname;
                memcpy(glaze.diffuse, col->rgb, sizeof glaze.diffuse);
                double spec = glossy ? 0.5 : matt ? 0.1 : 0.08;
                glaze.specular[0] = glaze.specular[1] = glaze.specular[2] = spec;
                glaze.shininess = glossy ? 128 : matt ? 16 : 12;
                int polished = !strcmp(ts->series, "Calacatta");
                glaze.kr = polished ? 0.25 : glossy ? 0.15 : matt ? 0.03 : 0.02;
                glaze.gloss = polished ? 0.85 : glossy ? 0.75 : matt ? 0.25 : 0.15;
                glaze.blend = glossy || matt ? "fresnel" : "mix";
                glaze.ior = 1.5;
                if (!strcmp(ts->type, "EIN") && ts->maker == ALTENA) { /* glass inserts */
                    glaze.transparency = 0.3;
                    glaze.kr = 0.1;
                    glaze.gloss = 1;
                }
                p.variants[0] = &glaze;
                p.variant_count = 1;
                write_rows(f, &p);
                count++;
            }
        }
    }
    return count;
}

/* ---- the synthetic catalog for benchmarks -------------------------------------------------- */

static const char *const syllables[] = {"ka", "lo", "ri",  "ven",  "sa",  "mo",  "tu", "del",
                                        "ar", "no", "qui", "ber",  "la",  "zen", "fi", "or",
                                        "pa", "gu", "el",  "ston", "mar", "vi",  "do", "ren"};

static void invent_word(char *out, size_t size, int parts)
{
    out[0] = 0;
    for (int i = 0; i < parts; i++) {
        size_t n = strlen(out);
        snprintf(out + n, size - n, "%s", syllables[rng_int(N(syllables))]);
    }
    if (out[0] >= 'a' && out[0] <= 'z')
        out[0] = (char)(out[0] - 'a' + 'A');
}

static int synthetic(const char *path, long count)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        perror(path);
        return 1;
    }
    fputs(header, f);
    enum { SMAKERS = 60, SSERIES = 24 };
    static maker sm[SMAKERS];
    static char names[SMAKERS][40], series[SMAKERS][SSERIES][24], gs1[SMAKERS][8];
    for (int i = 0; i < SMAKERS; i++) {
        char w[32];
        invent_word(w, sizeof w, 2 + i % 2);
        snprintf(names[i], sizeof names[i], "%s %s", w,
                 i % 3 == 0   ? "Bad"
                 : i % 3 == 1 ? "Sanitar"
                              : "Design");
        snprintf(gs1[i], sizeof gs1[i], "%07d", 4100000 + i * 37);
        sm[i] = (maker){names[i], gs1[i], "", 0, 0};
        for (int s = 0; s < SSERIES; s++)
            invent_word(series[i][s], sizeof series[i][s], 2 + s % 2);
    }
    struct {
        const char *category;
        const ptype *types;
        int n;
    } cats[] = {{"taps_mixers", TAPS, N(TAPS)},
                {"shower_sets", SHOWERS, N(SHOWERS)},
                {"basins", BASINS, N(BASINS)},
                {"wcs_bidets", WCS, N(WCS)},
                {"baths", BATHS, N(BATHS)},
                {"shower_trays", TRAYS, N(TRAYS)},
                {"shower_screens", SCREENS, N(SCREENS)},
                {"mirrors", MIRRORS, N(MIRRORS)},
                {"mirror_cabinets", CABINETS, N(CABINETS)},
                {"lamps", LAMPS, N(LAMPS)},
                {"towel_radiators", RADIATORS, N(RADIATORS)},
                {"vanity_units", VANITIES, N(VANITIES)},
                {"accessories", ACCESSORIES, N(ACCESSORIES)}};
    for (long i = 0; i < count; i++) {
        int mi = rng_int(SMAKERS);
        maker *m = &sm[mi];
        int ci = rng_int(N(cats));
        const ptype *t = &cats[ci].types[rng_int(cats[ci].n)];
        const char *se = series[mi][rng_int(SSERIES)];
        product p;
        memset(&p, 0, sizeof p);
        p.m = m;
        snprintf(p.article, sizeof p.article, "S%02d-%07ld", mi, i);
        gtin13(m, (int)(i % 100000), p.gtin);
        p.category = cats[ci].category;
        p.series = se;
        snprintf(p.name, sizeof p.name, "%s %s", se, t->name);
        snprintf(p.short_text, sizeof p.short_text, "%s", t->short_text);
        snprintf(p.long_text, sizeof p.long_text, "%s %s", t->long_text,
                 category_sentence(p.category));
        double scale = 0.9 + 0.2 * rng_int(100) / 100.0;
        p.w = round(t->w * (t->w < 300 ? scale : 1));
        p.d = t->d;
        p.h = t->h;
        p.price_cents = list_price(t->price * (0.7 + rng_int(100) / 100.0));
        p.unit = "piece";
        snprintf(p.discount_group, sizeof p.discount_group, "S%d", rng_int(5));
        p.variants[0] = t->variants->m[rng_int(2) && t->variants->m[1] ? 1 : 0];
        p.variant_count = 1;
        write_rows(f, &p);
    }
    if (fclose(f) != 0) {
        perror(path);
        return 1;
    }
    return 0;
}

/* ---- main ------------------------------------------------------------------------------------ */

static FILE *open_out(const char *dir, const char *name, char *path, size_t size)
{
    snprintf(path, size, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f)
        perror(path);
    else
        fputs(header, f);
    return f;
}

int main(int argc, char **argv)
{
    if (argc == 4 && !strcmp(argv[1], "--synthetic")) {
        long n = strtol(argv[2], NULL, 10);
        if (n < 1 || n > 10000000) {
            fprintf(stderr, "make_catalog_csv: bad count %s\n", argv[2]);
            return 2;
        }
        return synthetic(argv[3], n);
    }
    if (argc != 2) {
        fprintf(stderr, "usage: make_catalog_csv OUT_DIR\n"
                        "       make_catalog_csv --synthetic N FILE.csv\n");
        return 2;
    }
    char path[4096];
    FILE *f = open_out(argv[1], "fixtures.csv", path, sizeof path);
    if (!f)
        return 1;
    int fixtures = 0;
    for (int i = 0; i < N(fixture_ranges); i++) {
        const range *r = &fixture_ranges[i];
        fixtures += series_products(f, r->maker, r->category, r->series, r->factor, r->types,
                                    r->type_count, r->first, r->count, r->text);
    }
    if (fclose(f) != 0) {
        perror(path);
        return 1;
    }
    f = open_out(argv[1], "tiles.csv", path, sizeof path);
    if (!f)
        return 1;
    int tiles = tile_products(f);
    if (fclose(f) != 0) {
        perror(path);
        return 1;
    }
    printf("make_catalog_csv: %d fixtures, %d tiles, %d manufacturers in %s\n", fixtures, tiles,
           MAKER_COUNT, argv[1]);
    return 0;
}
