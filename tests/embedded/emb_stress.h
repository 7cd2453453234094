/* The embedded test's stress part: the fixed kernel on made-up bones and
 * vertices (emb_stress.c says which paths they reach), hashed. The same
 * LCG on every board, so the checksum must be equal everywhere. */
#ifndef EMB_STRESS_H
#define EMB_STRESS_H

#include <stdint.h>

/* bone_count bones (the embedded skeleton's), 48 rounds of 64 vertices. */
uint32_t emb_stress_checksum(int bone_count);

#endif
