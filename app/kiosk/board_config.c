#include "board_config.h"
#include "board_keys.h"

#include <string.h>

#include "ini.h"
#include "modes.h"
#include "skp_format.h"
#include "text_tokens.h"

#define STR_(x) #x
#define STR(x) STR_(x)
#define DISPLAY_MAX_TEXT STR(SKP_DISPLAY_MAX_W) "x" STR(SKP_DISPLAY_MAX_H)

typedef enum {
	SEC_NONE, SEC_DISPLAY, SEC_INPUT, SEC_BUTTON, SEC_STORAGE, SEC_LIMITS, SEC_SKIN, SEC_SHOW, SEC_WALL, SEC_CAMERA
} section_kind;

/* Per-button timing given in the file; -1 inherits [input]'s. */
typedef struct pending {
	long debounce[CONTROL_BTN_COUNT], long_press[CONTROL_BTN_COUNT];
	long debounce_all, long_all;
} pending;

void board_config_defaults(board_config *c)
{
	memset(c, 0, sizeof *c);
	c->rotation = -1;
	c->hud = -1;
	c->algo = -1;
	c->view = -1;
	c->split_verts = BOARD_SPLIT_VERTS;
	c->yaw_mode = -1;
	c->speed = 1.0;
	c->blend_ms = BOARD_BLEND_MS;
	c->root = BOARD_ROOT_IN_PLACE;
	c->loop = BOARD_LOOP_SHOW;
	c->show_buttons = 1;
	c->cam_pitch_deg = CAMERA_PITCH_DEFAULT_DEG;
	c->cam_distance = 1.0f;
	for (int i = 0; i < CONTROL_BTN_COUNT; i++) {
		c->button[i].active_low = 1;
		c->button[i].bias = BOARD_BIAS_PULL_UP;
		c->button[i].deb.debounce_ms = BOARD_DEBOUNCE_MS;
		c->button[i].deb.long_press_ms = BOARD_LONG_PRESS_MS;
	}
}


static skp_status copy_str(char *dst, size_t cap, const ini_entry *e, skp_error *err)
{
	size_t n = strlen(e->value);
	if (n >= cap)
		return skp_fail(err, SKP_ERR_LIMIT, e->line, "key '%s' in [%s]: value longer than %d characters",
				e->key, e->section, (int)cap - 1);
	memcpy(dst, e->value, n + 1);
	return SKP_OK;
}

static skp_status get_long(const ini_entry *e, long lo, long hi, long *out, const char *expected,
			   skp_error *err)
{
	if (tok_parse_long(e->value, out) != 0 || *out < lo || *out > hi)
		return board_bad(err, e, expected);
	return SKP_OK;
}


static skp_status parse_size(board_config *c, const ini_entry *e, skp_error *err)
{
	char buf[32];
	long w, h;
	const char *x = strchr(e->value, 'x');
	size_t n = x ? (size_t)(x - e->value) : 0;
	if (!x || n == 0 || n >= sizeof buf)
		return board_bad(err, e, "WxH");
	memcpy(buf, e->value, n);
	buf[n] = '\0';
	if (tok_parse_long(buf, &w) != 0 || tok_parse_long(x + 1, &h) != 0 || w < 16 || h < 16 ||
	    w > SKP_DISPLAY_MAX_W || h > SKP_DISPLAY_MAX_H)
		return board_bad(err, e, "WxH between 16x16 and the board's " DISPLAY_MAX_TEXT);
	c->width = (int)w;
	c->height = (int)h;
	return SKP_OK;
}

const char *const board_streams_names[BOARD_STREAMS_KINDS] = { "float", "compact" };
const char *const board_root_names[BOARD_ROOT_MODES] = { "in-place", "travel" };

int board_root_parse(const char *word)
{
	return word ? board_pick(word, board_root_names, BOARD_ROOT_MODES) : -1;
}

const char *const board_loop_names[BOARD_LOOP_MODES] = { "show", "clip" };

int board_loop_parse(const char *word)
{
	return word ? board_pick(word, board_loop_names, BOARD_LOOP_MODES) : -1;
}

int board_speed_parse(const char *word, double *out)
{
	return word && tok_parse_double(word, out) == 0 && *out >= BOARD_SPEED_MIN && *out <= BOARD_SPEED_MAX ? 0 : -1;
}

const char *const board_hud_names[BOARD_HUD_MODES] = { "off", "engineer", "visitor" };

int board_hud_parse(const char *word)
{
	return word ? board_pick(word, board_hud_names, BOARD_HUD_MODES) : -1;
}

