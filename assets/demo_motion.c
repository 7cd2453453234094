/* Writes the skinplay demo motion (AMC, 120 Hz) for assets/demo.asf to
 * stdout: a walk, then deep elbow and knee bends, then a large forearm and
 * upper-arm twist: the poses where LBS collapses and candy-wraps and DQBS
 * keeps its volume. Built and run by `make` into build/assets/demo.amc. */
#include <math.h>
#include <stdio.h>
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

int main(void)
{
	printf("#!OML:ASF demo.asf\n:FULLY-SPECIFIED\n:DEGREES\n");
	int frames = (int)(TWIST_END * FPS);
	for (int n = 1; n <= frames; n++) {
		pose p = pose_at((n - 1) / FPS);
		write_frame(n, &p);
	}
	return 0;
}
