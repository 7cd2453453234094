/* The ETC1 block search: see tex_encode_etc1.h. */
#include "tex_encode_etc1.h"

#include <stdint.h>
#include <string.h>

#include "tex_etc1.h"

/* Base colours tried around a half's mean: -1, 0, +1 steps a channel. */
#define NEIGHBOURS 27

/* The 8 pixels of one half and where each sits in the block (y * 4 + x). */
typedef struct half_pixels {
	int rgb[8][3];
	int pos[8];
} half_pixels;

/* A half encoded with one base colour (in the stored precision). */
typedef struct half_fit {
	uint32_t error;
	uint8_t base[3];
	uint8_t table;
	uint8_t index[8];
} half_fit;

static void gather_half(const uint8_t rgb[48], int flip, int half, half_pixels *hp)
{
	int n = 0;
	for (int y = 0; y < 4; y++)
		for (int x = 0; x < 4; x++) {
			if (tex_etc1_in_second_half(flip, x, y) != half)
				continue;
			for (int c = 0; c < 3; c++)
				hp->rgb[n][c] = rgb[(y * 4 + x) * 3 + c];
			hp->pos[n++] = y * 4 + x;
		}
}

static int clamp255(int v)
{
	return v < 0 ? 0 : v > 255 ? 255 : v;
}

/* Squared error of the half with one colour and table, each pixel on its
 * nearest modifier (into index). Stops once it reaches bound: the caller
 * only wants to know that it is no better. */
static uint32_t fit_table(const half_pixels *hp, const int colour[3], int table,
			  uint32_t bound, uint8_t index[8])
{
	int level[4][3];
	for (int k = 0; k < 4; k++)
		for (int c = 0; c < 3; c++)
			level[k][c] = clamp255(colour[c] + tex_etc1_modifier[table][k]);
	uint32_t total = 0;
	for (int i = 0; i < 8 && total < bound; i++) {
		uint32_t best = UINT32_MAX;
		for (int k = 0; k < 4; k++) {
			int dr = level[k][0] - hp->rgb[i][0];
			int dg = level[k][1] - hp->rgb[i][1];
			int db = level[k][2] - hp->rgb[i][2];
			uint32_t e = (uint32_t)(dr * dr + dg * dg + db * db);
			if (e < best) {
				best = e;
				index[i] = (uint8_t)k;
			}
		}
		total += best;
	}
	return total;
}

/* What a half's error against one colour needs, whatever the table, for
 * the tables under which no channel clamps: per pixel the sum over the
 * channels of pixel - colour, and the squared distance. */
typedef struct half_offsets {
	int sum[8];
	int dist[8];
	int spare; /* how far the colour's channels are from 0 and 255, the least */
} half_offsets;

static void offsets_of(const half_pixels *hp, const int colour[3], half_offsets *o)
{
	o->spare = 255;
	for (int c = 0; c < 3; c++) {
		int room = colour[c] < 255 - colour[c] ? colour[c] : 255 - colour[c];
		o->spare = room < o->spare ? room : o->spare;
	}
	for (int i = 0; i < 8; i++) {
		o->sum[i] = o->dist[i] = 0;
		for (int c = 0; c < 3; c++) {
			int d = hp->rgb[i][c] - colour[c];
			o->sum[i] += d;
			o->dist[i] += d * d;
		}
	}
}

/* fit_table's error and indices, the same to the bit, for a table whose
 * levels do not clamp: then a pixel's error with modifier m is
 * dist - 2 m sum + 3 m^2, so the sign of sum picks +m or -m, and
 * 2 |sum| > 3 (a + b) the large modifier b over the small a. */
static uint32_t fit_table_unclamped(const half_offsets *o, int table, uint32_t bound, uint8_t index[8])
{
	int a = tex_etc1_modifier[table][0], b = tex_etc1_modifier[table][1];
	uint32_t total = 0;
	for (int i = 0; i < 8 && total < bound; i++) {
		int negative = o->sum[i] < 0;
		int size = negative ? -o->sum[i] : o->sum[i];
		int large = 2 * size > 3 * (a + b);
		int m = large ? b : a;
		total += (uint32_t)(o->dist[i] + 3 * m * m - 2 * m * size);
		index[i] = (uint8_t)(negative << 1 | large);
	}
	return total;
}

