#include "bind_fit.h"

#include <math.h>

float bind_fit_skel_height(const skel *s, const skel_pose *pose, float *min_y)
{
	float lo = pose->head[0].y, hi = lo;
	for (int b = 0; b < s->count; b++) {
		lo = fminf(lo, fminf(pose->head[b].y, pose->tip[b].y));
		hi = fmaxf(hi, fmaxf(pose->head[b].y, pose->tip[b].y));
	}
	if (min_y)
		*min_y = lo;
	return hi - lo;
}

static void y_range(const vec3 *pos, int n, float *lo, float *hi)
{
	*lo = *hi = pos[0].y;
	for (int v = 1; v < n; v++) {
		*lo = fminf(*lo, pos[v].y);
		*hi = fmaxf(*hi, pos[v].y);
	}
}

/* Which vertices count for the XZ centre, in fitted coordinates. */
typedef struct fit_slice {
	float scale, dy;
	float y0, y_band;           /* |y - y0| <= y_band */
	float x0, x_band;           /* |x - x0| <= x_band */
} fit_slice;

static int in_slice(const fit_slice *f, vec3 p)
{
	return fabsf(p.y * f->scale + f->dy - f->y0) <= f->y_band &&
	       fabsf(p.x * f->scale - f->x0) <= f->x_band;
}

/* XZ centre (unfitted) of the bounding box of the vertices in the slice;
 * 0 when there are none. */
static int slice_centre(const vec3 *pos, int n, const fit_slice *f, float *cx, float *cz)
{
	float x_lo = INFINITY, x_hi = -INFINITY, z_lo = INFINITY, z_hi = -INFINITY;
	int found = 0;
	for (int v = 0; v < n; v++) {
		if (!in_slice(f, pos[v]))
			continue;
		found = 1;
		x_lo = fminf(x_lo, pos[v].x);
		x_hi = fmaxf(x_hi, pos[v].x);
		z_lo = fminf(z_lo, pos[v].z);
		z_hi = fmaxf(z_hi, pos[v].z);
	}
	*cx = 0.5f * (x_lo + x_hi);
	*cz = 0.5f * (z_lo + z_hi);
	return found;
}

/* The torso's centre at the root's height: first the whole box (arms and
 * legs are symmetric enough to give the middle in X), then the slice
 * around the root's height narrowed to the middle, which leaves out hands
 * hanging at that height. Wider fallbacks for odd shapes. */
static void torso_centre(const vec3 *pos, int n, float scale, float dy, float root_y,
			 float height, float *cx, float *cz)
{
	fit_slice all = { scale, dy, 0.0f, INFINITY, 0.0f, INFINITY };
	slice_centre(pos, n, &all, cx, cz);
	fit_slice torso = { scale, dy, root_y, BIND_FIT_SLICE * height, *cx * scale,
			    BIND_FIT_TORSO * height };
	if (slice_centre(pos, n, &torso, cx, cz))
		return;
	torso.x_band = INFINITY;
	if (!slice_centre(pos, n, &torso, cx, cz))
		slice_centre(pos, n, &all, cx, cz);
}

skp_status bind_fit_measure(const vec3 *pos, int n, const skel *s, const skel_pose *pose,
			    bind_fit_result *out, skp_error *err)
{
	if (n <= 0)
		return skp_fail(err, SKP_ERR_RANGE, 0, "cannot fit an empty mesh");
	float skel_lo, mesh_lo, mesh_hi;
	float skel_h = bind_fit_skel_height(s, pose, &skel_lo);
	y_range(pos, n, &mesh_lo, &mesh_hi);
	float mesh_h = mesh_hi - mesh_lo;
	if (!(skel_h > 0.0f) || !isfinite(skel_h))
		return skp_fail(err, SKP_ERR_RANGE, 0, "the skeleton has no height in its bind pose");
	if (!(mesh_h > 0.0f) || !isfinite(mesh_h))
		return skp_fail(err, SKP_ERR_RANGE, 0, "the mesh has no height (Y extent)");

	float scale = skel_h / mesh_h;
	float dy = skel_lo - mesh_lo * scale;
	vec3 root = pose->head[0];
	float cx, cz;
	torso_centre(pos, n, scale, dy, root.y, skel_h, &cx, &cz);
	out->scale = scale;
	out->offset = vec3_make(root.x - cx * scale, dy, root.z - cz * scale);
	out->skel_height = skel_h;
	out->mesh_height = mesh_h;
	return SKP_OK;
}

void bind_fit_apply(vec3 *pos, int n, const bind_fit_result *fit)
{
	for (int v = 0; v < n; v++)
		pos[v] = vec3_add(vec3_scale(pos[v], fit->scale), fit->offset);
}

skp_status bind_fit(vec3 *pos, int n, const skel *s, const skel_pose *pose,
		    bind_fit_result *out, skp_error *err)
{
	bind_fit_result fit;
	skp_status rc = bind_fit_measure(pos, n, s, pose, &fit, err);
	if (rc)
		return rc;
	bind_fit_apply(pos, n, &fit);
	if (out)
		*out = fit;
	return SKP_OK;
}
