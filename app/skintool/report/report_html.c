/* index.html of skintool compare: one static page, no JavaScript, inline
 * CSS, every figure a PNG beside it. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli_inputs.h"
#include "report.h"
#include "report_html.h"

static const char *const algo_label[SKIN_ALGO_COUNT] = { "LBS", "DQBS", "DQBS fixed" };

static const char css[] =
	"body{margin:0;background:#eef0f3;color:#1f2328;"
	"font:15px/1.55 -apple-system,'Segoe UI',Roboto,'Helvetica Neue',Arial,sans-serif}\n"
	"main{max-width:1040px;margin:0 auto;padding:28px 32px 64px;background:#fff;"
	"box-shadow:0 0 0 1px #dde1e6}\n"
	"h1{font-size:27px;margin:0 0 2px;letter-spacing:-.01em}\n"
	"h2{font-size:19px;margin:40px 0 12px;padding-bottom:6px;border-bottom:2px solid #e6e9ee}\n"
	"h3{font-size:16px;margin:24px 0 6px}\n"
	".meta{color:#59636e;font-size:13.5px;margin:0}\n"
	".meta code{font-size:12.5px}\n"
	"table{border-collapse:collapse;width:100%;font-size:14px;margin:10px 0 4px}\n"
	"th,td{padding:7px 10px;border-bottom:1px solid #e6e9ee;text-align:right;vertical-align:top}\n"
	"th{background:#f5f6f8;font-weight:600;font-size:13px;color:#3d444d}\n"
	"th:first-child,td:first-child{text-align:left}\n"
	"td{font-variant-numeric:tabular-nums}\n"
	"td small{display:block;color:#6e7781;font-size:12px}\n"
	".verdict{margin:8px 0;padding:10px 14px;border-left:4px solid #9aa4af;background:#f7f8fa}\n"
	".verdict.yes{border-color:#2da44e}.verdict.no{border-color:#cf222e}\n"
	"td.past{color:#cf222e}\n"
	".verdict b{font-weight:600}\n"
	".swatch{display:inline-block;width:26px;height:0;border-top:3px solid;vertical-align:middle;"
	"margin:0 6px 0 16px}\n"
	".swatch.dash{border-top-style:dashed}\n"
	".legend{font-size:14px;margin:6px 0 0}\n"
	"figure{margin:18px 0 22px}\n"
	"figure img{display:block;width:100%;height:auto;border:1px solid #dde1e6;border-radius:4px}\n"
	"figcaption{font-size:13.5px;color:#444c56;margin-top:6px}\n"
	".pair{display:grid;grid-template-columns:1fr 1fr;gap:12px}\n"
	".pair .cell{font-size:13.5px;color:#444c56;margin:0;align-self:center}\n"
	".lbs{color:#d64541}.dqbs{color:#266ebe}.fixed{color:#2ea05a}\n"
	"dl{font-size:14px}dt{font-weight:600;margin-top:10px}dd{margin:2px 0 0 18px;color:#3d444d}\n"
	"code{font-family:'SFMono-Regular',Consolas,'Liberation Mono',monospace;font-size:13px;"
	"background:#f3f4f6;padding:1px 4px;border-radius:3px}\n";

/* "elbows (lradius)" */
static void put_where(FILE *f, const report *r, const report_extreme *e)
{
	fputs(report_region_name(e->region), f);
	if (e->joint >= 0) {
		fputs(" (", f);
		report_html_escape(f, report_html_joint(r, e->joint));
		fputc(')', f);
	}
}

/* Volume lost on the worst frame, in percent (0 when it never shrinks). */
static double loss_pct(const report_algo *a)
{
	return a->vol_min.value < 1.0 ? 100.0 * (1.0 - a->vol_min.value) : 0.0;
}

/* Where a gate figure was worst: the region's bone and the pose or frame. */
static void where(FILE *f, const char *region, const char *pose)
{
	fputs(" (", f);
	report_html_escape(f, region);
	fputs(", ", f);
	report_html_escape(f, pose);
	fputs(")", f);
}

