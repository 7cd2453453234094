/* Random bytes from the kernel (getrandom): an image's id at pack time. */
#ifndef RANDOM_BYTES_H
#define RANDOM_BYTES_H

#include <stddef.h>

/* Fills buf with n random bytes. Returns 0 or -errno. */
int random_bytes(void *buf, size_t n);

#endif
