/* The user's state folder for the planner ($XDG_STATE_HOME/tessera, else
 * ~/.local/state/tessera; XDG Base Directory Specification 0.8): the recent-files list and the
 * autosaves live there, never beside the user's own files. Pure C, no window needed. */
#ifndef UI_USER_STATE_H
#define UI_USER_STATE_H

#include <stddef.h>

#define UI_RECENT_MAX 10

/* The folder (made with its parents when missing) into out; 0 ok, else why in out. */
int ui_state_dir(char *out, size_t size);

/* Writes data to path atomically: a temporary file in the same folder, fsync, rename. A
 * failure leaves the old file as it was. 0 ok, else errno's message in err. */
int ui_write_atomic(const char *path, const char *data, size_t len, char *err, size_t err_size);

/* The recent-files list, newest first, one absolute path a line. */
typedef struct ui_recent {
    char paths[UI_RECENT_MAX][1024];
    int count;
} ui_recent;

/* Reads the list from file (a missing file is an empty list); lines that are empty or too long
 * are skipped. 0 ok, 1 when the file exists but cannot be read. */
int ui_recent_load(ui_recent *r, const char *file);
/* Puts path first (once; the oldest falls off past UI_RECENT_MAX). */
void ui_recent_add(ui_recent *r, const char *path);
/* Writes the list atomically. 0 ok, else why in err. */
int ui_recent_save(const ui_recent *r, const char *file, char *err, size_t err_size);
/* The list file in the state folder: STATE/recent-files. 0 ok. */
int ui_recent_file(char *out, size_t size);

/* A file kept for the project at path (untitled: path empty) in a folder of the state folder:
 * STATE/FOLDER/BASENAME-HASH.json (untitled.json), HASH from the absolute path (FNV-1a, 64
 * bits) so two projects of one name do not share it. FOLDER "autosave": the autosave;
 * "previous": the version a save replaced. 0 ok, else why in out. */
int ui_project_state_file(const char *folder, const char *project_path, char *out, size_t size);

#endif
