/* The ETC1 block search: see tex_encode_etc1.h. */
#include "tex_encode_etc1.h"

#include <stdint.h>
#include <string.h>

#include "tex_encode_etc1_half.h"
#include "tex_etc1.h"

/* Base colours tried around a half's mean: -1, 0, +1 steps a channel. */
#define NEIGHBOURS 27

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

static int base_in_range(const int base[3], int top)
{
	for (int c = 0; c < 3; c++)
		if (base[c] < 0 || base[c] > top)
			return 0;
	return 1;
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
	tex_half_fit(hp, q, bits, 0, UINT32_MAX, &fits[13]);
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
		if (!base_in_range(base, top))
			continue;
		tex_half_fit(hp, base, bits, table, bound, &fits[n]);
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
	tex_half_fit(other, q, 5, 0, UINT32_MAX, fit);
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
			tex_half_fit(&hp[h], q[h], bits, 0, UINT32_MAX, &fit[h]);
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
		tex_half_gather(rgb, flip, 0, &halves[flip][0]);
		tex_half_gather(rgb, flip, 1, &halves[flip][1]);
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
