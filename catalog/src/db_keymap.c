/* A small open-addressing hash table from strings to the first line they were seen on, used
 * by the import to find rows of the same product and repeated variants. */
#include "db_internal.h"

#include <stdlib.h>
#include <string.h>

uint64_t catdb_hash64(uint64_t h, const void *data, size_t size)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < size; i++) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

uint32_t catdb_hash32(const void *data, size_t size)
{
    uint64_t h = catdb_hash64(CATDB_HASH64_INIT, data, size);
    return (uint32_t)(h ^ h >> 32);
}

static int grow(catdb_keymap *m)
{
    size_t cap = m->cap ? m->cap * 2 : 256;
    catdb_keymap_entry *slots = calloc(cap, sizeof *slots);
    if (!slots)
        return 0;
    for (size_t i = 0; i < m->cap; i++) {
        if (!m->slots[i].key)
            continue;
        size_t j = catdb_hash32(m->slots[i].key, strlen(m->slots[i].key)) & (cap - 1);
        while (slots[j].key)
            j = (j + 1) & (cap - 1);
        slots[j] = m->slots[i];
    }
    free(m->slots);
    m->slots = slots;
    m->cap = cap;
    return 1;
}

static size_t probe(const catdb_keymap *m, const char *key, size_t len)
{
    size_t j = catdb_hash32(key, len) & (m->cap - 1);
    while (m->slots[j].key && strcmp(m->slots[j].key, key))
        j = (j + 1) & (m->cap - 1);
    return j;
}

catdb_keymap_entry *catdb_keymap_get(catdb_keymap *m, const char *key, int create, int aux_count,
                                     int *created)
{
    if (created)
        *created = 0;
    size_t len = strlen(key);
    if (m->cap) {
        size_t j = probe(m, key, len);
        if (m->slots[j].key)
            return &m->slots[j];
    }
    if (!create)
        return NULL;
    if ((m->count + 1) * 2 > m->cap && !grow(m))
        return NULL;
    size_t j = probe(m, key, len);
    char *copy = malloc(len + 1);
    uint32_t *aux = aux_count > 0 ? calloc((size_t)aux_count, sizeof *aux) : NULL;
    if (!copy || (aux_count > 0 && !aux)) {
        free(copy);
        free(aux);
        return NULL;
    }
    memcpy(copy, key, len + 1);
    catdb_keymap_entry *e = &m->slots[j];
    e->key = copy;
    e->aux = aux;
    e->line = 0;
    e->flags = 0;
    m->count++;
    if (created)
        *created = 1;
    return e;
}

void catdb_keymap_free(catdb_keymap *m)
{
    for (size_t i = 0; i < m->cap; i++) {
        free(m->slots[i].key);
        free(m->slots[i].aux);
    }
    free(m->slots);
    m->slots = NULL;
    m->cap = m->count = 0;
}
