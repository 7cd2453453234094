/* Every part in its place (issues 33 and 44): a Mixamo-named biped of
 * boxes (tests/data/rigs/props_rig.gltf, made by make_props_rig.py beside
 * it) with parts that have no skin: a spear under the right hand's node,
 * turned 90 degrees and moved by its own node transform, a helmet under
 * the head's, a crate under no joint on the floor well away; beside the
 * armature, under no joint, a lance standing by the left hand and a cape
 * behind the back; a hat skinned to a slot joint hanging from the
 * armature, not the head; and an unweighted control rig whose "legs" lie
 * along the floor. Imported, each sits where its node puts it, the lance
 * held by the left hand and the cape by the spine; bound with the file's
 * weights (the controls do not make it a quadruped), spear and helmet go
 * wholly to their joint's bone, the lance to the left hand's, the cape to
 * the spine's, the hat to the head's (the mapped joint nearest its slot)
 * and the crate is named in a warning; bound with computed weights, the
 * lance and the cape keep their one bone and the choice is said; skinned
 * in CMU's walk, the spear keeps its shape and its place in the fist
 * while the hand swings. Skips without ../shared. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rig_scene.h"
#include "test_paths.h"
#include "test_run.h"

#define RIG "tests/data/rigs/props_rig.gltf"
#define MAX_V 256

static mesh rig_mesh;
static rig_scene scene;

typedef struct part_verts {
	int idx[MAX_V];
	int n;
} part_verts;

static int part_named(const char *name)
{
	for (int p = 0; p < scene.part_count; p++)
		if (!strcmp(scene.part[p], name))
			return p;
	fail_msg("no part named %s", name);
	return -1;
}

typedef struct props {
	part_verts spear, helmet, hand, lance, cape, hat;
} props;

static void add_vert(part_verts *p, int v)
{
	if (p->n < MAX_V)
		p->idx[p->n++] = v;
}

/* Each part's vertices by where they lie: the spear's reach far ahead of
 * and behind the right of the body (|z| > 0.5 m); the helmet's stand out
 * of the head's box (|x| > 0.1 m above 1.6 m), the hat's above it within
 * it; the right hand's box and the finger's beyond the spear's reach in
 * x; the lance's at the floor and 2 m up beside the left hand; the cape's
 * behind the back. */
static void find_parts(props *o)
{
	memset(o, 0, sizeof *o);
	for (int v = 0; v < rig_mesh.vert_count; v++) {
		vec3 p = rig_mesh.pos[v];
		if (fabsf(p.x - 0.78f) < 0.011f && (p.y < 0.01f || p.y > 1.99f))
			add_vert(&o->lance, v);
		else if (fabsf(p.z) > 0.5f && p.x < 0.0f)
			add_vert(&o->spear, v);
		else if (p.y > 1.6f && fabsf(p.x) > 0.1f)
			add_vert(&o->helmet, v);
		else if (p.y > 1.755f && fabsf(fabsf(p.x) - 0.08f) < 1e-3f)
			add_vert(&o->hat, v);
		else if (p.x < -0.8f && fabsf(p.z) < 0.05f)
			add_vert(&o->hand, v);
		else if (p.z < -0.11f && p.z > -0.15f)
			add_vert(&o->cape, v);
	}
}

static const char *holder(int part)
{
	int j = scene.part_near[part];
	return j >= 0 ? scene.joint[j].name : "(none)";
}

