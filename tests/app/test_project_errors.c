/* One case per bad input: each asserts the APP_ERR_* code and that the message names the
 * file, the JSON path (or line and column) and the problem.
 *
 * Most cases edit a valid base project in memory (replace one snippet); the file-level ones
 * read fixture files under tests/data/projects/ or make files in a temporary folder.
 * Usage: test_project_errors [case-name]   (no argument: every case) */
#include "test_util.h"

#include "app/project/project.h"

#include <fcntl.h>

#define DATA TESSERA_PROJECT_TEST_DATA
/* The name messages must carry; relative model/texture paths resolve against its folder. */
#define CASE_FILE DATA "/case.json"

static const char BASE[] =
    "{\n"
    "  \"version\": 1,\n"
    "  \"name\": \"base\",\n"
    "  \"room\": {\"width\": 2400, \"depth\": 3000, \"height\": 2500, \"floor\": \"tile\", "
    "\"walls\": \"tile\", \"ceiling\": \"white\"},\n"
    "  \"materials\": {\n"
    "    \"tile\": {\"diffuse\": [0.8, 0.8, 0.78], \"specular\": [0.3, 0.3, 0.3], \"shininess\": "
    "64, \"texture\": \"textures/wall.png\", \"texture_size\": [300, 600]},\n"
    "    \"white\": {\"diffuse\": [0.9, 0.9, 0.9], \"emissive\": [0, 0, 0]},\n"
    "    \"chrome\": {\"diffuse\": [0.1, 0.1, 0.1], \"ambient\": [0.1, 0.1, 0.1]}\n"
    "  },\n"
    "  \"objects\": [\n"
    "    {\"name\": \"basin\", \"shape\": \"cylinder\", \"position\": [600, 300, 850], \"size\": "
    "[600, 450, 150], \"rotation\": [0, 0, 0], \"scale\": [1, 1, 1], \"material\": \"white\"},\n"
    "    {\"name\": \"tap\", \"model\": \"models/tap.glb\", \"position\": [600, 100, 900], "
    "\"material\": \"chrome\"}\n"
    "  ],\n"
    "  \"lights\": [\n"
    "    {\"name\": \"ceiling\", \"type\": \"point\", \"position\": [1200, 1500, 2400], "
    "\"color\": [1, 0.95, 0.9], \"intensity\": 3, \"attenuation\": [1, 0, 1]},\n"
    "    {\"name\": \"spot\", \"type\": \"spot\", \"position\": [600, 300, 2400], \"direction\": "
    "[0, 0, -1], \"inner\": 20, \"outer\": 30}\n"
    "  ],\n"
    "  \"cameras\": [{\"name\": \"door\", \"position\": [1200, 2900, 1600], \"target\": [1200, "
    "0, 1000], \"fov\": 60, \"up\": [0, 0, 1]}],\n"
    "  \"render\": {\"ambient\": [0.1, 0.1, 0.1], \"exposure\": 0, \"white\": 4, \"size\": "
    "[1280, 720], \"supersample\": 1}\n"
    "}\n";

typedef struct edit_case {
    const char *name;
    const char *find, *replace; /* the edit applied to BASE */
    app_result expect;
    const char *path;   /* must appear in the message, e.g. "$.room.width: " */
    const char *detail; /* and this */
} edit_case;

#define CAM "{\"name\": \"door\", \"position\": [1200, 2900, 1600], \"target\": [1200, 0, 1000], "

