/* Headless software rendering through Mesa's OSMesa into a static buffer.
 *
 * libOSMesa exports every gl* symbol, as libGLESv2 does, so it is never
 * linked: dlopen() with RTLD_LOCAL keeps its symbols out of the global
 * namespace and the entry points come from OSMesaGetProcAddress. OSMesa
 * only makes desktop GL contexts; a compatibility profile accepts GLSL ES
 * 1.00 (#version 100) shaders through ARB_ES2_compatibility. */
#include "display.h"

#include <dlfcn.h>
#include <errno.h>
#include <stdint.h>
#include <string.h>
#include <sys/mman.h>

#include "board_limits.h"
#include "display_common.h"

/* From <GL/osmesa.h> and <GL/gl.h>, which cannot share a file with the
 * GLES 2 headers; these values are fixed by the OSMesa ABI. */
#define OSMESA_RGBA                  0x1908 /* GL_RGBA */
#define OSMESA_FORMAT                0x22
#define OSMESA_DEPTH_BITS            0x30
#define OSMESA_STENCIL_BITS          0x31
#define OSMESA_ACCUM_BITS            0x32
#define OSMESA_PROFILE               0x33
#define OSMESA_COMPAT_PROFILE        0x35
#define OSMESA_CONTEXT_MAJOR_VERSION 0x36
#define OSMESA_CONTEXT_MINOR_VERSION 0x37
#define GL_UNSIGNED_BYTE_            0x1401
#define GL_RENDERER_                 0x1F01

/* Largest framebuffer: the colour buffer is static (no malloc), and pages
 * never drawn to are never touched, so only the used size costs RAM. A
 * board may set SKP_DISPLAY_MAX_W/H in board_limits.h. */
#ifdef SKP_DISPLAY_MAX_W
#define DISPLAY_OSMESA_MAX_W SKP_DISPLAY_MAX_W
#define DISPLAY_OSMESA_MAX_H SKP_DISPLAY_MAX_H
#else
#define DISPLAY_OSMESA_MAX_W 3840
#define DISPLAY_OSMESA_MAX_H 2160
#endif

typedef struct osmesa_context *OSMesaContext;
typedef OSMesaContext (*create_fn)(const int *attribs, OSMesaContext share);
typedef unsigned char (*make_current_fn)(OSMesaContext ctx, void *buffer, unsigned type, int width, int height);
typedef void (*destroy_fn)(OSMesaContext ctx);
typedef void (*(*get_proc_fn)(const char *name))(void);
typedef const unsigned char *(*get_string_fn)(unsigned name);
typedef void (*finish_fn)(void);

static struct {
	void *lib;
	create_fn create;
	make_current_fn make_current;
	destroy_fn destroy;
	get_proc_fn get_proc;
	OSMesaContext ctx;
	finish_fn finish;
	char renderer[128];
} s;

/* Rows bottom-up, like glReadPixels; mapped at the display's size while
 * it is open (as a static at the largest size it was 32 MB of the program
 * image, which a leak checker reads whole at every exit). */
static struct {
	uint32_t *px;
	size_t bytes;
} color_buffer;

static int load_library(skp_error *err)
{
	static const char *const names[] = { "libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so" };

	/* Mesa is not safe to unload (LLVM and atexit handlers): once loaded
	 * the library stays for the life of the process. */
	for (size_t i = 0; !s.lib && i < sizeof names / sizeof names[0]; i++)
		s.lib = dlopen(names[i], RTLD_NOW | RTLD_LOCAL);
	if (!s.lib)
		return skp_fail(err, SKP_ERR_IO, 0, "cannot load libOSMesa.so.8 (package libosmesa6): %s",
				dlerror());
	s.create = (create_fn)dlsym(s.lib, "OSMesaCreateContextAttribs");
	s.make_current = (make_current_fn)dlsym(s.lib, "OSMesaMakeCurrent");
	s.destroy = (destroy_fn)dlsym(s.lib, "OSMesaDestroyContext");
	s.get_proc = (get_proc_fn)dlsym(s.lib, "OSMesaGetProcAddress");
	if (!s.create || !s.make_current || !s.destroy || !s.get_proc)
		return skp_fail(err, SKP_ERR_IO, 0, "libOSMesa lacks OSMesaCreateContextAttribs (Mesa < 11.2?)");
	return SKP_OK;
}

