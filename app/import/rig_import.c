#include "rig_scene.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "mem_cap.h"
#include "mesh_normals.h"
#include "rig_colour.h"
#include "rig_limits.h"
#include "rig_names.h"
#include "rig_rest.h"
#include "rig_seam.h"
#include "rig_weld.h"


static vec3 transform_point(const struct aiMatrix4x4 *m, vec3 p)
{
	return vec3_make(m->a1 * p.x + m->a2 * p.y + m->a3 * p.z + m->a4,
			 m->b1 * p.x + m->b2 * p.y + m->b3 * p.z + m->b4,
			 m->c1 * p.x + m->c2 * p.y + m->c3 * p.z + m->c4);
}

typedef struct rigid_part {
	int part, first, count;
	const struct aiNode *node;
} rigid_part;

typedef struct import_walk {
	const struct aiScene *scene;
	const char *group;
	rig_scene *out;
	skp_error *err;
	int group_found;
	int rigid_count;
	rigid_part rigid[RIG_MAX_PARTS];
	const struct aiNode *part_node[RIG_MAX_PARTS]; /* the node each part is */
	rig_colour_work colour;
	vec3 *rest_pos;                 /* the vertices in the nodes' rest pose (rig_rest.h) */
	vec3 rest_head[RIG_MAX_JOINTS]; /* the joints there */
	/* each joint's rest pose to its bind pose (bind x rest^-1) */
	struct aiMatrix4x4 rest_to_bind[RIG_MAX_JOINTS];
} import_walk;

static skp_status add_joint(import_walk *w, const struct aiBone *b, const struct aiMatrix4x4 *node_m,
			    int *index)
{
	rig_scene *r = w->out;
	char name[RIG_NAME];
	rig_rest_name(name, &b->mName);
	int j = rig_find_joint(r, name);
	if (j < 0) {
		if (r->joint_count >= RIG_MAX_JOINTS)
			return skp_fail(w->err, SKP_ERR_LIMIT, 0, "more than %d joints", RIG_MAX_JOINTS);
		j = r->joint_count++;
		rig_joint *jt = &r->joint[j];
		memset(jt, 0, sizeof *jt);
		memcpy(jt->name, name, sizeof name);
		jt->parent = -1;
		/* the offset matrix takes mesh space to the joint's space at bind */
		struct aiMatrix4x4 bind = b->mOffsetMatrix;
		aiMatrix4Inverse(&bind);
		jt->head = transform_point(node_m, transform_point(&bind, vec3_make(0.0f, 0.0f, 0.0f)));
		const struct aiNode *node = rig_rest_node(w->scene, name);
		struct aiMatrix4x4 rest = node ? rig_rest_global(node) : bind;
		if (!node)
			aiMultiplyMatrix4(&rest, node_m);
		w->rest_head[j] = transform_point(&rest, vec3_make(0.0f, 0.0f, 0.0f));
		struct aiMatrix4x4 to_bind = *node_m;
		aiMultiplyMatrix4(&to_bind, &bind);
		aiMatrix4Inverse(&rest);
		aiMultiplyMatrix4(&to_bind, &rest);
		w->rest_to_bind[j] = to_bind;
	}
	*index = j;
	return SKP_OK;
}

static skp_status add_bones(import_walk *w, const struct aiMesh *am, const struct aiMatrix4x4 *node_m,
			    int base)
{
	for (unsigned b = 0; b < am->mNumBones; b++) {
		const struct aiBone *bone = am->mBones[b];
		int j = -1;
		skp_status rc = add_joint(w, bone, node_m, &j);
		if (rc != SKP_OK)
			return rc;
		for (unsigned k = 0; k < bone->mNumWeights; k++) {
			const struct aiVertexWeight *vw = &bone->mWeights[k];
			if (vw->mVertexId >= am->mNumVertices || !(vw->mWeight > 0.0f))
				continue;
			rig_add_influence(w->out, base + (int)vw->mVertexId, j, vw->mWeight);
			w->out->joint[j].weighted++;
		}
	}
	return SKP_OK;
}