static int expand(int v, int bits)
{
	return bits == 4 ? tex_etc1_expand4(v) : tex_etc1_expand5(v);
}

/* The best table for a stored base colour; fit->error is UINT32_MAX when
 * none beats bound. Table first_table is tried first: a neighbour's best
 * table is usually this colour's too, and the bound it sets at once cuts
 * the other tables short after a pixel or two. */
static void fit_base(const half_pixels *hp, const int base[3], int bits, int first_table,
		     uint32_t bound, half_fit *fit)
{
	int colour[3];
	uint8_t index[8];
	for (int c = 0; c < 3; c++) {
		colour[c] = expand(base[c], bits);
		fit->base[c] = (uint8_t)base[c];
	}
	half_offsets o;
	offsets_of(hp, colour, &o);
	fit->error = UINT32_MAX;
	for (int k = 0; k <= 8; k++) {
		int t = k == 0 ? first_table : k - 1;
		if (k > 0 && t == first_table)
			continue;
		uint32_t e = tex_etc1_modifier[t][1] <= o.spare ? fit_table_unclamped(&o, t, bound, index)
								: fit_table(hp, colour, t, bound, index);
		if (e < bound && e < fit->error) {
			fit->error = bound = e;
			fit->table = (uint8_t)t;
			memcpy(fit->index, index, sizeof index);
		}
	}
}

/* The stored value whose expansion is nearest to the half's mean. */
static void quantised_mean(const half_pixels *hp, int bits, int q[3])
{
	int top = (1 << bits) - 1;
	for (int c = 0; c < 3; c++) {
		int sum = 0;
		for (int i = 0; i < 8; i++)
			sum += hp->rgb[i][c];
		q[c] = (sum * top + 8 * 255 / 2) / (8 * 255);
	}
}

/* Every base colour within a step of the mean (NEIGHBOURS of them), each
 * with its best table; those off the range, or no better than bound (the
 * block's best so far: a half that alone costs as much cannot be part of
 * a better block), are left at UINT32_MAX. With shrink set, bound drops to
 * each better fit found, for a caller that wants the best one only. */
static void fit_neighbours(const half_pixels *hp, int bits, uint32_t bound, int shrink,
			   half_fit fits[NEIGHBOURS])
{
	int q[3], top = (1 << bits) - 1, table = 0;
	quantised_mean(hp, bits, q);
	/* the mean itself first (n = 13: no step), for the table it likes */
	fit_base(hp, q, bits, 0, UINT32_MAX, &fits[13]);
	table = fits[13].table;
	if (fits[13].error >= bound)
		fits[13].error = UINT32_MAX;
	else if (shrink)
		bound = fits[13].error;
	for (int n = 0; n < NEIGHBOURS; n++) {
		int base[3] = { q[0] + n % 3 - 1, q[1] + n / 3 % 3 - 1, q[2] + n / 9 - 1 };
		if (n == 13)
			continue;
		fits[n].error = UINT32_MAX;
		if (base[0] < 0 || base[1] < 0 || base[2] < 0 || base[0] > top || base[1] > top || base[2] > top)
			continue;
		fit_base(hp, base, bits, table, bound, &fits[n]);
		if (shrink && fits[n].error < bound)
			bound = fits[n].error;
	}
}

static const half_fit *best_fit(const half_fit fits[NEIGHBOURS])
{
	const half_fit *best = &fits[0];
	for (int n = 1; n < NEIGHBOURS; n++)
		if (fits[n].error < best->error)
			best = &fits[n];
	return best;
}

static int delta_allowed(const uint8_t a[3], const uint8_t b[3])
{
	for (int c = 0; c < 3; c++) {
		int d = b[c] - a[c];
		if (d < -4 || d > 3)
			return 0;
	}
	return 1;
}

/* The other half's best base within the delta's reach of anchor (its mean
 * pulled into anchor - 4 .. anchor + 3), for halves too far apart for any
 * pair of neighbours. sign: +1 when other is half 1, -1 when half 0. */
static void fit_reaching(const half_pixels *other, const uint8_t anchor[3], int sign, half_fit *fit)
{
	int q[3];
	quantised_mean(other, 5, q);
	for (int c = 0; c < 3; c++) {
		int lo = sign > 0 ? anchor[c] - 4 : anchor[c] - 3;
		int hi = sign > 0 ? anchor[c] + 3 : anchor[c] + 4;
		lo = lo < 0 ? 0 : lo;
		hi = hi > 31 ? 31 : hi;
		q[c] = q[c] < lo ? lo : q[c] > hi ? hi : q[c];
	}
	fit_base(other, q, 5, 0, UINT32_MAX, fit);
}