static const edit_case EDITS[] = {
    /* malformed JSON: line and column instead of a JSON path */
    {"malformed_double_comma", "\"width\": 2400,", "\"width\": 2400,,", APP_ERR_PARSE,
     "case.json: line 4, column 27: ", "malformed JSON"},
    {"malformed_nan_literal", "\"width\": 2400", "\"width\": NaN", APP_ERR_PARSE,
     "case.json: line 4, column 21: ", "malformed JSON"},
    {"malformed_infinity_literal", "\"exposure\": 0", "\"exposure\": Infinity", APP_ERR_PARSE,
     "case.json: line 19, column ", "malformed JSON"},
    {"malformed_trailing_garbage", "\"supersample\": 1}\n}\n", "\"supersample\": 1}\n}\n{}\n",
     APP_ERR_PARSE, "case.json: line 21, column 1: ", "unexpected text after the end"},
    {"malformed_truncated", "\"supersample\": 1}\n}\n", "\"supersample\": 1", APP_ERR_PARSE,
     "case.json: line 19, column 106: ", "malformed JSON (unexpected end of file)"},
    {"malformed_unterminated_string", "\"name\": \"base\"", "\"name\": \"base", APP_ERR_PARSE,
     "case.json: line ", "malformed JSON"},
    /* versions */
    {"version_missing", "\"version\": 1,", "", APP_ERR_VERSION, "$.version: ", "missing"},
    {"version_newer", "\"version\": 1", "\"version\": 3", APP_ERR_VERSION,
     "$.version: ", "written by a newer Tessera (version 3), this build reads up to 2"},
    {"version_zero", "\"version\": 1", "\"version\": 0", APP_ERR_VERSION,
     "$.version: ", "must be >= 1, got 0"},
    {"version_string", "\"version\": 1", "\"version\": \"1\"", APP_ERR_VERSION,
     "$.version: ", "expected an integer, got string"},
    {"version_fraction", "\"version\": 1", "\"version\": 1.5", APP_ERR_VERSION,
     "$.version: ", "expected an integer, got 1.5"},
    {"version_inf", "\"version\": 1", "\"version\": 1e999", APP_ERR_VERSION,
     "$.version: ", "expected an integer"},
    /* project */
    {"name_wrong_type", "\"name\": \"base\"", "\"name\": [1]", APP_ERR_SCHEMA,
     "$.name: ", "expected a string, got array"},
    /* room */
    {"room_missing", "\"room\":", "\"rooms\":", APP_ERR_SCHEMA, "$.room: ", "missing (required)"},
    {"room_wrong_type", "\"room\": {", "\"room\": 5, \"x\": {", APP_ERR_SCHEMA,
     "$.room: ", "expected an object, got number"},
    {"room_width_negative", "\"width\": 2400", "\"width\": -2400", APP_ERR_SCHEMA,
     "$.room.width: ", "must be > 0, got -2400"},
    {"room_depth_zero", "\"depth\": 3000", "\"depth\": 0", APP_ERR_SCHEMA,
     "$.room.depth: ", "must be > 0, got 0"},
    {"room_height_too_large", "\"height\": 2500", "\"height\": 2e7", APP_ERR_SCHEMA,
     "$.room.height: ", "must be <= 1e+07, got 2e+07"},
    {"room_width_string", "\"width\": 2400", "\"width\": \"2400\"", APP_ERR_SCHEMA,
     "$.room.width: ", "expected a finite number, got string"},
    {"room_width_missing", "\"width\": 2400, ", "", APP_ERR_SCHEMA,
     "$.room.width: ", "missing (required)"},
    {"room_width_inf", "\"width\": 2400", "\"width\": 1e999", APP_ERR_SCHEMA,
     "$.room.width: ", "must be a finite number"},
    {"room_unknown_material", "\"walls\": \"tile\"", "\"walls\": \"tiles\"", APP_ERR_SCHEMA,
     "$.room.walls: ", "unknown material \"tiles\""},
    {"room_material_wrong_type", "\"floor\": \"tile\"", "\"floor\": true", APP_ERR_SCHEMA,
     "$.room.floor: ", "expected a string or an object, got boolean"},
    /* materials */
    {"materials_wrong_type", "\"materials\": {", "\"materials\": [], \"x\": {", APP_ERR_SCHEMA,
     "$.materials: ", "expected an object, got array"},
    {"material_not_object",
     "\"chrome\": {\"diffuse\": [0.1, 0.1, 0.1], \"ambient\": [0.1, 0.1, 0.1]}", "\"chrome\": [1]",
     APP_ERR_SCHEMA, "$.materials.chrome: ", "expected an object, got array"},
    {"material_duplicate", "\"chrome\": {", "\"white\": {", APP_ERR_SCHEMA,
     "$.materials.white: ", "duplicate material name \"white\""},
    {"material_empty_name", "\"chrome\": {", "\"\": {", APP_ERR_SCHEMA,
     "$.materials[\"\"]: ", "must not be empty"},
    {"material_color_negative", "\"diffuse\": [0.9, 0.9, 0.9]", "\"diffuse\": [0.9, -0.1, 0.9]",
     APP_ERR_SCHEMA, "$.materials.white.diffuse[1]: ", "must be >= 0, got -0.1"},
    {"material_color_string", "\"emissive\": [0, 0, 0]", "\"emissive\": \"black\"", APP_ERR_SCHEMA,
     "$.materials.white.emissive: ", "expected an array, got string"},
    {"material_color_element_null", "\"emissive\": [0, 0, 0]", "\"emissive\": [0, null, 0]",
     APP_ERR_SCHEMA, "$.materials.white.emissive[1]: ", "expected a finite number, got null"},
    {"material_color_two_elements", "\"emissive\": [0, 0, 0]", "\"emissive\": [0, 0]",
     APP_ERR_SCHEMA, "$.materials.white.emissive: ", "expected an array of 3 numbers, got 2"},
    {"material_color_too_large_for_float", "\"emissive\": [0, 0, 0]", "\"emissive\": [0, 1e300, 0]",
     APP_ERR_SCHEMA, "$.materials.white.emissive[1]: ", "must be <= 3.40282e+38"},
    {"material_pattern_unknown", "\"emissive\": [0, 0, 0]",
     "\"emissive\": [0, 0, 0], \"pattern\": \"marble\"", APP_ERR_SCHEMA,
     "$.materials.white.pattern: ", "unknown value \"marble\" (use one of: none, wood)"},
    {"material_pattern_number", "\"emissive\": [0, 0, 0]",
     "\"emissive\": [0, 0, 0], \"pattern\": 1", APP_ERR_SCHEMA,
     "$.materials.white.pattern: ", "expected a string, got number"},
    {"material_shininess_too_large", "\"shininess\": 64", "\"shininess\": 1e7", APP_ERR_SCHEMA,
     "$.materials.tile.shininess: ", "must be in [0, 1e+06], got 1e+07"},
    {"material_shininess_string", "\"shininess\": 64", "\"shininess\": \"64\"", APP_ERR_SCHEMA,
     "$.materials.tile.shininess: ", "expected a finite number, got string"},
    {"material_texture_missing_file", "textures/wall.png", "textures/missing.png",
     APP_ERR_NOT_FOUND, "$.materials.tile.texture: ",
     "file not found: /"}, /* the absolute path follows; checked in test_missing_paths */
    {"material_texture_is_folder", "textures/wall.png", "textures", APP_ERR_NOT_FOUND,
     "$.materials.tile.texture: ", "not a regular file"},
    {"material_texture_wrong_type", "\"texture\": \"textures/wall.png\"", "\"texture\": 12",
     APP_ERR_SCHEMA, "$.materials.tile.texture: ", "expected a string, got number"},
    {"material_texture_size_zero", "\"texture_size\": [300, 600]", "\"texture_size\": [300, 0]",
     APP_ERR_SCHEMA, "$.materials.tile.texture_size[1]: ", "must be > 0, got 0"},
    /* objects */
    {"objects_wrong_type", "\"objects\": [", "\"objects\": {}, \"x\": [", APP_ERR_SCHEMA,
     "$.objects: ", "expected an array, got object"},
    {"object_not_object", "\"objects\": [", "\"objects\": [42, ", APP_ERR_SCHEMA,
     "$.objects[0]: ", "expected an object, got number"},
    {"object_position_inf", "\"position\": [600, 300, 850]", "\"position\": [600, 1e999, 850]",
     APP_ERR_SCHEMA, "$.objects[0].position[1]: ", "must be a finite number"},
    {"object_position_negative_inf", "\"position\": [600, 300, 850]",
     "\"position\": [-1e999, 300, 850]", APP_ERR_SCHEMA,
     "$.objects[0].position[0]: ", "must be a finite number"},
    {"object_position_string", "\"position\": [600, 100, 900]", "\"position\": [600, \"100\", 900]",
     APP_ERR_SCHEMA, "$.objects[1].position[1]: ", "expected a finite number, got string"},
    {"object_position_short", "\"position\": [600, 100, 900]", "\"position\": [600, 100]",
     APP_ERR_SCHEMA, "$.objects[1].position: ", "expected an array of 3 numbers, got 2 elements"},
    {"object_position_not_array", "\"position\": [600, 300, 850]", "\"position\": 600",
     APP_ERR_SCHEMA, "$.objects[0].position: ", "expected an array, got number"},
    {"object_position_missing", "\"position\": [600, 300, 850], ", "", APP_ERR_SCHEMA,
     "$.objects[0].position: ", "missing (required)"},
    {"object_name_wrong_type", "\"name\": \"basin\"", "\"name\": 7", APP_ERR_SCHEMA,
     "$.objects[0].name: ", "expected a string, got number"},
    {"object_name_empty", "\"name\": \"basin\"", "\"name\": \"\"", APP_ERR_SCHEMA,
     "$.objects[0].name: ", "must not be empty"},
    {"object_name_too_long", "\"name\": \"basin\"",
     "\"name\": \"a-very-long-object-name-that-goes-on-and-on-well-past-sixty-three-bytes\"",
     APP_ERR_SCHEMA, "$.objects[0].name: ", "too long"},
    {"object_shape_unknown", "\"shape\": \"cylinder\"", "\"shape\": \"cone\"", APP_ERR_SCHEMA,
     "$.objects[0].shape: ", "unknown shape \"cone\""},
    {"object_shape_wrong_type", "\"shape\": \"cylinder\"", "\"shape\": 3", APP_ERR_SCHEMA,
     "$.objects[0].shape: ", "expected a string, got number"},
    {"object_shape_and_model", "\"shape\": \"cylinder\",",
     "\"shape\": \"cylinder\", \"model\": \"models/tap.glb\",", APP_ERR_SCHEMA,
     "$.objects[0]: ", "has more than one of \"shape\", \"model\" and \"product\""},
    {"object_neither_shape_nor_model", "\"model\": \"models/tap.glb\", ", "", APP_ERR_SCHEMA,
     "$.objects[1]: ", "needs a \"shape\", a \"model\" or a \"product\""},
    {"object_size_zero", "\"size\": [600, 450, 150]", "\"size\": [600, 0, 150]", APP_ERR_SCHEMA,
     "$.objects[0].size[1]: ", "must be > 0, got 0"},
    {"object_size_missing", "\"size\": [600, 450, 150], ", "", APP_ERR_SCHEMA,
     "$.objects[0].size: ", "missing (required)"},
    {"object_size_four", "\"size\": [600, 450, 150]", "\"size\": [600, 450, 150, 1]",
     APP_ERR_SCHEMA, "$.objects[0].size: ", "expected an array of 3 numbers, got 4 elements"},
    {"object_torus_too_thick",
     "\"cylinder\", \"position\": [600, 300, 850], \"size\": [600, 450, 150]",
     "\"torus\", \"position\": [600, 300, 850], \"size\": [600, 450, 300]", APP_ERR_SCHEMA,
     "$.objects[0].size[2]: ", "cannot be thicker than half its outer diameter"},
    {"object_scale_zero", "\"scale\": [1, 1, 1]", "\"scale\": [1, 0, 1]", APP_ERR_SCHEMA,
     "$.objects[0].scale[1]: ", "must not be 0"},
    {"object_rotation_wrong_type", "\"rotation\": [0, 0, 0]", "\"rotation\": [0, 0, false]",
     APP_ERR_SCHEMA, "$.objects[0].rotation[2]: ", "expected a finite number, got boolean"},
    {"object_model_missing_file", "models/tap.glb\", \"position\"",
     "models/no-such-tap.glb\", \"position\"", APP_ERR_NOT_FOUND,
     "$.objects[1].model: ", "file not found: /"},
    {"object_model_empty", "\"model\": \"models/tap.glb\"", "\"model\": \"\"", APP_ERR_SCHEMA,
     "$.objects[1].model: ", "must not be empty"},
    {"object_unknown_material", "\"material\": \"chrome\"", "\"material\": \"chrom\"",
     APP_ERR_SCHEMA, "$.objects[1].material: ", "unknown material \"chrom\""},
    {"object_material_wrong_type", "\"material\": \"white\"", "\"material\": 3", APP_ERR_SCHEMA,
     "$.objects[0].material: ", "expected a string or an object, got number"},
    {"object_inline_material_bad_field", "\"material\": \"white\"",
     "\"material\": {\"specular\": [1, 1, \"x\"]}", APP_ERR_SCHEMA,
     "$.objects[0].material.specular[2]: ", "expected a finite number, got string"},
    {"object_inline_material_name_taken", "\"material\": \"chrome\"}",
     "\"material\": {}}, {\"name\": \"tap\", \"shape\": \"box\", \"size\": [1, 1, 1], "
     "\"position\": [0, 0, 0], \"material\": {}}",
     APP_ERR_SCHEMA, "$.objects[2].material: ", "name \"tap#material\" is already used"},
    /* lights */
    {"lights_wrong_type", "\"lights\": [", "\"lights\": 5, \"x\": [", APP_ERR_SCHEMA,
     "$.lights: ", "expected an array, got number"},
    {"light_type_unknown", "\"type\": \"point\"", "\"type\": \"area\"", APP_ERR_SCHEMA,
     "$.lights[0].type: ", "unknown light type \"area\""},
    {"light_position_missing", "\"position\": [1200, 1500, 2400], ", "", APP_ERR_SCHEMA,
     "$.lights[0].position: ", "missing (required)"},
    {"light_direction_zero", "\"direction\": [0, 0, -1]", "\"direction\": [0, 0, 0]",
     APP_ERR_SCHEMA, "$.lights[1].direction: ", "must not be the zero vector"},
    {"light_direction_missing", "\"direction\": [0, 0, -1], ", "", APP_ERR_SCHEMA,
     "$.lights[1].direction: ", "missing (required)"},
    {"light_color_negative", "\"color\": [1, 0.95, 0.9]", "\"color\": [1, 0.95, -0.9]",
     APP_ERR_SCHEMA, "$.lights[0].color[2]: ", "must be >= 0, got -0.9"},
    {"light_intensity_string", "\"intensity\": 3", "\"intensity\": \"bright\"", APP_ERR_SCHEMA,
     "$.lights[0].intensity: ", "expected a finite number, got string"},
    {"light_attenuation_negative", "\"attenuation\": [1, 0, 1]", "\"attenuation\": [1, -1, 1]",
     APP_ERR_SCHEMA, "$.lights[0].attenuation[1]: ", "must be >= 0, got -1"},
    {"light_attenuation_all_zero", "\"attenuation\": [1, 0, 1]", "\"attenuation\": [0, 0, 0]",
     APP_ERR_SCHEMA, "$.lights[0].attenuation: ", "at least one coefficient"},
    {"light_spot_inner_not_below_outer", "\"inner\": 20", "\"inner\": 40", APP_ERR_SCHEMA,
     "$.lights[1].inner: ", "must be < outer"},
    {"light_spot_outer_too_wide", "\"outer\": 30", "\"outer\": 120", APP_ERR_SCHEMA,
     "$.lights[1].outer: ", "must be in [0, 90], got 120"},
    /* cameras */
    {"cameras_empty", "\"cameras\": [" CAM "\"fov\": 60, \"up\": [0, 0, 1]}]", "\"cameras\": []",
     APP_ERR_SCHEMA, "$.cameras: ", "at least one camera is required"},
    {"cameras_missing", "\"cameras\":", "\"kameras\":", APP_ERR_SCHEMA,
     "$.cameras: ", "missing (required)"},
    {"camera_fov_zero", "\"fov\": 60", "\"fov\": 0", APP_ERR_SCHEMA,
     "$.cameras[0].fov: ", "must be in (1, 179), got 0"},
    {"camera_fov_180", "\"fov\": 60", "\"fov\": 180", APP_ERR_SCHEMA,
     "$.cameras[0].fov: ", "must be in (1, 179), got 180"},
    {"camera_fov_1", "\"fov\": 60", "\"fov\": 1", APP_ERR_SCHEMA,
     "$.cameras[0].fov: ", "must be in (1, 179), got 1"},
    {"camera_fov_179", "\"fov\": 60", "\"fov\": 179", APP_ERR_SCHEMA,
     "$.cameras[0].fov: ", "must be in (1, 179), got 179"},
    {"camera_target_equals_position", "\"target\": [1200, 0, 1000]",
     "\"target\": [1200, 2900, 1600]", APP_ERR_SCHEMA,
     "$.cameras[0].target: ", "must differ from position"},
    {"camera_up_zero", "\"up\": [0, 0, 1]", "\"up\": [0, 0, 0]", APP_ERR_SCHEMA,
     "$.cameras[0].up: ", "must not be the zero vector"},
    {"camera_up_parallel", "\"up\": [0, 0, 1]", "\"up\": [0, -2900, -600]", APP_ERR_SCHEMA,
     "$.cameras[0].up: ", "parallel to the viewing direction"},
    {"camera_duplicate_name", "\"cameras\": [", "\"cameras\": [" CAM "\"fov\": 40}, ",
     APP_ERR_SCHEMA, "$.cameras[1].name: ", "duplicate camera name \"door\""},
    /* render */
    {"render_size_zero", "\"size\": [1280, 720]", "\"size\": [0, 0]", APP_ERR_SCHEMA,
     "$.render.size[0]: ", "must be in [1, 16384], got 0"},
    {"render_size_huge", "\"size\": [1280, 720]", "\"size\": [100000, 100000]", APP_ERR_SCHEMA,
     "$.render.size[0]: ", "must be in [1, 16384], got 100000"},
    {"render_size_height_huge", "\"size\": [1280, 720]", "\"size\": [1280, 16385]", APP_ERR_SCHEMA,
     "$.render.size[1]: ", "must be in [1, 16384], got 16385"},
    {"render_size_fraction", "\"size\": [1280, 720]", "\"size\": [1280.5, 720]", APP_ERR_SCHEMA,
     "$.render.size[0]: ", "expected an integer, got 1280.5"},
    {"render_size_three", "\"size\": [1280, 720]", "\"size\": [1280, 720, 3]", APP_ERR_SCHEMA,
     "$.render.size: ", "expected an array of 2 integers"},
    {"render_supersample_five", "\"supersample\": 1", "\"supersample\": 5", APP_ERR_SCHEMA,
     "$.render.supersample: ", "must be in [1, 4], got 5"},
    {"render_white_zero", "\"white\": 4", "\"white\": 0", APP_ERR_SCHEMA,
     "$.render.white: ", "must be > 0, got 0"},
    {"render_exposure_inf", "\"exposure\": 0", "\"exposure\": -1e999", APP_ERR_SCHEMA,
     "$.render.exposure: ", "must be a finite number"},
    {"render_exposure_word", "\"exposure\": 0", "\"exposure\": \"bright\"", APP_ERR_SCHEMA,
     "$.render.exposure: ", "unknown value \"bright\" (use \"auto\" or a number of EV)"},
    {"render_tone_unknown", "\"exposure\": 0", "\"exposure\": 0, \"tone\": \"filmic\"",
     APP_ERR_SCHEMA,
     "$.render.tone: ", "unknown tone curve \"filmic\" (use neutral, agx, reinhard or clamp)"},
    {"render_white_balance_negative", "\"exposure\": 0", "\"exposure\": 0, \"white_balance\": -1",
     APP_ERR_SCHEMA, "$.render.white_balance: ", "must be in [0, 40000], got -1"},
    {"render_ambient_negative", "\"ambient\": [0.1, 0.1, 0.1], \"exposure\"",
     "\"ambient\": [0.1, -1, 0.1], \"exposure\"", APP_ERR_SCHEMA,
     "$.render.ambient[1]: ", "must be >= 0, got -1"},
    {"render_wrong_type", "\"render\": {", "\"render\": \"fast\", \"x\": {", APP_ERR_SCHEMA,
     "$.render: ", "expected an object, got string"},
};

