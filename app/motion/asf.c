#include "asf.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "text_tokens.h"

typedef enum section {
	SEC_NONE, SEC_UNITS, SEC_DOC, SEC_ROOT, SEC_BONEDATA, SEC_HIERARCHY, SEC_SKIP
} section;

typedef struct asf_state {
	skel *s;
	skp_error *err;
	long line;
	section sec;
	int in_block;            /* between begin and end */
	skel_bone *bone;         /* bone being read in :bonedata */
	int limits_left;         /* limit values still expected for `bone` */
	int limit_pos;
	int dof_set;
	int root_seen, bonedata_seen, hierarchy_seen;
	uint8_t has_parent[SKP_MAX_BONES];
} asf_state;

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

static skp_status dispatch(asf_state *st, char **t, int n)
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

quat asf_axis_rotation(vec3 a, const uint8_t order[3])
{
	float ang[3] = { a.x, a.y, a.z };
	quat q = quat_identity();
	for (int i = 0; i < 3; i++)
		q = quat_mul(quat_from_basis_angle(order[i], ang[order[i]]), q);
	return q;
}

/* Parents before children, so FK can run in one pass; fails on a cycle. */
static skp_status order_bones(asf_state *st)
{
	skel *s = st->s;
	uint8_t placed[SKP_MAX_BONES] = { 0 };
	int n = 0;
	s->eval_order[n++] = 0;
	placed[0] = 1;
	while (n < s->count) {
		int progress = 0;
		for (int i = 1; i < s->count; i++) {
			if (!placed[i] && placed[s->bone[i].parent]) {
				placed[i] = 1;
				s->eval_order[n++] = (uint8_t)i;
				progress = 1;
			}
		}
		if (!progress)
			return skp_syntax(st->err, st->line, ":hierarchy: bones form a cycle (detached from root)");
	}
	return SKP_OK;
}

/* Lengths in the file's units divided by :units length: the root position,
 * bone lengths and the limits of translation and `l` channels (the AMC's
 * values get the same factor as they are read). */
static void apply_length_unit(skel *s)
{
	double k = skel_length_factor(s);
	s->root_position = vec3_scale(s->root_position, (float)k);
	for (int i = 0; i < s->count; i++) {
		skel_bone *b = &s->bone[i];
		b->length = (float)(b->length * k);
		for (int c = 0; c < b->channel_count; c++)
			if (b->channel[c] >= SKEL_TX)
				for (int e = 0; e < 2; e++)
					b->limit[c][e] = (float)(b->limit[c][e] * k);
	}
}

/* What forward kinematics cannot represent: a direction that does not
 * normalise, a reach beyond SKEL_MAX_REACH (a length of 3e38, a tiny
 * :units length), so that no pose of the skeleton is NaN. */
static skp_status check_geometry(asf_state *st)
{
	const skel *s = st->s;
	for (int i = 0; i < s->count; i++) {
		const skel_bone *b = &s->bone[i];
		float len = vec3_length(b->direction);
		if (b->length > 0 && !(fabsf(len - 1.0f) < 1e-3f))
			return skp_fail(st->err, SKP_ERR_RANGE, 0, "bone '%s': its direction cannot be normalised", b->name);
	}
	int far = skel_beyond_reach(s);
	if (far >= 0)
		return skp_fail(st->err, SKP_ERR_RANGE, 0,
				"bone '%s': the skeleton reaches beyond %g units there (its position, lengths in :units "
				"length, offsets): not a skeleton forward kinematics can pose", s->bone[far].name,
				SKEL_MAX_REACH);
	return SKP_OK;
}

static skp_status finish(asf_state *st)
{
	skel *s = st->s;
	if (st->in_block)
		return skp_syntax(st->err, st->line, "unexpected end of file: missing 'end'");
	if (!st->root_seen)
		return skp_syntax(st->err, st->line, "no :root section");
	for (int i = 1; i < s->count; i++)
		if (s->bone[i].parent < 0)
			return skp_syntax(st->err, st->line, "bone '%s' has no parent in :hierarchy", s->bone[i].name);
	skp_status rc = order_bones(st);
	if (rc)
		return rc;
	int dof = 0;
	apply_length_unit(s);
	for (int i = 0; i < s->count; i++) {
		skel_bone *b = &s->bone[i];
		b->dof_offset = (uint16_t)dof;
		dof += b->channel_count;
		b->direction = vec3_normalize(b->direction);
		vec3 rad = vec3_make(skel_angle_to_rad(s, b->axis_angle.x),
				     skel_angle_to_rad(s, b->axis_angle.y),
				     skel_angle_to_rad(s, b->axis_angle.z));
		b->axis_rot = asf_axis_rotation(rad, b->axis_order);
	}
	s->dof_count = dof;
	return check_geometry(st);
}

static void init_skel(skel *s)
{
	memset(s, 0, sizeof *s);
	s->length_scale = 1.0f;
	s->mass_scale = 1.0f;
	s->angle_in_degrees = 1;
	s->count = 1;
	skel_bone *root = &s->bone[0];
	memcpy(root->name, "root", 5);
	root->parent = -1;
	root->axis_order[1] = 1;
	root->axis_order[2] = 2;
	/* Acclaim's default root order when none is given */
	static const uint8_t def[6] = { SKEL_TX, SKEL_TY, SKEL_TZ, SKEL_RX, SKEL_RY, SKEL_RZ };
	memcpy(root->channel, def, sizeof def);
	root->channel_count = 6;
}

skp_status asf_parse(skel *out, text_lines *tl, skp_error *err)
{
	asf_state st;
	memset(&st, 0, sizeof st);
	st.s = out;
	st.err = err;
	skp_error_clear(err);
	init_skel(out);

	char *line;
	int r;
	while ((r = text_lines_next(tl, &line, NULL, err)) > 0) {
		st.line = tl->line_no;
		char *t[SKP_MAX_TOKENS];
		int n = tok_split(line, t, SKP_MAX_TOKENS);
		if (n < 0 && (st.sec == SEC_DOC || st.sec == SEC_SKIP) && t[0][0] != ':')
			continue; /* free text may be long: only a ':' keyword ends it */
		if (n < 0)
			return skp_fail(err, SKP_ERR_LIMIT, st.line,
					"more than %d tokens on a line (board limit SKP_MAX_TOKENS)",
					SKP_MAX_TOKENS);
		if (n == 0)
			continue;
		skp_status rc = dispatch(&st, t, n);
		if (rc)
			return rc;
	}
	if (r < 0)
		return (skp_status)-r;
	st.line = tl->line_no;
	return finish(&st);
}
