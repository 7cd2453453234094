#include "setup_scratch.h"

setup_scratch *setup_scratch_area(void)
{
	static setup_scratch area;
	return &area;
}
