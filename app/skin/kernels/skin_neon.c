/* NEON kernels (AArch64, e.g. the Raspberry Pi 4's Cortex-A72), over the
 * float and the compact vertex streams: 4 vertices per step, two steps per
 * SKIN_LANES block. As in the AVX2 kernels, the blends run per vertex (its
 * bones' rows, loaded whole, times one lane of its weights: NEON multiplies
 * by a lane, so the weights need no broadcast) and a transpose per four
 * values turns four vertices' blends into lanes for the transform, where
 * gathering each value into lanes cost three times the instructions. A
 * step first loads its batch (bones, weights, position, normal) from either
 * stream form, then the same arithmetic runs; everything is inlined into
 * the four kernels so that the choices fold away. Built when the board
 * sets SIMD=neon; results match skin_scalar.c and skin_compact_scalar.c to
 * float rounding (FMA). The fixed-point kernel is skin_fixed_neon.c. */
#include "skin_kernels.h"

#if defined(SKP_SIMD_NEON) && defined(__aarch64__)

#include "skin_neon.h"

typedef struct v3x4 {
	float32x4_t x, y, z;
} v3x4;

/* One step's vertices: influence k of lane j is bone[k][j], an array of
 * uint16 (float streams) or, bone_bytes 1, uint8 indices (compact), with
 * weight lane j of w[k]. */
typedef struct batch4 {
	const void *bone[SKP_MAX_INFLUENCES];
	int bone_bytes;
	float32x4_t w[SKP_MAX_INFLUENCES];
	v3x4 p, n;
} batch4;

NEON_INLINE int batch_bone(const batch4 *bt, int k, int j)
{
	return bt->bone_bytes == 2 ? ((const uint16_t *)bt->bone[k])[j] : ((const uint8_t *)bt->bone[k])[j];
}

NEON_INLINE v3x4 load3(const float *x, const float *y, const float *z, int v)
{
	v3x4 r = { vld1q_f32(x + v), vld1q_f32(y + v), vld1q_f32(z + v) };
	return r;
}

NEON_INLINE void load_float(const skin_soa *in, int v, batch4 *bt)
{
	bt->bone_bytes = 2;
#pragma GCC unroll 12
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		bt->bone[k] = in->bone[k] + v;
		bt->w[k] = vld1q_f32(in->weight[k] + v);
	}
	bt->p = load3(in->px, in->py, in->pz, v);
	bt->n = load3(in->nx, in->ny, in->nz, v);
}

NEON_INLINE float32x4_t load_u16(const uint16_t *src)
{
	return vcvtq_f32_u32(vmovl_u16(vld1_u16(src)));
}

/* 1 / |a| by the reciprocal square root estimate and two Newton steps
 * (about 1e-7 relative, as exact as float's rounding allows): a square
 * root and a division would hold the Cortex-A72's divider for dozens of
 * cycles per four vertices. */
NEON_INLINE v3x4 normalize4(v3x4 a)
{
	float32x4_t len2 = vfmaq_f32(vfmaq_f32(vmulq_f32(a.z, a.z), a.y, a.y), a.x, a.x);
	float32x4_t inv = vrsqrteq_f32(len2);
	inv = vmulq_f32(inv, vrsqrtsq_f32(vmulq_f32(len2, inv), inv));
	inv = vmulq_f32(inv, vrsqrtsq_f32(vmulq_f32(len2, inv), inv));
	v3x4 r = { vmulq_f32(a.x, inv), vmulq_f32(a.y, inv), vmulq_f32(a.z, inv) };
	return r;
}

/* skin_compact_scalar.c's decode on 4 lanes */
NEON_INLINE void load_compact(const skin_compact *in, int v, batch4 *bt)
{
	const float32x4_t wscale = vdupq_n_f32(1.0f / (float)SKIN_COMPACT_WEIGHT_ONE);
	uint32x4_t rest = vdupq_n_u32(SKIN_COMPACT_WEIGHT_ONE);
	bt->bone_bytes = 1;
#pragma GCC unroll 12
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		bt->bone[k] = in->bone[k] + v;
#pragma GCC unroll 12
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		uint32x4_t w = vmovl_u16(vld1_u16(in->weight[k - 1] + v));
		rest = vsubq_u32(rest, w);
		bt->w[k] = vmulq_f32(vcvtq_f32_u32(w), wscale);
	}
	bt->w[0] = vmulq_f32(vcvtq_f32_u32(rest), wscale);
	const uint16_t *const q[3] = { in->qx, in->qy, in->qz };
	float32x4_t *const p[3] = { &bt->p.x, &bt->p.y, &bt->p.z };
