/* The LBS vs DQBS comparison report of skintool compare: what the command
 * measures (report.c: joint regions; report_joints.c: which bends
 * carry a volume change) and the page that shows it (report_html.c).
 * Front-end code: it writes files. */
#ifndef REPORT_H
#define REPORT_H

#include "bind_gate.h"
#include "measure.h"
#include "runtime_skin.h"
#include "skel.h"
#include "skel_joints.h"
#include "skin.h"
#include "scene.h"

/* Joint regions. A vertex belongs to the region of the joint nearest to it
 * in the bind pose, a joint being a bone's head; the bone's name gives the
 * region (report_region_of_bone). */
typedef enum report_region {
	REGION_ELBOWS,
	REGION_KNEES,
	REGION_SHOULDERS,
	REGION_HIPS,
	REGION_WRISTS,
	REGION_COUNT
} report_region;

/* "elbows", ...; "other" for -1. */
const char *report_region_name(int region);

/* The region whose joint is the head of the bone named so, or -1:
 * CMU/HDM05 lhumerus/rhumerus shoulders, lradius/rradius elbows,
 * lwrist/rwrist/lhand/rhand wrists, lfemur/rfemur hips, ltibia/rtibia
 * knees; otherwise (endorphin) a name containing Shoulder, Elbow, Wrist,
 * Hip or Knee. */
int report_region_of_bone(const char *name);

/* For each vertex of the mesh bound in pose bind: the bone whose head is
 * nearest (joint[v]) and its region (region[v], -1 for none). */
void report_classify(const skel *s, const skel_pose *bind, const float *xyz, int n, int *joint,
		     int *region);

/* An extreme value over the clip and where it happened. */
typedef struct report_extreme {
	double value;
	long frame;
	int region;                 /* -1: outside the five regions */
	int joint;                  /* bone whose head is the nearest joint, -1 */
} report_extreme;

typedef struct report_algo {
	report_extreme vol_min, vol_max, rad_min, rad_max;
	report_extreme reg_min[REGION_COUNT], reg_max[REGION_COUNT]; /* value NAN: never measured */
	/* the volume of the skin around each joint region over its volume as
	 * bound (compare_region_volume.c): smallest and largest; NAN: none */
	report_extreme rvol_min[REGION_COUNT], rvol_max[REGION_COUNT];
	/* the region's skin turned inside out round its joint in some frame
	 * (the measure's sum went through zero: a deep fold, skin through the
	 * joint): no figure */
	uint8_t rvol_folded[REGION_COUNT];
	double vol_dev;             /* max over frames of |1 - volume_ratio| */
	long vol_dev_frame;
} report_algo;

#define REPORT_ANGLES 4
typedef struct report_scene {
	scene_kind kind;
	int angle_deg;
	double vol[SKIN_ALGO_COUNT], rmin[SKIN_ALGO_COUNT], rmax[SKIN_ALGO_COUNT];
} report_scene;

/* One joint's part in a pose's volume change. */
typedef struct report_joint {
	int bone;
	double share;               /* the pose's volume ratio minus the ratio with
				     * this joint's rotation back at the bind pose */
	int count;                  /* rotation channels */
	uint8_t channel[3];         /* SKEL_RX.. in the ASF's dof order */
	float deg[3];               /* their values, degrees */
	int past;                   /* channel farthest outside the ASF limits, -1: none */
	float past_deg;             /* by how much (modulo 360: 370 is 10) */
	float lo_deg, hi_deg;       /* its limits */
} report_joint;

#define REPORT_MAX_JOINTS 6
typedef struct report_joints {
	long frame;                 /* -1: not measured */
	double volume;              /* the frame's volume ratio */
	int count;
	report_joint joint[REPORT_MAX_JOINTS]; /* largest |share| first, |share| >= 0.05% */
} report_joints;

/* Skins frame `values` with algo once as it is and once per bone with
 * rotation channels, that bone's rotations set back to their bind-pose
 * values (bind_values): the joints whose bend moves the volume most.
 * The root is left out (it moves the body rigidly); so are translations.
 * sk is left in an arbitrary pose; pos and nrm are scratch. */
