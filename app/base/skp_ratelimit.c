#include "skp_ratelimit.h"

void skp_ratelimit_init(skp_ratelimit *r, uint64_t interval_ns)
{
	r->interval = interval_ns;
	r->said_at = 0;
	r->held = 0;
	r->said = 0;
}

int skp_ratelimit_take(skp_ratelimit *r, uint64_t now, unsigned long *held_back)
{
	/* a clock that went back (a new clip's clock): as if the interval passed */
	if (r->said && now >= r->said_at && now - r->said_at < r->interval) {
		r->held++;
		return 0;
	}
	*held_back = r->held;
	r->held = 0;
	r->said = 1;
	r->said_at = now;
	return 1;
}
