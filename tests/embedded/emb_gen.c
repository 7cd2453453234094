/* Host generator of the embedded skinning test's data (emb_tables.h).
 *
 *   emb_gen SKELETON.asf MOTION.amc FRAMES STRIDE OUT.h
 *
 * Writes, as C tables:
 *   - the ASF text and an AMC with FRAMES frames (every STRIDE-th frame of
 *     MOTION), as strings: the target parses them itself;
 *   - a generated body (the mannequin at the finest detail that fits the
 *     board's SKP_MAX_VERTS) as the bit patterns of its float positions and
 *     normals: the target binds it itself with app/bind/bind.c;
 *   - the same pipeline run here on the host, converted to fixed point: the
 *     skin_soa fixed arrays (Q15.16 positions, Q2.30 normals, bones, Q1.15
 *     weights) and, per frame, the bones' fixed dual quaternions.
 *
 * Why both: the float part of the pipeline (FK with sinf/cosf, binding,
 * float -> fixed conversion) may differ in the last bit between x86-64
 * (glibc libm) and a Cortex-M4 (newlib libm), so only the integer kernel
 * run on these host-made tables is required to match bit for bit; the
 * target's own float pipeline is compared against the tables and reported.
 *
 * With a sixth argument FLOAT.h it also writes, for the benchmark
 * (emb_bench.c), the float kernel's inputs: the skin_soa float arrays and
 * each frame's bone dual quaternions as float bit patterns.
 *
 * Built with the board's board_limits.h, so the tables fit the board. */
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amc.h"
#include "asf.h"
#include "bind.h"
#include "fk.h"
#include "mannequin.h"
#include "skin.h"
#include "skp_reader.h"
#include "text_lines.h"

#define MAX_TEXT (4 << 20) /* the demo motion: 1.4 MB with the tour of 19 s */

static char asf_text[MAX_TEXT], amc_src[MAX_TEXT], amc_text[MAX_TEXT];
static skel sk;
static text_lines tl;
static amc_frame frame;
static skel_pose bind_pose, pose;
static manq_work manq;
static mesh body;
static bind_rig rig;
static skin_weights weights;
static skin_bones bones;
static skin_soa soa;
static _Alignas(SKIN_ALIGN) unsigned char soa_mem[SKIN_SOA_BYTES(SKP_MAX_VERTS)];

static void die(const char *what, const skp_error *err)
{
	fprintf(stderr, "emb_gen: %s: line %ld: %s\n", what, err ? err->line : 0L, err ? err->msg : "");
	exit(1);
}

static size_t slurp(const char *path, char *buf)
{
	FILE *f = fopen(path, "rb");
	if (!f) {
		perror(path);
		exit(1);
	}
	size_t n = fread(buf, 1, MAX_TEXT - 1, f);
	if (!feof(f)) {
		fprintf(stderr, "emb_gen: %s: larger than %d bytes\n", path, MAX_TEXT);
		exit(1);
	}
	fclose(f);
	buf[n] = 0;
	return n;
}

/* The header lines of the AMC, then every stride-th frame, frames of them. */
static size_t pick_frames(const char *src, int frames, int stride, char *out)
{
	size_t o = 0;
	int seen = 0, kept = 0, keep = 1;
	for (const char *p = src; *p;) {
		const char *e = strchr(p, '\n');
		size_t len = e ? (size_t)(e - p + 1) : strlen(p);
		int is_number = p[0] >= '0' && p[0] <= '9';
		if (is_number) {
			keep = seen % stride == 0 && kept < frames;
			kept += keep;
			seen++;
		}
		if (keep && (is_number || seen > 0 || p[0] == '#' || p[0] == ':')) {
			memcpy(out + o, p, len);
			o += len;
		}
		p += len;
	}
	out[o] = 0;
	return o;
}

static void emit_string(FILE *f, const char *name, const char *s)
{
	fprintf(f, "static const char %s[] =\n\t\"", name);
	for (; *s; s++) {
		unsigned char c = (unsigned char)*s;
		if (c == '\n')
			fputs(*(s + 1) ? "\\n\"\n\t\"" : "\\n", f);
		else if (c == '"' || c == '\\')
			fprintf(f, "\\%c", c);
		else if (c < 32 || c > 126)
			fprintf(f, "\\%03o", c);
		else
			fputc(c, f);
	}
	fputs("\";\n\n", f);
}

static void emit_i32(FILE *f, const int32_t *v, int n)
{
	for (int i = 0; i < n; i++)
		fprintf(f, "%s%ld,", i % 8 ? " " : "\n\t", (long)v[i]);
}

static void emit_u32(FILE *f, const uint32_t *v, int n)
{
	for (int i = 0; i < n; i++)
		fprintf(f, "%s0x%08lxu,", i % 6 ? " " : "\n\t", (unsigned long)v[i]);
}

