/* The gpio backend's seam for libgpiod 2.x (Debian 13, Raspberry Pi OS
 * trixie): one struct gpiod_line_request per button. libgpiod 2 reads events
 * only through a request object, so the request's fd is read here as the
 * kernel's struct gpio_v2_line_event, exactly what the library reads: that
 * keeps the fd the one seam a test can feed through a pipe, as with 1.6.
 * libgpiod 2 dropped gpiod_chip_open_lookup(); open_chip does its lookup
 * (name, number, path or label) so board INIs work with either version. */
#include "input.h"

#include <dirent.h>
#include <errno.h>
#include <gpiod.h>
#include <limits.h>
#include <linux/gpio.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

const char input_gpio_api[] = "libgpiod 2";

typedef struct gpiod2_line {
	struct gpiod_line_request *req;   /* NULL: slot free */
	unsigned int offset;
} gpiod2_line;

static gpiod2_line lines[CONTROL_BTN_COUNT];

static struct gpiod_chip *open_path(const char *path)
{
	return gpiod_is_gpiochip_device(path) ? gpiod_chip_open(path) : NULL;
}

static int has_label(const char *path, const char *label)
{
	struct gpiod_chip *chip = open_path(path);
	struct gpiod_chip_info *info = chip ? gpiod_chip_get_info(chip) : NULL;
	int same = info && !strcmp(gpiod_chip_info_get_label(info), label);
	if (info)
		gpiod_chip_info_free(info);
	if (chip)
		gpiod_chip_close(chip);
	return same;
}

/* The first /dev/gpiochip* whose label is label, into path. */
static int find_label(const char *label, char *path, size_t size)
{
	DIR *dir = opendir("/dev");
	struct dirent *d;
	int found = 0;
	while (dir && !found && (d = readdir(dir)))
		if (!strncmp(d->d_name, "gpiochip", 8)) {
			snprintf(path, size, "/dev/%s", d->d_name);
			found = has_label(path, label);
		}
	if (dir)
		closedir(dir);
	return found;
}

static void *lg_open_chip(const char *chip)
{
	char path[PATH_MAX];
	if (strchr(chip, '/'))
		return gpiod_chip_open(chip);
	if (strspn(chip, "0123456789") == strlen(chip))
		snprintf(path, sizeof path, "/dev/gpiochip%s", chip);
	else
		snprintf(path, sizeof path, "/dev/%s", chip);
	struct gpiod_chip *c = open_path(path);
	if (c || find_label(chip, path, sizeof path))
		return c ? c : gpiod_chip_open(path);
	errno = ENOENT;
	return NULL;
}

static enum gpiod_line_bias line_bias(int flags)
{
	if (flags & INPUT_GPIO_BIAS_DISABLE)
		return GPIOD_LINE_BIAS_DISABLED;
	if (flags & INPUT_GPIO_PULL_UP)
		return GPIOD_LINE_BIAS_PULL_UP;
	if (flags & INPUT_GPIO_PULL_DOWN)
		return GPIOD_LINE_BIAS_PULL_DOWN;
	return GPIOD_LINE_BIAS_AS_IS;
}

static struct gpiod_line_request *request_line(struct gpiod_chip *chip, unsigned int offset, int flags,
					       const char *consumer)
{
	struct gpiod_line_settings *s = gpiod_line_settings_new();
	struct gpiod_line_config *lc = gpiod_line_config_new();
	struct gpiod_request_config *rc = gpiod_request_config_new();
	struct gpiod_line_request *req = NULL;
	if (!s || !lc || !rc)
		goto out;
	if (gpiod_line_settings_set_direction(s, GPIOD_LINE_DIRECTION_INPUT) ||
	    gpiod_line_settings_set_edge_detection(s, GPIOD_LINE_EDGE_BOTH) ||
	    gpiod_line_settings_set_bias(s, line_bias(flags)) ||
	    gpiod_line_settings_set_event_clock(s, GPIOD_LINE_CLOCK_MONOTONIC))
		goto out;
	gpiod_line_settings_set_active_low(s, (flags & INPUT_GPIO_ACTIVE_LOW) != 0);
	if (gpiod_line_config_add_line_settings(lc, &offset, 1, s))
		goto out;
	gpiod_request_config_set_consumer(rc, consumer);
	req = gpiod_chip_request_lines(chip, rc, lc);
out:;
	int saved = errno;
	gpiod_request_config_free(rc);
	gpiod_line_config_free(lc);
	gpiod_line_settings_free(s);
	errno = saved;
	return req;
}

static void *lg_request(void *chip, unsigned int offset, int flags, const char *consumer)
{
	gpiod2_line *l = NULL;
	for (int i = 0; i < CONTROL_BTN_COUNT && !l; i++)
		if (!lines[i].req)
			l = &lines[i];
	if (!l) {
		errno = ENOSPC;
		return NULL;
	}
	l->req = request_line(chip, offset, flags, consumer);
	l->offset = offset;
	return l->req ? l : NULL;
}

static int lg_event_fd(void *line)
{
	return gpiod_line_request_get_fd(((gpiod2_line *)line)->req);
}

static int lg_get_value(void *line)
{
	gpiod2_line *l = line;
	return gpiod_line_request_get_value(l->req, l->offset);
}

static void lg_release(void *line)
{
	gpiod2_line *l = line;
	gpiod_line_request_release(l->req);
	l->req = NULL;
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
	struct gpio_v2_line_event ev;
	ssize_t n = read(fd, &ev, sizeof ev);
	if (n < 0)
		return -1;
	if (n != (ssize_t)sizeof ev) {
		errno = EIO;
		return -1;
	}
	/* as 1.6 decodes it: anything but a rising edge is a falling one */
	e->rising = ev.id == GPIO_V2_LINE_EVENT_RISING_EDGE;
	e->ts_ns = ev.timestamp_ns;
	return 0;
}
