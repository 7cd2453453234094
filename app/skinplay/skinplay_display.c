/* Which display skinplay draws on: the one --platform names, or what auto
 * picks, falling back to OSMesa where headless EGL cannot start. Shared by
 * the frame loop's setup (skinplay.c) and the no-show screen
 * (skinplay_wait.c). */
#include <stdio.h>
#include <string.h>

#include "cli_quiet.h"
#include "skinplay.h"

int open_display(skinplay *p)
{
	skp_error err, first;
	display_config cfg = { p->o.width, p->o.height, p->o.device, p->o.rotation };
	p->disp = display_open(p->o.platform, &cfg, &p->info, &first, &err);
	if (first.code != SKP_OK)
		fprintf(stderr, "skinplay: %s; trying osmesa\n", first.msg);
	if (!p->disp) {
		fprintf(stderr, "skinplay: %s\n", err.msg);
		return -1;
	}
	if (gl_api_load(&p->gl, p->disp->get_proc, &err) != SKP_OK) {
		fprintf(stderr, "skinplay: %s: %s\n", p->disp->name, err.msg);
		p->disp->shutdown();
		return -1;
	}
	p->headless = !strcmp(p->disp->name, "surfaceless") || !strcmp(p->disp->name, "osmesa");
	fprintf(cli_note(), "display: %s %dx%d, %s\n", p->disp->name, p->info.width, p->info.height,
		p->info.gl_renderer ? p->info.gl_renderer : "?");
	return 0;
}