#pragma GCC unroll 12
	for (int i = 0; i < 3; i++)
		*p[i] = vfmaq_f32(vdupq_n_f32(in->origin[i]), load_u16(q[i] + v), vdupq_n_f32(in->step[i]));
	const float32x4_t nscale = vdupq_n_f32(1.0f / SKIN_COMPACT_NORMAL_ONE);
	float32x4_t x = vmulq_f32(vcvtq_f32_s32(vmovl_s16(vld1_s16(in->ox + v))), nscale);
	float32x4_t y = vmulq_f32(vcvtq_f32_s32(vmovl_s16(vld1_s16(in->oy + v))), nscale);
	float32x4_t z = vsubq_f32(vsubq_f32(vdupq_n_f32(1.0f), vabsq_f32(x)), vabsq_f32(y));
	float32x4_t t = vmaxq_f32(vnegq_f32(z), vdupq_n_f32(0.0f));
	/* x - t with x's sign: x >= 0 moves down by t, x < 0 up */
	uint32x4_t xneg = vcltq_f32(x, vdupq_n_f32(0.0f)), yneg = vcltq_f32(y, vdupq_n_f32(0.0f));
	v3x4 n = { vbslq_f32(xneg, vaddq_f32(x, t), vsubq_f32(x, t)), vbslq_f32(yneg, vaddq_f32(y, t), vsubq_f32(y, t)),
		   z };
	bt->n = normalize4(n);
}

NEON_INLINE void transpose4(float32x4_t r[4])
{
	int32x4_t t[4];
#pragma GCC unroll 12
	for (int i = 0; i < 4; i++)
		t[i] = vreinterpretq_s32_f32(r[i]);
	skin_transpose4(t);
#pragma GCC unroll 12
	for (int i = 0; i < 4; i++)
		r[i] = vreinterpretq_f32_s32(t[i]);
}

/* The step's weights per vertex: w[j] lane k is influence k's weight of
 * vertex j, the multiplier the blends take by lane. */
NEON_INLINE void weights_per_vertex(const batch4 *bt, float32x4_t w[NEON_LANES])
{
#pragma GCC unroll 12
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		w[k] = bt->w[k];
	transpose4(w);
}

NEON_INLINE void store_xyz4(float *dst, v3x4 a, int valid)
{
	skin_store_xyz4(dst, vreinterpretq_s32_f32(a.x), vreinterpretq_s32_f32(a.y), vreinterpretq_s32_f32(a.z), valid);
}

/* 4 unit normals as 16-bit snorm (rounded to nearest even, as skin_snorm16_of) */
NEON_INLINE void store_snorm4(int16_t *dst, v3x4 a, int valid)
{
	const float32x4_t one = vdupq_n_f32(SKIN_COMPACT_NORMAL_ONE);
	int16x4x3_t t = { { vqmovn_s32(vcvtnq_s32_f32(vmulq_f32(a.x, one))),
			    vqmovn_s32(vcvtnq_s32_f32(vmulq_f32(a.y, one))),
			    vqmovn_s32(vcvtnq_s32_f32(vmulq_f32(a.z, one))) } };
	if (valid == NEON_LANES) {
		vst3_s16(dst, t);
		return;
	}
	int16_t tmp[3 * NEON_LANES];
	vst3_s16(tmp, t);
	memcpy(dst, tmp, sizeof(int16_t) * 3 * (size_t)valid);
}

NEON_INLINE v3x4 apply_rows(const float32x4_t m[12], v3x4 p, int with_translation)
{
	v3x4 r;
	float32x4_t *out[3] = { &r.x, &r.y, &r.z };
#pragma GCC unroll 12
	for (int row = 0; row < 3; row++) {
		const float32x4_t *q = m + 4 * row;
		float32x4_t acc = with_translation ? q[3] : vdupq_n_f32(0.0f);
		acc = vfmaq_f32(acc, q[0], p.x);
		acc = vfmaq_f32(acc, q[1], p.y);
		*out[row] = vfmaq_f32(acc, q[2], p.z);
	}
	return r;
}

