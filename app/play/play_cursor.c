#include "play_cursor.h"

#include <math.h>
#include <string.h>

#include "play_blend.h"

/* Reads the next frame into *into (NULL: decoded and dropped): 1, 0 at
 * the end (the clip's last index lowered to what was read), or an error. */
static int read_frame(play_cursor *c, skel_local *into, long *number, skp_error *err)
{
	int r = c->src.next(c->src.ctx, &c->frame, err);
	if (r < 0)
		return r;
	if (r == 0) {
		if (c->next - 1 < c->last)
			c->last = c->next - 1;
		return 0;
	}
	c->next++;
	if (into)
		fk_local(c->s, c->frame.value, into);
	*number = c->frame.number;
	return 1;
}

static skp_status seek_to(play_cursor *c, long index, skp_error *err)
{
	c->ia = -1;
	c->have_b = 0;
	skp_status st = c->src.seek(c->src.ctx, index, err);
	if (st == SKP_OK)
		c->next = index;
	return st;
}

/* Frame i into a, read forward from where the source is (seeking back, or
 * far ahead where that is cheap). */
static skp_status move_a(play_cursor *c, long i, skp_error *err)
{
	if (c->have_b && c->ia + 1 == i) {
		c->a = c->b;
		c->number_a = c->number_b;
		c->ia = i;
		c->have_b = 0;
		return SKP_OK;
	}
	if (i < c->next || (c->src.seeks_fast && i > c->next + 1)) {
		skp_status st = seek_to(c, i, err);
		if (st != SKP_OK)
			return st;
	}
	while (c->next <= i) {
		int r = read_frame(c, c->next == i ? &c->a : NULL, &c->number_a, err);
		if (r < 0)
			return (skp_status)r;
		if (r == 0 && c->last < 0)
			return skp_fail(err, SKP_ERR_RANGE, 0, "the clip has no frames");
		if (r == 0)
			return move_a(c, c->last, err); /* it ended before i: back to its last */
	}
	c->ia = i;
	c->have_b = 0;
	return SKP_OK;
}

/* The window at frame i: a = i, b = i + 1 when the clip has it. */
static skp_status fill(play_cursor *c, long i, skp_error *err)
{
	if (c->ia != i) {
		skp_status st = move_a(c, i, err);
		if (st != SKP_OK)
			return st;
	}
	if (!c->have_b && c->ia < c->last) {
		int r = read_frame(c, &c->b, &c->number_b, err);
		if (r < 0)
			return (skp_status)r;
		c->have_b = r == 1;
	}
	return SKP_OK;
}

skp_status play_cursor_open(play_cursor *c, const skel *s, const play_source *src, skp_error *err)
{
	c->s = s;
	c->src = *src;
	c->last = src->frames - 1;
	skp_error_clear(err);
	if (src->frames < 1 || !(src->rate > 0.0))
		return skp_fail(err, SKP_ERR_RANGE, 0, "a clip needs frames and a frame rate (%ld frames at %g Hz)",
				src->frames, src->rate);
	skp_status st = seek_to(c, 0, err);
	return st != SKP_OK ? st : fill(c, 0, err);
}

skp_status play_cursor_sample(play_cursor *c, double x, skel_local *out, long *number, skp_error *err)
{
	if (!(x > 0.0))
		x = 0.0;
	long i = (long)floor(x);
	if (i >= c->last)
		i = c->last;
	skp_status st = fill(c, i, err);
	if (st == SKP_OK)
		i = c->ia; /* i, or the last frame of a clip that ended early */
	double frac = x - (double)i;
	if (st == SKP_OK && c->have_b && frac > 0.0)
		play_blend(c->s, &c->a, &c->b, (float)frac, out);
	else
		*out = c->a;
	*number = c->number_a;
	return st;
}
