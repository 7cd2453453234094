/* A box body around tests/data/tiny.asf's arm (8 corners, 12 triangles,
 * 3.6 x 0.6 x 0.6 units), its weights shared between the bones so that
 * quantisation has work to do: what the image tests pack. */
#ifndef TEST_BOX_H
#define TEST_BOX_H

#include "amc.h"
#include "mesh.h"
#include "skel.h"
#include "skin_weights.h"

void test_box_body(const skel *s, mesh *m, skin_weights *w);

/* tests/data/tiny.asf into s, the first cap frames of tiny.amc into
 * frames, and the box body: returns the frames read (the test fails when
 * the files do not read). */
int test_tiny_inputs(skel *s, amc_frame *frames, int cap, mesh *m, skin_weights *w);

#endif
