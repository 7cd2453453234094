/* Buttons on the keyboard of the controlling terminal, for desktop work:
 *
 *   1 / Left   ALGO        2 / Down   PLAY (r: long, restart)
 *   3 / Right  NEXT        4 / Up     VIEW (g: long, CPU/GPU)
 *
 * The terminal goes to non-canonical, no-echo mode (signals still work, so
 * Ctrl-C quits cleanly) and is restored by shutdown(). A terminal reports
 * no key releases: each key is a press and a release at once. */
#include "input.h"

#include <poll.h>

#include <errno.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

static struct {
	int fd;                  /* -1: no terminal */
	int saved;
	struct termios old;
	char esc[3];             /* an escape sequence read so far */
	int esc_len;
} k = { -1, 0, { 0 }, { 0 }, 0 };

static int kb_init(const board_config *cfg, const char *arg, uint64_t now_ms, skp_error *err)
{
	(void)cfg, (void)arg, (void)now_ms;
	k.fd = -1;
	k.esc_len = 0;
	if (!isatty(STDIN_FILENO))
		return 0; /* no terminal (a service, a pipe): no keys, not an error */
	struct termios t;
	if (tcgetattr(STDIN_FILENO, &k.old) != 0)
		return skp_fail(err, SKP_ERR_IO, 0, "keyboard: %s", strerror(errno)), -1;
	t = k.old;
	t.c_lflag &= ~(tcflag_t)(ICANON | ECHO);
	t.c_cc[VMIN] = 0;
	t.c_cc[VTIME] = 0;
	if (tcsetattr(STDIN_FILENO, TCSANOW, &t) != 0)
		return skp_fail(err, SKP_ERR_IO, 0, "keyboard: %s", strerror(errno)), -1;
	k.saved = 1;
	k.fd = STDIN_FILENO;
	return 0;
}

/* The button of a key and whether it is the long press; -1 for others. */
static int key_button(int c, int *is_long)
{
	static const char keys[] = "1234";
	static const char arrows[] = "DBCA"; /* ESC [ D left, B down, C right, A up */
	*is_long = 0;
	if (c == 'r' || c == 'g') {
		*is_long = 1;
		return c == 'r' ? CONTROL_BTN_PLAY : CONTROL_BTN_VIEW;
	}
	const char *p = c ? strchr(keys, c) : NULL;
	if (p)
		return (int)(p - keys);
	p = c < 0 && -c < 128 ? strchr(arrows, -c) : NULL;
	return p ? (int)(p - arrows) : -1;
}

/* Feeds one byte; returns a key (arrows as -'A'..-'D') or 0. */
static int key_of(char c)
{
	if (k.esc_len == 0 && c == 27) {
		k.esc[k.esc_len++] = c;
		return 0;
	}
	if (k.esc_len == 1) {
		k.esc_len = c == '[' ? 2 : 0;
		return 0;
	}
	if (k.esc_len == 2) {
		k.esc_len = 0;
		return -c;
	}
	return c;
}

static int kb_read(uint64_t now_ms, control_event *ev, int max, skp_error *err)
{
	int n = 0;
	(void)err;
	if (k.fd < 0)
		return 0;
	struct pollfd p = { k.fd, POLLIN, 0 };
	while (max - n >= 3 && poll(&p, 1, 0) > 0 && (p.revents & POLLIN)) {
		char c;
		if (read(k.fd, &c, 1) != 1)
			break;
		int is_long, b = key_button(key_of(c), &is_long);
		if (b < 0)
			continue;
		unsigned bits = DEBOUNCE_PRESS | DEBOUNCE_RELEASE | (is_long ? DEBOUNCE_LONG : 0);
		n += input_emit(bits, b, now_ms, ev + n);
	}
	return n;
}

static void kb_shutdown(void)
{
	if (k.saved)
		tcsetattr(STDIN_FILENO, TCSANOW, &k.old);
	k.saved = 0;
	k.fd = -1;
}

const input_backend input_keyboard = { "keyboard", kb_init, kb_read, kb_shutdown };
