/* What the input backends share (the registry, input.c, names them). */
#include "input.h"

int input_emit(unsigned bits, int button, uint64_t t_ms, control_event *ev)
{
	static const unsigned order[3] = { DEBOUNCE_PRESS, DEBOUNCE_LONG, DEBOUNCE_RELEASE };
	static const uint8_t kind[3] = { CONTROL_PRESS, CONTROL_LONG, CONTROL_RELEASE };
	int n = 0;
	for (int i = 0; i < 3; i++)
		if (bits & order[i]) {
			ev[n].button = (uint8_t)button;
			ev[n].kind = kind[i];
			ev[n].t_ms = t_ms;
			n++;
		}
	return n;
}
