/* The input registry: the one file that names the backends, each built when
 * the board lists it (board.mk: INPUTS -> SKP_INPUT_<name>); "none" always. */
#include "input.h"

#include <string.h>

extern const input_backend input_gpio, input_keyboard, input_script;

static int none_init(const board_config *cfg, const char *arg, uint64_t now_ms, skp_error *err)
{
	(void)cfg, (void)arg, (void)now_ms, (void)err;
	return 0;
}

static int none_read(uint64_t now_ms, control_event *ev, int max, skp_error *err)
{
	(void)now_ms, (void)ev, (void)max, (void)err;
	return 0;
}

static void none_shutdown(void)
{
}

const input_backend input_none = { "none", none_init, none_read, none_shutdown, NULL };

const input_backend *input_find(const char *spec, const char **arg)
{
	*arg = NULL;
	if (!spec || !strcmp(spec, "none") || !*spec)
		return &input_none;
#ifdef SKP_INPUT_gpio
	if (!strcmp(spec, "gpio"))
		return &input_gpio;
#endif
#ifdef SKP_INPUT_keyboard
	if (!strcmp(spec, "keyboard"))
		return &input_keyboard;
#endif
#ifdef SKP_INPUT_script
	if (!strncmp(spec, "script:", 7) && spec[7]) {
		*arg = spec + 7;
		return &input_script;
	}
#endif
	return NULL;
}
