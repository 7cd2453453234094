/* The report page's pictures: the worst frames (the kiosk's view with
 * its close-up, the close-up camera's view, the difference view) and the
 * synthetic scenes at their strongest poses, each with what to look at. */
#include <stdio.h>

#include "report_html.h"

/* "the left elbow, bent 95&deg;, 23 mm apart" from the close-up's texts
 * (HUD capitals: "LEFT ELBOW", "BENT 95 DEG"). */
static void put_closeup(FILE *f, const report_closeup *c)
{
	char name[sizeof c->name];
	size_t n = 0;
	for (const char *p = c->name; *p && n + 1 < sizeof name; p++)
		name[n++] = (char)(*p >= 'A' && *p <= 'Z' ? *p - 'A' + 'a' : *p);
	name[n] = '\0';
	fputs("<b class=\"closeup-joint\">", f);
	report_html_escape(f, name);
	fputs("</b>", f);
	if (c->turn != SKEL_TURN_SLIGHT)
		fprintf(f, ", %s %d&deg;", c->turn == SKEL_TURN_TWIST ? "twisted" : "bent", c->turn_deg);
	if (c->in_units)
		fprintf(f, ", LBS %.2f from DQBS there", c->apart);
	else
		fprintf(f, ", LBS %.0f mm from DQBS there%s", c->apart, c->size_assumed ? " (the body taken as 1.75 m "
			"tall)" : "");
}

void report_html_stills(FILE *f, const report *r)
{
	fputs("<h2>Where LBS fails: the worst frames</h2>\n", f);
	if (r->render_note) {
		fputs("<p>No renders: ", f);
		report_html_escape(f, r->render_note);
		fputs(".</p>\n", f);
		return;
	}
	if (r->still_count == 0) {
		fputs("<p>LBS is nowhere thinner than DQBS in this clip: nothing to show.</p>\n", f);
		return;
	}
	fputs("<p>For each joint region in turn, the frame where a vertex of that region keeps the least of "
	      "its radius with LBS compared with DQBS (see <i>LBS minus DQBS</i> below), the worst region "
	      "first, at least half a second apart. LBS on the left, DQBS on the right, same pose and camera. "
	      "In each frame the close-up shows the joint where the two methods part most, as the kiosk's "
	      "compare view chooses it: per joint the largest distance between a vertex's LBS and DQBS "
	      "positions, centred where they part (that distance squared weighs the vertices). First picture: "
	      "the whole body, the close-up beside it, the ring on the body round what the close-up shows; "
	      "second: each body from the close-up's side, near, the ring round every vertex of that joint "
	      "that the two put at least half as far apart as the most; third: the difference view.</p>\n", f);
	for (int i = 0; i < r->still_count; i++) {
		const report_still *s = &r->still[i];
		if (!s->rendered)
			continue;
		fprintf(f, "<h3>%d. Frame %ld &mdash; %s joint <code>", i + 1, s->frame,
			report_region_name(s->rel.region));
		report_html_escape(f, report_html_joint(r, s->rel.joint));
		fprintf(f, "</code></h3>\n<figure id=\"worst-%d\">\n<div class=\"pair\">\n", i + 1);
		fprintf(f, "<a href=\"%s\"><img src=\"%s\" alt=\"frame %ld, whole body with the close-up, LBS left, DQBS "
			"right\"></a>\n", s->full_png, s->full_png, s->frame);
		fprintf(f, "<a href=\"%s\"><img src=\"%s\" alt=\"frame %ld, close-up where LBS and DQBS part\"></a>\n",
			s->close_png, s->close_png, s->frame);
		fprintf(f, "<a href=\"%s\"><img src=\"%s\" alt=\"frame %ld, difference view: how far LBS lies from "
			"DQBS\"></a>\n", s->diff_png, s->diff_png, s->frame);
		fprintf(f, "<p class=\"cell\">The difference view: each vertex of both bodies coloured by how far LBS "
			"puts it from DQBS, dark blue for none through green to red for 40 mm or more (%s).</p>\n",
			s->closeup.size_assumed ? "the skeleton's units give no human height: the body taken as 1.75 m "
			"tall" : "at the body's real size");
		fprintf(f, "</div>\n<figcaption>Frame %ld: at the still's vertex (%s, by <code>", s->frame,
			report_region_name(s->rel.region));
		report_html_escape(f, report_html_joint(r, s->rel.joint));
		fprintf(f, "</code>) a vertex keeps %.3f of its bind-pose radius with <span class=\"lbs\">LBS</span> "
			"and %.3f with <span class=\"dqbs\">DQBS</span>. ", s->lbs_ratio, s->dqbs_ratio);
		if (s->closeup.joint >= 0) {
			fputs("Where the two part most in this frame, ringed and in the close-up: ", f);
			put_closeup(f, &s->closeup);
			fputs(".", f);
		} else {
			fputs("LBS and DQBS put every vertex in the same place in this frame: no close-up.", f);
		}
		fputs(" Top: whole body and close-up; bottom: the difference view.</figcaption>\n</figure>\n", f);
	}
}

/* A scene at its strongest pose, with what to look at. */
void report_html_scene_picture(FILE *f, const report_scene_still *s)
{
	if (!s->rendered)
		return;
	const char *kind = scene_name(s->kind);
	fprintf(f, "<figure id=\"scene-%s-picture\">\n<a href=\"%s\"><img src=\"%s\" alt=\"the %s scene at %d "
		"degrees, LBS left, DQBS right\"></a>\n<figcaption>", kind, s->png, s->png, kind, s->angle_deg);
	if (s->kind == SCENE_TWIST)
		fprintf(f, "Twisted %d&deg;, the largest twist of the table. Look at the joint: "
			"<span class=\"lbs\">LBS</span> (left) pinches the cylinder to %s at the joint ring (radius "
			"ratio %.3f), the candy wrapper; <span class=\"dqbs\">DQBS</span> (right) keeps the cylinder "
			"whole (%.3f): it turns each ring of the skin rigidly about the bone instead of shrinking it. ",
			s->angle_deg, s->lbs_rmin < 0.01 ? "a point" : "a waist", s->lbs_rmin, s->dqbs_rmin);
	else
		fprintf(f, "Bent %d&deg;, the deepest bend of the table short of 180&deg; (there the second bone "
			"lies inside the first, both bodies folded onto themselves). Look at the inside of the bend: "
			"<span class=\"lbs\">LBS</span> (left) flattens it (smallest radius ratio %.3f), its elbow a "
			"sharp crease; <span class=\"dqbs\">DQBS</span> (right) keeps more of it (%.3f) and bulges on "
			"the outside instead (up to %.3f), a round knuckle. ",
			s->angle_deg, s->lbs_rmin, s->dqbs_rmin, s->dqbs_rmax);
	if (s->closeup.joint >= 0) {
		fputs("The close-up beside each body (the same camera in both) is the kiosk's: the joint where "
		      "the two part most, ", f);
		put_closeup(f, &s->closeup);
		fputs(" (the cylinder's radius is 0.2; <i>lower</i> is the scene's second bone, the joint at its "
		      "head); the ring on the body marks what it shows.", f);
	}
	fputs("</figcaption>\n</figure>\n", f);
}

