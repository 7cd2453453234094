#include "cli_scratch.h"

cli_scratch *cli_scratch_area(void)
{
	static cli_scratch area;
	return &area;
}
