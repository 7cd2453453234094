/* The binding options shared by the skintool commands that need a bound
 * body (bind, skin, metrics, pack):
 *   --group G               keep only the faces of OBJ group/object G (default:
 *                           setup_mesh_pick.h)
 *   --fit, --no-fit         scale and move the mesh onto the skeleton (bind_fit.h);
 *                           default: when their sizes disagree (setup_mesh_place.h)
 *   --bind-pose P.amc[:F]   bind in frame F of P (the number written in the
 *                           file; default its first frame), or `rest` for the
 *                           rest pose; default: the mesh's own (setup_mesh_place.h)
 *   --weights W.csv         read the weights instead of computing them (bind.h);
 *   --weights mesh          a rigged mesh's own (glTF, FBX, COLLADA: the importer)
 *   --joint-map FILE        a rigged mesh's joints -> skeleton bones (rig_map_file.h)
 *   --rig FILE.mhskel       an OBJ's MakeHuman skeleton and the weights file it
 *                           names (rig_makehuman.h): the OBJ binds as a rigged mesh
 *   --force                 bind even when the quality gate (setup_gate.h) fails
 *   --balance on|off        volume balancing of computed weights (bind_balance.h);
 *                           default on for the generated body (also as the OBJ
 *                           `skintool mannequin` writes), off for a mesh of
 *                           your own: on the MakeHuman A-pose the regions its
 *                           large hip moments need reach the knee (max radius
 *                           ratio 10.1 -> 12.1 on 02_01)
 * parsed into a bind_args; app/setup (setup_bind.h) turns them into a
 * skeleton, a mesh and weights. */
#ifndef CLI_BIND_ARGS_H
#define CLI_BIND_ARGS_H

#include "cli_opts.h"

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

#endif
