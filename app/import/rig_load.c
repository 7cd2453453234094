#include "rig_load.h"

#include <stdio.h>
#include <string.h>

#include "runtime_body.h"
#include "setup_bind.h"
#include "setup_gate.h"
#include "setup_mesh_format.h"
#include "setup_mesh_io.h"
#include "setup_mesh_place.h"
#include "cli_error.h"
#include "cli_inputs.h"
#include "cli_progress.h"
#include "cli_quiet.h"
#include "clock.h"
#include "mesh_normals.h"
#include "rig_align.h"
#include "rig_biped.h"
#include "rig_colour.h"
#include "rig_makehuman.h"
#include "rig_obj_colour.h"
#include "rig_map_file.h"
#include "rig_pose.h"
#include "rig_proportions.h"
#include "rig_seam.h"
#include "rig_texture.h"
#include "rig_weights.h"

/* Everything here is tens of MB with the host's limits: static. */
static rig_scene scene;
static rig_map map;
static rig_map_file map_file;

/* The .mhw beside the .mhskel that names it. */
static const char *weights_beside(const char *rig, const char *name)
{
	static char path[4096];
	const char *slash = strrchr(rig, '/');
	int dir = name[0] == '/' || !slash ? 0 : (int)(slash - rig + 1);
	if (snprintf(path, sizeof path, "%.*s%s", dir, rig, name) >= (int)sizeof path)
		return NULL;
	return path;
}

static void say_colours(const char *path, const mesh *m);

/* The OBJ's materials (its mtllib), each problem a warning. */
static void obj_colours(const char *path, const obj_work *w, const mesh *m)
{
	static rig_obj_colour_report rep;
	rig_obj_colour(path, w, &scene, &rep);
	for (int k = 0; k < rep.warnings && k < RIG_OBJ_WARNINGS; k++)
		fprintf(stderr, "%s: warning: %s\n", path, rep.warning[k]);
	if (w->mtllib[0])
		say_colours(path, m);
}

static json_object *load_json(const char *path)
{
	skp_error err;
	cli_inputs_add(path); /* a rig's weights file is named inside it: never an output */
	json_object *v = rig_json_load(path, &err);
	if (!v)
		cli_error(path, &err);
	return v;
}

/* --rig: the OBJ's MakeHuman group (--group, default "body"), joints and
 * weights from the rig's two files. */
static int import_makehuman(const bind_args *a, const char *path, bound_body *body)
{
	const char *group = a->group ? a->group : "body", *wname = NULL, *wpath = NULL;
	int missing, rc = -1;
	skp_error err;
	const obj_work *w = setup_load_obj(path, group, &body->mesh, &missing);
	if (!w) {
		if (missing)
			fprintf(stderr, "%s: --rig: no faces in group '%s', the MakeHuman body (--group NAME picks "
				"another)\n", path, group);
		return -1;
	}
	json_object *sk = load_json(a->rig), *wt = NULL;
	if (!sk)
		return -1;
	if (rig_mh_skeleton(sk, w, &scene, &wname, &err) != SKP_OK) {
		cli_error(a->rig, &err);
		goto out;
	}
	if (!wname || !(wpath = weights_beside(a->rig, wname))) {
		fprintf(stderr, "%s: expected \"weights_file\": the name of its .mhw weights file\n", a->rig);
		goto out;
	}
	if (!(wt = load_json(wpath)))
		goto out;
	if (rig_mh_weights(wt, w, &scene, &err) != SKP_OK) {
		cli_error(wpath, &err);
		goto out;
	}
	fprintf(cli_note(), "%s: group '%s', %d vertices, %d triangles; %s: %d bones, weights from %s\n", path, group,
		body->mesh.vert_count, body->mesh.tri_count, a->rig, scene.joint_count, wpath);
	obj_colours(path, w, &body->mesh);
	rc = 0;
out:
	json_object_put(wt);
	json_object_put(sk);
	return rc;
}

/* What to do when the library cannot read the file, by what it is. */
static const char *import_advice(mesh_format fmt)
{
	switch (fmt) {
	case MESH_FMT_FBX:
		return "if this FBX does not load, export the character as glTF 2.0 (.glb) instead (Blender: File > "
		       "Export > glTF 2.0)";
	case MESH_FMT_ZIP:
		return "the library reads a zip archive as a zipped COLLADA (.zae); for one holding another model, "
		       "unpack it and give the model inside";
	case MESH_FMT_BLEND:
		return "export the character from Blender as glTF 2.0 (File > Export > glTF 2.0)";
	default:
		return "skintool reads rigged meshes as glTF 2.0 (.gltf, .glb), FBX (binary or ASCII 6.1-7.x) and "
		       "COLLADA (.dae, .zae); an OBJ works without a rig";
	}
}

