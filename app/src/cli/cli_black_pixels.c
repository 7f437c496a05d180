/* A render that shows no room (the camera outside it, the room behind the far plane or in
 * front of the near plane) is an image of the clear colour: count it instead of writing it
 * silently. */
#include "cli_black_pixels.h"

#include <stdio.h>

double cli_black_fraction(const uint8_t *rgba, int width, int height)
{
    size_t n = (size_t)width * (size_t)height, black = 0;
    if (!rgba || n == 0)
        return 0.0;
    for (size_t i = 0; i < n; i++) {
        const uint8_t *p = rgba + 4 * i;
        black += p[0] <= CLI_BLACK_LEVEL && p[1] <= CLI_BLACK_LEVEL && p[2] <= CLI_BLACK_LEVEL;
    }
    return (double)black / (double)n;
}

int cli_check_room_visible(const cli_session *s, const char *camera, const char *path)
{
    if (!(s->black_fraction > CLI_BLACK_LIMIT))
        return CLI_OK;
    fprintf(stderr,
            "tessera render: camera %s shows no room in %.0f %% of %s (black pixels): is the "
            "camera outside the room, or an object far outside it (`tessera check`)?\n",
            camera && camera[0] ? camera : "(the first)", 100.0 * s->black_fraction, path);
    return CLI_FAILED;
}
