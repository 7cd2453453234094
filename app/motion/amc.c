#include "amc.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "text_tokens.h"

void amc_open(amc_stream *a, const skel *s, text_lines *tl)
{
	memset(a, 0, sizeof *a);
	a->s = s;
	a->tl = tl;
	a->angle_in_degrees = s->angle_in_degrees;
	a->length_factor = skel_length_factor(s);
	a->pending_number = -1;
	a->hint = 1;
	a->cut_frame = a->cut_line = -1;
}

static int fail(amc_stream *a, skp_error *err, skp_status code, const char *fmt,
		const char *x, long y)
{
	return -(int)skp_fail(err, code, a->tl->line_no, fmt, x, y);
}

static int find_bone(amc_stream *a, const char *name)
{
	const skel *s = a->s;
	if (a->hint < s->count && strcmp(s->bone[a->hint].name, name) == 0)
		return a->hint++;
	int b = skel_find(s, name);
	if (b >= 0)
		a->hint = b + 1;
	return b;
}

/* One token of digits (a sign allowed): a frame number, or -1 when it
 * does not fit (then it is an error, not a bone's name). */
static int is_frame_number(char **t, int n, long *number)
{
	const char *s = t[0] + (t[0][0] == '-' || t[0][0] == '+');
	if (n != 1 || *s < '0' || *s > '9' || strspn(s, "0123456789") != strlen(s))
		return 0;
	return tok_parse_long(t[0], number) == 0 && *number >= -AMC_MAX_FRAME_NUMBER &&
	       *number <= AMC_MAX_FRAME_NUMBER ? 1 : -1;
}

static int count_seen(const amc_stream *a)
{
	int n = 0;
	for (int b = 0; b < a->s->count; b++)
		n += a->seen[b];
	return n;
}

static int bone_line(amc_stream *a, amc_frame *f, char **t, int n, skp_error *err)
{
	int b = find_bone(a, t[0]);
	if (b < 0)
		return fail(a, err, SKP_ERR_SYNTAX, "unknown bone '%s' (not in the skeleton)", t[0], 0);
	const skel_bone *bone = &a->s->bone[b];
	if (a->seen[b])
		return fail(a, err, SKP_ERR_SYNTAX, "bone '%s' appears twice in frame %ld", t[0],
			    f->number);
	a->seen[b] = 1;
	if (n - 1 != bone->channel_count) {
		skp_fail(err, SKP_ERR_SYNTAX, a->tl->line_no, "bone '%s': expected %d value(s), found %d",
			 t[0], bone->channel_count, n - 1);
		return -(int)SKP_ERR_SYNTAX;
	}
	float *dst = &f->value[bone->dof_offset];
	for (int i = 0; i < bone->channel_count; i++) {
		double v;
		if (tok_parse_double(t[i + 1], &v) != 0 || !isfinite(v))
			return fail(a, err, SKP_ERR_SYNTAX, "expected a finite number, found '%s'",
				    t[i + 1], 0);
		int is_angle = bone->channel[i] <= SKEL_RZ;
		if (is_angle && a->angle_in_degrees)
			v *= 3.14159265358979323846 / 180.0;
		else if (!is_angle)
			v *= a->length_factor;
		/* finite as a double, but the frame holds floats; a translation
		 * beyond SKEL_MAX_REACH would take the pose out of float range */
		if (fabs(v) > FLT_MAX)
			return fail(a, err, SKP_ERR_RANGE, "value '%s' is beyond a float's range", t[i + 1], 0);
		if (!is_angle && fabs(v) > SKEL_MAX_REACH)
			return fail(a, err, SKP_ERR_RANGE, "translation '%s' is beyond the skeleton's range (1e9 units)",
				    t[i + 1], 0);
		dst[i] = (float)v;
	}
	return 0;
}

static int header_line(amc_stream *a, char **t, skp_error *err)
{
	if (tok_ieq(t[0], ":DEGREES"))
		a->angle_in_degrees = 1;
	else if (tok_ieq(t[0], ":RADIANS"))
		a->angle_in_degrees = 0;
	else if (t[0][0] != ':')
		return fail(a, err, SKP_ERR_SYNTAX, "expected a frame number, found '%s'", t[0], 0);
	return 0; /* :FULLY-SPECIFIED and vendor keywords change nothing */
}

static void start_frame(amc_stream *a, amc_frame *f)
{
	f->number = a->pending_number;
	f->line = a->pending_line;
	memset(f->value, 0, sizeof f->value[0] * (size_t)a->s->dof_count);
	memset(a->seen, 0, sizeof a->seen);
	a->pending_number = -1;
}

int amc_next(amc_stream *a, amc_frame *f, skp_error *err)
{
	int in_frame = 0;
	char *line;
	int r;

	if (a->at_end)
		return 0;
	if (a->pending_number >= 0) {
		start_frame(a, f);
		in_frame = 1;
	}
	while ((r = text_lines_next(a->tl, &line, NULL, err)) > 0) {
		char *t[SKP_MAX_TOKENS];
		int n = tok_split(line, t, SKP_MAX_TOKENS);
		long number;
		if (n < 0) {
			skp_fail(err, SKP_ERR_LIMIT, a->tl->line_no,
				 "more than %d values on a line (board limit SKP_MAX_TOKENS)",
				 SKP_MAX_TOKENS - 1);
			return -(int)SKP_ERR_LIMIT;
		}
		if (n == 0)
			continue;
		int is_number = is_frame_number(t, n, &number);
		if (is_number < 0)
			return fail(a, err, SKP_ERR_RANGE, "frame number '%s' out of range (at most %ld)", t[0],
				    AMC_MAX_FRAME_NUMBER);
		if (is_number) {
			a->last_bones = count_seen(a);
			a->pending_number = number;
			a->pending_line = a->tl->line_no;
			if (in_frame)
				return 1;
			start_frame(a, f);
			in_frame = 1;
			continue;
		}
		int rc = in_frame ? bone_line(a, f, t, n, err) : header_line(a, t, err);
		if (rc < 0)
			return rc;
	}
	if (r < 0)
		return r;
	a->at_end = 1;
	/* the file ends inside its last frame (a copy cut short): drop that
	 * frame rather than play the missing bones at rest; cut_frame says */
	if (in_frame && a->last_bones > 0 && count_seen(a) < a->last_bones) {
		a->cut_frame = f->number;
		a->cut_line = f->line;
		return 0;
	}
	return in_frame;
}
