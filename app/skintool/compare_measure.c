/* skintool compare's measuring part (compare.h): the synthetic scenes, every
 * frame of the clip with the three algorithms (metrics.csv and the
 * summary's extremes), and the joints behind the worst volumes. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli_error.h"
#include "cli_inputs.h"
#include "clock.h"
#include "cli_progress.h"
#include "cli_quiet.h"
#include "compare.h"
#include "motion_file.h"
#include "overlap.h"
#include "rig_load.h"
#include "setup_bind.h"
#include "setup_gate.h"
#include "tool_state.h"

#define OVERLAP_GRID 256
#define OVERLAP_HITS (1 << 22)

/* ---- the synthetic scenes ------------------------------------------- */

int compare_measure_scenes(compare_run *c)
{
	static skel_pose pose;
	scene_rig *sc = &c->scene;
	static const int angles[REPORT_ANGLES] = { 45, 90, 135, 180 };
	report *r = &c->rep;
	scene_build(sc);
	if (runtime_skin_init(&c->sk, &sc->skel, &sc->bind, &sc->mesh, &sc->weights, "scene") < 0 ||
	    measure_init(&c->meas, &sc->mesh, &sc->bind, sc->skel.count, "scene") < 0)
		return -1;
	r->scene_count = 0;
	for (int k = 0; k < SCENE_KIND_COUNT; k++)
		for (int i = 0; i < REPORT_ANGLES; i++) {
			report_scene *s = &r->scene[r->scene_count++];
			s->kind = (scene_kind)k;
			s->angle_deg = angles[i];
			/* as skintool metrics --scene computes the angle */
			double deg = angles[i];
			scene_pose(sc, s->kind, (float)(deg * (3.14159265358979323846 / 180.0)), &pose);
			runtime_skin_pose(&c->sk, &pose);
			measure_pose(&c->meas, &c->sk.pose);
			for (int a = 0; a < NALGO; a++) {
				runtime_skin_run(&c->sk, (skin_algo)a, c->pos, c->nrm);
				measure_row row = measure_skinned(&c->meas, c->pos, NULL);
				s->vol[a] = row.volume_ratio;
				s->rmin[a] = row.radius.min;
				s->rmax[a] = row.radius.max;
			}
		}
	return 0;
}

/* ---- the clip ------------------------------------------------------- */

static void extreme_init(report_extreme *e, double value)
{
	e->value = value;
	e->frame = -1;
	e->region = -1;
	e->joint = -1;
}

static void reset_summary(report *r)
{
	for (int a = 0; a < NALGO; a++) {
		report_algo *s = &r->algo[a];
		extreme_init(&s->vol_min, INFINITY);
		extreme_init(&s->vol_max, -INFINITY);
		extreme_init(&s->rad_min, INFINITY);
		extreme_init(&s->rad_max, -INFINITY);
		for (int g = 0; g < REGION_COUNT; g++) {
			extreme_init(&s->reg_min[g], NAN);
			extreme_init(&s->reg_max[g], NAN);
			extreme_init(&s->rvol_min[g], NAN);
			extreme_init(&s->rvol_max[g], NAN);
			s->rvol_folded[g] = 0;
		}
		s->vol_dev = -1.0;
		s->vol_dev_frame = -1;
	}
	extreme_init(&r->rel_min, INFINITY);
}

void compare_set_extreme(compare_run *c, report_extreme *e, double value, long frame, int vertex)
{
	e->value = value;
	e->frame = frame;
	e->joint = vertex >= 0 ? c->joint[vertex] : -1;
	e->region = vertex >= 0 ? c->region[vertex] : -1;
}

/* Per region min and max of the ratios, with the vertices they are at. */
static void region_ranges(const compare_run *c, const float *ratio, frame_stats *st, int *at_min,
			  int *at_max)
{
	for (int g = 0; g < REGION_COUNT; g++) {
		st->reg_min[g] = INFINITY;
		st->reg_max[g] = -INFINITY;
		at_min[g] = at_max[g] = -1;
	}
	for (int v = 0; v < c->rep.vert_count; v++) {
		int g = c->region[v];
		float q = ratio[v];
		if (g < 0 || isnan(q))
			continue;
		if (q < st->reg_min[g])
			st->reg_min[g] = q, at_min[g] = v;
		if (q > st->reg_max[g])
			st->reg_max[g] = q, at_max[g] = v;
	}
	for (int g = 0; g < REGION_COUNT; g++)
		if (at_min[g] < 0)
			st->reg_min[g] = st->reg_max[g] = NAN;
}

