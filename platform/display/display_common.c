/* Helpers every display backend calls (display_common.h). */
#include "display_common.h"

#include <string.h>

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
