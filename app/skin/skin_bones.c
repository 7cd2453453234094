#include "skin.h"

#include "fixed_convert.h"

static void flatten(skin_bones *out, int b)
{
	const rigid *m = &out->mat[b];
	for (int r = 0; r < 3; r++) {
		out->lbs12[b][r * 4 + 0] = m->r[r][0];
		out->lbs12[b][r * 4 + 1] = m->r[r][1];
		out->lbs12[b][r * 4 + 2] = m->r[r][2];
	}
	out->lbs12[b][3] = m->t.x;
	out->lbs12[b][7] = m->t.y;
	out->lbs12[b][11] = m->t.z;
	const dq *d = &out->dq[b];
	float v[8] = { d->real.w, d->real.x, d->real.y, d->real.z,
		       d->dual.w, d->dual.x, d->dual.y, d->dual.z };
	for (int i = 0; i < 8; i++)
		out->dq8[b][i] = v[i];
}

static void set_bone(skin_bones *out, int b, quat q, vec3 t)
{
	out->mat[b] = rigid_from_quat_trans(q, t);
	out->dq[b] = dq_from_quat_trans(q, t);
	out->fdq[b] = fx_dq_from_dq(&out->dq[b]);
	flatten(out, b);
}

#ifdef SKIN_SIMD_FLIPS
/* The skeleton's bones and the identity slot, into slots; returns how
 * many. The tables below have entries for these only. */
static int used_slots(const skin_bones *out, int slots[SKP_MAX_BONES + 1])
{
	int n = 0;
	for (int i = 0; i < out->count; i++)
		slots[n++] = i;
	slots[n++] = SKIN_IDENTITY_BONE;
	return n;
}

/* real w x y z, dual w x y z, in 64 bits: a saturated dual component
 * negates past int32 */
static void fdq_components(const fx_dq *d, int64_t c[8])
{
	const int32_t src[8] = { d->real.w, d->real.x, d->real.y, d->real.z,
				 d->dual.w, d->dual.x, d->dual.y, d->dual.z };
	for (int i = 0; i < 8; i++)
		c[i] = src[i];
}

/* The byte offset of bone's row, or of its negation (flip), in a table of
 * pairs of rows pair_bytes long. */
static uint16_t row_offset(size_t pair_bytes, int bone, int flip)
{
	return (uint16_t)(pair_bytes * (size_t)bone + pair_bytes / 2 * (size_t)flip);
}

/* The sign fix for every pair of used slots, as the board's kernels read
 * it (see skin_bones). */
static void compute_flips(skin_bones *out)
{
	_Static_assert(sizeof out->SKIN_FIXED_ROWS <= UINT16_MAX, "row offsets fit 16 bits");
#ifdef SKP_SIMD_NEON
	_Static_assert(sizeof out->dq8_signed <= UINT16_MAX, "row offsets fit 16 bits");
#endif
	int slots[SKP_MAX_BONES + 1], n = used_slots(out, slots);
	for (int a = 0; a < n; a++) {
		int p = slots[a];
		for (int c = 0; c < n; c++) {
			int k = slots[c];
			int flip_f = quat_dot(out->dq[k].real, out->dq[p].real) < 0.0f;
			int flip_x = fx_quat_dot(out->fdq[k].real, out->fdq[p].real) < 0;
			out->fdq_at[p][k] = row_offset(sizeof out->SKIN_FIXED_ROWS[0], k, flip_x);
#ifdef SKP_SIMD_AVX2
			out->flip_f[p][k] = flip_f ? -0.0f : 0.0f;
#endif
#ifdef SKP_SIMD_NEON
			out->dq8_at[p][k] = row_offset(sizeof out->dq8_signed[0], k, flip_f);
#endif
		}
	}
}
#endif

