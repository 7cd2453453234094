/* Writes the skinplay demo motion (AMC, 120 Hz) for assets/demo.asf to
 * stdout: a 2 s walk, then the poses where linear blend skinning fails and
 * dual quaternion skinning keeps its volume, each staged on one joint of
 * one side so that a visitor at kiosk distance sees at once where the two
 * panels part. The rest of the body stands calm, the arms lowered 70
 * degrees from the T-pose. In this order, each held alone 2.3 s (seconds
 * into the tour):
 *
 *   1. 2.95-5.25   the left forearm twisted half a turn (the candy
 *                  wrapper), the arm held out to the side;
 *   2. 6.15-8.45   the right elbow bent to 150 degrees, a curl: the upper
 *                  arm hanging, the forearm folded up in front, the body
 *                  turned a quarter to show its right side (the fold in
 *                  profile);
 *   3. 9.35-11.65  the left arm raised overhead (the shoulder and armpit);
 *   4. 12.55-14.85 the right hip flexed 115 degrees, the knee bent (a high
 *                  march step);
 *   5. 15.75-18.35 the head turned 90 degrees to its right (the neck's
 *                  twist); a stand, and the tour ends at 19.25 s.
 *
 * Each eases in and out over EASE s (smoothstep). The next one eases in
 * while the last is still held and only then does the last ease out
 * (OVERLAP): the kiosk's close-up keeps a joint 2 s at least and leaves it
 * only for one that parts the methods 1.25x more (app/render/
 * render_closeup.h), so a pause in the rest pose between two artifacts
 * would hand it to the shoulders for most of the next hold.
 *
 * Built and run by `make` into build/assets/demo.amc.
 * tests/integration/test_compare_seen.c knows the holds' middles: change
 * both together.
 *
 * `demo_motion cmu` writes the same tour for the CMU skeleton (the default
 * show's, assets/cmu/02.asf), whose arm bones have other axes: each arm's
 * rotations are carried over so that every arm bone turns the same way in
 * space (build/assets/tour.amc). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FPS 120.0
#define EASE 0.6                      /* smoothstep in, and out again */
#define OVERLAP 0.9                   /* of one artifact's ease out and the next's ease in */
#define HOLD (2.0 + OVERLAP)          /* 2.3 s of it with nothing else posed */
#define STAGE (EASE + HOLD + EASE)
#define PERIOD (STAGE - OVERLAP)      /* 3.2 s from one artifact to the next */
#define STAGES 5
#define WALK_END (2.5 - OVERLAP / 2)  /* the holds' middles at 4.1 s + 3.2 s k */
#define WALK_STOP 0.4                 /* the walk slows to a stand over its last 0.4 s */
#define TOUR_END (WALK_END + STAGES * PERIOD + OVERLAP + 0.3) /* a moment's stand before the loop */

enum { RIGHT, LEFT };                 /* side indices, as the AMC's r and l */

typedef struct pose {
	double root[6];
	double lowerback[3], thorax[3], lowerneck[3], upperneck[3], head[3];
	double humerus[2][3], radius[2], wrist[2], clavicle[2][2];
	double femur[2][3], tibia[2], foot[2][2], toes[2];
} pose;

static double smoothstep(double a, double b, double t)
{
	double x = (t - a) / (b - a);
	x = x < 0 ? 0 : x > 1 ? 1 : x;
	return x * x * (3 - 2 * x);
}

/* 1 inside [a+ramp, b-ramp], easing in and out at the ends */
static double window(double a, double b, double ramp, double t)
{
	return smoothstep(a, a + ramp, t) * (1 - smoothstep(b - ramp, b, t));
}

/* Standing: the arms lowered 70 degrees from the T-pose, the legs drawn in
 * 14 from the skeleton's straddle as the default show's body stands in its
 * bind pose. Away from the staged joint LBS and DQBS then part by 8 mm at
 * most (the shoulders; the arms hang lower than bound). */
static void rest_pose(pose *p)
{
	/* rz lowers the T-pose arms */
	p->humerus[RIGHT][2] = 70;
	p->humerus[LEFT][2] = -70;
	p->radius[RIGHT] = p->radius[LEFT] = 15;
	p->femur[RIGHT][2] = 14;
	p->femur[LEFT][2] = -14;
}

