#include "scene.h"

#include <math.h>
#include <string.h>

#define TWO_PI 6.28318530717958647692f

static const char *const names[SCENE_KIND_COUNT] = { "twist", "bend" };

const char *scene_name(scene_kind k)
{
	return (unsigned)k < SCENE_KIND_COUNT ? names[k] : "?";
}

int scene_parse(const char *name)
{
	for (int k = 0; k < SCENE_KIND_COUNT; k++)
		if (strcmp(name, names[k]) == 0)
			return k;
	return -1;
}

static void scene_bone(skel *s, int b, const char *name, int parent)
{
	skel_bone *bone = &s->bone[b];
	strcpy(bone->name, name);
	bone->id = b;
	bone->parent = parent;
	bone->direction = vec3_make(1, 0, 0);
	bone->length = 1.0f;
	bone->axis_order[0] = 0; bone->axis_order[1] = 1; bone->axis_order[2] = 2;
	bone->axis_rot = quat_identity();
	s->eval_order[b] = (uint8_t)b;
}

static void scene_skel(skel *s)
{
	memset(s, 0, sizeof *s);
	strcpy(s->name, "scene");
	strcpy(s->version, "1.10");
	s->length_scale = 1.0f;
	s->mass_scale = 1.0f;
	s->count = 2;
	scene_bone(s, 0, "upper", -1);
	scene_bone(s, 1, "lower", 0);
}

static void scene_bind(skel_pose *p)
{
	memset(p, 0, sizeof *p);
	for (int b = 0; b < 2; b++) {
		p->rot[b] = quat_identity();
		p->head[b] = vec3_make((float)b, 0, 0);
		p->tip[b] = vec3_make((float)b + 1.0f, 0, 0);
	}
}

static void set_weights(skin_weights *w, int v, float x)
{
	float w1 = (x - (1.0f - SCENE_BLEND)) / (2.0f * SCENE_BLEND);
	w1 = w1 < 0.0f ? 0.0f : w1 > 1.0f ? 1.0f : w1;
	float w0 = 1.0f - w1;
	int big = w1 > w0; /* largest first, as bind writes them */
	w->bone[v][0] = (uint16_t)big;
	w->weight[v][0] = big ? w1 : w0;
	w->bone[v][1] = (uint16_t)!big;
	w->weight[v][1] = big ? w0 : w1;
	w->count[v] = w->weight[v][1] > 0.0f ? 2 : 1;
}

static void add_vertex(scene_rig *sc, vec3 p, vec3 n)
{
	int v = sc->mesh.vert_count++;
	sc->mesh.pos[v] = p;
	sc->mesh.normal[v] = n;
	set_weights(&sc->weights, v, p.x);
}

static void add_tri(mesh *m, int a, int b, int c)
{
	uint32_t *t = m->tri[m->tri_count++];
	t[0] = (uint32_t)a; t[1] = (uint32_t)b; t[2] = (uint32_t)c;
}

static void build_rings(scene_rig *sc)
{
	for (int i = 0; i < SCENE_RINGS; i++) {
		float x = 2.0f * (float)i / (float)(SCENE_RINGS - 1);
		for (int j = 0; j < SCENE_SEGMENTS; j++) {
			float a = TWO_PI * (float)j / (float)SCENE_SEGMENTS;
			vec3 n = vec3_make(0, cosf(a), sinf(a));
			add_vertex(sc, vec3_make(x, SCENE_RADIUS * n.y, SCENE_RADIUS * n.z), n);
		}
	}
}

static int ring_vertex(int i, int j)
{
	return i * SCENE_SEGMENTS + j % SCENE_SEGMENTS;
}

/* Counter-clockwise seen from outside: the angle grows about +X. */
static void build_faces(mesh *m)
{
	int c0 = SCENE_RINGS * SCENE_SEGMENTS, c1 = c0 + 1, last = SCENE_RINGS - 1;
	for (int i = 0; i < last; i++)
		for (int j = 0; j < SCENE_SEGMENTS; j++) {
			int a = ring_vertex(i, j), b = ring_vertex(i + 1, j);
			int c = ring_vertex(i + 1, j + 1), d = ring_vertex(i, j + 1);
			add_tri(m, a, d, c);
			add_tri(m, a, c, b);
		}
	for (int j = 0; j < SCENE_SEGMENTS; j++) {
		add_tri(m, c0, ring_vertex(0, j + 1), ring_vertex(0, j));
		add_tri(m, c1, ring_vertex(last, j), ring_vertex(last, j + 1));
	}
}

void scene_build(scene_rig *sc)
{
	scene_skel(&sc->skel);
	scene_bind(&sc->bind);
	sc->mesh.vert_count = 0;
	sc->mesh.tri_count = 0;
	sc->mesh.coloured = sc->mesh.textured = 0;
	build_rings(sc);
	add_vertex(sc, vec3_make(0, 0, 0), vec3_make(-1, 0, 0));
	add_vertex(sc, vec3_make(2, 0, 0), vec3_make(1, 0, 0));
	build_faces(&sc->mesh);
	sc->weights.vert_count = sc->mesh.vert_count;
}

void scene_pose(const scene_rig *sc, scene_kind k, float radians, skel_pose *out)
{
	*out = sc->bind;
	quat q = quat_from_basis_angle(k == SCENE_BEND ? 2 : 0, radians);
	out->rot[1] = quat_mul(q, sc->bind.rot[1]);
	out->tip[1] = vec3_add(out->head[1], quat_rotate(q, vec3_sub(sc->bind.tip[1], sc->bind.head[1])));
}
