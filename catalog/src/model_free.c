/* Freeing a loaded model. */
#include "catalog/model.h"

#include <stdlib.h>
#include <string.h>

void cat_model_free(cat_model *m)
{
    if (!m)
        return;
    for (int i = 0; m->meshes && i < m->mesh_count; i++) {
        free(m->meshes[i].positions);
        free(m->meshes[i].normals);
        free(m->meshes[i].uvs);
        free(m->meshes[i].indices);
    }
    free(m->meshes);
    free(m->materials);
    memset(m, 0, sizeof *m);
}
