/* The kiosk's controls, a state machine: four buttons drive what is shown.
 *
 *   ALGO  press: cycle lbs -> dqbs -> dqbs-fixed -> compare
 *   PLAY  short: play / pause           long: restart the clip
 *   NEXT  press: next clip of the image
 *   VIEW  short: the next view (body, skeleton, weights, difference)   long: CPU / GPU skinning
 *
 * ALGO and NEXT act on the press; PLAY and VIEW on the release (or the long
 * press), so a long press never also does the short action. Pure logic: no
 * allocation, no I/O; every action is described by one log line
 * "input: BUTTON -> action" the front end prints. */
#ifndef CONTROLS_H
#define CONTROLS_H

#include <stddef.h>
#include <stdint.h>

#include "modes.h"

typedef enum control_button {
	CONTROL_BTN_ALGO,
	CONTROL_BTN_PLAY,
	CONTROL_BTN_NEXT,
	CONTROL_BTN_VIEW,
	CONTROL_BTN_COUNT
} control_button;

typedef enum control_input {
	CONTROL_PRESS,
	CONTROL_RELEASE,
	CONTROL_LONG
} control_input;

/* A debounced button event, as the input backends deliver it. */
typedef struct control_event {
	uint8_t button;          /* control_button */
	uint8_t kind;            /* control_input */
	uint64_t t_ms;           /* when it happened (monotonic or script clock) */
} control_event;

typedef enum control_action {
	CONTROL_ACT_NONE,
	CONTROL_ACT_ALGO,         /* algo changed */
	CONTROL_ACT_PLAY,         /* playing toggled */
	CONTROL_ACT_RESTART,      /* start the clip again */
	CONTROL_ACT_CLIP,         /* clip changed: open clip `clip` from its start */
	CONTROL_ACT_VIEW,         /* view changed */
	CONTROL_ACT_GPU           /* gpu toggled */
} control_action;

typedef struct controls_state {
	int algo;                /* skin_algo */
	int playing;
	int clip, clip_count;    /* 0-based clip index; clip_count >= 1 */
	int view;                /* render_view */
	int gpu;                 /* 1: skin in the vertex shader where it fits */
	uint8_t down[CONTROL_BTN_COUNT];      /* seen pressed and not released */
	uint8_t long_done[CONTROL_BTN_COUNT]; /* this press gave its long action */
} controls_state;

void controls_init(controls_state *s, int algo, int view, int gpu, int clip_count);

/* Applies one event. Returns what changed (CONTROL_ACT_NONE for events with
 * no action, such as a release after a long press) and writes the log line
 * (without newline; "" when nothing happened) into log[cap]. */
control_action controls_handle(controls_state *s, const control_event *ev, char *log, size_t cap);

const char *control_button_name(int button);     /* "ALGO", ...; "?" */

/* Button by name, any case ("algo", "PLAY"); -1 when unknown. */
int control_button_find(const char *name);

#endif
