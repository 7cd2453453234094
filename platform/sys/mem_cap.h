/* A cap on the process's address space around a library call that may
 * allocate without bound on hostile input (the asset importer): what the
 * process uses now plus a budget (RLIMIT_AS, the soft limit only), so an
 * allocation past it fails inside the library instead of taking the
 * machine's memory. No cap in an AddressSanitizer build, whose shadow
 * memory is address space. */
#ifndef MEM_CAP_H
#define MEM_CAP_H

#include <stddef.h>
#include <sys/resource.h>

typedef struct mem_cap {
	struct rlimit old;
	int set;                  /* a cap is in force */
	size_t limit;             /* its bytes of address space */
} mem_cap;

/* Caps at the address space in use plus budget bytes. Returns 0 (also
 * when no cap is possible: then c->set is 0) or -errno. */
int mem_cap_set(mem_cap *c, size_t budget);

/* The limit as it was. */
void mem_cap_release(mem_cap *c);

#endif
