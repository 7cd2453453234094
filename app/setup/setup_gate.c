#include "setup_gate.h"

#include <string.h>

#include "cli_say.h"
#include "motion_file.h"
#include "runtime_body.h"
#include "setup_scratch.h"
#include "skp_format.h"

/* Where a figure was worst, for messages: "with lfemur forward 60 degrees"
 * or "at frame 84 of walk.amc". */
void setup_gate_where(const bound_body *body, const bind_gate_worst *w, char *out, size_t n)
{
	const bind_rom_move *m = w->move >= 0 ? &body->rom.move[w->move] : NULL;
	if (m)
		skp_format(out, n, "with %s %s %d degrees", body->skel.bone[m->bone].name, bind_rom_kind_name(m->kind),
			 m->degrees);
	else
		skp_format(out, n, "at frame %ld of the motion", w->frame);
}

typedef struct where_text {
	char s[96];
} where_text;

static where_text where(const bound_body *body, const bind_gate_worst *w)
{
	where_text t = { "" };
	setup_gate_where(body, w, t.s, sizeof t.s);
	return t;
}

static const char *region_name(const bound_body *body, const bind_gate_worst *w)
{
	return w->region > 0 ? body->skel.bone[w->region].name : "the root";
}

/* What to try, by how the body was bound. */
static const char *fix_for(const bind_args *a, const bound_body *body, unsigned check)
{
	int unmapped = check & (BIND_GATE_ROOT | BIND_GATE_RIGID);
	if (body->rigged && a->weights_mesh)
		return unmapped ? "name the joints of that part in a map file (--joint-map FILE, lines MESH_JOINT = "
				  "SKELETON_BONE; app/import/README.md), or leave out --weights mesh to have the "
				  "weights computed"
				: "check the joints mapped onto that part (--joint-map FILE overrides them), or leave out "
				  "--weights mesh to have the weights computed";
	if (body->rigged && !a->weights_path)
		return "--weights mesh keeps the artist's weights; --joint-map FILE maps the joints by hand";
	if (a->weights_path)
		return "the weights file does not fit this mesh and skeleton: leave out --weights to compute them";
	return "--group NAME binds one part of the file alone, --bind-pose P.amc[:F] or rest when the pose was "
	       "guessed wrong, and a rigged export (glTF 2.0) brings its own joints and weights";
}

static void say_failures(const char *name, const bind_args *a, const bound_body *body)
{
	const bind_gate_result *g = &body->gate;
	if (g->failed & BIND_GATE_TEARS) {
		cli_warn("%s: the skin tears at %s: an edge stretched to %.1f times its bind length %s (%d edges past "
			 "%.0fx and %.0f%% of the skeleton's extent); %s\n", name, region_name(body, &g->stretch),
			 (double)g->stretch.value, where(body, &g->stretch).s, g->torn_edges,
			 (double)bind_gate_default_limits.stretch_ratio,
			 100.0 * (double)bind_gate_default_limits.stretch_extent, fix_for(a, body, BIND_GATE_TEARS));
	}
	if (g->failed & BIND_GATE_DRIFT) {
		cli_warn("%s: a part leaves its bones at %s: a vertex's distance to the posed skeleton grows by "
			 "%.1f%% of its extent %s (%d vertices past %.0f%%); %s\n", name, region_name(body, &g->drift),
			 100.0 * (double)g->drift.value, where(body, &g->drift).s, g->drifting,
			 100.0 * (double)bind_gate_default_limits.drift, fix_for(a, body, BIND_GATE_DRIFT));
	}
	if (g->failed & BIND_GATE_ROOT)
		cli_warn("%s: %s moves, but %.0f%% of its vertices are bound to the root alone (%d such vertices in "
			"all): its joints mapped to nothing; %s\n", name, region_name(body, &g->root),
			100.0 * (double)g->root.value, g->root_moving, fix_for(a, body, BIND_GATE_ROOT));
	if (g->failed & BIND_GATE_RIGID)
		cli_warn("%s: %s stays rigid: its vertices follow its bone %.2f of the way (at least %.2f wanted); "
			"%s\n", name, region_name(body, &g->rigid), (double)g->rigid.value,
			(double)bind_gate_default_limits.follow_min, fix_for(a, body, BIND_GATE_RIGID));
}

static int run_moves(const bound_body *body, bind_gate_work *w, runtime_skin *sk, skel_pose *pose)
{
	for (int k = 0; k < body->rom.count; k++) {
		bind_rom_pose(&body->skel, &body->pose, &body->rom.move[k], pose);
		runtime_skin_pose(sk, pose);
		runtime_skin_run(sk, SKIN_DQBS, w->xyz, w->nrm);
		bind_gate_add(w, pose, w->xyz, &body->rom.move[k], k, 0);
	}
	return 0;
}

