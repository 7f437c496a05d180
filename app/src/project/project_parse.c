/* app_project_parse: JSON text -> validated app_project. The order of the sections matters:
 * materials first, so that the room and the objects can refer to them by name. */
#include "project_internal.h"

#include <stdlib.h>
#include <string.h>

static int is_json_space(char ch)
{
    return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r';
}

/* 1-based line and column (in bytes) of offset `at` in text. */
static void line_column(const char *text, size_t at, int *line, int *column)
{
    long l = 1, col = 1;
    for (size_t i = 0; i < at; i++) {
        if (text[i] == '\n') {
            l++;
            col = 1;
        } else {
            col++;
        }
    }
    *line = l > 2000000000 ? 2000000000 : (int)l;
    *column = col > 2000000000 ? 2000000000 : (int)col;
}

/* Whether the text ends inside a string or an unclosed array/object: cJSON then reports its
 * last character, and "unexpected end of file" at the very end says more. */
static int ends_early(const char *text, size_t len)
{
    long depth = 0;
    int in_string = 0, escaped = 0;
    for (size_t i = 0; i < len; i++) {
        char ch = text[i];
        if (in_string) {
            if (escaped)
                escaped = 0;
            else if (ch == '\\')
                escaped = 1;
            else if (ch == '"')
                in_string = 0;
        } else if (ch == '"') {
            in_string = 1;
        } else if (ch == '{' || ch == '[') {
            depth++;
        } else if (ch == '}' || ch == ']') {
            if (--depth < 0)
                return 0;
        }
    }
    return in_string || depth > 0;
}

app_result pj_parse_json(pj_ctx *c, const char *text, size_t len, cJSON **out)
{
    size_t first = 0;
    while (first < len && is_json_space(text[first]))
        first++;
    if (first == len)
        return pj_fail_file(c, APP_ERR_PARSE,
                            "line 1, column 1: malformed JSON: the file is empty");

    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(text, len, &end, 0);
    size_t at = (end && end >= text && end <= text + len) ? (size_t)(end - text) : 0;
    int line, column;
    if (!root) {
        int eof = at + 1 >= len && ends_early(text, len);
        line_column(text, eof ? len : at, &line, &column);
        return pj_fail_file(c, APP_ERR_PARSE, "line %d, column %d: malformed JSON%s", line, column,
                            eof ? " (unexpected end of file)" : "");
    }
    while (at < len && is_json_space(text[at]))
        at++;
    if (at < len) {
        cJSON_Delete(root);
        line_column(text, at, &line, &column);
        return pj_fail_file(c, APP_ERR_PARSE,
                            "line %d, column %d: malformed JSON (unexpected text after the end "
                            "of the document)",
                            line, column);
    }
    *out = root;
    return APP_OK;
}

/* The absolute name of the file for app_project.path; the name as given if it cannot be
 * resolved (app_project_parse with a name of a file that need not exist). */
static void set_project_path(app_project *p, const char *path)
{
    p->path[0] = '\0';
    if (!path)
        return;
    char *real = realpath(path, NULL);
    const char *use = real ? real : path;
    if (strlen(use) < sizeof p->path)
        memcpy(p->path, use, strlen(use) + 1);
    free(real);
}

app_result pj_read_root(pj_ctx *c, cJSON *root, app_project *p)
{
    if (!cJSON_IsObject(root))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an object (a Tessera project), got %s",
                       pj_type_name(root));
    /* A flat's room list; any other "rooms" is an unknown key, ignored as before. */
    if (cJSON_IsArray(cJSON_GetObjectItemCaseSensitive(root, "rooms"))) {
        pj_path_key(c, "rooms");
        return pj_fail(c, APP_ERR_SCHEMA,
                       "a flat of several rooms: this command reads one room (check, "
                       "quantities, render and print read flats; docs/project-format.md "
                       "\"Flats\")");
    }
    /* Text first (valid UTF-8 everywhere), then the sections, then the rules every command
     * relies on (project_validate.c): a room of a flat is held to the same. */
    app_result r = pj_check_text(c, root);
    if (r == APP_OK)
        r = pj_migrate(c, root, &p->file_version);
    if (r != APP_OK)
        return r;
    p->version = APP_PROJECT_VERSION;
    if ((r = pj_get_string(c, root, "name", 0, 1, p->name, sizeof p->name)) != APP_OK ||
        (r = pj_read_materials(c, root)) != APP_OK || (r = pj_read_room(c, root)) != APP_OK ||
        (r = pj_read_plan(c, root)) != APP_OK || (r = pj_read_tilings(c, root)) != APP_OK ||
        (r = pj_read_objects(c, root)) != APP_OK || (r = pj_read_lights(c, root)) != APP_OK ||
        (r = pj_read_cameras(c, root)) != APP_OK || (r = pj_read_render(c, root)) != APP_OK ||
        (r = pj_read_daylight(c, root)) != APP_OK || (r = pj_read_customer(c, root)) != APP_OK)
        return r;
    return pj_validate_project(c, p);
}

app_result app_project_parse(const char *json_text, size_t len,
                             const char *path_for_messages_and_relative_files, app_project *out,
                             char *err, size_t err_size)
{
    return pj_parse_text(json_text, len, path_for_messages_and_relative_files, 1, out, err,
                         err_size);
}

app_result pj_parse_text(const char *json_text, size_t len,
                         const char *path_for_messages_and_relative_files, int check_files,
                         app_project *out, char *err, size_t err_size)
{
    pj_ctx c;
    pj_ctx_init(&c, path_for_messages_and_relative_files, path_for_messages_and_relative_files, err,
                err_size);
    c.check_files = check_files;
    if (!out)
        return pj_fail_file(&c, APP_ERR_IO, "no project to read into (out is NULL)");
    memset(out, 0, sizeof *out);
    if (!json_text && len > 0)
        return pj_fail_file(&c, APP_ERR_IO, "no text to read (json_text is NULL)");
    if (len > (size_t)APP_PROJECT_MAX_FILE_BYTES)
        return pj_fail_file(&c, APP_ERR_IO, "too large (%zu bytes, the limit is 64 MiB)", len);

    cJSON *root = NULL;
    app_result r = pj_parse_json(&c, json_text ? json_text : "", len, &root);
    if (r != APP_OK)
        return r;
    app_project p;
    memset(&p, 0, sizeof p);
    c.p = &p;
    r = pj_read_root(&c, root, &p);
    cJSON_Delete(root);
    pj_ctx_release(&c);
    if (r != APP_OK) {
        app_project_free(&p);
        return r;
    }
    set_project_path(&p, path_for_messages_and_relative_files);
    *out = p;
    return APP_OK;
}
