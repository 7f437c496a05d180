/* The quotation's header: company file, customer, number, date and validity (app/output/quote.h).
 */
#define _DEFAULT_SOURCE /* timegm, gmtime_r */
#include "app/output/quote.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static app_result fail(char *err, size_t err_size, app_result r, const char *fmt, ...)
{
    if (err && err_size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, err_size, fmt, ap);
        va_end(ap);
    }
    return r;
}

int app_company_default_path(char *buf, size_t size)
{
    const char *xdg = getenv("XDG_CONFIG_HOME"), *home = getenv("HOME");
    int n;
    if (xdg && *xdg)
        n = snprintf(buf, size, "%s/tessera/company.json", xdg);
    else if (home && *home)
        n = snprintf(buf, size, "%s/.config/tessera/company.json", home);
    else
        return 0;
    return n > 0 && (size_t)n < size;
}

/* A company file is a few hundred bytes; a megabyte is surely not one. */
#define COMPANY_MAX_BYTES (1 << 20)

static char *read_text(const char *path, char *err, size_t err_size, app_result *r)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        *r = fail(err, err_size, APP_ERR_IO, "%s: %s", path, strerror(errno));
        return NULL;
    }
    char *buf = malloc(COMPANY_MAX_BYTES + 1);
    size_t n = buf ? fread(buf, 1, COMPANY_MAX_BYTES + 1, f) : 0;
    int bad = ferror(f);
    fclose(f);
    if (!buf) {
        *r = fail(err, err_size, APP_ERR_OUT_OF_MEMORY, "%s: out of memory", path);
        return NULL;
    }
    if (bad || n > COMPANY_MAX_BYTES) {
        free(buf);
        *r = fail(err, err_size, bad ? APP_ERR_IO : APP_ERR_SCHEMA,
                  bad ? "%s: read error" : "%s: larger than 1 MB, not a company file", path);
        return NULL;
    }
    buf[n] = '\0';
    *r = APP_OK;
    return buf;
}

static app_result get_string(const char *path, const cJSON *root, const char *key, char *out,
                             size_t size, char *err, size_t err_size)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(root, key);
    if (!v)
        return APP_OK;
    if (!cJSON_IsString(v))
        return fail(err, err_size, APP_ERR_SCHEMA, "%s: \"%s\" must be a string", path, key);
    if (strlen(v->valuestring) >= size)
        return fail(err, err_size, APP_ERR_SCHEMA, "%s: \"%s\" is longer than %zu bytes", path, key,
                    size - 1);
    snprintf(out, size, "%s", v->valuestring);
    return APP_OK;
}

static void add_line(app_company *c, const char *prefix, const char *text)
{
    if (text[0] && c->line_count < APP_COMPANY_LINES)
        snprintf(c->lines[c->line_count++], sizeof c->lines[0], "%s%s", prefix, text);
}

