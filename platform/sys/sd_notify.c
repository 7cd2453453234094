#include "sd_notify.h"

#include <errno.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

static struct sockaddr_un addr;
static socklen_t addr_len;

static int parse_addr(const char *path)
{
	size_t n = strlen(path);
	if ((path[0] != '/' && path[0] != '@') || n < 2 || n >= sizeof addr.sun_path)
		return -EINVAL;
	memset(&addr, 0, sizeof addr);
	addr.sun_family = AF_UNIX;
	memcpy(addr.sun_path, path, n);
	if (path[0] == '@')
		addr.sun_path[0] = '\0'; /* abstract: no NUL terminator counted */
	addr_len = (socklen_t)(offsetof(struct sockaddr_un, sun_path) + n + (path[0] == '/'));
	return 0;
}

static uint64_t watchdog_interval(void)
{
	const char *usec = getenv("WATCHDOG_USEC"), *pid = getenv("WATCHDOG_PID");
	char *end;
	if (!usec || !*usec)
		return 0;
	if (pid && *pid && strtol(pid, &end, 10) != (long)getpid())
		return 0;
	unsigned long long us = strtoull(usec, &end, 10);
	if (*end || us == 0)
		return 0;
	return (uint64_t)us * 1000u / 2;
}

int sdnotify_init(sdnotify *n)
{
	const char *path = getenv("NOTIFY_SOCKET");
	n->fd = -1;
	n->interval_ns = 0;
	n->last_ns = 0;
	if (!path || !*path)
		return 0;
	int rc = parse_addr(path);
	if (rc < 0)
		return rc;
	n->fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	if (n->fd < 0)
		return -errno;
	n->interval_ns = watchdog_interval();
	return 0;
}

int sdnotify_send(sdnotify *n, const char *state)
{
	if (n->fd < 0)
		return 0;
	ssize_t r;
	do
		r = sendto(n->fd, state, strlen(state), MSG_NOSIGNAL, (const struct sockaddr *)&addr, addr_len);
	while (r < 0 && errno == EINTR);
	return r < 0 ? -errno : 0;
}

int sdnotify_watchdog(sdnotify *n, uint64_t now_ns)
{
	if (n->fd < 0 || !n->interval_ns || (n->last_ns && now_ns - n->last_ns < n->interval_ns))
		return 0;
	n->last_ns = now_ns;
	int rc = sdnotify_send(n, "WATCHDOG=1");
	return rc < 0 ? rc : 1;
}

void sdnotify_close(sdnotify *n)
{
	if (n->fd >= 0)
		close(n->fd);
	n->fd = -1;
}
