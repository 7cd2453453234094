/* A user's mesh as a newcomer gives it: with --group, that group (a wrong
 * name lists the groups there are); without, the group named "body" when
 * the file has one beside others (MakeHuman's helper geometry: eyes,
 * teeth, clothes, joint markers), else the largest closed connected part.
 * What is left out is said on stderr. */
#ifndef SETUP_MESH_PICK_H
#define SETUP_MESH_PICK_H

#include "mesh.h"

/* Returns 0, or -1 after reporting the error. */
int setup_pick_mesh(const char *path, const char *group, mesh *out);

#endif
