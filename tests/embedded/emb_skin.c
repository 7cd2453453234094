/* The embedded skinning test: the same source runs on a Cortex-M (under
 * qemu-system-arm, output through semihosting) and on the host, and the
 * two must print the same fixed-kernel checksum.
 *
 * 1. Bit-exact part (every build; the stress inputs in emb_stress.c, the
 *    hash in emb_hash.c): the fixed-point DQBS kernel
 *    (skin_dqbs_fixed, integer only) skins the body for every frame from
 *    tables made on the host (emb_tables.h: Q15.16 positions, Q2.30
 *    normals, Q1.15 weights, per-frame bone dual quaternions). The vertex
 *    data is read in place from flash, 64 vertices at a time, and the
 *    Q16.16 outputs go into an FNV-1a hash (each int32 as 4 little-endian
 *    bytes). Integer arithmetic is the same on every target, so this
 *    checksum must match bit for bit.
 * 2. Sampler (EMB_FULL builds): the playback engine (app/play) plays the
 *    embedded clip by time at display rates of 24, 60 and 144 Hz and at
 *    jittered times, looping with crossfades: slerp, fade and FK in single
 *    precision with no libm call but the half-angle sin/cos of each
 *    channel, so its poses must match the host's bit for bit (hashed).
 * 3. Target pipeline (EMB_FULL builds, i.e. boards with the float core):
 *    parse the embedded ASF and AMC text, pose with FK, bind the body with
 *    app/bind/bind.c, convert to fixed point and skin, all on the target. FK
 *    uses sinf/cosf, whose last bit differs between libms (glibc on the
 *    host, newlib on the board), so this part is compared against the host
 *    tables and the differences are printed, not required to be zero.
 *
 * No malloc, no stdio: output through emb_puts (emb_port.h). */
#include <stdint.h>
#include <string.h>

#include "emb_hash.h"
#include "emb_port.h"
#include "emb_stress.h"
#include "emb_tables.h"
#ifdef EMB_FULL
#include "codec_decode.h"
#include "codec_synth.h"
#include "emb_codec.h"
#endif
#include "emb_soa.h" /* after emb_tables.h */
#include "skin_kernels.h" /* the fixed kernel itself: skin_run would link the float ones */

#ifdef EMB_FULL
#include "skp_format.h"
#include "amc.h"
#include "asf.h"
#include "bind.h"
#include "fk.h"
#include "play_engine.h"
#include "play_sync.h"
#include "skp_reader.h"
#include "text_lines.h"
#endif

_Static_assert(EMB_BONES <= SKP_MAX_BONES, "the embedded skeleton exceeds the board's SKP_MAX_BONES");

static void hex32(char *out, uint32_t v)
{
	static const char digits[] = "0123456789abcdef";
	out[0] = '0';
	out[1] = 'x';
	for (int i = 0; i < 8; i++)
		out[2 + i] = digits[(v >> (28 - 4 * i)) & 0xfu];
	out[10] = 0;
}

static void say(const char *s)
{
	emb_puts(s);
	emb_puts("\n");
}

static void load_frame_table(int frame)
{
	emb_bones.count = EMB_BONES;
	for (int b = 0; b <= EMB_BONES; b++) {
		const int32_t *v = emb_fdq[frame][b];
		fx_dq d = { { v[0], v[1], v[2], v[3] }, { v[4], v[5], v[6], v[7] } };
		emb_bones.fdq[b == EMB_BONES ? SKIN_IDENTITY_BONE : b] = d;
	}
	skin_bones_derive(&emb_bones); /* the kernel's per-frame tables, where the board has them */
}

static uint32_t fixed_checksum(void)
{
	skin_soa s;
	fnv f = { EMB_FNV_START };
	emb_table_soa(&s);
	for (int fr = 0; fr < EMB_FRAMES; fr++) {
		load_frame_table(fr);
		emb_skin_hash(&s, &f);
	}
	return f.h;
}

#ifdef EMB_FULL
static skel sk;
static text_lines tl;
static amc_stream as;
static amc_frame frame;
static skel_pose bind_pose, pose;
static vec3 body_pos[EMB_VERTS];
static mesh body;
static bind_rig rig;
static skin_weights weights;
static skin_soa soa;
static _Alignas(SKIN_ALIGN) unsigned char soa_mem[SKIN_SOA_BYTES(EMB_VERTS)];

