/* The display registry: the one file that names the backends, each built
 * when the board lists it (board.mk: DISPLAYS -> SKP_DISPLAY_<name>). */
#include "display.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef __GLIBC__ /* (defined by the headers above) */
#include <malloc.h>
#endif

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

/* Mesa's llvmpipe mallocs and frees about 2 MB in small blocks every
 * frame; glibc hands the freed top of the heap back to the kernel (its
 * trim threshold is 128 KiB) and the next frame faults every page in
 * again: at 160x90 that was 17 ms of CPU a frame, 3 ms with the heap kept.
 * Kept up to 64 MiB: no more memory than the frame's peak, held. */
static void keep_heap_between_frames(void)
{
#ifdef __GLIBC__
	mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

const display_backend *display_open(const char *name, const display_config *cfg, display_info *info,
				    skp_error *first, skp_error *err)
{
	int chosen = name && strcmp(name, "auto") && strcmp(name, "headless");
	const display_backend *d = !chosen ? (name && !strcmp(name, "headless") ? display_find("surfaceless")
										 : display_auto())
					   : display_find(name);
	skp_error_clear(first);
	keep_heap_between_frames();
	if (!d) {
		char names[128];
		display_list(names, sizeof names);
		skp_fail(err, SKP_ERR_RANGE, 0, "unknown platform '%s' (this build has: %s; or auto)", name, names);
		return NULL;
	}
	if (d->init(cfg, info, err) == 0)
		return d;
	/* headless EGL can be missing where Mesa's OSMesa still works */
	const display_backend *soft = display_find("osmesa");
	if (chosen || !soft || soft == d)
		return NULL;
	skp_fail(first, err->code, 0, "%s: %s", d->name, err->msg);
	return soft->init(cfg, info, err) == 0 ? soft : NULL;
}
