/* Writes the skinplay demo motion (AMC, 120 Hz) for assets/demo.asf to
 * stdout: a walk, then deep elbow and knee bends, then a large forearm and
 * upper-arm twist: the poses where LBS collapses and candy-wraps and DQBS
 * keeps its volume. Built and run by `make` into build/assets/demo.amc.
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
#define WALK_END 4.0
#define BEND_END 6.5
#define TWIST_END 9.5

typedef struct pose {
	double root[6];
	double lowerback[3], thorax[3], head[3];
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

static void rest_arms(pose *p)
{
	/* side index 0 = right, 1 = left; rz lowers the T-pose arms */
	p->humerus[0][2] = 70;
	p->humerus[1][2] = -70;
	p->radius[0] = p->radius[1] = 15;
}

static void walk(pose *p, double t, double w)
{
	double ph = 2 * M_PI * t / 1.1;
	double l = sin(ph);
	double dist = 13.0 * (t < WALK_END ? t : WALK_END);
	p->root[2] = dist;
	p->root[1] = 16.9 + w * 0.35 * cos(2 * ph);
	p->femur[1][0] += w * -25 * l;
	p->femur[0][0] += w * 25 * l;
	p->tibia[1] += w * 35 * fmax(0, sin(ph + 1.3));
	p->tibia[0] += w * 35 * fmax(0, sin(ph + 1.3 + M_PI));
	p->foot[1][0] += w * 10 * sin(ph + 0.5);
	p->foot[0][0] += w * -10 * sin(ph + 0.5);
	p->humerus[1][0] += w * -20 * l;
	p->humerus[0][0] += w * 20 * l;
	p->lowerback[1] += w * 6 * l;
	p->thorax[1] += w * -6 * l;
}

static void bend(pose *p, double s)
{
	p->root[1] -= 10.0 * s;
	p->lowerback[0] += 25 * s;
	p->head[0] -= 15 * s;
	for (int i = 0; i < 2; i++) {
		p->femur[i][0] += -105 * s;
		p->tibia[i] += 135 * s;
		p->foot[i][0] += -30 * s;
		p->humerus[i][0] += 40 * s;
		p->radius[i] += 135 * s;
	}
}

static void twist(pose *p, double t, double s)
{
	double k = sin(M_PI * (t - BEND_END) / (TWIST_END - BEND_END));
	for (int i = 0; i < 2; i++) {
		double sign = i ? 1 : -1;
		p->humerus[i][2] += sign * 55 * s;   /* raise the arms to shoulder height */
		p->humerus[i][0] += 60 * s;          /* and forward */
		p->radius[i] -= 15 * s;
		p->wrist[i] = -175 * s * k * k;      /* the forearm twists half a turn */
		p->humerus[i][1] += sign * 40 * s * k; /* and the upper arm rolls */
	}
}

static pose pose_at(double t)
{
	pose p;
	memset(&p, 0, sizeof p);
	rest_arms(&p);
	double walking = 1 - smoothstep(WALK_END - 0.4, WALK_END, t);
	walk(&p, t, walking);
	bend(&p, window(WALK_END, BEND_END, 0.7, t));
	twist(&p, t, window(BEND_END, TWIST_END, 0.5, t));
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
	line3("lowerneck", zero);
	line3("upperneck", zero);
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
	int frames = (int)(TWIST_END * FPS);
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
