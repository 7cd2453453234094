/* Hand-made skeletons for the binding tests: bones placed directly in a
 * pose, no ASF. */
#ifndef TEST_SKEL_H
#define TEST_SKEL_H

#include "fk.h"
#include "skel.h"

/* Appends bone `name` (parent index, -1 for the root) running from head to
 * tip in pose p; no channels. Returns its index. */
int test_skel_add_bone(skel *s, skel_pose *p, const char *name, int parent, vec3 head, vec3 tip);

#endif
