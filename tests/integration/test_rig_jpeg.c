/* JPEG base colour textures (issue 44), with JPEGs nobody here made: those
 * of Debian's assimp-testmodels (skipped without them).
 *   - mrfixit.iqm: its body's Body.jpg goes to the GPU pixel for pixel as
 *     libjpeg decodes it here, the head's Head.jpg is baked into its
 *     vertices' colours.
 *   - props_rig.gltf copied with the helmet's texture (all its UVs at the
 *     centre) pointed at a JPEG: the helmet's colour is the gold factor
 *     times the JPEG's centre, beside the model, progressive, named .png,
 *     or embedded as a data URI. Truncated, damaged, random bytes, too
 *     large by its header, CMYK: a warning naming file and material, and
 *     the helmet in its gold (255 203 89). A grey JPEG reads as grey. */
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

#include <jpeglib.h>

#include "rig_colour.h"
#include "rig_scene.h"
#include "test_paths.h"
#include "test_run.h"

#define SAMPLES "/usr/share/assimp/models"
#define BODY_JPG SAMPLES "/IQM/Body.jpg"          /* baseline, 1024x1024 */
#define JEEP_JPG SAMPLES "/MS3D/jeep1.jpg"        /* progressive, 512x512 */
#define FLARE_JPG SAMPLES "/OBJ/engineflare1.jpg" /* progressive, 128x128 */

static mesh m;
static rig_scene scene;

/* The file's bytes, or a skip when assimp-testmodels is not installed. */
static uint8_t *sample_file(const char *path, size_t *n)
{
	if (access(path, R_OK))
		skip();
	uint8_t *bytes = (uint8_t *)test_read_file(path, n);
	assert_non_null(bytes);
	return bytes;
}

/* A JPEG decoded by libjpeg's plain API, RGB, top row first (the test's
 * own reading, not the importer's). */
static uint8_t *decode_rgb(const uint8_t *bytes, size_t n, int *w, int *h)
{
	struct jpeg_decompress_struct cinfo;
	struct jpeg_error_mgr jerr;
	cinfo.err = jpeg_std_error(&jerr);
	jpeg_create_decompress(&cinfo);
	jpeg_mem_src(&cinfo, bytes, (unsigned long)n);
	jpeg_read_header(&cinfo, TRUE);
	cinfo.out_color_space = JCS_RGB;
	jpeg_start_decompress(&cinfo);
	*w = (int)cinfo.output_width;
	*h = (int)cinfo.output_height;
	uint8_t *rgb = malloc(3 * (size_t)*w * (size_t)*h);
	assert_non_null(rgb);
	while (cinfo.output_scanline < cinfo.output_height) {
		JSAMPROW row = rgb + 3 * (size_t)*w * cinfo.output_scanline;
		jpeg_read_scanlines(&cinfo, &row, 1);
	}
	jpeg_finish_decompress(&cinfo);
	jpeg_destroy_decompress(&cinfo);
	return rgb;
}

static double linear(int c)
{
	double s = c / 255.0;
	return s <= 0.04045 ? s / 12.92 : pow((s + 0.055) / 1.055, 2.4);
}

static int srgb(double l)
{
	double s = l <= 0.0031308 ? 12.92 * l : 1.055 * pow(l, 1.0 / 2.4) - 0.055;
	return (int)lrint(255.0 * s);
}

/* The helmet's colour with the JPEG as its texture: gold (linear 1 0.6
 * 0.1) times the mean, in linear light, of the JPEG's four centre pixels
 * (its UVs are 0.5 0.5: the centre of the texture, between them). */
static void helmet_expected(const uint8_t *jpeg, size_t n, int rgb[3])
{
	static const double gold[3] = { 1.0, 0.6, 0.1 };
	int w, h;
	uint8_t *px = decode_rgb(jpeg, n, &w, &h);
	for (int c = 0; c < 3; c++) {
		double sum = 0;
		for (int k = 0; k < 4; k++)
			sum += linear(px[3 * ((size_t)(h / 2 - 1 + (k >> 1)) * (size_t)w + (size_t)(w / 2 - 1 + (k & 1))) + c]);
		rgb[c] = srgb(gold[c] * sum / 4);
	}
	free(px);
}

