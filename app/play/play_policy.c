#include "play_policy.h"

int play_next_playable(const uint8_t *playable, int count, int from)
{
	for (int k = 0; k < count; k++) {
		int c = ((from % count) + count + k) % count;
		if (playable[c])
			return c;
	}
	return -1;
}

int play_slots_by_sequence(const uint64_t *sequence, const uint8_t *opened, int n, int *order)
{
	int k = 0;
	for (int i = 0; i < n; i++) {
		if (!opened[i])
			continue;
		int j = k++;
		while (j > 0 && sequence[order[j - 1]] < sequence[i]) {
			order[j] = order[j - 1];
			j--;
		}
		order[j] = i;
	}
	return k;
}

int play_slot_choose(const int *order, int k, int alternatives, const play_slot_checks *c)
{
	int damaged = -1;
	for (int i = 0; i < k; i++) {
		int slot = order[i];
		if (!c->accept(c->ctx, slot))
			continue;
		if (alternatives <= 1 || c->damaged(c->ctx, slot) == 0)
			return slot;
		if (damaged < 0)
			damaged = slot;
	}
	/* every accepted slot is damaged: the newest plays what it can */
	if (damaged >= 0 && c->accept(c->ctx, damaged))
		return damaged;
	return -1;
}
