/* skintool bench-image's figures of the per-block digests (format
 * version 7; bench_image_digests.c): what checking the digest blocks
 * against the root adds to an image's open, and what checking every block
 * read against its leaf adds to the first frame and to a frame's decode,
 * each against the same image with the check off in the same run. */
#ifndef BENCH_IMAGE_DIGESTS_H
#define BENCH_IMAGE_DIGESTS_H

#include "show_source.h"

/* Prints the figures for an opened image (nothing for versions 4 to 6);
 * best of runs each. */
void bench_block_digests(show_image *img, long runs);

#endif
