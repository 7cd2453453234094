/* A user's mesh put on the skeleton without flags: scaled and moved to the
 * skeleton when their sizes or places disagree (--fit forces it, --no-fit
 * keeps the mesh as it is), and bound in the pose it was modelled in, found
 * by bind_guess_pose (an A-posed mesh on a T-posed skeleton), unless
 * --bind-pose names one. The generated body's OBJ binds in its own pose
 * (skel_tpose.h). Each decision is said on stderr. */
#ifndef SETUP_MESH_PLACE_H
#define SETUP_MESH_PLACE_H

#include "cli_bind_args.h"
#include "runtime_body.h"

/* 1 when the skeleton (posed as pose) has a human's two legs and two
 * arms: only then is a mesh refused for not being a biped (bind_shape.h,
 * rig_biped.h). */
int setup_skel_is_biped(const skel *s, const skel_pose *pose);

/* Returns 0, or -1 after reporting the error. */
int setup_place_mesh(const bind_args *a, const char *obj, bound_body *body);

#endif
