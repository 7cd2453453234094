#include "controls.h"

#include "skp_format.h"
#include "text_tokens.h"

static const char *const button_names[CONTROL_BTN_COUNT] = { "ALGO", "PLAY", "NEXT", "VIEW" };

const char *control_button_name(int button)
{
	return button >= 0 && button < CONTROL_BTN_COUNT ? button_names[button] : "?";
}

int control_button_find(const char *name)
{
	for (int i = 0; i < CONTROL_BTN_COUNT; i++)
		if (tok_ieq(name, button_names[i]))
			return i;
	return -1;
}

void controls_init(controls_state *s, int algo, int view, int gpu, int clip_count)
{
	s->algo = algo >= 0 && algo < SKIN_SHOW_COUNT ? algo : SKIN_DQBS;
	s->view = view >= 0 && view < RENDER_VIEW_COUNT ? view : RENDER_VIEW_BODY;
	s->gpu = gpu ? 1 : 0;
	s->playing = 1;
	s->clip = 0;
	s->clip_count = clip_count > 0 ? clip_count : 1;
	for (int i = 0; i < CONTROL_BTN_COUNT; i++)
		s->down[i] = s->long_done[i] = 0;
}

/* The short action of a button. */
static control_action short_action(controls_state *s, int b, char *log, size_t cap)
{
	const char *name = button_names[b];
	switch (b) {
	case CONTROL_BTN_ALGO:
		s->algo = (s->algo + 1) % SKIN_SHOW_COUNT;
		skp_format(log, cap, "input: %s -> %s", name, skin_algo_name(s->algo));
		return CONTROL_ACT_ALGO;
	case CONTROL_BTN_PLAY:
		s->playing = !s->playing;
		skp_format(log, cap, "input: %s -> %s", name, s->playing ? "play" : "pause");
		return CONTROL_ACT_PLAY;
	case CONTROL_BTN_NEXT:
		s->clip = (s->clip + 1) % s->clip_count;
		skp_format(log, cap, "input: %s -> clip %d/%d", name, s->clip + 1, s->clip_count);
		return CONTROL_ACT_CLIP;
	default:
		s->view = (s->view + 1) % RENDER_VIEW_COUNT;
		skp_format(log, cap, "input: %s -> %s", name, render_view_name(s->view));
		return CONTROL_ACT_VIEW;
	}
}

static control_action long_action(controls_state *s, int b, char *log, size_t cap)
{
	if (b == CONTROL_BTN_PLAY) {
		skp_format(log, cap, "input: %s long -> restart", button_names[b]);
		return CONTROL_ACT_RESTART;
	}
	s->gpu = !s->gpu;
	skp_format(log, cap, "input: %s long -> %s skinning", button_names[b], s->gpu ? "gpu" : "cpu");
	return CONTROL_ACT_GPU;
}

/* PLAY and VIEW have a long action, so their short one waits for release. */
static int has_long(int b)
{
	return b == CONTROL_BTN_PLAY || b == CONTROL_BTN_VIEW;
}

control_action controls_handle(controls_state *s, const control_event *ev, char *log, size_t cap)
{
	if (cap)
		log[0] = '\0';
	int b = ev->button;
	if (b < 0 || b >= CONTROL_BTN_COUNT)
		return CONTROL_ACT_NONE;
	switch (ev->kind) {
	case CONTROL_PRESS:
		s->down[b] = 1;
		s->long_done[b] = 0;
		return has_long(b) ? CONTROL_ACT_NONE : short_action(s, b, log, cap);
	case CONTROL_LONG:
		if (!s->down[b] || s->long_done[b] || !has_long(b))
			return CONTROL_ACT_NONE;
		s->long_done[b] = 1;
		return long_action(s, b, log, cap);
	case CONTROL_RELEASE:
		/* a release with no press seen (held at start) does nothing */
		if (!s->down[b])
			return CONTROL_ACT_NONE;
		s->down[b] = 0;
		if (!has_long(b) || s->long_done[b])
			return CONTROL_ACT_NONE;
		return short_action(s, b, log, cap);
	default:
		return CONTROL_ACT_NONE;
	}
}