static int run_edit(const edit_case *c)
{
    int before = check_failures;
    char *text = tu_replace(BASE, c->find, c->replace);
    CHECK_MSG(text != NULL, "%s", c->find); /* the case must still match the base */
    if (!text)
        return 0;
    char err[2048] = "";
    app_project p;
    app_result r = app_project_parse(text, strlen(text), CASE_FILE, &p, err, sizeof err);
    CHECK_MSG(r == c->expect, "%s", err);
    if (r != c->expect)
        fprintf(stderr, "    got %s, expected %s\n", app_result_name(r),
                app_result_name(c->expect));
    if (getenv("TESSERA_TEST_VERBOSE"))
        printf("%-40s %-22s %s\n", c->name, app_result_name(r), err);
    CHECK_MSG(tu_contains(err, CASE_FILE ": "), "%s", err);
    CHECK_MSG(tu_contains(err, c->path), "%s", err);
    CHECK_MSG(tu_contains(err, c->detail), "%s", err);
    /* a failed parse leaves the project zeroed */
    CHECK(p.materials == NULL && p.objects == NULL && p.material_count == 0);
    if (r == APP_OK)
        app_project_free(&p);
    free(text);
    return check_failures == before;
}

/* ---- cases that are not one edit of the base -------------------------------------------- */

