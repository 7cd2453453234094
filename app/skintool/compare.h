/* skintool compare, inside: the run's state shared by its measuring part
 * (compare_measure.c: the scenes, every frame of the clip, the joints
 * behind the volume) and its output part (compare_output.c: charts, the
 * scenes' and the worst frames' pictures); skintool_compare.c reads the
 * arguments and runs them in order. Private to app/skintool. */
#ifndef COMPARE_H
#define COMPARE_H

#include <stdio.h>

#include "cli_bind_args.h"
#include "runtime_body.h"
#include "runtime_skin.h"
#include "measure.h"
#include "report.h"

#define NALGO SKIN_ALGO_COUNT
#define STORE_MAX 65536         /* frames kept for the charts (longer clips: every k-th) */
#define REPORT_IMG_W 1200
#define REPORT_IMG_H 600

typedef struct compare_args {
	bind_args bind;
	const char *asf, *amc, *mesh, *out;
	long renders;
	const char *csv_name;       /* in out: "metrics.csv" */
} compare_args;

/* One frame's figures for one algorithm, as kept for the charts. */
typedef struct frame_stats {
	float vol, rmin, rmax;
	float reg_min[REGION_COUNT], reg_max[REGION_COUNT];
	float rvol[REGION_COUNT];       /* the region's volume ratio (compare_region_volume) */
} frame_stats;

/* The skin around each joint region as a volume: each triangle of the
 * region (its first vertex's) with the joint nearest to that vertex makes
 * a tetrahedron, posed with the posed joint; their sum over the region,
 * over the same sum as bound, is the region's volume ratio. A collapsing
 * elbow shrinks it, a bulging one swells it, whatever the rest does. Only
 * the triangles the body's volume is measured on count (measure.h: the
 * outer closed parts). */
typedef struct region_volume {
	int8_t tri_region[SKP_MAX_TRIS];   /* -1: no region */
	int16_t tri_joint[SKP_MAX_TRIS];
	double bind[REGION_COUNT];         /* <= 0: not measured */
} region_volume;

typedef struct compare_run {
	bound_body body;
	runtime_skin sk;
	measure_state meas;
	report rep;
	int joint[SKP_MAX_VERTS], region[SKP_MAX_VERTS];
	region_volume rv;
	scene_rig scene;              /* the synthetic scenes (compare_measure_scenes) */
	float pos[3 * SKP_MAX_VERTS], nrm[3 * SKP_MAX_VERTS];
	float ratio[NALGO][SKP_MAX_VERTS];
	/* the kept frames */
	int stride, kept;
	long frame[STORE_MAX];
	frame_stats st[NALGO][STORE_MAX];
	float rel[STORE_MAX];         /* LBS - DQBS at the worst vertex */
	int rel_vertex[STORE_MAX];
	float rel_region[REGION_COUNT][STORE_MAX];   /* ... at each region's worst */
	int rel_region_vertex[REGION_COUNT][STORE_MAX];
	float floor_y;
	FILE *csv;
	char path[4096];
} compare_run;

extern const char *const compare_algo_label[NALGO];

/* A rigged mesh's own weights and computed ones side by side: the clip
 * measured again with the other weights (--weights mesh or not) into
 * DIR/metrics_OTHER.csv, its summary beside the main one on the page.
 * Returns 0 (also when the mesh has no weights of its own), or -1. */
int compare_other_weights(compare_run *main_run, const compare_args *a);

/* compare_region_volume.c: set up once the body is classified (joint[],
 * region[]); then each skinned frame's ratios (NAN where not measured). */
void compare_region_volume_init(compare_run *c);
void compare_region_volume(const compare_run *c, const float *pos, const skel_pose *pose,
			   double ratio[REGION_COUNT]);

/* The measuring part: each returns 0, or -1 after reporting. The scenes
 * leave c->sk holding the scene (c->scene) for compare_render_scenes,
 * until the clip is loaded: one runtime_skin at a time. */
int compare_measure_scenes(compare_run *c);
int compare_load_clip(compare_run *c, const compare_args *a);
int compare_measure_clip(compare_run *c, const compare_args *a);
/* Which bends carry LBS's worst loss and DQBS's largest deviation. */
int compare_explain_volume(compare_run *c, const compare_args *a);
void compare_set_extreme(compare_run *c, report_extreme *e, double value, long frame, int vertex);

/* The output part. */
/* Each scene at its strongest pose (the twist at its largest angle, the
 * bend at its deepest short of 180 degrees), LBS | DQBS with the
 * close-up, into a->out/scene_KIND.png, when a->renders > 0; right after
 * compare_measure_scenes. Returns 0 (no display: render_note says so), or
 * -1 after reporting. */
int compare_render_scenes(compare_run *c, const compare_args *a);
void compare_pick_stills(compare_run *c, int want);
int compare_render_stills(compare_run *c, const compare_args *a);
int compare_write_charts(compare_run *c, const char *dir);

#endif
