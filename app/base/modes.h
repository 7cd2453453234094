/* What a show can be set to, named once for every layer: the skinning
 * algorithm (the kernels, app/skin, and the kiosk's ALGO button, which adds
 * the side-by-side comparison) and the view (app/render, VIEW button).
 * Here, at the bottom, so that the kiosk, the renderer and the programs
 * share one list without depending on each other. */
#ifndef MODES_H
#define MODES_H

typedef enum skin_algo {
	SKIN_LBS,
	SKIN_DQBS,
	SKIN_DQBS_FIXED,
	SKIN_ALGO_COUNT,                   /* the skinning algorithms above */
	SKIN_COMPARE = SKIN_ALGO_COUNT,    /* LBS beside DQBS: a way to show, not a kernel */
	SKIN_SHOW_COUNT
} skin_algo;

typedef enum render_view {
	RENDER_VIEW_BODY,        /* the shaded body */
	RENDER_VIEW_SKELETON,    /* body plus the skeleton drawn over it */
	RENDER_VIEW_WEIGHTS,     /* body coloured by its bone weights */
	RENDER_VIEW_DIFFERENCE,  /* body coloured by how far LBS lies from DQBS (compare),
	                          * or the skin from its bone as bound (one method), in mm */
	RENDER_VIEW_COUNT
} render_view;

/* "lbs", "dqbs", "dqbs-fixed", "compare"; "?" out of range. */
const char *skin_algo_name(int a);
/* The algorithm (compare included) named name, or -1. */
int skin_algo_parse(const char *name);

/* "body", "skeleton", "weights", "difference"; "?" out of range. */
const char *render_view_name(int v);
/* The view named name, or -1. */
int render_view_parse(const char *name);

#endif
