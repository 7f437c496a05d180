/* Names of tile patterns and alignments, as the project file and the CLI spell them. */
#include "app/design/tile_layout.h"

#include <strings.h>

/* As the project file spells them (docs/project-format.md, project_read_tilings.c). */
static const char *const pattern_names[] = {"straight",       "half-offset", "third-offset",
                                            "vertical-stack", "diagonal",    "herringbone"};
static const char *const align_names[] = {"centred", "corner", "line", "auto"};

/* "half_offset" for "half-offset": what a shell user may type. */
static int same_but_underscore(const char *text, const char *name)
{
    for (; *text && *name; text++, name++) {
        char a = *text == '_' ? '-' : *text;
        if ((a | 0x20) != (*name | 0x20))
            return 0;
    }
    return *text == *name;
}

const char *app_tile_pattern_name(app_tile_pattern p)
{
    return (int)p >= 0 && (int)p < 6 ? pattern_names[p] : "";
}

int app_tile_pattern_parse(const char *text, app_tile_pattern *out)
{
    for (int i = 0; text && i < 6; i++)
        if (!strcasecmp(text, pattern_names[i]) || same_but_underscore(text, pattern_names[i])) {
            *out = (app_tile_pattern)i;
            return 1;
        }
    return 0;
}

const char *app_tile_align_name(app_tile_align a)
{
    return (int)a >= 0 && (int)a < 4 ? align_names[a] : "";
}

int app_tile_align_parse(const char *text, app_tile_align *out)
{
    for (int i = 0; text && i < 4; i++)
        if (!strcasecmp(text, align_names[i])) {
            *out = (app_tile_align)i;
            return 1;
        }
    return 0;
}
