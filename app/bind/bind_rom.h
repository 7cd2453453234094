/* A short range-of-motion test built from the skeleton, for checking a
 * bind before it is used (bind_gate.h): each move turns one bone, with
 * every bone below it, about its head, away from the bind pose: a hip
 * flexed 60 degrees and extended 20, a leg out 30, a knee bent 90, an
 * ankle 25; an arm forward 60, up and down 40, an elbow bent 90, a wrist
 * 40; the back bent 30 and twisted 30; the neck bent 30 and turned 40.
 * Which bones those are comes from the skeleton's shape (skel_roles.h): in
 * each limb the upper bone (one with rotation channels: a leg's first 0.6
 * as long as the limb's longest, an arm's first 0.3 as long starting out
 * to the side by 0.3 of its length, so not the clavicle), the next one,
 * the one after; the lowest spine bone with a length, and the spine bone
 * above the one the arms hang from (the neck). Front is the way the
 * feet point. The moves turn bones in world space, whatever channels the
 * skeleton has: they test the skin, not the motion. */
#ifndef BIND_ROM_H
#define BIND_ROM_H

#include "fk.h"

#define BIND_ROM_MAX_MOVES 32

typedef enum bind_rom_kind {
	BIND_ROM_FORWARD, BIND_ROM_BACK, BIND_ROM_OUT, BIND_ROM_UP, BIND_ROM_DOWN, BIND_ROM_BEND,
	BIND_ROM_TWIST, BIND_ROM_KIND_COUNT
} bind_rom_kind;

typedef struct bind_rom_move {
	int bone;               /* turned, with the bones below it, about its head */
	bind_rom_kind kind;
	int degrees;
	quat turn;              /* world-space rotation */
} bind_rom_move;

typedef struct bind_rom {
	int count;
	bind_rom_move move[BIND_ROM_MAX_MOVES];
} bind_rom;

/* The moves for s posed as bind (fk_pose). Needs two bones or more. */
void bind_rom_build(const skel *s, const skel_pose *bind, bind_rom *out);

/* out = bind with move m applied. */
void bind_rom_pose(const skel *s, const skel_pose *bind, const bind_rom_move *m, skel_pose *out);

/* 1 when bone b is a or below it. */
int bind_rom_below(const skel *s, int b, int a);

/* "forward", "bent", ... for messages. */
const char *bind_rom_kind_name(bind_rom_kind k);

#endif
