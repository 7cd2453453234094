/* A line of each section (:units, :root, :bonedata, :hierarchy, the ':'
 * keywords themselves) read into the skeleton as the file gives it; asf.c
 * derives the rest once the file has ended. */
#include "asf_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "text_tokens.h"

static skp_status expect_values(asf_state *st, char **t, int n, int want)
{
	if (n - 1 == want)
		return SKP_OK;
	return skp_syntax(st->err, st->line, "'%s' expects %d value(s), found %d", t[0], want, n - 1);
}

/* A float: finite as a float (1e308 is finite only as a double). */
static skp_status parse_float(asf_state *st, const char *key, const char *tok, float *out)
{
	double v;
	if (tok_parse_double(tok, &v) != 0 || isnan(v))
		return skp_syntax(st->err, st->line, "'%s': expected a number, found '%s'", key, tok);
	if (!(fabs(v) <= FLT_MAX))
		return skp_fail(st->err, SKP_ERR_RANGE, st->line, "'%s': value '%s' is beyond a float's range", key, tok);
	*out = (float)v;
	return SKP_OK;
}

static skp_status parse_vec3(asf_state *st, char **t, int n, vec3 *out)
{
	skp_status rc = expect_values(st, t, n, 3);
	if (!rc) rc = parse_float(st, t[0], t[1], &out->x);
	if (!rc) rc = parse_float(st, t[0], t[2], &out->y);
	if (!rc) rc = parse_float(st, t[0], t[3], &out->z);
	return rc;
}

/* Names reach terminals and logs: control characters are refused. */
static skp_status copy_name(asf_state *st, char *dst, size_t cap, const char *src)
{
	size_t n = strlen(src);
	for (size_t i = 0; i < n; i++)
		if ((unsigned char)src[i] < 0x20 || src[i] == 0x7f)
			return skp_syntax(st->err, st->line, "name '%s' holds a control character", src);
	if (n >= cap)
		return skp_fail(st->err, SKP_ERR_LIMIT, st->line,
				"name '%s' is longer than %d characters (board limit SKP_MAX_NAME)",
				src, (int)cap - 1);
	memcpy(dst, src, n + 1);
	return SKP_OK;
}

/* "XYZ", "zyx", ...: a permutation of the three axes, first applied first */
static skp_status parse_axis_order(asf_state *st, const char *tok, uint8_t order[3])
{
	unsigned seen = 0;
	if (strlen(tok) == 3) {
		for (int i = 0; i < 3; i++) {
			int c = (tok[i] | 0x20) - 'x';
			if (c < 0 || c > 2 || (seen & (1u << c)))
				break;
			seen |= 1u << c;
			order[i] = (uint8_t)c;
		}
	}
	if (seen != 7)
		return skp_syntax(st->err, st->line, "axis order: expected a permutation of XYZ, found '%s'", tok);
	return SKP_OK;
}

static int parse_channel(const char *tok)
{
	static const char *names[SKEL_MAX_CHANNELS] = { "rx", "ry", "rz", "tx", "ty", "tz", "l" };
	for (int c = 0; c < SKEL_MAX_CHANNELS; c++)
		if (tok_ieq(tok, names[c]))
			return c;
	return -1;
}

/* `dof` of a bone or `order` of the root: each channel once, any order and case */
static skp_status parse_channels(asf_state *st, char **t, int n, skel_bone *b, int allow_l)
{
	unsigned seen = 0;
	if (n - 1 > (allow_l ? SKEL_MAX_CHANNELS : 6))
		return skp_syntax(st->err, st->line, "'%s': too many channels", t[0]);
	b->channel_count = 0;
	for (int i = 1; i < n; i++) {
		int c = parse_channel(t[i]);
		if (c < 0 || (c == SKEL_L && !allow_l))
			return skp_syntax(st->err, st->line, "'%s': unknown channel '%s' (expected rx ry rz tx ty tz%s)",
				      t[0], t[i], allow_l ? " l" : "");
		if (seen & (1u << c))
			return skp_syntax(st->err, st->line, "'%s': channel '%s' listed twice", t[0], t[i]);
		seen |= 1u << c;
		b->channel[b->channel_count++] = (uint8_t)c;
	}
	return SKP_OK;
}

