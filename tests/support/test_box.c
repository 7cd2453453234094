#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "test_box.h"

#include <stdlib.h>
#include <string.h>

#include "test_parse.h"
#include "test_paths.h"

void test_box_body(const skel *s, mesh *m, skin_weights *w)
{
	static const uint32_t tri[12][3] = {
		{ 0, 1, 2 }, { 0, 2, 3 }, { 4, 6, 5 }, { 4, 7, 6 }, { 0, 4, 5 }, { 0, 5, 1 },
		{ 1, 5, 6 }, { 1, 6, 2 }, { 2, 6, 7 }, { 2, 7, 3 }, { 3, 7, 4 }, { 3, 4, 0 },
	};
	memset(m, 0, sizeof *m);
	memset(w, 0, sizeof *w);
	for (int v = 0; v < 8; v++) {
		m->pos[v] = vec3_make(v & 1 ? 3.5f : -0.1f, v & 2 ? 0.3f : -0.3f, v & 4 ? 0.3f : -0.3f);
		m->normal[v] = vec3_normalize(m->pos[v]);
		w->count[v] = (uint8_t)(1 + v % 3);
		float sum = 0;
		for (int i = 0; i < w->count[v]; i++) {
			w->bone[v][i] = (uint16_t)((v + i) % s->count);
			w->weight[v][i] = 1.0f / (float)(i + 1 + v % 2);
			sum += w->weight[v][i];
		}
		for (int i = 0; i < w->count[v]; i++)
			w->weight[v][i] /= sum;
	}
	memcpy(m->tri, tri, sizeof tri);
	m->vert_count = w->vert_count = 8;
	m->tri_count = 12;
}

typedef struct frame_sink {
	amc_frame *frames;
	int count, cap;
} frame_sink;

static void keep_frame(const amc_frame *f, void *ctx)
{
	frame_sink *k = ctx;
	if (k->count < k->cap)
		k->frames[k->count++] = *f;
}

int test_tiny_inputs(skel *s, amc_frame *frames, int cap, mesh *m, skin_weights *w)
{
	skp_error err;
	size_t n;
	frame_sink k = { frames, 0, cap };
	assert_int_equal(test_parse_asf_file("tests/data/tiny.asf", s, &err), SKP_OK);
	char *amc = test_read_file("tests/data/tiny.amc", &n);
	assert_non_null(amc);
	assert_true(test_stream_amc(amc, n, s, &err, keep_frame, &k) > 0);
	free(amc);
	test_box_body(s, m, w);
	return k.count;
}
