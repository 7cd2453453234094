#include "asf.h"

#include <math.h>
#include <string.h>

#include "asf_internal.h"
#include "text_tokens.h"

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
		skp_status rc = asf_line(&st, t, n);
		if (rc)
			return rc;
	}
	if (r < 0)
		return (skp_status)-r;
	st.line = tl->line_no;
	return finish(&st);
}
