/* The share export's page (app/output/share.h): texts are escaped, file names cannot leave the
 * folder, the panorama's data: URI is exact base64, the viewer is copied. */
#include "test_util.h"

#include "app/output/share.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int main(void)
{
    char dir[] = "/tmp/tessera-share-XXXXXX", err[1024], path[256];
    if (!mkdtemp(dir))
        return 1;
    const char *table[] = {"Article", "Name", "Total", "A-1", "Basin <b>600</b> & co", "249.00"};
    const char *totals[] = {"Total incl. VAT", "296.31 EUR"};
    app_share_image renders[] = {{"renders/door.jpg", "Door \"view\""}};
    app_share_image bad[] = {{"../secret.png", "x"}};
    app_share_page pg = {.title = "Bad <script>alert(1)</script>",
                         .subtitle = "Customer O'Neil",
                         .renders = renders,
                         .render_count = 1,
                         .pdf_file = "print.pdf",
                         .has_panorama = 1,
                         .table = table,
                         .columns = 3,
                         .rows = 1,
                         .totals = totals,
                         .total_count = 1};
    CHECK(app_share_write_page(dir, &pg, err, sizeof err) == APP_OK);
    snprintf(path, sizeof path, "%s/index.html", dir);
    char *html = tu_read_file(path, NULL);
    CHECK(html != NULL);
    if (html) {
        CHECK(!strstr(html, "<script>alert"));
        CHECK(strstr(html, "Bad &lt;script&gt;alert(1)&lt;/script&gt;") != NULL);
        CHECK(strstr(html, "Customer O&#39;Neil") != NULL);
        CHECK(strstr(html, "Basin &lt;b&gt;600&lt;/b&gt; &amp; co") != NULL);
        CHECK(strstr(html, "<td class=\"n\">249.00</td>") != NULL);
        CHECK(strstr(html, "src=\"renders/door.jpg\"") != NULL);
        CHECK(strstr(html, "<script src=\"pano-viewer.js\"></script>") != NULL);
        CHECK(strstr(html, "296.31 EUR") != NULL);
        free(html);
    }
    /* A file outside the folder is refused and the good page stays. */
    pg.renders = bad;
    CHECK(app_share_write_page(dir, &pg, err, sizeof err) != APP_OK &&
          strstr(err, "../secret.png"));
    pg.renders = renders;
    pg.pdf_file = "/etc/passwd";
    CHECK(app_share_write_page(dir, &pg, err, sizeof err) != APP_OK);
    html = tu_read_file(path, NULL);
    CHECK(html && strstr(html, "renders/door.jpg"));
    free(html);

    /* base64 with both paddings: "Man" -> TWFu, "Ma" -> TWE=, "M" -> TQ== */
    const uint8_t bytes[] = {'M', 'a', 'n', 'M', 'a'};
    CHECK(app_share_write_panorama(dir, bytes, 5, "image/png", err, sizeof err) == APP_OK);
    snprintf(path, sizeof path, "%s/panorama.js", dir);
    char *js = tu_read_file(path, NULL);
    CHECK(js && !strcmp(js, "window.TESSERA_PANORAMA = \"data:image/png;base64,TWFuTWE=\";\n"));
    free(js);
    CHECK(app_share_write_panorama(dir, bytes, 1, "image/jpeg", err, sizeof err) == APP_OK);
    js = tu_read_file(path, NULL);
    CHECK(js && strstr(js, "base64,TQ==\""));
    free(js);
    CHECK(app_share_write_panorama(dir, bytes, 3, "text/html", err, sizeof err) != APP_OK);

    CHECK(app_share_copy_viewer(dir, TESSERA_ASSETS_DIR, err, sizeof err) == APP_OK);
    snprintf(path, sizeof path, "%s/pano-viewer.js", dir);
    struct stat st;
    CHECK(stat(path, &st) == 0 && st.st_size > 1000);
    CHECK(app_share_copy_viewer(dir, "/nonexistent", err, sizeof err) == APP_ERR_IO &&
          strstr(err, "/nonexistent/share/pano-viewer.js"));
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0)
        return 1;
    return check_report("share_page");
}