/* The bone tables the steps read. Held in locals for the whole run: read
 * through skin_bones (or the streams through their struct) in every step,
 * each row address cost a constant materialised again and each stream
 * pointer a reload, as the stores might have changed them. */
typedef struct tables {
	const float (*lbs12)[12];
	const char *dq8_rows;                     /* skin_bones.dq8_signed */
	const uint16_t (*dq8_at)[SKP_MAX_BONES + 1];
} tables;

/* sum over the influences of w[k] times the 4 floats at row[k] + at; the
 * lane of a multiply by lane must be a constant, hence no loop over k */
NEON_INLINE float32x4_t blend_row(const float *const row[SKP_MAX_INFLUENCES], int at, float32x4_t w)
{
	_Static_assert(SKP_MAX_INFLUENCES == 4, "blend_row takes four influences");
	float32x4_t acc = vmulq_laneq_f32(vld1q_f32(row[0] + at), w, 0);
	acc = vfmaq_laneq_f32(acc, vld1q_f32(row[1] + at), w, 1);
	acc = vfmaq_laneq_f32(acc, vld1q_f32(row[2] + at), w, 2);
	return vfmaq_laneq_f32(acc, vld1q_f32(row[3] + at), w, 3);
}

/* Each vertex's blended 3x4 matrix, then m[i] = element i in lanes. */
NEON_INLINE void lbs_block(const tables *t, const batch4 *bt, float32x4_t m[12])
{
	float32x4_t w[NEON_LANES], r[3][NEON_LANES];
	weights_per_vertex(bt, w);
#pragma GCC unroll 12
	for (int j = 0; j < NEON_LANES; j++) {
		const float *row[SKP_MAX_INFLUENCES];
#pragma GCC unroll 12
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
			row[k] = t->lbs12[batch_bone(bt, k, j)];
#pragma GCC unroll 12
		for (int i = 0; i < 3; i++)
			r[i][j] = blend_row(row, 4 * i, w[j]);
	}
#pragma GCC unroll 12
	for (int i = 0; i < 3; i++) {
		transpose4(r[i]);
#pragma GCC unroll 12
		for (int c = 0; c < 4; c++)
			m[4 * i + c] = r[i][c];
	}
}

NEON_INLINE void lbs4(const tables *t, const batch4 *bt, v3x4 *p, v3x4 *n)
{
	float32x4_t m[12];
	lbs_block(t, bt, m);
	*p = apply_rows(m, bt->p, 1);
	*n = normalize4(apply_rows(m, bt->n, 0));
}

typedef struct dq4 {
	float32x4_t rw, rx, ry, rz, dw, dx, dy, dz;
} dq4;

/* Weighted sum with each influence's sign flipped when its real part
 * points away from the pivot (influence 0, the largest weight): the
 * decision per bone pair (the scalar kernel's own test, made once a frame)
 * is the offset of the bone's row or of its negated copy (dq8_at), one
 * 16-bit load per influence. */
NEON_INLINE dq4 dq_blend4(const tables *t, const batch4 *bt)
{
	float32x4_t w[NEON_LANES], re[NEON_LANES], du[NEON_LANES];
	weights_per_vertex(bt, w);
#pragma GCC unroll 12
	for (int j = 0; j < NEON_LANES; j++) {
		const uint16_t *at = t->dq8_at[batch_bone(bt, 0, j)];
		const float *row[SKP_MAX_INFLUENCES];
#pragma GCC unroll 12
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
			row[k] = (const float *)(t->dq8_rows + at[batch_bone(bt, k, j)]);
		re[j] = blend_row(row, 0, w[j]);
		du[j] = blend_row(row, 4, w[j]);
	}
	transpose4(re);
	transpose4(du);
	dq4 d = { re[0], re[1], re[2], re[3], du[0], du[1], du[2], du[3] };
	return d;
}

NEON_INLINE v3x4 cross4(v3x4 a, v3x4 b)
{
	v3x4 r = { vfmsq_f32(vmulq_f32(a.y, b.z), a.z, b.y),
		   vfmsq_f32(vmulq_f32(a.z, b.x), a.x, b.z),
		   vfmsq_f32(vmulq_f32(a.x, b.y), a.y, b.x) };
	return r;
}

