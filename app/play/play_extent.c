#include "play_extent.h"

#include <math.h>

static int has_child(const skel *s, int b)
{
	for (int i = 1; i < s->count; i++)
		if (s->bone[i].parent == b)
			return 1;
	return 0;
}

static int mostly_horizontal(const skel_pose *p, int b)
{
	vec3 d = vec3_sub(p->tip[b], p->head[b]);
	float h = sqrtf(d.x * d.x + d.z * d.z);
	return h > 0.0f && fabsf(d.y) < h;
}

/* Ankle to toe tip of a foot ending at leaf bone b: up the chain while its
 * bones lie flat. */
static vec3 foot_vector(const skel *s, const skel_pose *p, int b)
{
	int top = b;
	while (s->bone[top].parent > 0 && mostly_horizontal(p, s->bone[top].parent))
		top = s->bone[top].parent;
	return vec3_sub(p->tip[b], p->head[top]);
}

static void joint_range(const skel *s, const skel_pose *p, float *lo, float *hi)
{
	*lo = *hi = p->tip[0].y;
	for (int b = 0; b < s->count; b++) {
		*lo = fminf(*lo, fminf(p->tip[b].y, p->head[b].y));
		*hi = fmaxf(*hi, fmaxf(p->tip[b].y, p->head[b].y));
	}
}

float play_pose_facing(const skel *s, const skel_pose *p, float *sin_sum, float *cos_sum)
{
	float lo, hi, sx = 0.0f, sz = 0.0f;
	joint_range(s, p, &lo, &hi);
	float low = lo + 0.15f * (hi - lo);
	for (int b = 1; b < s->count; b++) {
		/* a foot: a leaf near the ground that lies flat */
		if (has_child(s, b) || p->tip[b].y > low || !mostly_horizontal(p, b))
			continue;
		vec3 f = foot_vector(s, p, b);
		float h = sqrtf(f.x * f.x + f.z * f.z);
		if (h > 0.0f) {
			sx += f.x / h;
			sz += f.z / h;
		}
	}
	*sin_sum += sx;
	*cos_sum += sz;
	return sqrtf(sx * sx + sz * sz);
}

static void grow_bounds(const skel *s, const skel_pose *p, vec3 root0, play_extent *out)
{
	/* in place: every frame's root over the first frame's */
	vec3 shift = vec3_make(root0.x - p->tip[0].x, 0.0f, root0.z - p->tip[0].z), way = vec3_scale(shift, -1.0f);
	out->travel_lo = vec3_min(out->travel_lo, way);
	out->travel_hi = vec3_max(out->travel_hi, way);
	for (int b = 0; b < s->count; b++) {
		vec3 q = vec3_add(p->tip[b], shift);
		out->lo = vec3_min(out->lo, q);
		out->hi = vec3_max(out->hi, q);
	}
}

skp_status play_extent_clip(const skel *s, const play_source *src, int stride, amc_frame *frame,
			    skel_pose *pose, play_extent *out, skp_error *err)
{
	float ss = 0.0f, cs = 0.0f, evidence = 0.0f;
	vec3 root0 = vec3_make(0.0f, 0.0f, 0.0f);
	skp_status st = src->seek(src->ctx, 0, err);
	out->frames = 0;
	out->facing_known = 0;
	out->facing = 0.0f;
	out->lo = vec3_make(INFINITY, INFINITY, INFINITY);
	out->hi = vec3_make(-INFINITY, -INFINITY, -INFINITY);
	out->first_root = root0;
	out->travel_lo = out->travel_hi = root0;
	int r = 0;
	while (st == SKP_OK && (r = src->next(src->ctx, frame, err)) > 0) {
		if (out->frames++ % (stride > 0 ? stride : 1))
			continue;
		fk_pose(s, frame->value, pose);
		if (out->frames == 1)
			root0 = out->first_root = pose->tip[0];
		evidence += play_pose_facing(s, pose, &ss, &cs);
		grow_bounds(s, pose, root0, out);
	}
	if (st == SKP_OK && r < 0)
		st = (skp_status)r;
	if (st == SKP_OK)
		st = src->seek(src->ctx, 0, err);
	if (evidence > 0.0f && (ss != 0.0f || cs != 0.0f)) {
		out->facing = atan2f(ss, cs);
		out->facing_known = 1;
	}
	return st;
}