static void emit_u16(FILE *f, const uint16_t *v, int n)
{
	for (int i = 0; i < n; i++)
		fprintf(f, "%s%u,", i % 12 ? " " : "\n\t", (unsigned)v[i]);
}

static uint32_t float_bits(float x)
{
	uint32_t u;
	memcpy(&u, &x, sizeof u);
	return u;
}

static void parse_asf(size_t len)
{
	skp_mem_source src;
	skp_error err;
	text_lines_init(&tl, skp_mem_reader(&src, asf_text, len));
	if (asf_parse(&sk, &tl, &err) != SKP_OK)
		die("ASF", &err);
}

/* The largest mannequin that fits the board. */
static void make_body(void)
{
	skp_error err;
	for (int detail = 40; detail >= MANQ_MIN_DETAIL; detail -= 2)
		if (manq_build(&sk, detail, &manq, &body, &err) == SKP_OK) {
			fprintf(stderr, "emb_gen: body at detail %d: %d vertices, %d triangles\n", detail,
				body.vert_count, body.tri_count);
			return;
		}
	die("mannequin", &err);
}

static void bind_body(void)
{
	skp_error err;
	fk_pose(&sk, NULL, &bind_pose);
	bind_prepare(&rig, &sk, &bind_pose, NULL);
	if (bind_weights(&rig, body.pos, body.vert_count, &weights, NULL, &err) != SKP_OK)
		die("bind", &err);
	skin_soa_attach(&soa, soa_mem, body.vert_count);
	if (skin_soa_load(&soa, &body, &weights, sk.count, &err) != SKP_OK)
		die("soa", &err);
}

/* n vec3s as float bit patterns, x y z per vertex, into bits */
static void vec3_bits(const vec3 *a, int n, uint32_t *bits)
{
	for (int v = 0; v < n; v++) {
		bits[3 * v] = float_bits(a[v].x);
		bits[3 * v + 1] = float_bits(a[v].y);
		bits[3 * v + 2] = float_bits(a[v].z);
	}
}

static void emit_mesh(FILE *f)
{
	static uint32_t bits[3 * SKP_MAX_VERTS];
	int n = body.vert_count;
	vec3_bits(body.pos, n, bits);
	fputs("/* the body, float bit patterns: x y z per vertex */\nstatic const uint32_t emb_pos_bits[] = {", f);
	emit_u32(f, bits, 3 * n);
	vec3_bits(body.normal, n, bits);
	fputs("\n};\n\nstatic const uint32_t emb_nrm_bits[] = {", f);
	emit_u32(f, bits, 3 * n);
	fputs("\n};\n\n", f);
}

static void emit_soa(FILE *f)
{
	const int32_t *arr[6] = { soa.fpx, soa.fpy, soa.fpz, soa.fnx, soa.fny, soa.fnz };
	const char *names[6] = { "emb_fpx", "emb_fpy", "emb_fpz", "emb_fnx", "emb_fny", "emb_fnz" };
	fputs("/* skin_soa fixed arrays made on the host, padded to SKIN_LANES */\n", f);
	for (int i = 0; i < 6; i++) {
		fprintf(f, "static const int32_t %s[EMB_PADDED] = {", names[i]);
		emit_i32(f, arr[i], soa.padded);
		fputs("\n};\n", f);
	}
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		fprintf(f, "static const uint16_t emb_bone%d[EMB_PADDED] = {", k);
		emit_u16(f, soa.bone[k], soa.padded);
		fprintf(f, "\n};\nstatic const uint16_t emb_fw%d[EMB_PADDED] = {", k);
		emit_u16(f, soa.fweight[k], soa.padded);
		fputs("\n};\n", f);
	}
	fputs("\n", f);
}

/* The same text into f and, when there is one, ff. */
static void to_both(FILE *f, FILE *ff, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vfprintf(f, fmt, ap);
	va_end(ap);
	if (ff) {
		va_start(ap, fmt);
		vfprintf(ff, fmt, ap);
		va_end(ap);
	}
}

/* One bone slot's dual quaternion: fixed (w x y z, real then dual) into f,
 * and when ff is given its float bit patterns into ff. */
static void emit_bone(FILE *f, FILE *ff, int slot)
{
	const fx_dq *d = &bones.fdq[slot];
	int32_t v[8] = { d->real.w, d->real.x, d->real.y, d->real.z, d->dual.w, d->dual.x, d->dual.y, d->dual.z };
	fputs("\n\t\t{", f);
	emit_i32(f, v, 8);
	fputs(" },", f);
	if (!ff)
		return;
	const dq *q = &bones.dq[slot];
	const float fl[8] = { q->real.w, q->real.x, q->real.y, q->real.z, q->dual.w, q->dual.x, q->dual.y, q->dual.z };
	uint32_t bits[8];
	for (int i = 0; i < 8; i++)
		bits[i] = float_bits(fl[i]);
	fputs("\n\t\t{", ff);
	emit_u32(ff, bits, 8);
	fputs(" },", ff);
}

