/* Every data block's own digest, the reader's half: the digest blocks
 * checked against the header's root when an image opens, then each block
 * read checked against its leaf in the digest block that covers it (one
 * digest block held at a time, checked against its own leaf). Fixed
 * memory: skp_image's top[] and leaves[]. */
#include "image_digests.h"

#include <string.h>

#include "image_error.h"
#include "image_parity.h"
#include "image_read.h"
#include "sha256.h"

uint32_t skp_digest_per_block(uint32_t bs)
{
	return (bs - SKP_IMAGE_BLOCK_EXTRA) / SKP_IMAGE_LEAF_BYTES;
}

uint32_t skp_digest_first(const skp_image_header *h)
{
	if (h->version < 7)
		return 0;
	return h->sec[SKP_SEC_DIRECTORY].first + h->sec[SKP_SEC_DIRECTORY].count;
}

uint32_t skp_digest_blocks(uint32_t leaves, uint32_t bs)
{
	uint32_t per = skp_digest_per_block(bs);
	return (uint32_t)(((uint64_t)leaves + per - 1) / per);
}

void skp_block_leaf(const uint8_t *block, uint32_t bs, uint8_t leaf[SKP_IMAGE_LEAF_BYTES])
{
	sha256_ctx c;
	uint8_t sum[SHA256_BYTES];
	sha256_init(&c);
	sha256_update(&c, block, bs);
	sha256_final(&c, sum);
	memcpy(leaf, sum, SKP_IMAGE_LEAF_BYTES);
}

static int root_holds(const skp_image *im, uint32_t n)
{
	sha256_ctx c;
	uint8_t sum[SHA256_BYTES];
	sha256_init(&c);
	sha256_update(&c, im->top, (size_t)n * SKP_IMAGE_LEAF_BYTES);
	sha256_final(&c, sum);
	return memcmp(sum, im->hdr.digest, SHA256_BYTES) == 0;
}

/* Digest block j into im->leaves: as stored, or rebuilt from parity
 * whatever is stored. Its frame checked; its leaf is the caller's. */
static skp_block_state digest_block_read(skp_image *im, uint32_t j, int rebuild)
{
	uint32_t b = im->digest_first + j;
	im->leaves_at = UINT32_MAX;
	return rebuild ? skp_image_rebuild(im, b, SKP_KIND_DIGESTS, 0, im->leaves)
		       : skp_image_read_framed(im, b, SKP_KIND_DIGESTS, 0, im->leaves);
}

static void told_rebuilt(skp_image *im, uint32_t block)
{
	im->rebuilt++;
	im->rebuilt_from = "parity";
	if (im->on_rebuild)
		im->on_rebuild(im->on_rebuild_ctx, block);
}

/* The root does not hold: a digest block altered with its CRC made again.
 * The one whose parity rebuild gives the root is taken as rebuilt. */
static int digest_block_altered(skp_image *im, uint32_t n)
{
	uint8_t kept[SKP_IMAGE_LEAF_BYTES];
	for (uint32_t j = 0; j < n; j++) {
		if (digest_block_read(im, j, 1) != SKP_BLOCK_OK)
			continue;
		memcpy(kept, im->top[j], sizeof kept);
		skp_block_leaf(im->leaves, im->hdr.block_size, im->top[j]);
		if (root_holds(im, n)) {
			told_rebuilt(im, im->digest_first + j);
			return 1;
		}
		memcpy(im->top[j], kept, sizeof kept);
	}
	return 0;
}

skp_status skp_image_digests_open(skp_image *im, skp_error *err)
{
	const skp_image_header *h = &im->hdr;
	im->digests = im->digests_broken = 0;
	im->leaves_at = UINT32_MAX;
	im->digest_first = skp_digest_first(h);
	if (im->digest_first == 0)
		return SKP_OK;
	uint32_t n = h->data_blocks - im->digest_first;
	if (n > SKP_IMAGE_MAX_DIGEST_BLOCKS)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "image needs %lu digest blocks, board limit "
				"SKP_IMAGE_MAX_DIGEST_BLOCKS is %d", (unsigned long)n, SKP_IMAGE_MAX_DIGEST_BLOCKS);
	for (uint32_t j = 0; j < n; j++) {
		skp_block_state st = digest_block_read(im, j, 0);
		if (st != SKP_BLOCK_OK && st != SKP_BLOCK_SHORT && digest_block_read(im, j, 1) == SKP_BLOCK_OK) {
			told_rebuilt(im, im->digest_first + j);
			st = SKP_BLOCK_OK;
		}
		if (st == SKP_BLOCK_SHORT) /* the data blocks end early */
			return image_block_fail(err, SKP_ERR_CORRUPT, im->digest_first + j,
						"block digests section: short read (image truncated)");
		if (st == SKP_BLOCK_OK)
			skp_block_leaf(im->leaves, h->block_size, im->top[j]);
		else
			memset(im->top[j], 0, SKP_IMAGE_LEAF_BYTES);
	}
	im->digests = root_holds(im, n) || digest_block_altered(im, n);
	im->digests_broken = !im->digests;
	return SKP_OK;
}

/* Digest block j held in im->leaves as the root knows it: as stored, else
 * rebuilt (not when the caller's block is in im->scratch, which a rebuild
 * uses). 0 when neither matches its leaf. */
static int digest_block_held(skp_image *im, uint32_t j, int may_rebuild)
{
	uint8_t leaf[SKP_IMAGE_LEAF_BYTES];
	if (im->leaves_at == j)
		return 1;
	for (int rebuild = 0; rebuild <= may_rebuild; rebuild++) {
		if (digest_block_read(im, j, rebuild) != SKP_BLOCK_OK)
			continue;
		skp_block_leaf(im->leaves, im->hdr.block_size, leaf);
		if (memcmp(leaf, im->top[j], sizeof leaf) == 0) {
			im->leaves_at = j;
			return 1;
		}
	}
	return 0;
}

skp_block_state skp_image_leaf_check(skp_image *im, uint32_t block, const uint8_t *buf)
{
	uint32_t bs = im->hdr.block_size, per = skp_digest_per_block(bs);
	uint8_t leaf[SKP_IMAGE_LEAF_BYTES];
	if (!im->digests || block == 0 || block >= im->hdr.data_blocks)
		return SKP_BLOCK_OK;
	skp_block_leaf(buf, bs, leaf);
	const uint8_t *want;
	if (block >= im->digest_first)
		want = im->top[block - im->digest_first];
	else if (digest_block_held(im, block / per, buf != im->scratch))
		want = im->leaves + SKP_IMAGE_BLOCK_HDR + (block % per) * SKP_IMAGE_LEAF_BYTES;
	else /* its digest lost as well (two faults): the CRC alone judges it */
		return SKP_BLOCK_OK;
	return memcmp(leaf, want, sizeof leaf) ? SKP_BLOCK_DIGEST : SKP_BLOCK_OK;
}