typedef struct file_case {
    const char *name;
    const char *file; /* under tests/data/projects/ */
    app_result expect;
    const char *path, *detail;
} file_case;

static const file_case FILES[] = {
    {"file_truncated", "bad_truncated.json", APP_ERR_PARSE, ": line 14, column ",
     "malformed JSON (unexpected end of file)"},
    {"file_trailing_garbage", "bad_trailing_garbage.json", APP_ERR_PARSE,
     ": line 3, column 1: ", "unexpected text after the end of the document"},
    {"file_empty", "bad_empty.json", APP_ERR_PARSE, ": line 1, column 1: ", "malformed JSON"},
    {"file_only_array", "bad_array.json", APP_ERR_SCHEMA,
     ": $: ", "expected an object (a Tessera project), got array"},
    {"file_nan_literal", "bad_nan_literal.json", APP_ERR_PARSE,
     ": line 1, column 34: ", "malformed JSON"},
    {"file_newer_version", "bad_newer_version.json", APP_ERR_VERSION,
     ": $.version: ", "written by a newer Tessera (version 99), this build reads up to 2"},
    {"file_missing_version", "bad_missing_version.json", APP_ERR_VERSION,
     ": $.version: ", "missing"},
    {"file_no_cameras", "bad_no_cameras.json", APP_ERR_SCHEMA,
     ": $.cameras: ", "at least one camera"},
    {"file_missing_model", "bad_missing_model.json", APP_ERR_NOT_FOUND,
     ": $.objects[0].model: ", "file not found: "},
    {"file_inf_position", "bad_inf_position.json", APP_ERR_SCHEMA,
     ": $.objects[0].position[1]: ", "must be a finite number"},
    {"file_unknown_parent", "bad_parent.json", APP_ERR_SCHEMA,
     ": $.objects[0].parent: ", "\"vanity\" names no other object"},
};

