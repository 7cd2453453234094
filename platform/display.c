#include "display.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "display_common.h"

static const display_backend *const backends[] = {
	&display_surfaceless, &display_osmesa, &display_kms, &display_x11,
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
	/* Under a display server the DRM device belongs to it: do not even
	 * probe, taking master would fail or blank its screen. */
	if (!env_set("DISPLAY") && !env_set("WAYLAND_DISPLAY") && display_kms_available())
		return &display_kms;
	if (env_set("DISPLAY"))
		return &display_x11;
	return &display_surfaceless;
}

int display_check_config(const display_config *cfg, int max_w, int max_h, skp_error *err)
{
	if (!cfg)
		return skp_fail(err, SKP_ERR_RANGE, 0, "display: no configuration");
	if (cfg->width < 1 || cfg->height < 1)
		return skp_fail(err, SKP_ERR_RANGE, 0, "display: size %dx%d is not positive",
				cfg->width, cfg->height);
	if (cfg->width > max_w || cfg->height > max_h)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "display: size %dx%d is larger than %dx%d",
				cfg->width, cfg->height, max_w, max_h);
	return display_check_rotation(cfg->rotation, err);
}

int display_check_rotation(int rotation, skp_error *err)
{
	if (rotation != 0 && rotation != 90 && rotation != 180 && rotation != 270)
		return skp_fail(err, SKP_ERR_RANGE, 0, "display: rotation %d is not 0, 90, 180 or 270",
				rotation);
	return SKP_OK;
}

int display_has_word(const char *list, const char *word)
{
	size_t n = strlen(word);
	for (const char *p = list; p && (p = strstr(p, word)) != NULL; p += n)
		if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
			return 1;
	return 0;
}
