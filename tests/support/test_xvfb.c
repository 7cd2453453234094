#include "test_xvfb.h"

#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

pid_t test_xvfb_start(const char *geometry, char *name, size_t size)
{
	int fds[2];
	char fd_arg[16], buf[16] = "";

	if (system("command -v Xvfb >/dev/null 2>&1") != 0 || pipe(fds) != 0)
		return 0;
	pid_t pid = fork();
	if (pid == 0) {
		close(fds[0]);
		snprintf(fd_arg, sizeof fd_arg, "%d", fds[1]);
		execlp("Xvfb", "Xvfb", "-displayfd", fd_arg, "-screen", "0", geometry, "-nolisten", "tcp", (char *)NULL);
		_exit(127);
	}
	close(fds[1]);
	/* Xvfb writes the number and the newline separately, and dies if the
	 * pipe is closed between the two: read up to the newline. */
	size_t n = 0;
	while (pid > 0 && n < sizeof buf - 1 && !strchr(buf, '\n')) {
		struct pollfd p = { .fd = fds[0], .events = POLLIN };
		ssize_t got = poll(&p, 1, 10000) == 1 ? read(fds[0], buf + n, sizeof buf - 1 - n) : -1;
		if (got <= 0)
			break;
		n += (size_t)got;
	}
	close(fds[0]);
	if (!strchr(buf, '\n')) {
		test_xvfb_stop(pid);
		return 0;
	}
	snprintf(name, size, ":%d", atoi(buf));
	return pid;
}

void test_xvfb_stop(pid_t pid)
{
	if (pid > 0) {
		kill(pid, SIGTERM);
		waitpid(pid, NULL, 0);
	}
}
