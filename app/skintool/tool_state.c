#include "tool_state.h"

#include <stdio.h>
#include <stdlib.h>

void *tool_state(void **slot, size_t size)
{
	if (!*slot && !(*slot = calloc(1, size))) {
		fprintf(stderr, "skintool: out of memory (%zu MiB of working state)\n", size >> 20);
		exit(1);
	}
	return *slot;
}