/* a + b * s */
NEON_INLINE v3x4 madd4(v3x4 a, v3x4 b, float32x4_t s)
{
	v3x4 r = { vfmaq_f32(a.x, b.x, s), vfmaq_f32(a.y, b.y, s), vfmaq_f32(a.z, b.z, s) };
	return r;
}

/* The unnormalised blend moves v to v + s (r x (r x v + w v + dv) + w dv -
 * dw r), s = 2 / |real|^2 (as the AVX2 kernel, skin_avx2_float.h); a
 * normal takes the rotation only. */
NEON_INLINE v3x4 move4(const dq4 *d, float32x4_t s, v3x4 v, int with_dual)
{
	v3x4 r = { d->rx, d->ry, d->rz }, dv = { d->dx, d->dy, d->dz };
	v3x4 a = madd4(cross4(r, v), v, d->rw);
	if (with_dual) {
		a.x = vaddq_f32(a.x, dv.x);
		a.y = vaddq_f32(a.y, dv.y);
		a.z = vaddq_f32(a.z, dv.z);
	}
	v3x4 c = cross4(r, a);
	if (with_dual)
		c = madd4(madd4(c, dv, d->rw), r, vnegq_f32(d->dw));
	return madd4(v, c, s);
}

NEON_INLINE void dqbs4(const tables *t, const batch4 *bt, v3x4 *p, v3x4 *n)
{
	dq4 d = dq_blend4(t, bt);
	float32x4_t n2 = vfmaq_f32(vfmaq_f32(vfmaq_f32(vmulq_f32(d.rz, d.rz), d.ry, d.ry), d.rx, d.rx), d.rw, d.rw);
	/* 2 / n2: an estimate and two Newton steps (about 1e-7), cheaper than
	 * the division on a Cortex-A72 */
	float32x4_t y = vrecpeq_f32(n2);
	y = vmulq_f32(y, vrecpsq_f32(n2, y));
	y = vmulq_f32(y, vrecpsq_f32(n2, y));
	float32x4_t s = vaddq_f32(y, y);
	*p = move4(&d, s, bt->p, 1);
	*n = move4(&d, s, bt->n, 0);
}

/* What the steps read and write, in locals for the whole run. */
typedef struct run_ctx {
	tables t;
	skin_soa fs;
	skin_compact cs;
	float *pos, *nrm;
	int16_t *nrm16;
} run_ctx;

/* One step of 4 vertices from v, the first `valid` of them stored. */
NEON_INLINE void step4(int dual, int compact, const run_ctx *c, int v, int valid)
{
	batch4 bt;
	v3x4 p, n;
	if (compact)
		load_compact(&c->cs, v, &bt);
	else
		load_float(&c->fs, v, &bt);
	if (dual)
		dqbs4(&c->t, &bt, &p, &n);
	else
		lbs4(&c->t, &bt, &p, &n);
	store_xyz4(c->pos + 3 * v, p, valid);
	if (compact)
		store_snorm4(c->nrm16 + 3 * v, n, valid);
	else
		store_xyz4(c->nrm + 3 * v, n, valid);
}

/* Steps of 4 vertices over either stream form (the other pointer NULL),
 * LBS or (dual 1) DQBS; inlined into each kernel so the choices fold. The
 * last 1-3 vertices take a step of their own after the loop, so that the
 * loop holds whole steps only, without the partial stores' memcpy call. */
NEON_INLINE void run4(int dual, const skin_soa *fl, const skin_compact *co, const skin_bones *b, int first, int end,
		      const skin_out *out)
{
	run_ctx c = { .t = { b->lbs12, (const char *)b->dq8_signed, b->dq8_at },
		      .pos = out->pos, .nrm = out->nrm, .nrm16 = out->nrm16 };
	if (co)
		c.cs = *co;
	else
		c.fs = *fl;
	int v = first;
	for (; end - v >= NEON_LANES; v += NEON_LANES)
		step4(dual, co != NULL, &c, v, NEON_LANES);
	if (v < end)
		step4(dual, co != NULL, &c, v, end - v);
}

void skin_lbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run4(0, in, NULL, b, first, end, out);
}

void skin_dqbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run4(1, in, NULL, b, first, end, out);
}

void skin_lbs_compact_neon(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run4(0, NULL, in, b, first, end, out);
}

void skin_dqbs_compact_neon(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run4(1, NULL, in, b, first, end, out);
}

#else
typedef int skin_neon_not_built; /* the board chose other kernels */
#endif