static void *osmesa_get_proc(const char *name)
{
	return s.get_proc ? (void *)s.get_proc(name) : NULL;
}

static void osmesa_shutdown(void)
{
	if (s.ctx)
		s.destroy(s.ctx);
	s.ctx = NULL;
	s.finish = NULL;
	if (color_buffer.px)
		munmap(color_buffer.px, color_buffer.bytes);
	color_buffer.px = NULL;
}

static int map_color_buffer(int width, int height, skp_error *err)
{
	color_buffer.bytes = (size_t)width * (size_t)height * sizeof *color_buffer.px;
	void *p = mmap(NULL, color_buffer.bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	if (p == MAP_FAILED)
		return skp_fail(err, SKP_ERR_IO, 0, "no memory for a %dx%d colour buffer: %s", width, height, strerror(errno));
	color_buffer.px = p;
	return SKP_OK;
}

static int make_context(int width, int height, skp_error *err)
{
	static const int attribs[] = {
		OSMESA_FORMAT, OSMESA_RGBA,
		OSMESA_DEPTH_BITS, 24,
		OSMESA_STENCIL_BITS, 0,
		OSMESA_ACCUM_BITS, 0,
		OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
		OSMESA_CONTEXT_MAJOR_VERSION, 2,
		OSMESA_CONTEXT_MINOR_VERSION, 1,
		0
	};
	int rc = map_color_buffer(width, height, err);
	if (rc != SKP_OK)
		return rc;
	s.ctx = s.create(attribs, NULL);
	if (!s.ctx)
		return skp_fail(err, SKP_ERR_IO, 0, "OSMesaCreateContextAttribs (RGBA, depth 24, GL 2.1 compat) failed");
	if (!s.make_current(s.ctx, color_buffer.px, GL_UNSIGNED_BYTE_, width, height))
		return skp_fail(err, SKP_ERR_IO, 0, "OSMesaMakeCurrent %dx%d failed", width, height);
	return SKP_OK;
}

static int osmesa_init(const display_config *cfg, display_info *out, skp_error *err)
{
	int rc = display_check_config(cfg, DISPLAY_OSMESA_MAX_W, DISPLAY_OSMESA_MAX_H, err);
	if (rc != SKP_OK)
		return rc;
	if ((rc = load_library(err)) != SKP_OK)
		return rc;
	if ((rc = make_context(cfg->width, cfg->height, err)) != SKP_OK)
		goto fail;
	get_string_fn get_string = (get_string_fn)osmesa_get_proc("glGetString");
	s.finish = (finish_fn)osmesa_get_proc("glFinish");
	if (!get_string || !s.finish) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "no glGetString or glFinish");
		goto fail;
	}
	const unsigned char *r = get_string(GL_RENDERER_);
	strncpy(s.renderer, r ? (const char *)r : "unknown", sizeof s.renderer - 1);
	out->width = cfg->width;
	out->height = cfg->height;
	out->rotation = cfg->rotation;
	out->name = "osmesa";
	out->gl_renderer = s.renderer;
	return SKP_OK;
fail:
	osmesa_shutdown();
	return rc;
}

static int osmesa_present(skp_error *err)
{
	(void)err;
	s.finish();
	return SKP_OK;
}

static int osmesa_handle_events(int *quit)
{
	(void)quit;
	return SKP_OK;
}

const display_backend display_osmesa = {
	.name = "osmesa",
	.init = osmesa_init,
	.get_proc = osmesa_get_proc,
	.present = osmesa_present,
	.handle_events = osmesa_handle_events,
	.shutdown = osmesa_shutdown,
};
