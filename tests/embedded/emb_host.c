/* Host build of the embedded test: the reference checksum. */
#include <stdio.h>

#include "emb_port.h"

void emb_puts(const char *s)
{
	fputs(s, stdout);
}

int main(void)
{
	return emb_main();
}
