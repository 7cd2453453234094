#include "rig_makehuman.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The mean of the file vertices listed for joint name. */
static skp_status joint_place(json_object *joints, const char *name, const obj_work *obj, vec3 *at,
			      skp_error *err)
{
	json_object *list = rig_json_get(joints, name, json_type_array);
	if (!list)
		return skp_syntax(err, 0, "joints: no list of vertices named '%s'", name);
	size_t n = json_object_array_length(list);
	if (n == 0)
		return skp_syntax(err, 0, "joints: '%s' lists no vertices", name);
	vec3 sum = vec3_make(0.0f, 0.0f, 0.0f);
	for (size_t i = 0; i < n; i++) {
		json_object *e = json_object_array_get_idx(list, i);
		int64_t v = json_object_is_type(e, json_type_int) ? json_object_get_int64(e) : -1;
		if (v < 0 || v >= obj->file_verts)
			return skp_fail(err, SKP_ERR_RANGE, 0,
					"joints: '%s' entry %lu: expected a vertex number from 0 to %ld (the OBJ's)",
					name, (unsigned long)i + 1, obj->file_verts - 1);
		sum = vec3_add(sum, obj->pos[v]);
	}
	*at = vec3_scale(sum, 1.0f / (float)n);
	return SKP_OK;
}

static skp_status add_bone(rig_scene *out, const char *name, json_object *bone, json_object *joints,
			   const obj_work *obj, skp_error *err)
{
	if (!json_object_is_type(bone, json_type_object))
		return skp_syntax(err, 0, "bones: '%s' is not an object", name);
	if (strlen(name) >= RIG_NAME)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "bones: '%s': names are at most %d bytes", name, RIG_NAME - 1);
	for (const char *c = name; *c; c++)
		if ((unsigned char)*c < 0x20 || *c == 0x7f)
			return skp_syntax(err, 0, "bones: '%s': a name with a control character", name);
	if (rig_find_joint(out, name) >= 0)
		return skp_syntax(err, 0, "bones: '%s' twice", name);
	if (out->joint_count == RIG_MAX_JOINTS)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "bones: more than %d", RIG_MAX_JOINTS);
	json_object *head = rig_json_get(bone, "head", json_type_string);
	if (!head)
		return skp_syntax(err, 0, "bones: '%s': expected \"head\": the name of a joint", name);
	rig_joint *j = &out->joint[out->joint_count];
	memset(j, 0, sizeof *j);
	memcpy(j->name, name, strlen(name) + 1);
	j->parent = -1;
	skp_status rc = joint_place(joints, json_object_get_string(head), obj, &j->head, err);
	if (rc == SKP_OK)
		out->joint_count++;
	return rc;
}

/* After every bone is in: each "parent" names one of them, or is null. */
static skp_status link_parents(json_object *bones, rig_scene *out, skp_error *err)
{
	json_object_object_foreach(bones, name, bone) {
		json_object *p = NULL;
		json_object_object_get_ex(bone, "parent", &p);
		if (!p)
			continue;
		const char *pn = json_object_is_type(p, json_type_string) ? json_object_get_string(p) : NULL;
		int j = rig_find_joint(out, name), up = pn ? rig_find_joint(out, pn) : -1;
		if (up < 0 || up == j)
			return skp_syntax(err, 0, "bones: '%s': expected \"parent\": another bone's name or null", name);
		out->joint[j].parent = up;
	}
	/* a parent chain longer than the bones has a cycle */
	for (int j = 0; j < out->joint_count; j++) {
		int steps = 0;
		for (int up = out->joint[j].parent; up >= 0; up = out->joint[up].parent)
			if (++steps > out->joint_count)
				return skp_syntax(err, 0, "bones: '%s': its parents form a loop", out->joint[j].name);
	}
	return SKP_OK;
}