/* Whether the skin tears: the bind's quality gate over its poses and the
 * clip (bind_gate.h). */
static void tears_paragraph(FILE *f, const report *r)
{
	const bind_gate_result *g = r->gate;
	fprintf(f, "<p class=\"meta\" id=\"tears\">Whether the skin tears (the bind's quality gate, DQBS, over %d "
		"range-of-motion poses and %ld frames of the clip): its worst edge reaches %.2f times its bind length",
		g->moves, g->frames, (double)g->stretch.value);
	where(f, r->gate_region, r->gate_where);
	fprintf(f, "; %d edges ever pass twice their length; the longest lengthening is %.2f%% of the skeleton's "
		"extent", g->doubled_edges, 100.0 * (double)g->grow.value);
	where(f, r->grow_region, r->grow_where);
	fputs(".</p>\n", f);
}

static void head(FILE *f, const report *r)
{
	fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
	      "<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\">\n<title>LBS vs DQBS: ",
	      f);
	report_html_escape(f, r->clip);
	fprintf(f, "</title>\n<style>\n%s</style>\n</head>\n<body>\n<main>\n", css);
	fputs("<h1>LBS vs DQBS on <code>", f);
	report_html_escape(f, r->clip);
	fputs("</code></h1>\n<p class=\"meta\">Skeleton <code>", f);
	report_html_escape(f, r->asf);
	fputs("</code>, motion <code>", f);
	report_html_escape(f, r->amc);
	fputs("</code>, mesh: ", f);
	report_html_escape(f, r->mesh_name);
	fprintf(f, " (%d vertices, %d triangles), weights %s. %ld frames, each skinned with LBS, DQBS and "
		"fixed-point DQBS and measured in %.2f s; the whole command, binding, renders, charts and this "
		"page included, took %.2f s. Numbers per frame: <a href=\"metrics.csv\">metrics.csv</a>.</p>\n",
		r->vert_count, r->tri_count, r->weights, r->frames, r->seconds, r->total_seconds);
	if (r->gate && r->gate->moves + r->gate->frames > 0)
		tears_paragraph(f, r);
}

/* A region's worst loss and largest gain of its own volume, in percent. */
static int region_volume(const report_algo *a, int g, double *loss, double *gain)
{
	if (isnan(a->rvol_min[g].value) || a->rvol_folded[g])
		return 0;
	*loss = 100.0 * (1.0 - fmin(a->rvol_min[g].value, 1.0));
	*gain = 100.0 * (fmax(a->rvol_max[g].value, 1.0) - 1.0);
	return 1;
}

/* Where DQBS wins (the skin around a joint loses less volume) and where it
 * loses (it swells more), region by region, with the figures. */
static void joint_verdicts(FILE *f, const report *r)
{
	const report_algo *l = &r->algo[SKIN_LBS], *d = &r->algo[SKIN_DQBS];
	int wins = 0, loses = 0;
	for (int pass = 0; pass < 2; pass++) {
		fprintf(f, "<p class=\"verdict\" id=\"verdict-%s\">%s", pass ? "dqbs-bulges" : "dqbs-keeps",
			pass ? "Where DQBS swells more than LBS: " : "Where DQBS keeps more volume than LBS: ");
		int n = 0;
		for (int g = 0; g < REGION_COUNT; g++) {
			double ll, lg, dl, dg;
			if (!region_volume(l, g, &ll, &lg) || !region_volume(d, g, &dl, &dg))
				continue;
			if (!pass && dl + 0.1 < ll)
				fprintf(f, "%s<b>%s</b> (loses %.1f%% against %.1f%%, LBS's worst at frame %ld)", n++ ? "; " : "",
					report_region_name(g), dl, ll, l->rvol_min[g].frame);
			if (pass && dg > lg + 0.1)
				fprintf(f, "%s<b>%s</b> (gains %.1f%% against %.1f%%, frame %ld)", n++ ? "; " : "",
					report_region_name(g), dg, lg, d->rvol_max[g].frame);
		}
		if (!n)
			fputs("none", f);
		*(pass ? &loses : &wins) = n;
		fputs(". <small>The volume of the skin around each joint region (below).</small></p>\n", f);
	}
	(void)wins, (void)loses;
}