/* The distance walked by t: the speed eases out with the stride, so that
 * the feet do not slide as the walk stops (the integral of 1 - smoothstep
 * over the stop is x - x^3 + x^4/2 of its share x). */
static double walked(double t)
{
	double a = WALK_END - WALK_STOP;
	double x = t < a ? 0 : t > WALK_END ? 1 : (t - a) / WALK_STOP;
	return 13.0 * ((t < a ? t : a) + WALK_STOP * (x - x * x * x + x * x * x * x / 2));
}

static void walk(pose *p, double t, double w)
{
	double ph = 2 * M_PI * t / 1.1;
	double l = sin(ph);
	p->root[2] = walked(t);
	p->root[1] = 16.9 + w * 0.35 * cos(2 * ph);
	p->femur[LEFT][0] += w * -25 * l;
	p->femur[RIGHT][0] += w * 25 * l;
	p->tibia[LEFT] += w * 35 * fmax(0, sin(ph + 1.3));
	p->tibia[RIGHT] += w * 35 * fmax(0, sin(ph + 1.3 + M_PI));
	p->foot[LEFT][0] += w * 10 * sin(ph + 0.5);
	p->foot[RIGHT][0] += w * -10 * sin(ph + 0.5);
	p->humerus[LEFT][0] += w * -20 * l;
	p->humerus[RIGHT][0] += w * 20 * l;
	p->lowerback[1] += w * 6 * l;
	p->thorax[1] += w * -6 * l;
}

/* The demo skeleton's arm dofs, rx ry rz, turn in the T-pose about the
 * vertical, the bone and the forward axis (rz lowers or raises the arm in
 * the body's plane); the forearm's rx bends the elbow about the vertical
 * there, the wrist's ry twists about the forearm. */

/* The candy wrapper: the skin between forearm and hand turned half a turn
 * collapses to a waist with LBS. The arm out to the side, 15 degrees below
 * the horizontal and straight, shows the whole forearm clear of the body. */
static void forearm_twist(pose *p, double s)
{
	p->humerus[LEFT][2] += 55 * s;
	p->radius[LEFT] -= 15 * s;
	p->wrist[LEFT] -= 180 * s;
}

/* LBS loses the inside of a deep bend: a curl, the upper arm hanging and
 * the forearm folded up in front of it, so that the bend's plane stands
 * upright (out from the side, the arm bent in a nearly level plane that no
 * view from the visitor's side shows in profile). The body turns a
 * quarter to its left meanwhile, its right side to the visitor, so that
 * the body and the close-up both see the fold in profile: from the front
 * the forearm hides it, and the close-up, kept within 60 degrees of the
 * main view, saw it half from the front (0.7% of the panels differed;
 * 1.5% turned, 5.3% framed closer but aimed within the arm, 11.1%
 * aimed at the fold's outside, render_closeup.h). Not rolled: a roll of the upper arm parts the
 * methods more at the shoulder than the bend does at the elbow, and the
 * close-up shows the shoulder. */
static void elbow_bend(pose *p, double s)
{
	p->humerus[RIGHT][2] += 20 * s;   /* from 70 degrees lowered to hanging */
	p->radius[RIGHT] += 135 * s;
	p->root[4] += 90 * s;             /* ry: the whole body, rigidly */
}

/* The upper arm from hanging to 80 degrees above the horizontal, up past
 * the head: the shoulder and armpit turn 150 degrees. */
static void shoulder_overhead(pose *p, double s)
{
	p->humerus[LEFT][2] += 150 * s;
}

/* A high march step: the thigh 115 degrees forward of hanging, above the
 * horizontal, the knee bent so that the shin hangs. The groin and buttock
 * fold. */
static void hip_flexion(pose *p, double s)
{
	p->femur[RIGHT][0] -= 115 * s;
	p->tibia[RIGHT] += 100 * s;
	p->foot[RIGHT][0] += 10 * s;
}

/* The head turned to its right about the vertical, as far as a neck
 * turns (90 degrees, the chin over the shoulder), shared evenly by the
 * lower and upper neck: a twist of the neck's skin, as the forearm's but
 * shorter. Each neck bone turns 45 degrees, so the close-up names the
 * twist (over 30). To the right the close-up, from the visitor's side,
 * sees the neck whole under the jaw, LBS's waist against DQBS's column;
 * turned 80 degrees to the left, most of it in the upper neck, it saw the
 * base of the neck and the shoulder (4.2% of the panels differed). */
