/* A valid project parses with every field as written and every default as documented
 * (docs/project-format.md). Fixtures: tests/data/projects/valid.json and minimal.json. */
#include "test_util.h"

#include "app/project/project.h"

#include <math.h>

#define DATA TESSERA_PROJECT_TEST_DATA

static int eq3d(const double *v, double a, double b, double c)
{
    return v[0] == a && v[1] == b && v[2] == c;
}

static int eq3f(const float *v, float a, float b, float c)
{
    return v[0] == a && v[1] == b && v[2] == c;
}

static int near3d(const double *v, double a, double b, double c)
{
    return fabs(v[0] - a) < 1e-12 && fabs(v[1] - b) < 1e-12 && fabs(v[2] - c) < 1e-12;
}

static void check_default_material_fields(const app_material *m)
{
    CHECK(eq3f(m->diffuse, 0.8f, 0.8f, 0.8f));
    CHECK(eq3f(m->ambient, 0.8f, 0.8f, 0.8f));
    CHECK(eq3f(m->specular, 0, 0, 0));
    CHECK(eq3f(m->emissive, 0, 0, 0));
    CHECK(m->shininess == 32.0f);
    CHECK(m->texture[0] == '\0');
    CHECK(m->texture_size_mm[0] == 1000.0f && m->texture_size_mm[1] == 1000.0f);
}

