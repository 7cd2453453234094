/* Every shared clip (../shared/data) through the codec (app/codec,
 * app/encode): each encodes within 0.01 cm of ACL's shell error (3 cm
 * points) on every frame, as decoded here segment by segment; the sizes
 * and ratios are printed. The codec's unit tests (tests/unit/test_codec.c)
 * take a few clips and broken input. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "test_clips.h"
#include "test_codec_clip.h"
#include "test_paths.h"

static void test_every_shared_clip(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	const int slow = test_slow();
	for (int i = 0; i < test_clip_count; i++) {
		/* under the sanitizers or an emulator (the encoder's search: 25 ms
		 * a frame under qemu) the first clip of each source (their units
		 * and skeletons differ), its first second: the same code, and
		 * make test natively checks every clip whole */
		if (slow && test_clip_source_seen(i))
			continue;
		static codec_test_clip c;
		encode_result r;
		assert_int_equal(codec_test_load(test_clips[i].asf, test_clips[i].amc, &c), 0);
		if (slow && c.n > 120)
			c.n = 120;
		codec_test_encode(&c, &r);
		double worst = codec_test_decode_all(&c, &r, NULL);
		double raw = 40.0 * c.s.count * (double)c.n;
		print_message("%s: %ld frames, %.1f bytes a frame, %.1f:1, worst %.4f cm (encoder: %.4f, p99 %.4f)\n",
			      test_clips[i].amc, c.n, (double)r.nbytes / (double)c.n, raw / (double)r.nbytes, worst,
			      r.worst * c.cm, r.p99 * c.cm);
		assert_true(worst <= CODEC_TEST_BUDGET_CM);
		assert_true(fabs(worst - r.worst * c.cm) < 1e-9);
		encode_result_free(&r);
		free(c.frames);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_shared_clip),
	};
	return cmocka_run_group_tests_name("codec_corpus", tests, NULL, NULL);
}
