#define _GNU_SOURCE /* pipe2 */
#include "signals.h"

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>

static int pipe_fd[2] = { -1, -1 };

static void signal_set(sigset_t *s)
{
	sigemptyset(s);
	sigaddset(s, SIGTERM);
	sigaddset(s, SIGINT);
	sigaddset(s, SIGHUP);
}

static void on_signal(int sig)
{
	int saved = errno;
	char c = sig == SIGHUP ? 'h' : 'q';
	/* full pipe: a byte is already waiting, nothing is lost */
	if (write(pipe_fd[1], &c, 1) < 0)
		(void)0;
	errno = saved;
}

int signals_init(void)
{
	if (pipe2(pipe_fd, O_NONBLOCK | O_CLOEXEC) != 0)
		return -errno;
	struct sigaction sa;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = on_signal;
	sa.sa_flags = SA_RESTART;
	sigemptyset(&sa.sa_mask);
	if (sigaction(SIGTERM, &sa, NULL) || sigaction(SIGINT, &sa, NULL) || sigaction(SIGHUP, &sa, NULL)) {
		int e = errno;
		signals_shutdown();
		return -e;
	}
	sigset_t s;
	signal_set(&s);
	pthread_sigmask(SIG_UNBLOCK, &s, NULL);
	return pipe_fd[0];
}

void signals_hold(void)
{
	sigset_t s;
	signal_set(&s);
	pthread_sigmask(SIG_BLOCK, &s, NULL);
}

unsigned signals_take(void)
{
	unsigned bits = 0;
	char buf[64];
	ssize_t n;
	if (pipe_fd[0] < 0)
		return 0;
	while ((n = read(pipe_fd[0], buf, sizeof buf)) > 0)
		for (ssize_t i = 0; i < n; i++)
			bits |= buf[i] == 'h' ? SIGNALS_RELOAD : SIGNALS_QUIT;
	return bits;
}

void signals_shutdown(void)
{
	signal(SIGTERM, SIG_DFL);
	signal(SIGINT, SIG_DFL);
	signal(SIGHUP, SIG_DFL);
	for (int i = 0; i < 2; i++) {
		if (pipe_fd[i] >= 0)
			close(pipe_fd[i]);
		pipe_fd[i] = -1;
	}
}