static skp_status place_vertices(import_walk *w, const struct aiMesh *am, const struct aiMatrix4x4 *node_m, int base)
{
	mesh *m = w->out->mesh;
	for (unsigned v = 0; v < am->mNumVertices; v++) {
		const struct aiVector3D *p = &am->mVertices[v];
		m->pos[base + (int)v] = w->rest_pos[base + (int)v] = transform_point(node_m, vec3_make(p->x, p->y, p->z));
		w->out->infl_count[base + (int)v] = w->out->held[base + (int)v] = 0;
	}
	if (!am->mNumBones || !am->mNumVertices)
		return SKP_OK;
	float *scratch = malloc(sizeof *scratch * am->mNumVertices);
	if (!scratch)
		return skp_fail(w->err, SKP_ERR_LIMIT, 0, "out of memory for %u vertices", am->mNumVertices);
	rig_rest_skin(w->scene, am, node_m, w->rest_pos + base, scratch);
	free(scratch);
	return SKP_OK;
}

static skp_status add_mesh(import_walk *w, const struct aiMesh *am, const struct aiNode *node,
			   const struct aiMatrix4x4 *node_m, int part)
{
	mesh *m = w->out->mesh;
	int base = m->vert_count;
	if ((long)base + am->mNumVertices > SKP_MAX_VERTS)
		return skp_fail(w->err, SKP_ERR_LIMIT, 0, "more than %d vertices", SKP_MAX_VERTS);
	skp_status rc = place_vertices(w, am, node_m, base);
	if (rc != SKP_OK)
		return rc;
	if (rig_colour_mesh(&w->colour, w->scene, am, m->colour + base, m->uv + base, m->sampled + base))
		m->coloured = 1;
	rigid_part *last = w->rigid_count ? &w->rigid[w->rigid_count - 1] : NULL;
	if (am->mNumBones || part < 0)
		;
	else if (last && last->part == part && last->first + last->count == base)
		last->count += (int)am->mNumVertices;   /* the node's next primitive */
	else if (w->rigid_count < RIG_MAX_PARTS)
		w->rigid[w->rigid_count++] = (rigid_part){ part, base, (int)am->mNumVertices, node };
	m->vert_count = base + (int)am->mNumVertices;
	for (unsigned f = 0; f < am->mNumFaces; f++) {
		const struct aiFace *face = &am->mFaces[f];
		if (face->mNumIndices != 3)
			continue;       /* points and lines: nothing to skin */
		if (m->tri_count >= SKP_MAX_TRIS)
			return skp_fail(w->err, SKP_ERR_LIMIT, 0, "more than %d triangles", SKP_MAX_TRIS);
		for (int k = 0; k < 3; k++)
			m->tri[m->tri_count][k] = (uint32_t)base + face->mIndices[k];
		m->tri_count++;
	}
	return add_bones(w, am, node_m, base);
}

static int wanted(const import_walk *w, const struct aiNode *node, const struct aiMesh *am)
{
	if (!w->group)
		return 1;
	return strcmp(am->mName.data, w->group) == 0 || strcmp(node->mName.data, w->group) == 0;
}

/* The part's index, or -1 past RIG_MAX_PARTS. A part is a node's meshes
 * with or without a skin: the library splits a mesh by material (a
 * Paladin's spear in 56 pieces), named for the node then. */
static int note_part(import_walk *w, const struct aiNode *node, const struct aiMesh *am, int used)
{
	rig_scene *r = w->out;
	for (int p = 0; p < r->part_count; p++)
		if (w->part_node[p] == node && r->part_skinned[p] == (am->mNumBones > 0)) {
			r->part_used[p] |= used;
			return p;
		}
	if (r->part_count >= RIG_MAX_PARTS)
		return -1;
	int one = node->mNumMeshes == 1 && am->mName.length;
	rig_rest_name(r->part[r->part_count], one || !node->mName.length ? &am->mName : &node->mName);
	w->part_node[r->part_count] = node;
	r->part_used[r->part_count] = used;
	r->part_skinned[r->part_count] = am->mNumBones > 0;
	r->part_joint[r->part_count] = r->part_near[r->part_count] = -1;
	return r->part_count++;
}

/* The textures the meshes walk_node will read use, counted first: the GPU
 * draws the one most of them use (rig_colour.h). */
