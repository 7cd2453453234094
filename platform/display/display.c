/* The display registry: the one file that names the backends, each built
 * when the board lists it (board.mk: DISPLAYS -> SKP_DISPLAY_<name>). */
#include "display.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef SKP_DISPLAY_surfaceless
#error "every board builds the surfaceless backend: headless runs, tests and display_auto's fallback"
#endif

extern const display_backend display_surfaceless, display_osmesa, display_kms, display_x11;

static const display_backend *const backends[] = {
#ifdef SKP_DISPLAY_surfaceless
	&display_surfaceless,
#endif
#ifdef SKP_DISPLAY_osmesa
	&display_osmesa,
#endif
#ifdef SKP_DISPLAY_kms
	&display_kms,
#endif
#ifdef SKP_DISPLAY_x11
	&display_x11,
#endif
};

const display_backend *display_find(const char *name)
{
	if (!name)
		return NULL;
	for (size_t i = 0; i < sizeof backends / sizeof backends[0]; i++)
		if (strcmp(backends[i]->name, name) == 0)
			return backends[i];
	return NULL;
}

void display_list(char *out, size_t size)
{
	size_t used = 0;
	out[0] = '\0';
	for (size_t i = 0; i < sizeof backends / sizeof backends[0] && used < size; i++)
		used += (size_t)snprintf(out + used, size - used, "%s%s", i ? " " : "", backends[i]->name);
}

static int env_set(const char *name)
{
	const char *v = getenv(name);
	return v && *v;
}

const display_backend *display_auto(void)
{
	const display_backend *kms = display_find("kms"), *x11 = display_find("x11");
	/* Under a display server the DRM device belongs to it: do not even
	 * probe, taking master would fail or blank its screen. */
	if (kms && !env_set("DISPLAY") && !env_set("WAYLAND_DISPLAY") && kms->available())
		return kms;
	if (x11 && env_set("DISPLAY"))
		return x11;
	return display_find("surfaceless");
}
