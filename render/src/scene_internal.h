#ifndef RENDER_SCENE_INTERNAL_H
#define RENDER_SCENE_INTERNAL_H

#include "render/render.h"

struct rd_scene {
    rd_context *ctx;
    rd_object_desc *objects;
    int object_count, object_capacity;
    rd_light lights[RD_MAX_LIGHTS];
    int light_count;
    float ambient[3];
};

#endif
