#include "bvh.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "text_tokens.h"

/* A joint as the HIERARCHY gives it, before it becomes a bone. */
typedef struct bvh_joint {
	int parent;
	int first_child;         /* -1: none */
	vec3 offset;
	vec3 end;                /* End Site OFFSET, when has_end */
	int has_end;
	uint8_t nch;
	uint8_t ch[6];           /* file order: 0..2 X Y Z position, 3..5 X Y Z rotation */
} bvh_joint;

typedef struct bvh_state {
	text_lines *tl;
	skp_error *err;
	char *tok[SKP_MAX_TOKENS];
	int ntok, itok;
	skel *s;
	bvh_layout *lay;
	int count;
	bvh_joint j[SKP_MAX_BONES];
} bvh_state;

static long line_of(const bvh_state *st)
{
	return st->tl->line_no;
}

/* The next token of the hierarchy, across lines; NULL at the end (err set
 * when the reader failed). */
static const char *next_tok(bvh_state *st, skp_status *rc)
{
	char *line;
	*rc = SKP_OK;
	while (st->itok == st->ntok) {
		int r = text_lines_next(st->tl, &line, NULL, st->err);
		if (r <= 0) {
			*rc = r < 0 ? (skp_status)-r : skp_syntax(st->err, line_of(st), "unexpected end of file in the HIERARCHY");
			return NULL;
		}
		st->ntok = tok_split(line, st->tok, SKP_MAX_TOKENS);
		st->itok = 0;
		if (st->ntok < 0) {
			*rc = skp_fail(st->err, SKP_ERR_LIMIT, line_of(st), "more than %d words on a line (board limit SKP_MAX_TOKENS)",
				       SKP_MAX_TOKENS - 1);
			return NULL;
		}
	}
	return st->tok[st->itok++];
}

static skp_status expect(bvh_state *st, const char *word)
{
	skp_status rc;
	const char *t = next_tok(st, &rc);
	if (!t && rc == SKP_ERR_SYNTAX)
		return skp_syntax(st->err, line_of(st), "unexpected end of file: expected '%s'", word);
	if (!t)
		return rc;
	return tok_ieq(t, word) ? SKP_OK : skp_syntax(st->err, line_of(st), "expected '%s', found '%s'", word, t);
}

static skp_status number(bvh_state *st, const char *what, double *v)
{
	skp_status rc;
	const char *t = next_tok(st, &rc);
	if (!t)
		return rc;
	if (tok_parse_double(t, v) != 0 || !isfinite(*v) || fabs(*v) > FLT_MAX)
		return skp_syntax(st->err, line_of(st), "%s: expected a finite number, found '%s'", what, t);
	return SKP_OK;
}

static skp_status read_vec3(bvh_state *st, vec3 *v)
{
	double x = 0, y = 0, z = 0;
	skp_status rc = number(st, "OFFSET", &x);
	if (!rc) rc = number(st, "OFFSET", &y);
	if (!rc) rc = number(st, "OFFSET", &z);
	*v = vec3_make((float)x, (float)y, (float)z);
	return rc;
}

static int channel_kind(const char *name)
{
	static const char *const names[6] = { "Xposition", "Yposition", "Zposition",
					      "Xrotation", "Yrotation", "Zrotation" };
	for (int i = 0; i < 6; i++)
		if (tok_ieq(name, names[i]))
			return i;
	return -1;
}

static skp_status read_channels(bvh_state *st, bvh_joint *j)
{
	double n;
	skp_status rc = number(st, "CHANNELS", &n);
	if (rc)
		return rc;
	if (!(n >= 0 && n <= 6 && n == floor(n)))
		return skp_syntax(st->err, line_of(st), "CHANNELS: expected a count from 0 to 6, found %g", n);
	j->nch = (uint8_t)n;
	unsigned seen = 0;
	for (int i = 0; i < j->nch; i++) {
		const char *t = next_tok(st, &rc);
		if (!t)
			return rc;
		int k = channel_kind(t);
		if (k < 0)
			return skp_syntax(st->err, line_of(st), "unknown channel '%s' (expected X/Y/Z position or rotation)", t);
		if (seen & (1u << k))
			return skp_syntax(st->err, line_of(st), "channel '%s' listed twice", t);
		seen |= 1u << k;
		j->ch[i] = (uint8_t)k;
	}
	return SKP_OK;
}

