/* skintool compare's output part (compare.h): the charts of the kept
 * frames, and the LBS | DQBS pictures: the scenes at their strongest, the
 * worst frames whole, near where the two part most, and as the difference
 * view (report_render.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compare.h"
#include "rig_load.h"
#include "motion_file.h"
#include "report_chart.h"
#include "report_render.h"
#include "tool_state.h"

const char *const compare_algo_label[NALGO] = { "LBS", "DQBS", "DQBS fixed" };

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
			 : field == 3 ? s->reg_min[region] : field == 4 ? s->reg_max[region] : s->rvol[region];
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

/* A chart over the kept frames with the ratio 1 marked. */
static void chart_start(const compare_run *c, chart *ch, const char *title)
{
	memset(ch, 0, sizeof *ch);
	ch->title = title;
	ch->x_label = "FRAME";
	ch->x = c->frame;
	ch->n = c->kept;
	ch->ref_y = 1.0f;
}

static float chart_y[2 * NALGO][STORE_MAX];

/* Region g's smallest (solid) and largest (dashed) radius ratio. */
static int region_radius_chart(compare_run *c, const char *dir, int g)
{
	static char title[REGION_COUNT][64], png[REGION_COUNT][32];
	static const char *const mins[NALGO] = { "LBS MIN", "DQBS MIN", "FIXED MIN" };
	chart ch;
	snprintf(title[g], sizeof title[g], "%s: MIN AND MAX RADIUS RATIO", report_region_name(g));
	snprintf(png[g], sizeof png[g], "region_%s.png", report_region_name(g));
	chart_start(c, &ch, title[g]);
	/* DQBS fixed is within 1e-4 of DQBS: two lines would hide each other */
	for (int a = 0; a < SKIN_DQBS_FIXED; a++) {
		column(c, a, 3, g, chart_y[2 * a]);
		column(c, a, 4, g, chart_y[2 * a + 1]);
		ch.series[ch.series_count++] = series(a, mins[a], chart_y[2 * a], 0);
	}
	for (int a = 0; a < SKIN_DQBS_FIXED; a++) {
		chart_series s = series(a, a ? "DQBS MAX" : "LBS MAX", chart_y[2 * a + 1], 1);
		s.width = 1.5f;
		ch.series[ch.series_count++] = s;
	}
	return write_chart(c, dir, png[g], title[g],
			   "Solid: the smallest radius ratio of the region's vertices; dashed: the largest.", &ch);
}

/* Region g's volume around its joints (compare_region_volume.c). */
static int region_volume_chart(compare_run *c, const char *dir, int g)
{
	static char title[REGION_COUNT][64], png[REGION_COUNT][40];
	chart ch;
	snprintf(title[g], sizeof title[g], "%s: VOLUME AROUND THE JOINTS", report_region_name(g));
	snprintf(png[g], sizeof png[g], "region_%s_volume.png", report_region_name(g));
	chart_start(c, &ch, title[g]);
	for (int a = 0; a < SKIN_DQBS_FIXED; a++) {
		column(c, a, 5, g, chart_y[a]);
		ch.series[ch.series_count++] = series(a, compare_algo_label[a], chart_y[a], 0);
	}
	return write_chart(c, dir, png[g], title[g],
			   "The volume of the region's skin over its volume as bound (see \"Volume around each "
			   "joint\"): below 1 the joints collapse, above they bulge.", &ch);
}

/* The body's volume over time, then per joint region its radius ratios and
 * its volume. The global radius extremes stay in the CSV: contact between
 * limbs sets them, flat for every algorithm. */
int compare_write_charts(compare_run *c, const char *dir)
{
	chart ch;
	chart_start(c, &ch, "VOLUME RATIO");
	for (int a = 0; a < NALGO; a++) {
		column(c, a, 0, 0, chart_y[a]);
		ch.series[ch.series_count++] = series(a, compare_algo_label[a], chart_y[a], 0);
	}
	if (write_chart(c, dir, "volume.png", "VOLUME RATIO", "Enclosed volume over the volume as bound (1 = kept). "
			"LBS loses volume at every bent or twisted joint.", &ch) < 0)
		return -1;
	for (int g = 0; g < REGION_COUNT; g++)
		if (c->rep.region_verts[g] &&
		    (region_radius_chart(c, dir, g) < 0 || region_volume_chart(c, dir, g) < 0))
			return -1;
	return 0;
}

/* ---- the pictures ---------------------------------------------------- */

/* The pictures' view: megabytes (tool_state.h), kept between the scenes' and the stills' renders. */
static report_view *the_view(void)
{
	TOOL_STATE(report_view, view);
	return view;
}

