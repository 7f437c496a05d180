/* Where a save to a path really goes. Saving through a symbolic link must update the file the
 * link names and keep the link a link: the temporary file is made next to the target and
 * renamed over it, never over the link itself. */
#ifndef RENDER_WRITE_TARGET_H
#define RENDER_WRITE_TARGET_H

#ifdef __cplusplus
extern "C" {
#endif

/* The file a write to path should replace (malloc'd; NULL only when out of memory): path
 * itself when it is not a symbolic link, else the link's target with every link resolved
 * (realpath), or for a link whose target does not exist yet, that target's name (followed up
 * to 40 links, the limit of Linux's path resolution). */
char *rd_write_target(const char *path);

/* Syncs the folder that holds path (".": none in the path), so that a rename into it is
 * durable: a new or renamed folder entry survives a crash only once its folder is synced. */
void rd_sync_parent_folder(const char *path);

#ifdef __cplusplus
}
#endif

#endif
