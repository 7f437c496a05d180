/* GTK 3's GtkFileChooserDialog behind file_dialog.h. GTK starts on the first dialog (a window
 * that never opens one never loads it) and never sets the process's locale: app's number
 * parsing expects the C locale. The dialog is not run modally (gtk_dialog_run would stop the
 * planner's frames); its events are handled by ui_file_dialog_poll, once a frame. */
#include "file_dialog.h"

#include <gtk/gtk.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static struct {
    int tried, usable;
    GtkWidget *dialog;
    ui_dialog_kind kind;
    int response; /* GTK_RESPONSE_*, 0 while open */
} dlg;

static const struct {
    const char *title, *accept, *filter_name, *patterns[4];
    GtkFileChooserAction action;
} kinds[UI_DIALOG_KIND_COUNT] = {
    [UI_DIALOG_OPEN_PROJECT] = {"Open project",
                                "_Open",
                                "Tessera projects (*.json)",
                                {"*.json"},
                                GTK_FILE_CHOOSER_ACTION_OPEN},
    [UI_DIALOG_SAVE_PROJECT] = {"Save project as",
                                "_Save",
                                "Tessera projects (*.json)",
                                {"*.json"},
                                GTK_FILE_CHOOSER_ACTION_SAVE},
    [UI_DIALOG_EXPORT_GLB] = {"Export as GLB",
                              "_Export",
                              "glTF binary (*.glb)",
                              {"*.glb"},
                              GTK_FILE_CHOOSER_ACTION_SAVE},
    [UI_DIALOG_PRINT_PDF] = {"Print to PDF",
                             "_Print",
                             "PDF documents (*.pdf)",
                             {"*.pdf"},
                             GTK_FILE_CHOOSER_ACTION_SAVE},
    [UI_DIALOG_SAVE_IMAGE] = {"Render at print quality",
                              "_Render",
                              "Images (*.png, *.jpg, *.tif)",
                              {"*.png", "*.jpg", "*.jpeg", "*.tif"},
                              GTK_FILE_CHOOSER_ACTION_SAVE},
    [UI_DIALOG_SAVE_FOLDER] =
        {"Share folder", "_Create", NULL, {NULL}, GTK_FILE_CHOOSER_ACTION_CREATE_FOLDER},
    [UI_DIALOG_SAVE_VIDEO] =
        {"Save the video", "_Save", "MP4 videos (*.mp4)", {"*.mp4"}, GTK_FILE_CHOOSER_ACTION_SAVE},
};

const char *ui_file_dialog_extension(ui_dialog_kind kind)
{
    static const char *const ext[UI_DIALOG_KIND_COUNT] = {".json", ".json", ".glb", ".pdf",
                                                          ".png",  "",      ".mp4"};
    return kind < UI_DIALOG_KIND_COUNT ? ext[kind] : "";
}

static void on_response(GtkDialog *d, gint response, gpointer user)
{
    (void)d;
    (void)user;
    dlg.response = response == 0 ? GTK_RESPONSE_CANCEL : response;
}

static int gtk_usable(char *err, size_t err_size)
{
    const char *off = getenv("TESSERA_FILE_DIALOG");
    if (off && !strcmp(off, "none")) {
        snprintf(err, err_size, "file dialogs are off (TESSERA_FILE_DIALOG=none)");
        return 0;
    }
    if (!dlg.tried) {
        dlg.tried = 1;
        gtk_disable_setlocale();
        dlg.usable = gtk_init_check(NULL, NULL);
    }
    if (!dlg.usable)
        snprintf(err, err_size, "GTK cannot open the display: no file dialog");
    return dlg.usable;
}

