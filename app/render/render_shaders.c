#include "render_shaders.h"

#include "skp_format.h"

#define STR_(x) #x
#define STR(x) STR_(x)

static const char body_vs[] =
	"attribute vec3 a_pos;\n"
	"attribute vec3 a_nrm;\n"
	"attribute vec3 a_col;\n"
	"attribute vec2 a_uv;\n"
	"attribute float a_sampled;\n"
	"uniform mat4 u_mvp;\n"
	"varying vec3 v_nrm;\n"
	"varying vec3 v_col;\n"
	"varying vec3 v_tex;\n"
	"#if defined(SKIN_LBS) || defined(SKIN_DQBS)\n"
	"attribute vec4 a_bones;\n"
	"attribute vec4 a_weights;\n"
	"uniform vec4 u_bone[BONE_VEC4S];\n"
	"#endif\n"
	"#ifdef SKIN_LBS\n"
	/* rows of the blended 3x4 matrix */
	"void skin(inout vec3 p, inout vec3 n) {\n"
	"  vec4 r0 = vec4(0.0), r1 = vec4(0.0), r2 = vec4(0.0);\n"
	"  for (int k = 0; k < 4; k++) {\n"
	"    int b = int(a_bones[k] + 0.5) * 3;\n"
	"    float w = a_weights[k];\n"
	"    r0 += w * u_bone[b]; r1 += w * u_bone[b + 1]; r2 += w * u_bone[b + 2];\n"
	"  }\n"
	"  vec4 hp = vec4(p, 1.0);\n"
	"  p = vec3(dot(r0, hp), dot(r1, hp), dot(r2, hp));\n"
	"  n = normalize(vec3(dot(r0.xyz, n), dot(r1.xyz, n), dot(r2.xyz, n)));\n"
	"}\n"
	"#endif\n"
	"#ifdef SKIN_DQBS\n"
	/* dual quaternions as (x y z w) pairs: real, dual */
	"void skin(inout vec3 p, inout vec3 n) {\n"
	"  vec4 pivot = u_bone[int(a_bones[0] + 0.5) * 2];\n"
	"  vec4 br = vec4(0.0), bd = vec4(0.0);\n"
	"  for (int k = 0; k < 4; k++) {\n"
	"    int b = int(a_bones[k] + 0.5) * 2;\n"
	"    vec4 r = u_bone[b];\n"
	"    float w = dot(r, pivot) < 0.0 ? -a_weights[k] : a_weights[k];\n"
	"    br += w * r; bd += w * u_bone[b + 1];\n"
	"  }\n"
	"  float inv = inversesqrt(dot(br, br));\n"
	"  br *= inv; bd *= inv;\n"
	"  vec3 t = 2.0 * (br.w * bd.xyz - bd.w * br.xyz + cross(br.xyz, bd.xyz));\n"
	"  p = p + 2.0 * cross(br.xyz, cross(br.xyz, p) + br.w * p) + t;\n"
	"  n = n + 2.0 * cross(br.xyz, cross(br.xyz, n) + br.w * n);\n"
	"}\n"
	"#endif\n"
	"void main() {\n"
	"  vec3 p = a_pos, n = a_nrm;\n"
	"#if defined(SKIN_LBS) || defined(SKIN_DQBS)\n"
	"  skin(p, n);\n"
	"#endif\n"
	"  v_nrm = n;\n"
	"  v_col = a_col;\n"
	"  v_tex = vec3(a_uv, a_sampled);\n"
	"  gl_Position = u_mvp * vec4(p, 1.0);\n"
	"}\n";

/* A key light from the front right above, a cool fill from the left and a
 * little ambient: enough shading to read elbows and twists. */
static const char body_fs[] =
	"precision mediump float;\n"
	"varying vec3 v_nrm;\n"
	"varying vec3 v_col;\n"
	"varying vec3 v_tex;\n"
	"uniform vec3 u_key;\n"
	"uniform vec3 u_fill;\n"
	"uniform vec3 u_skin;\n"
	"uniform float u_use_col;\n"
	"uniform sampler2D u_tex;\n"
	"uniform float u_use_tex;\n"
	"void main() {\n"
	"  vec3 n = normalize(v_nrm);\n"
	/* the texture's colour times the vertex's, where the vertex samples it */
	"  vec3 t = mix(vec3(1.0), texture2D(u_tex, v_tex.xy).rgb, v_tex.z * u_use_tex);\n"
	"  vec3 base = mix(u_skin, v_col * t, u_use_col);\n"
	"  float key = max(dot(n, u_key), 0.0);\n"
	"  float fill = max(dot(n, u_fill), 0.0);\n"
	"  vec3 c = base * (0.22 + 0.78 * key) + vec3(0.10, 0.12, 0.16) * fill;\n"
	"  gl_FragColor = vec4(c, 1.0);\n"
	"}\n";

static const char flat_vs[] =
	"attribute vec3 a_pos;\n"
	"uniform mat4 u_mvp;\n"
	"uniform float u_point;\n"
	"void main() {\n"
	"  gl_Position = u_mvp * vec4(a_pos, 1.0);\n"
	"  gl_PointSize = u_point;\n"
	"}\n";

