/* SHA-256 (FIPS 180-4): the flash image's whole-image digest. Streaming,
 * fixed memory (the context), no tables in RAM. */
#ifndef SHA256_H
#define SHA256_H

#include <stddef.h>
#include <stdint.h>

#define SHA256_BYTES 32

typedef struct sha256_ctx {
	uint32_t h[8];
	uint64_t length;          /* bytes hashed so far */
	uint8_t block[64];
	uint32_t fill;            /* bytes in block */
} sha256_ctx;

void sha256_init(sha256_ctx *c);
void sha256_update(sha256_ctx *c, const void *data, size_t len);
void sha256_final(sha256_ctx *c, uint8_t out[SHA256_BYTES]);

#endif