/* The GPU's texture as a message names it: its file, or which of the
 * file's own ("*0" to the library). */
static const char *texture_name(void)
{
	static char name[600];
	if (scene.texture_path[0] == '*')
		snprintf(name, sizeof name, "the file's embedded texture %.20s", scene.texture_path + 1);
	else
		snprintf(name, sizeof name, "texture '%.512s'", scene.texture_path);
	return name;
}

/* Where the body's colours come from, and the textures that could not be
 * read (said once, with how many more). */
static void say_colours(const char *path, const mesh *m)
{
	if (scene.texture_problems)
		fprintf(stderr, "%s: warning: %s%s\n", path, scene.texture_problem,
			scene.texture_problems > 1 ? " (and more textures like it)" : "");
	if (m->textured)
		fprintf(cli_note(), "%s: colours from its materials; %s (material '%s', %dx%d) drawn by the "
			"GPU%s, %d seam vertices kept apart\n", path, texture_name(), scene.texture_material,
			scene.texture_w, scene.texture_h, scene.textured > 1 ? ", the others per vertex" : "",
			scene.seams);
	else if (m->coloured)
		fprintf(cli_note(), "%s: colours from its materials%s (drawn per vertex)\n", path,
			scene.textured ? " and textures" : "");
	else
		fprintf(cli_note(), "%s: no colours of its own: drawn in the skin colour\n", path);
}

static int import_scene(const bind_args *a, const char *path, bound_body *body)
{
	skp_error err;
	scene.mesh = &body->mesh;
	body->texture.width = body->texture.height = 0;
	if (a->rig && setup_bind_is_interchange(path)) {
		fprintf(stderr, "%s: --rig gives an OBJ its MakeHuman rig; this mesh has its own joints (leave "
			"--rig out)\n", path);
		return -1;
	}
	if (a->rig)
		return import_makehuman(a, path, body);
	mesh_format fmt = setup_mesh_format(path);
	setup_mesh_format_note(path, fmt);
	uint64_t t0 = clock_now_ns();
	const char *hint = setup_mesh_format_named(path, fmt) ? NULL : mesh_format_extension(fmt);
	if (rig_import_as(path, hint, a->group, &scene, &err) != SKP_OK) {
		fprintf(stderr, "%s: %s\n", path, err.msg);
		if (!a->group)
			fprintf(stderr, "%s: read as %s: %s\n", path, mesh_format_name(fmt), import_advice(fmt));
		return -1;
	}
	fprintf(cli_note(), "%s: %d vertices, %d triangles, %d joints (imported in %.1f ms", path,
		body->mesh.vert_count, body->mesh.tri_count, scene.joint_count,
		(double)(clock_now_ns() - t0) / 1e6);
	if (scene.welded)
		fprintf(cli_note(), "; %d split vertices welded", scene.welded);
	fprintf(cli_note(), ")\n");
	say_colours(path, &body->mesh);
	for (int p = 0; p < scene.part_count; p++)
		if (!scene.part_used[p])
			fprintf(cli_note(), "%s: mesh '%s' left out (--group chooses)\n", path, scene.part[p]);
	if (fmt == MESH_FMT_BLEND && !scene.joint_count)
		fprintf(stderr, "%s: a Blender file's meshes are read, its armature and weights are not (the library "
			"does not read them): %s\n", path, import_advice(fmt));
	return 0;
}

/* Every unmapped joint, with the joint it moves with. */
static void say_unmapped(const char *path, const char *skel_name)
{
	int count = 0;
	for (int j = 0; j < scene.joint_count; j++)
		count += map.bone[j] < 0;
	if (!count)
		return;
	fprintf(cli_note(), "%s: %d joints unmapped, moving with their nearest mapped parent:", path, count);
	for (int j = 0; j < scene.joint_count; j++)
		if (map.bone[j] < 0)
			fprintf(cli_note(), " %s->%s%s", scene.joint[j].name,
				map.via[j] >= 0 ? scene.joint[map.via[j]].name : skel_name,
				map.beside[j] ? " (the nearest: no mapped joint above it)" : "");
	fprintf(cli_note(), "\n");
}