static void test_parts_placed_by_their_nodes(void **state)
{
	(void)state;
	skp_error err;
	scene.mesh = &rig_mesh;
	assert_int_equal(rig_import(RIG, NULL, &scene, &err), SKP_OK);
	int spear = part_named("Spear"), helmet = part_named("Helmet"), crate = part_named("Crate");
	int lance = part_named("Lance"), cape = part_named("Cape");
	assert_string_equal(scene.joint[scene.part_joint[spear]].name, "mixamorig:RightHand");
	assert_string_equal(scene.joint[scene.part_joint[helmet]].name, "mixamorig:Head");
	assert_int_equal(scene.part_joint[crate], -1);
	assert_int_equal(scene.part_near[crate], -1);
	assert_int_equal(scene.part_near[spear], -1);
	assert_false(scene.part_skinned[spear] || scene.part_skinned[crate]);
	/* beside the armature: held by the joint nearest them, a hand first,
	 * then the body's middle */
	assert_int_equal(scene.part_joint[lance], -1);
	assert_string_equal(holder(lance), "mixamorig:LeftHand");
	assert_non_null(strstr("mixamorig:Hips mixamorig:Spine mixamorig:Spine1 mixamorig:Spine2 mixamorig:Neck",
			       holder(cape)));
	props o;
	find_parts(&o);
	part_verts s = o.spear, h = o.helmet;
	assert_int_equal(s.n, 8);
	assert_int_equal(h.n, 8);
	assert_int_equal(o.hand.n, 8);
	assert_int_equal(o.lance.n, 8);
	assert_int_equal(o.cape.n, 8);
	assert_int_equal(o.hat.n, 8);
	for (int k = 0; k < o.lance.n; k++)
		assert_true(scene.held[o.lance.idx[k]]);
	for (int k = 0; k < s.n; k++)
		assert_false(scene.held[s.idx[k]]);
	/* the spear box runs along its node's Y from -0.9 to 0.7; the node turns
	 * it onto Z and moves it by (-0.05, 0, 0.03) from the hand at (-0.7, 1.4, 0) */
	for (int k = 0; k < s.n; k++) {
		vec3 p = rig_mesh.pos[s.idx[k]];
		assert_true(fabsf(p.x + 0.75f) < 0.0125f && fabsf(p.y - 1.4f) < 0.0125f);
		assert_true(fabsf(p.z + 0.87f) < 1e-4f || fabsf(p.z - 0.73f) < 1e-4f);
	}
	/* the helmet: its node 0.12 above the head's (1.55), the box -0.04..0.1 */
	for (int k = 0; k < h.n; k++) {
		vec3 p = rig_mesh.pos[h.idx[k]];
		assert_true(fabsf(p.y - 1.63f) < 1e-4f || fabsf(p.y - 1.77f) < 1e-4f);
	}
}

static char *run(const char *args, int want)
{
	const char *err = test_scratch("props.err");
	int st = test_run("%s %s 2>%s", test_tool_path("skintool"), args, err);
	char *text = test_read_file(err, NULL);
	assert_non_null(text);
	if (st != want)
		fail_msg("skintool %s: exit %d, wanted %d\n%s", args, st, want, text);
	return text;
}

/* The weights CSV row of vertex v (one bone, weight 1 expected). */
static void assert_whole(const char *csv, int v, const char *bone)
{
	char want[96];
	snprintf(want, sizeof want, "\n%d,%s,1\n", v, bone);
	char *text = test_read_file(csv, NULL);
	assert_non_null(text);
	if (!strstr(text, want))
		fail_msg("%s lacks the row %s", csv, want + 1);
	free(text);
}

static void read_obj(const char *path, vec3 *pos, int n)
{
	FILE *f = fopen(path, "r");
	assert_non_null(f);
	char line[256];
	int v = 0;
	while (fgets(line, sizeof line, f))
		if (line[0] == 'v' && line[1] == ' ' && v < n &&
		    sscanf(line + 2, "%f %f %f", &pos[v].x, &pos[v].y, &pos[v].z) == 3)
			v++;
	fclose(f);
	assert_int_equal(v, n);
}

static vec3 centroid(const vec3 *pos, const part_verts *p)
{
	vec3 c = vec3_make(0.0f, 0.0f, 0.0f);
	for (int k = 0; k < p->n; k++)
		c = vec3_add(c, pos[p->idx[k]]);
	return vec3_scale(c, 1.0f / (float)p->n);
}

