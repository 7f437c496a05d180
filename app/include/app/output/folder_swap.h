/* A folder replaced whole or not at all: its new content is written into a temporary folder
 * beside it (TARGET.tmp-XXXXXX, through symbolic links to the folder they name:
 * render/write_target.h), which then takes the target's place in one step. An existing folder
 * is exchanged with the new one atomically (renameat2 RENAME_EXCHANGE, Linux 3.15) and removed
 * afterwards; a missing one is made by a plain rename. A reader of the target sees the old
 * folder or the new one, never a mix. On any failure the temporary folder is removed and the
 * old folder keeps every byte. */
#ifndef APP_OUTPUT_FOLDER_SWAP_H
#define APP_OUTPUT_FOLDER_SWAP_H

#include "app/project/project.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_folder_swap {
    char *target; /* the folder replaced at the end (malloc'd) */
    char *temp;   /* the folder written into (malloc'd) */
} app_folder_swap;

/* Makes the temporary folder; write into s->temp. The target may be missing or a folder (a
 * file there is an error). On failure *s owns nothing and err names the path and the reason. */
app_result app_folder_swap_begin(app_folder_swap *s, const char *path, char *err, size_t err_size);

/* Puts the temporary folder in the target's place and removes the old folder. On failure
 * removes the temporary folder, leaves the target as it was, and writes "TARGET: cannot
 * replace the folder: REASON" into err. Frees what *s owns either way. */
app_result app_folder_swap_commit(app_folder_swap *s, char *err, size_t err_size);

/* Removes the temporary folder and frees what *s owns (after another failure). */
void app_folder_swap_discard(app_folder_swap *s);

/* Removes a folder and everything in it, never following a symbolic link out of it.
 * Returns 0, or -1 with errno set by the first removal that failed. */
int app_remove_tree(const char *path);

#ifdef __cplusplus
}
#endif
#endif
