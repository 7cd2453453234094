/* skintool compare SKELETON.asf MOTION.amc [--mesh MESH.obj [bind options]] -o DIR
 *     [--renders N]
 * The paper's experiment on any clip: skins every frame with LBS, DQBS and
 * fixed-point DQBS, measures them as `skintool metrics` does (cli_measure.h)
 * plus per joint region, and writes DIR/index.html (a static page),
 * DIR/metrics.csv, charts of the series over time, the synthetic twist and
 * bend scenes next to their analytic values, and LBS | DQBS renders of the
 * frames where LBS collapses most compared with DQBS. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "clock.h"
#include "cli_bind_args.h"
#include "cli_common.h"
#include "measure.h"
#include "report.h"
#include "report_chart.h"
#include "report_render.h"
#include "cli_skin.h"
#include "skin_overlap.h"
#include "skintool_cmds.h"

#define COMPARE_USAGE "usage: skintool compare SKELETON.asf MOTION.amc [--mesh MESH.obj " \
	BIND_ARGS_USAGE "] -o DIR [--renders N]\n"
#define NALGO SKIN_ALGO_COUNT
#define STORE_MAX 65536         /* frames kept for the charts (longer clips: every k-th) */
#define REPORT_IMG_W 1200
#define REPORT_IMG_H 600
#define OVERLAP_GRID 256
#define OVERLAP_HITS (1 << 22)

typedef struct compare_args {
	bind_args bind;
	const char *asf, *amc, *mesh, *out;
	long renders;
} compare_args;

/* One frame's figures for one algorithm, as kept for the charts. */
typedef struct frame_stats {
	float vol, rmin, rmax;
	float reg_min[REGION_COUNT], reg_max[REGION_COUNT];
} frame_stats;

typedef struct compare_run {
	bound_body body;
	cli_skin sk;
	measure_state meas;
	report rep;
	int joint[SKP_MAX_VERTS], region[SKP_MAX_VERTS];
	float pos[3 * SKP_MAX_VERTS], nrm[3 * SKP_MAX_VERTS];
	float ratio[NALGO][SKP_MAX_VERTS];
	/* the kept frames */
	int stride, kept;
	long frame[STORE_MAX];
	frame_stats st[NALGO][STORE_MAX];
	float rel[STORE_MAX];         /* LBS - DQBS at the worst vertex */
	int rel_vertex[STORE_MAX];
	float floor_y;
	FILE *csv;
	char path[4096];
} compare_run;

static const char *const algo_label[NALGO] = { "LBS", "DQBS", "DQBS fixed" };

static int parse_one(compare_args *a, int argc, char **argv, int *i)
{
	const char *opt = argv[*i];
	int r = bind_args_parse(&a->bind, argc, argv, i);
	if (r != 0)
		return r < 0 ? -1 : 0;
	if (!strcmp(opt, "--mesh") || !strcmp(opt, "-o") || !strcmp(opt, "--renders")) {
		if (*i + 1 >= argc) {
			fprintf(stderr, "skintool compare: %s needs a value\n", opt);
			return -1;
		}
		const char *val = argv[++*i];
		if (!strcmp(opt, "--mesh"))
			a->mesh = val;
		else if (!strcmp(opt, "-o"))
			a->out = val;
		else if (cli_parse_long(opt, val, &a->renders) < 0)
			return -1;
		return 0;
	}
	if (opt[0] == '-' && opt[1]) {
		fprintf(stderr, "skintool compare: unknown option '%s'\n", opt);
		return -1;
	}
	const char **slot = !a->asf ? &a->asf : !a->amc ? &a->amc : NULL;
	if (!slot) {
		fprintf(stderr, "skintool compare: unexpected argument '%s'\n", opt);
		return -1;
	}
	*slot = opt;
	return 0;
}

static int parse_args(compare_args *a, int argc, char **argv)
{
	memset(a, 0, sizeof *a);
	bind_args_init(&a->bind);
	a->renders = 4;
	for (int i = 0; i < argc; i++)
		if (parse_one(a, argc, argv, &i) < 0)
			return -1;
	if (!a->asf || !a->amc || !a->out) {
		fputs(COMPARE_USAGE, stderr);
		return -1;
	}
	if (a->renders < 0 || a->renders > REPORT_MAX_STILLS) {
		fprintf(stderr, "skintool compare: --renders takes 0 to %d, got %ld\n", REPORT_MAX_STILLS,
			a->renders);
		return -1;
	}
	if (!a->mesh && (a->bind.group || a->bind.fit || a->bind.pose_path)) {
		fprintf(stderr, "skintool compare: --group, --fit and --bind-pose need --mesh\n");
		return -1;
	}
	return 0;
}

