#define _GNU_SOURCE /* O_TMPFILE */
#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* The directory of path and its last component. */
static void split(const char *path, char *dir, size_t size, const char **name)
{
	const char *slash = strrchr(path, '/');
	*name = slash ? slash + 1 : path;
	if (!slash)
		snprintf(dir, size, ".");
	else if (slash == path)
		snprintf(dir, size, "/");
	else
		snprintf(dir, size, "%.*s", (int)(slash - path), path);
}

static int fail(atomic_file *a)
{
	int e = errno;
	atomic_file_abort(a);
	if (a->fd >= 0)
		close(a->fd);
	a->fd = -1;
	return -e;
}

int atomic_file_open(atomic_file *a, const char *path)
{
	char dir[PATH_MAX];
	const char *name;
	memset(a, 0, sizeof *a);
	a->fd = a->dir_fd = -1;
	if (strlen(path) + 16 >= sizeof a->path)
		return -ENAMETOOLONG;
	snprintf(a->path, sizeof a->path, "%s", path);
	split(path, dir, sizeof dir, &name);
	if (!*name)
		return -EISDIR;
	a->dir_fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (a->dir_fd < 0)
		return -errno;
	if (snprintf(a->tmp, sizeof a->tmp, "%s%s.%s.XXXXXX", dir, strcmp(dir, "/") ? "/" : "", name) >=
	    (int)sizeof a->tmp) {
		atomic_file_abort(a);
		return -ENAMETOOLONG;
	}
	a->fd = open(dir, O_TMPFILE | O_RDWR | O_CLOEXEC, 0644);
	if (a->fd >= 0)
		return 0;
	/* no O_TMPFILE here: a named temporary, removed on abort */
	a->fd = mkstemp(a->tmp);
	if (a->fd < 0 || fchmod(a->fd, 0644) != 0)
		return fail(a);
	a->named = 1;
	return 0;
}

/* Links the unnamed file under a fresh temporary name. */
static int link_tmpfile(atomic_file *a)
{
	char proc[64], base[PATH_MAX];
	snprintf(proc, sizeof proc, "/proc/self/fd/%d", a->fd);
	snprintf(base, sizeof base, "%s", a->tmp);
	size_t stem = strlen(base) - 6; /* the XXXXXX */
	unsigned long seed = (unsigned long)getpid() ^ (unsigned long)time(NULL) ^ (unsigned long)clock();
	for (int attempt = 0; attempt < 100; attempt++) {
		seed = seed * 6364136223846793005ul + 1442695040888963407ul;
		snprintf(a->tmp + stem, sizeof a->tmp - stem, "%06lx", (seed >> 24) & 0xfffffful);
		if (linkat(AT_FDCWD, proc, AT_FDCWD, a->tmp, AT_SYMLINK_FOLLOW) == 0) {
			a->named = 1;
			return 0;
		}
		if (errno != EEXIST)
			return -1;
	}
	return -1;
}

int atomic_file_commit(atomic_file *a)
{
	if (fsync(a->fd) != 0 || (!a->named && link_tmpfile(a) != 0) || rename(a->tmp, a->path) != 0)
		return -errno;
	a->named = 0;
	int rc = fsync(a->dir_fd) == 0 ? 0 : -errno;
	close(a->dir_fd);
	a->dir_fd = -1;
	return rc;
}

void atomic_file_abort(atomic_file *a)
{
	if (a->named)
		unlink(a->tmp);
	a->named = 0;
	if (a->dir_fd >= 0)
		close(a->dir_fd);
	a->dir_fd = -1;
}
