/* The ground-truth sub-commands (RENDERING.md section 10; docs/reference.md). Each returns the
 * process exit code as app/cli/cli.h's do: 0 success, 1 the work failed, 2 bad usage or bad input.
 * argv[1] is the sub-command's name, as app_cli_main passes it. */
#ifndef APP_CLI_REF_H
#define APP_CLI_REF_H

#ifdef __cplusplus
extern "C" {
#endif

/* tessera reference PROJECT -o OUT.(exr|png|jpg|tif) [--camera NAME] [--size WxH]
 *                   [--supersample N] [--samples N] [--threads N] [--seed N] [--png OUT.png]
 *                   [--mask MASK.png] */
int app_cli_reference(int argc, char **argv);

/* tessera compare A B [--mask M] [--heatmap OUT.png] [--heat-max E] */
int app_cli_compare(int argc, char **argv);

#ifdef __cplusplus
}
#endif
#endif
