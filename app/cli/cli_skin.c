#include "cli_skin.h"

#include <stdio.h>

#include "cli_common.h"

static _Alignas(SKIN_ALIGN) unsigned char block[SKIN_SOA_BYTES(SKP_MAX_VERTS)];
static _Alignas(SKIN_ALIGN) unsigned char compact_block[SKIN_COMPACT_BYTES(SKP_MAX_VERTS)];
/* The fixed-point kernel's output before conversion. */
static int32_t fpos[3 * SKP_MAX_VERTS], fnrm[3 * SKP_MAX_VERTS];

int cli_skin_init(cli_skin *t, const skel *s, const skel_pose *bind, const mesh *m,
		   const skin_weights *w, const char *what)
{
	skp_error err;
	if (m->vert_count > SKP_MAX_VERTS || skin_soa_bytes(m->vert_count) > sizeof block) {
		fprintf(stderr, "%s: %d vertices do not fit the skinning buffers\n", what,
			m->vert_count);
		return -1;
	}
	t->skel = s;
	t->bind = bind;
	t->pool = NULL;
	t->use_compact = 0;
	skin_soa_attach(&t->soa, block, m->vert_count);
	if (skin_soa_load(&t->soa, m, w, s->count, &err) != SKP_OK) {
		cli_error(what, &err);
		return -1;
	}
	cli_skin_pose(t, bind);
	return 0;
}

void cli_skin_pose(cli_skin *t, const skel_pose *pose)
{
	if (pose != &t->pose)
		t->pose = *pose;
	skin_bones_compute(&t->bones, t->skel, t->bind, &t->pose);
}

void cli_skin_frame(cli_skin *t, const float *values)
{
	fk_pose(t->skel, values, &t->pose);
	cli_skin_pose(t, &t->pose);
}

static void from_q16(const int32_t *in, float *out, int n)
{
	for (int i = 0; i < n; i++)
		out[i] = (float)in[i] * (1.0f / 65536.0f);
}

void cli_skin_use_workers(cli_skin *t, workers *pool)
{
	t->pool = pool;
}

int cli_skin_threads(const cli_skin *t)
{
	return t->pool ? workers_count(t->pool) : 1;
}

void cli_skin_use_compact(cli_skin *t)
{
	skin_compact_attach(&t->compact, compact_block, t->soa.count);
	skin_compact_load(&t->compact, &t->soa);
	t->use_compact = 1;
}

int cli_skin_compact(const cli_skin *t, skin_algo algo)
{
	return t->use_compact && (algo == SKIN_LBS || algo == SKIN_DQBS);
}

typedef struct skin_job {
	const cli_skin *t;
	skin_algo algo;
	int compact;
	skin_out out;
} skin_job;

static void run_part(const skin_job *j, int first, int count)
{
	if (j->compact)
		skin_run_compact(j->algo, &j->t->compact, &j->t->bones, first, count, &j->out);
	else
		skin_run(j->algo, &j->t->soa, &j->t->bones, first, count, &j->out);
}

static void run_share(void *ctx, int slice, int slices)
{
	const skin_job *j = ctx;
	int first, count;
	skin_slice(j->t->soa.padded, slice, slices, &first, &count);
	run_part(j, first, count);
}

static void run_kernel(cli_skin *t, skin_algo algo, int compact, const skin_out *out)
{
	skin_job job = { t, algo, compact, *out };
	if (cli_skin_threads(t) > 1)
		workers_run(t->pool, run_share, &job);
	else
		run_part(&job, 0, t->soa.count);
}

void cli_skin_run16(cli_skin *t, skin_algo algo, float *pos, int16_t *nrm16)
{
	skin_out out = { pos, NULL, NULL, NULL, nrm16 };
	run_kernel(t, algo, 1, &out);
}

void cli_skin_run(cli_skin *t, skin_algo algo, float *pos, float *nrm)
{
	int n = t->soa.count;
	if (algo != SKIN_DQBS_FIXED) {
		skin_out out = { pos, nrm, NULL, NULL, NULL };
		run_kernel(t, algo, 0, &out);
		return;
	}
	skin_out out = { NULL, NULL, fpos, fnrm, NULL };
	run_kernel(t, algo, 0, &out);
	from_q16(fpos, pos, 3 * n);
	from_q16(fnrm, nrm, 3 * n);
}

