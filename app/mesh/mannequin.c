/* Marching tetrahedra over the mannequin field, one z slab at a time. Every
 * cube is cut into the same six tetrahedra around its main diagonal, so
 * neighbouring cubes agree on the shared face diagonals; with no sample
 * exactly at the iso level and an all-outside border, the result is the
 * zero set of a piecewise linear field: closed and 2-manifold. Vertices
 * live on grid edges and are shared through a table keyed by the edge. */
#include <math.h>
#include <string.h>

#include "mannequin.h"
#include "mesh_normals.h"

typedef struct grid {
	manq_work *w;
	mesh *m;
	skp_error *err;
	int detail;
	int nx, ny, nz;          /* samples per axis */
	vec3 origin;
	float cell;
} grid;

/* Corners as bits (x 1, y 2, z 4); each tetrahedron positively oriented:
 * det(v1 - v0, v2 - v0, v3 - v0) > 0. */
static const uint8_t cube_tets[6][4] = {
	{ 0, 1, 3, 7 }, { 0, 2, 6, 7 }, { 0, 4, 5, 7 },
	{ 0, 5, 1, 7 }, { 0, 3, 2, 7 }, { 0, 6, 4, 7 },
};
/* Even permutations (orientation kept) that move corner i last ... */
static const uint8_t last[4][4] = {
	{ 1, 3, 2, 0 }, { 0, 2, 3, 1 }, { 0, 3, 1, 2 }, { 0, 1, 2, 3 },
};
/* ... or the pair of corners in the mask first. */
static const uint8_t pair_first[16][4] = {
	[0x3] = { 0, 1, 2, 3 }, [0x5] = { 0, 2, 3, 1 }, [0x9] = { 0, 3, 1, 2 },
	[0x6] = { 1, 2, 0, 3 }, [0xa] = { 1, 3, 2, 0 }, [0xc] = { 2, 3, 0, 1 },
};

static vec3 corner_pos(const grid *g, int x, int y, int z)
{
	return vec3_make(g->origin.x + g->cell * (float)x, g->origin.y + g->cell * (float)y,
			 g->origin.z + g->cell * (float)z);
}

static float range_gap(float v, float lo, float hi)
{
	return v < lo ? lo - v : v > hi ? v - hi : 0.0f;
}

/* Parts within reach of a row of samples: a part further than the blend
 * width plus a few cells cannot move the surface (the field there is
 * positive whatever its value), and most rows meet only a few parts. */
static int near_row(grid *g, float y, float z, float reach)
{
	const manq_body *b = &g->w->body;
	int n = 0;
	for (int i = 0; i < b->count; i++) {
		const manq_part *q = &b->part[i];
		float gy = range_gap(y, q->box_lo.y, q->box_hi.y);
		float gz = range_gap(z, q->box_lo.z, q->box_hi.z);
		if (sqrtf(gy * gy + gz * gz) - q->r_max < reach)
			g->w->near[n++] = (uint16_t)i;
	}
	return n;
}

/* Never exactly zero: a sample on the surface would make a vertex shared
 * by several edges and the surface could pinch there. */
static void fill_slice(grid *g, int z)
{
	float *s = g->w->slice[z & 1];
	float nudge = g->cell * 1e-5f, reach = g->w->body.blend + 3.0f * g->cell;
	for (int y = 0; y < g->ny; y++) {
		vec3 p = corner_pos(g, 0, y, z);
		int n = near_row(g, p.y, p.z, reach);
		for (int x = 0; x < g->nx; x++) {
			p.x = g->origin.x + g->cell * (float)x;
			float v = manq_field_of(&g->w->body, g->w->near, n, reach, p);
			s[y * g->nx + x] = v == 0.0f ? nudge : v;
		}
	}
}

typedef struct tet_corner {
	int x, y, z;
	float v;
} tet_corner;

static uint32_t edge_id(const grid *g, const tet_corner *a, const tet_corner *b)
{
	const tet_corner *lo = a, *hi = b;
	if (b->x + b->y + b->z < a->x + a->y + a->z)
		lo = b, hi = a;
	uint32_t dir = (uint32_t)((hi->x - lo->x) | (hi->y - lo->y) << 1 | (hi->z - lo->z) << 2);
	uint32_t corner = (uint32_t)lo->x + (uint32_t)g->nx * ((uint32_t)lo->y + (uint32_t)g->ny * (uint32_t)lo->z);
	return corner * 7u + dir; /* dir in 1..7, so never 0 */
}

