#include "bind_balance_solve.h"

#include <math.h>
#include <string.h>

/* Keeps the Laplacian positive definite on a band with no fixed border (a
 * whole closed mesh); small, so the field stays smooth. */
#define SOLVE_EPS 0.01
#define CG_MAX_ITER 500
#define CG_TOL2 1e-12              /* squared residual, relative: 1e-6 of the right side */
#define CLAMP_ROUNDS 6

/* (L + eps I) dir on the free slots: neighbours outside the band or
 * clamped count as 0 (the field vanishes at the border). dir, the CG
 * direction, is +0.0 on the clamped slots (solve_field keeps it so), so a
 * clamped neighbour needs no test: subtracting its +0.0 leaves the sum as
 * it was, bit for bit. */
static void apply_laplacian(const bind_balance_work *w, int m, const double *dir, double *out)
{
	for (int i = 0; i < m; i++) {
		if (w->clamped[i]) {
			out[i] = 0.0;
			continue;
		}
		uint32_t v = w->band[i], a = w->adj_start[v], b = w->adj_start[v + 1];
		double s = ((double)(b - a) + SOLVE_EPS) * dir[i];
		for (uint32_t k = a; k < b; k++) {
			int32_t j = w->slot[w->adj[k]];
			if (j >= 0)
				s -= dir[j];
		}
		out[i] = s;
	}
}

static double dot(const double *a, const double *b, int m)
{
	double s = 0.0;
	for (int i = 0; i < m; i++)
		s += a[i] * b[i];
	return s;
}

/* Conjugate gradients for (L + eps I) x = component k of the arm, on the
 * free slots. The direction p starts and stays +0.0 on the clamped ones
 * (their residual is 0, and so is their row of the product). */
static void solve_field(bind_balance_work *w, int m, int k, double *x)
{
	double *r = w->cg_r, *p = w->cg_p, *kp = w->cg_kp;
	for (int i = 0; i < m; i++) {
		x[i] = 0.0;
		r[i] = w->clamped[i] ? 0.0 : w->arm[w->band[i]][k];
		p[i] = r[i];
	}
	double rr = dot(r, r, m), stop = CG_TOL2 * rr;
	for (int it = 0; it < CG_MAX_ITER && rr > stop && rr > 0.0; it++) {
		apply_laplacian(w, m, p, kp);
		double alpha = rr / dot(p, kp, m);
		for (int i = 0; i < m; i++) {
			x[i] += alpha * p[i];
			r[i] -= alpha * kp[i];
		}
		double next = dot(r, r, m);
		for (int i = 0; i < m; i++)
			p[i] = r[i] + next / rr * p[i];
		rr = next;
	}
}

static double det3(double a[3][3])
{
	return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
	       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
	       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/* Cramer's rule; a tiny ridge keeps a direction the band cannot move (a
 * twist about a round limb's axis) from blowing up. */
static void solve3(double a[3][3], const double rhs[3], double x[3])
{
	double ridge = 1e-6 * (a[0][0] + a[1][1] + a[2][2]);
	for (int i = 0; i < 3; i++)
		a[i][i] += ridge;
	double d = det3(a);
	for (int c = 0; c < 3; c++) {
		double t[3][3];
		memcpy(t, a, sizeof t);
		for (int i = 0; i < 3; i++)
			t[i][c] = rhs[i];
		x[c] = fabs(d) > 0.0 ? det3(t) / d : 0.0;
	}
}

static void moment_left(const bind_balance_work *w, int m, const double moment[3], double left[3])
{
	for (int k = 0; k < 3; k++) {
		left[k] = moment[k];
		for (int i = 0; i < m; i++)
			left[k] += w->change[i] * w->arm[w->band[i]][k];
	}
}

/* One round: the three fields on the free slots, weighted to cancel what
 * is left; returns how many slots it had to clamp. */
static int solve_round(bind_balance_work *w, int m, const double moment[3])
{
	double left[3], a[3][3], lambda[3];
	moment_left(w, m, moment, left);
	for (int k = 0; k < 3; k++)
		solve_field(w, m, k, w->psi[k]);
	for (int i = 0; i < 3; i++)
		for (int k = 0; k < 3; k++) {
			a[i][k] = 0.0;
			for (int s = 0; s < m; s++)
				a[i][k] += w->arm[w->band[s]][i] * w->psi[k][s];
		}
	const double rhs[3] = { -left[0], -left[1], -left[2] };
	solve3(a, rhs, lambda);
	int clamped = 0;
	for (int s = 0; s < m; s++) {
		if (w->clamped[s])
			continue;
		double t0 = w->share[w->band[s]];
		double d = w->change[s] + lambda[0] * w->psi[0][s] + lambda[1] * w->psi[1][s] +
			   lambda[2] * w->psi[2][s];
		if (t0 + d < 0.0 || t0 + d > 1.0) {
			d = (t0 + d < 0.0 ? 0.0 : 1.0) - t0;
			w->clamped[s] = 1;
			clamped++;
		}
		w->change[s] = d;
	}
	return clamped;
}

double balance_solve(bind_balance_work *w, int m, const double moment[3], double left[3])
{
	memset(w->change, 0, (size_t)m * sizeof w->change[0]);
	memset(w->clamped, 0, (size_t)m);
	for (int round = 0; round < CLAMP_ROUNDS; round++)
		if (solve_round(w, m, moment) == 0)
			break;
	moment_left(w, m, moment, left);
	double most = 0.0;
	for (int s = 0; s < m; s++)
		most = fmax(most, fabs(w->change[s]));
	return most;
}
