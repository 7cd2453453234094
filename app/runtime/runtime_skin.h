/* A bound body ready for the kernels, for both programs (skintool skin,
 * skintool metrics, the renderer): pose the skeleton for a frame, compute
 * the bone transforms, run a kernel into float xyz arrays. The fixed-point
 * kernel's Q16.16 output is converted to float here, and only here. */
#ifndef RUNTIME_SKIN_H
#define RUNTIME_SKIN_H

#include "amc.h"
#include "skin.h"
#include "skin_compact.h"
#include "workers.h"

/* Measuring whether the pool pays (runtime_skin_measure_workers). */
typedef struct runtime_skin_tune {
	int on;                                /* still measuring */
	int choice;                            /* -1 none yet, 1 the pool kept, 0 one thread */
	int total;                             /* runs measured */
	int seen[SKIN_ALGO_COUNT];             /* runs per algorithm, the unmeasured first too */
	int runs[SKIN_ALGO_COUNT][2];          /* [algorithm][0 one thread, 1 the pool] */
	uint64_t ns[SKIN_ALGO_COUNT][2];
	double one_ms, pool_ms;                /* mean of a run, summed over the algorithms */
} runtime_skin_tune;

typedef struct runtime_skin {
	const skel *skel;
	const skel_pose *bind;
	skin_soa soa;         /* lives in one static block: one runtime_skin at a time */
	skel_pose pose;       /* the current pose */
	skin_bones bones;     /* its transforms */
	skin_compact compact; /* LBS and DQBS read these when use_compact */
	int use_compact;
	workers *pool;        /* NULL: the caller's thread skins alone */
	runtime_skin_tune tune;
} runtime_skin;

/* Lays the mesh and its weights out for the kernels (the mesh is bound in
 * pose bind of s) and poses the body in bind. what names the mesh in
 * messages. Returns 0, or -1 after reporting the error. */
int runtime_skin_init(runtime_skin *t, const skel *s, const skel_pose *bind, const mesh *m,
		   const skin_weights *w, const char *what);

/* Poses the skeleton for one frame (values of an amc_frame; NULL: the ASF
 * rest pose) and computes the bone transforms. */
void runtime_skin_frame(runtime_skin *t, const float *values);

/* The same for a pose computed elsewhere (the synthetic scene). */
void runtime_skin_pose(runtime_skin *t, const skel_pose *pose);

/* After runtime_skin_init (which leaves the pool out): from now on every
 * thread of pool skins its share of the mesh (results identical to one
 * thread's); pool NULL: the caller's thread alone. Worth it only for a
 * mesh big enough to pay for waking the pool: the caller decides. */
void runtime_skin_use_workers(runtime_skin *t, workers *pool);

/* As runtime_skin_use_workers, for a board where nobody measured the mesh
 * size from which threads pay: the first RUNTIME_SKIN_TUNE_RUNS kernel runs
 * alternate, per algorithm, between the pool and the caller's thread alone
 * (each algorithm's first run, with cold caches, left out), and the pool
 * stays only if its runs took at most 0.9x as long (runtime_skin_tune_pick).
 * Either way the results are the same. */
#define RUNTIME_SKIN_TUNE_RUNS 48
void runtime_skin_measure_workers(runtime_skin *t, workers *pool);

/* What the measurement chose: -1 while it runs (or none was asked for), 1
 * the pool, 0 one thread; the mean ms of a kernel run each way in *one_ms,
 * *pool_ms. */
int runtime_skin_measured(const runtime_skin *t, double *one_ms, double *pool_ms);

/* The choice from each algorithm's totals (runs[a][1] on the pool), over
 * the algorithms measured both ways: 1 when the pool's mean runs, summed,
 * took at most 0.9x one thread's, 0 when not, -1 when no algorithm was
 * measured both ways; the sums of the means in *one_ms, *pool_ms. */
int runtime_skin_tune_pick(const uint64_t ns[][2], const int runs[][2], int algos, double *one_ms,
		       double *pool_ms);

/* After runtime_skin_init: LBS and DQBS read compact streams (skin_compact.h,
 * made here from the float ones) from now on, through runtime_skin_run16. */
void runtime_skin_use_compact(runtime_skin *t);

/* Whether runtime_skin_run16 can skin algo: compact streams in use, and LBS or
 * DQBS (the fixed-point kernel has its own streams). */
int runtime_skin_compact(const runtime_skin *t, skin_algo algo);

/* runtime_skin_run over the compact streams: positions as float xyz, normals as
 * 16-bit snorm xyz. Only where runtime_skin_compact says so. */
void runtime_skin_run16(runtime_skin *t, skin_algo algo, float *pos, int16_t *nrm16);

/* Whether runtime_skin_run splits the current mesh across threads: their
 * count (also while it measures whether to), 1 when it does not. */
int runtime_skin_threads(const runtime_skin *t);

/* Skins every vertex with algo in the current pose: 3 floats per vertex
 * into pos and into nrm. */
void runtime_skin_run(runtime_skin *t, skin_algo algo, float *pos, float *nrm);


#endif