static skp_status read_end_site(bvh_state *st, bvh_joint *j)
{
	skp_status rc = expect(st, "Site");
	if (!rc) rc = expect(st, "{");
	if (!rc) rc = expect(st, "OFFSET");
	if (!rc) rc = read_vec3(st, &j->end);
	if (!rc) rc = expect(st, "}");
	j->has_end = 1;
	return rc;
}

static skp_status read_joint(bvh_state *st, int parent);

/* The body of joint i, after its name: { OFFSET ... CHANNELS ... children } */
static skp_status read_body(bvh_state *st, int i)
{
	skp_status rc = expect(st, "{");
	int has_offset = 0;
	while (!rc) {
		const char *t = next_tok(st, &rc);
		if (!t)
			return rc;
		if (tok_ieq(t, "}"))
			return has_offset ? SKP_OK : skp_syntax(st->err, line_of(st), "joint '%s' has no OFFSET",
								 st->s->bone[i].name);
		if (tok_ieq(t, "OFFSET")) {
			rc = read_vec3(st, &st->j[i].offset);
			has_offset = 1;
		} else if (tok_ieq(t, "CHANNELS")) {
			rc = read_channels(st, &st->j[i]);
		} else if (tok_ieq(t, "JOINT")) {
			rc = read_joint(st, i);
		} else if (tok_ieq(t, "End")) {
			rc = read_end_site(st, &st->j[i]);
		} else {
			rc = skp_syntax(st->err, line_of(st), "joint '%s': expected OFFSET, CHANNELS, JOINT, End Site or '}', found '%s'",
					st->s->bone[i].name, t);
		}
	}
	return rc;
}

static skp_status read_joint(bvh_state *st, int parent)
{
	skp_status rc;
	const char *name = next_tok(st, &rc);
	if (!name)
		return rc;
	if (st->count >= SKP_MAX_BONES)
		return skp_fail(st->err, SKP_ERR_LIMIT, line_of(st), "more than %d joints (board limit SKP_MAX_BONES)",
				SKP_MAX_BONES);
	if (strlen(name) >= SKP_MAX_NAME)
		return skp_fail(st->err, SKP_ERR_LIMIT, line_of(st), "joint name '%s' longer than %d (board limit SKP_MAX_NAME)",
				name, SKP_MAX_NAME - 1);
	for (const char *c = name; *c; c++)
		if ((unsigned char)*c < 0x20 || *c == 0x7f)
			return skp_syntax(st->err, line_of(st), "joint name '%s': expected letters, digits or "
					  "punctuation, found a control character", name);
	if (skel_find(st->s, name) >= 0 && st->count > 0)
		return skp_syntax(st->err, line_of(st), "joint name '%s' used twice", name);
	int i = st->count++;
	st->s->count = st->count;
	memset(&st->j[i], 0, sizeof st->j[i]);
	st->j[i].parent = parent;
	st->j[i].first_child = -1;
	strcpy(st->s->bone[i].name, name);
	if (parent >= 0 && st->j[parent].first_child < 0)
		st->j[parent].first_child = i;
	return read_body(st, i);
}

