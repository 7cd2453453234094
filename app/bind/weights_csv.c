#include "weights_csv.h"

#include <math.h>

#include "text_tokens.h"

static int is_header(char **t, int n)
{
	return n == 3 && tok_ieq(t[0], "vertex") && tok_ieq(t[1], "bone") &&
	       tok_ieq(t[2], "weight");
}

static skp_status add_row(const skel *s, skin_weights *out, char **t, int n, long line,
			  skp_error *err)
{
	long v;
	double w;
	if (n != 3)
		return skp_fail(err, SKP_ERR_SYNTAX, line, "expected vertex,bone,weight, found %d field(s)", n);
	if (tok_parse_long(t[0], &v) != 0)
		return skp_fail(err, SKP_ERR_SYNTAX, line, "bad vertex index '%s'", t[0]);
	if (v < 0 || v >= out->vert_count)
		return skp_fail(err, SKP_ERR_RANGE, line, "vertex %ld out of range (the mesh has %d)",
				v, out->vert_count);
	int b = skel_find(s, t[1]);
	if (b < 0)
		return skp_fail(err, SKP_ERR_SYNTAX, line, "unknown bone '%s' (not in the skeleton)", t[1]);
	if (tok_parse_double(t[2], &w) != 0 || !isfinite(w))
		return skp_fail(err, SKP_ERR_SYNTAX, line, "bad weight '%s' (not a finite number)", t[2]);
	if (w < 0.0)
		return skp_fail(err, SKP_ERR_RANGE, line, "negative weight %s", t[2]);
	int c = out->count[v];
	for (int k = 0; k < c; k++)
		if (out->bone[v][k] == b)
			return skp_fail(err, SKP_ERR_SYNTAX, line, "vertex %ld lists bone '%s' twice", v, t[1]);
	if (c >= SKP_MAX_INFLUENCES)
		return skp_fail(err, SKP_ERR_LIMIT, line, "vertex %ld has more than %d rows", v,
				SKP_MAX_INFLUENCES);
	out->bone[v][c] = (uint16_t)b;
	out->weight[v][c] = (float)w;
	out->count[v] = (uint8_t)(c + 1);
	return SKP_OK;
}

static skp_status normalise(skin_weights *out, skp_error *err)
{
	for (int v = 0; v < out->vert_count; v++) {
		if (out->count[v] == 0)
			return skp_fail(err, SKP_ERR_RANGE, 0, "vertex %d has no weights", v);
		double sum = 0.0;
		for (int k = 0; k < out->count[v]; k++)
			sum += out->weight[v][k];
		if (!(fabs(sum - 1.0) <= WEIGHTS_CSV_SUM_TOLERANCE))
			return skp_fail(err, SKP_ERR_RANGE, 0,
					"vertex %d: weights sum to %g, not 1 (tolerance %g)", v, sum,
					WEIGHTS_CSV_SUM_TOLERANCE);
		for (int k = 0; k < out->count[v]; k++)
			out->weight[v][k] = (float)(out->weight[v][k] / sum);
	}
	return SKP_OK;
}

skp_status weights_csv_read(text_lines *tl, const skel *s, int vert_count,
			    skin_weights *out, skp_error *err)
{
	if (vert_count < 0 || vert_count > SKP_MAX_VERTS)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "%d vertices: the board takes at most %d",
				vert_count, SKP_MAX_VERTS);
	out->vert_count = vert_count;
	for (int v = 0; v < vert_count; v++)
		out->count[v] = 0;

	char *line, *t[SKP_MAX_TOKENS];
	size_t len;
	int r, header = 0;
	while ((r = text_lines_next(tl, &line, &len, err)) > 0) {
		int n = tok_split(line, t, SKP_MAX_TOKENS);
		if (n == 0)
			continue;
		if (n < 0)
			return skp_fail(err, SKP_ERR_SYNTAX, tl->line_no, "too many fields");
		if (!header) {
			if (!is_header(t, n))
				return skp_fail(err, SKP_ERR_SYNTAX, tl->line_no,
						"expected the header vertex,bone,weight");
			header = 1;
			continue;
		}
		skp_status rc = add_row(s, out, t, n, tl->line_no, err);
		if (rc != SKP_OK)
			return rc;
	}
	if (r < 0)
		return (skp_status)-r;
	if (!header)
		return skp_fail(err, SKP_ERR_SYNTAX, 0, "empty file: expected the header vertex,bone,weight");
	return normalise(out, err);
}