/* `axis a b c XYZ` (bones) */
static skp_status parse_bone_axis(asf_state *st, char **t, int n, skel_bone *b)
{
	skp_status rc = expect_values(st, t, n, 4);
	if (!rc) rc = parse_float(st, t[0], t[1], &b->axis_angle.x);
	if (!rc) rc = parse_float(st, t[0], t[2], &b->axis_angle.y);
	if (!rc) rc = parse_float(st, t[0], t[3], &b->axis_angle.z);
	if (!rc) rc = parse_axis_order(st, t[4], b->axis_order);
	return rc;
}

static skp_status units_line(asf_state *st, char **t, int n)
{
	skel *s = st->s;
	if (tok_ieq(t[0], "angle")) {
		skp_status rc = expect_values(st, t, n, 1);
		if (rc)
			return rc;
		if (tok_ieq(t[1], "deg") || tok_ieq(t[1], "degrees"))
			s->angle_in_degrees = 1;
		else if (tok_ieq(t[1], "rad") || tok_ieq(t[1], "radians"))
			s->angle_in_degrees = 0;
		else
			return skp_syntax(st->err, st->line, "'angle': expected deg or rad, found '%s'", t[1]);
		return SKP_OK;
	}
	if (tok_ieq(t[0], "length") || tok_ieq(t[0], "mass")) {
		skp_status rc = expect_values(st, t, n, 1);
		float *dst = tok_ieq(t[0], "length") ? &s->length_scale : &s->mass_scale;
		if (!rc) rc = parse_float(st, t[0], t[1], dst);
		if (!rc && !(*dst > 1e-30f && *dst < 1e30f))
			rc = skp_syntax(st->err, st->line, "'%s': expected a positive scale, found '%s'", t[0], t[1]);
		return rc;
	}
	return SKP_OK; /* other units (time, ...) are recorded by nobody */
}

static skp_status root_line(asf_state *st, char **t, int n)
{
	skel_bone *root = &st->s->bone[0];
	if (tok_ieq(t[0], "order"))
		return parse_channels(st, t, n, root, 0);
	if (tok_ieq(t[0], "axis")) {
		skp_status rc = expect_values(st, t, n, 1);
		return rc ? rc : parse_axis_order(st, t[1], root->axis_order);
	}
	if (tok_ieq(t[0], "position"))
		return parse_vec3(st, t, n, &st->s->root_position);
	if (tok_ieq(t[0], "orientation"))
		return parse_vec3(st, t, n, &root->axis_angle);
	return skp_syntax(st->err, st->line, ":root: unknown keyword '%s' (expected order, axis, position or orientation)",
		      t[0]);
}

static skp_status limits_values(asf_state *st, char **t, int n, int first)
{
	skel_bone *b = st->bone;
	for (int i = first; i < n; i++) {
		if (st->limits_left == 0)
			return skp_syntax(st->err, st->line, "bone '%s': more limit values than the %d its dof need",
				      b->name, 2 * b->channel_count);
		/* limits may be unbounded: inf, or beyond a float (the same) */
		double v = 0.0;
		if (tok_parse_double(t[i], &v) != 0 || isnan(v))
			return skp_syntax(st->err, st->line, "'limits': expected a number, found '%s'", t[i]);
		b->limit[st->limit_pos / 2][st->limit_pos % 2] = (float)v;
		st->limit_pos++;
		st->limits_left--;
	}
	return SKP_OK;
}