static void region_volume_table(FILE *f, const report *r)
{
	fputs("<h2>Volume around each joint</h2>\n<table id=\"region-volume\">\n<tr><th>region</th>", f);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++)
		fprintf(f, "<th>%s worst loss</th><th>%s largest gain</th>", algo_label[a], algo_label[a]);
	fputs("</tr>\n", f);
	for (int g = 0; g < REGION_COUNT; g++) {
		fprintf(f, "<tr><td>%s</td>", report_region_name(g));
		for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
			double loss, gain;
			if (!region_volume(&r->algo[a], g, &loss, &gain)) {
				fprintf(f, "<td colspan=\"2\">%s</td>", r->algo[a].rvol_folded[g] ? "folded through "
					"its joint" : "&ndash;");
				continue;
			}
			fprintf(f, "<td>%.2f%%<small>frame %ld</small></td><td>%.2f%%<small>frame %ld</small></td>", loss,
				r->algo[a].rvol_min[g].frame, gain, r->algo[a].rvol_max[g].frame);
		}
		fputs("</tr>\n", f);
	}
	fputs("</table>\n<p class=\"meta\">Each region's skin (the vertices nearest to its joints) as a volume: "
	      "every triangle with the joint nearest to it makes a tetrahedron, posed with the posed joint, and "
	      "their sum is compared with the same sum as bound. A collapsing elbow or a candy-wrapper forearm "
	      "loses volume there; a bulging knee gains. Unlike the radius ratios, contact with another limb "
	      "does not move it. Where the skin folds through its joint in some frame (a deep knee bend, a "
	      "shrug, a hand turned past its limits) the sum goes through zero and has no meaning: such a "
	      "region shows no figure.</p>\n", f);
}

static void collapse_verdict(FILE *f, const report *r)
{
	if (r->rel_min.frame < 0)
		return;
	fprintf(f, "<p class=\"verdict\" id=\"verdict-collapse\">Where LBS collapses most compared "
		"with DQBS: at frame %ld a vertex keeps <b>%.3f less</b> of its radius with LBS, ",
		r->rel_min.frame, -r->rel_min.value);
	put_where(f, r, &r->rel_min);
	fputs(".</p>\n", f);
}

/* What the volume was measured on, when not the whole mesh. */
static void volume_basis(FILE *f, const report *r)
{
	const parts_summary *p = &r->parts;
	if (p->counted == p->parts)
		return;
	fprintf(f, " <span id=\"volume-parts\">Measured on the mesh's %d outer closed part%s of %d", p->counted,
		p->counted == 1 ? "" : "s", p->parts);
	if (p->inner)
		fprintf(f, "; %d inside %s (joint balls, eyes, teeth) left out", p->inner,
			p->counted == 1 ? "it" : "them");
	if (p->open)
		fprintf(f, "; %d open (%d edges meeting one triangle) left out", p->open, p->open_edges);
	fputs(".</span>", f);
}

/* A mesh with no closed part encloses no volume: both volume verdicts say
 * so instead of a yes or no. */
static void verdicts_unmeasured(FILE *f, const report *r)
{
	fprintf(f, "<p class=\"verdict na\" id=\"verdict-dqbs-volume\">DQBS keeps the volume within 1%% on every "
		"frame: <b>not measured</b> &mdash; no part of the mesh is closed (%d edges meet one triangle only), "
		"so it encloses no volume to keep; the radius ratios below still hold.</p>\n", r->parts.open_edges);
	fputs("<p class=\"verdict na\" id=\"verdict-lbs-loss\">LBS's worst frame loses more volume than DQBS's: "
	      "<b>not measured</b> &mdash; the mesh encloses no volume.</p>\n", f);
}

