/* The image's log lines: each block rebuilt or lost is logged once, the
 * rest counted, so a dying card does not fill the journal. */

#include "show_source.h"
#include "cli_say.h"

int show_log_once(show_image *img, long block)
{
	for (int i = 0; i < img->logged_count; i++)
		if (img->logged[i] == block)
			return 0;
	if (img->logged_count < SHOW_MAX_LOGGED) {
		img->logged[img->logged_count++] = block;
		return 1;
	}
	/* a dying card: past the table, blocks are counted, not listed */
	if (img->unlisted++ == 0)
		cli_warn("image: %s: more than %d damaged blocks: further ones are counted, not listed\n",
			img->path, SHOW_MAX_LOGGED);
	return 0;
}

void show_log_rebuild(void *ctx, uint32_t block)
{
	show_image *img = ctx;
	int kind;
	unsigned item;
	skp_block_report r = { .role = SKP_ROLE_DATA };
	skp_image_block_role(&img->im, block, &kind, &item);
	r.kind = kind;
	if (!show_log_once(img, (long)block))
		return;
	if (block == 0 && img->im.header_from_parity)
		cli_warn("image: %s: block 0 and the header copy bad: header rebuilt from parity group 0\n",
			img->path);
	else if (block == 0 && img->im.header_from_copy)
		cli_warn("image: %s: block 0 bad: header read from its copy\n", img->path);
	else
		cli_warn("image: %s: block %lu rebuilt from %s (%s, parity group %lu)\n", img->path,
			(unsigned long)block, img->im.rebuilt_from, skp_block_report_what(&r),
			(unsigned long)skp_image_group(&img->im.hdr, block));
}
