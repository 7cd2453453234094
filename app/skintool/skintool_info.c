/* skintool info show.skn
 * Prints a flash image's header, sections and clips, then checks every
 * block. Exit status 0 when every block is good, 2 when the image is
 * damaged (each bad block named), 1 when it cannot be read at all. */
#include <stdio.h>
#include <string.h>

#include "cli_show.h"
#include "skintool_cmds.h"

static void print_header(const show_image *s)
{
	const skp_image_header *h = &s->im.hdr;
	static const char *const names[] = { "skeleton", "bind", "directory", "clips" };
	printf("%s: skinplay image, format version %u\n", s->path, (unsigned)h->version);
	printf("  sequence    %llu\n", (unsigned long long)h->sequence);
	printf("  blocks      %lu of %lu bytes (%llu bytes), CRC-32 each; header CRC %08lx\n",
	       (unsigned long)h->block_count, (unsigned long)h->block_size,
	       (unsigned long long)h->block_count * h->block_size, (unsigned long)h->crc);
	printf("  needs       %lu bones, %lu dofs, %lu vertices, %lu triangles, %lu influences, %lu clips\n",
	       (unsigned long)h->bones, (unsigned long)h->dofs, (unsigned long)h->verts, (unsigned long)h->tris,
	       (unsigned long)h->influences, (unsigned long)h->clips);
	printf("  section     header: block 0\n");
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		const skp_image_section *sec = &h->sec[i];
		printf("  section     %s: blocks %lu..%lu", names[i], (unsigned long)sec->first,
		       (unsigned long)(sec->first + sec->count) - (sec->count > 0));
		if (i != SKP_SEC_CLIPS)
			printf(", %lu bytes", (unsigned long)sec->bytes);
		printf("\n");
	}
}

static void print_clips(const show_image *s)
{
	for (int i = 0; i < s->im.clip_count; i++) {
		const skp_image_clip *c = &s->im.clip[i];
		printf("  clip %d      %s: %lu frames at %g fps (%.2f s), frames %ld..%ld, blocks %lu..%lu "
		       "(%u frames per block), worst-case error %.3g rad (%.3g deg), %.3g length units\n",
		       i, c->name, (unsigned long)c->frame_count, (double)c->fps, c->frame_count / (double)c->fps,
		       (long)c->first_number, (long)c->first_number + (long)c->frame_count - 1,
		       (unsigned long)c->quant_first, (unsigned long)(c->frames_first + c->frame_blocks) - 1,
		       (unsigned)c->frames_per_block, (double)c->max_rot_err,
		       (double)c->max_rot_err * 57.29577951308232, (double)c->max_trans_err);
	}
}

/* What a bad block held, so the message says what is lost. */
static void bad_block(void *ctx, uint32_t b, skp_block_state st)
{
	const show_image *s = ctx;
	printf("block %lu bad: %s", (unsigned long)b, skp_block_state_name(st));
	for (int i = 0; i < s->im.clip_count; i++) {
		const skp_image_clip *c = &s->im.clip[i];
		if (b >= c->frames_first && b < c->frames_first + c->frame_blocks) {
			long first = (long)(b - c->frames_first) * c->frames_per_block;
			long last = first + c->frames_per_block - 1;
			if (last >= (long)c->frame_count)
				last = (long)c->frame_count - 1;
			printf(" (clip %s, frames %ld..%ld)", c->name, first + c->first_number, last + c->first_number);
		}
	}
	printf("\n");
}

/* The header is not trusted: find the block size under which most blocks
 * check, then name every block whose CRC fails at that size. */
static long scan_raw(storage_file *sf)
{
	static uint8_t buf[SKP_IMAGE_BLOCK_SIZE];
	uint32_t best = SKP_IMAGE_DEFAULT_BLOCK;
	long best_good = -1, bad = 0;
	for (uint32_t bs = SKP_IMAGE_MIN_BLOCK; bs <= SKP_IMAGE_BLOCK_SIZE; bs *= 2) {
		long good = 0;
		storage_file_set_block_size(sf, bs);
		for (uint32_t b = 0; b < sf->bd.block_count; b++)
			good += sf->bd.read(sf, b, buf) == (int)bs && skp_block_crc_ok(buf, bs);
		if (good > best_good)
			best_good = good, best = bs;
	}
	storage_file_set_block_size(sf, best);
	for (uint32_t b = 0; b < sf->bd.block_count; b++) {
		int n = sf->bd.read(sf, b, buf);
		skp_block_state st = n < 0 ? SKP_BLOCK_IO : n < (int)best ? SKP_BLOCK_SHORT
				   : skp_block_crc_ok(buf, best) ? SKP_BLOCK_OK : SKP_BLOCK_CRC;
		if (st != SKP_BLOCK_OK) {
			printf("block %lu bad: %s\n", (unsigned long)b, skp_block_state_name(st));
			bad++;
		}
	}
	printf("verify: %lu blocks of %lu bytes (block size found from their CRCs): %ld bad\n",
	       (unsigned long)sf->bd.block_count, (unsigned long)best, bad);
	return bad;
}

static int refused(show_image *s, const skp_error *err)
{
	if (err->block >= 0)
		printf("%s: block %ld bad: %s\n", s->path, err->block, err->msg);
	else
		printf("%s: %s\n", s->path, err->msg);
	if (err->code == SKP_ERR_LIMIT)
		return 2;
	int rc = show_storage_open(&s->sf, s->path);
	if (rc < 0)
		return 2;
	scan_raw(&s->sf);
	storage_file_close(&s->sf);
	return 2;
}

int cmd_info(int argc, char **argv)
{
	static show_image s;
	skp_error err;
	if (argc != 1 || argv[0][0] == '-') {
		fprintf(stderr, "usage: skintool info show.skn\n");
		return 1;
	}
	if (show_image_open(&s, argv[0], &err) < 0) {
		if (err.code == SKP_ERR_IO && err.block < 0) {
			fprintf(stderr, "%s: %s\n", argv[0], err.msg);
			return 1;
		}
		return refused(&s, &err);
	}
	print_header(&s);
	print_clips(&s);
	long bad = show_image_verify(&s, bad_block, &s);
	printf("verify: %lu blocks: %s%ld bad\n", (unsigned long)s.im.hdr.block_count, bad ? "" : "all good, ", bad);
	if (s.sf.bd.block_count > s.im.hdr.block_count)
		printf("note: %lu blocks after the image's end (ignored)\n",
		       (unsigned long)(s.sf.bd.block_count - s.im.hdr.block_count));
	show_image_close(&s);
	return bad ? 2 : 0;
}
