#include "tool_anchor.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static void child(char *const argv[], int out_fd)
{
	int null = open("/dev/null", O_RDONLY);
	if (null >= 0)
		dup2(null, 0);
	dup2(out_fd, 1);
	execv(argv[0], argv);
	_exit(127);
}

/* Reads all of fd, keeping what fits. */
static void drain(int fd, char *out, size_t n)
{
	size_t len = 0;
	char sink[4096];
	for (;;) {
		char *at = len + 1 < n ? out + len : sink;
		size_t room = len + 1 < n ? n - 1 - len : sizeof sink;
		ssize_t got = read(fd, at, room);
		if (got < 0 && errno == EINTR)
			continue;
		if (got <= 0)
			break;
		if (at != sink)
			len += (size_t)got;
	}
	out[len] = 0;
}

int tool_anchor_run(char *const argv[], char *out, size_t n)
{
	int fd[2], status;
	if (n == 0 || pipe(fd) != 0)
		return -1;
	pid_t pid = fork();
	if (pid < 0) {
		snprintf(out, n, "%s", strerror(errno));
		close(fd[0]);
		close(fd[1]);
		return -1;
	}
	if (pid == 0)
		child(argv, fd[1]);
	close(fd[1]);
	drain(fd[0], out, n);
	close(fd[0]);
	while (waitpid(pid, &status, 0) < 0)
		if (errno != EINTR)
			return -1;
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* M vertices/s of one round of the ozz anchor on the same case (verts,
 * one thread), or 0 after saying why not. */
double tool_anchor_ozz_rate(const char *ozz, long verts)
{
	char n[24], out[512];
	snprintf(n, sizeof n, "%ld", verts);
	char *const argv[] = { (char *)ozz, n, "1", NULL };
	int rc = tool_anchor_run(argv, out, sizeof out);
	const char *at = strstr(out, "ozz lbs P+N:");
	double rate = 0;
	if (rc != 0 || !at || sscanf(at, "ozz lbs P+N: %lf", &rate) != 1 || !(rate > 0)) {
		fprintf(stderr, "skintool bench: %s: no rate in its output (exit %d)\n", ozz, rc);
		return 0;
	}
	return rate;
}