static void say_map(const char *path, const bound_body *body, int with_file)
{
	if (!map.mapped) {
		fprintf(stderr, "%s: none of its %d joints is named as the built-in maps know (Rigify/Blender metarig, "
			"Mixamo, Unity/Mecanim, MakeHuman default, Unreal, Daz, 3ds Max Biped, CMU), nor are they shaped "
			"like a biped's (two legs from the hips, two arms from the chest, a neck):", path,
			scene.joint_count);
		for (int j = 0; j < scene.joint_count; j++)
			fprintf(stderr, " %s", scene.joint[j].name);
		fprintf(stderr, "\n");
		return;
	}
	if (map.family == RIG_FAMILY_SHAPE)
		fprintf(cli_note(), "%s: %d of %d joints mapped onto the skeleton by the skeleton's shape (its names say "
			"nothing)%s:", path, map.mapped, scene.joint_count, with_file ? ", and the joint map" : "");
	else
		fprintf(cli_note(), "%s: %d of %d joints mapped onto the skeleton (names: %s%s):", path, map.mapped,
			scene.joint_count, rig_family_name(map.family), with_file ? ", and the joint map" : "");
	for (int j = 0; j < scene.joint_count; j++)
		if (map.bone[j] >= 0)
			fprintf(cli_note(), " %s=%s", scene.joint[j].name, body->skel.bone[map.bone[j]].name);
	fprintf(cli_note(), "\n");
	say_unmapped(path, body->skel.bone[0].name);
}

static int load_map(const bind_args *a, const char *path, bound_body *body)
{
	skp_error err;
	if (a->joint_map && rig_map_file_read(a->joint_map, &map_file, &err) != SKP_OK) {
		cli_error(a->joint_map, &err);
		return -1;
	}
	if (rig_map_joints(&scene, &body->skel, &body->pose, a->joint_map ? &map_file : NULL, &map, &err) != SKP_OK) {
		if (err.line > 0)
			cli_error(a->joint_map, &err);
		else
			fprintf(stderr, "%s: %s\n", path, err.msg);
		return -1;
	}
	say_map(path, body, a->joint_map != NULL);
	return 0;
}

/* Joints whose place does not depend on how the arms and legs are posed. */
static int alignment_pairs(const bound_body *body, vec3 *from, vec3 *to)
{
	static const rig_slot fixed[] = { RIG_HEAD, RIG_CLAVICLE, RIG_UPPER_ARM, RIG_THIGH, RIG_SHIN, RIG_FOOT };
	int n = 0;
	if (map.hips >= 0 && map.bone[map.hips] >= 0) {
		from[n] = scene.joint[map.hips].head;
		to[n++] = body->pose.head[map.bone[map.hips]];
	}
	for (int side = RIG_CENTRE; side <= RIG_RIGHT; side++)
		for (size_t k = 0; k < sizeof fixed / sizeof fixed[0]; k++) {
			int j = rig_map_part_joint(&map, &scene, (rig_side)side, fixed[k]);
			if (j < 0)
				continue;
			from[n] = scene.joint[j].head;
			to[n++] = body->pose.head[map.bone[j]];
		}
	return n;
}

static int align_mesh(const char *path, bound_body *body)
{
	vec3 from[2 * RIG_SLOT_COUNT + 1], to[2 * RIG_SLOT_COUNT + 1];
	rig_align al;
	skp_error err;
	if (rig_align_fit(from, to, alignment_pairs(body, from, to), &al, &err) != SKP_OK) {
		fprintf(stderr, "%s: cannot put the mesh on the skeleton: %s\n", path, err.msg);
		return -1;
	}
	mesh *m = &body->mesh;
	for (int v = 0; v < m->vert_count; v++)
		m->pos[v] = rig_align_point(&al, m->pos[v]);
	for (int j = 0; j < scene.joint_count; j++)
		scene.joint[j].head = rig_align_point(&al, scene.joint[j].head);
	mesh_compute_normals(m);
	rig_seam_normals(&scene, m);
	body->fitted = 1;
	fprintf(cli_note(), "%s: put on the skeleton by its joints: turned %.0f degrees%s, scaled by %.4g, moved by "
		"%.4g %.4g %.4g; joints off by %.3g after (--no-fit keeps the mesh as it is)\n", path,
		(double)al.turn_deg, al.snapped ? " (a quarter-turn combination)" : "", (double)al.scale,
		(double)al.offset.x, (double)al.offset.y, (double)al.offset.z, (double)al.rms);
	return 0;
}

