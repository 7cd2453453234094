#include "render.h"

#include <math.h>
#include <string.h>

#include "render_font.h"
#include "render_internal.h"
#include "render_shaders.h"


static const char *const uniform_names[U_COUNT] = {
	"u_mvp", "u_bone", "u_key", "u_fill", "u_skin", "u_use_col", "u_color", "u_point",
	"u_strength", "u_font", "u_tex", "u_use_tex",
};
GLint render_loc[SHADER_COUNT][U_COUNT];

/* Hues spread by the golden angle. */
vec3 render_bone_color(int bone)
{
	float h = fmodf((float)bone * 0.618034f, 1.0f) * 6.0f;
	float x = 1.0f - fabsf(fmodf(h, 2.0f) - 1.0f);
	vec3 c[6] = { { 1, x, 0 }, { x, 1, 0 }, { 0, 1, x }, { 0, x, 1 }, { x, 0, 1 }, { 1, 0, x } };
	vec3 rgb = c[(int)h % 6];
	return vec3_make(0.25f + 0.7f * rgb.x, 0.25f + 0.7f * rgb.y, 0.25f + 0.7f * rgb.z);
}

static void static_vertex(renderer *r, const skin_soa *soa, int v, float *o)
{
	vec3 col = vec3_make(0, 0, 0);
	o[0] = soa->px[v]; o[1] = soa->py[v]; o[2] = soa->pz[v];
	o[3] = soa->nx[v]; o[4] = soa->ny[v]; o[5] = soa->nz[v];
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		float w = soa->weight[k][v];
		int b = soa->bone[k][v];
		if (w > 0.0f && b != SKIN_IDENTITY_BONE) {
			col = vec3_madd(col, render_bone_color(b), w);
			r->bone_used[b] = 1;
		}
		/* the identity slot has no uniform: point it at bone 0 with its
		 * zero weight */
		o[9 + k] = b == SKIN_IDENTITY_BONE ? 0.0f : (float)b;
		o[13 + k] = w;
	}
	o[6] = col.x; o[7] = col.y; o[8] = col.z;
}

/* Uploads in chunks through r->misc: no buffer the size of the mesh. */
static void upload_static(renderer *r, const skin_soa *soa)
{
	const gl_api *gl = r->gl;
	const int chunk = (int)(sizeof r->misc / sizeof r->misc[0]) / STATIC_FLOATS;
	gl->GenBuffers(1, &r->vbo_static);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_static);
	gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)soa->count * STATIC_STRIDE, NULL, GL_STATIC_DRAW);
	for (int first = 0; first < soa->count; first += chunk) {
		int n = soa->count - first < chunk ? soa->count - first : chunk;
		for (int i = 0; i < n; i++)
			static_vertex(r, soa, first + i, r->misc + i * STATIC_FLOATS);
		gl->BufferSubData(GL_ARRAY_BUFFER, (GLintptr)first * STATIC_STRIDE,
				  (GLsizeiptr)n * STATIC_STRIDE, r->misc);
	}
}

static void upload_indices(renderer *r, const uint32_t (*tri)[3], int tri_count)
{
	const gl_api *gl = r->gl;
	uint16_t *stage = (uint16_t *)r->misc;
	const int chunk = (int)sizeof(r->misc) / (int)sizeof(uint16_t) / 3;
	gl->GenBuffers(1, &r->ibo);
	gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo);
	gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)tri_count * 6, NULL, GL_STATIC_DRAW);
	for (int first = 0; first < tri_count; first += chunk) {
		int n = tri_count - first < chunk ? tri_count - first : chunk;
		for (int t = 0; t < n; t++)
			for (int c = 0; c < 3; c++)
				stage[3 * t + c] = (uint16_t)tri[first + t][c];
		gl->BufferSubData(GL_ELEMENT_ARRAY_BUFFER, (GLintptr)first * 6, (GLsizeiptr)n * 6, stage);
	}
	r->index_count = tri_count * 3;
}

static void upload_font(renderer *r)
{
	const gl_api *gl = r->gl;
	uint8_t *atlas = (uint8_t *)r->text;
	r->font_w = 1;
	while (r->font_w < font_glyph_count() * FONT_CELL_W)
		r->font_w *= 2; /* power of two: GLES 2.0 wraps and mipmaps only those */
	font_rasterize(atlas, r->font_w);
	gl->GenTextures(1, &r->font_tex);
	gl->BindTexture(GL_TEXTURE_2D, r->font_tex);
	gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
	gl->TexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, r->font_w, 16, 0, GL_ALPHA, GL_UNSIGNED_BYTE, NULL);
	gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, r->font_w, FONT_CELL_H, GL_ALPHA, GL_UNSIGNED_BYTE, atlas);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

static skp_status build_programs(renderer *r, skp_error *err)
{
	for (int k = 0; k < SHADER_COUNT; k++) {
		r->prog[k] = shader_build(r->gl, (shader_kind)k, err);
		if (!r->prog[k])
			return err ? err->code : SKP_ERR_RANGE;
		for (int u = 0; u < U_COUNT; u++)
			render_loc[k][u] = r->gl->GetUniformLocation(r->prog[k], uniform_names[u]);
	}
	return SKP_OK;
}

/* Largest side of the bind-pose bounding box: a body's height, an arm's
 * length. */