static void test_props_follow_their_joint(void **state)
{
	(void)state;
	if (!test_data_path("mocap/cmu/02_01.amc"))
		skip();
	char args[4096];
	const char *asf = test_data_path("mocap/cmu/02.asf"), *csv = test_scratch("props.csv");
	snprintf(args, sizeof args, "bind %s %s --weights mesh -o %s", asf, RIG, csv);
	char *notes = run(args, 0);
	if (!strstr(notes, "warning: mesh 'Crate' has no skin and no joint above it: it moves with the root"))
		fail_msg("the crate is not named:\n%s", notes);
	if (!strstr(notes, "mesh 'Lance' has no skin and no joint above it: it moves with mixamorig:LeftHand, the "
			   "joint that holds it"))
		fail_msg("the lance's holder is not said:\n%s", notes);
	if (!strstr(notes, "HatSlot->mixamorig:Head (the nearest: no mapped joint above it)"))
		fail_msg("the hat's slot does not follow the head:\n%s", notes);
	assert_null(strstr(notes, "not a biped"));
	assert_null(strstr(notes, "mesh 'Spear' has no skin"));
	assert_null(strstr(notes, "mesh 'Helmet' has no skin"));
	assert_null(strstr(notes, "weights computed"));
	free(notes);
	scene.mesh = &rig_mesh;
	skp_error err;
	assert_int_equal(rig_import(RIG, NULL, &scene, &err), SKP_OK);
	props o;
	find_parts(&o);
	part_verts s = o.spear, hand = o.hand;
	for (int k = 0; k < s.n; k++)
		assert_whole(csv, s.idx[k], "rhand");
	for (int k = 0; k < o.helmet.n; k++)
		assert_whole(csv, o.helmet.idx[k], "head");
	for (int k = 0; k < o.hat.n; k++)
		assert_whole(csv, o.hat.idx[k], "head");
	for (int k = 0; k < o.lance.n; k++)
		assert_whole(csv, o.lance.idx[k], "lhand");

	/* computed weights: the held parts keep their one bone, the choice said */
	snprintf(args, sizeof args, "bind %s %s -o %s", asf, RIG, csv);
	notes = run(args, 0);
	if (!strstr(notes, "weights computed from the skeleton (--weights mesh keeps the file's own)"))
		fail_msg("computed weights are not said:\n%s", notes);
	free(notes);
	for (int k = 0; k < o.lance.n; k++)
		assert_whole(csv, o.lance.idx[k], "lhand");

	/* two frames of the walk a swing apart: the spear moves with the fist */
	static vec3 a[MAX_V], b[MAX_V];
	const int frames[2] = { 1, 60 };
	vec3 *out[2] = { a, b };
	for (int f = 0; f < 2; f++) {
		const char *obj = test_scratch(f ? "props_b.obj" : "props_a.obj");
		snprintf(args, sizeof args, "skin %s %s %s --weights mesh --frame %d --algo dqbs -o %s", asf,
			 test_data_path("mocap/cmu/02_01.amc"), RIG, frames[f], obj);
		free(run(args, 0));
		read_obj(obj, out[f], rig_mesh.vert_count);
	}
	float spear_len = vec3_length(vec3_sub(a[s.idx[0]], a[s.idx[s.n - 1]]));
	float moved = vec3_length(vec3_sub(centroid(b, &hand), centroid(a, &hand)));
	float gap_a = vec3_length(vec3_sub(centroid(a, &s), centroid(a, &hand)));
	float gap_b = vec3_length(vec3_sub(centroid(b, &s), centroid(b, &hand)));
	print_message("props: the hand moved %.2f, the spear's centre from the hand %.3f then %.3f, its length %.2f "
		      "then %.2f\n", (double)moved, (double)gap_a, (double)gap_b, (double)spear_len,
		      (double)vec3_length(vec3_sub(b[s.idx[0]], b[s.idx[s.n - 1]])));
	assert_true(moved > 0.1f * spear_len);
	assert_true(fabsf(gap_a - gap_b) < 0.01f * spear_len);
	for (int i = 0; i < s.n; i++)
		for (int j = i + 1; j < s.n; j++) {
			float da = vec3_length(vec3_sub(a[s.idx[i]], a[s.idx[j]]));
			float db = vec3_length(vec3_sub(b[s.idx[i]], b[s.idx[j]]));
			assert_true(fabsf(da - db) < 0.01f * spear_len);
		}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_parts_placed_by_their_nodes),
		cmocka_unit_test(test_props_follow_their_joint),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
