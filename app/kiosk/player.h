/* The kiosk's player state machine: four buttons drive what is shown.
 *
 *   ALGO  press: cycle lbs -> dqbs -> dqbs-fixed -> compare
 *   PLAY  short: play / pause           long: restart the clip
 *   NEXT  press: next clip of the image
 *   VIEW  short: body -> skeleton -> weights   long: CPU / GPU skinning
 *
 * ALGO and NEXT act on the press; PLAY and VIEW on the release (or the long
 * press), so a long press never also does the short action. Pure logic: no
 * allocation, no I/O; every action is described by one log line
 * "input: BUTTON -> action" the front end prints. */
#ifndef PLAYER_H
#define PLAYER_H

#include <stddef.h>
#include <stdint.h>

#include "show_modes.h"

typedef enum player_button {
	PLAYER_BTN_ALGO,
	PLAYER_BTN_PLAY,
	PLAYER_BTN_NEXT,
	PLAYER_BTN_VIEW,
	PLAYER_BTN_COUNT
} player_button;

typedef enum player_input {
	PLAYER_PRESS,
	PLAYER_RELEASE,
	PLAYER_LONG
} player_input;

/* A debounced button event, as the input backends deliver it. */
typedef struct player_event {
	uint8_t button;          /* player_button */
	uint8_t kind;            /* player_input */
	uint64_t t_ms;           /* when it happened (monotonic or script clock) */
} player_event;

typedef enum player_action {
	PLAYER_ACT_NONE,
	PLAYER_ACT_ALGO,         /* algo changed */
	PLAYER_ACT_PLAY,         /* playing toggled */
	PLAYER_ACT_RESTART,      /* start the clip again */
	PLAYER_ACT_CLIP,         /* clip changed: open clip `clip` from its start */
	PLAYER_ACT_VIEW,         /* view changed */
	PLAYER_ACT_GPU           /* gpu toggled */
} player_action;

typedef struct player_state {
	int algo;                /* skin_algo */
	int playing;
	int clip, clip_count;    /* 0-based clip index; clip_count >= 1 */
	int view;                /* render_view */
	int gpu;                 /* 1: skin in the vertex shader where it fits */
	uint8_t down[PLAYER_BTN_COUNT];      /* seen pressed and not released */
	uint8_t long_done[PLAYER_BTN_COUNT]; /* this press gave its long action */
} player_state;

void player_init(player_state *s, int algo, int view, int gpu, int clip_count);

/* Applies one event. Returns what changed (PLAYER_ACT_NONE for events with
 * no action, such as a release after a long press) and writes the log line
 * (without newline; "" when nothing happened) into log[cap]. */
player_action player_handle(player_state *s, const player_event *ev, char *log, size_t cap);

const char *player_button_name(int button);     /* "ALGO", ...; "?" */

/* Button by name, any case ("algo", "PLAY"); -1 when unknown. */
int player_button_find(const char *name);

#endif
