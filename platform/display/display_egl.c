#define _GNU_SOURCE /* dl_iterate_phdr */
#include "display_egl.h"

#include <dlfcn.h>
#include <link.h>
#include <string.h>

#include "display_common.h"

#define MAX_CONFIGS 64

#if defined(__SANITIZE_ADDRESS__)
/* Sanitizer builds only. Mesa's DRI driver keeps caches in globals that it
 * never frees, and eglTerminate dlclose()s it: LeakSanitizer then reports
 * those blocks from an unknown module, which no suppression can name. An
 * extra reference keeps the driver and its globals mapped, so they stay
 * reachable; nothing of ours is hidden. */
static int pin_dri(struct dl_phdr_info *info, size_t size, void *data)
{
	(void)size, (void)data;
	if (strstr(info->dlpi_name, "/dri/") && strstr(info->dlpi_name, "_dri.so"))
		dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD);
	return 0;
}

static void pin_dri_driver(void)
{
	dl_iterate_phdr(pin_dri, NULL);
}
#else
static void pin_dri_driver(void)
{
}
#endif

const char *display_egl_error(void)
{
	switch (eglGetError()) {
	case EGL_SUCCESS: return "EGL_SUCCESS";
	case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
	case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
	case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
	case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
	case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
	case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
	case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
	case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
	case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
	case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
	case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
	case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
	case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
	case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
	default: return "unknown EGL error";
	}
}

void *display_egl_get_proc(const char *name)
{
	/* Mesa (EGL_KHR_get_all_proc_addresses) returns core GLES functions
	 * too; gl_api_load() rejects any NULL. */
	return (void *)eglGetProcAddress(name);
}

static int get_display(display_egl *e, EGLenum platform, const char *platform_ext, void *native,
		       skp_error *err)
{
	const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
	if (!display_has_word(client, "EGL_EXT_platform_base") || !display_has_word(client, platform_ext))
		return skp_fail(err, SKP_ERR_IO, 0, "EGL: %s is not supported by this libEGL", platform_ext);
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
		(PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
	if (!get_platform_display)
		return skp_fail(err, SKP_ERR_IO, 0, "EGL: no eglGetPlatformDisplayEXT");
	e->dpy = get_platform_display(platform, native, NULL);
	if (e->dpy == EGL_NO_DISPLAY)
		return skp_fail(err, SKP_ERR_IO, 0, "EGL: no %s display (%s)", platform_ext, display_egl_error());
	EGLint major, minor;
	if (!eglInitialize(e->dpy, &major, &minor)) {
		/* Not initialised, so close() must not terminate it. */
		e->dpy = EGL_NO_DISPLAY;
		return skp_fail(err, SKP_ERR_IO, 0, "EGL: eglInitialize on %s failed (%s)", platform_ext,
				display_egl_error());
	}
	pin_dri_driver();
	return SKP_OK;
}

static int choose_config(display_egl *e, const EGLint *attribs, EGLint visual_id, skp_error *err)
{
	EGLConfig configs[MAX_CONFIGS];
	EGLint n = 0;
	if (!eglChooseConfig(e->dpy, attribs, configs, MAX_CONFIGS, &n) || n < 1)
		return skp_fail(err, SKP_ERR_IO, 0, "EGL: no OpenGL ES 2 config (%s)", display_egl_error());
	for (EGLint i = 0; i < n; i++) {
		EGLint id = 0;
		if (visual_id && (!eglGetConfigAttrib(e->dpy, configs[i], EGL_NATIVE_VISUAL_ID, &id) || id != visual_id))
			continue;
		e->config = configs[i];
		return SKP_OK;
	}
	return skp_fail(err, SKP_ERR_IO, 0, "EGL: none of %d OpenGL ES 2 configs has native visual %d", (int)n,
			(int)visual_id);
}

int display_egl_open(display_egl *e, EGLenum platform, const char *platform_ext, void *native,
		     const EGLint *config_attribs, EGLint visual_id, skp_error *err)
{
	static const EGLint ctx_attribs[] = { EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE };
	int rc;

	memset(e, 0, sizeof *e);
	e->dpy = EGL_NO_DISPLAY;
	e->ctx = EGL_NO_CONTEXT;
	e->surface = EGL_NO_SURFACE;
	if ((rc = get_display(e, platform, platform_ext, native, err)) != SKP_OK)
		goto fail;
	if (!eglBindAPI(EGL_OPENGL_ES_API)) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "EGL: OpenGL ES API not available (%s)", display_egl_error());
		goto fail;
	}
	if ((rc = choose_config(e, config_attribs, visual_id, err)) != SKP_OK)
		goto fail;
	e->ctx = eglCreateContext(e->dpy, e->config, EGL_NO_CONTEXT, ctx_attribs);
	if (e->ctx == EGL_NO_CONTEXT) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "EGL: cannot create an OpenGL ES 2 context (%s)",
			      display_egl_error());
		goto fail;
	}
	return SKP_OK;
fail:
	display_egl_close(e);
	return rc;
}

int display_egl_bind(display_egl *e, EGLSurface surface, int width, int height, skp_error *err)
{
	if (!eglMakeCurrent(e->dpy, surface, surface, e->ctx))
		return skp_fail(err, SKP_ERR_IO, 0, "EGL: eglMakeCurrent failed (%s)", display_egl_error());
	int rc = gl_api_load(&e->gl, display_egl_get_proc, err);
	if (rc != SKP_OK)
		return rc;
	const char *r = (const char *)e->gl.GetString(GL_RENDERER);
	strncpy(e->renderer, r ? r : "unknown", sizeof e->renderer - 1);
	e->gl.Viewport(0, 0, width, height);
	return SKP_OK;
}

void display_egl_close(display_egl *e)
{
	if (e->dpy != EGL_NO_DISPLAY) {
		eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		if (e->surface != EGL_NO_SURFACE)
			eglDestroySurface(e->dpy, e->surface);
		if (e->ctx != EGL_NO_CONTEXT)
			eglDestroyContext(e->dpy, e->ctx);
		eglTerminate(e->dpy);
	}
	/* Frees this thread's EGL state, which eglTerminate keeps. */
	eglReleaseThread();
	memset(e, 0, sizeof *e);
	e->dpy = EGL_NO_DISPLAY;
	e->ctx = EGL_NO_CONTEXT;
	e->surface = EGL_NO_SURFACE;
}