int board_threads_parse(const char *word)
{
	long n;
	if (word && tok_ieq(word, "auto"))
		return 0;
	return word && tok_parse_long(word, &n) == 0 && n >= 1 && n <= BOARD_MAX_THREADS ? (int)n : -1;
}

int board_streams_parse(const char *word)
{
	return word ? board_pick(word, board_streams_names, BOARD_STREAMS_KINDS) : -1;
}

/* The index of v (any case) among a modes.h list, or -1. */
static int pick_mode(const char *v, const char *(*name)(int), int n)
{
	for (int i = 0; i < n; i++)
		if (tok_ieq(v, name(i)))
			return i;
	return -1;
}

/* [display] algo and view: a name modes.h knows. The names, and the
 * "a, b or c" list a mistake shows, come from there, so a method or view
 * added there is taken and listed here without a second list. */
static skp_status mode_key(int *out, const ini_entry *e, const char *(*name)(int), int n, skp_error *err)
{
	char names[128];
	size_t len = 0;
	if ((*out = pick_mode(e->value, name, n)) >= 0)
		return SKP_OK;
	names[0] = '\0';
	for (int i = 0; i < n; i++)
		len += skp_format(names + len, sizeof names - len, "%s%s", i == 0 ? "" : i < n - 1 ? ", " : " or ",
				  name(i));
	return board_bad(err, e, names);
}

static skp_status display_key(board_config *c, const ini_entry *e, skp_error *err)
{
	static const char *const plats[] = { "auto", "surfaceless", "osmesa", "kms", "x11" };
	long v;
	if (tok_ieq(e->key, "platform")) {
		if (board_pick(e->value, plats, 5) < 0)
			return board_bad(err, e, "auto, surfaceless, osmesa, kms or x11");
		return copy_str(c->platform, sizeof c->platform, e, err);
	}
	if (tok_ieq(e->key, "device"))
		return copy_str(c->device, sizeof c->device, e, err);
	if (tok_ieq(e->key, "size"))
		return parse_size(c, e, err);
	if (tok_ieq(e->key, "rotation")) {
		if (get_long(e, 0, 270, &v, "0, 90, 180 or 270", err) != SKP_OK)
			return err->code;
		if (v % 90)
			return board_bad(err, e, "0, 90, 180 or 270");
		c->rotation = (int)v;
		return SKP_OK;
	}
	if (tok_ieq(e->key, "hud")) {
		if ((c->hud = board_hud_parse(e->value)) < 0)
			return board_bad(err, e, "visitor, engineer or off");
		return SKP_OK;
	}
	if (tok_ieq(e->key, "yaw")) {
		if ((c->yaw_mode = board_yaw_parse(e->value, &c->yaw_deg)) < 0)
			return board_bad(err, e, "auto or degrees from -360 to 360");
		return SKP_OK;
	}
	if (tok_ieq(e->key, "algo"))
		return mode_key(&c->algo, e, skin_algo_name, SKIN_SHOW_COUNT, err);
	if (tok_ieq(e->key, "view"))
		return mode_key(&c->view, e, render_view_name, RENDER_VIEW_COUNT, err);
	return skp_fail(err, SKP_ERR_SYNTAX, e->line,
			"unknown key '%s' in [display] (platform, device, rotation, size, hud, yaw, algo, view)", e->key);
}

static skp_status timing_key(const ini_entry *e, long *debounce, long *long_press, skp_error *err)
{
	if (tok_ieq(e->key, "debounce_ms"))
		return get_long(e, 0, 1000, debounce, "a debounce time of 0..1000 ms", err);
	return get_long(e, 0, 60000, long_press, "a long-press time of 0..60000 ms (0: off)", err);
}

static int is_timing(const char *key)
{
	return tok_ieq(key, "debounce_ms") || tok_ieq(key, "long_press_ms");
}

static skp_status input_key(board_config *c, pending *p, const ini_entry *e, skp_error *err)
{
	if (tok_ieq(e->key, "backend")) {
		if (strcmp(e->value, "gpio") && strcmp(e->value, "keyboard") && strcmp(e->value, "none") &&
		    strncmp(e->value, "script:", 7))
			return board_bad(err, e, "gpio, keyboard, none or script:FILE");
		return copy_str(c->input, sizeof c->input, e, err);
	}
	if (tok_ieq(e->key, "chip"))
		return copy_str(c->chip, sizeof c->chip, e, err);
	if (is_timing(e->key))
		return timing_key(e, &p->debounce_all, &p->long_all, err);
	return skp_fail(err, SKP_ERR_SYNTAX, e->line,
			"unknown key '%s' in [input] (backend, chip, debounce_ms, long_press_ms)", e->key);
}

