/* The quality gate (bind_gate.h) run on every bound body before a command
 * writes anything: the range of motion built from the skeleton (bind_rom.h),
 * and the frames of the command's motion where there is one, skinned with
 * DQBS. A failing bind is refused with the region, the figure and the fix
 * (--joint-map, --weights mesh or not, --group); --force binds anyway with
 * the same warning. */
#ifndef SETUP_GATE_H
#define SETUP_GATE_H

#include "cli_bind_args.h"
#include "runtime_body.h"

/* Fills body->gate (and prints it when a->gate_report). Returns 0 (passed, or failed under --force after the
 * warning), or -1 after refusing; name is the mesh's file (or the
 * skeleton's, for the generated body). */
int setup_gate(const bind_args *a, const char *name, bound_body *body);

/* The gate's figures on stderr, for bind --report. */
void setup_gate_report(const bound_body *body);

/* Where a gate figure was worst, as words: "with rhumerus forward 60
 * degrees" (a range-of-motion pose) or "at frame 273 of the motion". */
void setup_gate_where(const bound_body *body, const bind_gate_worst *w, char *out, size_t n);

#endif
