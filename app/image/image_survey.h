/* Every block of an image judged for `skintool info`, `repair` and the
 * slot choice: what it holds, whether it is good, and if not whether
 * `skintool repair` (or the reader, on the fly) can rebuild it; and the
 * whole image against the digest in its header. */
#ifndef IMAGE_SURVEY_H
#define IMAGE_SURVEY_H

#include "image_read.h"

typedef enum skp_block_role {
	SKP_ROLE_DATA,           /* header, sections, clips */
	SKP_ROLE_PARITY,         /* the XOR of a parity group */
	SKP_ROLE_DIR_COPY,       /* the directory copy */
	SKP_ROLE_COPY            /* the header copy */
} skp_block_role;

typedef struct skp_block_report {
	skp_block_role role;
	int kind;                /* data: the SKP_KIND_* it must be */
	unsigned item;           /* its clip for kinds 5 and 6 */
	uint32_t group;          /* data and parity: the parity group */
	skp_block_state state;   /* good, or why not; parity: CRC when it does not match its group;
	                          * copies: MISPLACED when they differ from what they copy */
	int checked;             /* parity: 0 when a bad data block of its group hides whether it matches */
	int repairable;          /* bad, and rebuilt from its group or its copy (data), recomputed
	                          * (parity) or rewritten from what it copies (copies) */
} skp_block_report;

/* What data block b of an opened image must be. */
void skp_image_block_role(const skp_image *im, uint32_t b, int *kind, unsigned *item);

/* Judges block b. buf: one block of the caller's (im->buf and im->scratch
 * are used too: not while a section is being read);
 * for a data block it holds the block as packed afterwards when the block
 * is good or repairable. */
void skp_image_survey(skp_image *im, uint32_t b, skp_block_report *r, uint8_t *buf);

/* "header", "skeleton", "bind", "clip directory", "clip quantisation",
 * "clip frames" for a kind; "parity", "directory copy" and "header copy"
 * by role. */
const char *skp_block_report_what(const skp_block_report *r);

typedef struct skp_image_verdict {
	long bad;                /* blocks not as packed */
	long beyond;             /* ... of which beyond repair */
	int digest;              /* 1 the data blocks (as rebuilt) match the header's digest,
	                          * 0 they do not, -1 unknown (a data block beyond repair) */
} skp_image_verdict;

/* Surveys every block of an opened image, calling bad (when non-NULL) for
 * each bad one, and checks the digest. buf: one block of the caller's. */
void skp_image_verify(skp_image *im, uint8_t *buf, void (*bad)(void *ctx, uint32_t block, const skp_block_report *r),
		      void *ctx, skp_image_verdict *v);

#endif
