#include "encode_segment.h"

#include <stdlib.h>

static void grow(enc_bits *b)
{
	size_t cap = b->cap ? 2 * b->cap : 4096;
	uint8_t *p = realloc(b->buf, cap);
	if (!p) {
		b->failed = 1;
		return;
	}
	b->buf = p;
	b->cap = cap;
}

static void put(enc_bits *b, uint64_t v, int n)
{
	for (int i = 0; i < n; i++) {
		b->acc |= ((v >> i) & 1u) << b->nacc;
		if (++b->nacc == 8) {
			if (b->len == b->cap)
				grow(b);
			if (!b->failed)
				b->buf[b->len++] = (uint8_t)b->acc;
			b->acc = 0;
			b->nacc = 0;
		}
	}
}

static void align(enc_bits *b)
{
	if (b->nacc)
		put(b, 0, 8 - b->nacc);
}

void enc_bits_free(enc_bits *b)
{
	free(b->buf);
	b->buf = NULL;
	b->len = b->cap = 0;
}

static uint32_t zigzag(int64_t r)
{
	return r >= 0 ? (uint32_t)(2 * r) : (uint32_t)(-2 * r - 1);
}

static int64_t residual(const int32_t *q, int dofs, long f, int d, int order)
{
	int64_t a = q[(size_t)f * (size_t)dofs + (size_t)d], p1 = q[(size_t)(f - 1) * (size_t)dofs + (size_t)d];
	if (order == 1)
		return a - p1;
	int64_t p2 = q[(size_t)(f - 2) * (size_t)dofs + (size_t)d];
	if (order == 3)
		return a - (p1 + ((p1 - p2) >> 1));
	return a - 2 * p1 + p2;
}

static int first_raw(int order, int len)
{
	int raw = order > 1 ? 2 : 1;
	return raw < len ? raw : len;
}

/* One residual's Rice code with parameter k (or the escape): its length,
 * and when b is given, its bits. */
static int rice(enc_bits *b, int k, uint32_t z)
{
	int n;
	if ((z >> k) >= CODEC_RICE_ESCAPE) {
		n = CODEC_RICE_ESCAPE + 1 + CODEC_ESCAPE_BITS;
		if (b) {
			put(b, 0, CODEC_RICE_ESCAPE);
			put(b, 1, 1);
			put(b, z, CODEC_ESCAPE_BITS);
		}
	} else {
		n = (int)(z >> k) + 1 + k;
		if (b) {
			put(b, 0, (int)(z >> k));
			put(b, 1, 1);
			put(b, z, k);
		}
	}
	return n;
}

/* Bits the track takes with this predictor and its best starting k (into
 * *k); -1 when the predictor cannot code it (P 0 on a moving track). */
static long cost(const codec_clip *c, const int32_t *q, int dofs, long first, int len, int d, int order, int *k)
{
	const int bits = c->track[d].bits;
	if (order == 0) {
		for (int i = 1; i < len; i++)
			if (q[(size_t)(first + i) * (size_t)dofs + (size_t)d] != q[(size_t)first * (size_t)dofs + (size_t)d])
				return -1;
		*k = 0;
		return 2 + bits;
	}
	const int raw = first_raw(order, len);
	long best = -1;
	for (int kk = 0; kk <= CODEC_MAX_K; kk++) {
		long sum = 2 + 5 + (long)raw * bits;
		for (int i = raw; i < len; i++)
			sum += rice(NULL, kk, zigzag(residual(q, dofs, first + i, d, order)));
		if (best < 0 || sum < best) {
			best = sum;
			*k = kk;
		}
	}
	return best;
}

static void put_value(enc_bits *b, const codec_clip *c, const int32_t *q, int dofs, long f, int i, int d, int order,
		      int k)
{
	if (order == 0 && i > 0)
		return;
	if (i < (order > 1 ? 2 : 1)) {
		put(b, (uint64_t)q[(size_t)f * (size_t)dofs + (size_t)d], c->track[d].bits);
		return;
	}
	rice(b, k, zigzag(residual(q, dofs, f, d, order)));
}

void enc_segment(const codec_clip *c, const int32_t *q, int dofs, long first, int len, enc_bits *out)
{
	uint8_t order[SKP_MAX_DOF], kk[SKP_MAX_DOF];
	for (int d = 0; d < c->tracks; d++) {
		if (!c->track[d].bits)
			continue;
		long best = -1;
		for (int o = 0; o <= 3; o++) {
			int k = 0;
			long b = cost(c, q, dofs, first, len, d, o, &k);
			if (b >= 0 && (best < 0 || b < best)) {
				best = b;
				order[d] = (uint8_t)o;
				kk[d] = (uint8_t)k;
			}
		}
		put(out, order[d], 2);
		if (order[d])
			put(out, kk[d], 5);
	}
	for (int i = 0; i < len; i++)
		for (int d = 0; d < c->tracks; d++)
			if (c->track[d].bits)
				put_value(out, c, q, dofs, first + i, i, d, order[d], kk[d]);
	align(out);
}