typedef struct diff {
	long count; /* values that differ from the host's */
	long max;   /* largest difference, in LSB */
} diff;

static void diff_add(diff *d, int32_t got, int32_t want)
{
	long e = (long)got - (long)want;
	if (e < 0)
		e = -e;
	if (e) {
		d->count++;
		if (e > d->max)
			d->max = e;
	}
}

static float from_bits(uint32_t u)
{
	float x;
	memcpy(&x, &u, sizeof x);
	return x;
}

static int fail(const char *what, const skp_error *err)
{
	char line[300];
	skp_format(line, sizeof line, "emb: %s: line %ld: %s", what, err->line, err->msg);
	say(line);
	return 1;
}

/* Parse, FK, bind and convert on the target; diffs against the tables. */
static int bind_on_target(diff *soa_diff, skp_error *err)
{
	skp_mem_source src;
	text_lines_init(&tl, skp_mem_reader(&src, emb_asf, sizeof emb_asf - 1));
	if (asf_parse(&sk, &tl, err) != SKP_OK)
		return fail("ASF", err);
	fk_pose(&sk, NULL, &bind_pose);
	body.vert_count = EMB_VERTS;
	for (int v = 0; v < EMB_VERTS; v++) {
		body_pos[v] = vec3_make(from_bits(emb_pos_bits[3 * v]), from_bits(emb_pos_bits[3 * v + 1]),
					from_bits(emb_pos_bits[3 * v + 2]));
		body.pos[v] = body_pos[v];
		body.normal[v] = vec3_make(from_bits(emb_nrm_bits[3 * v]), from_bits(emb_nrm_bits[3 * v + 1]),
					   from_bits(emb_nrm_bits[3 * v + 2]));
	}
	bind_prepare(&rig, &sk, &bind_pose, NULL);
	if (bind_weights(&rig, body_pos, EMB_VERTS, &weights, NULL, err) != SKP_OK)
		return fail("bind", err);
	skin_soa_attach(&soa, soa_mem, EMB_VERTS);
	if (skin_soa_load(&soa, &body, &weights, sk.count, err) != SKP_OK)
		return fail("skin_soa_load", err);
	skin_soa t;
	emb_table_soa(&t);
	for (int v = 0; v < EMB_PADDED; v++) {
		diff_add(soa_diff, soa.fpx[v], t.fpx[v]); diff_add(soa_diff, soa.fpy[v], t.fpy[v]);
		diff_add(soa_diff, soa.fpz[v], t.fpz[v]); diff_add(soa_diff, soa.fnx[v], t.fnx[v]);
		diff_add(soa_diff, soa.fny[v], t.fny[v]); diff_add(soa_diff, soa.fnz[v], t.fnz[v]);
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			diff_add(soa_diff, soa.bone[k][v], t.bone[k][v]);
			diff_add(soa_diff, soa.fweight[k][v], t.fweight[k][v]);
		}
	}
	return 0;
}

static int pipeline_on_target(uint32_t *sum)
{
	skp_error err;
	skp_mem_source src;
	diff soa_diff = { 0, 0 }, dq_diff = { 0, 0 };
	fnv f = { EMB_FNV_START };
	int frames = 0, r;
	char line[200], hex[11];

	if (bind_on_target(&soa_diff, &err))
		return 1;
	text_lines_init(&tl, skp_mem_reader(&src, emb_amc, sizeof emb_amc - 1));
	amc_open(&as, &sk, &tl);
	while ((r = amc_next(&as, &frame, &err)) == 1 && frames < EMB_FRAMES) {
		fk_pose(&sk, frame.value, &pose);
		skin_bones_compute(&emb_bones, &sk, &bind_pose, &pose);
		for (int b = 0; b <= EMB_BONES; b++) {
			const fx_dq *d = &emb_bones.fdq[b == EMB_BONES ? SKIN_IDENTITY_BONE : b];
			const int32_t got[8] = { d->real.w, d->real.x, d->real.y, d->real.z,
						 d->dual.w, d->dual.x, d->dual.y, d->dual.z };
			for (int i = 0; i < 8; i++)
				diff_add(&dq_diff, got[i], emb_fdq[frames][b][i]);
		}
		emb_skin_hash(&soa, &f);
		frames++;
	}
	if (r < 0)
		return fail("AMC", &err);
	*sum = f.h;
	hex32(hex, f.h);
	skp_format(line, sizeof line, "emb: target pipeline: %d frames, checksum %s", frames, hex);
	say(line);
	skp_format(line, sizeof line,
		   "emb: target vs host tables: soa %ld values differ (max %ld LSB), bone dq %ld differ (max %ld LSB)",
		   soa_diff.count, soa_diff.max, dq_diff.count, dq_diff.max);
	say(line);
	return frames == EMB_FRAMES ? 0 : 1;
}
#endif