static void tally_node(import_walk *w, const struct aiNode *node)
{
	for (unsigned k = 0; k < node->mNumMeshes; k++) {
		const struct aiMesh *am = w->scene->mMeshes[node->mMeshes[k]];
		if ((am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) && wanted(w, node, am))
			rig_colour_tally(&w->colour, w->scene, am);
	}
	for (unsigned c = 0; c < node->mNumChildren; c++)
		tally_node(w, node->mChildren[c]);
}

static skp_status walk_node(import_walk *w, const struct aiNode *node, const struct aiMatrix4x4 *parent_m)
{
	struct aiMatrix4x4 m = *parent_m;
	aiMultiplyMatrix4(&m, &node->mTransformation);
	for (unsigned k = 0; k < node->mNumMeshes; k++) {
		const struct aiMesh *am = w->scene->mMeshes[node->mMeshes[k]];
		int use = (am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) && wanted(w, node, am);
		int part = note_part(w, node, am, use);
		if (!use)
			continue;
		w->group_found = 1;
		skp_status rc = add_mesh(w, am, node, &m, part);
		if (rc != SKP_OK)
			return rc;
	}
	for (unsigned c = 0; c < node->mNumChildren; c++) {
		skp_status rc = walk_node(w, node->mChildren[c], &m);
		if (rc != SKP_OK)
			return rc;
	}
	return SKP_OK;
}

/* The joint hierarchy is the node tree's, skipping nodes that are not
 * joints (an armature's own node, a mesh node). */
static void link_parents(const struct aiScene *scene, const struct aiNode *node, int joint_above, rig_scene *r)
{
	char name[RIG_NAME];
	rig_rest_name(name, &node->mName);
	int j = rig_rest_is_joint(scene, r, node) ? rig_find_joint(r, name) : -1;
	if (j >= 0 && r->joint[j].parent < 0 && joint_above != j)
		r->joint[j].parent = joint_above;
	for (unsigned c = 0; c < node->mNumChildren; c++)
		link_parents(scene, node->mChildren[c], j >= 0 ? j : joint_above, r);
}

/* Whether the skin's bind pose is a pose of its skeleton: every joint as
 * far from its parent as the nodes put it, up to one scale for all (the
 * nodes may carry a unit change), within 2% of the skeleton's size. A
 * part bound away from its joints (BCN_Epileptic.X's head, half a body
 * from its neck) is not: the nodes' rest pose is taken instead. */
static int bind_is_a_pose(const import_walk *w)
{
	const rig_scene *r = w->out;
	double sum_bind = 0.0, sum_rest = 0.0;
	float longest = 0.0f;
	for (int j = 0; j < r->joint_count; j++) {
		int p = r->joint[j].parent;
		if (p < 0)
			continue;
		sum_bind += vec3_length(vec3_sub(r->joint[j].head, r->joint[p].head));
		sum_rest += vec3_length(vec3_sub(w->rest_head[j], w->rest_head[p]));
		longest = fmaxf(longest, vec3_length(vec3_sub(w->rest_head[j], w->rest_head[p])));
	}
	if (!(sum_bind > 0.0) || !(sum_rest > 0.0))
		return 1;
	float k = (float)(sum_rest / sum_bind);
	for (int j = 0; j < r->joint_count; j++) {
		int p = r->joint[j].parent;
		if (p < 0)
			continue;
		float bind = k * vec3_length(vec3_sub(r->joint[j].head, r->joint[p].head));
		float rest = vec3_length(vec3_sub(w->rest_head[j], w->rest_head[p]));
		if (fabsf(bind - rest) > 0.1f * longest)
			return 0;
	}
	return 1;
}

static void take_rest_pose(import_walk *w)
{
	rig_scene *r = w->out;
	r->rest_posed = !bind_is_a_pose(w);
	if (!r->rest_posed)
		return;
	memcpy(r->mesh->pos, w->rest_pos, sizeof *w->rest_pos * (size_t)r->mesh->vert_count);
	for (int j = 0; j < r->joint_count; j++)
		r->joint[j].head = w->rest_head[j];
}

#define HOLD_REACH 0.15f /* of the joints' extent: a held part comes this near its joint */