static void neck_turn(pose *p, double s)
{
	p->lowerneck[1] -= 45 * s;
	p->upperneck[1] -= 45 * s;
}

static void (*const stage[STAGES])(pose *, double) = {
	forearm_twist, elbow_bend, shoulder_overhead, hip_flexion, neck_turn,
};

static pose pose_at(double t)
{
	pose p;
	memset(&p, 0, sizeof p);
	rest_pose(&p);
	walk(&p, t, 1 - smoothstep(WALK_END - WALK_STOP, WALK_END, t));
	for (int k = 0; k < STAGES; k++) {
		double a = WALK_END + k * PERIOD;
		stage[k](&p, window(a, a + STAGE, EASE, t));
	}
	return p;
}

/* ---- the tour on the CMU skeleton's arms ----
 * A bone's local rotation is C M C^-1, C from its ASF axis (x turned first)
 * and M from its dof values in the order rx ry rz (x first). Axes in
 * degrees, per side (0 right, 1 left); the legs, spine and clavicles have
 * the same axes in both skeletons (the feet's differ by 7 degrees about y:
 * left as it is). */
typedef double mat3[3][3];

static const double demo_axis[2][3][3] = { /* humerus, radius, wrist */
	{ { 0, 0, 90 }, { 0, 0, 90 }, { 0, 0, 90 } },
	{ { 0, 0, -90 }, { 0, 0, -90 }, { 0, 0, -90 } },
};
static const double cmu_axis[2][3][3] = { /* the same in every CMU subject's ASF */
	{ { 180, 30, 90 }, { 180, 30, 90 }, { 0, -90, -90 } },
	{ { 180, -30, -90 }, { 180, -30, -90 }, { 0, 90, 90 } },
};

static void mat_mul(const mat3 a, const mat3 b, mat3 out)
{
	mat3 t;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			t[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
	memcpy(out, t, sizeof t);
}

static void mat_transpose(const mat3 a, mat3 out)
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			out[j][i] = a[i][j];
}

/* rotation by deg degrees about basis axis k (0 x, 1 y, 2 z) */
static void mat_basis(int k, double deg, mat3 out)
{
	double c = cos(deg * M_PI / 180), s = sin(deg * M_PI / 180);
	int a = (k + 1) % 3, b = (k + 2) % 3;
	memset(out, 0, sizeof(mat3));
	out[k][k] = 1;
	out[a][a] = out[b][b] = c;
	out[b][a] = s;
	out[a][b] = -s;
}

/* Rz(v[2]) Ry(v[1]) Rx(v[0]): an ASF axis, or the dofs rx ry rz */
static void mat_euler(const double v[3], mat3 out)
{
	mat3 r;
	mat_basis(0, v[0], out);
	mat_basis(1, v[1], r);
	mat_mul(r, out, out);
	mat_basis(2, v[2], r);
	mat_mul(r, out, out);
}

static void euler_of(const mat3 m, double v[3])
{
	v[0] = atan2(m[2][1], m[2][2]) * 180 / M_PI;
	v[1] = atan2(-m[2][0], hypot(m[0][0], m[1][0])) * 180 / M_PI;
	v[2] = atan2(m[1][0], m[0][0]) * 180 / M_PI;
}

static void column(const mat3 m, int k, double v[3])
{
	for (int i = 0; i < 3; i++)
		v[i] = m[i][k];
}

/* The CMU elbow hinge is turned about the upper arm from the demo's: the
 * roll about the bone's axis (x in the rest pose) that takes the CMU hinge
 * onto the demo's. With it on the upper arm, the elbow bends in the same
 * plane and the forearm's twist turns about the same line. */
static void hinge_roll(int side, mat3 out)
{
	mat3 cd, cc;
	double hd[3], hc[3];
	mat_euler(demo_axis[side][1], cd);
	mat_euler(cmu_axis[side][1], cc);
	column(cd, 0, hd);
	column(cc, 0, hc);
	double deg = atan2(hc[1] * hd[2] - hc[2] * hd[1], hc[1] * hd[1] + hc[2] * hd[2]) * 180 / M_PI;
	mat_basis(0, deg, out);
}

