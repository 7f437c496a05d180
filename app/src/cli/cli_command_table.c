/* Every `tessera` command: name, function, synopsis, the options it takes (keys of
 * cli_option_table.c), a summary for `tessera --help` and help for `tessera help CMD`.
 * Dispatch and every usage text come from here (docs/cli.md, "Adding a command"). */
#include "cli_commands.h"
#include "cli_table.h"

/* The options every command that renders through the GPU renderer takes. */
#define RENDER_SETTINGS                                                                            \
    "quality adaptive planar-mirrors mirror-bounce mirror-panes room-probe glaze exact-lamps "     \
    "self-reflections probe-resolution "                                                           \
    "shadows probes blur ambient backend bake bake-bounces tone exposure white-balance sky time "  \
    "room prime "

static const cli_command catalog_commands[] = {
    {.name = "search",
     .run = cli_cmd_catalog_search,
     .synopsis = "TEXT...",
     .min_args = 1,
     .max_args = CLI_MAX_ARGS,
     .options = "category max-width manufacturer limit db",
     .summary = "products matching the words (default: at most 20)",
     .parent = "catalog"},
    {.name = "show",
     .run = cli_cmd_catalog_show,
     .synopsis = "ARTICLE|GTIN",
     .min_args = 1,
     .max_args = 1,
     .options = "manufacturer db",
     .summary = "one product with its variants",
     .parent = "catalog"},
    {.name = "import",
     .run = cli_cmd_catalog_import,
     .synopsis = "FILE.csv",
     .min_args = 1,
     .max_args = 1,
     .options = "dry-run db",
     .summary = "adds or updates products from a CSV file",
     .parent = "catalog"},
    {.name = "export",
     .run = cli_cmd_catalog_export,
     .synopsis = "",
     .options = "output db",
     .summary = "the whole catalog as CSV (default: to standard output)",
     .parent = "catalog"},
    {.name = "info",
     .run = cli_cmd_catalog_info,
     .synopsis = "",
     .options = "db",
     .summary = "the catalog file, its size and products per category",
     .parent = "catalog"},
    {.name = "bench",
     .run = cli_cmd_catalog_bench,
     .synopsis = "",
     .options = "queries csv db",
     .summary = "search latency by kind of query",
     .parent = "catalog"},
    {.name = "model",
     .run = IN_FULL(cli_cmd_catalog_model),
     .synopsis = "ARTICLE|GTIN",
     .min_args = 1,
     .max_args = 1,
     .options = "manufacturer variant output db",
     .summary = "writes the product's model as GLB (default: ./ARTICLE.glb)",
     .help = "  Its finish parts in the variant CODE (default: the first by code). Origin: the\n"
             "  bottom centre of the back face; Y up, metres (docs/catalog.md, \"Models\").\n",
     .parent = "catalog"},
    {.name = "thumbs",
     .run = IN_FULL(cli_cmd_catalog_thumbs),
     .synopsis = "",
     .options = "thumb-size out category limit variant supersample backend db",
     .summary = "a thumbnail of every product into DIR/MANUFACTURER-ARTICLE.png",
     .help = "  Its model, or a box of its size while it has none; tiles: a small tiled square\n"
             "  of their texture (default: thumbs/, 256 px, at most 10000 products a run).\n",
     .parent = "catalog"},
    {.name = "lod",
     .run = IN_FULL(cli_cmd_catalog_lod),
     .synopsis = "MODEL.(glb|gltf)",
     .min_args = 1,
     .max_args = 1,
     .options = "fraction output",
     .summary = "validates a model's meshes; with -o writes a level of detail",
     .help = "  The level of detail keeps about F (default 0.5) of each mesh's triangles and the\n"
             "  same bounding box.\n",
     .parent = "catalog"},
    {0},
};

