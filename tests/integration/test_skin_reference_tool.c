/* `skintool skin` writes exactly the skinning kernel's output (through
 * skin_run, so the SIMD ones when built), in the input's vertex order,
 * with the input's faces: the generated body of CMU subject 02 at frame
 * 100 of 02_01.amc, bound as the tool binds it, for every algorithm. The
 * kernels against a double-precision reference: test_skin_reference.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bind.h"
#include "bind_balance.h"
#include "obj.h"
#include "skin.h"
#include "test_parse.h"
#include "test_paths.h"
#include "test_run.h"
#include "test_skinref.h"

static skinref_kernels kern;
static skinref_cmu02 cmu;
static int have_skel;

/* The skeleton only: the test binds the body skintool writes (a bind of
 * the generated body here went unused, seconds under qemu). */
static int setup(void **state)
{
	(void)state;
	have_skel = !skinref_cmu02_skel(&cmu);
	return 0;
}

/* ---- skintool skin writes the kernel's output ---- */

static void parse_obj(const char *path, mesh *out)
{
	static obj_work work;
	static text_lines tl;
	skp_mem_source src;
	skp_error err;
	size_t len;
	char *text = test_read_file(path, &len);
	assert_non_null(text);
	text_lines_init(&tl, skp_mem_reader(&src, text, len));
	skp_status rc = obj_parse(out, &work, &tl, NULL, &err);
	free(text);
	if (rc != SKP_OK)
		fail_msg("%s:%ld: %s", path, err.line, err.msg);
}

static void frame_values(const amc_frame *f, void *ctx)
{
	amc_frame *want = ctx;
	if (f->number == want->number)
		*want = *f;
}

static void sh(const char *cmd)
{
	if (system(cmd) != 0)
		fail_msg("failed: %s", cmd);
}

static void check_written(const mesh *in, const mesh *out, skin_algo a, double height)
{
	assert_int_equal(out->vert_count, in->vert_count);
	assert_int_equal(out->tri_count, in->tri_count);
	assert_memory_equal(out->tri, in->tri, sizeof in->tri[0] * (size_t)in->tri_count);
	double perr = 0, nerr = 0;
	for (int v = 0; v < in->vert_count; v++) {
		double p[3], n[3];
		const float *kn = &kern.nrm[a][3 * v];
		float unit[3];   /* the OBJ reader normalises vn; fixed point is unit to 2^-16 */
		float len = sqrtf(kn[0] * kn[0] + kn[1] * kn[1] + kn[2] * kn[2]);
		for (int k = 0; k < 3; k++)
			unit[k] = kn[k] / len;
		skinref_d3(out->pos[v], p);
		skinref_d3(out->normal[v], n);
		perr = fmax(perr, skinref_err3(&kern.pos[a][3 * v], p));
		nerr = fmax(nerr, skinref_err3(unit, n));
	}
	print_message("skintool skin --algo %s: %d vertices, %d faces as given; max difference from the kernel: position %.3g, normal %.3g\n",
		      skin_algo_name(a), out->vert_count, out->tri_count, perr, nerr);
	assert_true(perr <= 1e-7 * height); /* %.9g round-trips a float */
	assert_true(nerr < 1e-5);           /* normals are written with %.6g */
}

static void test_skintool_skin_output(void **state)
{
	(void)state;
	const char *asf = test_data_path("mocap/cmu/02.asf"), *amc = test_data_path("mocap/cmu/02_01.amc");
	if (!have_skel || !amc)
		skip();
	static mesh in, out;
	static skin_weights w;
	static bind_rig rig;
	static bind_balance_work balance;
	static amc_frame f;
	static skel_pose pose;
	char dir[] = "/tmp/skp_skin_XXXXXX", cmd[4096], body_obj[256], out_obj[256];
	skp_error err;
	assert_non_null(mkdtemp(dir));
	snprintf(body_obj, sizeof body_obj, "%s/body.obj", dir);
	snprintf(out_obj, sizeof out_obj, "%s/out.obj", dir);
	/* under the sanitizers or an emulator a coarser generated body (the
	 * default one's binds, here and in each skintool skin, took 8 and 12 s
	 * under qemu) */
	snprintf(cmd, sizeof cmd, "%s mannequin %s %s -o %s >/dev/null", test_tool_path("skintool"), asf,
		 test_mannequin_detail(), body_obj);
	sh(cmd);
	/* the tool's inputs, loaded and bound as it does */
	parse_obj(body_obj, &in);
	bind_prepare(&rig, &cmu.skel, &cmu.rest, NULL);
	assert_int_equal(bind_weights(&rig, in.pos, in.vert_count, &w, NULL, &err), SKP_OK);
	assert_int_equal(bind_balance(&cmu.skel, &cmu.rest, in.pos, in.vert_count, (const uint32_t (*)[3])in.tri,
				      in.tri_count, &w, &balance, NULL, &err), SKP_OK);
	skin_soa_attach(&kern.soa, kern.block, in.vert_count);
	assert_int_equal(skin_soa_load(&kern.soa, &in, &w, cmu.skel.count, &err), SKP_OK);
	size_t len;
	char *text = test_read_file(amc, &len);
	f.number = 100;
	test_stream_amc(text, len, &cmu.skel, &err, frame_values, &f);
	free(text);
	fk_pose(&cmu.skel, f.value, &pose);
	skinref_body tool = { .skel = &cmu.skel, .bind = &cmu.rest };
	skinref_run_kernels(&kern, &tool, &pose, in.vert_count);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		/* under the sanitizers or an emulator (each run binds the body
		 * again) the two DQBS kernels, float and fixed-point; the native
		 * run checks LBS too */
		if (test_slow() && a == SKIN_LBS)
			continue;
		snprintf(cmd, sizeof cmd, "%s skin %s %s %s --frame 100 --algo %s -o %s", test_tool_path("skintool"),
			 asf, amc, body_obj, skin_algo_name((skin_algo)a), out_obj);
		sh(cmd);
		parse_obj(out_obj, &out);
		check_written(&in, &out, (skin_algo)a, skinref_height_of(&in));
	}
	unlink(body_obj);
	unlink(out_obj);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_skintool_skin_output),
	};
	return cmocka_run_group_tests_name("skin_reference_tool", tests, setup, NULL);
}