static void write_file(const char *path, const void *bytes, size_t n)
{
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(bytes, 1, n, f), n);
	assert_int_equal(fclose(f), 0);
}

/* props_rig.gltf in the scratch directory, its helmet's image uri
 * replaced by uri, imported. */
static void import_props(const char *uri)
{
	size_t n;
	char *gltf = test_read_file("tests/data/rigs/props_rig.gltf", &n);
	assert_non_null(gltf);
	char *at = strstr(gltf, "missing_gold.png");
	assert_non_null(at);
	const char *path = test_scratch("props_rig.gltf");
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	fprintf(f, "%.*s%s%s", (int)(at - gltf), gltf, uri, at + strlen("missing_gold.png"));
	assert_int_equal(fclose(f), 0);
	free(gltf);
	skp_error err;
	scene.mesh = &m;
	if (rig_import(path, NULL, &scene, &err) != SKP_OK)
		fail_msg("%s: %s", path, err.msg);
}

static int in_helmet(vec3 p) { return p.y > 1.6f && fabsf(p.x) > 0.1f && fabsf(p.x) < 0.12f; }

/* Every helmet vertex has colour rgb (within 1: rounding); they are 8. */
static void helmet_is(const int rgb[3])
{
	int n = 0;
	for (int v = 0; v < m.vert_count; v++) {
		if (!in_helmet(m.pos[v]))
			continue;
		const uint8_t *c = m.colour[v];
		for (int k = 0; k < 3; k++)
			if (abs(c[k] - rgb[k]) > 1)
				fail_msg("helmet vertex %d: %d %d %d, wanted %d %d %d", v, c[0], c[1], c[2], rgb[0], rgb[1],
					 rgb[2]);
		n++;
	}
	assert_int_equal(n, 8);
}

/* The GPU's texture is the JPEG's pixels, each as libjpeg decodes them
 * here. */
static void gpu_texture_is(const uint8_t *jpeg, size_t n)
{
	int w, h;
	uint8_t *rgb = decode_rgb(jpeg, n, &w, &h);
	assert_non_null(scene.texture_rgba);
	assert_int_equal(scene.texture_w, w);
	assert_int_equal(scene.texture_h, h);
	for (size_t i = 0; i < (size_t)w * (size_t)h; i++) {
		const uint8_t *p = scene.texture_rgba + 4 * i;
		if (memcmp(p, rgb + 3 * i, 3) || p[3] != 255)
			fail_msg("pixel %zu: %d %d %d %d, libjpeg says %d %d %d", i, p[0], p[1], p[2], p[3], rgb[3 * i],
				 rgb[3 * i + 1], rgb[3 * i + 2]);
	}
	free(rgb);
}

/* The helmet's texture was read from the JPEG: the GPU has it (the one
 * texture of the file), and baked at the helmet's UVs it gives the
 * helmet gold times the JPEG's centre. */
static void helmet_textured_by(const char *what, const uint8_t *jpeg, size_t n)
{
	if (scene.texture_problems)
		fail_msg("%s: %s", what, scene.texture_problem);
	assert_int_equal(m.textured, 1);
	gpu_texture_is(jpeg, n);
	rig_colour_bake(scene.texture_rgba, scene.texture_w, scene.texture_h, (const float (*)[2])m.uv, m.sampled,
			m.colour, m.vert_count);
	int want[3];
	helmet_expected(jpeg, n, want);
	print_message("helmet with %s (%dx%d): %d %d %d\n", what, scene.texture_w, scene.texture_h, want[0], want[1],
		      want[2]);
	helmet_is(want);
}

/* The helmet with the JPEG as a file named name beside the model. */
static void helmet_reads(const char *name, const uint8_t *jpeg, size_t n)
{
	write_file(test_scratch(name), jpeg, n);
	import_props(name);
	helmet_textured_by(name, jpeg, n);
}

/* The helmet with bytes as a file named name: the warning says why, the
 * helmet is gold. */
static void helmet_refuses(const char *name, const void *bytes, size_t n, const char *why)
{
	static const int gold[3] = { 255, 203, 89 };
	write_file(test_scratch(name), bytes, n);
	import_props(name);
	char said[300];
	snprintf(said, sizeof said, "material 'Gold': texture '%s' %s", name, why);
	assert_int_equal(scene.texture_problems, 1);
	if (!strstr(scene.texture_problem, said))
		fail_msg("said \"%s\", wanted \"%s\"", scene.texture_problem, said);
	assert_int_equal(m.textured, 0);
	helmet_is(gold);
	print_message("%s: %s\n", name, scene.texture_problem);
}

