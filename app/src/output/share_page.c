/* The share export's files (app/output/share.h): index.html, panorama.js, the viewer script. */
#include "app/output/share.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void html_text(FILE *f, const char *s)
{
    for (; s && *s; s++) {
        switch (*s) {
        case '&':
            fputs("&amp;", f);
            break;
        case '<':
            fputs("&lt;", f);
            break;
        case '>':
            fputs("&gt;", f);
            break;
        case '"':
            fputs("&quot;", f);
            break;
        case '\'':
            fputs("&#39;", f);
            break;
        default:
            fputc(*s, f);
        }
    }
}

/* A file the page refers to must stay inside the shared folder, or the folder is not
 * self-contained (and a crafted name could point anywhere). */
static int safe_relative(const char *file)
{
    if (!file || !*file || file[0] == '/' || strchr(file, '\\') || strchr(file, ':'))
        return 0;
    for (const char *p = file; *p;) {
        const char *slash = strchr(p, '/');
        size_t n = slash ? (size_t)(slash - p) : strlen(p);
        if ((n == 2 && p[0] == '.' && p[1] == '.') || n == 0)
            return 0;
        p += n + (slash ? 1 : 0);
    }
    return 1;
}

static const char *style =
    "body{font-family:sans-serif;margin:0;color:#222;background:#f4f3f0}"
    "header{background:#2d3a40;color:#fff;padding:16px 32px}header h1{margin:0;font-size:26px}"
    "header p{margin:4px 0 0;color:#cfd8dc}main{padding:16px 32px;max-width:1400px}"
    "h2{border-bottom:2px solid #2d3a40;padding-bottom:4px}"
    "#pano{width:100%;height:480px;background:#000;cursor:grab;display:block}"
    ".grid{display:flex;flex-wrap:wrap;gap:16px}.grid figure{margin:0;flex:1 1 420px}"
    ".grid img{width:100%;border:1px solid #bbb;background:#fff}"
    "figcaption{font-size:14px;color:#555}"
    "table{border-collapse:collapse;width:100%;background:#fff;font-size:14px}"
    "th,td{border:1px solid #ccc;padding:4px 8px;text-align:left}th{background:#e3e7e9}"
    "td.n{text-align:right}.totals{margin-top:8px;text-align:right}";

static int is_number(const char *s)
{
    if (!s || !*s)
        return 0;
    for (; *s; s++)
        if (!strchr("0123456789.,- %", *s) && !(s[0] >= 'A' && s[0] <= 'Z' && s[1] == 0))
            return 0;
    return 1;
}

static int write_images(FILE *f, const char *heading, const app_share_image *img, int n, char *err,
                        size_t err_size)
{
    if (n <= 0)
        return 0;
    fprintf(f, "<h2>");
    html_text(f, heading);
    fprintf(f, "</h2>\n<div class=\"grid\">\n");
    for (int i = 0; i < n; i++) {
        if (!safe_relative(img[i].file)) {
            snprintf(err, err_size, "share: image \"%s\" is not a file inside the folder",
                     img[i].file ? img[i].file : "(null)");
            return 1;
        }
        fprintf(f, "<figure><a href=\"");
        html_text(f, img[i].file);
        fprintf(f, "\"><img src=\"");
        html_text(f, img[i].file);
        fprintf(f, "\" alt=\"");
        html_text(f, img[i].title);
        fprintf(f, "\"></a><figcaption>");
        html_text(f, img[i].title);
        fprintf(f, "</figcaption></figure>\n");
    }
    fprintf(f, "</div>\n");
    return 0;
}

static void write_table(FILE *f, const app_share_page *pg)
{
    if (pg->columns <= 0 || !pg->table)
        return;
    fprintf(f, "<h2>Part list</h2>\n<table>\n<tr>");
    for (int c = 0; c < pg->columns; c++) {
        fprintf(f, "<th>");
        html_text(f, pg->table[c]);
        fprintf(f, "</th>");
    }
    fprintf(f, "</tr>\n");
    for (int r = 0; r < pg->rows; r++) {
        fprintf(f, "<tr>");
        for (int c = 0; c < pg->columns; c++) {
            const char *cell = pg->table[(size_t)(r + 1) * pg->columns + c];
            fprintf(f, is_number(cell) ? "<td class=\"n\">" : "<td>");
            html_text(f, cell);
            fprintf(f, "</td>");
        }
        fprintf(f, "</tr>\n");
    }
    fprintf(f, "</table>\n<div class=\"totals\">\n");
    for (int t = 0; t + 1 < pg->total_count * 2; t += 2) {
        fprintf(f, "<div>");
        html_text(f, pg->totals[t]);
        fprintf(f, ": <b>");
        html_text(f, pg->totals[t + 1]);
        fprintf(f, "</b></div>\n");
    }
    fprintf(f, "</div>\n");
}

/* Writes through a temporary file renamed into place, so a reader never sees half a page. */
static FILE *open_temp(const char *dir, const char *name, char *tmp, size_t tmp_size, char *err,
                       size_t err_size)
{
    snprintf(tmp, tmp_size, "%s/.%s.tmp-%ld", dir, name, (long)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f)
        snprintf(err, err_size, "%s/%s: cannot write: %s", dir, name, strerror(errno));
    return f;
}