static void keep_closeup(report_closeup *out, const report_part *p)
{
	out->joint = p->joint;
	snprintf(out->name, sizeof out->name, "%s", p->name);
	out->turn = p->turn;
	out->turn_deg = p->turn_deg;
	out->in_units = p->in_units;
	out->size_assumed = p->size_assumed;
	out->apart = p->in_units ? p->apart : p->apart * p->mm_per_unit;
}

/* The scene's row of the tables at the angle pictured. */
static const report_scene *scene_row(const report *r, scene_kind k, int angle)
{
	for (int i = 0; i < r->scene_count; i++)
		if (r->scene[i].kind == k && r->scene[i].angle_deg == angle)
			return &r->scene[i];
	return NULL;
}

/* The angle a scene is pictured at: the twist's largest in the tables
 * (at 180 degrees LBS pinches the joint to a point); the bend's deepest
 * short of 180 degrees, where the second bone would lie inside the first
 * and both bodies fold onto themselves, the bend itself out of sight. */
static int scene_angle(const report *r, scene_kind k)
{
	int best = 0;
	for (int i = 0; i < r->scene_count; i++)
		if (r->scene[i].kind == k && r->scene[i].angle_deg > best &&
		    (k == SCENE_TWIST || r->scene[i].angle_deg < 180))
			best = r->scene[i].angle_deg;
	return best;
}

/* The close-up of a scene shows the cross-fade and a little either side. */
#define SCENE_CLOSEUP_SPAN (1.5f * SCENE_BLEND)

int compare_render_scenes(compare_run *c, const compare_args *a)
{
	static skel_pose pose;
	static const char *const what[SCENE_KIND_COUNT] = { "TWISTED ABOUT ITS AXIS", "BENT" };
	report_view *view = the_view();
	const scene_rig *sc = &c->scene;
	report *r = &c->rep;
	char hud0[96];
	if (a->renders <= 0)
		return 0;
	/* the ground under the skin, which bulges out of the bend */
	if (report_view_open(view, &c->sk, &sc->mesh, NULL, -2.0f * SCENE_RADIUS, REPORT_IMG_W, REPORT_IMG_H) < 0) {
		r->render_note = "no headless display could be opened (surfaceless EGL, OSMesa)";
		return 0;
	}
	report_view_scene(view, SCENE_CLOSEUP_SPAN);
	int rc = 0;
	for (int k = 0; k < SCENE_KIND_COUNT && rc == 0; k++) {
		report_scene_still *s = &r->scene_still[k];
		memset(s, 0, sizeof *s);
		s->kind = (scene_kind)k;
		s->angle_deg = scene_angle(r, s->kind);
		const report_scene *row = scene_row(r, s->kind, s->angle_deg);
		if (!row)
			continue;
		s->lbs_rmin = row->rmin[SKIN_LBS];
		s->dqbs_rmin = row->rmin[SKIN_DQBS];
		s->dqbs_rmax = row->rmax[SKIN_DQBS];
		scene_pose(sc, s->kind, (float)(s->angle_deg * (3.14159265358979323846 / 180.0)), &pose);
		runtime_skin_pose(&c->sk, &pose);
		keep_closeup(&s->closeup, report_view_pose(view, &c->sk));
		snprintf(hud0, sizeof hud0, "%s SCENE: THE SECOND BONE %s %d DEG", s->kind == SCENE_TWIST ? "TWIST" : "BEND",
			 what[k], s->angle_deg);
		snprintf(s->png, sizeof s->png, "scene_%s.png", scene_name(s->kind));
		snprintf(c->path, sizeof c->path, "%s/%s", a->out, s->png);
		rc = report_view_write(view, &c->sk, REPORT_SHOT_BODY, hud0, "A CYLINDER OF RADIUS 0.2 ROUND TWO BONES OF LENGTH 1",
				       c->path);
		s->rendered = rc == 0;
	}
	report_view_close(view);
	return rc;
}

/* ---- the worst frames ----------------------------------------------- */

/* The kept frames with the most negative LBS - DQBS, at least sep frames
 * apart, worst first. */
/* The kept frame where LBS is thinnest against DQBS (in region g, or
 * anywhere for g < 0), at least sep frames from the stills so far. -1:
 * none. */
static int worst_kept(const compare_run *c, long sep, int g)
{
	const report *r = &c->rep;
	const float *rel = g >= 0 ? c->rel_region[g] : c->rel;
	int best = -1;
	for (int k = 0; k < c->kept; k++) {
		if (!(rel[k] < 0.0f) || (best >= 0 && !(rel[k] < rel[best])))
			continue;
		int near = 0;
		for (int i = 0; i < r->still_count; i++)
			near |= labs(c->frame[k] - r->still[i].frame) < sep;
		if (!near)
			best = k;
	}
	return best;
}