/* How near the part's edges come to joint j (a long lance's faces have
 * their corners far from the hand beside it). */
static float part_distance(const rig_scene *r, const rigid_part *p, int j)
{
	const mesh *m = r->mesh;
	float best = -1.0f;
	for (int t = 0; t < m->tri_count; t++) {
		int a = (int)m->tri[t][0];
		if (a < p->first || a >= p->first + p->count)
			continue;
		for (int k = 0; k < 3; k++) {
			float d = vec3_segment_distance(m->pos[m->tri[t][k]], m->pos[m->tri[t][(k + 1) % 3]],
							r->joint[j].head);
			best = best < 0.0f || d < best ? d : best;
		}
	}
	return best;
}

/* The joints' extent: the diagonal of the box round their heads. */
static float joints_extent(const rig_scene *r)
{
	vec3 lo = r->joint[0].head, hi = lo;
	for (int j = 1; j < r->joint_count; j++) {
		lo = vec3_min(lo, r->joint[j].head);
		hi = vec3_max(hi, r->joint[j].head);
	}
	return vec3_length(vec3_sub(hi, lo));
}

/* Which joint a part beside the armature is held by: of the joints that
 * deform skin (not a control or IK helper) and come near it (within twice
 * the nearest one's distance, or 2% of the skeleton's extent beyond it), a
 * hand first (a spear whose butt rests by a foot is held in the hand),
 * then one on the body's middle (a cape by the spine, not a shoulder),
 * then any; the nearest of them. -1 when no joint deforms skin or none
 * comes within HOLD_REACH of the skeleton's extent (a crate on the floor
 * beside the figure is scenery). */
static int part_holder(const rig_scene *r, const rigid_part *p)
{
	static float dist[RIG_MAX_JOINTS];
	float nearest = -1.0f;
	for (int j = 0; j < r->joint_count; j++) {
		dist[j] = r->joint[j].weighted ? part_distance(r, p, j) : -1.0f;
		if (dist[j] >= 0.0f && (nearest < 0.0f || dist[j] < nearest))
			nearest = dist[j];
	}
	float extent = joints_extent(r), near = fmaxf(2.0f * nearest, nearest + 0.02f * extent);
	if (nearest < 0.0f || nearest > HOLD_REACH * extent)
		return -1;
	int best = -1, best_rank = -1;
	for (int j = 0; j < r->joint_count; j++) {
		if (dist[j] < 0.0f || dist[j] > near)
			continue;
		rig_name n;
		rig_name_parse(r->joint[j].name, &n);
		int rank = n.slot == RIG_HAND ? 2 : rig_name_side(r->joint[j].name) == RIG_CENTRE;
		if (best < 0 || rank > best_rank || (rank == best_rank && dist[j] < dist[best])) {
			best = j;
			best_rank = rank;
		}
	}
	return best;
}

/* Parts without a skin move wholly with the joint above them, from where
 * the nodes put them to where the skin's bind pose puts that joint (a
 * helmet, a prop in a hand: the nodes may hold another pose). A part with
 * no joint above it (a spear or a cape beside the armature, not under it)
 * moves with the joint that holds it (part_holder), where it is. */
static void attach_rigid(import_walk *w)
{
	rig_scene *r = w->out;
	for (int k = 0; k < w->rigid_count; k++) {
		const rigid_part *p = &w->rigid[k];
		int j = rig_rest_joint_above(w->scene, r, p->node), near = -1;
		r->part_joint[p->part] = j;
		if (j < 0)
			j = r->part_near[p->part] = near = part_holder(r, p);
		if (j < 0)
			continue;
		for (int v = p->first; v < p->first + p->count; v++) {
			rig_add_influence(r, v, j, 1.0f);
			r->held[v] = near >= 0;
			if (!r->rest_posed && near < 0)
				r->mesh->pos[v] = transform_point(&w->rest_to_bind[j], r->mesh->pos[v]);
		}
		r->joint[j].weighted += p->count;
	}
}