static void fit_proportions(const char *path, bound_body *body)
{
	rig_proportions pr;
	rig_fit_proportions(&body->skel, body->pose_value, &body->pose, &scene, &map, &pr);
	fprintf(cli_note(), "%s: skeleton given the mesh's proportions: mesh scaled by %.4g more to match the legs",
		path, (double)pr.mesh_scale);
	if (pr.scaled)
		fprintf(cli_note(), ", %d stretches of bones by %.3g to %.3g", pr.scaled, (double)pr.min_ratio,
			(double)pr.max_ratio);
	if (pr.hip_bones)
		fprintf(cli_note(), ", %d hip bones moved to the mesh's hips", pr.hip_bones);
	fprintf(cli_note(), "\n");
}

static void pose_skeleton(const bind_args *a, const char *path, bound_body *body)
{
	static rig_pose_result res;
	if (a->pose_path || a->rest_pose) {
		rig_pose_measure(&scene, &map, &body->pose, &res);
	} else {
		rig_pose_fit(&body->skel, &scene, &map, body->pose_value, &body->pose, &res);
		fprintf(cli_note(), "%s: skeleton posed as the mesh stands:", path);
		for (int k = 0; k < res.aim_count; k++)
			if (res.aim[k].turned_deg >= 1.0f)
				fprintf(cli_note(), " %s %.0f", body->skel.bone[res.aim[k].bone].name,
					(double)res.aim[k].turned_deg);
		fprintf(cli_note(), " degrees (--bind-pose P.amc[:F] or rest chooses)\n");
	}
	float h = bind_fit_skel_height(&body->skel, &body->pose, NULL);
	if (res.pairs && h > 0.0f)
		fprintf(cli_note(), "%s: mapped joints %.1f%% of the height from the skeleton's on average, %.1f%% at "
			"worst (%s)\n", path, (double)(100.0f * res.mean_gap / h), (double)(100.0f * res.worst_gap / h),
			scene.joint[res.worst_joint].name);
}

/* Parts with no skin and no joint above them in the file's node tree
 * follow the joint nearest them (rig_scene.h): said, so that a prop meant
 * for the other hand is not left there unnoticed. */
static void say_loose_parts(const char *path)
{
	for (int p = 0; p < scene.part_count; p++) {
		if (!scene.part_used[p] || scene.part_skinned[p] || scene.part_joint[p] >= 0)
			continue;
		if (scene.part_near[p] >= 0)
			fprintf(stderr, "%s: mesh '%s' has no skin and no joint above it: it moves with %s, the joint "
				"that holds it (parent it to a joint in the file to choose, or --group leaves it out)\n", path,
				scene.part[p], scene.joint[scene.part_near[p]].name);
		else
			fprintf(stderr, "%s: warning: mesh '%s' has no skin and no joint above it: it moves with the "
				"root (parent it to a joint in the file, or --group leaves it out)\n", path, scene.part[p]);
	}
}

static int mesh_weights(const bind_args *a, const char *path, bound_body *body)
{
	rig_weights_info info;
	rig_weights_to_skel(&scene, &map, &body->weights, &info, body->orphan);
	body->has_orphans = 1;
	body->automatic = 0;
	fprintf(cli_note(), "%s: the mesh's own weights%s", path,
		a->balance == 1 ? " (kept as they are: --balance is for computed weights)" : "");
	if (info.trimmed)
		fprintf(cli_note(), ", %d vertices cut to their 4 largest bones", info.trimmed);
	if (info.unweighted)
		fprintf(cli_note(), ", %d vertices without weights given to the root", info.unweighted);
	fprintf(cli_note(), "\n");
	return 0;
}

/* No skin, or joints that do not map: bound as an OBJ of one's own. */
static int bind_unrigged(const bind_args *a, const char *path, bound_body *body)
{
	if (a->weights_mesh && !scene.joint_count) {
		fprintf(stderr, "%s: --weights mesh: the mesh has no skin (no joints, no weights); without --weights "
			"skintool computes them\n", path);
		return -1;
	}
	if (a->weights_mesh) {
		fprintf(stderr, "%s: --weights mesh: its arms and legs did not map onto the skeleton; name its joints "
			"in a map file (--joint-map FILE, lines MESH_JOINT = SKELETON_BONE; app/import/README.md) "
			"or leave out --weights to have skintool compute them\n", path);
		return -1;
	}
	if (scene.joint_count)
		fprintf(stderr, "%s: its arms and legs did not map onto the skeleton (a --joint-map FILE would map "
			"them): bound like an OBJ, weights computed\n", path);
	if (setup_place_mesh(a, path, body) < 0 || setup_bind_weights(a, 0, path, body) < 0)
		return -1;
	rig_seam_weights(&scene, &body->weights);
	return 0;
}

/* A rig that is not a biped's (rig_biped.h): 0 when it is, or --force
 * binds it anyway; -1 after refusing. */
