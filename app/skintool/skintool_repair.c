/* skintool repair show.skn
 * Rebuilds every bad block of an image that has parity (format version 2):
 * data blocks from their parity group, parity blocks from their data, the
 * header copy from the header. The repaired image is written beside the old
 * one, synced and renamed over it (cli_image_out.h), so the old image is
 * never lost. Exit status 0 when the image is whole (repaired, or nothing
 * to repair), 2 when a block is beyond repair (the image is left as it
 * was), 1 when it cannot be read or written. */
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cli_image_out.h"
#include "cli_show.h"
#include "image_parity.h"
#include "skintool_cmds.h"
#include "tool_args.h"

static void beyond(void *ctx, uint32_t b, const skp_block_report *r)
{
	long *count = ctx;
	if (!r->repairable)
		fprintf(stderr, "block %lu: %s (%s): beyond repair\n", (unsigned long)b,
			skp_block_state_name(r->state), skp_block_report_what(r));
	(*count)++;
}

/* Every data block as the reader rebuilds it, then fresh parity and copy. */
static int rewrite(show_image *s, cli_image_out *out)
{
	static uint8_t buf[SKP_IMAGE_BLOCK_SIZE], tmp[SKP_IMAGE_BLOCK_SIZE];
	const skp_image_header *h = &s->im.hdr;
	const skp_blockdev *dev = &out->sf.bd;
	skp_error err;
	for (uint32_t b = 0; b < h->data_blocks; b++) {
		int kind;
		unsigned item;
		skp_image_block_role(&s->im, b, &kind, &item);
		skp_block_state st = skp_image_read_block(&s->im, b, kind, item, buf);
		if (st != SKP_BLOCK_OK) {
			fprintf(stderr, "%s: block %lu: %s on the second read\n", s->path, (unsigned long)b,
				skp_block_state_name(st));
			return -1;
		}
		if (dev->write(dev->ctx, b, buf) < 0) {
			fprintf(stderr, "%s: cannot write block %lu\n", out->af.path, (unsigned long)b);
			return -1;
		}
	}
	if (skp_parity_write(dev, h, NULL, buf, tmp, &err) != SKP_OK) {
		cli_error(out->af.path, &err);
		return -1;
	}
	skp_header_copy_frame(buf, h);
	if (dev->write(dev->ctx, h->copy_block, buf) < 0) {
		fprintf(stderr, "%s: cannot write the header copy\n", out->af.path);
		return -1;
	}
	return 0;
}

static const cli_command repair_command = {
	.prog = "skintool repair",
	.usage = "SHOW.skn",
	.about = "Rebuilds an image's bad blocks from its parity and replaces the file (written under a\n"
		 "temporary name, synced and renamed). Exit status 2, the file untouched, when a block is\n"
		 "beyond repair.",
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
	long bad = 0, lost;
	show_image_verify(&s, beyond, &bad, &lost);
	int rc = 0;
	if (bad == 0)
		printf("%s: all %lu blocks good: nothing to repair\n", s.path, (unsigned long)s.im.hdr.block_count);
	else if (lost > 0 || s.im.hdr.version < 2) {
		fprintf(stderr, "%s: %ld of %ld bad blocks beyond repair%s: the image is left as it was\n", s.path,
			lost ? lost : bad, bad, s.im.hdr.version < 2 ? " (format version 1 has no parity)" : "");
		rc = 2;
	} else if (cli_image_out_open(&out, s.path, s.im.hdr.block_size) < 0) {
		rc = 1;
	} else if (rewrite(&s, &out) < 0) {
		cli_image_out_abort(&out);
		rc = 1;
	} else if (cli_image_out_commit(&out) < 0) {
		rc = 1;
	} else {
		printf("%s: %ld bad block%s rebuilt; the repaired image replaced the old one\n", s.path, bad,
		       bad == 1 ? "" : "s");
	}
	show_image_close(&s);
	return rc;
}