static skp_status read_motion_header(bvh_state *st)
{
	double frames = 0, dt = 0;
	skp_status rc = expect(st, "MOTION");
	if (!rc) rc = expect(st, "Frames:");
	if (!rc) rc = number(st, "Frames:", &frames);
	if (!rc && (frames < 0 || frames != floor(frames) || frames > 2147483647.0))
		rc = skp_syntax(st->err, line_of(st), "Frames: expected a whole count, found %g", frames);
	if (!rc) rc = expect(st, "Frame");
	if (!rc) rc = expect(st, "Time:");
	if (!rc) rc = number(st, "Frame Time:", &dt);
	if (!rc && !(dt >= BVH_MIN_FRAME_TIME && dt <= BVH_MAX_FRAME_TIME))
		rc = skp_syntax(st->err, line_of(st), "Frame Time: expected seconds per frame from 0.000001 to 10, found %g",
				dt);
	if (!rc && st->itok != st->ntok)
		rc = skp_syntax(st->err, line_of(st), "unexpected '%s' after Frame Time", st->tok[st->itok]);
	if (rc)
		return rc;
	st->lay->frames = (long)frames;
	st->lay->frame_time = dt;
	return SKP_OK;
}

/* A bone's segment: to the first child joint, else to the End Site. */
static vec3 segment(const bvh_state *st, int i)
{
	const bvh_joint *j = &st->j[i];
	if (j->first_child >= 0)
		return st->j[j->first_child].offset;
	return j->has_end ? j->end : vec3_make(0, 0, 0);
}

/* Skel channels: positions in file order, then rotations in reverse file
 * order (BVH's Z X Y is Rz Rx Ry: Y applies first, and skel applies its
 * first channel first). */
static void place_channels(bvh_state *st, int i, int *dof)
{
	static const uint8_t skel_ch[6] = { SKEL_TX, SKEL_TY, SKEL_TZ, SKEL_RX, SKEL_RY, SKEL_RZ };
	bvh_joint *j = &st->j[i];
	skel_bone *b = &st->s->bone[i];
	bvh_layout *lay = st->lay;
	int file_base = *dof, n = 0;
	b->dof_offset = (uint16_t)*dof;
	float off[3] = { j->offset.x, j->offset.y, j->offset.z };
	for (int pass = 0; pass < 2; pass++)
		for (int k = 0; k < j->nch; k++) {
			int f = pass ? j->nch - 1 - k : k;   /* rotations reversed */
			int kind = j->ch[f];
			if ((kind >= 3) != pass)
				continue;
			b->channel[n] = skel_ch[kind];
			lay->dof[file_base + f] = (uint16_t)(*dof + n);
			lay->rotation[file_base + f] = (uint8_t)(kind >= 3);
			lay->minus[file_base + f] = kind < 3 ? off[kind] : 0.0f;
			n++;
		}
	b->channel_count = j->nch;
	*dof += j->nch;
}

static void build_skel(bvh_state *st)
{
	skel *s = st->s;
	int dof = 0;
	for (int i = 0; i < st->count; i++) {
		skel_bone *b = &s->bone[i];
		const bvh_joint *j = &st->j[i];
		vec3 v = i == 0 ? vec3_make(0, 0, 0) : segment(st, i);
		b->id = i;
		b->parent = j->parent;
		b->length = vec3_length(v);
		b->direction = b->length > 0 ? vec3_scale(v, 1.0f / b->length) : vec3_make(0, 0, 0);
		b->offset = i == 0 ? vec3_make(0, 0, 0)
			  : vec3_sub(j->offset, j->parent == 0 ? vec3_make(0, 0, 0) : segment(st, j->parent));
		b->axis_angle = vec3_make(0, 0, 0);
		b->axis_rot = quat_identity();
		for (int a = 0; a < 3; a++)
			b->axis_order[a] = (uint8_t)a;
		place_channels(st, i, &dof);
		s->eval_order[i] = (uint8_t)i;
	}
	s->root_position = st->j[0].offset;
	s->dof_count = dof;
	st->lay->channels = dof;
}

