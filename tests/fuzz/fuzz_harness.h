/* Fuzz harnesses: each feeds one input through a parser of app/ the way a
 * front end would, and returns 0. The libFuzzer targets (fuzz_*.c) call
 * them; so does tests/unit/test_fuzz_regressions.c with every input kept
 * under tests/fuzz/regressions/<name>/, so a fixed crash stays fixed. */
#ifndef FUZZ_HARNESS_H
#define FUZZ_HARNESS_H

#include <stddef.h>
#include <stdint.h>

typedef int (*fuzz_fn)(const uint8_t *data, size_t size);

typedef struct fuzz_target {
	const char *name; /* also the regressions/ subdirectory */
	fuzz_fn run;
} fuzz_target;

int fuzz_asf(const uint8_t *data, size_t size);
int fuzz_amc(const uint8_t *data, size_t size);
int fuzz_bvh(const uint8_t *data, size_t size);
int fuzz_obj(const uint8_t *data, size_t size);
int fuzz_ini(const uint8_t *data, size_t size);
int fuzz_board_config(const uint8_t *data, size_t size);
int fuzz_image(const uint8_t *data, size_t size);
int fuzz_joint_map(const uint8_t *data, size_t size);
int fuzz_makehuman(const uint8_t *data, size_t size);
int fuzz_mesh_format(const uint8_t *data, size_t size);
int fuzz_codec(const uint8_t *data, size_t size);
int fuzz_mtl(const uint8_t *data, size_t size);

/* Every harness, NULL-terminated. */
extern const fuzz_target fuzz_targets[];

#endif