static const char *basename_of(const char *path)
{
	const char *s = strrchr(path, '/');
	return s ? s + 1 : path;
}

/* ---- the synthetic scenes ------------------------------------------- */

static int measure_scenes(compare_run *c)
{
	static skin_scene sc;
	static skel_pose pose;
	static const int angles[REPORT_ANGLES] = { 45, 90, 135, 180 };
	report *r = &c->rep;
	skin_scene_build(&sc);
	if (cli_skin_init(&c->sk, &sc.skel, &sc.bind, &sc.mesh, &sc.weights, "scene") < 0 ||
	    measure_init(&c->meas, &sc.mesh, &sc.bind, sc.skel.count, "scene") < 0)
		return -1;
	r->scene_count = 0;
	for (int k = 0; k < SKIN_SCENE_KIND_COUNT; k++)
		for (int i = 0; i < REPORT_ANGLES; i++) {
			report_scene *s = &r->scene[r->scene_count++];
			s->kind = (skin_scene_kind)k;
			s->angle_deg = angles[i];
			/* as skintool metrics --scene computes the angle */
			double deg = angles[i];
			skin_scene_pose(&sc, s->kind, (float)(deg * (3.14159265358979323846 / 180.0)), &pose);
			cli_skin_pose(&c->sk, &pose);
			measure_pose(&c->meas, &c->sk.pose);
			for (int a = 0; a < NALGO; a++) {
				cli_skin_run(&c->sk, (skin_algo)a, c->pos, c->nrm);
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
		}
		s->vol_dev = -1.0;
		s->vol_dev_frame = -1;
	}
	extreme_init(&r->rel_min, INFINITY);
}

static void set_extreme(compare_run *c, report_extreme *e, double value, long frame, int vertex)
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

static void summarise(compare_run *c, long frame, int a, const measure_row *row,
		      const frame_stats *st, const int *at_min, const int *at_max)
{
	report_algo *s = &c->rep.algo[a];
	double dev = fabs(1.0 - row->volume_ratio);
	if (row->volume_ratio < s->vol_min.value)
		set_extreme(c, &s->vol_min, row->volume_ratio, frame, -1);
	if (row->volume_ratio > s->vol_max.value)
		set_extreme(c, &s->vol_max, row->volume_ratio, frame, -1);
	if (dev > s->vol_dev)
		s->vol_dev = dev, s->vol_dev_frame = frame;
	if (row->radius.counted && row->radius.min < s->rad_min.value)
		set_extreme(c, &s->rad_min, row->radius.min, frame, row->worst_vertex);
	if (row->radius.counted && row->radius.max > s->rad_max.value) {
		/* the largest ratio's vertex is not tracked by the shared row */
		set_extreme(c, &s->rad_max, row->radius.max, frame, -1);
	}
	for (int g = 0; g < REGION_COUNT; g++) {
		if (at_min[g] < 0)
			continue;
		if (!(st->reg_min[g] >= s->reg_min[g].value))
			set_extreme(c, &s->reg_min[g], st->reg_min[g], frame, at_min[g]);
		if (!(st->reg_max[g] <= s->reg_max[g].value))
			set_extreme(c, &s->reg_max[g], st->reg_max[g], frame, at_max[g]);
	}
}

/* The joint-region vertex where LBS is thinnest compared with DQBS:
 * min(LBS ratio, 1) - min(DQBS ratio, 1). Contact with another limb
 * shrinks both alike and DQBS's bulges are no collapse, so what remains
 * is LBS's own collapse. */