static app_result close_temp(FILE *f, const char *tmp, const char *dir, const char *name,
                             int failed, char *err, size_t err_size)
{
    char final[4096];
    snprintf(final, sizeof final, "%s/%s", dir, name);
    /* A stream's write error may show only at the flush, the fsync or the close; each keeps
     * its errno ("No space left on device") for the message. */
    errno = EIO;
    /* The flush first: after a failed write it tries again and leaves the reason in errno. */
    int bad = fflush(f) != 0 || ferror(f) || fsync(fileno(f)) != 0;
    int saved = errno;
    if (fclose(f) != 0 && !bad) {
        bad = 1;
        saved = errno;
    }
    if (!failed && !bad && rename(tmp, final) != 0) {
        bad = 1;
        saved = errno;
    }
    if (failed || bad) {
        if (!failed)
            snprintf(err, err_size, "%s: cannot write: %s", final, strerror(saved));
        remove(tmp);
        return failed ? APP_ERR_SCHEMA : APP_ERR_IO;
    }
    return APP_OK;
}

app_result app_share_write_page(const char *dir, const app_share_page *pg, char *err,
                                size_t err_size)
{
    if (pg->pdf_file && !safe_relative(pg->pdf_file)) {
        snprintf(err, err_size, "share: \"%s\" is not a file inside the folder", pg->pdf_file);
        return APP_ERR_SCHEMA;
    }
    char tmp[4096];
    FILE *f = open_temp(dir, "index.html", tmp, sizeof tmp, err, err_size);
    if (!f)
        return APP_ERR_IO;
    fprintf(f, "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
               "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
               "<title>");
    html_text(f, pg->title);
    fprintf(f, "</title>\n<style>%s</style>\n</head>\n<body>\n<header><h1>", style);
    html_text(f, pg->title);
    fprintf(f, "</h1>");
    if (pg->subtitle && *pg->subtitle) {
        fprintf(f, "<p>");
        html_text(f, pg->subtitle);
        fprintf(f, "</p>");
    }
    fprintf(f, "</header>\n<main>\n");
    if (pg->has_panorama)
        fprintf(f, "<h2>Look around</h2>\n<canvas id=\"pano\" width=\"1280\" height=\"480\">"
                   "</canvas>\n<p id=\"pano-status\">Loading the panorama...</p>\n");
    int failed = write_images(f, "Views", pg->renders, pg->render_count, err, err_size) ||
                 write_images(f, "Plan and elevations", pg->plans, pg->plan_count, err, err_size);
    write_table(f, pg);
    if (pg->pdf_file) {
        fprintf(f, "<p><a href=\"");
        html_text(f, pg->pdf_file);
        fprintf(f, "\">The print set as PDF</a></p>\n");
    }
    fprintf(f, "<p style=\"color:#888;font-size:12px\">Made with Tessera.</p>\n</main>\n");
    if (pg->has_panorama)
        fprintf(f, "<script src=\"panorama.js\"></script>\n"
                   "<script src=\"pano-viewer.js\"></script>\n");
    fprintf(f, "</body>\n</html>\n");
    return close_temp(f, tmp, dir, "index.html", failed, err, err_size);
}

app_result app_share_write_panorama(const char *dir, const uint8_t *image, size_t size,
                                    const char *mime, char *err, size_t err_size)
{
    static const char b64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    if (!image || !size || !mime || (strcmp(mime, "image/jpeg") && strcmp(mime, "image/png"))) {
        snprintf(err, err_size, "share: the panorama must be a JPEG or PNG image");
        return APP_ERR_SCHEMA;
    }
    char tmp[4096];
    FILE *f = open_temp(dir, "panorama.js", tmp, sizeof tmp, err, err_size);
    if (!f)
        return APP_ERR_IO;
    fprintf(f, "window.TESSERA_PANORAMA = \"data:%s;base64,", mime);
    for (size_t i = 0; i < size; i += 3) {
        unsigned v = (unsigned)image[i] << 16;
        if (i + 1 < size)
            v |= (unsigned)image[i + 1] << 8;
        if (i + 2 < size)
            v |= image[i + 2];
        fputc(b64[(v >> 18) & 63], f);
        fputc(b64[(v >> 12) & 63], f);
        fputc(i + 1 < size ? b64[(v >> 6) & 63] : '=', f);
        fputc(i + 2 < size ? b64[v & 63] : '=', f);
    }
    fprintf(f, "\";\n");
    return close_temp(f, tmp, dir, "panorama.js", 0, err, err_size);
}

app_result app_share_copy_viewer(const char *dir, const char *assets_dir, char *err,
                                 size_t err_size)
{
    char src[4096];
    snprintf(src, sizeof src, "%s/share/pano-viewer.js", assets_dir);
    FILE *in = fopen(src, "rb");
    if (!in) {
        snprintf(err, err_size, "%s: cannot read the panorama viewer: %s", src, strerror(errno));
        return APP_ERR_IO;
    }
    char tmp[4096];
    FILE *out = open_temp(dir, "pano-viewer.js", tmp, sizeof tmp, err, err_size);
    if (!out) {
        fclose(in);
        return APP_ERR_IO;
    }
    char buf[65536];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        if (fwrite(buf, 1, n, out) != n)
            break;
    int failed = ferror(in);
    fclose(in);
    if (failed)
        snprintf(err, err_size, "%s: read error", src);
    return close_temp(out, tmp, dir, "pano-viewer.js", failed, err, err_size);
}