app_result app_company_read(const char *path, app_company *out, char *err, size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!path || !out)
        return fail(err, err_size, APP_ERR_SCHEMA, "no company file");
    app_result r;
    char *text = read_text(path, err, err_size, &r);
    if (!text)
        return r;
    cJSON *root = cJSON_Parse(text);
    free(text);
    if (!cJSON_IsObject(root)) {
        cJSON_Delete(root);
        return fail(err, err_size, APP_ERR_SCHEMA,
                    "%s: not a JSON object (expected {\"name\": ..., \"address\": [...]})", path);
    }
    char phone[128] = "", email[128] = "", web[128] = "", vat[128] = "", bank[128] = "",
         logo[1024] = "";
    if ((r = get_string(path, root, "name", out->name, sizeof out->name, err, err_size)) ||
        (r = get_string(path, root, "phone", phone, sizeof phone, err, err_size)) ||
        (r = get_string(path, root, "email", email, sizeof email, err, err_size)) ||
        (r = get_string(path, root, "web", web, sizeof web, err, err_size)) ||
        (r = get_string(path, root, "vat_id", vat, sizeof vat, err, err_size)) ||
        (r = get_string(path, root, "bank", bank, sizeof bank, err, err_size)) ||
        (r = get_string(path, root, "logo", logo, sizeof logo, err, err_size)))
        goto done;
    if (!out->name[0]) {
        r = fail(err, err_size, APP_ERR_SCHEMA, "%s: \"name\" (the company's name) is missing",
                 path);
        goto done;
    }
    const cJSON *addr = cJSON_GetObjectItemCaseSensitive(root, "address");
    if (addr && !cJSON_IsArray(addr)) {
        r = fail(err, err_size, APP_ERR_SCHEMA, "%s: \"address\" must be a list of lines", path);
        goto done;
    }
    const cJSON *line;
    cJSON_ArrayForEach(line, addr)
    {
        if (!cJSON_IsString(line) || strlen(line->valuestring) >= sizeof out->lines[0]) {
            r = fail(err, err_size, APP_ERR_SCHEMA,
                     "%s: \"address\" lines must be strings of at most %zu bytes", path,
                     sizeof out->lines[0] - 1);
            goto done;
        }
        add_line(out, "", line->valuestring);
    }
    add_line(out, "Phone ", phone);
    add_line(out, "", email);
    add_line(out, "", web);
    add_line(out, "VAT ID ", vat);
    add_line(out, "", bank);
    if (logo[0]) {
        /* Relative to the company file's folder. */
        const char *slash = strrchr(path, '/');
        if (logo[0] == '/' || !slash)
            snprintf(out->logo, sizeof out->logo, "%s", logo);
        else
            snprintf(out->logo, sizeof out->logo, "%.*s/%s", (int)(slash - path), path, logo);
        struct stat st;
        if (stat(out->logo, &st) != 0) {
            r = fail(err, err_size, APP_ERR_IO, "%s: logo %s: %s", path, out->logo,
                     strerror(errno));
            goto done;
        }
    }
    r = APP_OK;
done:
    cJSON_Delete(root);
    if (r != APP_OK)
        memset(out, 0, sizeof *out);
    return r;
}

static int parse_date(const char *s, struct tm *tm)
{
    int y, m, d, n = 0;
    if (sscanf(s, "%4d-%2d-%2d%n", &y, &m, &d, &n) != 3 || s[n] || y < 1900 || y > 9999 || m < 1 ||
        m > 12 || d < 1 || d > 31)
        return 0;
    memset(tm, 0, sizeof *tm);
    tm->tm_year = y - 1900;
    tm->tm_mon = m - 1;
    tm->tm_mday = d;
    tm->tm_hour = 12;
    return 1;
}

app_result app_quote_make(const app_project *p, const char *company_path, const char *date,
                          app_quote *out, char *err, size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!p || !out)
        return fail(err, err_size, APP_ERR_SCHEMA, "quote: no project");
    char path[4096];
    if (company_path) {
        app_result r = app_company_read(company_path, &out->company, err, err_size);
        if (r != APP_OK)
            return r;
        out->has_company = 1;
    } else if (app_company_default_path(path, sizeof path) && access(path, F_OK) == 0) {
        app_result r = app_company_read(path, &out->company, err, err_size);
        if (r != APP_OK)
            return r;
        out->has_company = 1;
    }
    out->customer = p->customer;
    struct tm tm;
    if (date) {
        if (!parse_date(date, &tm))
            return fail(err, err_size, APP_ERR_SCHEMA,
                        "quote: the date must be YYYY-MM-DD, got \"%s\"", date);
    } else {
        time_t now = time(NULL);
        gmtime_r(&now, &tm);
        tm.tm_hour = 12;
    }
    time_t day = timegm(&tm);
    gmtime_r(&day, &tm);
    strftime(out->date, sizeof out->date, "%Y-%m-%d", &tm);
    out->valid_days = p->customer.valid_days > 0 ? p->customer.valid_days : 30;
    time_t until = day + (time_t)out->valid_days * 86400;
    struct tm tu;
    gmtime_r(&until, &tu);
    strftime(out->valid_until, sizeof out->valid_until, "%Y-%m-%d", &tu);
    if (p->customer.quote_number[0])
        snprintf(out->number, sizeof out->number, "%s", p->customer.quote_number);
    else {
        /* FNV-1a of the project's name: the same project gets the same number on one day. */
        unsigned h = 2166136261u;
        for (const char *c = p->name; *c; c++)
            h = (h ^ (unsigned char)*c) * 16777619u;
        char digits[16];
        strftime(digits, sizeof digits, "%Y%m%d", &tm);
        snprintf(out->number, sizeof out->number, "Q-%s-%04X", digits, (h ^ (h >> 16)) & 0xFFFF);
    }
    return APP_OK;
}