int ui_file_dialog_start(ui_dialog_kind kind, const char *suggested, char *err, size_t err_size)
{
    if (kind >= UI_DIALOG_KIND_COUNT || !gtk_usable(err, err_size))
        return 1;
    if (dlg.dialog) {
        snprintf(err, err_size, "a file dialog is already open");
        return 1;
    }
    GtkWidget *d = gtk_file_chooser_dialog_new(kinds[kind].title, NULL, kinds[kind].action,
                                               "_Cancel", GTK_RESPONSE_CANCEL, kinds[kind].accept,
                                               GTK_RESPONSE_ACCEPT, NULL);
    GtkFileChooser *fc = GTK_FILE_CHOOSER(d);
    gtk_dialog_set_default_response(GTK_DIALOG(d), GTK_RESPONSE_ACCEPT);
    if (kinds[kind].filter_name) {
        GtkFileFilter *f = gtk_file_filter_new();
        gtk_file_filter_set_name(f, kinds[kind].filter_name);
        for (int i = 0; i < 4 && kinds[kind].patterns[i]; i++)
            gtk_file_filter_add_pattern(f, kinds[kind].patterns[i]);
        gtk_file_chooser_add_filter(fc, f);
        GtkFileFilter *all = gtk_file_filter_new();
        gtk_file_filter_set_name(all, "All files");
        gtk_file_filter_add_pattern(all, "*");
        gtk_file_chooser_add_filter(fc, all);
    }
    int saving = kinds[kind].action != GTK_FILE_CHOOSER_ACTION_OPEN;
    if (saving)
        gtk_file_chooser_set_do_overwrite_confirmation(fc, TRUE);
    if (suggested && *suggested) {
        char *dir = g_path_get_dirname(suggested), *base = g_path_get_basename(suggested);
        if (g_file_test(suggested, G_FILE_TEST_IS_DIR))
            gtk_file_chooser_set_current_folder(fc, suggested);
        else {
            if (g_file_test(dir, G_FILE_TEST_IS_DIR))
                gtk_file_chooser_set_current_folder(fc, dir);
            if (saving)
                gtk_file_chooser_set_current_name(fc, base);
        }
        g_free(dir);
        g_free(base);
    }
    g_signal_connect(d, "response", G_CALLBACK(on_response), NULL);
    /* GTK cannot make it transient for the GLFW window: centred on the screen and above. */
    gtk_window_set_default_size(GTK_WINDOW(d), 760, 520);
    gtk_window_set_position(GTK_WINDOW(d), GTK_WIN_POS_CENTER);
    gtk_window_set_keep_above(GTK_WINDOW(d), TRUE);
    gtk_widget_show_all(d);
    gtk_window_present(GTK_WINDOW(d));
    dlg.dialog = d;
    dlg.kind = kind;
    dlg.response = 0;
    return 0;
}

static void pump(void)
{
    for (int i = 0; i < 100 && gtk_events_pending(); i++)
        gtk_main_iteration_do(FALSE);
}

void ui_file_dialog_close(void)
{
    if (!dlg.dialog)
        return;
    gtk_widget_destroy(dlg.dialog);
    dlg.dialog = NULL;
    pump(); /* let the window go away now */
}

ui_dialog_state ui_file_dialog_poll(char *path, size_t size)
{
    if (!dlg.dialog)
        return UI_DIALOG_IDLE;
    pump();
    if (!dlg.response)
        return UI_DIALOG_RUNNING;
    int accepted = dlg.response == GTK_RESPONSE_ACCEPT;
    char *name = accepted ? gtk_file_chooser_get_filename(GTK_FILE_CHOOSER(dlg.dialog)) : NULL;
    ui_dialog_state s = UI_DIALOG_CANCELLED;
    if (name && *name) {
        const char *ext = ui_file_dialog_extension(dlg.kind), *base = strrchr(name, '/');
        int typed_ext = strchr(base ? base + 1 : name, '.') != NULL;
        snprintf(path, size, "%s%s", name, *ext && !typed_ext ? ext : "");
        s = UI_DIALOG_ACCEPTED;
    }
    g_free(name);
    ui_file_dialog_close();
    return s;
}
