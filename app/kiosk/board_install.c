/* A device's part in an installation of many screens: [show] sync, epoch
 * and buttons (one show on synchronised clocks), [wall] (this screen's
 * tile of a video wall) and [camera] (this screen's own view). */
#include "board_keys.h"


#include "text_tokens.h"
#include "utc_time.h"

/* [show]'s keys for synchronised installations: sync, epoch, buttons. */
skp_status board_show_sync_key(board_config *c, const ini_entry *e, skp_error *err)
{
	static const char *const sync_words[] = { "off", "clock" }, *const on_off[] = { "off", "on" };
	int w;
	if (tok_ieq(e->key, "sync")) {
		if ((w = board_pick(e->value, sync_words, 2)) < 0)
			return board_bad(err, e, "off or clock");
		c->sync = w;
		return SKP_OK;
	}
	if (tok_ieq(e->key, "epoch")) {
		if (utc_time_parse(e->value, &c->epoch_ns) < 0)
			return board_bad(err, e, "an ISO 8601 UTC time such as 2026-01-01T00:00:00Z");
		return SKP_OK;
	}
	if (tok_ieq(e->key, "buttons")) {
		if ((w = board_pick(e->value, on_off, 2)) < 0)
			return board_bad(err, e, "on or off");
		c->show_buttons = w;
		return SKP_OK;
	}
	return skp_fail(err, SKP_ERR_SYNTAX, e->line,
			"unknown key '%s' in [show] (speed, blend_ms, root, loop, sync, epoch, buttons)", e->key);
}

static skp_status get_int(const ini_entry *e, long lo, long hi, int *out, const char *expected, skp_error *err)
{
	long v;
	if (tok_parse_long(e->value, &v) != 0 || v < lo || v > hi)
		return board_bad(err, e, expected);
	*out = (int)v;
	return SKP_OK;
}

skp_status board_wall_key(board_config *c, const ini_entry *e, skp_error *err)
{
	if (tok_ieq(e->key, "columns"))
		return get_int(e, 1, BOARD_WALL_MAX, &c->wall_columns, "1 to 16 screens across", err);
	if (tok_ieq(e->key, "rows"))
		return get_int(e, 1, BOARD_WALL_MAX, &c->wall_rows, "1 to 16 screens down", err);
	if (tok_ieq(e->key, "column"))
		return get_int(e, 0, BOARD_WALL_MAX - 1, &c->wall_column, "this screen's column, 0 to 15 from the left", err);
	if (tok_ieq(e->key, "row"))
		return get_int(e, 0, BOARD_WALL_MAX - 1, &c->wall_row, "this screen's row, 0 to 15 from the top", err);
	if (tok_ieq(e->key, "bezel"))
		return get_int(e, 0, 2000, &c->wall_bezel, "0 to 2000 pixels behind two screens' frames", err);
	return skp_fail(err, SKP_ERR_SYNTAX, e->line, "unknown key '%s' in [wall] (columns, rows, column, row, bezel)",
			e->key);
}

static skp_status get_float(const ini_entry *e, double lo, double hi, float *out, const char *expected, skp_error *err)
{
	double v;
	if (tok_parse_double(e->value, &v) != 0 || !(v >= lo && v <= hi))
		return board_bad(err, e, expected);
	*out = (float)v;
	return SKP_OK;
}

/* "x, y, z": three numbers from -5 to 5, commas or spaces between. */
static skp_status get_target(const ini_entry *e, float out[3], skp_error *err)
{
	char words[3][32];
	const char *p = e->value;
	for (int i = 0; i < 3; i++) {
		int n = 0;
		while (*p == ' ' || *p == '\t' || *p == ',')
			p++;
		while (*p && *p != ' ' && *p != '\t' && *p != ',' && n < 31)
			words[i][n++] = *p++;
		words[i][n] = '\0';
	}
	while (*p == ' ' || *p == '\t')
		p++;
	float v[3];
	for (int i = 0; i < 3; i++) {
		double d;
		if (*p || tok_parse_double(words[i], &d) != 0 || !(d >= -5.0 && d <= 5.0))
			return board_bad(err, e, "x, y, z from the body's centre in body heights, -5 to 5 each");
		v[i] = (float)d;
	}
	for (int i = 0; i < 3; i++)
		out[i] = v[i];
	return SKP_OK;
}

skp_status board_camera_key(board_config *c, const ini_entry *e, skp_error *err)
{
	if (tok_ieq(e->key, "yaw")) {
		int mode = board_yaw_parse(e->value, &c->yaw_deg);
		if (mode < 0)
			return board_bad(err, e, "auto or degrees from -360 to 360");
		c->yaw_mode = mode;
		return SKP_OK;
	}
	if (tok_ieq(e->key, "pitch"))
		return get_float(e, -30.0, 80.0, &c->cam_pitch_deg, "degrees from above, -30 to 80", err);
	if (tok_ieq(e->key, "distance"))
		return get_float(e, 0.2, 10.0, &c->cam_distance, "0.2 to 10 times the distance that frames the body", err);
	if (tok_ieq(e->key, "target"))
		return get_target(e, c->cam_aim, err);
	return skp_fail(err, SKP_ERR_SYNTAX, e->line, "unknown key '%s' in [camera] (yaw, pitch, distance, target)",
			e->key);
}
