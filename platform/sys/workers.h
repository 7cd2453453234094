/* A fixed pool of worker threads, created once at start-up, that run one
 * job split into slices: the skinning kernels use it for `--threads`. */
#ifndef WORKERS_H
#define WORKERS_H

#define WORKERS_MAX 16

typedef void (*workers_fn)(void *ctx, int slice, int slices);

typedef struct workers workers;

/* threads >= 1 (1: everything runs on the caller). NULL on failure. */
workers *workers_start(int threads);
/* Runs fn(ctx, i, n) for i in 0..n-1, slice 0 on the caller; returns when
 * all slices are done. */
void workers_run(workers *w, workers_fn fn, void *ctx);
int workers_count(const workers *w);
/* Cores online (at most WORKERS_MAX; 1 when the system does not say). */
int workers_cpu_count(void);
void workers_stop(workers *w);

#endif
