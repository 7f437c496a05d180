/* Native file dialogs for the planner window: GTK 3's file chooser (file_dialog_gtk.c), shown
 * beside the window and pumped from the frame loop, so the window keeps drawing while the
 * dialog is open. Without a display GTK can open (or with TESSERA_FILE_DIALOG=none) there is no
 * dialog: ui_file_dialog_start fails and the caller asks for a typed path instead. */
#ifndef UI_FILE_DIALOG_H
#define UI_FILE_DIALOG_H

#include <stddef.h>

typedef enum ui_dialog_kind {
    UI_DIALOG_OPEN_PROJECT, /* *.json */
    UI_DIALOG_SAVE_PROJECT, /* *.json, asks before replacing */
    UI_DIALOG_EXPORT_GLB,   /* *.glb */
    UI_DIALOG_PRINT_PDF,    /* *.pdf */
    UI_DIALOG_SAVE_IMAGE,   /* *.png, *.jpg, *.tif */
    UI_DIALOG_SAVE_FOLDER,  /* a new folder's name (the share folder) */
    UI_DIALOG_SAVE_VIDEO,   /* *.mp4 */
    UI_DIALOG_KIND_COUNT
} ui_dialog_kind;

typedef enum ui_dialog_state {
    UI_DIALOG_IDLE = 0, /* no dialog */
    UI_DIALOG_RUNNING,
    UI_DIALOG_ACCEPTED, /* path holds the chosen file */
    UI_DIALOG_CANCELLED
} ui_dialog_state;

/* Opens a dialog of that kind (one at a time), starting at suggested (a path, a folder or
 * NULL). 0 when it shows; 1 when no dialog can be shown (why in err). */
int ui_file_dialog_start(ui_dialog_kind kind, const char *suggested, char *err, size_t err_size);
/* Handles the dialog's events (call once a frame); on ACCEPTED or CANCELLED the dialog is gone
 * and the next poll says IDLE. path gets the chosen file on ACCEPTED; the name gets the
 * kind's extension when the user typed none. */
ui_dialog_state ui_file_dialog_poll(char *path, size_t size);
/* Closes a dialog still open (the window is closing). */
void ui_file_dialog_close(void);
/* The file name filter's extension of a kind (".json", ...; "" for a folder). */
const char *ui_file_dialog_extension(ui_dialog_kind kind);

#endif