static void verdicts(FILE *f, const report *r)
{
	const report_algo *l = &r->algo[SKIN_LBS], *d = &r->algo[SKIN_DQBS];
	if (!r->volume_closed) {
		verdicts_unmeasured(f, r);
		joint_verdicts(f, r);
		collapse_verdict(f, r);
		return;
	}
	int within = d->vol_dev <= 0.01;
	int loses_more = loss_pct(l) > loss_pct(d);
	double dq_dev_signed = 0;
	/* the sign of DQBS's worst deviation: a loss or a gain (bulge) */
	dq_dev_signed = fabs(1.0 - d->vol_min.value) >= fabs(d->vol_max.value - 1.0)
				? 100.0 * (d->vol_min.value - 1.0) : 100.0 * (d->vol_max.value - 1.0);
	fprintf(f, "<p class=\"verdict %s\" id=\"verdict-dqbs-volume\">DQBS keeps the volume within 1%% "
		"on every frame: <b>%s</b> &mdash; its largest deviation is %+.2f%% (frame %ld%s)",
		within ? "yes" : "no", within ? "yes" : "no", dq_dev_signed, d->vol_dev_frame,
		dq_dev_signed > 0 ? ", a gain: DQBS bulges at bends" : "");
	if (r->vol_joints[SKIN_DQBS].count > 0)
		fprintf(f, "; the largest share, %+.2f%%, from the bend of <code>%s</code> (<a href=\"#joints\">"
			"where the volume goes</a>)", 100.0 * r->vol_joints[SKIN_DQBS].joint[0].share,
			r->skel->bone[r->vol_joints[SKIN_DQBS].joint[0].bone].name);
	if (r->dqbs_overlap >= 0.0005 && r->parts.parts == 1)
		fprintf(f, ". In that pose the skin also passes through itself: "
			"<span id=\"dqbs-overlap\">%.2f%%</span> of the bound volume lies inside two parts at "
			"once, which the signed volume counts twice, as the flesh of both; the space the body "
			"takes up is %+.2f%%", 100.0 * r->dqbs_overlap, dq_dev_signed - 100.0 * r->dqbs_overlap);
	fputs(".", f);
	volume_basis(f, r);
	fputs("</p>\n", f);
	if (loss_pct(l) < 0.005 && loss_pct(d) < 0.005)
		fprintf(f, "<p class=\"verdict na\" id=\"verdict-lbs-loss\">LBS's worst frame loses more volume "
			"than DQBS's: <b>neither loses volume</b> &mdash; on no frame does either keep less than the "
			"bound volume (LBS's smallest %+.2f%%, frame %ld; DQBS's %+.2f%%, frame %ld).</p>\n",
			100.0 * (l->vol_min.value - 1.0), l->vol_min.frame, 100.0 * (d->vol_min.value - 1.0),
			d->vol_min.frame);
	else {
		fprintf(f, "<p class=\"verdict %s\" id=\"verdict-lbs-loss\">LBS's worst frame loses more volume "
			"than DQBS's: <b>%s</b> &mdash; LBS loses up to %.2f%% (frame %ld), DQBS at most %.2f%%",
			loses_more ? "yes" : "no", loses_more ? "yes" : "no", loss_pct(l), l->vol_min.frame,
			loss_pct(d));
		if (d->vol_min.value < 1.0)
			fprintf(f, " (frame %ld)", d->vol_min.frame);
		fputs(".</p>\n", f);
	}
	joint_verdicts(f, r);
	collapse_verdict(f, r);
}

/* The smallest region minimum, or NULL when no region was measured. */
static const report_extreme *worst_region(const report_algo *a)
{
	const report_extreme *w = NULL;
	for (int g = 0; g < REGION_COUNT; g++)
		if (!isnan(a->reg_min[g].value) && (!w || a->reg_min[g].value < w->value))
			w = &a->reg_min[g];
	return w;
}

