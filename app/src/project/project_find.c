/* Look-ups and release of a project. */
#include "project_internal.h"

#include <stdlib.h>
#include <string.h>

void app_project_free(app_project *p)
{
    if (!p)
        return;
    free(p->materials);
    free(p->objects);
    free(p->lights);
    free(p->cameras);
    free(p->plan.corners);
    free(p->plan.openings);
    free(p->plan.prewalls);
    free(p->plan.niches);
    free(p->tilings);
    memset(p, 0, sizeof *p);
}

const app_camera *app_project_find_camera(const app_project *p, const char *name)
{
    if (!p || !p->cameras || p->camera_count <= 0)
        return NULL;
    if (!name)
        return &p->cameras[0];
    for (int i = 0; i < p->camera_count; i++) {
        if (strncmp(p->cameras[i].name, name, sizeof p->cameras[i].name) == 0)
            return &p->cameras[i];
    }
    return NULL;
}

int app_project_find_material(const app_project *p, const char *name)
{
    if (!p || !name || !p->materials)
        return -1;
    for (int i = 0; i < p->material_count; i++) {
        if (strncmp(p->materials[i].name, name, sizeof p->materials[i].name) == 0)
            return i;
    }
    return -1;
}
