/* Interchange files split a vertex wherever its normal or texture
 * coordinates change (a hard edge, a UV seam). Skinning and the volume and
 * smooth-normal measures want one vertex per place: rig_weld merges the
 * vertices at exactly the same place with the same joint weights, unless
 * they show different texels of the texture the GPU draws (a seam's two
 * sides): those stay apart, noted as twins (rig_seam.h). */
#ifndef RIG_WELD_H
#define RIG_WELD_H

#include "rig_scene.h"

/* Merges them in r->mesh (triangles renumbered, influences kept) and sets
 * r->welded, r->seams and r->seam_lead. Needs three ints a vertex of
 * scratch: allocated here (host). */
void rig_weld(rig_scene *r);

#endif
