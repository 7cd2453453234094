/* The writer's section byte stream, shared by image_write.c and the clip
 * writer (image_write_clip.c) only. Private to app/image. */
#ifndef IMAGE_WRITE_INTERNAL_H
#define IMAGE_WRITE_INTERNAL_H

#include "image_write.h"

/* A section of kind and item starts at the next block; put appends to it
 * across blocks, sec_end writes its partial last block and gives its
 * extent (out may be NULL). */
void image_sec_begin(skp_image_writer *w, uint8_t kind, uint16_t item);
skp_status image_sec_end(skp_image_writer *w, skp_image_section *out, skp_error *err);
skp_status image_put_u8(skp_image_writer *w, unsigned v, skp_error *err);
skp_status image_put_u16(skp_image_writer *w, unsigned v, skp_error *err);
skp_status image_put_u32(skp_image_writer *w, uint32_t v, skp_error *err);
skp_status image_put_f32(skp_image_writer *w, float v, skp_error *err);

/* Frames w->block, CRCs it and writes it at the next position. */
skp_status image_flush_block(skp_image_writer *w, skp_error *err);

#endif
