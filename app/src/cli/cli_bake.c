/* tessera bake PROJECT [--stats FILE.json]
 * The baked indirect light of a project (app/scene/scene_bake.h) into its cache, with a progress
 * bar, and a line saying what was computed and what came from the cache. Renders bake on their
 * own; this runs the bake alone, to prepare a showing or to time it. */
#include "app/scene/render_list.h"
#include "app/scene/scene_bake.h"
#include "cli_commands.h"
#include "cli_stats.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <unistd.h>

int cli_cmd_bake(const cli_options *o)
{
    char err[2048];
    app_project p;
    app_result r = app_project_read(o->project, &p, err, sizeof err);
    if (r != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return r == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    app_render_list l;
    r = app_render_list_build(&p, 0, &l, err, sizeof err);
    if (r != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        app_project_free(&p);
        return r == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    app_bake_settings s = {.on = 1, .progress = isatty(2)};
    ref_bake bake;
    app_bake_stats st;
    r = app_bake_list(&l, &s, &bake, &st, err, sizeof err);
    app_render_list_free(&l);
    app_project_free(&p);
    if (r != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    printf("bake: %d elements, %d from the cache; baked %lld of %lld texels and %lld of %lld "
           "vertices (%lld rays) in %.2f s\n",
           st.elements, st.reused_elements, st.baked_texels, st.total_texels, st.baked_vertices,
           st.total_vertices, st.rays, st.seconds);
    printf("cache: %s%s\n", st.cache_path[0] ? st.cache_path : "(none: no HOME)",
           st.cache_hit ? " (whole scene reused)" : "");
    ref_bake_free(&bake);
    if (o->stats) {
        cJSON *root = cJSON_CreateObject();
        cJSON_AddStringToObject(root, "project", o->project);
        cJSON_AddItemToObject(root, "bake", cli_bake_stats_json());
        return cli_write_json_atomic(o->stats, root);
    }
    return CLI_OK;
}
