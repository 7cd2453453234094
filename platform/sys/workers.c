#include "workers.h"

#include <pthread.h>
#include <unistd.h>

struct workers {
	int count;
	pthread_t thread[WORKERS_MAX];
	pthread_barrier_t start, done;
	workers_fn fn;
	void *ctx;
	int quit;
	int slice_of[WORKERS_MAX];
};

/* One static pool: the process starts it once and never allocates. */
static workers pool;

static void *worker_main(void *arg)
{
	int *slice = arg;
	for (;;) {
		pthread_barrier_wait(&pool.start);
		if (pool.quit)
			return NULL;
		pool.fn(pool.ctx, *slice, pool.count);
		pthread_barrier_wait(&pool.done);
	}
}

workers *workers_start(int threads)
{
	if (threads < 1 || threads > WORKERS_MAX || pool.count)
		return NULL;
	pool.count = threads;
	pool.quit = 0;
	if (threads == 1)
		return &pool;
	pthread_barrier_init(&pool.start, NULL, (unsigned)threads);
	pthread_barrier_init(&pool.done, NULL, (unsigned)threads);
	for (int i = 1; i < threads; i++) {
		pool.slice_of[i] = i;
		/* The threads already started stay parked on the start barrier,
		 * which can never fill: harmless, and the caller runs alone. */
		if (pthread_create(&pool.thread[i], NULL, worker_main, &pool.slice_of[i]) != 0)
			return NULL;
	}
	return &pool;
}

void workers_run(workers *w, workers_fn fn, void *ctx)
{
	w->fn = fn;
	w->ctx = ctx;
	if (w->count == 1) {
		fn(ctx, 0, 1);
		return;
	}
	pthread_barrier_wait(&w->start);
	fn(ctx, 0, w->count);
	pthread_barrier_wait(&w->done);
}

int workers_count(const workers *w)
{
	return w->count;
}

int workers_cpu_count(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);
	return n < 1 ? 1 : n > WORKERS_MAX ? WORKERS_MAX : (int)n;
}

void workers_stop(workers *w)
{
	if (w->count > 1) {
		w->quit = 1;
		pthread_barrier_wait(&w->start);
		for (int i = 1; i < w->count; i++)
			pthread_join(w->thread[i], NULL);
		pthread_barrier_destroy(&w->start);
		pthread_barrier_destroy(&w->done);
	}
	w->count = 0;
}