static skp_status new_vertex(grid *g, const tet_corner *a, const tet_corner *b, uint32_t *out)
{
	mesh *m = g->m;
	if (m->vert_count >= SKP_MAX_VERTS)
		return skp_fail(g->err, SKP_ERR_LIMIT, 0,
				"detail %d needs more than %d vertices (board limit SKP_MAX_VERTS)",
				g->detail, SKP_MAX_VERTS);
	float t = a->v / (a->v - b->v);
	vec3 pa = corner_pos(g, a->x, a->y, a->z), pb = corner_pos(g, b->x, b->y, b->z);
	m->pos[m->vert_count] = vec3_add(pa, vec3_scale(vec3_sub(pb, pa), t));
	*out = (uint32_t)m->vert_count++;
	return SKP_OK;
}

/* murmur3's finaliser: every key bit reaches the low bits we keep */
static uint32_t mix(uint32_t h)
{
	h ^= h >> 16;
	h *= 0x85ebca6bu;
	h ^= h >> 13;
	h *= 0xc2b2ae35u;
	return h ^ (h >> 16);
}

static skp_status edge_vertex(grid *g, const tet_corner *a, const tet_corner *b, uint32_t *out)
{
	uint32_t key = edge_id(g, a, b);
	uint32_t i = mix(key) & (MANQ_HASH_SIZE - 1);
	uint32_t *keys = g->w->edge_key;
	while (keys[i] != 0 && keys[i] != key)
		i = (i + 1) & (MANQ_HASH_SIZE - 1);
	if (keys[i] == key) {
		*out = g->w->edge_vert[i];
		return SKP_OK;
	}
	skp_status rc = new_vertex(g, a, b, out);
	if (!rc) {
		keys[i] = key;
		g->w->edge_vert[i] = *out;
	}
	return rc;
}

/* Vertices on edges p0-p1, p2-p3, p4-p5 of c, as one triangle. */
static skp_status emit(grid *g, const tet_corner *c, const uint8_t e[6])
{
	uint32_t v[3];
	for (int i = 0; i < 3; i++) {
		skp_status rc = edge_vertex(g, &c[e[2 * i]], &c[e[2 * i + 1]], &v[i]);
		if (rc)
			return rc;
	}
	mesh *m = g->m;
	if (m->tri_count >= SKP_MAX_TRIS)
		return skp_fail(g->err, SKP_ERR_LIMIT, 0,
				"detail %d needs more than %d triangles (board limit SKP_MAX_TRIS)",
				g->detail, SKP_MAX_TRIS);
	memcpy(m->tri[m->tri_count++], v, sizeof v);
	return SKP_OK;
}

/* c: a positively oriented tetrahedron; triangles face the positive
 * (outside) corners. */
static skp_status march_tet(grid *g, const tet_corner *c)
{
	unsigned in = 0;
	for (int i = 0; i < 4; i++)
		in |= (unsigned)(c[i].v < 0.0f) << i;
	int n = (int)((in & 1) + (in >> 1 & 1) + (in >> 2 & 1) + (in >> 3 & 1));
	if (n == 0 || n == 4)
		return SKP_OK;
	if (n == 2) {
		const uint8_t *o = pair_first[in]; /* inside a, b; outside c, d */
		const uint8_t t0[6] = { o[0], o[2], o[0], o[3], o[1], o[3] };
		const uint8_t t1[6] = { o[0], o[2], o[1], o[3], o[1], o[2] };
		skp_status rc = emit(g, c, t0);
		return rc ? rc : emit(g, c, t1);
	}
	unsigned lone = n == 1 ? in : (~in & 0xfu);
	int d = 0;
	while (!(lone >> d & 1))
		d++;
	const uint8_t *o = last[d];
	/* around d: inside alone faces away from it, outside alone towards it */
	const uint8_t inward[6] = { o[3], o[0], o[3], o[2], o[3], o[1] };
	const uint8_t outward[6] = { o[3], o[0], o[3], o[1], o[3], o[2] };
	return emit(g, c, n == 1 ? inward : outward);
}

static skp_status march_cube(grid *g, int x, int y, int z)
{
	tet_corner k[8];
	int pos = 0;
	for (int i = 0; i < 8; i++) {
		k[i].x = x + (i & 1);
		k[i].y = y + (i >> 1 & 1);
		k[i].z = z + (i >> 2);
		k[i].v = g->w->slice[k[i].z & 1][k[i].y * g->nx + k[i].x];
		pos += k[i].v > 0.0f;
	}
	if (pos == 0 || pos == 8)
		return SKP_OK;
	for (int t = 0; t < 6; t++) {
		tet_corner c[4];
		for (int i = 0; i < 4; i++)
			c[i] = k[cube_tets[t][i]];
		skp_status rc = march_tet(g, c);
		if (rc)
			return rc;
	}
	return SKP_OK;
}

