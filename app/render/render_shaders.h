/* GLSL ES 1.00 sources of the renderer and the code that builds them. */
#ifndef RENDER_SHADERS_H
#define RENDER_SHADERS_H

#include "gl_api.h"

/* Attribute slots, bound before linking so every program agrees. */
enum {
	ATTR_POS = 0,
	ATTR_NRM = 1,
	ATTR_COL = 2,
	ATTR_BONES = 3,
	ATTR_WEIGHTS = 4,
	ATTR_UV = 5,      /* glyphs', the shadow's; the body's texture coordinates */
	ATTR_SAMPLED = 6, /* 1: the body's vertex samples its texture */
};

/* Bone uniforms the GPU skinning shaders may use: GLES 2.0 guarantees 128
 * vertex uniform vectors; the matrices and lights take the rest. */
#define RENDER_UNIFORM_BUDGET 128
#define RENDER_UNIFORMS_RESERVED 8
#define RENDER_BONE_VEC4S (RENDER_UNIFORM_BUDGET - RENDER_UNIFORMS_RESERVED)

typedef enum shader_kind {
	SHADER_BODY_CPU,    /* positions already skinned */
	SHADER_BODY_LBS,    /* skinned in the vertex shader, 3 vec4 per bone */
	SHADER_BODY_DQBS,   /* skinned in the vertex shader, 2 vec4 per bone */
	SHADER_FLAT,        /* lines and points in one colour */
	SHADER_SHADOW,      /* the soft blob under the body */
	SHADER_TEXT,        /* HUD glyphs from the font atlas */
	SHADER_COUNT
} shader_kind;

/* Compiles and links one program; 0 and err (with the driver's log) on
 * failure. */
GLuint shader_build(const gl_api *gl, shader_kind kind, skp_error *err);

#endif
