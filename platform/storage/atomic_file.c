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

/* path with its symbolic links followed, into out: the file a write
 * through the link replaces (a dangling link: the path it names). */
static int follow_links(const char *path, char *out, size_t size)
{
	char cur[PATH_MAX], link[PATH_MAX], dir[PATH_MAX];
	const char *name;
	struct stat st;
	snprintf(cur, sizeof cur, "%s", path);
	for (int depth = 0; depth < 16; depth++) {
		if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
			return snprintf(out, size, "%s", cur) < (int)size ? 0 : -ENAMETOOLONG;
		ssize_t n = readlink(cur, link, sizeof link - 1);
		if (n < 0)
			return -errno;
		link[n] = '\0';
		split(cur, dir, sizeof dir, &name);
		if (link[0] == '/' || !strcmp(dir, "."))
			snprintf(cur, sizeof cur, "%s", link);
		else if (snprintf(cur, sizeof cur, "%s/%s", dir, link) >= (int)sizeof cur)
			return -ENAMETOOLONG;
	}
	return -ELOOP;
}

/* A block device: written in place (synced by commit). */
static int open_in_place(atomic_file *a)
{
	a->fd = open(a->path, O_RDWR | O_CLOEXEC);
	if (a->fd < 0)
		return -errno;
	a->in_place = 1;
	return 0;
}

/* The replaced file's mode and owner on the temporary (an owner this
 * process may not give is left as it is). */
static int keep_mode(atomic_file *a, const struct stat *st)
{
	if (fchmod(a->fd, st->st_mode & 07777) != 0)
		return -1;
	if (fchown(a->fd, st->st_uid, st->st_gid) != 0 && errno != EPERM)
		return -1;
	return 0;
}

int atomic_file_open(atomic_file *a, const char *path)
{
	char dir[PATH_MAX];
	const char *name;
	struct stat st;
	memset(a, 0, sizeof *a);
	a->fd = a->dir_fd = -1;
	if (strlen(path) + 16 >= sizeof a->path)
		return -ENAMETOOLONG;
	int rc = follow_links(path, a->path, sizeof a->path - 16);
	if (rc < 0)
		return rc;
	int exists = stat(a->path, &st) == 0;
	if (exists && S_ISBLK(st.st_mode))
		return open_in_place(a);
	if (exists && !S_ISREG(st.st_mode))
		return S_ISDIR(st.st_mode) ? -EISDIR : -EINVAL;
	path = a->path;
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
	if (a->fd < 0) {
		/* no O_TMPFILE here: a named temporary, removed on abort */
		a->fd = mkstemp(a->tmp);
		if (a->fd < 0 || fchmod(a->fd, 0644) != 0)
			return fail(a);
		a->named = 1;
	}
	if (exists && keep_mode(a, &st) != 0)
		return fail(a);
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
	if (a->in_place)
		return fsync(a->fd) == 0 ? 0 : -errno;
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