static int check_biped(const bind_args *a, const char *path, const bound_body *body)
{
	char why[256];
	if (!setup_skel_is_biped(&body->skel, &body->pose) || rig_biped_check(&scene, &map, why, sizeof why))
		return 0;
	fprintf(stderr, "%s: not a biped: %s; skintool plays human motion on bipeds%s\n", path, why,
		a->force ? " (--force: bound anyway)" : " (--force binds it anyway)");
	return a->force ? 0 : -1;
}

/* The vertices of parts held by the joint nearest them (rig_scene.h)
 * for the gate; computed weights (body->automatic) would spread a spear
 * over every bone it passes, so they keep the one bone their joint moves
 * with. */
static void keep_held(bound_body *body, int computed)
{
	body->has_held = 0;
	for (int v = 0; v < body->mesh.vert_count; v++) {
		body->held[v] = scene.held[v];
		if (!scene.held[v] || !scene.infl_count[v])
			continue;
		body->has_held = 1;
		if (!computed)
			continue;
		body->weights.count[v] = 1;
		body->weights.bone[v][0] = (uint16_t)map.follow[scene.infl_joint[v][0]];
		body->weights.weight[v][0] = 1.0f;
	}
}

int rig_load_mesh(const bind_args *a, const char *path, bound_body *body)
{
	if (import_scene(a, path, body) < 0 || (scene.joint_count && load_map(a, path, body) < 0) ||
	    (scene.joint_count && check_biped(a, path, body) < 0))
		return -1;
	if (!scene.joint_count || (map.limbs < 2 && !a->joint_map))
		return bind_unrigged(a, path, body);
	body->rigged = 1;
	if (!a->no_fit) {
		if (align_mesh(path, body) < 0)
			return -1;
		fit_proportions(path, body);
	}
	pose_skeleton(a, path, body);
	if (!a->weights_mesh && !a->weights_path)
		fprintf(cli_note(), "%s: weights computed from the skeleton (--weights mesh keeps the file's own)\n", path);
	int rc = a->weights_mesh ? mesh_weights(a, path, body) : setup_bind_weights(a, 0, path, body);
	if (rc == 0) {
		rig_seam_weights(&scene, &body->weights);
		say_loose_parts(path);
		keep_held(body, body->automatic);
	}
	return rc;
}

static void progress_step(void *ctx, long done, long total)
{
	cli_progress *pr = ctx;
	pr->total = total;
	cli_progress_step(pr, done);
}

void rig_load_texture(const char *path, bound_body *body)
{
	skp_error err;
	mesh *m = &body->mesh;
	if (!m->textured || body->texture.width > 0)
		return;         /* none, or encoded already */
	if (!scene.texture_rgba) {
		m->textured = 0; /* another body's import released it: the vertices keep their colours */
		return;
	}
	uint64_t t0 = clock_now_ns();
	static cli_progress pr;
	cli_progress_start(&pr, "texture", "ETC1 blocks", 0);
	tex_encode_progress told = { progress_step, &pr };
	skp_status rc = rig_texture_make(scene.texture_rgba, scene.texture_w, scene.texture_h, &body->texture, &told,
					 &err);
	cli_progress_clear(&pr);
	if (rc != SKP_OK) {
		fprintf(stderr, "%s: warning: %s of material '%s': %s: drawn per vertex\n", path, texture_name(),
			scene.texture_material, err.msg);
		rig_colour_bake(scene.texture_rgba, scene.texture_w, scene.texture_h, (const float (*)[2])m->uv,
				m->sampled, m->colour, m->vert_count);
		m->textured = 0;
	} else {
		const tex_image *t = &body->texture;
		fprintf(cli_note(), "%s: %s packed at %dx%d%s: ETC1, %d mip levels, %lu bytes (encoded in %.1f s)\n",
			path, texture_name(), t->width, t->height,
			t->width != scene.texture_w || t->height != scene.texture_h ? " (the board's power-of-two sides)"
										     : "",
			t->chain.levels, (unsigned long)t->chain.etc1_bytes, (double)(clock_now_ns() - t0) / 1e9);
	}
	rig_scene_release(&scene);
}

int rig_bind_load(const bind_args *a, const char *asf, const char *obj, bound_body *body)
{
	if (!setup_bind_rigged(a, obj))
		return setup_bind_load(a, asf, obj, body);
	if (setup_bind_begin(a, asf, body) < 0 || rig_load_mesh(a, obj, body) < 0)
		return -1;
	return setup_gate(a, obj, body);
}