static const char flat_fs[] =
	"precision mediump float;\n"
	"uniform vec4 u_color;\n"
	"void main() { gl_FragColor = u_color; }\n";

static const char shadow_vs[] =
	"attribute vec3 a_pos;\n"
	"attribute vec2 a_uv;\n"
	"uniform mat4 u_mvp;\n"
	"varying vec2 v_uv;\n"
	"void main() { v_uv = a_uv; gl_Position = u_mvp * vec4(a_pos, 1.0); }\n";

static const char shadow_fs[] =
	"precision mediump float;\n"
	"varying vec2 v_uv;\n"
	"uniform float u_strength;\n"
	"void main() {\n"
	"  float r2 = dot(v_uv, v_uv);\n"
	"  float a = u_strength * (1.0 - smoothstep(0.0, 1.0, r2));\n"
	"  gl_FragColor = vec4(0.0, 0.0, 0.0, a);\n"
	"}\n";

static const char text_vs[] =
	"attribute vec3 a_pos;\n"
	"attribute vec2 a_uv;\n"
	"uniform mat4 u_mvp;\n"
	"varying vec2 v_uv;\n"
	"void main() { v_uv = a_uv; gl_Position = u_mvp * vec4(a_pos, 1.0); }\n";

static const char text_fs[] =
	"precision mediump float;\n"
	"varying vec2 v_uv;\n"
	"uniform sampler2D u_font;\n"
	"uniform vec4 u_color;\n"
	"void main() { gl_FragColor = vec4(u_color.rgb, u_color.a * texture2D(u_font, v_uv).a); }\n";

typedef struct shader_src {
	const char *defines, *vs, *fs;
} shader_src;

static const shader_src sources[SHADER_COUNT] = {
	[SHADER_BODY_CPU] = { "", body_vs, body_fs },
	[SHADER_BODY_LBS] = { "#define SKIN_LBS\n#define BONE_VEC4S " STR(RENDER_BONE_VEC4S) "\n", body_vs, body_fs },
	[SHADER_BODY_DQBS] = { "#define SKIN_DQBS\n#define BONE_VEC4S " STR(RENDER_BONE_VEC4S) "\n", body_vs, body_fs },
	[SHADER_FLAT] = { "", flat_vs, flat_fs },
	[SHADER_SHADOW] = { "", shadow_vs, shadow_fs },
	[SHADER_TEXT] = { "", text_vs, text_fs },
};

static GLuint compile(const gl_api *gl, GLenum type, const char *defines, const char *body,
		      skp_error *err)
{
	const char *parts[3] = { "#version 100\n", defines, body };
	GLuint sh = gl->CreateShader(type);
	gl->ShaderSource(sh, 3, parts, NULL);
	gl->CompileShader(sh);
	GLint ok = 0;
	gl->GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
	if (ok)
		return sh;
	char log[160];
	gl->GetShaderInfoLog(sh, sizeof log, NULL, log);
	skp_fail(err, SKP_ERR_RANGE, 0, "%s shader does not compile: %s",
		 type == GL_VERTEX_SHADER ? "vertex" : "fragment", log);
	gl->DeleteShader(sh);
	return 0;
}

static void bind_attributes(const gl_api *gl, GLuint prog)
{
	gl->BindAttribLocation(prog, ATTR_POS, "a_pos");
	gl->BindAttribLocation(prog, ATTR_NRM, "a_nrm");
	gl->BindAttribLocation(prog, ATTR_COL, "a_col");
	gl->BindAttribLocation(prog, ATTR_BONES, "a_bones");
	gl->BindAttribLocation(prog, ATTR_WEIGHTS, "a_weights");
	gl->BindAttribLocation(prog, ATTR_UV, "a_uv");
	gl->BindAttribLocation(prog, ATTR_SAMPLED, "a_sampled");
}

GLuint shader_build(const gl_api *gl, shader_kind kind, skp_error *err)
{
	const shader_src *src = &sources[kind];
	GLuint vs = compile(gl, GL_VERTEX_SHADER, src->defines, src->vs, err);
	if (!vs)
		return 0;
	GLuint fs = compile(gl, GL_FRAGMENT_SHADER, src->defines, src->fs, err);
	if (!fs) {
		gl->DeleteShader(vs);
		return 0;
	}
	GLuint prog = gl->CreateProgram();
	gl->AttachShader(prog, vs);
	gl->AttachShader(prog, fs);
	bind_attributes(gl, prog);
	gl->LinkProgram(prog);
	gl->DeleteShader(vs);
	gl->DeleteShader(fs);
	GLint ok = 0;
	gl->GetProgramiv(prog, GL_LINK_STATUS, &ok);
	if (ok)
		return prog;
	char log[160];
	gl->GetProgramInfoLog(prog, sizeof log, NULL, log);
	skp_fail(err, SKP_ERR_RANGE, 0, "shader program %d does not link: %s", (int)kind, log);
	gl->DeleteProgram(prog);
	return 0;
}