static skp_status button_key(board_config *c, pending *p, int b, const ini_entry *e, skp_error *err)
{
	static const char *const levels[] = { "high", "low" };
	static const char *const biases[] = { "as-is", "disable", "pull-up", "pull-down" };
	board_button *btn = &c->button[b];
	long v;
	int k;
	if (tok_ieq(e->key, "line")) {
		if (get_long(e, 0, 1023, &v, "a line offset 0..1023 (BCM GPIO number on a Pi)", err) != SKP_OK)
			return err->code;
		btn->line = (unsigned int)v;
		btn->present = 1;   /* a button exists once it has a line */
		return SKP_OK;
	}
	if (tok_ieq(e->key, "active")) {
		if ((k = board_pick(e->value, levels, 2)) < 0)
			return board_bad(err, e, "high or low");
		btn->active_low = k;
		return SKP_OK;
	}
	if (tok_ieq(e->key, "bias")) {
		if ((k = board_pick(e->value, biases, 4)) < 0)
			return board_bad(err, e, "as-is, disable, pull-up or pull-down");
		btn->bias = k;
		return SKP_OK;
	}
	if (is_timing(e->key))
		return timing_key(e, &p->debounce[b], &p->long_press[b], err);
	return skp_fail(err, SKP_ERR_SYNTAX, e->line,
			"unknown key '%s' in [%s] (line, active, bias, debounce_ms, long_press_ms)", e->key,
			e->section);
}

static skp_status storage_key(board_config *c, const ini_entry *e, skp_error *err)
{
	if (!tok_ieq(e->key, "slot"))
		return skp_fail(err, SKP_ERR_SYNTAX, e->line, "unknown key '%s' in [storage] (slot)", e->key);
	if (c->slot_count >= SKP_MAX_SLOTS)
		return skp_fail(err, SKP_ERR_LIMIT, e->line, "key 'slot' in [storage]: more than %d slots (SKP_MAX_SLOTS)",
				SKP_MAX_SLOTS);
	return copy_str(c->slot[c->slot_count++], SKP_MAX_PATH, e, err);
}

static skp_status limits_key(board_config *c, const ini_entry *e, skp_error *err)
{
	long v;
	if (tok_ieq(e->key, "max_fps")) {
		if (get_long(e, 0, 1000, &v, "a frame rate of 0..1000 (0: no cap)", err) != SKP_OK)
			return err->code;
		c->max_fps = (int)v;
		return SKP_OK;
	}
	return skp_fail(err, SKP_ERR_SYNTAX, e->line, "unknown key '%s' in [limits] (max_fps)", e->key);
}

static skp_status skin_key(board_config *c, const ini_entry *e, skp_error *err)
{
	long v;
	if (tok_ieq(e->key, "threads")) {
		if ((c->threads = board_threads_parse(e->value)) < 0)
			return board_bad(err, e, "auto or a thread count of 1.." STR(BOARD_MAX_THREADS));
		return SKP_OK;
	}
	if (tok_ieq(e->key, "streams")) {
		if ((c->streams = board_streams_parse(e->value)) < 0)
			return board_bad(err, e, "float or compact");
		return SKP_OK;
	}
	if (tok_ieq(e->key, "split_verts")) {
		if (tok_ieq(e->value, "auto")) {
			c->split_verts = BOARD_SPLIT_AUTO;
			return SKP_OK;
		}
		if (get_long(e, 1, 100000000, &v, "auto or a vertex count of 1..100000000", err) != SKP_OK)
			return err->code;
		c->split_verts = (int)v;
		return SKP_OK;
	}
	return skp_fail(err, SKP_ERR_SYNTAX, e->line, "unknown key '%s' in [skin] (threads, split_verts, streams)", e->key);
}

static skp_status show_key(board_config *c, const ini_entry *e, skp_error *err)
{
	long v;
	if (tok_ieq(e->key, "speed")) {
		if (board_speed_parse(e->value, &c->speed) < 0)
			return board_bad(err, e, "a speed from 0.1 to 4 (1: as captured)");
		return SKP_OK;
	}
	if (tok_ieq(e->key, "blend_ms")) {
		if (get_long(e, 0, BOARD_BLEND_MS_MAX, &v, "a crossfade of 0.." STR(BOARD_BLEND_MS_MAX) " ms (0: cut)", err) !=
		    SKP_OK)
			return err->code;
		c->blend_ms = (int)v;
		return SKP_OK;
	}
	if (tok_ieq(e->key, "root")) {
		if ((c->root = board_root_parse(e->value)) < 0)
			return board_bad(err, e, "in-place or travel");
		return SKP_OK;
	}
	if (tok_ieq(e->key, "loop")) {
		if ((c->loop = board_loop_parse(e->value)) < 0)
			return board_bad(err, e, "show or clip");
		return SKP_OK;
	}
	return board_show_sync_key(c, e, err);
}

