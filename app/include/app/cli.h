/* The `tessera` command line: one sub-command per capability. Each returns the process exit
 * code: 0 success, 1 the work failed, 2 bad usage or bad input. */
#ifndef APP_CLI_H
#define APP_CLI_H

#ifdef __cplusplus
extern "C" {
#endif

int app_cli_main(int argc, char **argv);
int app_cli_render(int argc, char **argv);
int app_cli_demo(int argc, char **argv);
int app_cli_bench(int argc, char **argv);
int app_cli_probe_bench(int argc, char **argv);
int app_cli_sweep(int argc, char **argv);
int app_cli_extremes(int argc, char **argv);
int app_cli_catalog(int argc, char **argv);

#ifdef __cplusplus
}
#endif
#endif