static int run_file(const file_case *c)
{
    int before = check_failures;
    char path[4096], err[2048] = "";
    snprintf(path, sizeof path, "%s/%s", DATA, c->file);
    app_project p;
    app_result r = app_project_read(path, &p, err, sizeof err);
    CHECK_MSG(r == c->expect, "%s", err);
    CHECK_MSG(tu_contains(err, path), "%s", err);
    CHECK_MSG(tu_contains(err, c->path), "%s", err);
    CHECK_MSG(tu_contains(err, c->detail), "%s", err);
    if (r == APP_OK)
        app_project_free(&p);
    return check_failures == before;
}

static int case_missing_file(void)
{
    int before = check_failures;
    char err[1024];
    app_project p;
    app_result r = app_project_read(DATA "/no-such-project.json", &p, err, sizeof err);
    CHECK(r == APP_ERR_IO);
    CHECK_MSG(strcmp(err, DATA "/no-such-project.json: cannot open: No such file or directory") ==
                  0,
              "%s", err);
    return check_failures == before;
}

static int case_directory(void)
{
    int before = check_failures;
    char err[1024];
    app_project p;
    app_result r = app_project_read(DATA, &p, err, sizeof err);
    CHECK(r == APP_ERR_IO);
    CHECK_MSG(tu_contains(err, DATA ": ") && tu_contains(err, "is a directory"), "%s", err);
    return check_failures == before;
}

