/* Display backends: each one brings up an OpenGL ES 2 capable context with
 * a width x height framebuffer bound, and hands out the GL entry points
 * (see app/render/gl_api.h: skinplay links no GL library itself).
 *
 * Backends are singletons with static state: one may be initialised at a
 * time, and shutdown() must come before another init(). */
#ifndef DISPLAY_H
#define DISPLAY_H

#include <stddef.h>

#include "skp_error.h"

typedef struct display_config {
	int width, height;      /* wanted size; kms uses the mode of this size if the
	                         * connector has one, else its preferred mode */
	const char *device;     /* kms: DRM card node; x11: X display name; NULL = default */
	int rotation;           /* 0, 90, 180 or 270 degrees: applied by the renderer */
} display_config;

typedef struct display_info {
	int width, height;      /* actual framebuffer size */
	int rotation;           /* cfg->rotation, checked */
	const char *name;       /* backend name */
	const char *gl_renderer; /* GL_RENDERER string */
} display_info;

/* A window's pointer since the last look: drags with the left button
 * (orbit) and with the right or middle one, or shift and left (pan), in
 * pixels (y down), wheel clicks (up positive), and whether a drag ended. */
typedef struct display_pointer {
	int orbit_dx, orbit_dy, pan_dx, pan_dy, wheel;
	int released;
} display_pointer;

/* display_backend.key's codes for keys that are not characters. */
#define DISPLAY_KEY_LEFT 0x100
#define DISPLAY_KEY_RIGHT 0x101

typedef struct display_backend {
	const char *name;
	/* NULL, or 1 when the backend can start here (kms: a /dev/dri/card*
	 * with a connected connector whose DRM master this process can be). */
	int (*available)(void);
	/* Makes a context current with a width x height framebuffer bound
	 * (an FBO on surfaceless) and the viewport set. On failure nothing is
	 * left open. */
	int (*init)(const display_config *cfg, display_info *out, skp_error *err);
	void *(*get_proc)(const char *name);
	/* Shows the frame: swap or page flip (kms waits for the previous flip
	 * first); surfaceless and osmesa only finish rendering. */
	int (*present)(skp_error *err);
	/* Never blocks: the frame loop calls it every frame (Xlib buffers
	 * events it already read, so nothing polls the connection). Sets *quit
	 * on a close request. */
	int (*handle_events)(int *quit);
	/* NULL, or the next key pressed in the window since (a printable
	 * character, DISPLAY_KEY_LEFT or _RIGHT, 0 when none is waiting): keys
	 * the frame loop maps to methods, views and time. */
	int (*key)(void);
	/* NULL, or the pointer's drags and wheel since the last call (then
	 * cleared): what the frame loop turns into the camera's moves. */
	void (*pointer)(display_pointer *moved);
	/* Releases everything init took (kms: restores the saved CRTC). */
	void (*shutdown)(void);
} display_backend;

/* The board's backends (board.mk: DISPLAYS), by name: "surfaceless",
 * "osmesa", "kms", "x11"; NULL if unknown or not built. */
const display_backend *display_find(const char *name);

/* kms on a text console with a usable DRM device, x11 when DISPLAY is set,
 * surfaceless otherwise (of those the board builds). */
const display_backend *display_auto(void);

/* Starts a display: the backend named, or for NULL or "auto"
 * display_auto's pick, for "headless" surfaceless. When auto's or the
 * headless pick does not start, OSMesa where this build has it (headless
 * EGL can be missing where Mesa's OSMesa still works), the first failure
 * then in *first ("NAME: why"; code SKP_OK when there was none). Returns
 * the started backend, or NULL with err filled (an unknown name lists the
 * ones built). */
const display_backend *display_open(const char *name, const display_config *cfg, display_info *info,
				    skp_error *first, skp_error *err);

/* The backends built in, by name, space-separated, into out. */
void display_list(char *out, size_t size);

#endif