skp_status rig_mh_skeleton(json_object *root, const obj_work *obj, rig_scene *out, const char **weights_file,
			   skp_error *err)
{
	json_object *bones = rig_json_get(root, "bones", json_type_object);
	json_object *joints = rig_json_get(root, "joints", json_type_object);
	json_object *wf = rig_json_get(root, "weights_file", json_type_string);
	*weights_file = wf ? json_object_get_string(wf) : NULL;
	if (!bones || !joints)
		return skp_syntax(err, 0, "expected a MakeHuman skeleton: an object with \"bones\" and \"joints\"");
	mesh *m = out->mesh;
	rig_scene_reset(out);
	memset(out->infl_count, 0, sizeof out->infl_count[0] * (size_t)m->vert_count);
	json_object_object_foreach(bones, name, bone) {
		skp_status rc = add_bone(out, name, bone, joints, obj, err);
		if (rc != SKP_OK)
			return rc;
	}
	if (out->joint_count == 0)
		return skp_syntax(err, 0, "bones: none");
	return link_parents(bones, out, err);
}

static skp_status add_pair(rig_scene *out, const int32_t *mesh_of, long file_verts, const char *bone, int j,
			   json_object *pair, size_t i, skp_error *err)
{
	/* json-c asserts on an index into anything but an array */
	int pair_ok = json_object_is_type(pair, json_type_array) && json_object_array_length(pair) == 2;
	json_object *v = pair_ok ? json_object_array_get_idx(pair, 0) : NULL;
	json_object *w = pair_ok ? json_object_array_get_idx(pair, 1) : NULL;
	int ok = pair_ok && json_object_is_type(v, json_type_int) &&
		 (json_object_is_type(w, json_type_double) || json_object_is_type(w, json_type_int));
	int64_t vi = ok ? json_object_get_int64(v) : -1;
	double wt = ok ? json_object_get_double(w) : -1.0;
	if (!ok || vi < 0 || vi >= file_verts || !(wt >= 0.0 && wt <= 1.0))
		return skp_fail(err, ok ? SKP_ERR_RANGE : SKP_ERR_SYNTAX, 0,
				"weights: '%s' entry %lu: expected [vertex, weight], a vertex from 0 to %ld and a "
				"weight from 0 to 1", bone, (unsigned long)i + 1, file_verts - 1);
	int mv = mesh_of[vi];
	if (mv < 0 || wt == 0.0)
		return SKP_OK;
	rig_add_influence(out, mv, j, (float)wt);
	out->joint[j].weighted++;
	return SKP_OK;
}

static skp_status add_bone_weights(rig_scene *out, const int32_t *mesh_of, long file_verts, const char *bone,
				   json_object *pairs, skp_error *err)
{
	int j = rig_find_joint(out, bone);
	if (j < 0)
		return skp_syntax(err, 0, "weights: '%s' is not a bone of the skeleton", bone);
	if (!json_object_is_type(pairs, json_type_array))
		return skp_syntax(err, 0, "weights: '%s': expected a list of [vertex, weight]", bone);
	size_t n = json_object_array_length(pairs);
	for (size_t i = 0; i < n; i++) {
		skp_status rc = add_pair(out, mesh_of, file_verts, bone, j, json_object_array_get_idx(pairs, i), i, err);
		if (rc != SKP_OK)
			return rc;
	}
	return SKP_OK;
}

skp_status rig_mh_weights(json_object *root, const obj_work *obj, rig_scene *out, skp_error *err)
{
	json_object *weights = rig_json_get(root, "weights", json_type_object);
	if (!weights)
		return skp_syntax(err, 0, "expected MakeHuman weights: an object with \"weights\"");
	int32_t *mesh_of = malloc(sizeof *mesh_of * (size_t)(obj->file_verts ? obj->file_verts : 1));
	if (!mesh_of)
		return skp_fail(err, SKP_ERR_IO, 0, "out of memory");
	for (long f = 0; f < obj->file_verts; f++)
		mesh_of[f] = -1;
	for (int v = 0; v < out->mesh->vert_count; v++)
		mesh_of[obj->source[v]] = v;
	skp_status rc = SKP_OK;
	json_object_object_foreach(weights, bone, pairs) {
		rc = add_bone_weights(out, mesh_of, obj->file_verts, bone, pairs, err);
		if (rc != SKP_OK)
			break;
	}
	free(mesh_of);
	return rc;
}