/* The missing file's absolute, normalised path is in the message. */
static int case_missing_paths_are_absolute(void)
{
    int before = check_failures;
    char *text = tu_replace(BASE, "models/tap.glb", "./models/../models/gone.glb");
    char *dir = realpath(DATA, NULL);
    char expect[4096], err[2048] = "";
    snprintf(expect, sizeof expect, "$.objects[1].model: file not found: %s/models/gone.glb",
             dir ? dir : "?");
    app_project p;
    app_result r = app_project_parse(text, strlen(text), CASE_FILE, &p, err, sizeof err);
    CHECK(r == APP_ERR_NOT_FOUND);
    CHECK_MSG(tu_contains(err, expect), "%s", err);
    free(text);
    free(dir);
    return check_failures == before;
}

static int case_too_large(void)
{
    int before = check_failures;
    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return 0;
    char path[4096], err[1024];
    snprintf(path, sizeof path, "%s/huge.json", dir);
    int fd = open(path, O_CREAT | O_WRONLY | O_TRUNC, 0644);
    CHECK(fd >= 0 && ftruncate(fd, 65L * 1024 * 1024) == 0); /* sparse: costs no disk */
    if (fd >= 0)
        close(fd);
    app_project p;
    app_result r = app_project_read(path, &p, err, sizeof err);
    CHECK(r == APP_ERR_IO);
    CHECK_MSG(tu_contains(err, path) && tu_contains(err, "too large"), "%s", err);
    tu_remove_tree(dir);
    free(dir);
    return check_failures == before;
}