static void summary_table(FILE *f, const report *r)
{
	fputs("<table id=\"summary\">\n<tr><th>algorithm</th><th>worst volume loss</th>"
	      "<th>largest volume gain</th><th>worst collapse<br>(min radius ratio)</th>"
	      "<th>where</th><th>worst collapse in<br>a joint region</th><th>largest swelling<br>"
	      "(max radius ratio)</th></tr>\n", f);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		const report_algo *s = &r->algo[a];
		fprintf(f, "<tr><td>%s</td><td>%.2f%%<small>frame %ld</small></td>", algo_label[a],
			loss_pct(s), s->vol_min.frame);
		fprintf(f, "<td>%.2f%%<small>frame %ld</small></td>",
			s->vol_max.value > 1.0 ? 100.0 * (s->vol_max.value - 1.0) : 0.0, s->vol_max.frame);
		fprintf(f, "<td>%.4f<small>frame %ld</small></td><td>", s->rad_min.value, s->rad_min.frame);
		put_where(f, r, &s->rad_min);
		const report_extreme *w = worst_region(s);
		if (w) {
			fprintf(f, "</td><td>%.4f<small>frame %ld, ", w->value, w->frame);
			put_where(f, r, w);
			fputs("</small>", f);
		} else {
			fputs("</td><td>&ndash;", f);
		}
		fprintf(f, "</td><td>%.4f<small>frame %ld</small></td></tr>\n", s->rad_max.value,
			s->rad_max.frame);
	}
	fputs("</table>\n<p class=\"meta\">Volume: the closed mesh's signed volume over the volume as bound. Radius "
	      "ratio: a vertex's distance to the nearest posed bone over the same distance as bound; "
	      "the minimum over all vertices also drops where a limb touches another one (for every "
	      "algorithm alike), which is why the renders below are chosen by the difference between "
	      "LBS and DQBS at the same vertex.</p>\n", f);
}

static void weights_row(FILE *f, const char *algo, const char *weights, const report_algo *s)
{
	fprintf(f, "<tr><td>%s</td><td>", algo);
	report_html_escape(f, weights);
	fprintf(f, "</td><td>%.2f%%<small>frame %ld</small></td><td>%.2f%%<small>frame %ld</small></td>"
		"<td>%.4f<small>frame %ld</small></td><td>%.4f<small>frame %ld</small></td></tr>\n",
		loss_pct(s), s->vol_min.frame, s->vol_max.value > 1.0 ? 100.0 * (s->vol_max.value - 1.0) : 0.0,
		s->vol_max.frame, s->rad_min.value, s->rad_min.frame, s->rad_max.value, s->rad_max.frame);
}

/* A rigged mesh: its own weights and computed ones, algorithm by algorithm. */
static void weights_table(FILE *f, const report *r)
{
	if (!r->other_algo)
		return;
	fputs("<h2>The mesh's own weights next to computed ones</h2>\n<table id=\"weights\">\n<tr><th>algorithm"
	      "</th><th>weights</th><th>worst volume loss</th><th>largest volume gain</th><th>worst collapse<br>"
	      "(min radius ratio)</th><th>largest swelling<br>(max radius ratio)</th></tr>\n", f);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		weights_row(f, algo_label[a], r->weights, &r->algo[a]);
		weights_row(f, algo_label[a], r->other_weights, &r->other_algo[a]);
	}
	fputs("</table>\n<p class=\"meta\">The same clip skinned with the artist's weights from the mesh file and "
	      "with the weights skintool computes (the paper's rule), on the same skeleton in the same bind "
	      "pose; the other run's frames are in <a href=\"", f);
	report_html_escape(f, r->other_csv);
	fputs("\">", f);
	report_html_escape(f, r->other_csv);
	fputs("</a>, in the columns of metrics.csv.</p>\n", f);
}

static void region_table(FILE *f, const report *r)
{
	fputs("<h2>Joint regions</h2>\n<table id=\"regions\">\n<tr><th>region</th><th>vertices</th>", f);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++)
		fprintf(f, "<th>%s min</th>", algo_label[a]);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++)
		fprintf(f, "<th>%s max</th>", algo_label[a]);
	fputs("</tr>\n", f);
	for (int g = 0; g < REGION_COUNT; g++) {
		fprintf(f, "<tr><td>%s</td><td>%d</td>", report_region_name(g), r->region_verts[g]);
		for (int m = 0; m < 2; m++)
			for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
				const report_extreme *e = m ? &r->algo[a].reg_max[g] : &r->algo[a].reg_min[g];
				if (isnan(e->value)) {
					fputs("<td>&ndash;</td>", f);
					continue;
				}
				fprintf(f, "<td>%.4f<small>frame %ld", e->value, e->frame);
				if (e->joint >= 0) {
					fputs(", ", f);
					report_html_escape(f, report_html_joint(r, e->joint));
				}
				fputs("</small></td>", f);
			}
		fputs("</tr>\n", f);
	}
	fputs("</table>\n<p class=\"meta\">Smallest and largest radius ratio over the clip of the "
	      "vertices in each region, with the frame and the joint nearest to the vertex.</p>\n", f);
}

