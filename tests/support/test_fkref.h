/* The independent double-precision FK reference of test_fk_reference and
 * test_fk_reference_time: its own (simple, trusting) ASF parser, 3x3
 * matrices and quaternions in double, sharing no code with app/. */
#ifndef TEST_FKREF_H
#define TEST_FKREF_H

#include "test_dref.h"

#define FKREF_MAX 160

typedef struct {
	char name[64];
	int parent;
	double dir[3], len;
	dmat3 c;            /* axis rotation */
	int nch, ch[7];     /* 0..2 rx ry rz, 3..5 tx ty tz, 6 l */
} fkref_bone;

typedef struct {
	int n;
	int deg;
	double per_unit;    /* 1 / :units length: Acclaim lengths are divided by it */
	double pos[3];
	fkref_bone b[FKREF_MAX];
} fkref_skel;

typedef struct {
	dmat3 g[FKREF_MAX];
	double tip[FKREF_MAX][3];
	int done[FKREF_MAX];
} fkref_pose;

/* Index of the bone called name, -1 if none. */
int fkref_find(const fkref_skel *s, const char *name);
/* Blanks the brackets, commas, tabs and line ends of an ASF/AMC line. */
void fkref_clean(char *line);
/* Reads the ASF at path into s (the test fails when it cannot open it). */
void fkref_load_asf(const char *path, fkref_skel *s);
/* Bone i (and its parents first) posed from its channel values v. */
void fkref_pose_bone(const fkref_skel *s, const double v[FKREF_MAX][7], int i, fkref_pose *p);
/* The rotation of the unit quaternion q (w x y z). */
dmat3 fkref_quat_mat(const double q[4]);
/* The extent in y of the bones' tips with every channel at zero. */
double fkref_skeleton_height(const fkref_skel *s);

#endif