/* More objects than the limit: refused before any is read. */
static int case_too_many_objects(void)
{
    int before = check_failures;
    const char *head =
        "{\"version\": 1, \"room\": {\"width\": 1, \"depth\": 1, \"height\": 1}, "
        "\"cameras\": [{\"position\": [0,0,0], \"target\": [1,0,0]}], \"objects\": [";
    size_t n = APP_PROJECT_MAX_ITEMS + 1;
    size_t len = strlen(head) + n * 3 + 8;
    char *text = malloc(len);
    CHECK(text != NULL);
    if (!text)
        return 0;
    size_t k = strlen(head);
    memcpy(text, head, k);
    for (size_t i = 0; i < n; i++) {
        memcpy(text + k, "{},", 3);
        k += 3;
    }
    memcpy(text + k - 1, "]}", 2);
    k += 1;
    char err[1024];
    app_project p;
    app_result r = app_project_parse(text, k, CASE_FILE, &p, err, sizeof err);
    CHECK(r == APP_ERR_SCHEMA);
    CHECK_MSG(tu_contains(err, CASE_FILE ": $.objects: too many objects (more than 100000)"), "%s",
              err);
    free(text);
    return check_failures == before;
}

/* Nesting deeper than the JSON parser allows is malformed JSON, not a crash. */
static int case_deep_nesting(void)
{
    int before = check_failures;
    size_t depth = 5000;
    char *text = malloc(depth * 2 + 1);
    CHECK(text != NULL);
    if (!text)
        return 0;
    memset(text, '[', depth);
    memset(text + depth, ']', depth);
    char err[1024];
    app_project p;
    app_result r = app_project_parse(text, depth * 2, CASE_FILE, &p, err, sizeof err);
    CHECK(r == APP_ERR_PARSE);
    CHECK_MSG(tu_contains(err, CASE_FILE ": line 1, column ") && tu_contains(err, "malformed"),
              "%s", err);
    free(text);
    return check_failures == before;
}