void report_find_joints(runtime_skin *sk, const measure_state *meas, skin_algo algo, long frame,
			const float *values, const float *bind_values, float *pos, float *nrm,
			report_joints *out);

/* Where a rendered pose's LBS and DQBS part most: the close-up's joint
 * (skin_diff.h, the kiosk's choice), for the captions. */
typedef struct report_closeup {
	int joint;                  /* -1: they do not differ */
	char name[48];              /* "LEFT ELBOW" (skel_joints.h) */
	skel_turn_kind turn;        /* how it turned (skel_joint_turn_say), and by how much */
	int turn_deg;
	double apart;               /* the largest distance there, in mm, or in */
	int in_units;               /* the skeleton's units when 1 (a synthetic scene) */
	int size_assumed;           /* mm at a size assumed: the units gave no human height */
} report_closeup;

#define REPORT_MAX_STILLS 8
typedef struct report_still {
	long frame;
	report_extreme rel;         /* LBS minus DQBS radius ratio at its worst vertex */
	int vertex;                 /* that vertex */
	double lbs_ratio, dqbs_ratio; /* the two ratios there */
	report_closeup closeup;
	/* the whole body with the close-up inset, the close-up camera's view,
	 * the difference view */
	char full_png[64], close_png[64], diff_png[64];
	int rendered;
} report_still;

/* A synthetic scene at its strongest pose, LBS | DQBS with the close-up. */
typedef struct report_scene_still {
	scene_kind kind;
	int angle_deg;
	double lbs_rmin, dqbs_rmin, dqbs_rmax; /* its table's radius ratios */
	report_closeup closeup;
	char png[32];
	int rendered;
} report_scene_still;

typedef struct report_chart {
	char png[64];
	const char *title, *caption;
} report_chart;

/* report.mesh_name without --mesh */
#define GENERATED_BODY "generated body"

#define REPORT_MAX_CHARTS 12
typedef struct report {
	const char *asf, *amc, *mesh_name, *clip;
	const char *weights;        /* how the weights came about, for the page */
	/* a rigged mesh: the clip measured with its other weights too
	 * (compare_other_weights), NULL when not */
	const char *other_weights, *other_csv;
	const report_algo *other_algo;
	int balanced;               /* weights volume-balanced (bind_balance.h) */
	/* the skin's longest stretch in the quality gate's poses and the clip
	 * (bind_gate.h): worst edge ratio, where, lengthening, edges past 2x */
	const bind_gate_result *gate;
	char gate_where[96], grow_where[96];
	const char *gate_region, *grow_region;
	const skel *skel;
	int vert_count, tri_count, measured;
	int region_verts[REGION_COUNT];
	long frames;
	double seconds;             /* measuring the clip */
	double total_seconds;       /* the whole command, as its last line says */
	report_algo algo[SKIN_ALGO_COUNT];
	report_extreme rel_min;     /* worst LBS - DQBS over the clip */
	/* at DQBS's largest volume deviation: the volume where the skin passes
	 * through itself, which the signed volume counts twice, over the bound
	 * volume (overlap.h); NAN when not measured */
	double dqbs_overlap;
	/* the parts the volume is measured on (measure.h, parts.h); volume_closed
	 * 0: none is closed, the volume figures mean nothing */
	parts_summary parts;
	int volume_closed;
	/* LBS at its worst volume loss, DQBS at its largest deviation */
	report_joints vol_joints[2];
	report_scene scene[2 * REPORT_ANGLES];
	int scene_count;
	report_scene_still scene_still[SCENE_KIND_COUNT];
	report_still still[REPORT_MAX_STILLS];
	int still_count;
	const char *render_note;    /* why there are no renders, or NULL */
	report_chart chart[REPORT_MAX_CHARTS];
	int chart_count;
} report;

/* Writes dir/index.html. Returns 0 or -1 (reported). */
int report_write_html(const report *r, const char *dir);

#endif
