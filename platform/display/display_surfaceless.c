/* Headless EGL: Mesa's surfaceless platform, a context current without any
 * surface, drawing into an FBO that stands in for the window. Needs no
 * device node and no display server (llvmpipe in CI, the GPU's render node
 * where there is one). */
#include "display.h"

#include "display_common.h"
#include "display_egl.h"

#include <GLES2/gl2ext.h>

static struct {
	display_egl egl;
	GLuint fbo, color, depth;
} s;

static int create_fbo(int width, int height, skp_error *err)
{
	gl_api *gl = &s.egl.gl;
	GLint max = 0;

	gl->GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max);
	if (width > max || height > max)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "%dx%d is larger than GL_MAX_RENDERBUFFER_SIZE %d",
				width, height, (int)max);
	gl->GenFramebuffers(1, &s.fbo);
	gl->GenRenderbuffers(1, &s.color);
	gl->GenRenderbuffers(1, &s.depth);
	/* Core GLES 2 only has 16-bit renderbuffer formats; Mesa has
	 * OES_rgb8_rgba8 and OES_depth24 everywhere. */
	gl->BindRenderbuffer(GL_RENDERBUFFER, s.color);
	gl->RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8_OES, width, height);
	gl->BindRenderbuffer(GL_RENDERBUFFER, s.depth);
	gl->RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24_OES, width, height);
	gl->BindRenderbuffer(GL_RENDERBUFFER, 0);
	gl->BindFramebuffer(GL_FRAMEBUFFER, s.fbo);
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, s.color);
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, s.depth);
	GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
	if (status != GL_FRAMEBUFFER_COMPLETE)
		return skp_fail(err, SKP_ERR_IO, 0, "RGBA8 + depth24 framebuffer incomplete (status %u)",
				(unsigned)status);
	return SKP_OK;
}

static void delete_fbo(void)
{
	gl_api *gl = &s.egl.gl;
	if (!s.fbo)
		return;
	gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
	gl->DeleteFramebuffers(1, &s.fbo);
	gl->DeleteRenderbuffers(1, &s.color);
	gl->DeleteRenderbuffers(1, &s.depth);
	s.fbo = s.color = s.depth = 0;
}

static void surfaceless_shutdown(void)
{
	delete_fbo();
	display_egl_close(&s.egl);
}

static int surfaceless_init(const display_config *cfg, display_info *out, skp_error *err)
{
	/* No window system: a config is only needed to create the context. */
	static const EGLint attribs[] = {
		EGL_SURFACE_TYPE, 0,
		EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
		EGL_NONE
	};
	int rc = display_check_config(cfg, 16384, 16384, err);
	if (rc != SKP_OK)
		return rc;
	rc = display_egl_open(&s.egl, EGL_PLATFORM_SURFACELESS_MESA, "EGL_MESA_platform_surfaceless",
			      EGL_DEFAULT_DISPLAY, attribs, 0, err);
	if (rc != SKP_OK)
		return rc;
	if (!display_has_word(eglQueryString(s.egl.dpy, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "EGL_KHR_surfaceless_context is not supported");
		goto fail;
	}
	if ((rc = display_egl_bind(&s.egl, EGL_NO_SURFACE, cfg->width, cfg->height, err)) != SKP_OK)
		goto fail;
	if ((rc = create_fbo(cfg->width, cfg->height, err)) != SKP_OK)
		goto fail;
	out->width = cfg->width;
	out->height = cfg->height;
	out->rotation = cfg->rotation;
	out->name = "surfaceless";
	out->gl_renderer = s.egl.renderer;
	return SKP_OK;
fail:
	surfaceless_shutdown();
	return rc;
}

static int surfaceless_present(skp_error *err)
{
	(void)err;
	/* Nothing is shown; finishing keeps frame timing honest for benchmarks. */
	s.egl.gl.Finish();
	return SKP_OK;
}

static int surfaceless_handle_events(int *quit)
{
	(void)quit;
	return SKP_OK;
}

const display_backend display_surfaceless = {
	.name = "surfaceless",
	.init = surfaceless_init,
	.get_proc = display_egl_get_proc,
	.present = surfaceless_present,
	.handle_events = surfaceless_handle_events,
	.shutdown = surfaceless_shutdown,
};
