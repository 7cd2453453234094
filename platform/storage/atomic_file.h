/* Writing a file so that its old contents are never lost and nothing is left
 * behind: the new contents go to an unnamed file in the same directory
 * (O_TMPFILE; freed by the kernel if the writer dies), which commit syncs,
 * links under a unique temporary name and renames over the target, then
 * syncs the directory. Where the file system has no O_TMPFILE (FAT on an SD
 * card), a unique named temporary (".NAME.XXXXXX") takes its place and
 * abort removes it. Two writers to one path never share a temporary: the
 * last commit wins whole. */
#ifndef ATOMIC_FILE_H
#define ATOMIC_FILE_H

#include <limits.h>

typedef struct atomic_file {
	int fd;                    /* write the contents here */
	int dir_fd;
	int named;                 /* tmp exists in the directory */
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
