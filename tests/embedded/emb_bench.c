/* The embedded skinning benchmark: the fixed-point DQBS kernel and the float
 * DQBS kernel (soft-float on a Cortex-M0, the FPU's single precision on a
 * Cortex-M4F) skin the test body (emb_tables.h, emb_float_tables.h: the
 * host's inputs of both kernels) for BENCH_FRAMES frames, each run between
 * emb_count_begin and emb_count_end. QEMU has no cycle counter worth the
 * name: tests/embedded/mcu_count.sh runs this program one instruction per
 * translation block with every instruction logged and counts those
 * executed between the two marks (the kernels and everything they call:
 * libgcc's soft-float and 64-bit helpers, libm), then divides by the
 * vertices this program says it skinned. The fixed kernel's output also
 * goes into a checksum, which must equal the host build's.
 *
 * No malloc, no stdio: output through emb_puts (emb_port.h). */
#include <stdint.h>
#include <string.h>

#include "emb_port.h"
#include "emb_tables.h"
#include "emb_float_tables.h" /* after emb_tables.h: its sizes */
#include "emb_soa.h"
#include "skin_kernels.h"

/* One frame: the counts a vertex are the figure, and the fixed kernel's
 * hardly move with the pose (2974.8 on the first frame, 2974.6 over two);
 * soft-float's do by a few per cent (15,199 and 15,948), as on a device.
 * Two frames took twice as long (170 processor seconds in CI). */
#ifndef BENCH_FRAMES
#define BENCH_FRAMES 1
#endif
_Static_assert(BENCH_FRAMES <= EMB_FRAMES, "the tables hold EMB_FRAMES frames");

static skin_bones bones;
static int32_t out_fpos[3 * EMB_PADDED], out_fnrm[3 * EMB_PADDED];
static float out_pos[3 * EMB_PADDED], out_nrm[3 * EMB_PADDED];
static float in_float[6 + SKP_MAX_INFLUENCES][EMB_PADDED];

/* What the counter sees: a write the compiler cannot drop, in two
 * functions it cannot merge. */
static volatile int counting = -1;

__attribute__((noinline)) void emb_count_begin(int kernel);
__attribute__((noinline)) void emb_count_end(void);
void emb_count_begin(int kernel)
{
	counting = kernel;
}

void emb_count_end(void)
{
	counting = -1;
}

static float from_bits(uint32_t u)
{
	float x;
	memcpy(&x, &u, sizeof x);
	return x;
}

static void load_bones(int frame)
{
	bones.count = EMB_BONES;
	for (int b = 0; b <= EMB_BONES; b++) {
		const int32_t *v = emb_fdq[frame][b];
		const uint32_t *u = emb_dq_bits[frame][b];
		int slot = b == EMB_BONES ? SKIN_IDENTITY_BONE : b;
		fx_dq d = { { v[0], v[1], v[2], v[3] }, { v[4], v[5], v[6], v[7] } };
		dq q = { { from_bits(u[0]), from_bits(u[1]), from_bits(u[2]), from_bits(u[3]) },
			 { from_bits(u[4]), from_bits(u[5]), from_bits(u[6]), from_bits(u[7]) } };
		bones.fdq[slot] = d;
		bones.dq[slot] = q;
	}
}

/* The fixed input in place in flash (emb_soa.h), the floats copied out of
 * their bit patterns once. */
static void table_soa(skin_soa *s)
{
	emb_table_soa(s);
	for (int i = 0; i < 6 + SKP_MAX_INFLUENCES; i++)
		for (int v = 0; v < EMB_PADDED; v++)
			in_float[i][v] = from_bits(emb_float_bits[i][v]);
	s->px = in_float[0]; s->py = in_float[1]; s->pz = in_float[2];
	s->nx = in_float[3]; s->ny = in_float[4]; s->nz = in_float[5];
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		s->weight[k] = in_float[6 + k];
}

static uint32_t fnv_i32s(uint32_t h, const int32_t *v, int n)
{
	for (int i = 0; i < n; i++)
		for (int b = 0; b < 4; b++) {
			h ^= ((uint32_t)v[i] >> (8 * b)) & 0xffu;
			h *= 16777619u;
		}
	return h;
}

/* Decimal and hex without a formatter (skp_format carries %g). */
static void put_uint(unsigned long u, int base)
{
	char buf[24], *p = buf + sizeof buf;
	*--p = 0;
	do
		*--p = "0123456789abcdef"[u % (unsigned)base];
	while (u /= (unsigned)base);
	emb_puts(p);
}

enum { K_FIXED, K_FLOAT, K_COUNT };
static const char *const kernel_name[K_COUNT] = { "dqbs-fixed", "dqbs" };

static void run(int k, const skin_soa *s, const skin_out *o, uint32_t *sum)
{
	for (int fr = 0; fr < BENCH_FRAMES; fr++) {
		load_bones(fr);
		emb_count_begin(k);
		skin_bones_derive(&bones); /* a frame's tables count with it */
		if (k == K_FIXED)
			skin_dqbs_fixed(s, &bones, 0, s->count, o);
		else
			skin_dqbs_scalar(s, &bones, 0, s->count, o);
		emb_count_end();
		if (k == K_FIXED) {
			*sum = fnv_i32s(*sum, out_fpos, 3 * s->count);
			*sum = fnv_i32s(*sum, out_fnrm, 3 * s->count);
		}
	}
}

int emb_main(void)
{
	static skin_soa s;
	skin_out o = { out_pos, out_nrm, out_fpos, out_fnrm, NULL };
	uint32_t sum = 2166136261u;
	table_soa(&s);
	for (int k = 0; k < K_COUNT; k++) {
		run(k, &s, &o, &sum);
		emb_puts("emb-bench: ");
		emb_puts(kernel_name[k]);
		emb_puts(" runs ");
		put_uint(BENCH_FRAMES, 10);
		emb_puts(" vertices ");
		put_uint((unsigned long)s.count * BENCH_FRAMES, 10);
		emb_puts("\n");
	}
	emb_puts("emb-bench: fixed-kernel checksum 0x");
	put_uint(sum, 16);
	emb_puts("\n");
	return 0;
}