static void add_still(compare_run *c, int k, int g)
{
	report *r = &c->rep;
	report_still *s = &r->still[r->still_count++];
	int v = g >= 0 ? c->rel_region_vertex[g][k] : c->rel_vertex[k];
	memset(s, 0, sizeof *s);
	s->frame = c->frame[k];
	compare_set_extreme(c, &s->rel, g >= 0 ? c->rel_region[g][k] : c->rel[k], s->frame, v);
	s->vertex = v;
}

/* The frames to render: LBS's worst collapse against DQBS at each joint
 * region in turn, the region where it is worst first, then, when renders
 * are left, the next worst frames wherever they are. */
void compare_pick_stills(compare_run *c, int want)
{
	report *r = &c->rep;
	long sep = r->frames / 16 > 60 ? 60 : r->frames / 16 < 1 ? 1 : r->frames / 16;
	int done[REGION_COUNT] = { 0 };
	r->still_count = 0;
	while (r->still_count < want) {
		int best_g = -1, best_k = -1;
		float best = 0.0f;
		for (int g = 0; g < REGION_COUNT; g++) {
			int k = done[g] ? -1 : worst_kept(c, sep, g);
			if (k >= 0 && (best_k < 0 || c->rel_region[g][k] < best))
				best_g = g, best_k = k, best = c->rel_region[g][k];
		}
		if (best_k < 0)
			break;
		done[best_g] = 1;
		add_still(c, best_k, best_g);
	}
	while (r->still_count < want) {
		int k = worst_kept(c, sep, -1);
		if (k < 0)
			break;
		add_still(c, k, -1);
	}
}

int compare_render_stills(compare_run *c, const compare_args *a)
{
	static amc_frame f;
	report_view *view = the_view();
	report *r = &c->rep;
	char hud0[96], hud1[96], near0[128], near1[128];
	if (r->still_count == 0)
		return 0;
	rig_load_texture(a->mesh, &c->body); /* the stills only: drawn as skinplay would */
	if (report_view_open(view, &c->sk, &c->body.mesh, c->body.mesh.textured ? &c->body.texture : NULL, c->floor_y,
			     REPORT_IMG_W, REPORT_IMG_H) < 0) {
		r->render_note = "no headless display could be opened (surfaceless EGL, OSMesa)";
		return 0;
	}
	int rc = 0;
	for (int i = 0; i < r->still_count && rc == 0; i++) {
		report_still *s = &r->still[i];
		if (motion_read_frame(a->amc, &c->body.skel, s->frame, &f) < 0) {
			rc = -1;
			break;
		}
		runtime_skin_frame(&c->sk, f.value);
		const report_part *part = report_view_pose(view, &c->sk);
		keep_closeup(&s->closeup, part);
		/* the two ratios at the still's vertex, for the caption */
		measure_pose(&c->meas, &c->sk.pose);
		for (int k = 0; k < 2; k++)
			measure_skinned(&c->meas, view->pos[k], c->ratio[k]);
		s->lbs_ratio = c->ratio[SKIN_LBS][s->vertex];
		s->dqbs_ratio = c->ratio[SKIN_DQBS][s->vertex];
		snprintf(hud0, sizeof hud0, "%s  FRAME %ld", r->clip, s->frame);
		snprintf(hud1, sizeof hud1, "CLOSE-UP AND RING: WHERE LBS AND DQBS PART MOST");
		snprintf(near0, sizeof near0, "%s  FRAME %ld  %s", r->clip, s->frame, part->name);
		snprintf(near1, sizeof near1, "%s%s%s", part->note, part->note[0] ? ", " : "", part->effect);
		snprintf(s->full_png, sizeof s->full_png, "worst_%d.png", i + 1);
		snprintf(s->close_png, sizeof s->close_png, "worst_%d_closeup.png", i + 1);
		snprintf(s->diff_png, sizeof s->diff_png, "worst_%d_difference.png", i + 1);
		snprintf(c->path, sizeof c->path, "%s/%s", a->out, s->full_png);
		rc = report_view_write(view, &c->sk, REPORT_SHOT_BODY, hud0, hud1, c->path);
		snprintf(c->path, sizeof c->path, "%s/%s", a->out, s->close_png);
		if (rc == 0)
			rc = report_view_write(view, &c->sk, REPORT_SHOT_CLOSEUP, near0, near1, c->path);
		snprintf(c->path, sizeof c->path, "%s/%s", a->out, s->diff_png);
		if (rc == 0)
			rc = report_view_write(view, &c->sk, REPORT_SHOT_DIFFERENCE, hud0, NULL, c->path);
		s->rendered = rc == 0;
	}
	report_view_close(view);
	return rc;
}