#ifdef EMB_FULL
/* The embedded AMC text as the engine's source: seeking re-reads it. */
static skp_mem_source clip_mem;
static text_lines clip_lines;
static amc_stream clip_stream;
static play_engine eng;

static int clip_next(void *ctx, amc_frame *f, skp_error *err)
{
	(void)ctx;
	return amc_next(&clip_stream, f, err);
}

static skp_status clip_seek(void *ctx, long index, skp_error *err)
{
	text_lines_init(&clip_lines, skp_mem_reader(&clip_mem, emb_amc, sizeof emb_amc - 1));
	amc_open(&clip_stream, &sk, &clip_lines);
	for (long i = 0; i < index; i++)
		if (clip_next(ctx, &frame, err) != 1)
			return SKP_ERR_RANGE;
	return SKP_OK;
}

static void hash_pose(fnv *f, const play_engine *e)
{
	for (int b = 0; b < sk.count; b++) {
		const float v[7] = { e->pose.tip[b].x, e->pose.tip[b].y, e->pose.tip[b].z, e->pose.rot[b].w,
				     e->pose.rot[b].x, e->pose.rot[b].y, e->pose.rot[b].z };
		for (int i = 0; i < 7; i++) {
			uint32_t u;
			memcpy(&u, &v[i], sizeof u);
			emb_fnv_i32(f, (int32_t)u);
		}
	}
	emb_fnv_i32(f, (int32_t)e->number);
}

/* A show of the clip and a clip of 0.7 s on the wall clock
 * (app/play/play_sync.h) from 2026-01-01 plus a day: 3 s of 60 Hz frames,
 * each the clock's clip and time set on the engine as skinplay
 * --sync=clock does; the positions are hashed with the poses. */
static int synced_poses(fnv *f, long *samples)
{
	static const uint64_t len[2] = { EMB_FRAMES * 100000000ull, 700000000ull };
	const int64_t epoch = 1767225600LL * 1000000000LL, wall0 = epoch + 86400LL * 1000000000LL + 123456789LL;
	play_config cfg = { 1.0, 300, PLAY_ROOT_IN_PLACE, 1 };
	play_source src = { NULL, clip_next, clip_seek, EMB_FRAMES, 10.0, 0 };
	skp_error err;
	play_init(&eng, &sk, &cfg);
	if (play_start(&eng, &src, 0, &err) != SKP_OK)
		return fail("sync", &err);
	for (uint32_t n = 0; n < 180; n++) {
		uint64_t now = (uint64_t)n * 1000000000ull / 60;
		play_sync_at at;
		if (play_sync_locate(wall0 + (int64_t)now, epoch, len, 2, &at) != 0) {
			say("emb: sync: the show has no length");
			return 1;
		}
		emb_fnv_i32(f, at.clip);
		emb_fnv_i32(f, (int32_t)(at.into_ns / 1000));
		if (at.clip == 0)
			play_set_clip_time(&eng, (double)at.into_ns * 1e-9, now);
		if (play_update(&eng, now, &err) != SKP_OK)
			return fail("sync", &err);
		hash_pose(f, &eng);
		(*samples)++;
	}
	return 0;
}

/* The clip (EMB_FRAMES frames at 10 Hz) over 3 s of display frames at
 * each rate, then at times a fixed generator jitters (5..45 ms apart). */
