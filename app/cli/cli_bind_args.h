/* The binding options shared by the skintool commands that need a bound
 * body (bind, skin, metrics, pack):
 *   --group G               keep only the faces of OBJ group/object G (default:
 *                           cli_mesh_pick.h)
 *   --fit, --no-fit         scale and move the mesh onto the skeleton (bind_fit.h);
 *                           default: when their sizes disagree (cli_mesh_place.h)
 *   --bind-pose P.amc[:F]   bind in frame F of P (the number written in the
 *                           file; default its first frame), or `rest` for the
 *                           rest pose; default: the mesh's own (cli_mesh_place.h)
 *   --weights W.csv         read the weights instead of computing them (bind.h);
 *   --weights mesh          a rigged mesh's own (glTF, FBX, COLLADA: the importer)
 *   --joint-map FILE        a rigged mesh's joints -> skeleton bones (rig_map_file.h)
 *   --rig FILE.mhskel       an OBJ's MakeHuman skeleton and the weights file it
 *                           names (rig_makehuman.h): the OBJ binds as a rigged mesh
 *   --force                 bind even when the quality gate (cli_bind_gate.h) fails
 *   --balance on|off        volume balancing of computed weights (bind_balance.h);
 *                           default on for the generated body (also as the OBJ
 *                           `skintool mannequin` writes), off for a mesh of
 *                           your own: on the MakeHuman A-pose the regions its
 *                           large hip moments need reach the knee (max radius
 *                           ratio 10.1 -> 12.1 on 02_01)
 * and the one call that turns them into a skeleton, a mesh and weights. */
#ifndef CLI_BIND_ARGS_H
#define CLI_BIND_ARGS_H

#include "bind.h"
#include "bind_balance.h"
#include "bind_fit.h"
#include "bind_gate.h"
#include "bind_pose_guess.h"
#include "cli_opts.h"
#include "mesh.h"


typedef struct bind_args {
	const char *group;          /* NULL: every face */
	int fit, no_fit;
	int rest_pose;              /* --bind-pose rest */
	const char *pose_path;      /* NULL: the rest pose, or the mesh's own */
	long pose_frame;            /* -1: the file's first frame */
	const char *weights_path;   /* NULL: automatic weights */
	int weights_mesh;           /* --weights mesh: a rigged mesh's own */
	const char *joint_map;      /* --joint-map FILE */
	const char *rig;            /* --rig FILE.mhskel: the OBJ's MakeHuman rig */
	int balance;                /* -1 default, 0 off, 1 on (bind_balance) */
	int force;                  /* --force: a bind the gate fails is kept, with the warning */
	const char *const *gate_motion; /* the command's clips, whose frames the gate also checks */
	int gate_motion_count;
	int gate_report;            /* print every figure of the gate (bind --report) */
	char pose_buf[1024];        /* pose_path without its :F */
} bind_args;

void bind_args_init(bind_args *a);

/* The options above as a cli_opts table (ids BIND_OPT_FIRST and up), and
 * taking one: 0, or -1 after reporting a bad value (prog names the
 * command). */
#define BIND_OPT_FIRST 500
extern const cli_opt bind_opts[];
int bind_args_take(bind_args *a, const char *prog, int id, const char *value);
/* 1 when id is one of bind_opts'. */
#define BIND_OPT_ID(id) ((id) >= BIND_OPT_FIRST && (id) < BIND_OPT_FIRST + 16)


/* Everything bind_args_load produces: tens of MB, keep it static. */
typedef struct bound_body {
	skel skel;
	skel_pose pose;             /* the bind pose */
	long pose_frame;            /* frame bound in, -1 for the rest pose or a derived one */
	float pose_value[SKP_MAX_DOF]; /* its channel values (all 0 for the rest pose) */
	int arms_raised;            /* > 0: derived from the rest pose by skel_tpose */
	bind_guess_result guess;    /* .turned > 0: the mesh's own pose (bind_pose_guess.h) */
	mesh mesh;                  /* fitted when --fit */
	int fitted;
	bind_fit_result fit;
	bind_rig rig;
	skin_weights weights;
	int automatic;              /* 1: computed (info, bind_ns valid), 0: --weights */
	int rigged;                 /* the mesh has weights of its own that map onto the
				     * skeleton (the importer): --weights mesh can use them */
	bind_info info;
	bind_balance_info balance;  /* valid when automatic and balanced */
	int balanced;
	unsigned long long bind_ns; /* time bind_prepare + bind_weights (+ bind_balance) took */
	uint8_t orphan[SKP_MAX_VERTS]; /* with has_orphans: vertices left to the root for want of a
					* mapped joint (the importer's, --weights mesh) */
	int has_orphans;
	bind_rom rom;               /* the gate's range of motion */
	bind_gate_result gate;      /* and its figures (cli_bind_gate.h) */
} bound_body;

/* Loads skeleton asf, mesh obj (group), the bind pose, fits the mesh when
 * asked, then computes the weights (default bind_params) or reads them,
 * and checks the result (cli_bind_gate.h): a failing bind is refused.
 * obj NULL or BIND_MESH_GENERATED: the generated body (skintool mannequin)
 * in the rest pose with its arms out (skel_tpose.h), which is then the
 * bind pose (a file of that name is ./generated).
 * Returns 0, or -1 after reporting the error on stderr. */
#define BIND_MESH_GENERATED "generated"
int bind_args_load(const bind_args *a, const char *asf, const char *obj, bound_body *body);

/* Meshes other than OBJ (glTF, FBX, COLLADA), and an OBJ with --rig, go
 * to this loader, which
 * skintool sets (its importer links the asset library; skinplay reads OBJ
 * and packed images only). It fills body->mesh, the bind pose and the
 * weights (bind_args_auto_weights for computed ones) as bind_args_load
 * does for an OBJ; body->skel and the requested pose are loaded before.
 * Returns 0, or -1 after reporting the error. */
typedef int (*bind_mesh_importer)(const bind_args *a, const char *path, bound_body *body);
void bind_args_set_importer(bind_mesh_importer importer);

/* 1 when path names a mesh the importer reads rather than an OBJ. */
int bind_args_is_interchange(const char *path);

/* The paper's weights (balanced when asked, or by default for the
 * generated body) on body->mesh in body->pose. Returns 0, or -1 after
 * reporting the error. */
int bind_args_auto_weights(const bind_args *a, int generated, const char *name, bound_body *body);

/* The weights file's (--weights W.csv) when given, else as
 * bind_args_auto_weights. Returns 0, or -1 after reporting the error. */
int bind_args_weights(const bind_args *a, int generated, const char *name, bound_body *body);

/* The bind pose's values, or NULL when it is the rest pose. */
const float *bound_pose_values(const bound_body *body);

#endif