static skp_status begin_bone(asf_state *st)
{
	skel *s = st->s;
	if (s->count >= SKP_MAX_BONES)
		return skp_fail(st->err, SKP_ERR_LIMIT, st->line,
				"more than %d bones (board limit SKP_MAX_BONES)", SKP_MAX_BONES - 1);
	st->bone = &s->bone[s->count++];
	memset(st->bone, 0, sizeof *st->bone);
	st->bone->axis_order[0] = 0;
	st->bone->axis_order[1] = 1;
	st->bone->axis_order[2] = 2;
	st->bone->parent = -1;
	st->in_block = 1;
	st->limits_left = 0;
	st->limit_pos = 0;
	st->dof_set = 0;
	return SKP_OK;
}

static skp_status end_bone(asf_state *st)
{
	skel_bone *b = st->bone;
	if (st->limits_left)
		return skp_syntax(st->err, st->line, "bone '%s': 'limits' needs %d more value(s)", b->name, st->limits_left);
	if (b->name[0] == '\0')
		return skp_syntax(st->err, st->line, "bone ends without a 'name'");
	for (int i = 0; i < st->s->count - 1; i++)
		if (strcmp(st->s->bone[i].name, b->name) == 0)
			return skp_syntax(st->err, st->line, "bone name '%s' used twice", b->name);
	/* a bone with a length points somewhere: a zero direction would put
	 * its end on its start and turn its children with nothing to turn by */
	if (b->length > 0 && b->direction.x == 0 && b->direction.y == 0 && b->direction.z == 0)
		return skp_syntax(st->err, st->line, "bone '%s': 'direction' is 0 0 0 but 'length' is %g",
				  b->name, (double)b->length);
	st->in_block = 0;
	st->bone = NULL;
	return SKP_OK;
}

static skp_status bone_key(asf_state *st, char **t, int n)
{
	skel_bone *b = st->bone;
	const char *k = t[0];
	if (tok_ieq(k, "id")) {
		skp_status rc = expect_values(st, t, n, 1);
		if (!rc && tok_parse_long(t[1], &b->id) != 0)
			return skp_syntax(st->err, st->line, "'id': expected an integer, found '%s'", t[1]);
		return rc;
	}
	if (tok_ieq(k, "name")) {
		skp_status rc = expect_values(st, t, n, 1);
		if (!rc && tok_ieq(t[1], "root"))
			return skp_syntax(st->err, st->line, "a bone may not be named 'root'");
		return rc ? rc : copy_name(st, b->name, sizeof b->name, t[1]);
	}
	if (tok_ieq(k, "direction"))
		return parse_vec3(st, t, n, &b->direction);
	if (tok_ieq(k, "length")) {
		skp_status rc = expect_values(st, t, n, 1);
		if (!rc) rc = parse_float(st, k, t[1], &b->length);
		if (!rc && !(b->length >= 0.0f && isfinite(b->length)))
			return skp_syntax(st->err, st->line, "'length' must be finite and not negative, found '%s'", t[1]);
		return rc;
	}
	if (tok_ieq(k, "axis"))
		return parse_bone_axis(st, t, n, b);
	if (tok_ieq(k, "dof")) {
		st->dof_set = 1;
		return parse_channels(st, t, n, b, 1);
	}
	if (tok_ieq(k, "limits")) {
		if (!st->dof_set)
			return skp_syntax(st->err, st->line, "bone '%s': 'limits' before 'dof'", b->name);
		b->has_limits = 1;
		st->limits_left = 2 * b->channel_count;
		st->limit_pos = 0;
		return limits_values(st, t, n, 1);
	}
	if (tok_ieq(k, "bodymass") || tok_ieq(k, "cofmass"))
		return SKP_OK; /* optional dynamics data: not used for kinematics */
	return skp_syntax(st->err, st->line, "bone '%s': unknown keyword '%s'", b->name, k);
}

