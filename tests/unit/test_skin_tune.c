/* Whether skinning threads pay, by measurement (runtime_skin_measure_workers):
 * the choice from per-algorithm totals, and the alternation itself on a
 * real body and pool, which must give one thread's results whatever it
 * chooses. The times are the machine's: no choice is asserted for them. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "cli_bind_args.h"
#include "runtime_body.h"
#include "runtime_skin.h"
#include "setup_bind.h"
#include "test_run.h"

enum { ONE, POOL };

static void test_pick(void **state)
{
	(void)state;
	double one, pool;
	/* LBS: 4 runs each way, 1.0 ms alone, 0.5 on the pool; DQBS only
	 * alone (left out); fixed 2.0 and 1.0 */
	uint64_t ns[SKIN_ALGO_COUNT][2] = { { 4000000, 2000000 }, { 3000000, 0 }, { 8000000, 4000000 } };
	int runs[SKIN_ALGO_COUNT][2] = { { 4, 4 }, { 3, 0 }, { 4, 4 } };
	assert_int_equal(runtime_skin_tune_pick(ns, runs, SKIN_ALGO_COUNT, &one, &pool), 1);
	assert_float_equal(one, 3.0, 1e-9);
	assert_float_equal(pool, 1.5, 1e-9);
	/* within 10%: not worth the threads */
	ns[0][POOL] = 3800000;
	ns[2][POOL] = 7200000;
	assert_int_equal(runtime_skin_tune_pick(ns, runs, SKIN_ALGO_COUNT, &one, &pool), 0);
	assert_float_equal(pool, 2.75, 1e-9);
	ns[2][POOL] = 6600000; /* 2.6 ms: 0.87x */
	assert_int_equal(runtime_skin_tune_pick(ns, runs, SKIN_ALGO_COUNT, &one, &pool), 1);
	ns[2][POOL] = 7200000;
	/* slower on the pool */
	ns[0][POOL] = 9000000;
	assert_int_equal(runtime_skin_tune_pick(ns, runs, SKIN_ALGO_COUNT, &one, &pool), 0);
	/* nothing measured both ways */
	int none[SKIN_ALGO_COUNT][2] = { { 4, 0 }, { 0, 0 }, { 0, 3 } };
	assert_int_equal(runtime_skin_tune_pick(ns, none, SKIN_ALGO_COUNT, &one, &pool), -1);
}

static bound_body body;
static float pos[2][3 * SKP_MAX_VERTS], nrm[2][3 * SKP_MAX_VERTS];

/* The generated body on the repository's small skeleton, ready to skin
 * (each runtime_skin_init takes the one static vertex block anew). */
static void load_body(runtime_skin *t)
{
	static int loaded;
	if (!loaded) {
		bind_args a;
		bind_args_init(&a);
		assert_int_equal(setup_bind_load(&a, "tests/data/tiny.asf", NULL, &body), 0);
		loaded = 1;
	}
	assert_int_equal(runtime_skin_init(t, &body.skel, &body.pose, &body.mesh, &body.weights, "body"), 0);
}

static void test_measuring_alternates_and_decides(void **state)
{
	(void)state;
	test_skip_threads_if_emulated();
	static runtime_skin t, ref;
	load_body(&ref);
	runtime_skin_run(&ref, SKIN_DQBS, pos[0], nrm[0]);
	load_body(&t);
	workers *w = workers_start(2);
	assert_non_null(w);
	runtime_skin_measure_workers(&t, w);
	double one, pool;
	int runs = 0;
	/* LBS and DQBS in turn, as the compare view runs them */
	while (runtime_skin_measured(&t, &one, &pool) < 0) {
		assert_int_equal(runtime_skin_threads(&t), 2);
		skin_algo a = runs % 2 ? SKIN_DQBS : SKIN_LBS;
		runtime_skin_run(&t, a, pos[1], nrm[1]);
		runs++;
		assert_true(runs <= RUNTIME_SKIN_TUNE_RUNS + 2);
	}
	/* each algorithm's first run is not measured */
	assert_int_equal(runs, RUNTIME_SKIN_TUNE_RUNS + 2);
	assert_int_equal(t.tune.runs[SKIN_LBS][0], t.tune.runs[SKIN_LBS][1]);
	assert_int_equal(t.tune.runs[SKIN_DQBS][0], t.tune.runs[SKIN_DQBS][1]);
	assert_true(one > 0 && pool > 0);
	int chosen = runtime_skin_measured(&t, &one, &pool);
	print_message("two threads %.3f ms, one %.3f ms a run: %s\n", pool, one, chosen ? "the pool" : "one thread");
	assert_int_equal(runtime_skin_threads(&t), chosen ? 2 : 1);
	runtime_skin_run(&t, SKIN_DQBS, pos[1], nrm[1]);
	assert_memory_equal(pos[0], pos[1], sizeof(float) * 3 * (size_t)body.mesh.vert_count);
	assert_memory_equal(nrm[0], nrm[1], sizeof(float) * 3 * (size_t)body.mesh.vert_count);
	workers_stop(w);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_pick),
		cmocka_unit_test(test_measuring_alternates_and_decides),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
