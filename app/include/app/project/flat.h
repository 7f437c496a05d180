/* A flat: several rooms in one project file (docs/project-format.md "Flats").
 *
 * A file with a top-level "rooms" array is a flat; each room is read as the single-room
 * project it would be on its own (its name, room materials, plan, tilings, objects, lights and
 * cameras, in the room's own coordinates), sharing the file's version, materials, render
 * settings and daylight. A file without "rooms" is a flat of one room, read unchanged, so every
 * command that takes flats takes every project. */
#ifndef APP_FLAT_H
#define APP_FLAT_H

#include "app/project/project.h"

#ifdef __cplusplus
extern "C" {
#endif

#define APP_FLAT_MAX_ROOMS 256

typedef struct app_flat {
    char name[128];         /* the flat's name ($.name); the rooms carry their own */
    int is_flat;            /* 1: read from a "rooms" array; 0: a single-room project */
    app_project *rooms;     /* each a complete project; rooms[i].name is the room's name */
    double (*offset_mm)[2]; /* where each room's origin lies in the flat's plan, mm */
    int room_count;         /* >= 1 after a successful read */
} app_flat;

/* Reads a flat or a single-room project. *out is overwritten; on success it owns its rooms
 * (app_flat_free), on failure it is all zero and err names the file and the JSON path, e.g.
 *     FILE: $.rooms[2].plan.corners: ... */
app_result app_flat_read(const char *path, app_flat *out, char *err, size_t err_size);

void app_flat_free(app_flat *f);

/* The room holding the camera named `camera` (the first such room); NULL = room 0; -1 when no
 * room has it. */
int app_flat_room_of_camera(const app_flat *f, const char *camera);

/* Moves room i out of f into *out (the caller frees it with app_project_free) and frees the
 * rest of f: a command that needs one room keeps only that one. */
void app_flat_take_room(app_flat *f, int i, app_project *out);

#ifdef __cplusplus
}
#endif
#endif
