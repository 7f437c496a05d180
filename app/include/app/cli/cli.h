/* The `tessera` command line: one sub-command per capability. Each returns the process exit
 * code: 0 success, 1 the work failed, 2 bad usage or bad input. */
#ifndef APP_CLI_H
#define APP_CLI_H

#ifdef __cplusplus
extern "C" {
#endif

int app_cli_main(int argc, char **argv);
int app_cli_render(int argc, char **argv);
int app_cli_panorama(int argc, char **argv);
int app_cli_video(int argc, char **argv);
int app_cli_demo(int argc, char **argv);
int app_cli_bench(int argc, char **argv);
int app_cli_probe_bench(int argc, char **argv);
int app_cli_sweep(int argc, char **argv);
int app_cli_extremes(int argc, char **argv);
int app_cli_catalog(int argc, char **argv);
int app_cli_catalog_model(int argc, char **argv);
int app_cli_catalog_thumbs(int argc, char **argv); /* cli_catalog_thumbs.c */
int app_cli_catalog_lod(int argc, char **argv);    /* cli_catalog_lod.c */
int app_cli_print(int argc, char **argv);
int app_cli_share(int argc, char **argv); /* cli_share.c */
/* tessera demo's print set: OUT_DIR/plan.pdf with the demo-CAMERA.png renders found there. */
struct app_project;
int app_cli_print_demo(const struct app_project *p, const char *out_dir);
int app_cli_quantities(int argc, char **argv);
int app_cli_edit(int argc, char **argv);       /* cli_edit.c */
int app_cli_check(int argc, char **argv);      /* cli_check.c */
int app_cli_surfaces(int argc, char **argv);   /* cli_surfaces.c */
int app_cli_export_glb(int argc, char **argv); /* cli_export_glb.c */

#ifdef __cplusplus
}
#endif
#endif
