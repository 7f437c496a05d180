#include "cli_stats.h"

#include "app/measure/image_contrast.h"
#include "app/scene/quality.h"
#include "app/scene/scene_bake.h"
#include "render/image_io.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *on_off(int on)
{
    return on ? "on" : "off";
}

static cJSON *frame_json(const rd_frame_stats *st)
{
    cJSON *f = cJSON_CreateObject();
#define FIELD(name) cJSON_AddNumberToObject(f, #name, (double)st->name)
    FIELD(probes);
    FIELD(faces_captured);
    FIELD(prefiltered);
    FIELD(adaptive);
    FIELD(refined_pixels);
    FIELD(planar_mirrors);
    FIELD(room_probe);
    FIELD(glazed);
    FIELD(emitters);
    FIELD(emitter_probes);
    FIELD(self_traced_probes);
    FIELD(self_triangles);
    FIELD(exposure_ev);
#undef FIELD
    return f;
}

static cJSON *settings_json(const cli_session *s, const cli_options *o, const rd_view *view)
{
    rd_reflection_defaults d = rd_scene_reflection_defaults(s->scene.scene);
    rd_shadow_settings sh = rd_scene_shadows(s->scene.scene);
    cJSON *j = cJSON_CreateObject();
    cJSON_AddStringToObject(j, "quality", o->quality ? o->quality->name : "project");
    cJSON_AddNumberToObject(j, "width", view->width);
    cJSON_AddNumberToObject(j, "height", view->height);
    cJSON_AddNumberToObject(j, "supersample", view->supersample > 1 ? view->supersample : 1);
    cJSON_AddStringToObject(j, "adaptive", on_off(view->adaptive && view->supersample > 1));
    cJSON_AddStringToObject(j, "planar_mirrors", on_off(d.planar_mirrors == RD_SWITCH_ON));
    cJSON_AddStringToObject(j, "room_probe", on_off(d.room_probe != RD_SWITCH_OFF));
    cJSON_AddStringToObject(j, "glaze", on_off(d.glaze == RD_SWITCH_ON));
    cJSON_AddStringToObject(j, "exact_lamps", on_off(d.exact_lamps != RD_SWITCH_OFF));
    cJSON_AddStringToObject(j, "self_reflections", on_off(d.self_reflections > 0));
    cJSON_AddNumberToObject(j, "self_reflection_rays", d.self_reflections);
    cJSON_AddNumberToObject(j, "probe_resolution", d.resolution);
    cJSON_AddStringToObject(j, "shadows", rd_shadow_mode_name(sh.mode));
    cJSON_AddStringToObject(j, "tone", rd_tonemap_name(view->tonemap));
    if (view->auto_exposure)
        cJSON_AddStringToObject(j, "exposure", "auto");
    else
        cJSON_AddNumberToObject(j, "exposure", view->exposure_ev);
    cJSON_AddNumberToObject(j, "white_balance", view->white_balance_k);
    return j;
}

/* `text` into `path` through a temporary file in the same folder, so a reader never sees half a
 * file and a failed write leaves the old one. */
static int write_atomic(const char *path, const char *text)
{
    size_t n = strlen(path);
    char *tmp = malloc(n + sizeof ".tmp-XXXXXX");
    if (!tmp) {
        fprintf(stderr, "tessera: %s: out of memory\n", path);
        return CLI_FAILED;
    }
    memcpy(tmp, path, n);
    memcpy(tmp + n, ".tmp-XXXXXX", sizeof ".tmp-XXXXXX");
    int fd = mkstemp(tmp);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    int ok = f && fputs(text, f) >= 0;
    ok = f && fclose(f) == 0 && ok;
    ok = ok && rename(tmp, path) == 0;
    if (!ok) {
        fprintf(stderr, "tessera: %s: cannot write the statistics: %s\n", path, strerror(errno));
        if (fd >= 0)
            unlink(tmp);
    }
    free(tmp);
    return ok ? CLI_OK : CLI_FAILED;
}

cJSON *cli_bake_stats_json(void)
{
    const app_bake_stats *b = app_bake_last_stats();
    cJSON *j = cJSON_CreateObject();
    cJSON_AddStringToObject(j, "bake", on_off(b->ran));
    cJSON_AddStringToObject(j, "cache_hit", on_off(b->cache_hit));
    cJSON_AddNumberToObject(j, "elements", b->elements);
    cJSON_AddNumberToObject(j, "reused_elements", b->reused_elements);
    cJSON_AddNumberToObject(j, "baked_elements", (double)(b->baked_texels + b->baked_vertices));
    cJSON_AddNumberToObject(j, "baked_texels", (double)b->baked_texels);
    cJSON_AddNumberToObject(j, "baked_vertices", (double)b->baked_vertices);
    cJSON_AddNumberToObject(j, "total_texels", (double)b->total_texels);
    cJSON_AddNumberToObject(j, "total_vertices", (double)b->total_vertices);
    cJSON_AddNumberToObject(j, "rays", (double)b->rays);
    cJSON_AddNumberToObject(j, "seconds", b->seconds);
    return j;
}

int cli_write_json_atomic(const char *path, cJSON *root)
{
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) {
        fprintf(stderr, "tessera: %s: out of memory\n", path);
        return CLI_FAILED;
    }
    int rc = write_atomic(path, text);
    free(text);
    return rc;
}

/* The written image's contrast (app_image_contrast); NULL for a linear (float) file. */
static cJSON *image_json(const char *image_path)
{
    rd_image img;
    char err[1024];
    if (rd_image_read(image_path, &img, NULL, err, sizeof err) != RD_IMAGE_OK)
        return NULL;
    app_image_contrast c;
    int ok = img.srgb_encoded &&
             app_image_contrast_of(img.pixels, img.width, img.height, img.channels, &c) == 0;
    free(img.pixels);
    if (!ok)
        return NULL;
    cJSON *j = cJSON_CreateObject();
    cJSON_AddStringToObject(j, "file", image_path);
    cJSON_AddNumberToObject(j, "luma_p1", c.luma_p1);
    cJSON_AddNumberToObject(j, "luma_p50", c.luma_p50);
    cJSON_AddNumberToObject(j, "luma_p99", c.luma_p99);
    cJSON_AddNumberToObject(j, "luma_mean", c.luma_mean);
    cJSON_AddNumberToObject(j, "clipped_fraction", c.clipped_fraction);
    return j;
}

int cli_write_stats(const char *path, const cli_session *s, const cli_options *o,
                    const rd_view *view, const rd_frame_stats *st, const char *image_path)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "project", s->project.path);
    cJSON_AddItemToObject(root, "settings", settings_json(s, o, view));
    cJSON_AddItemToObject(root, "frame", frame_json(st));
    cJSON_AddItemToObject(root, "bake", cli_bake_stats_json());
    cJSON *image = image_path ? image_json(image_path) : NULL;
    if (image)
        cJSON_AddItemToObject(root, "image", image);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) {
        fprintf(stderr, "tessera: %s: out of memory\n", path);
        return CLI_FAILED;
    }
    size_t len = strlen(text);
    char *line = realloc(text, len + 2); /* a text file ends in a newline */
    if (line) {
        memcpy(line + len, "\n", 2);
        text = line;
    }
    int rc = write_atomic(path, text);
    free(text);
    return rc;
}
