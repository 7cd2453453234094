/* NEON kernels (AArch64, e.g. the Raspberry Pi 4's Cortex-A72), over the
 * float and the compact vertex streams: 4 lanes, two steps per SKIN_LANES
 * block. NEON has no gather, so each step loads the 4 vertices' bone rows
 * and transposes them (4x4 at a time) into lanes. A step first loads its
 * batch (bones, weights, position, normal) from either stream form, then
 * the same arithmetic runs. Built when the board sets SIMD=neon; results
 * match skin_scalar.c and skin_compact_scalar.c to float rounding (FMA).
 * The fixed-point kernel is skin_fixed_neon.c. */
#include "skin_kernels.h"

#if defined(SKP_SIMD_NEON) && defined(__aarch64__)

#include "skin_neon.h"

typedef struct v3x4 {
	float32x4_t x, y, z;
} v3x4;

/* One step's vertices: bone[k][j] is influence k of lane j. */
typedef struct batch4 {
	int bone[SKP_MAX_INFLUENCES][NEON_LANES];
	float32x4_t w[SKP_MAX_INFLUENCES];
	v3x4 p, n;
} batch4;

static v3x4 load3(const float *x, const float *y, const float *z, int v)
{
	v3x4 r = { vld1q_f32(x + v), vld1q_f32(y + v), vld1q_f32(z + v) };
	return r;
}

static void load_float(const skin_soa *in, int v, batch4 *bt)
{
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		for (int j = 0; j < NEON_LANES; j++)
			bt->bone[k][j] = in->bone[k][v + j];
		bt->w[k] = vld1q_f32(in->weight[k] + v);
	}
	bt->p = load3(in->px, in->py, in->pz, v);
	bt->n = load3(in->nx, in->ny, in->nz, v);
}

static float32x4_t load_u16(const uint16_t *src)
{
	return vcvtq_f32_u32(vmovl_u16(vld1_u16(src)));
}

static v3x4 normalize4(v3x4 a)
{
	float32x4_t len2 = vfmaq_f32(vfmaq_f32(vmulq_f32(a.z, a.z), a.y, a.y), a.x, a.x);
	float32x4_t inv = vdivq_f32(vdupq_n_f32(1.0f), vsqrtq_f32(len2));
	v3x4 r = { vmulq_f32(a.x, inv), vmulq_f32(a.y, inv), vmulq_f32(a.z, inv) };
	return r;
}

/* skin_compact_scalar.c's decode on 4 lanes */
static void load_compact(const skin_compact *in, int v, batch4 *bt)
{
	const float32x4_t wscale = vdupq_n_f32(1.0f / (float)SKIN_COMPACT_WEIGHT_ONE);
	uint32x4_t rest = vdupq_n_u32(SKIN_COMPACT_WEIGHT_ONE);
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		for (int j = 0; j < NEON_LANES; j++)
			bt->bone[k][j] = in->bone[k][v + j];
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		uint32x4_t w = vmovl_u16(vld1_u16(in->weight[k - 1] + v));
		rest = vsubq_u32(rest, w);
		bt->w[k] = vmulq_f32(vcvtq_f32_u32(w), wscale);
	}
	bt->w[0] = vmulq_f32(vcvtq_f32_u32(rest), wscale);
	const uint16_t *const q[3] = { in->qx, in->qy, in->qz };
	float32x4_t *const p[3] = { &bt->p.x, &bt->p.y, &bt->p.z };
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

static void transpose4(float32x4_t r[4])
{
	int32x4_t t[4];
	for (int i = 0; i < 4; i++)
		t[i] = vreinterpretq_s32_f32(r[i]);
	skin_transpose4(t);
	for (int i = 0; i < 4; i++)
		r[i] = vreinterpretq_f32_s32(t[i]);
}

/* Four consecutive floats at offset `at` of each lane's bone row, in lanes. */
static void gather4x4(const float *base, int stride, const int bone[NEON_LANES], int at, float32x4_t out[4])
{
	for (int j = 0; j < NEON_LANES; j++)
		out[j] = vld1q_f32(base + (size_t)bone[j] * (size_t)stride + at);
	transpose4(out);
}

static void store_xyz4(float *dst, v3x4 a, int valid)
{
	skin_store_xyz4(dst, vreinterpretq_s32_f32(a.x), vreinterpretq_s32_f32(a.y), vreinterpretq_s32_f32(a.z), valid);
}

/* 4 unit normals as 16-bit snorm (rounded to nearest even, as skin_snorm16_of) */
static void store_snorm4(int16_t *dst, v3x4 a, int valid)
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

static v3x4 apply_rows(const float32x4_t m[12], v3x4 p, int with_translation)
{
	v3x4 r;
	float32x4_t *out[3] = { &r.x, &r.y, &r.z };
	for (int row = 0; row < 3; row++) {
		const float32x4_t *q = m + 4 * row;
		float32x4_t acc = with_translation ? q[3] : vdupq_n_f32(0.0f);
		acc = vfmaq_f32(acc, q[0], p.x);
		acc = vfmaq_f32(acc, q[1], p.y);
		*out[row] = vfmaq_f32(acc, q[2], p.z);
	}
	return r;
}

