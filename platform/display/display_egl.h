/* EGL plumbing shared by the surfaceless, kms and x11 backends: display,
 * OpenGL ES 2 context, make current and load the GL entry points. */
#ifndef DISPLAY_EGL_H
#define DISPLAY_EGL_H

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "gl_api.h"
#include "skp_error.h"

typedef struct display_egl {
	EGLDisplay dpy;
	EGLConfig config;
	EGLContext ctx;
	EGLSurface surface;
	gl_api gl;
	char renderer[128];
} display_egl;

/* eglGetPlatformDisplayEXT(platform, native) and an OpenGL ES 2 context on
 * the first config matching config_attribs (and, when visual_id is not 0,
 * whose EGL_NATIVE_VISUAL_ID is visual_id). platform_ext is the client
 * extension that must be present, e.g. "EGL_MESA_platform_surfaceless". */
int display_egl_open(display_egl *e, EGLenum platform, const char *platform_ext, void *native,
		     const EGLint *config_attribs, EGLint visual_id, skp_error *err);

/* Makes the context current on surface (EGL_NO_SURFACE for surfaceless),
 * loads e->gl, reads GL_RENDERER and sets the viewport. */
int display_egl_bind(display_egl *e, EGLSurface surface, int width, int height, skp_error *err);

/* Undoes open and bind; safe on a partly opened or zeroed display_egl. */
void display_egl_close(display_egl *e);

void *display_egl_get_proc(const char *name);

/* "EGL_BAD_ALLOC" and so on for eglGetError(). */
const char *display_egl_error(void);

#endif