static skp_status bonedata_line(asf_state *st, char **t, int n)
{
	if (!st->in_block) {
		if (tok_ieq(t[0], "begin") && n == 1)
			return begin_bone(st);
		return skp_syntax(st->err, st->line, ":bonedata: expected 'begin', found '%s'", t[0]);
	}
	if (tok_ieq(t[0], "end") && n == 1)
		return end_bone(st);
	double probe;
	if (st->limits_left && tok_parse_double(t[0], &probe) == 0)
		return limits_values(st, t, n, 0);
	if (st->limits_left)
		return skp_syntax(st->err, st->line, "bone '%s': 'limits' needs %d more value(s), found '%s'",
			      st->bone->name, st->limits_left, t[0]);
	return bone_key(st, t, n);
}

static skp_status hierarchy_line(asf_state *st, char **t, int n)
{
	skel *s = st->s;
	if (!st->in_block) {
		if (tok_ieq(t[0], "begin") && n == 1) {
			st->in_block = 1;
			return SKP_OK;
		}
		return skp_syntax(st->err, st->line, ":hierarchy: expected 'begin', found '%s'", t[0]);
	}
	if (tok_ieq(t[0], "end") && n == 1) {
		st->in_block = 0;
		return SKP_OK;
	}
	int parent = skel_find(s, t[0]);
	if (parent < 0)
		return skp_syntax(st->err, st->line, ":hierarchy: unknown bone '%s'", t[0]);
	for (int i = 1; i < n; i++) {
		int child = skel_find(s, t[i]);
		if (child < 0)
			return skp_syntax(st->err, st->line, ":hierarchy: unknown bone '%s'", t[i]);
		if (child == 0)
			return skp_syntax(st->err, st->line, ":hierarchy: the root cannot have a parent");
		if (st->has_parent[child])
			return skp_syntax(st->err, st->line, ":hierarchy: bone '%s' has two parents", t[i]);
		st->has_parent[child] = 1;
		s->bone[child].parent = parent;
	}
	return SKP_OK;
}

static skp_status section_line(asf_state *st, char **t, int n)
{
	skel *s = st->s;
	const char *k = t[0];
	if (st->in_block)
		return skp_syntax(st->err, st->line, "'%s' inside a begin/end block (missing 'end')", k);
	if (tok_ieq(k, ":version")) {
		st->sec = SEC_NONE;
		return n > 1 ? copy_name(st, s->version, sizeof s->version, t[1]) : SKP_OK;
	}
	if (tok_ieq(k, ":name")) {
		st->sec = SEC_NONE;
		return n > 1 ? copy_name(st, s->name, sizeof s->name, t[1]) : SKP_OK;
	}
	if (tok_ieq(k, ":units"))
		st->sec = SEC_UNITS;
	else if (tok_ieq(k, ":documentation"))
		st->sec = SEC_DOC;
	else if (tok_ieq(k, ":root"))
		st->sec = SEC_ROOT, st->root_seen = 1;
	else if (tok_ieq(k, ":bonedata"))
		st->sec = SEC_BONEDATA, st->bonedata_seen = 1;
	else if (tok_ieq(k, ":hierarchy"))
		st->sec = SEC_HIERARCHY, st->hierarchy_seen = 1;
	else
		st->sec = SEC_SKIP; /* :skin and vendor sections do not affect the skeleton */
	return SKP_OK;
}

skp_status asf_line(asf_state *st, char **t, int n)
{
	if (t[0][0] == ':')
		return section_line(st, t, n);
	switch (st->sec) {
	case SEC_UNITS: return units_line(st, t, n);
	case SEC_ROOT: return root_line(st, t, n);
	case SEC_BONEDATA: return bonedata_line(st, t, n);
	case SEC_HIERARCHY: return hierarchy_line(st, t, n);
	case SEC_DOC:
	case SEC_SKIP: return SKP_OK;
	case SEC_NONE: break;
	}
	return skp_syntax(st->err, st->line, "expected a ':' keyword, found '%s'", t[0]);
}
