/* The probe policy fields' choices and edit lines (probe_props.h). */
#include "probe_props.h"

#include "app/project/project.h"

#include <stdio.h>
#include <string.h>

const char *const ui_probe_update_labels[6] = {"default",   "every frame", "once",
                                               "on change", "time sliced", "static (map)"};
const char *const ui_probe_correction_labels[5] = {"default", "none", "box", "sphere", "depth"};

/* The edit language's words (docs/editing.md `probe`), as the project file spells them. */
static const char *const update_words[6] = {"default",   "every-frame", "once",
                                            "on-change", "time-sliced", "static"};
static const char *const correction_words[5] = {"default", "none", "box", "sphere", "depth"};
static const char *const resolution_labels[5] = {"auto", "64", "128", "256", "512"};
static const int resolutions[5] = {0, 64, 128, 256, 512};

int ui_probe_resolution_items(int resolution, const char *items[6], char other[16], int *current)
{
    int n = 5;
    *current = -1;
    for (int k = 0; k < 5; k++) {
        items[k] = resolution_labels[k];
        if (resolutions[k] == resolution)
            *current = k;
    }
    if (*current < 0) {
        snprintf(other, 16, "%d", resolution);
        items[n] = other;
        *current = n++;
    }
    return n;
}

int ui_probe_resolution_of(int k, int resolution)
{
    return k >= 0 && k < 5 ? resolutions[k] : resolution;
}

int ui_probe_line(char *out, size_t size, const char *material, ui_probe_field field, int value)
{
    int n;
    switch (field) {
    case UI_PROBE_UPDATE:
        n = snprintf(out, size, "probe \"%s\" update %s", material,
                     value >= 0 && value < 6 ? update_words[value] : "?");
        break;
    case UI_PROBE_EVERY:
        n = snprintf(out, size, "probe \"%s\" every %d", material, value);
        break;
    case UI_PROBE_RESOLUTION:
        if (value)
            n = snprintf(out, size, "probe \"%s\" resolution %d", material, value);
        else
            n = snprintf(out, size, "probe \"%s\" resolution auto", material);
        break;
    default:
        n = snprintf(out, size, "probe \"%s\" correction %s", material,
                     value >= 0 && value < 5 ? correction_words[value] : "?");
        break;
    }
    return n < 0 || (size_t)n >= size;
}

int ui_probe_expect(const struct app_project *p, const char *text, char *why, size_t why_size)
{
    /* The last word is the policy; what is before it, without surrounding quotes, the name. */
    char name[128];
    const char *space = strrchr(text, ' ');
    if (!space || !space[1]) {
        snprintf(why, why_size, "expect-probe needs a material and an update policy");
        return 1;
    }
    const char *start = text + strspn(text, " \t");
    size_t len = (size_t)(space - start);
    while (len && (start[len - 1] == ' ' || start[len - 1] == '\t'))
        len--;
    if (len >= 2 && start[0] == '"' && start[len - 1] == '"') {
        start++;
        len -= 2;
    }
    if (len >= sizeof name) {
        snprintf(why, why_size, "expect-probe: the material name is too long");
        return 1;
    }
    memcpy(name, start, len);
    name[len] = 0;
    const char *word = space + 1;
    int want = -1;
    for (int i = 0; i < 6; i++)
        if (!strcmp(word, update_words[i]))
            want = i;
    if (want < 0) {
        snprintf(why, why_size,
                 "expect-probe: %s is not default, every-frame, once, on-change, time-sliced or "
                 "static",
                 word);
        return 1;
    }
    int m = app_project_find_material(p, name);
    if (m < 0) {
        snprintf(why, why_size, "expect-probe: no material named \"%s\"", name);
        return 1;
    }
    int have = p->materials[m].probe_update;
    if (have != want) {
        snprintf(why, why_size, "the probe of \"%s\" updates %s, expected %s", name,
                 have >= 0 && have < 6 ? update_words[have] : "?", update_words[want]);
        return 1;
    }
    fprintf(stderr, "tessera: the probe of \"%s\" updates %s (every %d, resolution %d)\n", name,
            update_words[have], p->materials[m].probe_every, p->materials[m].probe_resolution);
    return 0;
}