/* The offset of the JPEG's frame header (SOFn), found by walking its
 * segments. */
static size_t frame_header(const uint8_t *jpeg, size_t n)
{
	size_t at = 2;
	while (at + 4 < n && jpeg[at] == 0xFF) {
		uint8_t marker = jpeg[at + 1];
		if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC)
			return at;
		at += 2 + (size_t)(jpeg[at + 2] << 8 | jpeg[at + 3]);
	}
	fail_msg("no frame header");
	return 0;
}

static void test_character_in_its_jpegs(void **state)
{
	(void)state;
	size_t n;
	uint8_t *body = sample_file(BODY_JPG, &n);
	skp_error err;
	scene.mesh = &m;
	if (rig_import(SAMPLES "/IQM/mrfixit.iqm", NULL, &scene, &err) != SKP_OK)
		fail_msg("mrfixit.iqm: %s", err.msg);
	if (scene.texture_problems)
		fail_msg("mrfixit.iqm: %s", scene.texture_problem);
	assert_string_equal(scene.texture_path, "Body.jpg");
	gpu_texture_is(body, n);
	/* the head's texture baked: its vertices in many colours, not its
	 * material's one */
	int baked = 0, distinct = 0;
	static uint8_t seen[1 << 15];
	memset(seen, 0, sizeof seen);
	for (int v = 0; v < m.vert_count; v++) {
		if (m.sampled[v])
			continue;
		const uint8_t *c = m.colour[v];
		unsigned key = (unsigned)(c[0] >> 3) << 10 | (unsigned)(c[1] >> 3) << 5 | (unsigned)(c[2] >> 3);
		distinct += !seen[key];
		seen[key] = 1;
		baked++;
	}
	print_message("mrfixit.iqm: %d vertices, %d textured meshes, %d on Body.jpg (the GPU's), %d baked from "
		      "Head.jpg in %d colours (5 bits a channel)\n",
		      m.vert_count, scene.textured, m.vert_count - baked, baked, distinct);
	assert_int_equal(scene.textured, 2);
	assert_true(baked > 100 && distinct > 30);
	free(body);
}

static void test_jpeg_beside_the_model(void **state)
{
	(void)state;
	size_t n;
	uint8_t *body = sample_file(BODY_JPG, &n);
	assert_int_equal(body[frame_header(body, n) + 1], 0xC0);   /* baseline */
	helmet_reads("gold.jpg", body, n);
	helmet_reads("gold.JPEG", body, n);
	/* told by its bytes, not its name */
	helmet_reads("gold.png", body, n);
	free(body);
	uint8_t *jeep = sample_file(JEEP_JPG, &n);
	assert_int_equal(jeep[frame_header(jeep, n) + 1], 0xC2);   /* progressive */
	helmet_reads("jeep.jpg", jeep, n);
	free(jeep);
}

