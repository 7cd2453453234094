/* skintool repair show.skn
 * Rebuilds every bad block of an image: data blocks from their parity
 * group (block 0 and directory blocks from their copies when their group
 * cannot), parity blocks from their data, the copies from what they copy;
 * a block of another image is bad like any other. The result must match
 * the digest in the header, or nothing is written. The repaired image is
 * written beside the old one, synced and renamed over it (cli_image_out.h),
 * so the old image is never lost. Exit status 0 when the image is whole
 * (repaired, or nothing to repair), 2 when a block is beyond repair or the
 * data does not match the digest (the image is left as it was), 1 when it
 * cannot be read or written. */
#include <stdio.h>
#include <string.h>

#include "cli_error.h"
#include "cli_image_out.h"
#include "cli_quiet.h"
#include "show_source.h"
#include "image_copies.h"
#include "image_parity.h"
#include "sha256.h"
#include "skintool_cmds.h"
#include "tool_args.h"

static void beyond(void *ctx, uint32_t b, const skp_block_report *r)
{
	(void)ctx;
	if (!r->repairable)
		fprintf(stderr, "block %lu: %s (%s): beyond repair\n", (unsigned long)b,
			skp_block_state_name(r->state), skp_block_report_what(r));
}

/* Data block b as the reader rebuilds it, written to out and hashed. */
static int rewrite_block(show_image *s, cli_image_out *out, uint32_t b, uint8_t *buf, sha256_ctx *digest)
{
	const skp_blockdev *dev = &out->sf.bd;
	int kind;
	unsigned item;
	skp_image_block_role(&s->im, b, &kind, &item);
	skp_block_state st = skp_image_read_block(&s->im, b, kind, item, buf);
	if (st != SKP_BLOCK_OK) {
		fprintf(stderr, "%s: block %lu: %s on the second read\n", s->path, (unsigned long)b, skp_block_state_name(st));
		return -1;
	}
	if (b > 0)
		sha256_update(digest, buf, s->im.hdr.block_size);
	if (dev->write(dev->ctx, b, buf) < 0) {
		fprintf(stderr, "%s: cannot write block %lu\n", out->af.path, (unsigned long)b);
		return -1;
	}
	return 0;
}

/* Every data block as the reader rebuilds it (matching the digest), then
 * fresh parity and copies. */
static int rewrite(show_image *s, cli_image_out *out)
{
	static uint8_t buf[SKP_IMAGE_BLOCK_SIZE], tmp[SKP_IMAGE_BLOCK_SIZE];
	const skp_image_header *h = &s->im.hdr;
	uint8_t sum[SKP_IMAGE_DIGEST_BYTES];
	sha256_ctx digest;
	skp_error err;
	sha256_init(&digest);
	for (uint32_t b = 0; b < h->data_blocks; b++)
		if (rewrite_block(s, out, b, buf, &digest) < 0)
			return -1;
	sha256_final(&digest, sum);
	/* version 7: each block read matched its own digest, the digests the root */
	if (s->im.digest_first ? !s->im.digests : memcmp(sum, h->digest, sizeof sum) != 0) {
		fprintf(stderr, "%s: the rebuilt data does not match the image's digest: not repaired\n", s->path);
		return -1;
	}
	if (skp_parity_write(&out->sf.bd, h, NULL, buf, tmp, &err) != SKP_OK ||
	    skp_image_write_copies(&out->sf.bd, h, buf, &err) != SKP_OK) {
		cli_error(out->af.path, &err);
		return -1;
	}
	return 0;
}

static const cli_command repair_command = {
	.prog = "skintool repair",
	.usage = "SHOW.skn",
	.about = "Rebuilds an image's bad blocks from its parity and copies and replaces the file (written\n"
		 "under a temporary name, synced and renamed); with a block beyond repair the file is left as it was.",
	.exit2 = "blocks beyond repair: the file is left as it was",
	.examples = (const cli_example[]){
		{ "Rebuild the bad blocks of an image in place",
		  "skintool repair show.skn" },
		{ NULL, NULL },
	},
};

int cmd_repair(int argc, char **argv)
{
	static show_image s;
	static cli_image_out out;
	skp_error err;
	const char *path;
	int prc = tool_one_file(&repair_command, argc, argv, &path);
	if (prc != 0)
		return prc < 0;
	if (show_image_open(&s, path, &err) < 0) {
		cli_error(path, &err);
		return err.code == SKP_ERR_IO && err.block < 0 ? 1 : 2;
	}
	skp_image_verdict v;
	show_image_verify(&s, beyond, NULL, &v);
	int rc = 0;
	if (v.bad == 0 && v.digest > 0) {
		fprintf(cli_summary(), "%s: all %lu blocks good: nothing to repair\n", s.path, (unsigned long)s.im.hdr.block_count);
	} else if (v.beyond > 0) {
		fprintf(stderr, "%s: %ld of %ld bad blocks beyond repair: the image is left as it was\n", s.path, v.beyond,
			v.bad);
		rc = 2;
	} else if (v.digest == 0) {
		fprintf(stderr, "%s: the data blocks do not match the image's digest (a block altered with a good CRC): "
			"the image is left as it was\n", s.path);
		rc = 2;
	} else if (cli_image_out_replace(&out, s.path, s.im.hdr.block_size) < 0) {
		rc = 1;
	} else if (rewrite(&s, &out) < 0) {
		cli_image_out_abort(&out);
		rc = 1;
	} else if (cli_image_out_commit(&out) < 0) {
		rc = 1;
	} else {
		fprintf(cli_summary(), "%s: %ld bad block%s rebuilt; the repaired image replaced the old one\n", s.path, v.bad,
		       v.bad == 1 ? "" : "s");
	}
	show_image_close(&s);
	return rc;
}
