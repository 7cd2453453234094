/* One half block against a base colour: see tex_encode_etc1_half.h. */
#include "tex_encode_etc1_half.h"

#include <string.h>

#include "tex_etc1.h"

void tex_half_gather(const uint8_t rgb[48], int flip, int half, half_pixels *hp)
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

/* See tex_encode_etc1_half.h. */
void tex_half_fit(const half_pixels *hp, const int base[3], int bits, int first_table,
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