const cli_command cli_commands[] = {
    {.name = "open",
     .run = IN_FULL(cli_cmd_open),
     .synopsis = "[PROJECT]",
     .max_args = 1,
     .options = "script quality window-size fullscreen frame-log",
     .summary = "the planner window (also what `tessera` alone does)"},
    {.name = "demo",
     .run = IN_FULL(cli_cmd_demo),
     .synopsis = "",
     .options = "bake output size supersample quality adaptive planar-mirrors backend stats",
     .summary = "renders the shipped demo bathroom from each of its cameras into out/"},
    {.name = "bake",
     .run = IN_FULL(cli_cmd_bake),
     .synopsis = "PROJECT",
     .min_args = 1,
     .max_args = 1,
     .options = "stats bake-bounces",
     .summary = "bakes the indirect light and occlusion into the cache (docs/rendering.md)",
     .help = "  render, demo, print, panorama, video, share and bench bake on their own (cached);\n"
             "  this runs it alone and says what it did. --stats FILE.json writes the counts.\n"},
    {.name = "render",
     .run = IN_FULL(cli_cmd_render),
     .synopsis = "PROJECT -o OUT.(png|jpg|tif|exr)",
     .min_args = 1,
     .max_args = 1,
     .options = "output camera all-views serve size supersample dpi tile stats " RENDER_SETTINGS,
     .summary = "renders a project to PNG, JPEG, TIFF (8-bit sRGB) or EXR (linear)",
     .help =
         "  Any size: beyond the GL limits the image is rendered in tiles. With --all-views,\n"
         "  -o names a folder that gets every stored camera as NAME.png. With --serve, no -o:\n"
         "  each line on standard input, EYE(x y z) TARGET(x y z) FOV PRESET W H OUT.png (mm),\n"
         "  is rendered into OUT.png and answered \"done OUT.png\" on standard output, the\n"
         "  scene and its probes kept between views (the planner window's still view).\n"},
    {.name = "panorama",
     .run = IN_FULL(cli_cmd_panorama),
     .synopsis = "PROJECT -o OUT.jpg",
     .min_args = 1,
     .max_args = 1,
     .options = "bake output camera size supersample faces tile quality adaptive planar-mirrors "
                "shadows probes blur ambient backend tone exposure white-balance sky time",
     .summary = "a 360-degree equirectangular panorama (GPano XMP) from six cube faces",
     .help = "  --size is the panorama's, twice as wide as high (default: 4096x2048).\n"},
    {.name = "video",
     .run = IN_FULL(cli_cmd_video),
     .synopsis = "PROJECT -o OUT.mp4",
     .min_args = 1,
     .max_args = 1,
     .options = "bake output seconds fps size supersample tile quality adaptive planar-mirrors "
                "shadows probes blur ambient backend tone exposure white-balance sky time",
     .summary = "a smooth path through the stored cameras: PNG frames, MP4 with ffmpeg",
     .help = "  Default: 8 seconds at 25 frames a second.\n"},
    {.name = "share",
     .run = IN_FULL(cli_cmd_share),
     .synopsis = "PROJECT -o DIR",
     .min_args = 1,
     .max_args = 1,
     .options = "bake output size panorama-size camera",
     .summary = "a folder for any browser: renders, plan, 360-degree panorama, part list"},
    {.name = "print",
     .run = IN_FULL(cli_cmd_print),
     .synopsis = "PROJECT -o OUT.pdf",
     .min_args = 1,
     .max_args = 1,
     .options = "bake output paper landscape scale svg renders render-size customer date "
                "company xlsx no-clearances quality backend text-boxes",
     .summary = "the print set: plan, wall elevations with tiles, renders, part list, quotation",
     .help = "  Renders of the project's cameras at quality final (or the PNG files in\n"
             "  --renders DIR).\n"},
    {.name = "edit",
     .run = IN_FULL(cli_cmd_edit),
     .synopsis = "PROJECT SCRIPT",
     .min_args = 2,
     .max_args = 2,
     .options = "output db quiet",
     .summary = "replays an edit script and saves the project (docs/editing.md)",
     .help = "  SCRIPT has one command per line: place, add, move, nudge, rotate, remove,\n"
             "  variant, product, tile, untile, door, window, move-opening, remove-opening,\n"
             "  corner, prewall, remove-prewall, niche, remove-niche, reflect, undo, redo.\n"
             "  It saves to OUT (default: PROJECT itself), atomically. SCRIPT - reads standard\n"
             "  input.\n"},
    {.name = "check",
     .run = cli_cmd_check,
     .synopsis = "PROJECT",
     .min_args = 1,
     .max_args = 1,
     .options = "barrier-free wheelchair db",
     .summary = "collisions and clearances of the fixtures (exit 1 on errors)",
     .help = "  Validates the project file and checks its fixtures: collisions, walls, free\n"
             "  areas and 200 mm distances (VDI 6000).\n"
             "  Exit 0: no errors; 1: errors found; 2: bad usage or unreadable project.\n"},
    {.name = "quantities",
     .run = IN_FULL(cli_cmd_quantities),
     .synopsis = "PROJECT",
     .max_args = 1,
     .options = "csv-table json-table surplus offcuts company date xlsx bench bench-mosaic db",
     .summary = "the tile part list (whole/cut tiles, offcuts, boxes), consumables, labour and the "
                "quotation",
     .help = "  Prices and VAT from the catalog. --json or --csv print machine-readable output;\n"
             "  --xlsx FILE writes the quotation as a spreadsheet with formulas (a flat: each\n"
             "  room, the total and one quotation over the rooms); --company FILE\n"
             "  the company block (default $XDG_CONFIG_HOME/tessera/company.json), --date\n"
             "  YYYY-MM-DD the quote's date. --bench N times the layout; --bench-mosaic needs no\n"
             "  project.\n",
     .defaults = IN_FULL(cli_defaults_quantities)},
    {.name = "surfaces",
     .run = IN_FULL(cli_cmd_surfaces),
     .synopsis = "PROJECT",
     .min_args = 1,
     .max_args = 1,
     .options = "csv-table",
     .summary = "the room's tileable surfaces: frames, holes (openings, covered) and net m2"},
    {.name = "generate-flat",
     .run = cli_cmd_generate_flat,
     .synopsis = "-o FLAT.json",
     .options = "rooms seed output",
     .summary = "a synthetic flat of N rooms from catalog products (tests, benchmarks)",
     .help = "  Writes a flat (docs/project-format.md \"Flats\"): bathroom, kitchen, WC, hall,\n"
             "  shower room, utility, en-suite, guest WC, then again; about 300 fixtures and\n"
             "  40 000 tiles at 8 rooms. The same --rooms and --seed give the same file.\n"},
    {.name = "export-glb",
     .run = IN_FULL(cli_cmd_export_glb),
     .synopsis = "PROJECT",
     .min_args = 1,
     .max_args = 1,
     .options = "output",
     .summary = "the whole project (room, tiles, objects, products) as GLB (default: PROJECT.glb)"},
    {.name = "catalog",
     .synopsis = "COMMAND",
     .subcommands = catalog_commands,
     .summary = "the product catalog: search, show, import, export, model, thumbs, ...",
     .help = "  The catalog file is --db, else $TESSERA_CATALOG, else\n"
             "  ~/.cache/tessera/catalog.sqlite; it is built from the shipped CSV files\n"
             "  ($TESSERA_ASSETS/catalog) on first use.\n"
             "  Categories: taps_mixers shower_sets basins wcs_bidets baths shower_trays\n"
             "  shower_screens mirrors mirror_cabinets lamps towel_radiators vanity_units\n"
             "  accessories tiles\n"},
    {.name = "bench",
     .run = IN_FULL(cli_cmd_bench),
     .synopsis = "PROJECT",
     .min_args = 1,
     .max_args = 1,
     .options = "bake camera size frames warmup animate csv stats quality exact-lamps glaze "
                "self-reflections probe-resolution probes blur ambient shadows backend live prime",
     .summary = "milliseconds per frame (median and spread) against a full-screen floor",
     .help = "  --animate drags an object 10 mm a frame; the cpu row: CPU ms, all threads.\n",
     .defaults = IN_FULL(cli_defaults_bench)},
    {.name = "probe-bench",
     .run = IN_FULL(cli_cmd_probe_bench),
     .synopsis = "",
     .options = "size frames warmup csv backend",
     .summary = "what reflection probes cost: per update by resolution, per object",
     .defaults = IN_FULL(cli_defaults_probe_bench)},
    {.name = "reference",
     .run = IN_FULL(cli_cmd_reference),
     .synopsis = "PROJECT -o OUT.(exr|png|jpg|tif)",
     .min_args = 1,
     .max_args = 1,
     .options = "output camera size supersample samples threads seed png mask quality shadows "
                "ambient bounces tone exposure white-balance sky time",
     .summary = "the ground truth: a CPU ray tracer (Embree) with the same shading",
     .help = "  Defaults: --bounces 4 (a path tracer with indirect and area lights), 16 paths a\n"
             "  subsample; --bounces 0 is the direct-only tracer with 64 rays a glossy lookup.\n",
     .defaults = IN_FULL(cli_defaults_reference)},
    {.name = "compare",
     .run = IN_FULL(cli_cmd_compare),
     .synopsis = "A B",
     .min_args = 2,
     .max_args = 2,
     .options = "mask heatmap heat-max worst block",
     .summary = "RMSE and PSNR in linear RGB, over all pixels and the masked ones",
     .help = "  --worst N lists where the error is: the N blocks that carry most of it.\n"},
    {.name = "sweep",
     .run = IN_FULL(cli_cmd_sweep),
     .synopsis = "PROJECT",
     .min_args = 1,
     .max_args = 1,
     .options = "camera size supersample shadows frames warmup samples animate csv plot markdown "
                "backend bounces",
     .summary = "the speed/accuracy trade: each reflection setting timed and compared",
     .help = "  Defaults: 480x270, 16 samples a glossy lookup in the reference, 6 frames after 2\n"
             "  warm-up frames. The baseline takes the project's ambient model and supersampling\n"
             "  (--supersample, --shadows refine it); the reference is traced with the same,\n"
             "  direct light only unless --bounces N.\n",
     .defaults = IN_FULL(cli_defaults_sweep)},
    {.name = "extremes",
     .run = IN_FULL(cli_cmd_extremes),
     .synopsis = "",
     .options = "size samples markdown backend bounces",
     .summary = "RENDERING.md section 11: every extreme finite on the GPU and in the reference",
     .help = "  The reference also path-traces each case with --bounces N (default 4; 0: off).\n",
     .defaults = IN_FULL(cli_defaults_extremes)},
    {.name = "help",
     .run = cli_cmd_help,
     .synopsis = "[COMMAND [SUB-COMMAND]]",
     .max_args = 2,
     .options = "list",
     .summary = "this overview, or a command's usage"},
    {0},
};