static void test_valid(void)
{
    char err[1024];
    app_project p;
    app_result r = app_project_read(DATA "/valid.json", &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return;
    char *real_file = realpath(DATA "/valid.json", NULL);
    char *real_texture = realpath(DATA "/textures/wall.png", NULL);
    char *real_model = realpath(DATA "/models/tap.glb", NULL);
    CHECK(real_file && real_texture && real_model);

    CHECK(p.version == APP_PROJECT_VERSION);
    CHECK(p.file_version == 1);
    CHECK(strcmp(p.name, "Valid test bathroom") == 0);
    CHECK(real_file && strcmp(p.path, real_file) == 0);

    /* room */
    CHECK(p.room.width_mm == 2400 && p.room.depth_mm == 3000 && p.room.height_mm == 2500);
    CHECK(p.room.floor_material == 1);
    CHECK(p.room.wall_material == 0);
    CHECK(p.room.ceiling_material == 5);

    /* materials: the dictionary in file order, then inline ones and "default" as met */
    CHECK(p.material_count == 8);
    const char *names[] = {"wall-tile",       "floor-tile", "chrome",
                           "ceramic",         "lamp-glass", "room.ceiling#material",
                           "mirror#material", "default"};
    for (int i = 0; i < 8 && i < p.material_count; i++)
        CHECK_MSG(strcmp(p.materials[i].name, names[i]) == 0, "%s", names[i]);
    if (p.material_count == 8) {
        const app_material *m = &p.materials[0];
        CHECK(eq3f(m->diffuse, 0.8f, 0.8f, 0.78f));
        CHECK(eq3f(m->ambient, 0.7f, 0.7f, 0.68f));
        CHECK(eq3f(m->specular, 0.3f, 0.3f, 0.3f));
        CHECK(eq3f(m->emissive, 0, 0, 0));
        CHECK(m->shininess == 64.0f);
        CHECK(real_texture && strcmp(m->texture, real_texture) == 0);
        CHECK(m->texture_size_mm[0] == 300.0f && m->texture_size_mm[1] == 600.0f);

        m = &p.materials[1]; /* only diffuse: ambient follows it */
        CHECK(eq3f(m->diffuse, 0.5f, 0.45f, 0.4f));
        CHECK(eq3f(m->ambient, 0.5f, 0.45f, 0.4f));
        CHECK(eq3f(m->specular, 0, 0, 0));
        CHECK(m->shininess == 32.0f);
        CHECK(m->texture[0] == '\0');

        m = &p.materials[2];
        CHECK(eq3f(m->diffuse, 0.1f, 0.1f, 0.1f));
        CHECK(eq3f(m->specular, 0.9f, 0.9f, 0.9f));
        CHECK(m->shininess == 512.0f);

        check_default_material_fields(&p.materials[3]); /* "ceramic": {} */
        check_default_material_fields(&p.materials[7]); /* "default" */

        m = &p.materials[4];
        CHECK(eq3f(m->emissive, 4.0f, 3.6f, 3.0f));
        CHECK(eq3f(m->ambient, 1, 1, 1));

        m = &p.materials[5];
        CHECK(eq3f(m->diffuse, 0.9f, 0.9f, 0.9f));
        CHECK(eq3f(m->ambient, 0.9f, 0.9f, 0.9f));

        m = &p.materials[6];
        CHECK(eq3f(m->diffuse, 0.05f, 0.05f, 0.05f));
        CHECK(eq3f(m->ambient, 0.05f, 0.05f, 0.05f));
        CHECK(eq3f(m->specular, 1, 1, 1));
        CHECK(m->shininess == 1000.0f);
        CHECK(m->texture_size_mm[0] == 1000.0f);
    }

    /* objects */
    CHECK(p.object_count == 6);
    if (p.object_count == 6) {
        const app_object *o = &p.objects[0];
        CHECK(strcmp(o->name, "basin") == 0);
        CHECK(o->shape == APP_SHAPE_CYLINDER);
        CHECK(o->model[0] == '\0');
        CHECK(eq3d(o->position_mm, 600, 300, 850));
        CHECK(eq3d(o->size_mm, 600, 450, 150));
        CHECK(eq3d(o->rotation_deg, 0, 0, 90));
        CHECK(eq3d(o->scale, 1, 1, 1));
        CHECK(o->material == 3);

        o = &p.objects[1];
        CHECK(strcmp(o->name, "tap") == 0);
        CHECK(o->shape == APP_SHAPE_MODEL);
        CHECK(real_model && strcmp(o->model, real_model) == 0);
        CHECK(eq3d(o->position_mm, 600, 100, 900));
        CHECK(eq3d(o->rotation_deg, 0, 0, 0));
        CHECK(eq3d(o->scale, 1, 1, 1));
        CHECK(eq3d(o->size_mm, 0, 0, 0));
        CHECK(o->material == 2);

        o = &p.objects[2];
        CHECK(o->shape == APP_SHAPE_PLANE);
        CHECK(eq3d(o->size_mm, 500, 700, 0));
        CHECK(eq3d(o->rotation_deg, 90, 0, 0));
        CHECK(o->material == 6);

        o = &p.objects[3]; /* no name, no material, no rotation */
        CHECK(strcmp(o->name, "object-3") == 0);
        CHECK(o->shape == APP_SHAPE_BOX);
        CHECK(eq3d(o->size_mm, 700, 1400, 800));
        CHECK(eq3d(o->scale, 1, 1, -1));
        CHECK(eq3d(o->rotation_deg, 0, 0, 0));
        CHECK(o->material == 7);

        CHECK(p.objects[4].shape == APP_SHAPE_SPHERE && p.objects[4].material == 4);
        CHECK(p.objects[5].shape == APP_SHAPE_TORUS && eq3d(p.objects[5].size_mm, 180, 180, 20));
    }

    /* lights */
    CHECK(p.light_count == 4);
    if (p.light_count == 4) {
        const app_light *l = &p.lights[0];
        CHECK(strcmp(l->name, "ceiling") == 0);
        CHECK(l->type == APP_LIGHT_POINT);
        CHECK(eq3d(l->position_mm, 1200, 1500, 2400));
        CHECK(eq3d(l->direction, 0, 0, -1));
        CHECK(eq3f(l->color, 1, 0.95f, 0.9f));
        CHECK(l->intensity == 3.0f);
        CHECK(eq3f(l->specular, 0.5f, 0.5f, 0.5f));
        CHECK(eq3f(l->attenuation, 1, 0.5f, 1));
        CHECK(l->inner_deg == 25.0f && l->outer_deg == 35.0f);

        l = &p.lights[1];
        CHECK(l->type == APP_LIGHT_SPOT);
        CHECK(eq3d(l->direction, 0, 0, -1)); /* [0,0,-2] normalised */
        CHECK(eq3f(l->color, 1, 1, 1));
        CHECK(l->intensity == 1.0f);
        CHECK(eq3f(l->specular, 1, 1, 1));
        CHECK(eq3f(l->attenuation, 1, 0, 1));
        CHECK(l->inner_deg == 20.0f && l->outer_deg == 30.0f);

        l = &p.lights[2];
        CHECK(strcmp(l->name, "light-2") == 0);
        CHECK(l->type == APP_LIGHT_DIRECTIONAL);
        CHECK(near3d(l->direction, 0, 0.6, -0.8));
        CHECK(eq3d(l->position_mm, 0, 0, 0));
        CHECK(eq3f(l->color, 0.2f, 0.2f, 0.3f));
        CHECK(eq3f(l->specular, 0.2f, 0.2f, 0.3f)); /* specular follows color */

        l = &p.lights[3];
        CHECK(strcmp(l->name, "light-3") == 0);
        CHECK(l->type == APP_LIGHT_POINT);
        CHECK(eq3d(l->position_mm, 100, 100, 100));
        CHECK(eq3f(l->color, 1, 1, 1) && l->intensity == 1.0f);
        CHECK(eq3f(l->attenuation, 1, 0, 1));
    }

    /* cameras */
    CHECK(p.camera_count == 2);
    if (p.camera_count == 2) {
        const app_camera *cam = &p.cameras[0];
        CHECK(strcmp(cam->name, "door") == 0);
        CHECK(eq3d(cam->position_mm, 1200, 2900, 1600));
        CHECK(eq3d(cam->target_mm, 1200, 0, 1000));
        CHECK(eq3d(cam->up, 0, 0, 1));
        CHECK(cam->fov_deg == 50);
        cam = &p.cameras[1];
        CHECK(strcmp(cam->name, "camera-1") == 0);
        CHECK(eq3d(cam->up, 0, 0, 1));
        CHECK(cam->fov_deg == 60);
    }

    /* render */
    CHECK(eq3f(p.render.ambient, 0.2f, 0.2f, 0.2f));
    CHECK(p.render.exposure_ev == -1.5f);
    CHECK(p.render.white == 6.0f);
    CHECK(p.render.width == 640 && p.render.height == 360);
    CHECK(p.render.supersample == 2);

    /* look-ups */
    CHECK(app_project_find_camera(&p, NULL) == &p.cameras[0]);
    CHECK(app_project_find_camera(&p, "camera-1") == &p.cameras[1]);
    CHECK(app_project_find_camera(&p, "kitchen") == NULL);
    CHECK(app_project_find_material(&p, "chrome") == 2);
    CHECK(app_project_find_material(&p, "default") == 7);
    CHECK(app_project_find_material(&p, "chrom") == -1);
    CHECK(app_project_find_material(&p, NULL) == -1);

    free(real_file);
    free(real_texture);
    free(real_model);
    app_project_free(&p);
    CHECK(p.materials == NULL && p.material_count == 0 && p.camera_count == 0);
}

/* Only the required fields: every default of render and room materials. */
static void test_minimal_defaults(void)
{
    char err[1024];
    app_project p;
    app_result r = app_project_read(DATA "/minimal.json", &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return;
    CHECK(p.name[0] == '\0');
    CHECK(p.material_count == 1 && strcmp(p.materials[0].name, "default") == 0);
    check_default_material_fields(&p.materials[0]);
    CHECK(p.room.floor_material == 0 && p.room.wall_material == 0 && p.room.ceiling_material == 0);
    CHECK(p.object_count == 0 && p.light_count == 0 && p.camera_count == 1);
    CHECK(strcmp(p.cameras[0].name, "camera-0") == 0);
    CHECK(p.cameras[0].fov_deg == 60 && eq3d(p.cameras[0].up, 0, 0, 1));
    CHECK(eq3f(p.render.ambient, 0.1f, 0.1f, 0.1f));
    CHECK(p.render.exposure_ev == 0.0f);
    CHECK(p.render.white == 4.0f);
    CHECK(p.render.width == 1280 && p.render.height == 720);
    CHECK(p.render.supersample == 1);
    app_project_free(&p);
}

/* From memory: no path means "<memory>" in messages and an empty app_project.path. */
static void test_parse_from_memory(void)
{
    static const char text[] =
        "{\"version\": 1, \"room\": {\"width\": 1, \"depth\": 1, \"height\": 1},"
        " \"cameras\": [{\"position\": [0,0,0], \"target\": [1,0,0]}]}";
    char err[256];
    app_project p;
    app_result r = app_project_parse(text, sizeof text - 1, NULL, &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    CHECK(p.path[0] == '\0');
    app_project_free(&p);

    /* not NUL-terminated: only len bytes are read */
    char buf[sizeof text + 8];
    memcpy(buf, text, sizeof text - 1);
    memset(buf + sizeof text - 1, 'x', 9);
    r = app_project_parse(buf, sizeof text - 1, NULL, &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    app_project_free(&p);

    r = app_project_parse(text, 10, NULL, &p, err, sizeof err);
    CHECK(r == APP_ERR_PARSE);
    CHECK_MSG(tu_contains(err, "<memory>: line 1, column 11: malformed JSON"), "%s", err);

    /* no error buffer at all is fine */
    CHECK(app_project_parse(text, 10, NULL, &p, NULL, 0) == APP_ERR_PARSE);
    CHECK(app_project_parse(text, 10, NULL, NULL, err, sizeof err) != APP_OK);
}

/* The example in docs/project-format.md is a valid project (read next to the fixtures, so
 * its "models/tap.glb" and "textures/wall.png" resolve). */
static void test_docs_example(void)
{
    char *doc = tu_read_file(TESSERA_PROJECT_DOCS, NULL);
    CHECK(doc != NULL);
    if (!doc)
        return;
    const char *section = strstr(doc, "\n## Example");
    const char *start = section ? strstr(section, "```json\n") : NULL;
    const char *end = start ? strstr(start + 8, "\n```") : NULL;
    CHECK(section && start && end);
    if (start && end) {
        start += 8;
        char err[1024];
        app_project p;
        app_result r = app_project_parse(start, (size_t)(end - start), DATA "/docs-example.json",
                                         &p, err, sizeof err);
        CHECK_MSG(r == APP_OK, "%s", err);
        if (r == APP_OK) {
            CHECK(strcmp(p.name, "Demo bathroom") == 0);
            CHECK(p.object_count == 4 && p.light_count == 3 && p.camera_count == 1);
            app_project_free(&p);
        }
    }
    free(doc);
}

static void test_free_is_safe(void)
{
    app_project zero;
    memset(&zero, 0, sizeof zero);
    app_project_free(&zero);
    app_project_free(&zero);
    app_project_free(NULL);
    CHECK(app_project_find_camera(&zero, NULL) == NULL);
    CHECK(app_project_find_camera(NULL, NULL) == NULL);
    CHECK(app_project_find_material(NULL, "x") == -1);
    CHECK(strcmp(app_result_name(APP_ERR_VERSION), "APP_ERR_VERSION") == 0);
}

int main(void)
{
    test_valid();
    test_minimal_defaults();
    test_parse_from_memory();
    test_docs_example();
    test_free_is_safe();
    return check_report("project_valid");
}