typedef struct block_choice {
	uint32_t error;
	tex_etc1_fields fields;
} block_choice;

static void choose(block_choice *best, int differential, int flip, const half_pixels hp[2],
		   const half_fit *a, const half_fit *b)
{
	if (a->error == UINT32_MAX || b->error == UINT32_MAX || a->error + b->error >= best->error)
		return;
	tex_etc1_fields *f = &best->fields;
	best->error = a->error + b->error;
	f->differential = (uint8_t)differential;
	f->flip = (uint8_t)flip;
	const half_fit *fit[2] = { a, b };
	for (int h = 0; h < 2; h++) {
		memcpy(f->base[h], fit[h]->base, 3);
		f->table[h] = fit[h]->table;
		for (int i = 0; i < 8; i++)
			f->index[hp[h].pos[i]] = fit[h]->index[i];
	}
}

static void try_differential(block_choice *best, int flip, const half_pixels hp[2])
{
	half_fit fits[2][NEIGHBOURS], reach;
	fit_neighbours(&hp[0], 5, best->error, 0, fits[0]);
	fit_neighbours(&hp[1], 5, best->error, 0, fits[1]);
	for (int i = 0; i < NEIGHBOURS; i++)
		for (int j = 0; j < NEIGHBOURS; j++)
			if (fits[0][i].error != UINT32_MAX && fits[1][j].error != UINT32_MAX &&
			    delta_allowed(fits[0][i].base, fits[1][j].base))
				choose(best, 1, flip, hp, &fits[0][i], &fits[1][j]);
	const half_fit *b0 = best_fit(fits[0]), *b1 = best_fit(fits[1]);
	if (b0->error == UINT32_MAX || b1->error == UINT32_MAX)
		return;
	fit_reaching(&hp[1], b0->base, +1, &reach);
	choose(best, 1, flip, hp, b0, &reach);
	fit_reaching(&hp[0], b1->base, -1, &reach);
	choose(best, 1, flip, hp, &reach, b1);
}

static void try_individual(block_choice *best, int flip, const half_pixels hp[2])
{
	half_fit fits[2][NEIGHBOURS];
	fit_neighbours(&hp[0], 4, best->error, 1, fits[0]);
	fit_neighbours(&hp[1], 4, best->error, 1, fits[1]);
	choose(best, 0, flip, hp, best_fit(fits[0]), best_fit(fits[1]));
}

/* Each mode's block from the halves' means alone: a good block found
 * cheaply, whose error bounds the searches that follow from the start. */
static void try_means(block_choice *best, int flip, const half_pixels hp[2])
{
	half_fit fit[2];
	for (int bits = 4; bits <= 5; bits++) {
		int q[2][3];
		for (int h = 0; h < 2; h++) {
			quantised_mean(&hp[h], bits, q[h]);
			fit_base(&hp[h], q[h], bits, 0, UINT32_MAX, &fit[h]);
		}
		if (bits == 4 || delta_allowed(fit[0].base, fit[1].base)) {
			choose(best, bits == 5, flip, hp, &fit[0], &fit[1]);
		} else {
			fit_reaching(&hp[1], fit[0].base, +1, &fit[1]);
			choose(best, 1, flip, hp, &fit[0], &fit[1]);
		}
	}
}

uint32_t tex_encode_etc1_block(const uint8_t rgb[4 * 4 * 3], uint8_t block[TEX_ETC1_BLOCK_BYTES])
{
	block_choice best;
	memset(&best, 0, sizeof best);
	best.error = UINT32_MAX;
	half_pixels halves[2][2];
	for (int flip = 0; flip < 2; flip++) {
		gather_half(rgb, flip, 0, &halves[flip][0]);
		gather_half(rgb, flip, 1, &halves[flip][1]);
		try_means(&best, flip, halves[flip]);
	}
	for (int flip = 0; flip < 2; flip++) {
		try_individual(&best, flip, halves[flip]);
		try_differential(&best, flip, halves[flip]);
	}
	/* every field was chosen within its range: packing cannot fail */
	(void)tex_etc1_pack(&best.fields, block);
	return best.error;
}
