/* Scripted button presses for tests and demos: `script:FILE` with lines
 *
 *     # comment
 *     TIME_MS BUTTON press|release      e.g. "1000 ALGO press"
 *
 * in time order, TIME_MS counted from init(). Presses are clean, so there
 * is no debounce time, but the board's long-press time applies: a press
 * released after long_press_ms gives a long press at that time. */
#include "input.h"

#include <string.h>

#include "file_reader.h"
#include "text_lines.h"
#include "text_tokens.h"

#define SCRIPT_MAX_EVENTS 1024

typedef struct script_line {
	uint64_t t_ms;
	uint8_t button, level;
} script_line;

static struct {
	script_line ev[SCRIPT_MAX_EVENTS];
	int count, next;
	uint64_t base;
	debounce_config cfg[CONTROL_BTN_COUNT];
	debounce_data deb[CONTROL_BTN_COUNT];
	text_lines lines;
} s;

static int parse_line(const char *path, char *line, long ln, uint64_t prev, skp_error *err)
{
	char *tok[4];
	long t;
	int n = tok_split(line, tok, 4);
	if (n == 0)
		return 0;
	if (n != 3)
		return skp_fail(err, SKP_ERR_SYNTAX, ln, "%s:%ld: expected 'TIME_MS BUTTON press|release'", path, ln), -1;
	if (tok_parse_long(tok[0], &t) != 0 || t < 0)
		return skp_fail(err, SKP_ERR_SYNTAX, ln, "%s:%ld: expected a time in ms >= 0, found '%s'", path, ln,
				tok[0]), -1;
	if ((uint64_t)t < prev)
		return skp_fail(err, SKP_ERR_SYNTAX, ln, "%s:%ld: time %ld is before the previous line's %lu", path, ln,
				t, (unsigned long)prev), -1;
	int b = control_button_find(tok[1]);
	if (b < 0)
		return skp_fail(err, SKP_ERR_SYNTAX, ln, "%s:%ld: unknown button '%s' (ALGO, PLAY, NEXT, VIEW)", path,
				ln, tok[1]), -1;
	int press = tok_ieq(tok[2], "press");
	if (!press && !tok_ieq(tok[2], "release"))
		return skp_fail(err, SKP_ERR_SYNTAX, ln, "%s:%ld: expected press or release, found '%s'", path, ln,
				tok[2]), -1;
	if (s.count >= SCRIPT_MAX_EVENTS)
		return skp_fail(err, SKP_ERR_LIMIT, ln, "%s:%ld: more than %d events", path, ln, SCRIPT_MAX_EVENTS), -1;
	script_line *e = &s.ev[s.count++];
	e->t_ms = (uint64_t)t;
	e->button = (uint8_t)b;
	e->level = (uint8_t)press;
	return 0;
}

static int load(const char *path, skp_error *err)
{
	file_reader fr;
	int rc = file_reader_open(&fr, path);
	if (rc < 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: cannot open: %s", path, strerror(-rc)), -1;
	text_lines_init(&s.lines, file_reader_as_reader(&fr));
	char *line;
	while ((rc = text_lines_next(&s.lines, &line, NULL, err)) > 0) {
		uint64_t prev = s.count ? s.ev[s.count - 1].t_ms : 0;
		if (parse_line(path, line, s.lines.line_no, prev, err) < 0)
			break;
	}
	if (rc < 0) {
		/* the line reader's error: put the file name in front */
		skp_error e = *err;
		skp_fail(err, e.code, e.line, "%s:%ld: %s", path, e.line, e.msg);
	}
	file_reader_close(&fr);
	return rc != 0 ? -1 : 0;
}

static int script_init(const board_config *cfg, const char *arg, uint64_t now_ms, skp_error *err)
{
	s.count = s.next = 0;
	s.base = now_ms;
	for (int b = 0; b < CONTROL_BTN_COUNT; b++) {
		s.cfg[b].debounce_ms = 0;
		s.cfg[b].long_press_ms = cfg ? cfg->button[b].deb.long_press_ms : BOARD_LONG_PRESS_MS;
		debounce_init(&s.deb[b], 0, now_ms);
	}
	return load(arg, err);
}

/* Fires every button's timers up to t, in time order with the lines. */
static int tick_all(uint64_t t, control_event *ev)
{
	int n = 0;
	for (int b = 0; b < CONTROL_BTN_COUNT; b++)
		n += input_emit(debounce_update(&s.cfg[b], &s.deb[b], t, DEBOUNCE_TICK), b, t, ev + n);
	return n;
}

static int script_read(uint64_t now_ms, control_event *ev, int max, skp_error *err)
{
	int n = 0;
	(void)err;
	/* room for a line's events plus every button's timers */
	while (s.next < s.count && s.base + s.ev[s.next].t_ms <= now_ms && max - n >= 3 + 3 * CONTROL_BTN_COUNT) {
		const script_line *e = &s.ev[s.next++];
		uint64_t t = s.base + e->t_ms;
		n += tick_all(t, ev + n);
		n += input_emit(debounce_update(&s.cfg[e->button], &s.deb[e->button], t, e->level), e->button, t,
				ev + n);
	}
	if (max - n >= 3 * CONTROL_BTN_COUNT)
		n += tick_all(now_ms, ev + n);
	return n;
}

static void script_shutdown(void)
{
	s.count = s.next = 0;
}

const input_backend input_script = { "script", script_init, script_read, script_shutdown, NULL };