static float lbs_vs_dqbs(const compare_run *c, int *vertex)
{
	const float *l = c->ratio[SKIN_LBS], *d = c->ratio[SKIN_DQBS];
	float best = INFINITY;
	*vertex = -1;
	for (int v = 0; v < c->rep.vert_count; v++) {
		if (c->region[v] < 0 || isnan(l[v]) || isnan(d[v]))
			continue;
		float x = fminf(l[v], 1.0f) - fminf(d[v], 1.0f);
		if (x < best)
			best = x, *vertex = v;
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
		cli_skin_run(&c->sk, (skin_algo)a, c->pos, c->nrm);
		row[a] = measure_skinned(&c->meas, c->pos, c->ratio[a]);
		st[a].vol = (float)row[a].volume_ratio;
		st[a].rmin = row[a].radius.min;
		st[a].rmax = row[a].radius.max;
		region_ranges(c, c->ratio[a], &st[a], at_min, at_max);
		print_row(c, frame, a, &row[a], &st[a]);
		summarise(c, frame, a, &row[a], &st[a], at_min, at_max);
		if (a == SKIN_DQBS && isnan(c->floor_y)) {
			c->floor_y = INFINITY;
			for (int v = 0; v < c->rep.vert_count; v++)
				c->floor_y = fminf(c->floor_y, c->pos[3 * v + 1]);
		}
	}
	int v;
	float rel = lbs_vs_dqbs(c, &v);
	if (v >= 0 && rel < c->rep.rel_min.value)
		set_extreme(c, &c->rep.rel_min, rel, frame, v);
	if (!keep || c->kept >= STORE_MAX)
		return;
	int k = c->kept++;
	c->frame[k] = frame;
	for (int a = 0; a < NALGO; a++)
		c->st[a][k] = st[a];
	c->rel[k] = v >= 0 ? rel : NAN;
	c->rel_vertex[k] = v;
}

static void progress(long done, long total, uint64_t t0, int final)
{
	static uint64_t last;
	uint64_t now = clock_now_ns();
	if (!final && now - last < 200000000u)
		return;
	last = now;
	int tty = isatty(2), width = 40, fill = total > 0 ? (int)(width * done / total) : width;
	if (!tty && !final)
		return;
	char bar[64];
	for (int i = 0; i < width; i++)
		bar[i] = i < fill ? '#' : '.';
	bar[width] = '\0';
	double secs = (double)(now - t0) * 1e-9;
	fprintf(stderr, "%scompare [%s] %3ld%% frame %ld/%ld %.1f s%s", tty ? "\r" : "", bar,
		total > 0 ? 100 * done / total : 100, done, total, secs, final ? "\n" : "");
}

static long count_frames(const compare_args *a, const skel *s)
{
	static cli_motion mo;
	static amc_frame f;
	long n = 0;
	int rc;
	if (cli_motion_open(&mo, a->amc, s) < 0)
		return -1;
	while ((rc = cli_motion_next(&mo, &f)) > 0)
		n++;
	cli_motion_close(&mo);
	if (rc < 0)
		return -1;
	if (n == 0)
		fprintf(stderr, "%s: no frames\n", a->amc);
	return n ? n : -1;
}