skp_status bvh_parse(skel *s, bvh_layout *layout, text_lines *tl, skp_error *err)
{
	static bvh_state st; /* 6 KB: kept off the stack of small boards */
	memset(&st, 0, sizeof st);
	memset(s, 0, sizeof *s);
	memset(layout, 0, sizeof *layout);
	skp_error_clear(err);
	st.tl = tl;
	st.err = err;
	st.s = s;
	st.lay = layout;
	s->length_scale = s->mass_scale = 1.0f;
	s->angle_in_degrees = 1;
	strcpy(s->name, "bvh");
	strcpy(s->version, "bvh");
	skp_status rc = expect(&st, "HIERARCHY");
	if (!rc) rc = expect(&st, "ROOT");
	if (!rc) rc = read_joint(&st, -1);
	if (!rc) rc = read_motion_header(&st);
	if (rc)
		return rc;
	build_skel(&st);
	/* OFFSETs in float range can still add up past what a pose holds */
	int far = skel_beyond_reach(s);
	if (far >= 0)
		return skp_fail(err, SKP_ERR_RANGE, 0,
				"joint '%s': the skeleton reaches beyond %g units there (OFFSETs): not a skeleton forward "
				"kinematics can pose", s->bone[far].name, SKEL_MAX_REACH);
	return SKP_OK;
}

void bvh_open(bvh_stream *b, const skel *s, const bvh_layout *layout, text_lines *tl)
{
	memset(b, 0, sizeof *b);
	b->s = s;
	b->layout = layout;
	b->tl = tl;
}

/* The frame line's numbers, in place (the line is the reader's buffer). */
static int frame_values(bvh_stream *b, char *line, amc_frame *f, skp_error *err)
{
	const bvh_layout *lay = b->layout;
	int n = 0;
	char *p = line;
	for (;;) {
		while (*p == ' ' || *p == '\t' || *p == '\v' || *p == '\f')
			p++;
		if (!*p)
			break;
		char *start = p;
		while (*p && *p != ' ' && *p != '\t' && *p != '\v' && *p != '\f')
			p++;
		char keep = *p;
		*p = '\0';
		double v;
		if (n >= lay->channels)
			return -(int)skp_syntax(err, b->tl->line_no, "frame %ld: more than the %d values of the HIERARCHY",
						b->next + 1, lay->channels);
		if (tok_parse_double(start, &v) != 0 || !isfinite(v))
			return -(int)skp_syntax(err, b->tl->line_no, "frame %ld: expected a finite number, found '%s'",
						b->next + 1, start);
		v = lay->rotation[n] ? v * (3.14159265358979323846 / 180.0) : v - lay->minus[n];
		if (fabs(v) > (lay->rotation[n] ? FLT_MAX : SKEL_MAX_REACH))
			return -(int)skp_fail(err, SKP_ERR_RANGE, b->tl->line_no, "value '%s' is beyond %s", start,
					      lay->rotation[n] ? "a float's range" : "the skeleton's range (1e9 units)");
		f->value[lay->dof[n++]] = (float)v;
		*p = keep;
	}
	if (n < lay->channels)
		return -(int)skp_syntax(err, b->tl->line_no, "frame %ld: expected %d values, found %d", b->next + 1,
					lay->channels, n);
	return 1;
}

int bvh_next(bvh_stream *b, amc_frame *f, skp_error *err)
{
	char *line;
	size_t len;
	if (b->next >= b->layout->frames)
		return 0;
	for (;;) {
		int r = text_lines_next(b->tl, &line, &len, err);
		if (r < 0)
			return r;
		if (r == 0) {
			b->cut_frames = b->layout->frames - b->next;
			return 0;
		}
		if (strspn(line, " \t\v\f") != len)
			break;
	}
	memset(f->value, 0, sizeof f->value[0] * (size_t)b->s->dof_count);
	int r = frame_values(b, line, f, err);
	if (r < 0)
		return r;
	f->number = ++b->next;
	f->line = b->tl->line_no;
	return 1;
}

int bvh_is_path(const char *path)
{
	size_t n = strlen(path);
	return n >= 4 && tok_ieq(path + n - 4, ".bvh");
}