static float body_extent(const skin_soa *soa)
{
	vec3 lo = vec3_make(soa->px[0], soa->py[0], soa->pz[0]), hi = lo;
	for (int v = 1; v < soa->count; v++) {
		vec3 q = vec3_make(soa->px[v], soa->py[v], soa->pz[v]);
		lo = vec3_min(lo, q);
		hi = vec3_max(hi, q);
	}
	vec3 d = vec3_sub(hi, lo);
	return fmaxf(d.x, fmaxf(d.y, d.z));
}

skp_status render_init(renderer *r, const gl_api *gl, int width, int height, int rotation,
		       const skel *s, const skin_soa *soa, const uint32_t (*tri)[3], int tri_count,
		       float floor_y, skp_error *err)
{
	memset(r, 0, sizeof *r);
	r->gl = gl;
	r->width = width;
	r->height = height;
	r->rotation = ((rotation / 90) % 4 + 4) % 4;
	r->skel = s;
	r->bone_count = s->count;
	r->vert_count = soa->count;
	r->floor_y = floor_y;
	r->screen = mat4_rotate_z90(r->rotation);
	if (soa->count > 65536)
		return skp_fail(err, SKP_ERR_LIMIT, 0,
				"%d vertices: GLES 2.0 draws at most 65536 with 16-bit indices", soa->count);
	skp_status rc = build_programs(r, err);
	if (rc)
		return rc;
	upload_static(r, soa);
	upload_indices(r, tri, tri_count);
	upload_font(r);
	gl->GenBuffers(RENDER_MAX_PANELS, r->vbo_skinned);
	for (int i = 0; i < RENDER_MAX_PANELS; i++) {
		gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_skinned[i]);
		gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)soa->count * 24, NULL, GL_DYNAMIC_DRAW);
	}
	gl->GenBuffers(1, &r->vbo_misc);
	gl->GenBuffers(1, &r->vbo_diff);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_diff);
	gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)soa->count * 4, NULL, GL_DYNAMIC_DRAW);
	gl->GenBuffers(1, &r->vbo_look);
	r->look_ready = 0;
	r->tex_ready = 0;
	camera_init(&r->cam, body_extent(soa), floor_y, RENDER_CAMERA_AZIMUTH);
	render_set_units(r, 0.0f);
	return gl->GetError() == GL_NO_ERROR ? SKP_OK
					      : skp_fail(err, SKP_ERR_RANGE, 0, "OpenGL error while uploading the body");
}

void render_set_colours(renderer *r, const uint8_t (*rgb)[3])
{
	const gl_api *gl = r->gl;
	r->look_ready = rgb != NULL;
	if (!rgb)
		return;
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_look);
	gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)r->vert_count * 3, rgb, GL_STATIC_DRAW);
}

skp_status render_init_notice(renderer *r, const gl_api *gl, int width, int height, int rotation, skp_error *err)
{
	memset(r, 0, sizeof *r);
	r->gl = gl;
	r->width = width;
	r->height = height;
	r->rotation = ((rotation / 90) % 4 + 4) % 4;
	r->screen = mat4_rotate_z90(r->rotation);
	skp_status rc = build_programs(r, err);
	if (rc)
		return rc;
	upload_font(r);
	gl->GenBuffers(1, &r->vbo_misc);
	return gl->GetError() == GL_NO_ERROR ? SKP_OK : skp_fail(err, SKP_ERR_RANGE, 0, "OpenGL error at start-up");
}

int render_gpu_fits(const renderer *r, skin_algo algo)
{
	int per_bone = algo == SKIN_LBS ? 3 : 2;
	return algo != SKIN_DQBS_FIXED && r->bone_count * per_bone <= RENDER_BONE_VEC4S;
}

void render_shutdown(renderer *r)
{
	const gl_api *gl = r->gl;
	if (!gl)
		return;
	for (int k = 0; k < SHADER_COUNT; k++)
		gl->DeleteProgram(r->prog[k]);
	gl->DeleteBuffers(1, &r->vbo_static);
	gl->DeleteBuffers(RENDER_MAX_PANELS, r->vbo_skinned);
	gl->DeleteBuffers(1, &r->ibo);
	gl->DeleteBuffers(1, &r->vbo_misc);
	gl->DeleteBuffers(1, &r->vbo_diff);
	gl->DeleteBuffers(1, &r->vbo_look);
	gl->DeleteTextures(1, &r->font_tex);
	render_texture_shutdown(r);
	r->gl = NULL;
}

void render_read_rgba(const renderer *r, uint8_t *rgba)
{
	r->gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
	r->gl->ReadPixels(0, 0, r->width, r->height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

void render_set_extent(renderer *r, vec3 lo, vec3 hi, int immediate)
{
	r->goal_lo = lo;
	r->goal_hi = hi;
	if (immediate || !r->framed) {
		r->ext_lo = lo;
		r->ext_hi = hi;
	}
	r->framed = 1;
}

void render_set_yaw(renderer *r, float yaw, int immediate)
{
	camera_turn_to(&r->cam, RENDER_CAMERA_AZIMUTH + yaw, immediate);
}

void render_set_units(renderer *r, float mm_per_unit)
{
	float tall = r->cam.height * mm_per_unit;
	r->size_assumed = !(tall >= 1000.0f && tall <= 2500.0f);
	r->mm_per_unit = r->size_assumed ? 1750.0f / r->cam.height : mm_per_unit;
}
