/* Writing a file so that its old contents are never lost and nothing is left
 * behind: the new contents go to an unnamed file in the same directory
 * (O_TMPFILE; freed by the kernel if the writer dies), which commit syncs,
 * links under a unique temporary name and renames over the target, then
 * syncs the directory. Where the file system has no O_TMPFILE (FAT on an SD
 * card), a unique named temporary (".NAME.XXXXXX") takes its place and
 * abort removes it. Two writers to one path never share a temporary: the
 * last commit wins whole.
 *
 * A symbolic link is written through: its target is replaced (the
 * temporary in the target's directory), the link stays a link. A file
 * replaced keeps its mode and, where allowed, its owner. A block device (a
 * raw A/B slot partition) is written in place, then synced: it cannot be
 * renamed over. Anything else that is not a regular file (a character
 * device, a FIFO, a socket, a directory) is refused: -EINVAL. */
#ifndef ATOMIC_FILE_H
#define ATOMIC_FILE_H

#include <limits.h>

typedef struct atomic_file {
	int fd;                    /* write the contents here */
	int dir_fd;
	int named;                 /* tmp exists in the directory */
	int in_place;              /* a block device: fd is the device itself */
	char path[PATH_MAX];
	char tmp[PATH_MAX];
} atomic_file;

/* Creates the temporary for path. Returns 0 or -errno. */
int atomic_file_open(atomic_file *a, const char *path);

/* fsync, then the temporary becomes path, then the directory's fsync.
 * Returns 0 or -errno (then abort). fd stays open: the caller closes it. */
int atomic_file_commit(atomic_file *a);

/* Removes the temporary (the target is untouched); closes dir_fd. fd
 * stays open for the caller to close. */
void atomic_file_abort(atomic_file *a);

#endif