static void charts(FILE *f, const report *r)
{
	fputs("<h2>Over time</h2>\n<p class=\"legend\"><span class=\"swatch\" style=\"border-color:#d64541\">"
	      "</span>LBS<span class=\"swatch\" style=\"border-color:#266ebe\"></span>DQBS"
	      "<span class=\"swatch dash\" style=\"border-color:#2ea05a\"></span>DQBS fixed point"
	      "<span class=\"swatch dash\" style=\"border-color:#969696;border-top-width:1px\"></span>"
	      "1.0 (as bound)</p>\n", f);
	for (int i = 0; i < r->chart_count; i++) {
		const report_chart *c = &r->chart[i];
		fprintf(f, "<figure>\n<img src=\"%s\" alt=\"", c->png);
		report_html_escape(f, c->title);
		fputs("\">\n<figcaption>", f);
		report_html_escape(f, c->caption);
		fputs("</figcaption>\n</figure>\n", f);
	}
}

static void scenes(FILE *f, const report *r)
{
	fputs("<h2>The synthetic scenes</h2>\n<p>A closed cylinder of radius 0.2 around two bones of "
	      "length 1, the weights cross-fading over 0.3 either side of the joint; the second bone "
	      "turned about its axis (twist) or about a perpendicular axis (bend). At the joint ring a "
	      "twist by <i>a</i> shrinks LBS to |cos(<i>a</i>/2)| of the radius (the candy wrapper: a "
	      "point at 180&deg;); DQBS keeps it (1).</p>\n", f);
	fputs("<table id=\"scene-twist\">\n<tr><th>twist</th><th>analytic LBS<br>|cos(a/2)|</th>"
	      "<th>LBS min radius</th><th>analytic DQBS</th><th>DQBS min radius</th>"
	      "<th>fixed min radius</th><th>LBS volume</th><th>DQBS volume</th><th>fixed volume</th></tr>\n", f);
	for (int i = 0; i < r->scene_count; i++) {
		const report_scene *s = &r->scene[i];
		if (s->kind != SCENE_TWIST)
			continue;
		double an = fabs(cos(s->angle_deg * 3.14159265358979323846 / 360.0));
		fprintf(f, "<tr><td>%d&deg;</td><td>%.6f</td><td>%.6f</td><td>1</td><td>%.6f</td><td>%.6f</td>"
			"<td>%.6f</td><td>%.6f</td><td>%.6f</td></tr>\n", s->angle_deg, an, s->rmin[0],
			s->rmin[1], s->rmin[2], s->vol[0], s->vol[1], s->vol[2]);
	}
	fputs("</table>\n", f);
	report_html_scene_picture(f, &r->scene_still[SCENE_TWIST]);
	fputs("<table id=\"scene-bend\">\n<tr><th>bend</th><th>LBS min radius</th>"
	      "<th>DQBS min radius</th><th>fixed min radius</th><th>LBS max radius</th>"
	      "<th>DQBS max radius</th><th>LBS volume</th><th>DQBS volume</th><th>fixed volume</th></tr>\n", f);
	for (int i = 0; i < r->scene_count; i++) {
		const report_scene *s = &r->scene[i];
		if (s->kind != SCENE_BEND)
			continue;
		fprintf(f, "<tr><td>%d&deg;</td><td>%.6f</td><td>%.6f</td><td>%.6f</td><td>%.6f</td><td>%.6f</td>"
			"<td>%.6f</td><td>%.6f</td><td>%.6f</td></tr>\n", s->angle_deg, s->rmin[0], s->rmin[1],
			s->rmin[2], s->rmax[0], s->rmax[1], s->vol[0], s->vol[1], s->vol[2]);
	}
	fputs("</table>\n<p class=\"meta\">A bend has no closed form for the blended radius: the inside of "
	      "the bend collapses with LBS and, less, with DQBS, which bulges on the outside instead "
	      "(max radius &gt; 1) and keeps the volume.</p>\n", f);
	report_html_scene_picture(f, &r->scene_still[SCENE_BEND]);
}

