#include "skin.h"

#include <string.h>

#include "skin_kernels.h"

#ifdef SKP_SIMD_AVX2
#define LBS skin_lbs_avx2
#define DQBS skin_dqbs_avx2
#define DQBS_FIXED skin_dqbs_fixed_avx2
#define SIMD_NAME "avx2+fma"
#define LBS_COMPACT skin_lbs_compact_avx2
#define DQBS_COMPACT skin_dqbs_compact_avx2
#elif defined(SKP_SIMD_NEON)
#define LBS skin_lbs_neon
#define DQBS skin_dqbs_neon
#define DQBS_FIXED skin_dqbs_fixed_neon
#define SIMD_NAME "neon"
#define LBS_COMPACT skin_lbs_compact_neon
#define DQBS_COMPACT skin_dqbs_compact_neon
#else
#define LBS skin_lbs_scalar
#define DQBS skin_dqbs_scalar
#define DQBS_FIXED skin_dqbs_fixed
#define SIMD_NAME "scalar"
#define LBS_COMPACT skin_lbs_compact_scalar
#define DQBS_COMPACT skin_dqbs_compact_scalar
#endif

const char *skin_simd_name(void)
{
	return SIMD_NAME;
}

void skin_run(skin_algo algo, const skin_soa *in, const skin_bones *b, int first, int count,
	      const skin_out *out)
{
	int end = first + count;
	if (end > in->count)
		end = in->count;
	switch (algo) {
	case SKIN_LBS: LBS(in, b, first, end, out); break;
	case SKIN_DQBS: DQBS(in, b, first, end, out); break;
	case SKIN_DQBS_FIXED: DQBS_FIXED(in, b, first, end, out); break;
	case SKIN_COMPARE: /* not a kernel: the caller skins LBS and DQBS */
	case SKIN_SHOW_COUNT: break;
	}
}

void skin_run_compact(skin_algo algo, const skin_compact *in, const skin_bones *b, int first, int count,
		      const skin_out *out)
{
	int end = first + count;
	if (end > in->count)
		end = in->count;
	if (algo == SKIN_LBS)
		LBS_COMPACT(in, b, first, end, out);
	else if (algo == SKIN_DQBS)
		DQBS_COMPACT(in, b, first, end, out);
}

void skin_slice(int padded, int slice, int slices, int *first, int *count)
{
	int lanes = padded / SKIN_LANES;
	*first = lanes * slice / slices * SKIN_LANES;
	*count = lanes * (slice + 1) / slices * SKIN_LANES - *first;
}
