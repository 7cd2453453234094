/* What plays: the kiosk's choices of slot and clip, as pure decisions over
 * what the caller found (no I/O here; the shell opens, checks and logs).
 *
 * Slots: the newest (highest sequence) that is accepted and whole (no
 * block beyond repair, its digest matched, a clip that can play) plays;
 * when no accepted slot is whole, the newest of those plays what survives;
 * an update cut short by power loss never bricks the display.
 * Clips: the first playable one at or after the one asked for, round the
 * end; none playable: the shell holds the bind pose with a message. */
#ifndef PLAY_POLICY_H
#define PLAY_POLICY_H

#include <stdint.h>

/* The first playable clip at or after from (wrapping), -1 if none. */
int play_next_playable(const uint8_t *playable, int count, int from);

/* Orders the opened slots (opened[i] != 0) newest first into order[];
 * returns how many. Equal sequences keep their order. */
int play_slots_by_sequence(const uint64_t *sequence, const uint8_t *opened, int n, int *order);

typedef struct play_slot_checks {
	void *ctx;
	/* 1 when slot i is accepted (and made current), 0 refused */
	int (*accept)(void *ctx, int slot);
	/* nonzero when slot i is not whole: an older whole slot wins over it */
	long (*damaged)(void *ctx, int slot);
} play_slot_checks;

/* The slot to play among order[0..k-1] (newest first), or -1. Damage is
 * asked only when there is another slot to fall back to (alternatives >
 * 1): one slot plays whatever survives. The slot returned
 * was the last one accept() was called for. */
int play_slot_choose(const int *order, int k, int alternatives, const play_slot_checks *c);

#endif
