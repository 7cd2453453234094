/* The synthetic scene that shows the classic skinning artifacts with known
 * answers: a closed cylinder of radius 0.2 around two bones of length 1
 * along +X (bone 0 from x = 0 to 1, bone 1 from x = 1 to 2), weights
 * cross-fading linearly over 0.3 either side of the joint:
 *   w1 = clamp((x - 0.7) / 0.6, 0, 1),  w0 = 1 - w1.
 * "twist" turns bone 1 about +X, "bend" about +Z, by an angle. At the
 * joint ring (w0 = w1 = 0.5) a twist by a shrinks LBS to |cos(a / 2)| of
 * the radius (a point at 180 degrees); DQBS keeps the radius.
 *
 * The poses are built directly, not through fk_pose: bone 0 stands for a
 * root with a length, which an Acclaim root does not have. */
#ifndef SCENE_H
#define SCENE_H

#include "fk.h"
#include "mesh.h"
#include "skin_weights.h"

#define SCENE_RADIUS   0.2f
#define SCENE_BLEND    0.3f  /* half-width of the weight ramp */
#define SCENE_RINGS    65    /* x = 0, 1/32, ..., 2: one ring on the joint */
#define SCENE_SEGMENTS 48    /* vertices around a ring */
#define SCENE_VERTS    (SCENE_RINGS * SCENE_SEGMENTS + 2)
#define SCENE_TRIS     (2 * SCENE_RINGS * SCENE_SEGMENTS)

typedef enum scene_kind {
	SCENE_TWIST,
	SCENE_BEND,
	SCENE_KIND_COUNT
} scene_kind;

/* "twist", "bend" */
const char *scene_name(scene_kind k);
/* -1 when the name is not a scene */
int scene_parse(const char *name);

/* About 5 MB (the mesh and weights are board-sized): keep it static. */
typedef struct scene_rig {
	skel skel;            /* "upper" (bone 0) and its child "lower" */
	skel_pose bind;       /* both bones along +X, identity rotations */
	mesh mesh;            /* ring-major, then the caps' centres at x = 0, 2 */
	skin_weights weights;
} scene_rig;

void scene_build(scene_rig *out);

/* The bind pose with bone 1 turned by radians about its head (twist: +X,
 * bend: +Z). */
void scene_pose(const scene_rig *sc, scene_kind k, float radians, skel_pose *out);

#endif