static int open_csv(compare_run *c, const compare_args *a)
{
	snprintf(c->path, sizeof c->path, "%s/metrics.csv", a->out);
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

static int load_clip(compare_run *c, const compare_args *a)
{
	report *r = &c->rep;
	const char *what = a->mesh ? a->mesh : GENERATED_BODY;
	if (bind_args_load(&a->bind, a->asf, a->mesh, &c->body) < 0 ||
	    cli_skin_init(&c->sk, &c->body.skel, &c->body.pose, &c->body.mesh, &c->body.weights, what) < 0 ||
	    measure_init(&c->meas, &c->body.mesh, &c->body.pose, c->body.skel.count, what) < 0)
		return -1;
	r->skel = &c->body.skel;
	r->mesh_name = what;
	r->balanced = c->body.balanced;
	r->weights = !c->body.automatic ? "read from the weights file" :
		     c->body.balanced ? "automatic, volume-balanced" : "automatic (the paper's rule alone)";
	r->vert_count = c->body.mesh.vert_count;
	r->tri_count = c->body.mesh.tri_count;
	report_classify(&c->body.skel, &c->body.pose, c->meas.bind_xyz, r->vert_count, c->joint, c->region);
	r->measured = 0;
	for (int v = 0; v < r->vert_count; v++) {
		int measured = c->meas.rest_dist[v] > c->meas.min_rest;
		r->measured += measured;
		if (c->region[v] >= 0 && measured)
			r->region_verts[c->region[v]]++;
	}
	return 0;
}

static int measure_clip(compare_run *c, const compare_args *a)
{
	static cli_motion mo;
	static amc_frame f;
	report *r = &c->rep;
	long total = count_frames(a, &c->body.skel);
	if (total < 0 || open_csv(c, a) < 0 || cli_motion_open(&mo, a->amc, &c->body.skel) < 0)
		return -1;
	c->stride = (int)((total + STORE_MAX - 1) / STORE_MAX);
	c->kept = 0;
	c->floor_y = NAN;
	reset_summary(r);
	uint64_t t0 = clock_now_ns();
	long n = 0;
	int rc;
	while ((rc = cli_motion_next(&mo, &f)) > 0) {
		cli_skin_frame(&c->sk, f.value);
		measure_frame(c, f.number, n % c->stride == 0);
		progress(++n, total, t0, 0);
	}
	cli_motion_close(&mo);
	progress(n, total, t0, 1);
	r->frames = n;
	r->seconds = (double)(clock_now_ns() - t0) * 1e-9;
	int bad = ferror(c->csv);
	if (fclose(c->csv) != 0 || bad) {
		fprintf(stderr, "%s: write failed\n", c->path);
		return -1;
	}
	return rc < 0 ? -1 : 0;
}

/* ---- charts --------------------------------------------------------- */

static const rgba8 algo_color[NALGO] = { { 214, 69, 65, 255 }, { 38, 110, 190, 255 },
					 { 46, 160, 90, 255 } };

static chart_series series(int a, const char *label, const float *y, int dashed)
{
	chart_series s = { label, y, algo_color[a], a == SKIN_DQBS_FIXED ? 1.5f : 2.0f,
			   a == SKIN_DQBS_FIXED || dashed };
	return s;
}

/* Pulls one field of the kept frames into a plain series. */
static void column(const compare_run *c, int a, int field, int region, float *out)
{
	for (int k = 0; k < c->kept; k++) {
		const frame_stats *s = &c->st[a][k];
		out[k] = field == 0 ? s->vol : field == 1 ? s->rmin : field == 2 ? s->rmax
			 : field == 3 ? s->reg_min[region] : s->reg_max[region];
	}
}

static int write_chart(compare_run *c, const char *dir, const char *png, const char *title,
		       const char *caption, chart *ch)
{
	report *r = &c->rep;
	snprintf(c->path, sizeof c->path, "%s/%s", dir, png);
	if (chart_write_png(c->path, ch, 1000, 320) < 0)
		return -1;
	report_chart *rc = &r->chart[r->chart_count++];
	snprintf(rc->png, sizeof rc->png, "%s", png);
	rc->title = title;
	rc->caption = caption;
	return 0;
}

static int write_charts(compare_run *c, const char *dir)
{
	static float y[2 * NALGO][STORE_MAX];
	static const char *const titles[3] = { "VOLUME RATIO", "MIN RADIUS RATIO", "MAX RADIUS RATIO" };
	static const char *const captions[3] = {
		"Enclosed volume over the volume as bound (1 = kept). LBS loses volume at every bent or twisted joint.",
		"Smallest ratio over all vertices of the distance to the nearest posed bone over the same distance as bound: where the skin collapses (contact with another limb lowers it for every algorithm alike).",
		"Largest ratio: where the skin swells (DQBS bulges a little at bends instead of collapsing).",
	};
	static char region_title[REGION_COUNT][64], region_png[REGION_COUNT][32];
	chart ch;
	for (int f = 0; f < 3; f++) {
		memset(&ch, 0, sizeof ch);
		ch.title = titles[f];
		ch.x_label = "FRAME";
		ch.x = c->frame;
		ch.n = c->kept;
		ch.ref_y = 1.0f;
		for (int a = 0; a < NALGO; a++) {
			column(c, a, f, 0, y[a]);
			ch.series[ch.series_count++] = series(a, algo_label[a], y[a], 0);
		}
		static const char *const pngs[3] = { "volume.png", "radius_min.png", "radius_max.png" };
		if (write_chart(c, dir, pngs[f], titles[f], captions[f], &ch) < 0)
			return -1;
	}
	for (int g = 0; g < REGION_COUNT; g++) {
		if (!c->rep.region_verts[g])
			continue;
		memset(&ch, 0, sizeof ch);
		snprintf(region_title[g], sizeof region_title[g], "%s: MIN AND MAX RADIUS RATIO",
			 report_region_name(g));
		snprintf(region_png[g], sizeof region_png[g], "region_%s.png", report_region_name(g));
		ch.title = region_title[g];
		ch.x_label = "FRAME";
		ch.x = c->frame;
		ch.n = c->kept;
		ch.ref_y = 1.0f;
		static const char *const mins[NALGO] = { "LBS MIN", "DQBS MIN", "FIXED MIN" };
		for (int a = 0; a < NALGO; a += 1) {
			if (a == SKIN_DQBS_FIXED)
				continue; /* within 1e-4 of DQBS: two lines would hide each other */
			column(c, a, 3, g, y[2 * a]);
			column(c, a, 4, g, y[2 * a + 1]);
			ch.series[ch.series_count++] = series(a, mins[a], y[2 * a], 0);
		}
		for (int a = 0; a < SKIN_DQBS_FIXED; a++) {
			chart_series s = series(a, a ? "DQBS MAX" : "LBS MAX", y[2 * a + 1], 1);
			s.width = 1.5f;
			ch.series[ch.series_count++] = s;
		}
		if (write_chart(c, dir, region_png[g], region_title[g],
				"Solid: the smallest radius ratio of the region's vertices; dashed: the largest.", &ch) < 0)
			return -1;
	}
	return 0;
}

/* ---- the worst frames ----------------------------------------------- */

/* The kept frames with the most negative LBS - DQBS, at least sep frames
 * apart, worst first. */
static void pick_stills(compare_run *c, int want)
{
	report *r = &c->rep;
	long sep = r->frames / 16 > 60 ? 60 : r->frames / 16 < 1 ? 1 : r->frames / 16;
	r->still_count = 0;
	while (r->still_count < want) {
		int best = -1;
		for (int k = 0; k < c->kept; k++) {
			if (!(c->rel[k] < 0.0f) || (best >= 0 && !(c->rel[k] < c->rel[best])))
				continue;
			int near = 0;
			for (int i = 0; i < r->still_count; i++)
				near |= labs(c->frame[k] - r->still[i].frame) < sep;
			if (!near)
				best = k;
		}
		if (best < 0)
			break;
		report_still *s = &r->still[r->still_count++];
		memset(s, 0, sizeof *s);
		s->frame = c->frame[best];
		set_extreme(c, &s->rel, c->rel[best], s->frame, c->rel_vertex[best]);
		s->vertex = c->rel_vertex[best];
	}
}

static int render_stills(compare_run *c, const compare_args *a)
{
	static report_view view;
	static amc_frame f;
	report *r = &c->rep;
	char hud0[96], hud1[96];
	if (r->still_count == 0)
		return 0;
	if (report_view_open(&view, &c->sk, &c->body.mesh, c->floor_y, REPORT_IMG_W, REPORT_IMG_H) < 0) {
		r->render_note = "no headless display could be opened (surfaceless EGL, OSMesa)";
		return 0;
	}
	int rc = 0;
	for (int i = 0; i < r->still_count && rc == 0; i++) {
		report_still *s = &r->still[i];
		if (cli_read_frame(a->amc, &c->body.skel, s->frame, &f) < 0) {
			rc = -1;
			break;
		}
		cli_skin_frame(&c->sk, f.value);
		/* the two ratios at the marked vertex, for the caption */
		measure_pose(&c->meas, &c->sk.pose);
		for (int k = 0; k < 2; k++) {
			cli_skin_run(&c->sk, (skin_algo)k, c->pos, c->nrm);
			measure_skinned(&c->meas, c->pos, c->ratio[k]);
		}
		s->lbs_ratio = c->ratio[SKIN_LBS][s->vertex];
		s->dqbs_ratio = c->ratio[SKIN_DQBS][s->vertex];
		vec3 joint = c->sk.pose.head[s->rel.joint >= 0 ? s->rel.joint : 0];
		snprintf(hud0, sizeof hud0, "%s  FRAME %ld", r->clip, s->frame);
		snprintf(hud1, sizeof hud1, "RING: %s HEAD (%s)",
			 s->rel.joint >= 0 ? c->body.skel.bone[s->rel.joint].name : "?",
			 report_region_name(s->rel.region));
		snprintf(s->full_png, sizeof s->full_png, "worst_%d.png", i + 1);
		snprintf(s->close_png, sizeof s->close_png, "worst_%d_closeup.png", i + 1);
		snprintf(c->path, sizeof c->path, "%s/%s", a->out, s->full_png);
		rc = report_view_compare(&view, &c->sk, joint, 0, hud0, hud1, c->path);
		snprintf(c->path, sizeof c->path, "%s/%s", a->out, s->close_png);
		if (rc == 0)
			rc = report_view_compare(&view, &c->sk, joint, 1, hud0, hud1, c->path);
		s->rendered = rc == 0;
	}
	report_view_close(&view);
	return rc;
}

/* How much of the body, posed by values and skinned with DQBS, is inside
 * two of its parts at once (a thigh pressed into the belly), which the
 * signed volume counts twice and the space the body takes up once. */
static void measure_overlap(compare_run *c, const float *values)
{
	static int ray_start[OVERLAP_GRID * OVERLAP_GRID + 1];
	static float hit_z[OVERLAP_HITS];
	static signed char hit_dir[OVERLAP_HITS];
	static const skin_overlap_work work = { OVERLAP_GRID, OVERLAP_HITS, ray_start, hit_z, hit_dir };
	if (!(c->meas.rest_volume > 0.0))
		return;
	cli_skin_frame(&c->sk, values);
	cli_skin_run(&c->sk, SKIN_DQBS, c->pos, c->nrm);
	const mesh *m = &c->body.mesh;
	int ok;
	double excess = skin_mesh_overlap(c->pos, m->vert_count, (const uint32_t (*)[3])m->tri, m->tri_count,
					  &work, &ok);
	if (ok)
		c->rep.dqbs_overlap = excess / c->meas.rest_volume;
}

/* Which bends carry LBS's worst loss and DQBS's largest deviation, and at
 * the latter the overlap: each frame read once. */
static int explain_volume(compare_run *c, const compare_args *a)
{
	static amc_frame f;
	const long frame[2] = { c->rep.algo[SKIN_LBS].vol_min.frame, c->rep.algo[SKIN_DQBS].vol_dev_frame };
	c->rep.dqbs_overlap = NAN;
	for (int k = 0; k < 2; k++) {
		report_joints *j = &c->rep.vol_joints[k];
		j->frame = -1;
		if (frame[k] < 0)
			continue;
		if (cli_read_frame(a->amc, &c->body.skel, frame[k], &f) < 0)
			return -1;
		if (k == SKIN_DQBS)
			measure_overlap(c, f.value);
		report_find_joints(&c->sk, &c->meas, (skin_algo)k, frame[k], f.value, c->body.pose_value,
				   c->pos, c->nrm, j);
	}
	return 0;
}

static int make_dir(const char *dir)
{
	if (mkdir(dir, 0755) != 0 && errno != EEXIST) {
		fprintf(stderr, "skintool compare: %s: %s\n", dir, strerror(errno));
		return -1;
	}
	return 0;
}

int cmd_compare(int argc, char **argv)
{
	static compare_args a;
	static compare_run c;
	static char clip[256];
	if (parse_args(&a, argc, argv) < 0 || make_dir(a.out) < 0)
		return 1;
	uint64_t t0 = clock_now_ns();
	memset(&c.rep, 0, sizeof c.rep);
	snprintf(clip, sizeof clip, "%s", basename_of(a.amc));
	char *dot = strrchr(clip, '.');
	if (dot)
		*dot = '\0';
	c.rep.asf = a.asf;
	c.rep.amc = a.amc;
	c.rep.clip = clip;
	if (measure_scenes(&c) < 0 || load_clip(&c, &a) < 0 || measure_clip(&c, &a) < 0)
		return 1;
	uint64_t t1 = clock_now_ns();
	pick_stills(&c, (int)a.renders);
	if (explain_volume(&c, &a) < 0 || render_stills(&c, &a) < 0 || write_charts(&c, a.out) < 0 || report_write_html(&c.rep, a.out) < 0)
		return 1;
	uint64_t t2 = clock_now_ns();
	fprintf(stderr, "%s: %ld frames x 3 algorithms, %d vertices: measured in %.2f s, renders, "
		"charts and page %.2f s, total %.2f s -> %s/index.html\n", a.amc, c.rep.frames,
		c.rep.vert_count, (double)(t1 - t0) * 1e-9, (double)(t2 - t1) * 1e-9,
		(double)(t2 - t0) * 1e-9, a.out);
	return 0;
}
