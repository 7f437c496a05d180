/* file_dialog.h without GTK 3 (the build found none): no dialog, the window asks for typed
 * paths. */
#include "file_dialog.h"

#include <stdio.h>

int ui_file_dialog_start(ui_dialog_kind kind, const char *suggested, char *err, size_t err_size)
{
    (void)kind;
    (void)suggested;
    snprintf(err, err_size, "this build has no file dialogs (GTK 3 was not found)");
    return 1;
}

ui_dialog_state ui_file_dialog_poll(char *path, size_t size)
{
    (void)path;
    (void)size;
    return UI_DIALOG_IDLE;
}

void ui_file_dialog_close(void) {}

const char *ui_file_dialog_extension(ui_dialog_kind kind)
{
    static const char *const ext[UI_DIALOG_KIND_COUNT] = {".json", ".json", ".glb", ".pdf",
                                                          ".png",  "",      ".mp4"};
    return kind < UI_DIALOG_KIND_COUNT ? ext[kind] : "";
}