static void definitions(FILE *f, const report *r)
{
	fprintf(f, "<h2>Definitions</h2>\n<dl>\n"
		"<dt>volume ratio</dt><dd>The closed mesh's signed volume (divergence theorem, in "
		"double) over the volume as bound. 1 means kept. Where the skin passes through itself "
		"the overlap counts twice, as the flesh of both parts: the ratio measures what the "
		"skinning does to the body, not the space the pose takes up.</dd>\n"
		"<dt>radius ratio</dt><dd>For each vertex farther than 1e-4 of the mesh's size from the "
		"bones as bound (%d of %d vertices): its distance to the nearest posed bone segment over "
		"the same distance in the bind pose. Below 1 the skin moved towards the bones (collapse, "
		"candy wrapper), above 1 away (bulge).</dd>\n"
		"<dt>joint regions</dt><dd>A vertex belongs to the joint nearest to it in the bind pose, "
		"a joint being the head of a bone; the bone's name gives the region: "
		"<code>lhumerus</code>/<code>rhumerus</code> shoulders, <code>lradius</code>/<code>rradius</code> "
		"elbows, <code>lwrist</code>/<code>rwrist</code>/<code>lhand</code>/<code>rhand</code> wrists, "
		"<code>lfemur</code>/<code>rfemur</code> hips, <code>ltibia</code>/<code>rtibia</code> knees "
		"(CMU, HDM05); for other skeletons a name containing Shoulder, Elbow, Wrist, Hip or Knee. "
		"A region's min and max are over its vertices' radius ratios. Vertices near other joints "
		"(spine, neck, ankles, fingers) are in no region.</dd>\n"
		"<dt>LBS minus DQBS</dt><dd>Per vertex of the joint regions, min(LBS radius ratio, 1) minus "
		"min(DQBS radius ratio, 1) in the same frame: contact between limbs shrinks both alike and a "
		"bulge is no collapse, so what remains is LBS's own collapse. The worst frames are its most "
		"negative ones.</dd>\n"
		"<dt>metrics.csv</dt><dd>One row per frame and algorithm: <code>frame,algo,volume_ratio,"
		"min_radius_ratio,max_radius_ratio</code> exactly as <code>skintool metrics</code> prints "
		"them for the same inputs, then <code>elbows_min,elbows_max,knees_min,knees_max,"
		"shoulders_min,shoulders_max,hips_min,hips_max,wrists_min,wrists_max</code> (empty when "
		"the skeleton has no such region).</dd>\n</dl>\n", r->measured, r->vert_count);
}

int report_write_html(const report *r, const char *dir)
{
	char path[4096];
	snprintf(path, sizeof path, "%s/index.html", dir);
	if (cli_output_check(path) < 0)
		return -1;
	FILE *f = fopen(path, "w");
	if (!f) {
		fprintf(stderr, "%s: %s\n", path, strerror(errno));
		return -1;
	}
	head(f, r);
	fputs("<h2>Summary</h2>\n", f);
	verdicts(f, r);
	summary_table(f, r);
	weights_table(f, r);
	report_html_joints(f, r);
	report_html_stills(f, r);
	region_volume_table(f, r);
	region_table(f, r);
	charts(f, r);
	scenes(f, r);
	definitions(f, r);
	fputs("</main>\n</body>\n</html>\n", f);
	int bad = ferror(f);
	if (fclose(f) != 0 || bad) {
		fprintf(stderr, "%s: write failed\n", path);
		return -1;
	}
	return 0;
}