static void lbs4(const skin_bones *b, const batch4 *bt, v3x4 *p, v3x4 *n)
{
	const float *base = &b->lbs12[0][0];
	float32x4_t m[12];
	for (int i = 0; i < 12; i++)
		m[i] = vdupq_n_f32(0.0f);
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		for (int row = 0; row < 3; row++) {
			float32x4_t c[4];
			gather4x4(base, 12, bt->bone[k], 4 * row, c);
			for (int i = 0; i < 4; i++)
				m[4 * row + i] = vfmaq_f32(m[4 * row + i], bt->w[k], c[i]);
		}
	*p = apply_rows(m, bt->p, 1);
	*n = normalize4(apply_rows(m, bt->n, 0));
}

typedef struct dq4 {
	float32x4_t rw, rx, ry, rz, dw, dx, dy, dz;
} dq4;

static dq4 gather_dq(const skin_bones *b, const int bone[NEON_LANES])
{
	float32x4_t r[4], d[4];
	gather4x4(&b->dq8[0][0], 8, bone, 0, r);
	gather4x4(&b->dq8[0][0], 8, bone, 4, d);
	dq4 q = { r[0], r[1], r[2], r[3], d[0], d[1], d[2], d[3] };
	return q;
}

static void dq_accumulate(dq4 *acc, const dq4 *d, float32x4_t w)
{
	acc->rw = vfmaq_f32(acc->rw, w, d->rw);
	acc->rx = vfmaq_f32(acc->rx, w, d->rx);
	acc->ry = vfmaq_f32(acc->ry, w, d->ry);
	acc->rz = vfmaq_f32(acc->rz, w, d->rz);
	acc->dw = vfmaq_f32(acc->dw, w, d->dw);
	acc->dx = vfmaq_f32(acc->dx, w, d->dx);
	acc->dy = vfmaq_f32(acc->dy, w, d->dy);
	acc->dz = vfmaq_f32(acc->dz, w, d->dz);
}

/* Weighted sum with each influence's sign flipped when its real part points
 * away from the pivot (influence 0, the largest weight). */
static dq4 dq_blend4(const skin_bones *b, const batch4 *bt)
{
	const uint32x4_t sign = vdupq_n_u32(0x80000000u);
	dq4 pivot = gather_dq(b, bt->bone[0]);
	float32x4_t zero = vdupq_n_f32(0.0f);
	dq4 acc = { zero, zero, zero, zero, zero, zero, zero, zero };
	dq_accumulate(&acc, &pivot, bt->w[0]);
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		dq4 d = gather_dq(b, bt->bone[k]);
		float32x4_t dot = vmulq_f32(d.rw, pivot.rw);
		dot = vfmaq_f32(dot, d.rx, pivot.rx);
		dot = vfmaq_f32(dot, d.ry, pivot.ry);
		dot = vfmaq_f32(dot, d.rz, pivot.rz);
		uint32x4_t wbits = veorq_u32(vreinterpretq_u32_f32(bt->w[k]), vandq_u32(vreinterpretq_u32_f32(dot), sign));
		dq_accumulate(&acc, &d, vreinterpretq_f32_u32(wbits));
	}
	return acc;
}

static v3x4 cross4(v3x4 a, v3x4 b)
{
	v3x4 r = { vfmsq_f32(vmulq_f32(a.y, b.z), a.z, b.y),
		   vfmsq_f32(vmulq_f32(a.z, b.x), a.x, b.z),
		   vfmsq_f32(vmulq_f32(a.x, b.y), a.y, b.x) };
	return r;
}

/* a + b * s */
static v3x4 madd4(v3x4 a, v3x4 b, float32x4_t s)
{
	v3x4 r = { vfmaq_f32(a.x, b.x, s), vfmaq_f32(a.y, b.y, s), vfmaq_f32(a.z, b.z, s) };
	return r;
}

/* The unnormalised blend moves v to v + s (r x (r x v + w v + dv) + w dv -
 * dw r), s = 2 / |real|^2 (as the AVX2 kernel, skin_avx2_float.h); a
 * normal takes the rotation only. */
static v3x4 move4(const dq4 *d, float32x4_t s, v3x4 v, int with_dual)
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

static void dqbs4(const skin_bones *b, const batch4 *bt, v3x4 *p, v3x4 *n)
{
	dq4 d = dq_blend4(b, bt);
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

typedef void (*step_fn)(const skin_bones *b, const batch4 *bt, v3x4 *p, v3x4 *n);

/* Steps of 4 vertices over either stream form (the other pointer NULL),
 * inlined per kernel so that the choices fold away. */
static inline __attribute__((always_inline)) void run4(step_fn step, const skin_soa *fl, const skin_compact *co,
							 const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v += NEON_LANES) {
		batch4 bt;
		v3x4 p, n;
		if (co)
			load_compact(co, v, &bt);
		else
			load_float(fl, v, &bt);
		step(b, &bt, &p, &n);
		int valid = end - v < NEON_LANES ? end - v : NEON_LANES;
		store_xyz4(out->pos + 3 * v, p, valid);
		if (co)
			store_snorm4(out->nrm16 + 3 * v, n, valid);
		else
			store_xyz4(out->nrm + 3 * v, n, valid);
	}
}

void skin_lbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run4(lbs4, in, NULL, b, first, end, out);
}

void skin_dqbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run4(dqbs4, in, NULL, b, first, end, out);
}

void skin_lbs_compact_neon(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run4(lbs4, NULL, in, b, first, end, out);
}

void skin_dqbs_compact_neon(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run4(dqbs4, NULL, in, b, first, end, out);
}

#else
typedef int skin_neon_not_built; /* the board chose other kernels */
#endif
