#include "mem_report.h"

#include <string.h>

void mem_report(FILE *to)
{
	char line[256], hwm[64] = "?", rss[64] = "?";
	FILE *f = fopen("/proc/self/status", "r");
	while (f && fgets(line, sizeof line, f)) {
		if (!strncmp(line, "VmHWM:", 6))
			sscanf(line + 6, " %63[^\n]", hwm);
		else if (!strncmp(line, "VmRSS:", 6))
			sscanf(line + 6, " %63[^\n]", rss);
	}
	if (f)
		fclose(f);
	fprintf(to, "memory: VmHWM %s, VmRSS %s\n", hwm, rss);
}
