/* The project's materials as they are read, with a hash of their names so that 100 000
 * objects referring to 100 000 materials resolve in linear time, not quadratic. */
#include "project_internal.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static uint32_t name_hash(const char *s)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (; *s; s++) {
        h ^= (unsigned char)*s;
        h *= 16777619u;
    }
    return h;
}

static void insert_slot(int *slots, size_t count, const char *name, int index)
{
    size_t mask = count - 1;
    size_t i = name_hash(name) & mask;
    while (slots[i])
        i = (i + 1) & mask;
    slots[i] = index + 1;
}

/* Keeps the table at most half full. */
static int grow_slots(pj_ctx *c, int needed)
{
    if (c->material_slot_count >= (size_t)needed * 2)
        return 1;
    size_t count = c->material_slot_count ? c->material_slot_count : 16;
    while (count < (size_t)needed * 2)
        count *= 2;
    int *slots = pj_calloc(count, sizeof *slots);
    if (!slots)
        return 0;
    for (int k = 0; k < c->p->material_count; k++)
        insert_slot(slots, count, c->p->materials[k].name, k);
    free(c->material_slots);
    c->material_slots = slots;
    c->material_slot_count = count;
    return 1;
}

int pj_lookup_material(const pj_ctx *c, const char *name)
{
    if (!c->material_slots)
        return -1;
    size_t mask = c->material_slot_count - 1;
    size_t i = name_hash(name) & mask;
    while (c->material_slots[i]) {
        int k = c->material_slots[i] - 1;
        if (strcmp(c->p->materials[k].name, name) == 0)
            return k;
        i = (i + 1) & mask;
    }
    return -1;
}

app_result pj_add_material(pj_ctx *c, const app_material *m, int *index)
{
    app_project *p = c->p;
    if (p->material_count >= APP_PROJECT_MAX_ITEMS)
        return pj_fail(c, APP_ERR_SCHEMA, "too many materials (more than %d, inline ones included)",
                       APP_PROJECT_MAX_ITEMS);
    if (p->material_count == c->material_capacity) {
        int cap = c->material_capacity ? c->material_capacity * 2 : 8;
        app_material *grown = pj_realloc(p->materials, (size_t)cap * sizeof *grown);
        if (!grown)
            return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory");
        p->materials = grown;
        c->material_capacity = cap;
    }
    if (!grow_slots(c, p->material_count + 1))
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    int k = p->material_count++;
    p->materials[k] = *m;
    insert_slot(c->material_slots, c->material_slot_count, m->name, k);
    *index = k;
    return APP_OK;
}
