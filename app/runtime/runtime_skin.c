#include "runtime_skin.h"

#include <string.h>

#include "cli_error.h"
#include "cli_say.h"
#include "clock.h"

static _Alignas(SKIN_ALIGN) unsigned char block[SKIN_SOA_BYTES(SKP_MAX_VERTS)];
static _Alignas(SKIN_ALIGN) unsigned char compact_block[SKIN_COMPACT_BYTES(SKP_MAX_VERTS)];
/* The fixed-point kernel's output before conversion. */
static int32_t fpos[3 * SKP_MAX_VERTS], fnrm[3 * SKP_MAX_VERTS];

static void tune_reset(runtime_skin_tune *u, int on)
{
	memset(u, 0, sizeof *u);
	u->choice = -1;
	u->on = on;
}

int runtime_skin_init(runtime_skin *t, const skel *s, const skel_pose *bind, const mesh *m,
		   const skin_weights *w, const char *what)
{
	skp_error err;
	if (m->vert_count > SKP_MAX_VERTS || skin_soa_bytes(m->vert_count) > sizeof block) {
		cli_warn("%s: %d vertices do not fit the skinning buffers\n", what,
			m->vert_count);
		return -1;
	}
	t->skel = s;
	t->bind = bind;
	t->pool = NULL;
	tune_reset(&t->tune, 0);
	t->use_compact = 0;
	skin_soa_attach(&t->soa, block, m->vert_count);
	if (skin_soa_load(&t->soa, m, w, s->count, &err) != SKP_OK) {
		cli_error(what, &err);
		return -1;
	}
	runtime_skin_pose(t, bind);
	return 0;
}

void runtime_skin_pose(runtime_skin *t, const skel_pose *pose)
{
	if (pose != &t->pose)
		t->pose = *pose;
	skin_bones_compute(&t->bones, t->skel, t->bind, &t->pose);
}

void runtime_skin_frame(runtime_skin *t, const float *values)
{
	fk_pose(t->skel, values, &t->pose);
	runtime_skin_pose(t, &t->pose);
}

static void from_q16(const int32_t *in, float *out, int n)
{
	for (int i = 0; i < n; i++)
		out[i] = (float)in[i] * (1.0f / 65536.0f);
}

void runtime_skin_use_workers(runtime_skin *t, workers *pool)
{
	t->pool = pool;
}

void runtime_skin_measure_workers(runtime_skin *t, workers *pool)
{
	runtime_skin_use_workers(t, pool);
	tune_reset(&t->tune, pool != NULL && workers_count(pool) > 1);
}

int runtime_skin_measured(const runtime_skin *t, double *one_ms, double *pool_ms)
{
	*one_ms = t->tune.one_ms;
	*pool_ms = t->tune.pool_ms;
	return t->tune.choice;
}

int runtime_skin_tune_pick(const uint64_t ns[][2], const int runs[][2], int algos, double *one_ms,
		       double *pool_ms)
{
	double mean[2] = { 0, 0 };
	int both = 0;
	for (int a = 0; a < algos; a++) {
		if (!runs[a][0] || !runs[a][1])
			continue;
		both++;
		for (int m = 0; m < 2; m++)
			mean[m] += (double)ns[a][m] * 1e-6 / runs[a][m];
	}
	*one_ms = mean[0];
	*pool_ms = mean[1];
	return both ? mean[1] <= 0.9 * mean[0] : -1;
}

int runtime_skin_threads(const runtime_skin *t)
{
	return t->pool && t->tune.choice != 0 ? workers_count(t->pool) : 1;
}

/* While measuring: whether this run of algo goes to the pool (-1: the
 * algorithm's first, unmeasured, on one thread). */
static int tune_mode(const runtime_skin_tune *u, skin_algo algo)
{
	if (u->seen[algo] == 0)
		return -1;
	return u->runs[algo][0] > u->runs[algo][1];
}

static void tune_note(runtime_skin_tune *u, skin_algo algo, int mode, uint64_t ns)
{
	u->seen[algo]++;
	if (mode < 0)
		return;
	u->runs[algo][mode]++;
	u->ns[algo][mode] += ns;
	if (++u->total < RUNTIME_SKIN_TUNE_RUNS)
		return;
	u->choice = runtime_skin_tune_pick((const uint64_t (*)[2])u->ns, (const int (*)[2])u->runs, SKIN_ALGO_COUNT,
				       &u->one_ms, &u->pool_ms);
	u->on = 0;
}

void runtime_skin_use_compact(runtime_skin *t)
{
	skin_compact_attach(&t->compact, compact_block, t->soa.count);
	skin_compact_load(&t->compact, &t->soa);
	t->use_compact = 1;
}

int runtime_skin_compact(const runtime_skin *t, skin_algo algo)
{
	return t->use_compact && (algo == SKIN_LBS || algo == SKIN_DQBS);
}

typedef struct skin_job {
	const runtime_skin *t;
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

static void run_kernel(runtime_skin *t, skin_algo algo, int compact, const skin_out *out)
{
	skin_job job = { t, algo, compact, *out };
	int mode = t->tune.on ? tune_mode(&t->tune, algo) : runtime_skin_threads(t) > 1;
	uint64_t t0 = t->tune.on ? clock_now_ns() : 0;
	if (mode > 0)
		workers_run(t->pool, run_share, &job);
	else
		run_part(&job, 0, t->soa.count);
	if (t->tune.on)
		tune_note(&t->tune, algo, mode, clock_now_ns() - t0);
}

void runtime_skin_run16(runtime_skin *t, skin_algo algo, float *pos, int16_t *nrm16)
{
	skin_out out = { pos, NULL, NULL, NULL, nrm16 };
	run_kernel(t, algo, 1, &out);
}

void runtime_skin_run(runtime_skin *t, skin_algo algo, float *pos, float *nrm)
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

