/* CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320, init and final
 * xor 0xFFFFFFFF: the zlib/PNG checksum, "123456789" -> 0xCBF43926).
 * Table-driven, the table is const data: no RAM, no malloc. */
#ifndef CRC32_H
#define CRC32_H

#include <stddef.h>
#include <stdint.h>

/* CRC of len bytes. */
uint32_t crc32_compute(const void *data, size_t len);

/* Continues a CRC: crc32_update(crc32_update(0, a, n), b, m) equals the CRC
 * of a followed by b; start from 0. */
uint32_t crc32_update(uint32_t crc, const void *data, size_t len);

#endif