static void print_row(compare_run *c, long frame, int a, const measure_row *row,
		      const frame_stats *st)
{
	fprintf(c->csv, "%ld,%s,%.6f,%.6f,%.6f", frame, skin_algo_name((skin_algo)a),
		row->volume_ratio, (double)row->radius.min, (double)row->radius.max);
	for (int g = 0; g < REGION_COUNT; g++) {
		if (isnan(st->reg_min[g]))
			fputs(",,", c->csv);
		else
			fprintf(c->csv, ",%.6f,%.6f", (double)st->reg_min[g], (double)st->reg_max[g]);
	}
	fputc('\n', c->csv);
}

/* The regions' volume ratios against their extremes over the clip. */
static void summarise_region_volumes(compare_run *c, long frame, int a, const double *ratio)
{
	report_algo *s = &c->rep.algo[a];
	for (int g = 0; g < REGION_COUNT; g++) {
		if (isnan(ratio[g]))
			continue;
		if (ratio[g] <= 0.0)
			s->rvol_folded[g] = 1;
		if (!(ratio[g] >= s->rvol_min[g].value)) {
			compare_set_extreme(c, &s->rvol_min[g], ratio[g], frame, -1);
			s->rvol_min[g].region = g;
		}
		if (!(ratio[g] <= s->rvol_max[g].value)) {
			compare_set_extreme(c, &s->rvol_max[g], ratio[g], frame, -1);
			s->rvol_max[g].region = g;
		}
	}
}

static void summarise(compare_run *c, long frame, int a, const measure_row *row,
		      const frame_stats *st, const int *at_min, const int *at_max)
{
	report_algo *s = &c->rep.algo[a];
	double dev = fabs(1.0 - row->volume_ratio);
	if (row->volume_ratio < s->vol_min.value)
		compare_set_extreme(c, &s->vol_min, row->volume_ratio, frame, -1);
	if (row->volume_ratio > s->vol_max.value)
		compare_set_extreme(c, &s->vol_max, row->volume_ratio, frame, -1);
	if (dev > s->vol_dev)
		s->vol_dev = dev, s->vol_dev_frame = frame;
	if (row->radius.counted && row->radius.min < s->rad_min.value)
		compare_set_extreme(c, &s->rad_min, row->radius.min, frame, row->worst_vertex);
	if (row->radius.counted && row->radius.max > s->rad_max.value) {
		/* the largest ratio's vertex is not tracked by the shared row */
		compare_set_extreme(c, &s->rad_max, row->radius.max, frame, -1);
	}
	for (int g = 0; g < REGION_COUNT; g++) {
		if (at_min[g] < 0)
			continue;
		if (!(st->reg_min[g] >= s->reg_min[g].value))
			compare_set_extreme(c, &s->reg_min[g], st->reg_min[g], frame, at_min[g]);
		if (!(st->reg_max[g] <= s->reg_max[g].value))
			compare_set_extreme(c, &s->reg_max[g], st->reg_max[g], frame, at_max[g]);
	}
}

/* The joint-region vertex where LBS is thinnest compared with DQBS:
 * min(LBS ratio, 1) - min(DQBS ratio, 1). Contact with another limb
 * shrinks both alike and DQBS's bulges are no collapse, so what remains
 * is LBS's own collapse. */
static float lbs_vs_dqbs(const compare_run *c, int *vertex, float *region_best, int *region_vertex)
{
	const float *l = c->ratio[SKIN_LBS], *d = c->ratio[SKIN_DQBS];
	float best = INFINITY;
	*vertex = -1;
	for (int g = 0; g < REGION_COUNT; g++)
		region_best[g] = INFINITY, region_vertex[g] = -1;
	for (int v = 0; v < c->rep.vert_count; v++) {
		int g = c->region[v];
		if (g < 0 || isnan(l[v]) || isnan(d[v]))
			continue;
		float x = fminf(l[v], 1.0f) - fminf(d[v], 1.0f);
		if (x < best)
			best = x, *vertex = v;
		if (x < region_best[g])
			region_best[g] = x, region_vertex[g] = v;
	}
	return best;
}

