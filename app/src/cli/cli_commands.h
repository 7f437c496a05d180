/* The functions the command table (cli_command_table.c) runs, one a command; each gets the
 * options parsed by the table and returns the exit code (0 done, 1 failed, 2 bad usage). */
#ifndef APP_CLI_COMMANDS_H
#define APP_CLI_COMMANDS_H

#include "cli_options.h"

int cli_cmd_help(const cli_options *o);
int cli_cmd_open(const cli_options *o);
int cli_cmd_demo(const cli_options *o);
int cli_cmd_render(const cli_options *o);
int cli_cmd_bake(const cli_options *o);
int cli_cmd_panorama(const cli_options *o);
int cli_cmd_video(const cli_options *o);
int cli_cmd_share(const cli_options *o);
int cli_cmd_print(const cli_options *o);
int cli_cmd_edit(const cli_options *o);
int cli_cmd_check(const cli_options *o);
int cli_cmd_quantities(const cli_options *o);
int cli_cmd_surfaces(const cli_options *o);
int cli_cmd_export_glb(const cli_options *o);
int cli_cmd_generate_flat(const cli_options *o);

/* The measurement tools (app/src/measure/). */
int cli_cmd_bench(const cli_options *o);
int cli_cmd_probe_bench(const cli_options *o);
int cli_cmd_reference(const cli_options *o);
int cli_cmd_compare(const cli_options *o);
int cli_cmd_sweep(const cli_options *o);
int cli_cmd_extremes(const cli_options *o);

/* tessera catalog ... */
int cli_cmd_catalog_search(const cli_options *o);
int cli_cmd_catalog_show(const cli_options *o);
int cli_cmd_catalog_import(const cli_options *o);
int cli_cmd_catalog_export(const cli_options *o);
int cli_cmd_catalog_info(const cli_options *o);
int cli_cmd_catalog_bench(const cli_options *o);
int cli_cmd_catalog_model(const cli_options *o);
int cli_cmd_catalog_thumbs(const cli_options *o);
int cli_cmd_catalog_lod(const cli_options *o);

/* Defaults a command presets before parsing, where zero is a value the user may give. */
void cli_defaults_bench(cli_options *o);
void cli_defaults_probe_bench(cli_options *o);
void cli_defaults_sweep(cli_options *o);
void cli_defaults_reference(cli_options *o);
void cli_defaults_extremes(cli_options *o);
void cli_defaults_quantities(cli_options *o);

#endif