static char *base64(const uint8_t *bytes, size_t n)
{
	static const char digit[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	char *out = malloc(4 * (n / 3 + 1) + 1), *o = out;
	assert_non_null(out);
	for (size_t i = 0; i < n; i += 3) {
		uint32_t v = (uint32_t)bytes[i] << 16 | (i + 1 < n ? (uint32_t)bytes[i + 1] << 8 : 0) |
			     (i + 2 < n ? bytes[i + 2] : 0);
		for (int k = 0; k < 4; k++)
			*o++ = k < 2 || i + (size_t)k - 1 < n ? digit[(v >> (18 - 6 * k)) & 63] : '=';
	}
	*o = '\0';
	return out;
}

/* A data URI: the library hands the texture over embedded ("*0"). */
static void test_jpeg_embedded(void **state)
{
	(void)state;
	size_t n;
	uint8_t *flare = sample_file(FLARE_JPG, &n);
	char *b64 = base64(flare, n);
	char *uri = malloc(strlen(b64) + 32);
	assert_non_null(uri);
	sprintf(uri, "data:image/jpeg;base64,%s", b64);
	import_props(uri);
	assert_string_equal(scene.texture_path, "*0");
	helmet_textured_by("an embedded engineflare1.jpg", flare, n);
	free(uri);
	free(b64);
	free(flare);
}

static void test_damaged_jpegs(void **state)
{
	(void)state;
	size_t n;
	uint8_t *body = sample_file(BODY_JPG, &n);
	/* libjpeg's "Premature end of JPEG file", a warning: grey pixels past it */
	helmet_refuses("half.jpg", body, n / 2, "is truncated or damaged");
	/* its header cut: an error, which must not end the process */
	helmet_refuses("cut.jpg", body, frame_header(body, n) + 4, "is truncated or damaged");
	/* entropy-coded data overwritten halfway: corrupt data libjpeg skips */
	uint8_t *hit = malloc(n);
	assert_non_null(hit);
	memcpy(hit, body, n);
	for (size_t i = n / 2; i < n / 2 + 64; i++)
		hit[i] = (uint8_t)(i * 37 % 251) | 0xC0;
	hit[n / 2 + 10] = 0xFF;
	hit[n / 2 + 11] = 0xD9;   /* an EOI in the middle of the scan */
	helmet_refuses("hit.jpg", hit, n, "is truncated or damaged");
	/* 9000 pixels wide by its header: refused before any pixel is decoded */
	memcpy(hit, body, n);
	size_t sof = frame_header(hit, n);
	hit[sof + 7] = 9000 >> 8;
	hit[sof + 8] = 9000 & 255;
	helmet_refuses("wide.jpg", hit, n, "is larger than 8192 pixels a side");
	free(hit);
	free(body);
	uint8_t noise[4096];
	for (size_t i = 0; i < sizeof noise; i++)
		noise[i] = (uint8_t)((i * 2654435761u) >> 13);
	helmet_refuses("noise.jpg", noise, sizeof noise, "is neither PNG nor JPEG (PNG and JPEG textures are read)");
}

/* A flat 64x64 JPEG of the colour space's components each at value,
 * encoded here (assimp-testmodels has no grey or CMYK one); malloc()ed. */
static uint8_t *flat_jpeg(J_COLOR_SPACE space, int components, uint8_t value, size_t *n)
{
	struct jpeg_compress_struct cinfo;
	struct jpeg_error_mgr jerr;
	unsigned char *out = NULL;
	unsigned long size = 0;
	uint8_t row[64 * 4];
	memset(row, value, sizeof row);
	cinfo.err = jpeg_std_error(&jerr);
	jpeg_create_compress(&cinfo);
	jpeg_mem_dest(&cinfo, &out, &size);
	cinfo.image_width = cinfo.image_height = 64;
	cinfo.input_components = components;
	cinfo.in_color_space = space;
	jpeg_set_defaults(&cinfo);
	jpeg_start_compress(&cinfo, TRUE);
	while (cinfo.next_scanline < cinfo.image_height) {
		JSAMPROW r = row;
		jpeg_write_scanlines(&cinfo, &r, 1);
	}
	jpeg_finish_compress(&cinfo);
	jpeg_destroy_compress(&cinfo);
	*n = size;
	return out;
}

static void test_grey_and_cmyk(void **state)
{
	(void)state;
	size_t n;
	uint8_t *grey = flat_jpeg(JCS_GRAYSCALE, 1, 128, &n);
	write_file(test_scratch("grey.jpg"), grey, n);
	import_props("grey.jpg");
	helmet_textured_by("a grey JPEG", grey, n);
	int want[3] = { srgb(linear(128)), srgb(0.6 * linear(128)), srgb(0.1 * linear(128)) };
	helmet_is(want);
	free(grey);
	uint8_t *cmyk = flat_jpeg(JCS_CMYK, 4, 100, &n);
	helmet_refuses("cmyk.jpg", cmyk, n, "is a CMYK JPEG (RGB and grey ones are read)");
	free(cmyk);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_character_in_its_jpegs),
		cmocka_unit_test(test_jpeg_beside_the_model),
		cmocka_unit_test(test_jpeg_embedded),
		cmocka_unit_test(test_damaged_jpegs),
		cmocka_unit_test(test_grey_and_cmyk),
	};
	int failed = cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
	rig_scene_release(&scene);
	return failed;
}