static skp_status group_missing(const rig_scene *r, const char *group, skp_error *err)
{
	char list[160] = "";
	size_t used = 0;
	for (int p = 0; p < r->part_count && used + RIG_NAME + 4 < sizeof list; p++)
		used += (size_t)snprintf(list + used, sizeof list - used, "%s'%s'", p ? ", " : "", r->part[p]);
	return skp_fail(err, SKP_ERR_RANGE, 0, "no mesh named '%s'; there are: %s", group, list);
}

/* The whole file read into memory, for the library to read as hint says. */
static const struct aiScene *read_as(const char *path, const char *hint, unsigned flags)
{
	if (!hint)
		return aiImportFile(path, flags);
	FILE *f = fopen(path, "rb");
	if (!f)
		return aiImportFile(path, flags);   /* the library says why */
	const struct aiScene *scene = NULL;
	long n = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
	char *buf = n > 0 && fseek(f, 0, SEEK_SET) == 0 ? malloc((size_t)n) : NULL;
	if (buf && fread(buf, 1, (size_t)n, f) == (size_t)n && n <= (long)UINT32_MAX)
		scene = aiImportFileFromMemory(buf, (unsigned)n, flags, hint);
	free(buf);
	fclose(f);
	return scene;
}

/* The GPU's texture from the colour work to the scene. */
static void keep_texture(import_walk *w)
{
	rig_scene *r = w->out;
	rig_colour_work *c = &w->colour;
	r->texture_rgba = c->gpu_rgba;
	r->texture_w = c->gpu_w;
	r->texture_h = c->gpu_h;
	memcpy(r->texture_path, c->gpu_path, sizeof r->texture_path);
	memcpy(r->texture_material, c->gpu_material, sizeof r->texture_material);
	r->mesh->textured = c->gpu_rgba != NULL;
	c->gpu_rgba = NULL;
}

skp_status rig_import(const char *path, const char *group, rig_scene *out, skp_error *err)
{
	return rig_import_as(path, NULL, group, out, err);
}

skp_status rig_import_as(const char *path, const char *hint, const char *group, rig_scene *out, skp_error *err)
{
	mesh *m = out->mesh;
	rig_scene_reset(out);
	m->vert_count = m->tri_count = m->coloured = m->textured = 0;
	uint64_t size;
	mem_cap cap;
	if (rig_limits_check(path, &size, err) != SKP_OK)
		return err->code;
	mem_cap_set(&cap, rig_limits_budget(size));
	const struct aiScene *scene = read_as(path, hint, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
							       aiProcess_SortByPType);
	mem_cap_release(&cap);
	if (!scene || !scene->mRootNode)
		return skp_fail(err, SKP_ERR_SYNTAX, 0, "%s%s", aiGetErrorString(),
				cap.limit ? " (the import's memory is capped: 1 GiB and 64 bytes a byte of the file)" : "");
	static import_walk w;
	memset(&w, 0, sizeof w);
	w.rest_pos = malloc(sizeof *w.rest_pos * SKP_MAX_VERTS);
	if (!w.rest_pos) {
		aiReleaseImport(scene);
		return skp_fail(err, SKP_ERR_LIMIT, 0, "out of memory");
	}
	w.scene = scene;
	w.group = group;
	w.out = out;
	w.err = err;
	w.colour.model_path = path;
	struct aiMatrix4x4 id;
	aiIdentityMatrix4(&id);
	tally_node(&w, scene->mRootNode);
	rig_colour_choose(&w.colour);
	skp_status rc = walk_node(&w, scene->mRootNode, &id);
	if (rc == SKP_OK) {
		link_parents(scene, scene->mRootNode, -1, out);
		take_rest_pose(&w);
		attach_rigid(&w);
	}
	free(w.rest_pos);
	rig_colour_done(&w.colour);
	aiReleaseImport(scene);
	keep_texture(&w);
	out->texture_problems = w.colour.problems;
	memcpy(out->texture_problem, w.colour.problem, sizeof out->texture_problem);
	out->textured = w.colour.textured;
	if (rc != SKP_OK)
		return rc;
	if (group && !w.group_found)
		return group_missing(out, group, err);
	if (m->tri_count == 0)
		return skp_fail(err, SKP_ERR_SYNTAX, 0, "no triangles in the file");
	rig_weld(out);
	mesh_compute_normals(m);
	rig_seam_normals(out, m);
	return SKP_OK;
}
