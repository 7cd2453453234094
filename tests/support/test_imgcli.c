/* Flash images through the real tools (test_imgcli.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_imgcli.h"
#include "test_paths.h"
#include "test_run.h"

char *imgcli_slurp(const char *path)
{
	size_t n;
	char *t = test_read_file(path, &n);
	assert_non_null(t);
	return t;
}

int imgcli_info_names(const char *image, long want)
{
	const char *out = test_scratch("info.txt");
	int st = test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), image, out);
	char *text = imgcli_slurp(out);
	int named = 0;
	for (char *p = text; (p = strstr(p, "block ")) != NULL; p += 6) {
		long b;
		char word[8];
		if (sscanf(p + 6, "%ld %7s", &b, word) == 2 && !strcmp(word, "bad:")) {
			if (b != want)
				fail_msg("%s: block %ld named, expected %ld:\n%s", image, b, want, text);
			named++;
		}
	}
	if (want >= 0 && !named)
		fail_msg("%s: block %ld not named:\n%s", image, want, text);
	free(text);
	return st;
}

int imgcli_cmu_walk(char *asf, char *amc)
{
	if (!test_data_path("mocap"))
		return 0;
	snprintf(asf, 1024, "%s", test_data_path("mocap/cmu/02.asf"));
	snprintf(amc, 1024, "%s", test_data_path("mocap/cmu/02_01.amc"));
	return 1;
}
