/* sd_notify against a unix datagram socket the test opens (a path, and the
 * abstract namespace '@'), the watchdog period from $WATCHDOG_USEC, and the
 * signal fd (SIGTERM/SIGINT quit, SIGHUP reload). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include "sd_notify.h"
#include "signals.h"

/* Binds a datagram socket at name ('@...' abstract, else a path). */
static int listen_at(const char *name)
{
	struct sockaddr_un a;
	memset(&a, 0, sizeof a);
	a.sun_family = AF_UNIX;
	size_t n = strlen(name);
	memcpy(a.sun_path, name, n);
	socklen_t len = (socklen_t)(offsetof(struct sockaddr_un, sun_path) + n);
	if (name[0] == '@')
		a.sun_path[0] = '\0';
	else
		unlink(name);
	int fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	assert_true(fd >= 0);
	if (bind(fd, (struct sockaddr *)&a, len) != 0)
		fail_msg("bind %s: %s", name, strerror(errno));
	return fd;
}

/* The next datagram, or "" when none arrives within 1 s. */
static const char *recv_msg(int fd, int wait_ms)
{
	static char buf[256];
	struct pollfd p = { fd, POLLIN, 0 };
	buf[0] = '\0';
	if (poll(&p, 1, wait_ms) == 1) {
		ssize_t n = recv(fd, buf, sizeof buf - 1, 0);
		buf[n > 0 ? n : 0] = '\0';
	}
	return buf;
}

static void check_socket(const char *name)
{
	int srv = listen_at(name);
	sdnotify n;
	setenv("NOTIFY_SOCKET", name, 1);
	setenv("WATCHDOG_USEC", "200000", 1);
	unsetenv("WATCHDOG_PID");
	assert_int_equal(sdnotify_init(&n), 0);
	assert_true(n.fd >= 0);
	assert_int_equal(n.interval_ns, 100000000u); /* half the period */
	assert_int_equal(sdnotify_send(&n, "READY=1"), 0);
	assert_string_equal(recv_msg(srv, 1000), "READY=1");
	uint64_t t0 = 5000000000u;
	assert_int_equal(sdnotify_watchdog(&n, t0), 1);
	assert_string_equal(recv_msg(srv, 1000), "WATCHDOG=1");
	assert_int_equal(sdnotify_watchdog(&n, t0 + 99999999u), 0);
	assert_string_equal(recv_msg(srv, 0), "");
	assert_int_equal(sdnotify_watchdog(&n, t0 + 100000000u), 1);
	assert_string_equal(recv_msg(srv, 1000), "WATCHDOG=1");
	sdnotify_close(&n);
	close(srv);
	if (name[0] == '/')
		unlink(name);
}

static void test_path_socket(void **state)
{
	(void)state;
	char path[64];
	snprintf(path, sizeof path, "/tmp/skp_notify_%d", (int)getpid());
	check_socket(path);
}

static void test_abstract_socket(void **state)
{
	(void)state;
	char name[64];
	snprintf(name, sizeof name, "@skp_notify_%d", (int)getpid());
	check_socket(name);
}

static void test_not_under_systemd_and_foreign_watchdog(void **state)
{
	(void)state;
	sdnotify n;
	unsetenv("NOTIFY_SOCKET");
	assert_int_equal(sdnotify_init(&n), 0);
	assert_int_equal(n.fd, -1);
	assert_int_equal(sdnotify_send(&n, "READY=1"), 0);
	assert_int_equal(sdnotify_watchdog(&n, 1), 0);
	/* the watchdog belongs to another process: not ours to feed */
	char name[64];
	snprintf(name, sizeof name, "@skp_notify_pid_%d", (int)getpid());
	int srv = listen_at(name);
	setenv("NOTIFY_SOCKET", name, 1);
	setenv("WATCHDOG_USEC", "200000", 1);
	setenv("WATCHDOG_PID", "1", 1);
	assert_int_equal(sdnotify_init(&n), 0);
	assert_int_equal(n.interval_ns, 0);
	assert_int_equal(sdnotify_watchdog(&n, 1000000000u), 0);
	assert_int_equal(sdnotify_send(&n, "READY=1"), 0);
	assert_string_equal(recv_msg(srv, 1000), "READY=1");
	sdnotify_close(&n);
	close(srv);
	/* a socket name that is neither a path nor abstract */
	setenv("NOTIFY_SOCKET", "relative/sock", 1);
	assert_int_equal(sdnotify_init(&n), -EINVAL);
	unsetenv("NOTIFY_SOCKET");
	unsetenv("WATCHDOG_USEC");
	unsetenv("WATCHDOG_PID");
}

static void test_signals_become_bits(void **state)
{
	(void)state;
	int fd = signals_init();
	assert_true(fd >= 0);
	assert_int_equal(signals_take(), 0);
	struct pollfd p = { fd, POLLIN, 0 };
	assert_int_equal(poll(&p, 1, 0), 0);
	raise(SIGHUP);
	assert_int_equal(poll(&p, 1, 1000), 1);
	assert_int_equal(signals_take(), SIGNALS_RELOAD);
	raise(SIGTERM);
	raise(SIGINT);
	assert_int_equal(signals_take(), SIGNALS_QUIT);
	raise(SIGHUP);
	raise(SIGTERM);
	assert_int_equal(signals_take(), SIGNALS_QUIT | SIGNALS_RELOAD);
	assert_int_equal(signals_take(), 0);
	signals_shutdown();
	assert_int_equal(signals_take(), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_path_socket),
		cmocka_unit_test(test_abstract_socket),
		cmocka_unit_test(test_not_under_systemd_and_foreign_watchdog),
		cmocka_unit_test(test_signals_become_bits),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