/* Frames of the motion, at most GATE_FRAMES of them evenly spread. */
#define GATE_FRAMES 240

static int run_motion(const char *path, long cap, const bound_body *body, bind_gate_work *w, runtime_skin *sk)
{
	static motion_file mo;
	static amc_frame f;
	long total = motion_file_count(path, &body->skel), n = 0;
	if (total < 0 || motion_file_open(&mo, path, &body->skel) < 0)
		return -1;
	long stride = total > cap ? (total + cap - 1) / cap : 1;
	int rc;
	while ((rc = motion_file_next(&mo, &f)) > 0) {
		if (n++ % stride)
			continue;
		runtime_skin_frame(sk, f.value);
		runtime_skin_run(sk, SKIN_DQBS, w->xyz, w->nrm);
		bind_gate_add(w, &sk->pose, w->xyz, NULL, -1, f.number);
	}
	motion_file_close(&mo);
	return rc < 0 ? -1 : 0;
}

int setup_gate(const bind_args *a, const char *name, bound_body *body)
{
	setup_scratch *sc = setup_scratch_area();
	bind_gate_work *w = &sc->gate.work;
	const mesh *m = &body->mesh;
	if (runtime_skin_init(&sc->gate.skin, &body->skel, &body->pose, m, &body->weights, name) < 0)
		return -1;
	bind_rom_build(&body->skel, &body->pose, &body->rom);
	bind_gate_start(w, &body->skel, &body->pose, m, &body->weights, body->has_orphans ? body->orphan : NULL,
			body->has_held ? body->held : NULL, NULL);
	run_moves(body, w, &sc->gate.skin, &sc->gate.pose);
	for (int i = 0; i < a->gate_motion_count; i++) {
		long cap = GATE_FRAMES / a->gate_motion_count;
		if (run_motion(a->gate_motion[i], cap < 30 ? 30 : cap, body, w, &sc->gate.skin) < 0)
			return -1;
	}
	bind_gate_finish(w, &body->gate);
	if (a->gate_report)
		setup_gate_report(body);
	if (!body->gate.failed)
		return 0;
	say_failures(name, a, body);
	if (a->force) {
		cli_warn("%s: --force: bound anyway\n", name);
		return 0;
	}
	cli_warn("%s: bind refused (bind --report prints every figure; --force binds anyway)\n", name);
	return -1;
}

static const char *verdict(const bound_body *body, unsigned check)
{
	return body->gate.failed & check ? "FAILED" : "ok";
}

void setup_gate_report(const bound_body *body)
{
	const bind_gate_result *g = &body->gate;
	const bind_gate_limits *lim = &bind_gate_default_limits;
	cli_warn("quality gate: %d range-of-motion poses, %ld motion frames, skeleton extent %.4g\n", g->moves,
		g->frames, (double)g->extent);
	cli_warn("  tears: worst edge %.2f times its bind length (%s, %s), %d edges ever past 2x, %d past %.0fx and "
		 "%.0f%%: %s\n", (double)g->stretch.value, region_name(body, &g->stretch), where(body, &g->stretch).s,
		 g->doubled_edges, g->torn_edges,
		(double)lim->stretch_ratio, 100.0 * (double)lim->stretch_extent, verdict(body, BIND_GATE_TEARS));
	cli_warn("  grow: an edge longer by %.2f%% of the extent at most (%s, %s)\n", 100.0 * (double)g->grow.value,
		 region_name(body, &g->grow), where(body, &g->grow).s);
	cli_warn("  drift: a vertex's distance to the posed skeleton grew by %.2f%% of its extent at most (%s), "
		"%d vertices past %.0f%%: %s\n", 100.0 * (double)g->drift.value, region_name(body, &g->drift),
		g->drifting, 100.0 * (double)lim->drift, verdict(body, BIND_GATE_DRIFT));
	cli_warn("  closer: and shrank by %.2f%% at most (%s: contact, not judged)\n", 100.0 * (double)g->closer.value,
		region_name(body, &g->closer));
	cli_warn("  root: %.1f%% of a moving region's vertices bound to the root alone at most (%s), %d in all, "
		"limit %.0f%%: %s\n", 100.0 * (double)g->root.value, region_name(body, &g->root), g->root_moving,
		100.0 * (double)lim->root_share, verdict(body, BIND_GATE_ROOT));
	cli_warn("  rigid: the region following its bone least follows it %.2f of the way (%s), limit %.2f: %s\n",
		(double)g->rigid.value, region_name(body, &g->rigid), (double)lim->follow_min,
		verdict(body, BIND_GATE_RIGID));
}
