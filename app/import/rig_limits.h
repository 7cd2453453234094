/* Bounds on what the asset importer is handed: a file whose own counts
 * cannot fit its size is refused before the library sees it (a binary
 * glTF's header and chunk lengths say how much it allocates), and the
 * memory the import may take is capped (platform/sys/mem_cap.h). */
#ifndef RIG_LIMITS_H
#define RIG_LIMITS_H

#include <stddef.h>
#include <stdint.h>

#include "skp_error.h"

/* Memory the import may take beyond what skintool holds already: 1 GiB
 * and 64 bytes for each byte of the file. */
#define RIG_IMPORT_BASE_BYTES ((size_t)1 << 30)
#define RIG_IMPORT_BYTES_PER_BYTE 64

/* A binary glTF's lengths checked against its size (other files pass).
 * *size: the file's bytes. SKP_OK, or an error naming the length. */
skp_status rig_limits_check(const char *path, uint64_t *size, skp_error *err);

/* The import's memory budget for a file of size bytes. */
size_t rig_limits_budget(uint64_t size);

#define RIG_TEXTURE_MAX_SIDE 8192 /* a texture wider or taller is not read */

/* Whether a texture of w x h pixels (from its header, before any pixel is
 * decoded) may be read: 1, or 0 with why the words every decoder says. */
int rig_limits_texture_fits(uint32_t w, uint32_t h, const char **why);

#endif
