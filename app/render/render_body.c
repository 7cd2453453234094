/* The body: its program (lit as seen from the camera's side), its colours
 * (the skin's, the bones', the differences'), skinned on the CPU or in
 * the vertex shader. */
#include <string.h>

#include "render_internal.h"

static const float skin_rgb[3] = MESH_SKIN_RGB;

/* Bone uniforms in the layout the skinning shaders read. */
static int bone_uniforms(renderer *r, const skin_bones *b, int as_dq)
{
	float *u = r->bone_uniforms;
	for (int i = 0; i < r->bone_count; i++) {
		if (as_dq) {
			const float *q = b->dq8[i]; /* (w x y z) pairs to (x y z w) */
			float v[8] = { q[1], q[2], q[3], q[0], q[5], q[6], q[7], q[4] };
			memcpy(u + 8 * i, v, sizeof v);
		} else {
			memcpy(u + 12 * i, b->lbs12[i], 12 * sizeof(float));
		}
	}
	return r->bone_count * (as_dq ? 2 : 3);
}

static void body_program(renderer *r, shader_kind k, const mat4 *vp, int use_col, int use_tex, float azimuth)
{
	const gl_api *gl = r->gl;
	/* the lights turn with the camera about the vertical: a close-up from
	 * behind a joint is lit as well as the usual front view */
	quat turn = quat_from_axis_angle(vec3_make(0.0f, 1.0f, 0.0f), azimuth - RENDER_CAMERA_AZIMUTH);
	vec3 key = quat_rotate(turn, vec3_normalize(vec3_make(0.45f, 0.8f, 0.55f)));
	vec3 fill = quat_rotate(turn, vec3_normalize(vec3_make(-0.7f, 0.25f, 0.2f)));
	gl->UseProgram(r->prog[k]);
	gl->UniformMatrix4fv(render_loc[k][U_MVP], 1, GL_FALSE, vp->m);
	gl->Uniform3f(render_loc[k][U_KEY], key.x, key.y, key.z);
	gl->Uniform3f(render_loc[k][U_FILL], fill.x, fill.y, fill.z);
	gl->Uniform3fv(render_loc[k][U_SKIN], 1, skin_rgb);
	gl->Uniform1f(render_loc[k][U_USE_COL], use_col ? 1.0f : 0.0f);
	gl->Uniform1i(render_loc[k][U_TEX], 1);
	gl->Uniform1f(render_loc[k][U_USE_TEX], use_tex ? 1.0f : 0.0f);
}

/* The body's texture coordinates, where its own colours are drawn and it
 * has a texture (render_set_texture); 1 when bound. */
static int bind_texture(renderer *r, const render_frame *f)
{
	const gl_api *gl = r->gl;
	if (!r->tex_ready || !r->look_ready || f->view == RENDER_VIEW_WEIGHTS || f->view == RENDER_VIEW_DIFFERENCE)
		return 0;
	gl->ActiveTexture(GL_TEXTURE1);
	gl->BindTexture(GL_TEXTURE_2D, r->body_tex);
	gl->ActiveTexture(GL_TEXTURE0);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_uv);
	render_attrib(gl, ATTR_UV, 2, 8, 0);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_sampled);
	gl->EnableVertexAttribArray(ATTR_SAMPLED);
	gl->VertexAttribPointer(ATTR_SAMPLED, 1, GL_UNSIGNED_BYTE, GL_FALSE, 1, (const void *)0);
	return 1;
}

/* The vertex colours: the bones' (weights view), the differences'
 * (difference view, once uploaded), the body's own (render_set_colours),
 * else none (the skin's colour). */
static int bind_colours(renderer *r, const render_frame *f)
{
	const gl_api *gl = r->gl;
	if (f->view == RENDER_VIEW_DIFFERENCE && r->diff_ready) {
		gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_diff);
		gl->EnableVertexAttribArray(ATTR_COL);
		gl->VertexAttribPointer(ATTR_COL, 3, GL_UNSIGNED_BYTE, GL_TRUE, 4, (const void *)0);
		return 1;
	}
	if (f->view != RENDER_VIEW_WEIGHTS && f->view != RENDER_VIEW_DIFFERENCE && r->look_ready) {
		gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_look);
		gl->EnableVertexAttribArray(ATTR_COL);
		gl->VertexAttribPointer(ATTR_COL, 3, GL_UNSIGNED_BYTE, GL_TRUE, 3, (const void *)0);
		return 1;
	}
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_static);
	render_attrib(gl, ATTR_COL, 3, STATIC_STRIDE, 24);
	return f->view == RENDER_VIEW_WEIGHTS;
}

void render_body(renderer *r, const mat4 *vp, const render_frame *f, int panel)
{
	render_body_seen(r, vp, f, panel, r->cam.azimuth);
}

void render_body_seen(renderer *r, const mat4 *vp, const render_frame *f, int panel, float azimuth)
{
	const gl_api *gl = r->gl;
	const render_panel *p = &f->panel[panel];
	int use_col = bind_colours(r, f), use_tex = bind_texture(r, f);
	if (p->pos) {
		body_program(r, SHADER_BODY_CPU, vp, use_col, use_tex, azimuth);
		gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_skinned[panel]);
		render_attrib(gl, ATTR_POS, 3, 12, 0);
		if (p->nrm)
			render_attrib(gl, ATTR_NRM, 3, 12, (size_t)r->vert_count * 12);
		else
			render_attrib_snorm16(gl, ATTR_NRM, 3, (size_t)r->vert_count * 12);
	} else {
		int as_dq = p->algo != SKIN_LBS;
		shader_kind k = as_dq ? SHADER_BODY_DQBS : SHADER_BODY_LBS;
		body_program(r, k, vp, use_col, use_tex, azimuth);
		gl->Uniform4fv(render_loc[k][U_BONE], bone_uniforms(r, f->bones, as_dq), r->bone_uniforms);
		gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_static);
		render_attrib(gl, ATTR_POS, 3, STATIC_STRIDE, 0);
		render_attrib(gl, ATTR_NRM, 3, STATIC_STRIDE, 12);
		render_attrib(gl, ATTR_BONES, 4, STATIC_STRIDE, 36);
		render_attrib(gl, ATTR_WEIGHTS, 4, STATIC_STRIDE, 52);
	}
	gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo);
	gl->DrawElements(GL_TRIANGLES, r->index_count, GL_UNSIGNED_SHORT, 0);
	render_disable_attribs(gl);
}

