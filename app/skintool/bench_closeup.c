/* What the compare view's close-up and the difference view add to a
 * frame on the CPU, next to the two kernels the compare view runs: per
 * vertex, LBS's distance from DQBS with the largest per joint
 * (skin_diff_between), where on the chosen joint they part
 * (skin_diff_focus) and the difference view's colours
 * (render_diff_colours). tests/count_insns.sh counts their instructions
 * on the rpi4 build as it counts the NEON kernels'. */
#include <stdio.h>
#include <stdlib.h>

#include "bench_closeup.h"
#include "clock.h"
#include "render.h"
#include "skin_diff.h"

#define CLOSEUP_BONES 31

/* Joints scattered through the mesh's box (-1..1), for the vertices to be
 * sorted among. */
static void make_skeleton(skel *s, skel_pose *bind)
{
	unsigned long long x = 0x2545f4914f6cdd1dull;
	s->count = CLOSEUP_BONES;
	for (int b = 0; b < CLOSEUP_BONES; b++) {
		float c[3];
		for (int k = 0; k < 3; k++) {
			x ^= x << 13, x ^= x >> 7, x ^= x << 17;
			c[k] = (float)(x >> 40) / (float)(1ull << 24) * 2.0f - 1.0f;
		}
		bind->head[b] = vec3_make(c[0], c[1], c[2]);
		bind->tip[b] = vec3_make(c[0] + 0.1f, c[1], c[2]);
	}
}

int bench_closeup(const skin_soa *soa, const skin_bones *bones, double kernels_ns, int rounds)
{
	static skin_diff d;
	static skel s;
	static skel_pose bind;
	int n = soa->count;
	if (n > SKP_MAX_VERTS) {
		printf("close-up and difference view: skipped (%d vertices, the board's limit is %d)\n", n, SKP_MAX_VERTS);
		return 0;
	}
	size_t pad = (size_t)soa->padded + SKIN_LANES;
	float *a = malloc(sizeof(float) * 3 * pad * 3), *dist = malloc(sizeof(float) * (size_t)n);
	uint8_t *rgba = malloc(4 * (size_t)n);
	if (!a || !dist || !rgba) {
		free(a), free(dist), free(rgba);
		fprintf(stderr, "skintool bench: out of memory for the close-up's %d vertices\n", n);
		return -1;
	}
	float *b = a + 3 * pad, *nrm = b + 3 * pad;
	make_skeleton(&s, &bind);
	skin_diff_init(&d, &s, &bind, NULL, soa);
	skin_run(SKIN_LBS, soa, bones, 0, soa->padded, &(skin_out){ .pos = a, .nrm = nrm });
	skin_run(SKIN_DQBS, soa, bones, 0, soa->padded, &(skin_out){ .pos = b, .nrm = nrm });
	double best[3] = { 1e30, 1e30, 1e30 };
	for (int r = 0; r < rounds; r++) {
		uint64_t t0 = clock_now_ns();
		skin_diff_between(&d, a, b, NULL);
		uint64_t t1 = clock_now_ns();
		(void)skin_diff_focus(&d, &bind, a, b, skin_diff_worst(&d));
		uint64_t t2 = clock_now_ns();
		skin_diff_between(&d, a, b, dist);
		render_diff_colours(dist, n, 25.4f, 0, rgba);
		uint64_t t3 = clock_now_ns();
		double ns[3] = { (double)(t1 - t0) / n, (double)(t2 - t1) / n, (double)(t3 - t2) / n };
		for (int k = 0; k < 3; k++)
			best[k] = ns[k] < best[k] ? ns[k] : best[k];
	}
	printf("close-up: %.2f ns/vert (where LBS and DQBS part %.2f, where on the joint %.2f), %.2fx the LBS and "
	       "DQBS kernels' %.2f ns/vert of a compare frame\n", best[0] + best[1], best[0], best[1],
	       (best[0] + best[1]) / kernels_ns, kernels_ns);
	printf("difference view: %.2f ns/vert (distances and colours), %.2fx the two kernels\n", best[2],
	       best[2] / kernels_ns);
	free(a), free(dist), free(rgba);
	return 0;
}
