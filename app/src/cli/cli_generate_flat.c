/* tessera generate-flat [--rooms N] [--seed S] -o FLAT.json: the synthetic flat of
 * app/project/flat_generate.h, for tests and the benchmarks of docs/benchmarks.md. */
#include "app/project/flat_generate.h"
#include "cli_commands.h"

#include <stdio.h>

int cli_cmd_generate_flat(const cli_options *o)
{
    if (!o->output)
        return cli_usage_error(o);
    int rooms = o->rooms > 0 ? o->rooms : 8;
    app_flat_generate_report rep;
    char err[2048];
    app_result r =
        app_flat_generate(rooms, (unsigned long long)o->seed, o->output, &rep, err, sizeof err);
    if (r != APP_OK) {
        fprintf(stderr, "tessera generate-flat: %s\n", err);
        return r == APP_ERR_IO || r == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    printf("%s: %d rooms, %d fixtures, %d tilings\n", o->output, rep.rooms, rep.fixtures,
           rep.tilings);
    return CLI_OK;
}
