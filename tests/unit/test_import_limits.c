/* The importer's bounds: a binary glTF whose header or chunk lengths do not
 * fit its size is refused before the asset library sees it (a 94 KB glb
 * claiming a 2 GB chunk took 2.1 GB and 10 s), and the memory an import
 * may take is capped (an allocation past the cap fails, and works again
 * once the cap is released). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mem_cap.h"
#include "rig_limits.h"
#include "rig_scene.h"
#include "test_paths.h"

static char path[] = "/tmp/skp_glb_XXXXXX";

static void le32(uint8_t *p, uint32_t v)
{
	for (int i = 0; i < 4; i++)
		p[i] = (uint8_t)(v >> (8 * i));
}

/* A glb: header, a JSON chunk of 8 bytes, a BIN chunk of 16. */
static size_t make_glb(uint8_t *d)
{
	memset(d, 0, 64);
	memcpy(d, "glTF", 4);
	le32(d + 4, 2);
	le32(d + 8, 12 + 8 + 8 + 8 + 16);
	le32(d + 12, 8);
	memcpy(d + 16, "JSON", 4);
	memcpy(d + 20, "{}      ", 8);
	le32(d + 28, 16);
	memcpy(d + 32, "BIN\0", 4);
	return 12 + 8 + 8 + 8 + 16;
}

static skp_status check(const uint8_t *d, size_t n, skp_error *err)
{
	uint64_t size;
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(d, 1, n, f), n);
	fclose(f);
	return rig_limits_check(path, &size, err);
}

static void test_glb_lengths(void **state)
{
	(void)state;
	uint8_t d[64];
	skp_error err;
	size_t n = make_glb(d);
	assert_int_equal(check(d, n, &err), SKP_OK);
	le32(d + 8, 0x7ffffff0);
	assert_int_equal(check(d, n, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "its header says 2147483632 bytes, the file has 52"));
	n = make_glb(d);
	le32(d + 28, 0x7ffffff0);
	assert_int_equal(check(d, n, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "the chunk at byte 28 says 2147483632 bytes, 16 are left"));
	n = make_glb(d);
	le32(d + 8, 32);
	assert_int_equal(check(d, 32, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "a chunk header cut off at byte 28"));
	/* not a glb: the library judges it */
	assert_int_equal(check((const uint8_t *)"v 0 0 0\n", 8, &err), SKP_OK);
}

/* The shared CC0 glb passes; with its BIN chunk's length made 2 GB the
 * import is refused at once, naming the chunk. */
static void test_real_glb(void **state)
{
	(void)state;
	const char *glb = test_data_path("mesh/orange_juice_male_base/male_base_mesh.glb");
	size_t n;
	uint8_t *d = glb ? (uint8_t *)test_read_file(glb, &n) : NULL;
	if (!d)
		skip();
	skp_error err;
	assert_int_equal(check(d, n, &err), SKP_OK);
	uint32_t json = (uint32_t)d[12] | (uint32_t)d[13] << 8 | (uint32_t)d[14] << 16 | (uint32_t)d[15] << 24;
	le32(d + 20 + json, 0x7ffffff0);
	static mesh m;
	static rig_scene r;
	r.mesh = &m;
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(d, 1, n, f), n);
	fclose(f);
	assert_int_equal(rig_import(path, NULL, &r, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "says 2147483632 bytes"));
	free(d);
}

static void test_memory_cap(void **state)
{
	(void)state;
	mem_cap cap;
	/* qemu-user maps the guest's heap inside space it reserved before the
	 * cap: the cap holds on the Pi, not under the emulator */
	if (test_emulator())
		skip();
	assert_int_equal(mem_cap_set(&cap, (size_t)64 << 20), 0);
	if (!cap.set)
		skip();   /* AddressSanitizer's build: no cap */
	void *big = malloc((size_t)256 << 20);
	mem_cap_release(&cap);
	assert_null(big);
	big = malloc((size_t)256 << 20);
	assert_non_null(big);
	free(big);
	assert_true(rig_limits_budget(94 * 1024) == RIG_IMPORT_BASE_BYTES + 94 * 1024 * RIG_IMPORT_BYTES_PER_BYTE);
}

static int teardown(void **state)
{
	(void)state;
	remove(path);
	return 0;
}

int main(void)
{
	int fd = mkstemp(path);
	if (fd < 0)
		return 1;
	close(fd);
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_glb_lengths),
		cmocka_unit_test(test_real_glb),
		cmocka_unit_test(test_memory_cap),
	};
	return cmocka_run_group_tests(tests, NULL, teardown);
}
