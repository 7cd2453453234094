/* What the embedded test needs from its target: text output and exit. The
 * host build writes to stdout; the Cortex-M builds use semihosting
 * (emb_cortex_m.c). */
#ifndef EMB_PORT_H
#define EMB_PORT_H

void emb_puts(const char *s);
/* The test itself: 0 when it ran to the end. */
int emb_main(void);

#endif
