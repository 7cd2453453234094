/* The keyboard of the controlling terminal, for desktop work and a
 * console: its keys, mapped by the kiosk as a window's are (1-4 the
 * method, V the view, space, N, the arrows, [ ], + -, the camera's keys,
 * Q or Escape to quit: app/runtime/kiosk_shell.h), not buttons.
 *
 * The terminal goes to non-canonical, no-echo mode (signals still work, so
 * Ctrl-C quits cleanly) and is restored by shutdown(). */
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
} k = { -1, 0, { 0 } };

static int kb_init(const board_config *cfg, const char *arg, uint64_t now_ms, skp_error *err)
{
	(void)cfg, (void)arg, (void)now_ms;
	k.fd = -1;
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

/* The next byte typed, without waiting; 0 when none. */
static int next_byte(unsigned char *c)
{
	struct pollfd p = { k.fd, POLLIN, 0 };
	return poll(&p, 1, 0) > 0 && (p.revents & POLLIN) && read(k.fd, c, 1) == 1;
}

/* An escape sequence after its ESC: the arrows left and right as
 * INPUT_KEY_*, a lone Escape as itself, any other sequence (up, down,
 * function keys, Alt and a key) read to its end and passed over (0). A
 * terminal sends a sequence's bytes together: an ESC with nothing after
 * it is the Escape key. */
static int escape(void)
{
	unsigned char c;
	if (!next_byte(&c))
		return INPUT_KEY_ESCAPE;
	if (c != '[' && c != 'O')
		return 0;
	while (next_byte(&c))
		if (c >= 0x40 && c <= 0x7e)
			return c == 'D' ? INPUT_KEY_LEFT : c == 'C' ? INPUT_KEY_RIGHT : 0;
	return 0;
}

static int kb_key(void)
{
	unsigned char c;
	if (k.fd < 0)
		return 0;
	while (next_byte(&c)) {
		int key = c == 27 ? escape() : c >= 0x20 && c < 0x7f ? c : 0;
		if (key)
			return key;
	}
	return 0;
}

/* Keys, not buttons: the kiosk maps them (key()). */
static int kb_read(uint64_t now_ms, control_event *ev, int max, skp_error *err)
{
	(void)now_ms, (void)ev, (void)max, (void)err;
	return 0;
}

static void kb_shutdown(void)
{
	if (k.saved)
		tcsetattr(STDIN_FILENO, TCSANOW, &k.old);
	k.saved = 0;
	k.fd = -1;
}

const input_backend input_keyboard = { "keyboard", kb_init, kb_read, kb_shutdown, kb_key };
