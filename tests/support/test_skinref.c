/* The kernel side of the skinning reference tests (test_skinref.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "skin_kernels.h"
#include "test_diff.h"
#include "test_parse.h"
#include "test_paths.h"
#include "test_skinref.h"

int skinref_cmu02_skel(skinref_cmu02 *c)
{
	skp_error err;
	const char *asf = test_data_path("mocap/cmu/02.asf");
	if (!asf || test_parse_asf_file(asf, &c->skel, &err) != SKP_OK)
		return -1;
	fk_pose(&c->skel, NULL, &c->rest);
	return 0;
}

int skinref_cmu02_setup(skinref_cmu02 *c)
{
	skp_error err;
	if (skinref_cmu02_skel(c))
		return 0;
	if (manq_build(&c->skel, 0, &c->work, &c->body, &err) != SKP_OK)
		return -1;
	bind_prepare(&c->rig, &c->skel, &c->rest, NULL);
	if (bind_weights(&c->rig, c->body.pos, c->body.vert_count, &c->w, NULL, &err) != SKP_OK)
		return -1;
	c->have = 1;
	return 0;
}

void skinref_d3(vec3 v, double o[3])
{
	o[0] = v.x; o[1] = v.y; o[2] = v.z;
}

double skinref_err3(const float *k, const double r[3])
{
	double dx = k[0] - r[0], dy = k[1] - r[1], dz = k[2] - r[2];
	return sqrt(dx * dx + dy * dy + dz * dz);
}

double skinref_height_of(const mesh *m)
{
	float lo = m->pos[0].y, hi = lo;
	for (int v = 1; v < m->vert_count; v++) {
		lo = fminf(lo, m->pos[v].y);
		hi = fmaxf(hi, m->pos[v].y);
	}
	return hi - lo;
}

/* skin_run's kernels against the portable ones, into b->simd_err */
static void compare_portable(skinref_kernels *k, skinref_body *b, int n)
{
	skin_out out = { k->spos, k->snrm, k->sfpos, k->sfnrm, NULL };
	skin_lbs_scalar(&k->soa, &k->bones, 0, n, &out);
	b->simd_err[SKIN_LBS] = fmax(b->simd_err[SKIN_LBS], fmax(test_max_diff(k->pos[SKIN_LBS], k->spos, 3 * n),
								   test_max_diff(k->nrm[SKIN_LBS], k->snrm, 3 * n)));
	skin_dqbs_scalar(&k->soa, &k->bones, 0, n, &out);
	b->simd_err[SKIN_DQBS] = fmax(b->simd_err[SKIN_DQBS], fmax(test_max_diff(k->pos[SKIN_DQBS], k->spos, 3 * n),
								     test_max_diff(k->nrm[SKIN_DQBS], k->snrm, 3 * n)));
	skin_dqbs_fixed(&k->soa, &k->bones, 0, n, &out);
	b->simd_err[SKIN_DQBS_FIXED] = fmax(b->simd_err[SKIN_DQBS_FIXED],
					    fmax(test_max_diff_i32(k->fpos, k->sfpos, 3 * n), test_max_diff_i32(k->fnrm, k->sfnrm, 3 * n)));
}

/* The compact streams' LBS and DQBS against the float streams' (pos, nrm
 * of skin_run), into b->compact_err */
static void compare_compact(skinref_kernels *k, skinref_body *b, int n)
{
	for (int a = SKIN_LBS; a <= SKIN_DQBS; a++) {
		skin_out out = { k->spos, NULL, NULL, NULL, k->nrm16 };
		skin_run_compact((skin_algo)a, &k->compact, &k->bones, 0, n, &out);
		for (int v = 0; v < n; v++) {
			double rp[3], rn[3];
			for (int i = 0; i < 3; i++) {
				rp[i] = k->pos[a][3 * v + i];
				rn[i] = k->nrm[a][3 * v + i];
			}
			const float n3[3] = { k->nrm16[3 * v] / SKIN_COMPACT_NORMAL_ONE, k->nrm16[3 * v + 1] / SKIN_COMPACT_NORMAL_ONE,
					      k->nrm16[3 * v + 2] / SKIN_COMPACT_NORMAL_ONE };
			b->compact_err[a] = fmax(b->compact_err[a], skinref_err3(&k->spos[3 * v], rp));
			b->compact_nrm_err[a] = fmax(b->compact_nrm_err[a], skinref_err3(n3, rn));
		}
	}
}

void skinref_run_kernels(skinref_kernels *k, skinref_body *b, const skel_pose *pose, int n)
{
	skin_bones_compute(&k->bones, b->skel, b->bind, pose);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		skin_out out = { k->pos[a], k->nrm[a], k->fpos, k->fnrm, NULL };
		skin_run((skin_algo)a, &k->soa, &k->bones, 0, n, &out);
	}
	compare_portable(k, b, n);
	if (b->mesh)
		compare_compact(k, b, n);
	for (int i = 0; i < 3 * n; i++) {
		k->pos[SKIN_DQBS_FIXED][i] = (float)(k->fpos[i] / 65536.0);
		k->nrm[SKIN_DQBS_FIXED][i] = (float)(k->fnrm[i] / 65536.0);
	}
}
