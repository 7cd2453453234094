#include "mem_cap.h"

#include <errno.h>
#include <stdio.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define MEM_CAP_OFF 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MEM_CAP_OFF 1
#endif
#endif

#ifndef MEM_CAP_OFF
/* Address space in use now: /proc/self/statm's first field, in pages. */
static size_t in_use(void)
{
	unsigned long pages = 0;
	FILE *f = fopen("/proc/self/statm", "r");
	if (f) {
		if (fscanf(f, "%lu", &pages) != 1)
			pages = 0;
		fclose(f);
	}
	return (size_t)pages * (size_t)sysconf(_SC_PAGESIZE);
}
#endif

int mem_cap_set(mem_cap *c, size_t budget)
{
	c->set = 0;
	c->limit = 0;
#ifdef MEM_CAP_OFF
	(void)budget;
	return 0;
#else
	size_t used = in_use();
	if (used == 0 || getrlimit(RLIMIT_AS, &c->old) != 0)
		return used == 0 ? 0 : -errno;
	rlim_t want = (rlim_t)(used + budget);
	if (c->old.rlim_cur != RLIM_INFINITY && c->old.rlim_cur <= want)
		return 0;   /* already tighter */
	struct rlimit cap = { want, c->old.rlim_max };
	if (setrlimit(RLIMIT_AS, &cap) != 0)
		return -errno;
	c->set = 1;
	c->limit = (size_t)want;
	return 0;
#endif
}

void mem_cap_release(mem_cap *c)
{
	if (c->set)
		setrlimit(RLIMIT_AS, &c->old);
	c->set = 0;
}
