/* --stats FILE.json: the renderer's frame statistics and the settings a render resolved to, as
 * one JSON object for scripts and tests (docs/cli.md, "Frame statistics"). */
#ifndef APP_CLI_STATS_H
#define APP_CLI_STATS_H

#include "cli_options.h"

/* Writes `st` (every rd_frame_stats field by its C name, under "frame"), the resolved
 * settings of `s` and `view` (under "settings": the preset, each switch "on" or "off", the
 * tone curve, exposure and white balance) and, when image_path names an 8-bit image just
 * written, its contrast (under "image": luma percentiles, clipped fraction) to `path`,
 * atomically (a temporary file next to it, then rename). Prints the problem naming the file
 * and returns CLI_FAILED if it cannot be written. */
int cli_write_stats(const char *path, const cli_session *s, const cli_options *o,
                    const rd_view *view, const rd_frame_stats *st, const char *image_path);

/* The last bake's counts (app_bake_last_stats) as a JSON object, and a JSON document written
 * atomically (root is freed). */
typedef struct cJSON cJSON;
cJSON *cli_bake_stats_json(void);
int cli_write_json_atomic(const char *path, cJSON *root);

#endif