static skp_status march(grid *g)
{
	fill_slice(g, 0);
	for (int z = 0; z + 1 < g->nz; z++) {
		fill_slice(g, z + 1);
		for (int y = 0; y + 1 < g->ny; y++)
			for (int x = 0; x + 1 < g->nx; x++) {
				skp_status rc = march_cube(g, x, y, z);
				if (rc)
					return rc;
			}
	}
	return SKP_OK;
}

/* Samples count along one axis from the anchor, which sits on a sample
 * so that the grid never misses the whole body; two cells of margin beyond
 * the parts keep the border samples outside, which closes the surface. */
static int axis_samples(float anchor, float lo, float hi, float cell, float *origin)
{
	int below = (int)ceilf((anchor - lo) / cell) + 2;
	*origin = anchor - cell * (float)below;
	return below + (int)ceilf((hi - anchor) / cell) + 3;
}

static skp_status setup_grid(grid *g)
{
	const manq_body *b = &g->w->body;
	vec3 pad = vec3_make(b->blend, b->blend, b->blend);
	vec3 lo = vec3_sub(b->lo, pad), hi = vec3_add(b->hi, pad), ext = vec3_sub(hi, lo);
	vec3 anchor = b->part[0].a; /* the trunk: the thickest part */
	g->cell = fmaxf(ext.x, fmaxf(ext.y, ext.z)) / (float)g->detail;
	g->nx = axis_samples(anchor.x, lo.x, hi.x, g->cell, &g->origin.x);
	g->ny = axis_samples(anchor.y, lo.y, hi.y, g->cell, &g->origin.y);
	g->nz = axis_samples(anchor.z, lo.z, hi.z, g->cell, &g->origin.z);
	if (g->nx > MANQ_MAX_SIDE || g->ny > MANQ_MAX_SIDE || g->nz > MANQ_MAX_SIDE)
		return skp_fail(g->err, SKP_ERR_LIMIT, 0, "grid of %d x %d x %d samples is over %d a side",
				g->nx, g->ny, g->nz, MANQ_MAX_SIDE);
	return SKP_OK;
}

/* The field's gradient points outwards; where it vanishes the faces'
 * normal stands in. */
static void set_normals(grid *g)
{
	mesh *m = g->m;
	float step = g->cell * 0.05f;
	int flat = 0;
	for (int i = 0; i < m->vert_count; i++) {
		m->normal[i] = manq_field_normal(&g->w->body, m->pos[i], step);
		flat |= vec3_dot(m->normal[i], m->normal[i]) == 0.0f;
	}
	if (!flat)
		return;
	mesh_compute_normals(m);
	for (int i = 0; i < m->vert_count; i++) {
		vec3 n = manq_field_normal(&g->w->body, m->pos[i], step);
		if (vec3_dot(n, n) > 0.0f)
			m->normal[i] = n;
	}
}

skp_status manq_build(const skel *s, int detail, manq_work *w, mesh *out, skp_error *err)
{
	skp_error_clear(err);
	out->vert_count = out->tri_count = out->coloured = out->textured = 0;
	if (detail == 0)
		detail = MANQ_DEFAULT_DETAIL;
	if (detail < MANQ_MIN_DETAIL || detail > MANQ_MAX_DETAIL)
		return skp_fail(err, SKP_ERR_RANGE, 0, "detail %d is outside %d..%d",
				detail, MANQ_MIN_DETAIL, MANQ_MAX_DETAIL);
	w->arms_raised = skel_tpose(s, w->pose_value, &w->rest);
	skp_status rc = manq_body_from_skel(s, &w->rest, &w->body, err);
	if (rc)
		return rc;
	grid g = { w, out, err, detail, 0, 0, 0, { 0.0f, 0.0f, 0.0f }, 0.0f };
	rc = setup_grid(&g);
	if (rc)
		return rc;
	memset(w->edge_key, 0, sizeof w->edge_key);
	rc = march(&g);
	if (rc)
		return rc;
	if (out->tri_count == 0)
		return skp_fail(err, SKP_ERR_RANGE, 0, "the body is thinner than the grid at detail %d",
				detail);
	set_normals(&g);
	return SKP_OK;
}