static void measure_frame(compare_run *c, long frame, int keep)
{
	measure_row row[NALGO];
	frame_stats st[NALGO];
	int at_min[REGION_COUNT], at_max[REGION_COUNT];
	measure_pose(&c->meas, &c->sk.pose);
	for (int a = 0; a < NALGO; a++) {
		runtime_skin_run(&c->sk, (skin_algo)a, c->pos, c->nrm);
		row[a] = measure_skinned(&c->meas, c->pos, c->ratio[a]);
		st[a].vol = (float)row[a].volume_ratio;
		st[a].rmin = row[a].radius.min;
		st[a].rmax = row[a].radius.max;
		region_ranges(c, c->ratio[a], &st[a], at_min, at_max);
		print_row(c, frame, a, &row[a], &st[a]);
		summarise(c, frame, a, &row[a], &st[a], at_min, at_max);
		double rvol[REGION_COUNT];
		compare_region_volume(c, c->pos, &c->sk.pose, rvol);
		summarise_region_volumes(c, frame, a, rvol);
		for (int g = 0; g < REGION_COUNT; g++)
			st[a].rvol[g] = (float)rvol[g];
		if (a == SKIN_DQBS && isnan(c->floor_y)) {
			c->floor_y = INFINITY;
			for (int v = 0; v < c->rep.vert_count; v++)
				c->floor_y = fminf(c->floor_y, c->pos[3 * v + 1]);
		}
	}
	int v, reg_v[REGION_COUNT];
	float reg_rel[REGION_COUNT];
	float rel = lbs_vs_dqbs(c, &v, reg_rel, reg_v);
	if (v >= 0 && rel < c->rep.rel_min.value)
		compare_set_extreme(c, &c->rep.rel_min, rel, frame, v);
	if (!keep || c->kept >= STORE_MAX)
		return;
	int k = c->kept++;
	c->frame[k] = frame;
	for (int a = 0; a < NALGO; a++)
		c->st[a][k] = st[a];
	c->rel[k] = v >= 0 ? rel : NAN;
	c->rel_vertex[k] = v;
	for (int g = 0; g < REGION_COUNT; g++) {
		c->rel_region[g][k] = reg_v[g] >= 0 ? reg_rel[g] : NAN;
		c->rel_region_vertex[g][k] = reg_v[g];
	}
}

static long count_frames(const compare_args *a, const skel *s)
{
	static motion_file mo;
	static amc_frame f;
	long n = 0;
	int rc;
	if (motion_file_open(&mo, a->amc, s) < 0)
		return -1;
	while ((rc = motion_file_next(&mo, &f)) > 0)
		n++;
	motion_file_close(&mo);
	if (rc < 0)
		return -1;
	if (n == 0)
		fprintf(stderr, "%s: no frames\n", a->amc);
	return n ? n : -1;
}

static int open_csv(compare_run *c, const compare_args *a)
{
	snprintf(c->path, sizeof c->path, "%s/%s", a->out, a->csv_name ? a->csv_name : "metrics.csv");
	if (cli_output_check(c->path) < 0)
		return -1;
	if (!(c->csv = fopen(c->path, "w"))) {
		fprintf(stderr, "%s: %s\n", c->path, strerror(errno));
		return -1;
	}
	fputs("frame,algo,volume_ratio,min_radius_ratio,max_radius_ratio", c->csv);
	for (int g = 0; g < REGION_COUNT; g++)
		fprintf(c->csv, ",%s_min,%s_max", report_region_name(g), report_region_name(g));
	fputc('\n', c->csv);
	return 0;
}

int compare_load_clip(compare_run *c, const compare_args *a)
{
	report *r = &c->rep;
	const char *what = a->mesh ? a->mesh : GENERATED_BODY;
	if (rig_bind_load(&a->bind, a->asf, a->mesh, &c->body) < 0 ||
	    runtime_skin_init(&c->sk, &c->body.skel, &c->body.pose, &c->body.mesh, &c->body.weights, what) < 0 ||
	    measure_init(&c->meas, &c->body.mesh, &c->body.pose, c->body.skel.count, what) < 0)
		return -1;
	r->skel = &c->body.skel;
	r->mesh_name = what;
	r->balanced = c->body.balanced;
	r->gate = &c->body.gate;
	setup_gate_where(&c->body, &c->body.gate.stretch, r->gate_where, sizeof r->gate_where);
	setup_gate_where(&c->body, &c->body.gate.grow, r->grow_where, sizeof r->grow_where);
	r->gate_region = c->body.gate.stretch.region > 0 ? c->body.skel.bone[c->body.gate.stretch.region].name : "the root";
	r->grow_region = c->body.gate.grow.region > 0 ? c->body.skel.bone[c->body.gate.grow.region].name : "the root";
	r->weights = a->bind.weights_mesh ? "the mesh's own (its skin, mapped onto the skeleton)" :
		     !c->body.automatic ? "read from the weights file" :
		     c->body.balanced ? "automatic, volume-balanced" : "automatic (the paper's rule alone)";
	r->vert_count = c->body.mesh.vert_count;
	r->tri_count = c->body.mesh.tri_count;
	r->parts = c->meas.parts;
	r->volume_closed = c->meas.volume_closed;
	report_classify(&c->body.skel, &c->body.pose, c->meas.bind_xyz, r->vert_count, c->joint, c->region);
	compare_region_volume_init(c);
	r->measured = 0;
	for (int v = 0; v < r->vert_count; v++) {
		int measured = c->meas.rest_dist[v] > c->meas.min_rest;
		r->measured += measured;
		if (c->region[v] >= 0 && measured)
			r->region_verts[c->region[v]]++;
	}
	return 0;
}