static int sampler_checksum(uint32_t *sum)
{
	static const uint32_t rates[3] = { 24, 60, 144 };
	play_config cfg = { 1.0, 300, PLAY_ROOT_IN_PLACE, 1 };
	play_source src = { NULL, clip_next, clip_seek, EMB_FRAMES, 10.0, 0 };
	skp_error err;
	fnv f = { EMB_FNV_START };
	uint32_t seed = 12345u;
	long samples = 0;
	for (int k = 0; k < 4; k++) {
		play_init(&eng, &sk, &cfg);
		if (play_start(&eng, &src, 0, &err) != SKP_OK)
			return fail("sampler", &err);
		uint64_t now = 0;
		for (uint32_t n = 0; now < 3000000000ull; n++) {
			seed = seed * 1664525u + 1013904223u;
			now = k < 3 ? (uint64_t)n * 1000000000ull / rates[k] : now + 5000000u + (seed >> 8) % 40000000u;
			if (play_update(&eng, now, &err) != SKP_OK)
				return fail("sampler", &err);
			hash_pose(&f, &eng);
			samples++;
		}
	}
	if (synced_poses(&f, &samples) != 0)
		return 1;
	char line[120], hex[11];
	*sum = f.h;
	hex32(hex, f.h);
	skp_format(line, sizeof line, "emb: sampler: %ld poses at 24, 60, 144 Hz, jittered and on a wall clock", samples);
	say(line);
	emb_puts("emb: sampler checksum ");
	say(hex);
	return 0;
}
#endif

#ifdef EMB_FULL
/* The compressed clip coded on the host (emb_codec.h, from integers:
 * tests/support/codec_synth.h) decoded here, its values' bits hashed:
 * decode is bit-exact across boards when this equals the host's. */
static int codec_checksum(void)
{
	static codec_clip c;
	static codec_decoder d;
	static float v[CODEC_SYNTH_TRACKS];
	skp_error err;
	uint32_t h = 2166136261u;
	long frames = 0;
	codec_synth_clip(&c);
	if (codec_clip_check(&c, &err) != SKP_OK)
		return fail("codec", &err);
	for (uint32_t s = 0; s < EMB_CODEC_SEGMENTS; s++) {
		if (codec_begin(&d, &c, s, emb_codec_bytes + emb_codec_offset[s], emb_codec_offset[s + 1] - emb_codec_offset[s],
				&err) != SKP_OK)
			return fail("codec", &err);
		int r;
		while ((r = codec_next(&d, v, &err)) == 1) {
			h = codec_synth_hash(h, v, CODEC_SYNTH_TRACKS);
			frames++;
		}
		if (r < 0)
			return fail("codec", &err);
	}
	char line[80], hex[11];
	skp_format(line, sizeof line, "emb: codec: %ld frames of %d tracks decoded", frames, CODEC_SYNTH_TRACKS);
	say(line);
	hex32(hex, h);
	emb_puts("emb: codec checksum ");
	say(hex);
	return frames == CODEC_SYNTH_FRAMES ? 0 : 1;
}
#endif

/* Decimal without a formatter: the fixed-only builds (Cortex-M0) link no
 * floating point at all, and skp_format carries %g. */
static void put_int(long v)
{
	char buf[24], *p = buf + sizeof buf;
	unsigned long u = v < 0 ? 0ul - (unsigned long)v : (unsigned long)v;
	*--p = 0;
	do
		*--p = (char)('0' + u % 10);
	while (u /= 10);
	if (v < 0)
		*--p = '-';
	emb_puts(p);
}

int emb_main(void)
{
	char hex[11];
	emb_puts("emb: ");
	put_int(EMB_VERTS);
	emb_puts(" vertices, ");
	put_int(EMB_BONES);
	emb_puts(" bones, ");
	put_int(EMB_FRAMES);
	say(" frames, skinning dqbs-fixed (scalar)");
	hex32(hex, fixed_checksum());
	emb_puts("emb: fixed-kernel checksum ");
	say(hex);
	hex32(hex, emb_stress_checksum(EMB_BONES));
	emb_puts("emb: stress checksum ");
	say(hex);
#ifdef EMB_FULL
	uint32_t sum;
	if (pipeline_on_target(&sum) || sampler_checksum(&sum) || codec_checksum())
		return 1;
#endif
	say("emb: done");
	return 0;
}
