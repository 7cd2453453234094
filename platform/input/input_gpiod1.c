/* The gpio backend's seam for libgpiod 1.6 (Debian 12, Raspberry Pi OS
 * bookworm): one struct gpiod_line per button, events decoded by
 * gpiod_line_event_read_fd() (the kernel's v1 struct gpioevent_data). */
#include "input.h"

#include <errno.h>
#include <gpiod.h>

const char input_gpio_api[] = "libgpiod 1.6";

static void *lg_open_chip(const char *chip)
{
	return gpiod_chip_open_lookup(chip);
}

static int request_flags(int flags)
{
	int f = flags & INPUT_GPIO_ACTIVE_LOW ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
	if (flags & INPUT_GPIO_BIAS_DISABLE)
		f |= GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE;
	if (flags & INPUT_GPIO_PULL_UP)
		f |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
	if (flags & INPUT_GPIO_PULL_DOWN)
		f |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN;
	return f;
}

static void *lg_request(void *chip, unsigned int offset, int flags, const char *consumer)
{
	struct gpiod_line *line = gpiod_chip_get_line(chip, offset);
	if (!line || gpiod_line_request_both_edges_events_flags(line, consumer, request_flags(flags)) != 0)
		return NULL;
	return line;
}

static int lg_event_fd(void *line)
{
	return gpiod_line_event_get_fd(line);
}

static int lg_get_value(void *line)
{
	return gpiod_line_get_value(line);
}

static void lg_release(void *line)
{
	gpiod_line_release(line);
}

static void lg_close_chip(void *chip)
{
	gpiod_chip_close(chip);
}

const input_gpio_ops input_gpio_libgpiod = {
	lg_open_chip, lg_request, lg_event_fd, lg_get_value, lg_release, lg_close_chip
};

int input_gpio_read_edge(int fd, input_gpio_edge *e)
{
	struct gpiod_line_event ev;
	if (gpiod_line_event_read_fd(fd, &ev) != 0)
		return -1;
	e->rising = ev.event_type == GPIOD_LINE_EVENT_RISING_EDGE;
	e->ts_ns = (uint64_t)ev.ts.tv_sec * 1000000000u + (uint64_t)ev.ts.tv_nsec;
	return 0;
}
