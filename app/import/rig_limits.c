#include "rig_limits.h"

#include <stdio.h>
#include <string.h>

#define GLB_HEADER 12
#define GLB_CHUNK 8

static uint32_t le32(const uint8_t *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* The header's length is the file's; each chunk's length fits what is
 * left of it. */
static skp_status glb_lengths(FILE *f, uint64_t size, skp_error *err)
{
	uint8_t h[GLB_HEADER];
	if (fseek(f, 0, SEEK_SET) != 0 || fread(h, 1, sizeof h, f) != sizeof h || memcmp(h, "glTF", 4))
		return SKP_OK;   /* not a glb: the library judges it */
	uint32_t total = le32(h + 8);
	if (total != size)
		return skp_fail(err, SKP_ERR_RANGE, 0, "binary glTF: its header says %lu bytes, the file has %lu",
				(unsigned long)total, (unsigned long)size);
	for (uint64_t at = GLB_HEADER; at < size;) {
		uint8_t c[GLB_CHUNK];
		if (size - at < GLB_CHUNK || fseek(f, (long)at, SEEK_SET) != 0 || fread(c, 1, sizeof c, f) != sizeof c)
			return skp_fail(err, SKP_ERR_RANGE, 0, "binary glTF: a chunk header cut off at byte %lu",
					(unsigned long)at);
		uint32_t len = le32(c);
		if (len > size - at - GLB_CHUNK)
			return skp_fail(err, SKP_ERR_RANGE, 0,
					"binary glTF: the chunk at byte %lu says %lu bytes, %lu are left in the file",
					(unsigned long)at, (unsigned long)len, (unsigned long)(size - at - GLB_CHUNK));
		at += GLB_CHUNK + (uint64_t)len;
	}
	return SKP_OK;
}

skp_status rig_limits_check(const char *path, uint64_t *size, skp_error *err)
{
	*size = 0;
	FILE *f = fopen(path, "rb");
	if (!f)
		return SKP_OK;   /* the library says why it cannot read it */
	long n = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
	skp_status rc = n < 0 ? SKP_OK : glb_lengths(f, (uint64_t)n, err);
	*size = n > 0 ? (uint64_t)n : 0;
	fclose(f);
	return rc;
}

size_t rig_limits_budget(uint64_t size)
{
	uint64_t b = RIG_IMPORT_BASE_BYTES + size * RIG_IMPORT_BYTES_PER_BYTE;
	return b > (uint64_t)SIZE_MAX / 2 ? SIZE_MAX / 2 : (size_t)b;
}

int rig_limits_texture_fits(uint32_t w, uint32_t h, const char **why)
{
	if (w <= RIG_TEXTURE_MAX_SIDE && h <= RIG_TEXTURE_MAX_SIDE)
		return 1;
	*why = "is larger than 8192 pixels a side";
	return 0;
}
