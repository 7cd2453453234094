#include "rig_rest.h"

#include <string.h>

#include <assimp/cimport.h>

#include "skp_format.h"

void rig_rest_name(char *dst, const struct aiString *s)
{
	char raw[RIG_NAME];
	size_t n = s->length < RIG_NAME - 1 ? s->length : RIG_NAME - 1;
	memcpy(raw, s->data, n);
	raw[n] = '\0';
	skp_escape_name(dst, RIG_NAME, raw);
}

/* The first node named name, among those without meshes when meshless
 * is set. */
static const struct aiNode *find_in(const struct aiNode *n, const char *name, int meshless, int depth)
{
	char own[RIG_NAME];
	rig_rest_name(own, &n->mName);
	if (strcmp(own, name) == 0 && !(meshless && n->mNumMeshes))
		return n;
	for (unsigned c = 0; c < n->mNumChildren && depth < 1024; c++) {
		const struct aiNode *f = find_in(n->mChildren[c], name, meshless, depth + 1);
		if (f)
			return f;
	}
	return NULL;
}

/* A mesh node may share its joint's name (RobotExpressive's Torso mesh
 * beside its Torso joint): the joint is the node without meshes. */
const struct aiNode *rig_rest_node(const struct aiScene *scene, const char *name)
{
	if (!scene->mRootNode)
		return NULL;
	const struct aiNode *n = find_in(scene->mRootNode, name, 1, 0);
	return n ? n : find_in(scene->mRootNode, name, 0, 0);
}

int rig_rest_is_joint(const struct aiScene *scene, const rig_scene *r, const struct aiNode *node)
{
	char name[RIG_NAME];
	rig_rest_name(name, &node->mName);
	return rig_find_joint(r, name) >= 0 && rig_rest_node(scene, name) == node;
}

struct aiMatrix4x4 rig_rest_global(const struct aiNode *node)
{
	struct aiMatrix4x4 m = node->mTransformation;
	for (const struct aiNode *p = node->mParent; p; p = p->mParent) {
		struct aiMatrix4x4 up = p->mTransformation;
		aiMultiplyMatrix4(&up, &m);
		m = up;
	}
	return m;
}

static vec3 apply(const struct aiMatrix4x4 *m, struct aiVector3D p)
{
	return vec3_make(m->a1 * p.x + m->a2 * p.y + m->a3 * p.z + m->a4, m->b1 * p.x + m->b2 * p.y + m->b3 * p.z + m->b4,
			 m->c1 * p.x + m->c2 * p.y + m->c3 * p.z + m->c4);
}

void rig_rest_skin(const struct aiScene *scene, const struct aiMesh *am, const struct aiMatrix4x4 *node_m,
		   vec3 *out, float *scratch)
{
	unsigned n = am->mNumVertices;
	for (unsigned v = 0; v < n; v++) {
		out[v] = vec3_make(0.0f, 0.0f, 0.0f);
		scratch[v] = 0.0f;
	}
	for (unsigned b = 0; b < am->mNumBones; b++) {
		const struct aiBone *bone = am->mBones[b];
		char name[RIG_NAME];
		rig_rest_name(name, &bone->mName);
		const struct aiNode *node = rig_rest_node(scene, name);
		struct aiMatrix4x4 m = node ? rig_rest_global(node) : *node_m;
		if (node)
			aiMultiplyMatrix4(&m, &bone->mOffsetMatrix);
		for (unsigned k = 0; k < bone->mNumWeights; k++) {
			const struct aiVertexWeight *vw = &bone->mWeights[k];
			if (vw->mVertexId >= n || !(vw->mWeight > 0.0f))
				continue;
			out[vw->mVertexId] = vec3_madd(out[vw->mVertexId], apply(&m, am->mVertices[vw->mVertexId]), vw->mWeight);
			scratch[vw->mVertexId] += vw->mWeight;
		}
	}
	for (unsigned v = 0; v < n; v++)
		out[v] = scratch[v] > 0.0f ? vec3_scale(out[v], 1.0f / scratch[v]) : apply(node_m, am->mVertices[v]);
}

int rig_rest_joint_above(const struct aiScene *scene, const rig_scene *r, const struct aiNode *node)
{
	for (const struct aiNode *n = node; n; n = n->mParent)
		if (rig_rest_is_joint(scene, r, n)) {
			char name[RIG_NAME];
			rig_rest_name(name, &n->mName);
			return rig_find_joint(r, name);
		}
	return -1;
}