int compare_measure_clip(compare_run *c, const compare_args *a)
{
	static motion_file mo;
	static amc_frame f;
	report *r = &c->rep;
	long total = count_frames(a, &c->body.skel);
	if (total < 0 || open_csv(c, a) < 0 || motion_file_open(&mo, a->amc, &c->body.skel) < 0)
		return -1;
	c->stride = (int)((total + STORE_MAX - 1) / STORE_MAX);
	c->kept = 0;
	c->floor_y = NAN;
	reset_summary(r);
	static cli_progress pr;
	static char what[300];
	snprintf(what, sizeof what, "compare %s%s", cli_basename(a->amc), a->csv_name ? " (other weights)" : "");
	cli_progress_start(&pr, what, "frames", total);
	long n = 0;
	int rc;
	while ((rc = motion_file_next(&mo, &f)) > 0) {
		runtime_skin_frame(&c->sk, f.value);
		measure_frame(c, f.number, n % c->stride == 0);
		cli_progress_step(&pr, ++n);
	}
	motion_file_close(&mo);
	cli_progress_end(&pr, " x 3 algorithms measured");
	r->frames = n;
	r->seconds = cli_progress_seconds(&pr);
	int bad = ferror(c->csv);
	if (fclose(c->csv) != 0 || bad) {
		fprintf(stderr, "%s: write failed\n", c->path);
		return -1;
	}
	return rc < 0 ? -1 : 0;
}

/* How much of the body, posed by values and skinned with DQBS, is inside
 * two of its parts at once (a thigh pressed into the belly), which the
 * signed volume counts twice and the space the body takes up once. */
static void measure_overlap(compare_run *c, const float *values)
{
	static int ray_start[OVERLAP_GRID * OVERLAP_GRID + 1];
	TOOL_STATE_ARRAY(float, hit_z, OVERLAP_HITS);
	TOOL_STATE_ARRAY(signed char, hit_dir, OVERLAP_HITS);
	const overlap_work work = { OVERLAP_GRID, OVERLAP_HITS, ray_start, hit_z, hit_dir };
	if (!(c->meas.rest_volume > 0.0))
		return;
	runtime_skin_frame(&c->sk, values);
	runtime_skin_run(&c->sk, SKIN_DQBS, c->pos, c->nrm);
	const mesh *m = &c->body.mesh;
	int ok;
	double excess = overlap_of_mesh(c->pos, m->vert_count, (const uint32_t (*)[3])m->tri, m->tri_count,
					  &work, &ok);
	if (ok)
		c->rep.dqbs_overlap = excess / c->meas.rest_volume;
}

/* At DQBS's frame also the overlap: each frame read once. */
int compare_explain_volume(compare_run *c, const compare_args *a)
{
	static amc_frame f;
	const long frame[2] = { c->rep.algo[SKIN_LBS].vol_min.frame, c->rep.algo[SKIN_DQBS].vol_dev_frame };
	c->rep.dqbs_overlap = NAN;
	for (int k = 0; k < 2; k++) {
		report_joints *j = &c->rep.vol_joints[k];
		j->frame = -1;
		if (frame[k] < 0)
			continue;
		if (motion_read_frame(a->amc, &c->body.skel, frame[k], &f) < 0)
			return -1;
		if (k == SKIN_DQBS)
			measure_overlap(c, f.value);
		report_find_joints(&c->sk, &c->meas, (skin_algo)k, frame[k], f.value, c->body.pose_value,
				   c->pos, c->nrm, j);
	}
	return 0;
}


int compare_other_weights(compare_run *main_run, const compare_args *a)
{
	TOOL_STATE(compare_run, other);
	static compare_args oa;
	if (!main_run->body.rigged || a->bind.weights_path)
		return 0;
	oa = *a;
	oa.bind.weights_mesh = !a->bind.weights_mesh;
	oa.bind.force = 1;  /* the other weights are shown beside, whatever the gate says of them */
	oa.csv_name = oa.bind.weights_mesh ? "metrics_weights_mesh.csv" : "metrics_weights_computed.csv";
	fprintf(cli_note(), "%s: the clip again with the %s weights, for the side-by-side table\n", a->mesh,
		oa.bind.weights_mesh ? "mesh's own" : "computed");
	memset(&other->rep, 0, sizeof other->rep);
	if (compare_load_clip(other, &oa) < 0 || compare_measure_clip(other, &oa) < 0)
		return -1;
	main_run->rep.other_weights = other->rep.weights;
	main_run->rep.other_csv = oa.csv_name;
	main_run->rep.other_algo = other->rep.algo;
	/* runtime_skin keeps one body's vertices (a static block), now the other
	 * weights': the renders and the rest of the report are the main run's */
	const compare_run *m = main_run;
	return runtime_skin_init(&main_run->sk, &m->body.skel, &m->body.pose, &m->body.mesh, &m->body.weights,
			     m->rep.mesh_name);
}
