/* The body's base colour texture: its coordinates and which vertices
 * sample it in two static buffers, and its ETC1 mip chain on texture unit
 * 1 (unit 0 is the font's): handed to the GPU as it is where the GPU
 * samples ETC1 (OES_compressed_ETC1_RGB8_texture: the Raspberry Pi's V3D
 * does), else each level decoded to RGB565 (half the bytes of RGB8, and
 * what GLES 2 takes as GL_UNSIGNED_SHORT_5_6_5). */
#include <string.h>

#include "render_internal.h"
#include "tex_etc1.h"

#define GL_ETC1_RGB8_OES 0x8D64

/* one level at a time: level 0 is the largest */
static uint16_t level_rgb565[SKP_MAX_TEXTURE_SIDE * SKP_MAX_TEXTURE_SIDE + 1];

/* The extension named whole in the GL's list (not a longer name's start). */
static int gl_has(const gl_api *gl, const char *name)
{
	const char *list = (const char *)gl->GetString(GL_EXTENSIONS);
	size_t n = strlen(name);
	for (const char *at = list; at && (at = strstr(at, name)) != NULL; at += n)
		if ((at == list || at[-1] == ' ') && (at[n] == ' ' || at[n] == '\0'))
			return 1;
	return 0;
}

static skp_status upload_levels(renderer *r, const tex_image *t, int etc1, skp_error *err)
{
	const gl_api *gl = r->gl;
	gl->PixelStorei(GL_UNPACK_ALIGNMENT, 2);
	for (int i = 0; i < t->chain.levels; i++) {
		const tex_level *l = &t->chain.level[i];
		const uint8_t *blocks = t->etc1 + l->etc1_offset;
		if (etc1) {
			gl->CompressedTexImage2D(GL_TEXTURE_2D, i, GL_ETC1_RGB8_OES, l->width, l->height, 0,
						 (GLsizei)l->etc1_bytes, blocks);
			continue;
		}
		skp_status rc = tex_etc1_decode_rgb565(blocks, l->etc1_bytes, l->width, l->height, level_rgb565,
						       sizeof level_rgb565, err);
		if (rc)
			return rc;
		gl->TexImage2D(GL_TEXTURE_2D, i, GL_RGB, l->width, l->height, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5,
			       level_rgb565);
	}
	gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
	return SKP_OK;
}

static void upload_coordinates(renderer *r, const mesh *m)
{
	const gl_api *gl = r->gl;
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_uv);
	gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)r->vert_count * 8, m->uv, GL_STATIC_DRAW);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_sampled);
	gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)r->vert_count, m->sampled, GL_STATIC_DRAW);
}

skp_status render_set_texture(renderer *r, const mesh *m, const tex_image *t, int etc1, skp_error *err)
{
	const gl_api *gl = r->gl;
	render_texture_shutdown(r);
	if (!m->textured || !t || t->width < 1 || m->vert_count != r->vert_count)
		return SKP_OK;
	etc1 = etc1 && gl_has(gl, "GL_OES_compressed_ETC1_RGB8_texture");
	gl->GenBuffers(1, &r->vbo_uv);
	gl->GenBuffers(1, &r->vbo_sampled);
	upload_coordinates(r, m);
	gl->GenTextures(1, &r->body_tex);
	gl->ActiveTexture(GL_TEXTURE1);
	gl->BindTexture(GL_TEXTURE_2D, r->body_tex);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
	skp_status rc = upload_levels(r, t, etc1, err);
	gl->ActiveTexture(GL_TEXTURE0);
	if (!rc && gl->GetError() != GL_NO_ERROR)
		rc = skp_fail(err, SKP_ERR_RANGE, 0, "OpenGL error while uploading the body's %dx%d texture (%s)",
			      t->width, t->height, etc1 ? "ETC1" : "RGB565");
	if (rc) {
		render_texture_shutdown(r);
		return rc;
	}
	r->tex_ready = 1;
	r->tex_path = etc1 ? "ETC1" : "RGB565";
	return SKP_OK;
}

void render_texture_shutdown(renderer *r)
{
	const gl_api *gl = r->gl;
	if (r->body_tex)
		gl->DeleteTextures(1, &r->body_tex);
	if (r->vbo_uv)
		gl->DeleteBuffers(1, &r->vbo_uv);
	if (r->vbo_sampled)
		gl->DeleteBuffers(1, &r->vbo_sampled);
	r->body_tex = r->vbo_uv = r->vbo_sampled = 0;
	r->tex_ready = 0;
	r->tex_path = NULL;
}