/* Per frame, the fixed dual quaternions of the bones and the identity slot
 * (the last row), real then dual, w x y z; into ff (when given) the same
 * in float. */
static int emit_bones(FILE *f, FILE *ff, size_t amc_len)
{
	skp_mem_source src;
	skp_error err;
	amc_stream as;
	int frames = 0, r;
	text_lines_init(&tl, skp_mem_reader(&src, amc_text, amc_len));
	amc_open(&as, &sk, &tl);
	fputs("static const int32_t emb_fdq[EMB_FRAMES][EMB_BONES + 1][8] = {", f);
	if (ff)
		fputs("static const uint32_t emb_dq_bits[EMB_FRAMES][EMB_BONES + 1][8] = {", ff);
	while ((r = amc_next(&as, &frame, &err)) == 1) {
		fk_pose(&sk, frame.value, &pose);
		skin_bones_compute(&bones, &sk, &bind_pose, &pose);
		to_both(f, ff, "\n\t{ /* frame %ld */", frame.number);
		for (int b = 0; b <= sk.count; b++)
			emit_bone(f, ff, b == sk.count ? SKIN_IDENTITY_BONE : b);
		to_both(f, ff, "\n\t},");
		frames++;
	}
	if (r < 0)
		die("AMC", &err);
	to_both(f, ff, "\n};\n");
	return frames;
}

/* The float kernel's inputs (emb_bench.c): skin_soa's float arrays as bit
 * patterns. */
static void emit_float_soa(FILE *f)
{
	static uint32_t bits[SKIN_SOA_PADDED(SKP_MAX_VERTS)];
	const float *arr[6 + SKP_MAX_INFLUENCES] = { soa.px, soa.py, soa.pz, soa.nx, soa.ny, soa.nz };
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		arr[6 + k] = soa.weight[k];
	fputs("/* skin_soa float arrays (px py pz nx ny nz, weights 0-3) as bit patterns */\n", f);
	fputs("static const uint32_t emb_float_bits[][EMB_PADDED] = {", f);
	for (int i = 0; i < 6 + SKP_MAX_INFLUENCES; i++) {
		for (int v = 0; v < soa.padded; v++)
			bits[v] = float_bits(arr[i][v]);
		fputs("\n\t{", f);
		emit_u32(f, bits, soa.padded);
		fputs("\n\t},", f);
	}
	fputs("\n};\n\n", f);
}

static FILE *open_tmp(const char *path, char *tmp, size_t n)
{
	snprintf(tmp, n, "%s.tmp", path);
	FILE *f = fopen(tmp, "w");
	if (!f) {
		perror(tmp);
		exit(1);
	}
	return f;
}

static void close_rename(FILE *f, const char *tmp, const char *path)
{
	if (fclose(f) != 0 || rename(tmp, path) != 0) {
		perror(path);
		exit(1);
	}
}

int main(int argc, char **argv)
{
	if (argc != 6 && argc != 7) {
		fprintf(stderr, "usage: emb_gen SKELETON.asf MOTION.amc FRAMES STRIDE OUT.h [FLOAT.h]\n");
		return 2;
	}
	int frames = atoi(argv[3]), stride = atoi(argv[4]);
	size_t asf_len = slurp(argv[1], asf_text);
	slurp(argv[2], amc_src);
	size_t amc_len = pick_frames(amc_src, frames, stride > 0 ? stride : 1, amc_text);
	parse_asf(asf_len);
	make_body();
	bind_body();

	char tmp[4096], ftmp[4096];
	FILE *f = open_tmp(argv[5], tmp, sizeof tmp), *ff = argc == 7 ? open_tmp(argv[6], ftmp, sizeof ftmp) : NULL;
	to_both(f, ff, "/* Generated by tests/embedded/emb_gen.c from %s and %s: do not edit. */\n", argv[1], argv[2]);
	fprintf(f, "#define EMB_VERTS %d\n#define EMB_PADDED %d\n#define EMB_BONES %d\n#define EMB_FRAMES %d\n\n",
		soa.count, soa.padded, sk.count, frames);
	emit_string(f, "emb_asf", asf_text);
	emit_string(f, "emb_amc", amc_text);
	emit_mesh(f);
	emit_soa(f);
	if (ff)
		emit_float_soa(ff);
	int got = emit_bones(f, ff, amc_len);
	if (got != frames) {
		fprintf(stderr, "emb_gen: %s has %d frames at stride %d, wanted %d\n", argv[2], got, stride,
			frames);
		return 1;
	}
	close_rename(f, tmp, argv[5]);
	if (ff)
		close_rename(ff, ftmp, argv[6]);
	return 0;
}