/* An error buffer too small for the message is filled and terminated, never overrun. */
static int case_small_error_buffer(void)
{
    int before = check_failures;
    char err[16];
    memset(err, 'x', sizeof err);
    app_project p;
    app_result r = app_project_read(DATA "/bad_newer_version.json", &p, err, 8);
    CHECK(r == APP_ERR_VERSION);
    CHECK(strlen(err) == 7);
    CHECK(err[8] == 'x');
    return check_failures == before;
}

typedef struct special_case {
    const char *name;
    int (*fn)(void);
} special_case;

static const special_case SPECIALS[] = {
    {"file_does_not_exist", case_missing_file},
    {"file_is_directory", case_directory},
    {"missing_paths_are_absolute", case_missing_paths_are_absolute},
    {"file_too_large", case_too_large},
    {"too_many_objects", case_too_many_objects},
    {"deep_nesting", case_deep_nesting},
    {"small_error_buffer", case_small_error_buffer},
};

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

int main(int argc, char **argv)
{
    const char *only = argc > 1 ? argv[1] : NULL;
    int ran = 0, failed = 0;

    /* the base itself must be valid, or every case would pass for the wrong reason */
    {
        char err[2048];
        app_project p;
        app_result r = app_project_parse(BASE, strlen(BASE), CASE_FILE, &p, err, sizeof err);
        CHECK_MSG(r == APP_OK, "%s", err);
        if (r == APP_OK)
            app_project_free(&p);
    }
    for (size_t i = 0; i < COUNT(EDITS); i++) {
        if (only && strcmp(only, EDITS[i].name) != 0)
            continue;
        ran++;
        if (!run_edit(&EDITS[i])) {
            failed++;
            fprintf(stderr, "FAIL %s\n", EDITS[i].name);
        }
    }
    for (size_t i = 0; i < COUNT(FILES); i++) {
        if (only && strcmp(only, FILES[i].name) != 0)
            continue;
        ran++;
        if (!run_file(&FILES[i])) {
            failed++;
            fprintf(stderr, "FAIL %s\n", FILES[i].name);
        }
    }
    for (size_t i = 0; i < COUNT(SPECIALS); i++) {
        if (only && strcmp(only, SPECIALS[i].name) != 0)
            continue;
        ran++;
        if (!SPECIALS[i].fn()) {
            failed++;
            fprintf(stderr, "FAIL %s\n", SPECIALS[i].name);
        }
    }
    if (only && ran == 0) {
        fprintf(stderr, "no case named %s\n", only);
        return 2;
    }
    printf("project_errors: %d cases, %d failed\n", ran, failed);
    return check_report("project_errors");
}
