/* The compare view's close-up: which joint it shows and the camera that
 * looks at it. The joint is where LBS and DQBS part most at the moment
 * (skin_diff.h's score per joint), held at least CLOSEUP_HOLD_S seconds
 * so that a visitor can look before it moves on, and only left for a
 * joint that differs clearly more; the camera glides from joint to joint
 * rather than cutting. */
#ifndef RENDER_CLOSEUP_H
#define RENDER_CLOSEUP_H

#include "mat4.h"

#define CLOSEUP_HOLD_S 2.0f    /* seconds a joint is shown at least */
#define CLOSEUP_SWITCH 1.25f   /* another joint must differ this much more */
#define CLOSEUP_SPAN 0.09f     /* the inset shows a sphere this radius (of the body's size), */
#define CLOSEUP_REACH 1.1f     /* or round where the methods part: this times that reach, */
#define CLOSEUP_SPAN_MIN 0.024f /* within these (of the body's size) */
#define CLOSEUP_SPAN_MAX 0.14f
/* A joint bent past 60 degrees is framed this much of its shorter bone at
 * least: the fold's point whole, with the limb leaving it. 0.85 showed both
 * bones whole, and the elbow's parting (21 mm at the fold's point) in a
 * sliver of the inset (1.5% of the panels differed); 0.45 5.3%, aimed
 * within the arm, between the hidden crease and the point. Aimed at the
 * fold's outside (skin_diff_focus), 0.26 shows the point whole and
 * the arm above it (11%; the generated body's elbow is framed at about
 * CLOSEUP_SPAN_MIN). */
#define CLOSEUP_FOLD_SHOWN 0.26f
/* The glide's time constant, in seconds: half the main camera's, so that
 * the close-up settles on a joint within the first second of its hold.
 * Between two joints its view may pass through the body (the elbow's
 * profile is across a forearm folded towards the visitor): a slower glide
 * showed a blur of skin for most of the elbow's hold. */
#define CLOSEUP_EASE_S 0.3f

typedef struct closeup_pick {
	int joint;     /* -1: none yet */
	float held;    /* seconds on it */
} closeup_pick;

void closeup_pick_init(closeup_pick *c);

/* dt seconds later, with score[j] the largest difference at joint j of n
 * (0: none): the joint to show. -1 while nothing differs. */
int closeup_pick_update(closeup_pick *c, const float *score, int n, float dt);

typedef struct closeup_camera {
	int started;
	vec3 target;       /* eased towards the joint */
	float azimuth;     /* eased towards a view across the bone */
	float pitch;
	float span;        /* the radius framed, eased towards the close-up's (0: not yet) */
} closeup_camera;

/* Follows the point at on a joint whose bone points along axis and its
 * parent along parent (posed), seen by the main camera from main_azimuth,
 * over dt seconds; immediate: there at once. A bent joint is seen square
 * to its bend, a straight one with the main camera's view turned square
 * to the bone: a limb from its side, never down its length. */
void closeup_camera_follow(closeup_camera *c, vec3 at, vec3 axis, vec3 parent, float main_azimuth, float dt,
			   int immediate);

/* The radius the close-up frames round a joint whose bone points along
 * axis and its parent along parent (posed), on a body height tall: round
 * where the methods part (reach, 0 if unknown), so that a twisted wrist
 * fills the inset; a joint bent past 60 degrees wide enough to show the
 * two bones folded, or its crease is a stretch of skin nobody reads as an
 * elbow. */
float closeup_span_want(float reach, vec3 axis, vec3 parent, float height);

/* View-projection of the close-up for a viewport of aspect, framing a
 * sphere of radius span round the target. */
mat4 closeup_camera_matrix(const closeup_camera *c, float span, float aspect);

#endif