/* One arm's dofs from the demo skeleton's values to the CMU skeleton's. */
static void arm_to_cmu(pose *p, int side)
{
	mat3 cd, cc, cct, m, roll;
	mat_euler(demo_axis[side][0], cd);
	mat_euler(cmu_axis[side][0], cc);
	mat_transpose(cc, cct);
	mat_transpose(cd, m);             /* C_demo^-1 */
	mat3 motion;
	mat_euler(p->humerus[side], motion);
	mat_mul(motion, m, m);            /* M C_demo^-1 */
	mat_mul(cd, m, m);                /* the local rotation, C_demo M C_demo^-1 */
	hinge_roll(side, roll);
	mat_mul(m, roll, m);
	mat_mul(m, cc, m);
	mat_mul(cct, m, m);               /* C_cmu^-1 (local roll) C_cmu */
	euler_of(m, p->humerus[side]);
	/* the forearm's twist axis (the wrist's y) points the other way */
	double td[3], tc[3];
	mat_euler(demo_axis[side][2], cd);
	mat_euler(cmu_axis[side][2], cc);
	column(cd, 1, td);
	column(cc, 1, tc);
	if (td[0] * tc[0] + td[1] * tc[1] + td[2] * tc[2] < 0)
		p->wrist[side] = -p->wrist[side];
}

/* Euler angles as continuous as the motion: within 180 degrees of the
 * previous frame's */
static void unwrap(double *v, int n, const double *prev)
{
	for (int i = 0; i < n; i++) {
		while (v[i] - prev[i] > 180)
			v[i] -= 360;
		while (v[i] - prev[i] < -180)
			v[i] += 360;
	}
}

static void line3(const char *name, const double v[3])
{
	printf("%s %.4f %.4f %.4f\n", name, v[0], v[1], v[2]);
}

static void write_frame(int n, const pose *p)
{
	static const double zero[3];
	static const char *side = "rl";
	printf("%d\n", n);
	printf("root %.4f %.4f %.4f %.4f %.4f %.4f\n", p->root[0], p->root[1], p->root[2],
	       p->root[3], p->root[4], p->root[5]);
	line3("lowerback", p->lowerback);
	line3("upperback", zero);
	line3("thorax", p->thorax);
	line3("lowerneck", p->lowerneck);
	line3("upperneck", p->upperneck);
	line3("head", p->head);
	for (int i = 0; i < 2; i++) {
		char name[16];
		printf("%cclavicle %.4f %.4f\n", side[i], p->clavicle[i][0], p->clavicle[i][1]);
		snprintf(name, sizeof name, "%chumerus", side[i]);
		line3(name, p->humerus[i]);
		printf("%cradius %.4f\n%cwrist %.4f\n", side[i], p->radius[i], side[i], p->wrist[i]);
		printf("%chand 0 0\n%cfingers 0\n%cthumb 0 0\n", side[i], side[i], side[i]);
	}
	for (int i = 0; i < 2; i++) {
		char name[16];
		snprintf(name, sizeof name, "%cfemur", side[i]);
		line3(name, p->femur[i]);
		printf("%ctibia %.4f\n%cfoot %.4f %.4f\n%ctoes %.4f\n", side[i], p->tibia[i], side[i],
		       p->foot[i][0], p->foot[i][1], side[i], p->toes[i]);
	}
}

int main(int argc, char **argv)
{
	int cmu = argc > 1 && !strcmp(argv[1], "cmu");
	if (argc > 2 || (argc == 2 && !cmu)) {
		fprintf(stderr, "usage: demo_motion [cmu] > M.amc\n");
		return 1;
	}
	printf("#!OML:ASF %s\n:FULLY-SPECIFIED\n:DEGREES\n", cmu ? "02.asf" : "demo.asf");
	int frames = (int)(TOUR_END * FPS + 0.5);
	pose prev;
	for (int n = 1; n <= frames; n++) {
		pose p = pose_at((n - 1) / FPS);
		for (int side = 0; cmu && side < 2; side++) {
			arm_to_cmu(&p, side);
			if (n > 1)
				unwrap(p.humerus[side], 3, prev.humerus[side]);
		}
		write_frame(n, &p);
		prev = p;
	}
	return 0;
}