#ifdef SKP_SIMD_AVX2
static void split_halves(int16_t dst[16], const int64_t c[8])
{
	for (int i = 0; i < 8; i++) {
		int16_t lo = (int16_t)(uint16_t)((uint64_t)c[i] & 0xffff);
		int16_t hi = (int16_t)((c[i] - lo) / 65536);
		dst[i / 4 * 8 + i % 4] = lo;
		dst[i / 4 * 8 + 4 + i % 4] = hi;
	}
}

static void compute_halves(skin_bones *out)
{
	int slots[SKP_MAX_BONES + 1], n = used_slots(out, slots);
	out->simd_ok = 1;
	for (int a = 0; a < n; a++) {
		int b = slots[a];
		int64_t c[8];
		fdq_components(&out->fdq[b], c);
		/* within the limit, hi fits int16 too, negated or not (real
		 * parts are at most 2^30 long); beyond it the halves go unused */
		for (int i = 4; i < 8; i++)
			if (c[i] >= SKIN_SIMD_DUAL_LIMIT || c[i] <= -SKIN_SIMD_DUAL_LIMIT)
				out->simd_ok = 0;
		split_halves(out->fdq_halves[b][0], c);
		for (int i = 0; i < 8; i++)
			c[i] = -c[i];
		split_halves(out->fdq_halves[b][1], c);
	}
}
#endif

#ifdef SKP_SIMD_NEON
/* The NEON kernels' rows: each bone's fdq and dq8 and their negations. */
static void compute_signed(skin_bones *out)
{
	int slots[SKP_MAX_BONES + 1], n = used_slots(out, slots);
	out->simd_ok = 1;
	for (int a = 0; a < n; a++) {
		int b = slots[a];
		int64_t c[8];
		int32_t neg[8];
		fdq_components(&out->fdq[b], c);
		for (int i = 0; i < 8; i++) {
			if (c[i] == INT32_MIN)
				out->simd_ok = 0;
			neg[i] = fx_sat32(-c[i]);
		}
		fx_dq negated = { { neg[0], neg[1], neg[2], neg[3] }, { neg[4], neg[5], neg[6], neg[7] } };
		out->fdq_signed[b][0] = out->fdq[b];
		out->fdq_signed[b][1] = negated;
		for (int i = 0; i < 8; i++) {
			out->dq8_signed[b][0][i] = out->dq8[b][i];
			out->dq8_signed[b][1][i] = -out->dq8[b][i];
		}
	}
}
#endif

#if FX_NARROW_MUL
static void compute_split(skin_bones *out)
{
	for (int b = 0; b <= SKP_MAX_BONES; b++) {
		if (b >= out->count && b != SKIN_IDENTITY_BONE)
			continue;
		const fx_dq *d = &out->fdq[b];
		const int32_t c[8] = { d->real.w, d->real.x, d->real.y, d->real.z,
				       d->dual.w, d->dual.x, d->dual.y, d->dual.z };
		for (int i = 0; i < 8; i++) {
			out->fdq_split[b][0][i] = c[i] >> 16;
			out->fdq_split[b][1][i] = c[i] & 0xffff;
		}
	}
}
#endif

void skin_bones_compute(skin_bones *out, const skel *s, const skel_pose *bind,
			const skel_pose *pose)
{
	out->count = s->count;
	for (int b = 0; b < s->count; b++) {
		quat q = quat_normalize(quat_mul(pose->rot[b], quat_conj(bind->rot[b])));
		vec3 t = vec3_sub(pose->head[b], quat_rotate(q, bind->head[b]));
		set_bone(out, b, q, t);
	}
	set_bone(out, SKIN_IDENTITY_BONE, quat_identity(), vec3_make(0, 0, 0));
	skin_bones_derive(out);
}

void skin_bones_derive(skin_bones *out)
{
	(void)out; /* scalar boards derive nothing */
#ifdef SKIN_SIMD_FLIPS
	compute_flips(out);
#endif
#ifdef SKP_SIMD_AVX2
	compute_halves(out);
#endif
#ifdef SKP_SIMD_NEON
	compute_signed(out);
#endif
#if FX_NARROW_MUL
	compute_split(out);
#endif
}
