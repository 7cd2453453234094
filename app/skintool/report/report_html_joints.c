/* The report page's section on which bends carry the volume change: per
 * algorithm, the joints whose bend, turned back to the bind pose, gives
 * back most of it (report_joints.c measures them). */
#include <stdio.h>
#include <string.h>

#include "report_html.h"

static void joint_row(FILE *f, const report *r, const report_joint *j)
{
	static const char *const axis[3] = { "rx", "ry", "rz" };
	fputs("<tr><td><code>", f);
	report_html_escape(f, r->skel->bone[j->bone].name);
	fputs("</code></td><td>", f);
	for (int c = 0; c < j->count; c++)
		fprintf(f, "%s%s %.1f", c ? ", " : "", axis[j->channel[c]], (double)j->deg[c]);
	if (j->past >= 0)
		fprintf(f, "</td><td class=\"past\">%s %.1f&deg; past (%.0f, %.0f)", axis[j->channel[j->past]],
			(double)j->past_deg, (double)j->lo_deg, (double)j->hi_deg);
	else
		fputs("</td><td>within", f);
	fprintf(f, "</td><td>%+.2f%%</td></tr>\n", 100.0 * j->share);
}

/* The listed joints of j outside their ASF limits. */
static int joints_past(const report_joints *j)
{
	int n = 0;
	for (int i = 0; i < j->count; i++)
		n += j->joint[i].past >= 0;
	return n;
}

static void joint_table(FILE *f, const report *r, int algo)
{
	static const char *const what[2] = { "LBS at its worst volume loss", "DQBS at its largest deviation" };
	static const char *const id[2] = { "joints-lbs", "joints-dqbs" };
	const report_joints *j = &r->vol_joints[algo];
	if (j->frame < 0)
		return;
	fprintf(f, "<h3>%s: frame %ld, volume %+.2f%%</h3>\n", what[algo], j->frame, 100.0 * (j->volume - 1.0));
	if (j->count == 0) {
		fputs("<p>No single joint moves the volume by 0.05% or more.</p>\n", f);
		return;
	}
	fprintf(f, "<table id=\"%s\" data-frame=\"%ld\">\n<tr><th>joint</th><th>rotation (degrees)</th><th>ASF limits</th>"
		"<th>volume change from its bend</th></tr>\n", id[algo], j->frame);
	for (int i = 0; i < j->count; i++)
		joint_row(f, r, &j->joint[i]);
	fputs("</table>\n", f);
	int past = joints_past(j);
	if (past > 0)
		fprintf(f, "<p class=\"meta\">%d of these joints %s a channel outside the limits the "
			"skeleton file gives it (compared modulo 360 degrees).</p>\n", past, past > 1 ? "have" : "has");
}

void report_html_joints(FILE *f, const report *r)
{
	if (r->vol_joints[0].frame < 0 && r->vol_joints[1].frame < 0)
		return;
	fputs("<h2 id=\"joints\">Where the volume goes</h2>\n<p>Each worst frame skinned again with one "
	      "joint at a time turned back to its bind-pose rotation: the difference is what that joint's "
	      "bend does to the volume. DQBS turns each cross-section of a bending joint rigidly about the "
	      "joint, so it keeps the volume only where the flesh around the joint is centred on it; "
	      "elsewhere the volume changes in proportion to the bend angle, up one way and down the other", f);
	if (r->balanced)
		fputs(". These weights are volume-balanced: at each joint the cross-fade was moved so that "
		      "this change is zero for small bends of the bind pose (skintool bind --report tables "
		      "it), so what is left grows faster than the angle, or comes from joints the balancing "
		      "left alone", f);
	else if (strcmp(r->mesh_name, GENERATED_BODY) == 0)
		fputs(" (on the generated body, the hips: a CMU hip joint lies in front of the pelvis; and the "
		      "ankles, where the foot leaves the shin at a right angle)", f);
	fputs(". LBS adds its collapse, which grows faster than the angle. The shares need not add up to "
	      "the total: bends interact where their regions meet. Joints moving the volume by less than "
	      "0.05% are left out.</p>\n", f);
	joint_table(f, r, SKIN_LBS);
	joint_table(f, r, SKIN_DQBS);
}

