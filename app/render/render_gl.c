/* The renderer's small GL helpers, shared by its drawing files: a stream
 * of vertices through the one scratch buffer, the flat-colour program,
 * attribute pointers, and text in the built-in font. */
#include <string.h>

#include "render_font.h"
#include "render_internal.h"

void render_logical_size(const renderer *r, int *w, int *h)
{
	int sideways = r->rotation & 1;
	*w = sideways ? r->height : r->width;
	*h = sideways ? r->width : r->height;
}

/* Logical rectangle to the physical viewport, following mat4_rotate_z90. */
void render_set_viewport(const renderer *r, render_rect a)
{
	int lw, lh;
	render_logical_size(r, &lw, &lh);
	switch (r->rotation) {
	case 1: r->gl->Viewport(lh - a.y - a.h, a.x, a.h, a.w); break;
	case 2: r->gl->Viewport(lw - a.x - a.w, lh - a.y - a.h, a.w, a.h); break;
	case 3: r->gl->Viewport(a.y, lw - a.x - a.w, a.h, a.w); break;
	default: r->gl->Viewport(a.x, a.y, a.w, a.h); break;
	}
}


void render_stream(renderer *r, const float *data, int floats)
{
	const gl_api *gl = r->gl;
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_misc);
	gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)floats * 4, data, GL_STREAM_DRAW);
}

void render_use_flat(renderer *r, const mat4 *vp, const float rgba[4], float point)
{
	const gl_api *gl = r->gl;
	gl->UseProgram(r->prog[SHADER_FLAT]);
	gl->UniformMatrix4fv(render_loc[SHADER_FLAT][U_MVP], 1, GL_FALSE, vp->m);
	gl->Uniform4fv(render_loc[SHADER_FLAT][U_COLOR], 1, rgba);
	gl->Uniform1f(render_loc[SHADER_FLAT][U_POINT], point);
}

void render_flat(renderer *r, const mat4 *vp, const float rgba[4], GLenum mode, const float *xyz, int vertices,
		 float line_width)
{
	const gl_api *gl = r->gl;
	render_use_flat(r, vp, rgba, 1.0f);
	render_stream(r, xyz, 3 * vertices);
	render_attrib(gl, ATTR_POS, 3, 12, 0);
	if (line_width != 1.0f)
		gl->LineWidth(line_width);
	gl->DrawArrays(mode, 0, vertices);
	if (line_width != 1.0f)
		gl->LineWidth(1.0f);
	render_disable_attribs(gl);
}

void render_attrib(const gl_api *gl, GLuint slot, int size, int stride, size_t offset)
{
	gl->EnableVertexAttribArray(slot);
	gl->VertexAttribPointer(slot, size, GL_FLOAT, GL_FALSE, stride, (const void *)offset);
}

/* 16-bit snorm values, which GL turns into -1..1 */
void render_attrib_snorm16(const gl_api *gl, GLuint slot, int size, size_t offset)
{
	gl->EnableVertexAttribArray(slot);
	gl->VertexAttribPointer(slot, size, GL_SHORT, GL_TRUE, 2 * size, (const void *)offset);
}

void render_disable_attribs(const gl_api *gl)
{
	for (GLuint a = 0; a <= ATTR_SAMPLED; a++)
		gl->DisableVertexAttribArray(a);
}

int render_text(renderer *r, render_rect area, int x, int y, int scale, const char *s,
		const float rgba[4])
{
	const gl_api *gl = r->gl;
	int n = 0, pen = x;
	float top = (float)(area.h - y), du = 1.0f / (float)r->font_w, dv = 1.0f / 16.0f;
	for (; *s && n < RENDER_MAX_TEXT; s++, pen += (FONT_GLYPH_W + 1) * scale) {
		int g = font_glyph_index(*s);
		if (g < 0)
			continue;
		float x0 = (float)(pen - scale), x1 = x0 + (float)(FONT_CELL_W * scale);
		float y1 = top + (float)scale, y0 = y1 - (float)(FONT_CELL_H * scale);
		float u0 = (float)(g * FONT_CELL_W) * du, u1 = u0 + FONT_CELL_W * du;
		float v0 = 0.0f, v1 = FONT_CELL_H * dv;
		float q[30] = { x0, y0, 0, u0, v1,  x1, y0, 0, u1, v1,  x1, y1, 0, u1, v0,
				x0, y0, 0, u0, v1,  x1, y1, 0, u1, v0,  x0, y1, 0, u0, v0 };
		memcpy(r->text + 30 * n++, q, sizeof q);
	}
	if (n == 0)
		return pen - x;
	mat4 ortho = mat4_ortho(0, (float)area.w, 0, (float)area.h, -1, 1);
	mat4 m = mat4_mul(&r->screen, &ortho);
	gl->UseProgram(r->prog[SHADER_TEXT]);
	gl->UniformMatrix4fv(render_loc[SHADER_TEXT][U_MVP], 1, GL_FALSE, m.m);
	gl->Uniform4fv(render_loc[SHADER_TEXT][U_COLOR], 1, rgba);
	gl->Uniform1i(render_loc[SHADER_TEXT][U_FONT], 0);
	gl->ActiveTexture(GL_TEXTURE0);
	gl->BindTexture(GL_TEXTURE_2D, r->font_tex);
	gl->Enable(GL_BLEND);
	gl->BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
	gl->Disable(GL_DEPTH_TEST);
	render_stream(r, r->text, 30 * n);
	render_attrib(gl, ATTR_POS, 3, 20, 0);
	render_attrib(gl, ATTR_UV, 2, 20, 12);
	gl->DrawArrays(GL_TRIANGLES, 0, 6 * n);
	render_disable_attribs(gl);
	gl->Enable(GL_DEPTH_TEST);
	gl->Disable(GL_BLEND);
	return pen - x;
}

int render_text_width(const char *s, int scale)
{
	return (int)strlen(s) * (FONT_GLYPH_W + 1) * scale;
}

