#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "test_imgpack.h"

#include <math.h>
#include <string.h>

static const tex_image *pack_texture;
static int pack_version;

void test_imgpack_texture(const tex_image *t)
{
	pack_texture = t;
}

void test_imgpack_version(int version)
{
	pack_version = version;
}

void test_imgpack_next_id(uint8_t id[SKP_IMAGE_ID_BYTES])
{
	static uint64_t n = 0x9e3779b97f4a7c15ull;
	for (int i = 0; i < SKP_IMAGE_ID_BYTES; i++) {
		n = n * 6364136223846793005ull + 1442695040888963407ull;
		id[i] = (uint8_t)(n >> 56);
	}
}

void test_imgpack_synth(const skel *s, amc_frame *f, int n)
{
	for (int i = 0; i < n; i++) {
		memset(&f[i], 0, sizeof f[i]);
		f[i].number = 10 + i;
		for (int d = 0; d < s->dof_count; d++)
			f[i].value[d] = (float)(sin(0.1 * i + d) * (d < 3 ? 40.0 : 3.0));
	}
}

static skp_status write_clip(const test_imgpack *p, const char *name, const amc_frame *f, int n, skp_error *err)
{
	skp_clip_range_init(p->range, p->s);
	for (int i = 0; i < n; i++)
		if (skp_clip_range_add(p->range, &f[i], err) != SKP_OK)
			return err->code;
	skp_status rc = skp_image_clip_begin(p->wr, name, 120.0f, p->range, err);
	for (int i = 0; i < n && rc == SKP_OK; i++)
		rc = skp_image_clip_frame(p->wr, &f[i], err);
	return rc;
}

void test_imgpack_pack(const test_imgpack *p, uint64_t sequence, const float *bind_values, int parity)
{
	static skp_mem_blockdev mb;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	skp_error err;
	skp_blockdev dev = skp_mem_blockdev_init(&mb, p->img, p->cap, TEST_IMGPACK_BS);
	memset(p->img, 0, p->cap);
	test_imgpack_next_id(id);
	assert_int_equal(skp_image_write_begin(p->wr, &dev, sequence, id, p->s, &err), SKP_OK);
	p->wr->parity_group = parity;
	p->wr->texture = pack_texture;
	if (pack_version)
		p->wr->hdr.version = (uint16_t)pack_version;
	assert_int_equal(skp_image_write_bind(p->wr, p->m, p->w, bind_values, 7, &err), SKP_OK);
	assert_int_equal(write_clip(p, "tiny", p->frames, *p->frame_count, &err), SKP_OK);
	test_imgpack_synth(p->s, p->synth, TEST_IMGPACK_SYNTH);
	assert_int_equal(write_clip(p, "synth", p->synth, TEST_IMGPACK_SYNTH, &err), SKP_OK);
	assert_int_equal(skp_image_write_end(p->wr, &err), SKP_OK);
	*p->size = mb.size;
	assert_int_equal(*p->size, (size_t)p->wr->hdr.block_count * TEST_IMGPACK_BS);
}

skp_status test_imgpack_open(const test_imgpack *p, size_t size, skp_error *err)
{
	*p->rdev = skp_mem_blockdev_ro(p->rb, p->img, size, TEST_IMGPACK_BS);
	return skp_image_open(p->im, p->rdev, err);
}

void test_imgpack_refused(const test_imgpack *p, const char *needle, skp_status code)
{
	skp_error err;
	assert_int_not_equal(test_imgpack_open(p, *p->size, &err), SKP_OK);
	assert_int_equal(err.code, code);
	if (!strstr(err.msg, needle))
		fail_msg("expected '%s' in '%s'", needle, err.msg);
}
