/* Whether a rigged mesh is a biped, for a human skeleton's motion: a
 * quadruped has a biped's topology (two limb pairs and a neck) but not
 * its geometry. Judged on the joints as the file has them:
 *   - the legs hang from the hips the other way from the spine (hips to
 *     head): at least 120 degrees between them; a quadruped's spine lies
 *     level, square to its legs;
 *   - the arms' ends are off the floor: a quarter of the legs' height or
 *     more above the feet, along the file's axis nearest the legs' line
 *     (its vertical); a quadruped's forelegs stand on it, even where its
 *     hind legs slope back enough to pass the first test (Khronos' Fox).
 * A rig without two limb pairs is not judged here (the shape of its mesh
 * is, bind_shape.h, when it binds like an OBJ). */
#ifndef RIG_BIPED_H
#define RIG_BIPED_H

#include <stddef.h>

#include "rig_map.h"
#include "rig_scene.h"

/* 1 when the rig is a biped or cannot be judged; 0 with why (a sentence
 * of at most n bytes) when it is not. Judged on the joints m (may be NULL)
 * mapped to the hips, head, feet and hands when it mapped them all (a rig
 * with control chains beside its bones has more limb-like pairs than
 * limbs), else on the parts its shape shows. */
int rig_biped_check(const rig_scene *r, const rig_map *m, char *why, size_t n);

#endif
