/* An image written where another may already be: to a temporary that
 * becomes the target only once whole and synced (atomic_file.h), as block
 * storage for the image writer. skintool pack and skintool repair. */
#ifndef CLI_IMAGE_OUT_H
#define CLI_IMAGE_OUT_H

#include <stdint.h>

#include "atomic_file.h"
#include "storage_file.h"

typedef struct cli_image_out {
	atomic_file af;
	storage_file sf;          /* sf.bd: the blocks to write (and read back) */
} cli_image_out;

/* Returns 0, or -1 after reporting (path is one of the command's inputs:
 * cli_inputs.h). */
int cli_image_out_open(cli_image_out *o, const char *path, uint32_t block_size);

/* The same for an output that replaces its input by design (repair). */
int cli_image_out_replace(cli_image_out *o, const char *path, uint32_t block_size);

/* The image becomes path (synced, then the directory synced). Returns 0,
 * or -1 after reporting, with path untouched and nothing left behind. */
int cli_image_out_commit(cli_image_out *o);

/* Drops what was written; path is untouched. */
void cli_image_out_abort(cli_image_out *o);

#endif
