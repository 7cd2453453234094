/* Which bends carry a pose's volume change. DQBS turns each cross-section
 * of a bending joint rigidly about the joint, so it keeps the volume only
 * where the flesh around the joint is centred on it; elsewhere the volume
 * changes with the bend angle, up one way and down the other. Straightening
 * one joint at a time shows where: the shares need not add up to the
 * total, since bends interact where their regions meet. */
#include <math.h>
#include <string.h>

#include "report.h"

#define SHARE_MIN 0.0005

static double deg_of(float rad)
{
	return (double)rad * (180.0 / M_PI);
}

/* How far v lies outside [lo, hi], all in degrees, trying v + 360 k: a
 * rotation by 379 degrees is one by 19. */
static float past_limits(float v, float lo, float hi)
{
	if (!(hi - lo < 360.0f))
		return 0.0f;
	float mid = 0.5f * (lo + hi), best = INFINITY;
	float k0 = roundf((mid - v) / 360.0f);
	for (int k = -1; k <= 1; k++) {
		float w = v + 360.0f * (k0 + (float)k);
		float d = w < lo ? lo - w : (w > hi ? w - hi : 0.0f);
		best = fminf(best, d);
	}
	return best;
}

/* The joint's rotation channels and their values; -1 when it has none. */
static int describe(const skel *s, int b, const float *values, report_joint *j)
{
	const skel_bone *bone = &s->bone[b];
	memset(j, 0, sizeof *j);
	j->bone = b;
	j->past = -1;
	for (int k = 0; k < bone->channel_count && j->count < 3; k++) {
		if (bone->channel[k] > SKEL_RZ)
			continue;
		int c = j->count++;
		j->channel[c] = bone->channel[k];
		j->deg[c] = (float)deg_of(values[bone->dof_offset + k]);
		if (!bone->has_limits)
			continue;
		float lo = (float)deg_of(skel_angle_to_rad(s, bone->limit[k][0]));
		float hi = (float)deg_of(skel_angle_to_rad(s, bone->limit[k][1]));
		float past = past_limits(j->deg[c], lo, hi);
		if (past > 0.0f && (j->past < 0 || past > j->past_deg)) {
			j->past = c;
			j->past_deg = past;
			j->lo_deg = lo;
			j->hi_deg = hi;
		}
	}
	return j->count > 0 ? 0 : -1;
}

static double volume_of(runtime_skin *sk, const measure_state *meas, skin_algo algo, const float *values,
			float *pos, float *nrm)
{
	runtime_skin_frame(sk, values);
	runtime_skin_run(sk, algo, pos, nrm);
	return measure_volume(meas, pos);
}

static void keep_largest(report_joints *out, const report_joint *j)
{
	int k = out->count;
	if (k == REPORT_MAX_JOINTS) {
		if (fabs(out->joint[k - 1].share) >= fabs(j->share))
			return;
		k--;
	} else {
		out->count++;
	}
	for (; k > 0 && fabs(out->joint[k - 1].share) < fabs(j->share); k--)
		out->joint[k] = out->joint[k - 1];
	out->joint[k] = *j;
}

void report_find_joints(runtime_skin *sk, const measure_state *meas, skin_algo algo, long frame,
			const float *values, const float *bind_values, float *pos, float *nrm,
			report_joints *out)
{
	static float v[SKP_MAX_DOF];
	const skel *s = sk->skel;
	memset(out, 0, sizeof *out);
	out->frame = frame;
	out->volume = volume_of(sk, meas, algo, values, pos, nrm);
	memcpy(v, values, sizeof v);
	for (int b = 1; b < s->count; b++) {
		report_joint j;
		if (describe(s, b, values, &j) < 0)
			continue;
		const skel_bone *bone = &s->bone[b];
		for (int k = 0; k < bone->channel_count; k++)
			if (bone->channel[k] <= SKEL_RZ)
				v[bone->dof_offset + k] = bind_values[bone->dof_offset + k];
		j.share = out->volume - volume_of(sk, meas, algo, v, pos, nrm);
		for (int k = 0; k < bone->channel_count; k++)
			v[bone->dof_offset + k] = values[bone->dof_offset + k];
		if (fabs(j.share) >= SHARE_MIN)
			keep_largest(out, &j);
	}
}
