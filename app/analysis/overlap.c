#include "overlap.h"

#include <math.h>

/* Rays pass off the cell middles by fractions no real mesh lines up with:
 * a ray through a vertex or along an edge would count a crossing twice or
 * not at all. */
#define RAY_OFFSET_X 0.5180339887
#define RAY_OFFSET_Y 0.4142135624

typedef struct ray_grid {
	double x0, y0, h;
	int nx, ny;
} ray_grid;

static int grid_over(const float *xyz, int n, int grid, ray_grid *g)
{
	if (n <= 0 || grid <= 0)
		return 0;
	double lo[2] = { xyz[0], xyz[1] }, hi[2] = { xyz[0], xyz[1] };
	for (int v = 1; v < n; v++)
		for (int k = 0; k < 2; k++) {
			lo[k] = fmin(lo[k], xyz[3 * v + k]);
			hi[k] = fmax(hi[k], xyz[3 * v + k]);
		}
	double ext = fmax(hi[0] - lo[0], hi[1] - lo[1]);
	if (!(ext > 0.0) || !isfinite(ext))
		return 0;
	g->h = ext / grid;
	g->x0 = lo[0];
	g->y0 = lo[1];
	g->nx = (int)fmin(grid, floor((hi[0] - lo[0]) / g->h) + 1);
	g->ny = (int)fmin(grid, floor((hi[1] - lo[1]) / g->h) + 1);
	return 1;
}

/* The first and last ray index (clamped to [0, n)) whose centre may lie in
 * [lo, hi] along an axis starting at origin. */
static void ray_range(double lo, double hi, double origin, double h, double offset, int n,
		      int *first, int *last)
{
	double a = floor((lo - origin) / h - offset), b = floor((hi - origin) / h - offset) + 1;
	*first = (int)fmax(a, 0.0);
	*last = (int)fmin(b, n - 1.0);
}

typedef struct crossing_pass {
	const overlap_work *w;
	int fill;     /* 0: count into ray_start[ray + 1]; 1: place the hits */
} crossing_pass;

static void record(const crossing_pass *p, int ray, float z, int dir)
{
	if (!p->fill) {
		p->w->ray_start[ray + 1]++;
		return;
	}
	int k = p->w->ray_start[ray]++;
	p->w->hit_z[k] = z;
	p->w->hit_dir[k] = (signed char)dir;
}

/* Every ray through the x-y projection of triangle abc: where along z it
 * crosses, entering (the face looks down, -z) or leaving. */
static void cross_triangle(const ray_grid *g, const float *a, const float *b, const float *c,
			   const crossing_pass *p)
{
	double area = ((double)b[0] - a[0]) * ((double)c[1] - a[1]) -
		      ((double)b[1] - a[1]) * ((double)c[0] - a[0]);
	if (area == 0.0 || !isfinite(area))
		return; /* edge-on, or a vertex blown up to nan / inf */
	int i0, i1, j0, j1;
	ray_range(fmin(a[0], fmin(b[0], c[0])), fmax(a[0], fmax(b[0], c[0])), g->x0, g->h,
		  RAY_OFFSET_X, g->nx, &i0, &i1);
	ray_range(fmin(a[1], fmin(b[1], c[1])), fmax(a[1], fmax(b[1], c[1])), g->y0, g->h,
		  RAY_OFFSET_Y, g->ny, &j0, &j1);
	int dir = area > 0.0 ? -1 : 1;
	for (int j = j0; j <= j1; j++) {
		double py = g->y0 + (j + RAY_OFFSET_Y) * g->h;
		for (int i = i0; i <= i1; i++) {
			double px = g->x0 + (i + RAY_OFFSET_X) * g->h;
			double wa = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area;
			double wb = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area;
			double wc = 1.0 - wa - wb;
			if (wa < 0.0 || wb < 0.0 || wc < 0.0)
				continue;
			record(p, j * g->nx + i, (float)(wa * a[2] + wb * b[2] + wc * c[2]), dir);
		}
	}
}

static void cross_all(const ray_grid *g, const float *xyz, const uint32_t (*tri)[3], int tri_count,
		      const crossing_pass *p)
{
	for (int t = 0; t < tri_count; t++)
		cross_triangle(g, xyz + 3 * tri[t][0], xyz + 3 * tri[t][1], xyz + 3 * tri[t][2], p);
}

/* Along one ray: sorts the crossings by z, then integrates w - [w >= 1]. */
static double sweep(float *z, signed char *dir, int n)
{
	for (int i = 1; i < n; i++) {
		float zi = z[i];
		signed char di = dir[i];
		int k = i;
		for (; k > 0 && z[k - 1] > zi; k--) {
			z[k] = z[k - 1];
			dir[k] = dir[k - 1];
		}
		z[k] = zi;
		dir[k] = di;
	}
	double excess = 0.0;
	int wind = 0;
	for (int k = 0; k + 1 < n; k++) {
		wind += dir[k];
		double dz = (double)z[k + 1] - z[k];
		if (wind >= 2)
			excess += (wind - 1) * dz;
		else if (wind < 0)
			excess += wind * dz;
	}
	return excess;
}

double overlap_of_mesh(const float *xyz, int vert_count, const uint32_t (*tri)[3], int tri_count,
			 const overlap_work *w, int *ok)
{
	ray_grid g;
	*ok = 0;
	if (!grid_over(xyz, vert_count, w->grid, &g))
		return 0.0;
	int rays = g.nx * g.ny;
	for (int r = 0; r <= rays; r++)
		w->ray_start[r] = 0;
	crossing_pass count = { w, 0 }, fill = { w, 1 };
	cross_all(&g, xyz, tri, tri_count, &count);
	for (int r = 0; r < rays; r++) {
		if (w->ray_start[r + 1] > w->max_hits - w->ray_start[r])
			return 0.0;
		w->ray_start[r + 1] += w->ray_start[r];
	}
	/* placing advances each ray's start to its end, which is the next
	 * ray's start: shift back after */
	cross_all(&g, xyz, tri, tri_count, &fill);
	for (int r = rays; r > 0; r--)
		w->ray_start[r] = w->ray_start[r - 1];
	w->ray_start[0] = 0;
	double excess = 0.0;
	for (int r = 0; r < rays; r++) {
		int a = w->ray_start[r], b = w->ray_start[r + 1];
		excess += sweep(w->hit_z + a, w->hit_dir + a, b - a);
	}
	*ok = 1;
	return excess * g.h * g.h;
}
