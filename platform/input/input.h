/* The button input backends and their registry (input.c, the one file that
 * names them; a board builds those its board.mk lists in INPUTS):
 *
 *   gpio          libgpiod (1.6 or 2.x) both-edge line events, debounced per button
 *   keyboard      the controlling terminal's keys (key(): mapped as a window's)
 *   script:FILE   lines "TIME_MS BUTTON press|release" (tests, demos)
 *   none          no input
 *
 * The interface they implement is the port app/kiosk/input_port.h. */
#ifndef INPUT_H
#define INPUT_H

#include "input_port.h"

/* No buttons: every board has it, and the kiosk falls back to it. */
extern const input_backend input_none;

/* "gpio", "keyboard", "none" or "script:FILE" (then *arg = FILE); NULL
 * when unknown or not built for this board. */
const input_backend *input_find(const char *spec, const char **arg);

/* For backends: appends the events of DEBOUNCE_* bits (in their order)
 * to ev; returns how many (at most 3). */
int input_emit(unsigned bits, int button, uint64_t t_ms, control_event *ev);

/* The seam between the gpio backend and libgpiod, so that tests can hand it
 * pipes instead of line event fds. One implementation per libgpiod API,
 * chosen at build time (SKP_GPIOD_API, from pkg-config): input_gpiod1.c for
 * 1.6, input_gpiod2.c for 2.x. Both read the kernel's own event structs from
 * the fd (1.6 through gpiod_line_event_read_fd, 2.x as struct
 * gpio_v2_line_event), so the tests exercise the real decoding. */

/* Line settings a button asks for (the board INI's active and bias). */
enum {
	INPUT_GPIO_ACTIVE_LOW = 1,
	INPUT_GPIO_BIAS_DISABLE = 2,
	INPUT_GPIO_PULL_UP = 4,
	INPUT_GPIO_PULL_DOWN = 8
};

typedef struct input_gpio_ops {
	/* A chip by name (gpiochip0), number, path or label, as libgpiod 1.6's
	 * gpiod_chip_open_lookup does; NULL with errno. */
	void *(*open_chip)(const char *chip);
	/* Requests both-edge events on one input line with INPUT_GPIO_* flags;
	 * NULL with errno. */
	void *(*request)(void *chip, unsigned int offset, int flags, const char *consumer);
	int (*event_fd)(void *line);
	int (*get_value)(void *line);                  /* active level: 1 pressed, -1 error */
	void (*release)(void *line);
	void (*close_chip)(void *chip);
} input_gpio_ops;

extern const input_gpio_ops input_gpio_libgpiod;
extern const char input_gpio_api[];               /* "libgpiod 1.6" or "libgpiod 2" */

/* One edge event read from a line's event fd. */
typedef struct input_gpio_edge {
	int rising;                                    /* 1: became active */
	uint64_t ts_ns;                                /* the kernel's timestamp */
} input_gpio_edge;

/* Reads one event from fd: 0, or -1 with errno (EAGAIN: none pending, EIO:
 * a short or malformed event). */
int input_gpio_read_edge(int fd, input_gpio_edge *e);

/* NULL restores libgpiod. */
void input_gpio_set_ops(const input_gpio_ops *ops);

/* The INPUT_GPIO_* flags for a button (active level, bias). */
int input_gpio_flags(const board_button *b);

#endif
