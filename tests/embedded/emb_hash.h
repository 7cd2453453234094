/* The embedded test's hash of skinned output: the fixed-point DQBS kernel
 * run over a vertex table in chunks, each Q16.16 output fed to FNV-1a as
 * 4 little-endian bytes, so every target hashes the same bytes. */
#ifndef EMB_HASH_H
#define EMB_HASH_H

#include <stdint.h>

#include "skin.h"

typedef struct fnv {
	uint32_t h;
} fnv;

#define EMB_FNV_START 2166136261u

void emb_fnv_i32(fnv *f, int32_t v);

/* The bones emb_skin_hash skins with: filled by the caller per frame. */
extern skin_bones emb_bones;

/* Skins vertices [0, in->count) with emb_bones into the hash. */
void emb_skin_hash(const skin_soa *in, fnv *f);

#endif