/* "button.algo" -> CONTROL_BTN_ALGO; -1 when not a button section. */
static int button_section(const char *s)
{
	if (strncmp(s, "button.", 7) && strncmp(s, "Button.", 7))
		return -1;
	return control_button_find(s + 7);
}

static skp_status section_of(const ini_entry *e, section_kind *k, int *b, skp_error *err)
{
	static const char *const names[] = { "", "display", "input", "button", "storage", "limits", "skin", "show",
					     "wall", "camera" };
	*b = button_section(e->section);
	if (*b >= 0) {
		*k = SEC_BUTTON;
		return SKP_OK;
	}
	for (int i = 1; i < 10; i++)
		if (i != SEC_BUTTON && tok_ieq(e->section, names[i])) {
			*k = (section_kind)i;
			return SKP_OK;
		}
	if (!*e->section)
		return skp_fail(err, SKP_ERR_SYNTAX, e->line, "key '%s' before any [section]", e->key);
	return skp_fail(err, SKP_ERR_SYNTAX, e->line,
			"key '%s' in unknown section [%s] (display, input, button.algo|play|next|view, storage, limits, skin, show, "
			"wall, camera)",
			e->key, e->section);
}

static void resolve(board_config *c, const pending *p)
{
	for (int i = 0; i < CONTROL_BTN_COUNT; i++) {
		long d = p->debounce[i] >= 0 ? p->debounce[i] : p->debounce_all;
		long l = p->long_press[i] >= 0 ? p->long_press[i] : p->long_all;
		if (d >= 0)
			c->button[i].deb.debounce_ms = (uint32_t)d;
		if (l >= 0)
			c->button[i].deb.long_press_ms = (uint32_t)l;
	}
}

void board_config_problem(board_config *c, long line, const char *msg)
{
	if (c->problem_count < BOARD_MAX_PROBLEMS) {
		board_problem *p = &c->problem[c->problem_count];
		p->line = line;
		skp_format(p->msg, sizeof p->msg, "%s", msg);
	}
	c->problem_count++;
}

static skp_status apply_key(board_config *c, pending *p, const ini_entry *e, skp_error *err)
{
	section_kind k = SEC_NONE;
	int b;
	skp_status st = section_of(e, &k, &b, err);
	if (st != SKP_OK)
		return st;
	switch (k) {
	case SEC_DISPLAY: return display_key(c, e, err);
	case SEC_INPUT: return input_key(c, p, e, err);
	case SEC_BUTTON: return button_key(c, p, b, e, err);
	case SEC_STORAGE: return storage_key(c, e, err);
	case SEC_SKIN: return skin_key(c, e, err);
	case SEC_SHOW: return show_key(c, e, err);
	case SEC_WALL: return board_wall_key(c, e, err);
	case SEC_CAMERA: return board_camera_key(c, e, err);
	default: return limits_key(c, e, err);
	}
}

/* One key applied; a mistake leaves what was there before (the default)
 * and is recorded. */
static void take_key(board_config *c, pending *p, const ini_entry *e)
{
	static board_config before; /* a few KiB: not on a small stack */
	pending was = *p;
	skp_error err;
	before = *c;
	if (apply_key(c, p, e, &err) == SKP_OK)
		return;
	*c = before;
	*p = was;
	board_config_problem(c, err.line, err.msg);
}

skp_status board_config_read(board_config *c, skp_reader rd, skp_error *err)
{
	static ini_reader ini; /* 5 KiB of line buffers: not on a small stack */
	pending p;
	ini_entry e;
	int rc;
	board_config_defaults(c);
	p.debounce_all = p.long_all = -1;
	for (int i = 0; i < CONTROL_BTN_COUNT; i++)
		p.debounce[i] = p.long_press[i] = -1;
	ini_init(&ini, rd);
	while ((rc = ini_next(&ini, &e, err)) != 0) {
		if (rc > 0) {
			take_key(c, &p, &e);
			continue;
		}
		if (err->code == SKP_ERR_IO)
			return SKP_ERR_IO;
		board_config_problem(c, err->line, err->msg);
		if (!ini_can_go_on(&ini))
			break;
	}
	skp_error_clear(err);
	resolve(c, &p);
	return SKP_OK;
}
