/* Text on the report page, shared by its files: HTML escaping and bone
 * names. */
#include <stdio.h>

#include "report_html.h"

void report_html_escape(FILE *f, const char *s)
{
	for (; *s; s++) {
		switch (*s) {
		case '<': fputs("&lt;", f); break;
		case '>': fputs("&gt;", f); break;
		case '&': fputs("&amp;", f); break;
		case '"': fputs("&quot;", f); break;
		default: fputc(*s, f);
		}
	}
}

const char *report_html_joint(const report *r, int joint)
{
	return joint >= 0 && joint < r->skel->count ? r->skel->bone[joint].name : "?";
}
