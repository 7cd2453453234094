#include "cli_program.h"

#include <stdio.h>
#include <string.h>

static char program[32] = "skintool";

void cli_set_program(const char *prog)
{
	snprintf(program, sizeof program, "%.*s", (int)strcspn(prog, " "), prog);
}

const char *cli_program(void)
{
	return program;
}
