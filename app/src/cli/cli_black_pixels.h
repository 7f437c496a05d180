#ifndef APP_CLI_BLACK_PIXELS_H
#define APP_CLI_BLACK_PIXELS_H

#include "cli_options.h"

#include <stdint.h>

/* A pixel is black when each of its display values is at most this (of 255): the clear
 * colour where no surface was drawn, which a lit room never tone maps to. */
#define CLI_BLACK_LEVEL 1
/* `render` fails when more than this fraction of the image is black: the camera saw (almost)
 * no room (docs/cli.md, "render"). */
#define CLI_BLACK_LIMIT 0.5

/* The fraction of the RGBA8 image's pixels that are black. */
double cli_black_fraction(const uint8_t *rgba, int width, int height);

/* After `render` wrote `path` from `camera`: prints a warning naming the camera and returns
 * CLI_FAILED when s->black_fraction is over CLI_BLACK_LIMIT, else CLI_OK. */
int cli_check_room_visible(const cli_session *s, const char *camera, const char *path);

#endif
