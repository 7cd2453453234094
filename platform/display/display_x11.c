/* A fixed-size Xlib window with an EGL window surface (EGL platform X11).
 * Drags and the wheel go to skinplay's camera (display_backend.pointer).
 * q, Escape or the window manager's close button quit; other keys pressed
 * in the window are handed to skinplay (display_backend.key: the method,
 * view and time keys of app/runtime/kiosk_shell.h, the arrows as
 * DISPLAY_KEY_*), besides the input backends' buttons (keyboard: the
 * terminal that started it). */
#include "display.h"

#include <stdio.h>
#include <string.h>

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>

#include "display_common.h"
#include "display_egl.h"

static struct {
	Display *dpy;
	Window win;
	Colormap cmap;
	Atom wm_delete;
	display_egl egl;
	int keys[16];           /* keys pressed in the window, not yet taken */
	int key_count;
	display_pointer moved;  /* drags and wheel not yet taken */
	int drag;               /* 0 none, 1 orbit, 2 pan: the button held */
	int last_x, last_y;
} s;

static unsigned long x_errors;

/* Xlib's own handler exits the program on any protocol error (a window
 * gone under the window manager, a request the server refused): a kiosk
 * says it and keeps playing. The first is said; shutdown counts the rest. */
static int on_x_error(Display *dpy, XErrorEvent *ev)
{
	if (x_errors++ == 0) {
		char text[128];
		XGetErrorText(dpy, ev->error_code, text, (int)sizeof text);
		fprintf(stderr, "x11: X error '%s' (request %u.%u): ignored, the window plays on\n", text,
			(unsigned)ev->request_code, (unsigned)ev->minor_code);
	}
	return 0;
}

static int open_x(const char *name, skp_error *err)
{
	XSetErrorHandler(on_x_error);
	s.dpy = XOpenDisplay(name);
	if (!s.dpy) {
		const char *shown = XDisplayName(name);
		return skp_fail(err, SKP_ERR_IO, 0, "cannot open display '%s'", shown ? shown : "");
	}
	return SKP_OK;
}

/* The window needs the X visual of the EGL config it will render with. */
static int create_window(int width, int height, skp_error *err)
{
	EGLint visual_id = 0;
	XVisualInfo want, *vi;
	int n = 0;

	eglGetConfigAttrib(s.egl.dpy, s.egl.config, EGL_NATIVE_VISUAL_ID, &visual_id);
	want.visualid = (VisualID)visual_id;
	vi = XGetVisualInfo(s.dpy, VisualIDMask, &want, &n);
	if (!vi)
		return skp_fail(err, SKP_ERR_IO, 0, "no X visual %d for the EGL config", (int)visual_id);
	Window root = RootWindow(s.dpy, vi->screen);
	XSetWindowAttributes attr = { 0 };
	s.cmap = XCreateColormap(s.dpy, root, vi->visual, AllocNone);
	attr.colormap = s.cmap;
	attr.background_pixel = 0;
	attr.border_pixel = 0;
	attr.event_mask = ExposureMask | StructureNotifyMask | KeyPressMask | ButtonPressMask | ButtonReleaseMask |
			  PointerMotionMask;
	s.win = XCreateWindow(s.dpy, root, 0, 0, (unsigned)width, (unsigned)height, 0, vi->depth, InputOutput,
			      vi->visual, CWBackPixel | CWBorderPixel | CWColormap | CWEventMask, &attr);
	XFree(vi);
	/* The renderer draws width x height: ask the window manager to keep
	 * that size rather than follow every resize. */
	XSizeHints hints = { .flags = PMinSize | PMaxSize, .min_width = width, .max_width = width,
			     .min_height = height, .max_height = height };
	XSetWMNormalHints(s.dpy, s.win, &hints);
	XStoreName(s.dpy, s.win, "skinplay");
	s.wm_delete = XInternAtom(s.dpy, "WM_DELETE_WINDOW", False);
	XSetWMProtocols(s.dpy, s.win, &s.wm_delete, 1);
	XMapWindow(s.dpy, s.win);
	return SKP_OK;
}

static void x11_shutdown(void)
{
	display_egl_close(&s.egl);
	if (s.dpy) {
		if (s.win)
			XDestroyWindow(s.dpy, s.win);
		if (s.cmap)
			XFreeColormap(s.dpy, s.cmap);
		XCloseDisplay(s.dpy);
	}
	if (x_errors > 1)
		fprintf(stderr, "x11: %lu X errors ignored in all\n", x_errors);
	x_errors = 0;
	memset(&s, 0, sizeof s);
}

static int x11_init(const display_config *cfg, display_info *out, skp_error *err)
{
	static const EGLint attribs[] = {
		EGL_SURFACE_TYPE, EGL_WINDOW_BIT,
		EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
		EGL_DEPTH_SIZE, 24,
		EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
		EGL_NONE
	};
	s.key_count = 0;
	memset(&s.moved, 0, sizeof s.moved);
	s.drag = 0;
	int rc = display_check_config(cfg, 16384, 16384, err);
	if (rc != SKP_OK)
		return rc;
	if ((rc = open_x(cfg->device, err)) != SKP_OK)
		goto fail;
	rc = display_egl_open(&s.egl, EGL_PLATFORM_X11_KHR, "EGL_KHR_platform_x11", s.dpy, attribs, 0, err);
	if (rc != SKP_OK || (rc = create_window(cfg->width, cfg->height, err)) != SKP_OK)
		goto fail;
	/* The core entry point takes the Window itself; the platform (EXT)
	 * one would want a pointer to it. */
	s.egl.surface = eglCreateWindowSurface(s.egl.dpy, s.egl.config, (EGLNativeWindowType)s.win, NULL);
	if (s.egl.surface == EGL_NO_SURFACE) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "EGL window surface failed (%s)", display_egl_error());
		goto fail;
	}
	if ((rc = display_egl_bind(&s.egl, s.egl.surface, cfg->width, cfg->height, err)) != SKP_OK)
		goto fail;
	out->width = cfg->width;
	out->height = cfg->height;
	out->rotation = cfg->rotation;
	out->name = "x11";
	out->gl_renderer = s.egl.renderer;
	return SKP_OK;
fail:
	x11_shutdown();
	return rc;
}

static int x11_present(skp_error *err)
{
	if (!eglSwapBuffers(s.egl.dpy, s.egl.surface))
		return skp_fail(err, SKP_ERR_IO, 0, "eglSwapBuffers failed (%s)", display_egl_error());
	return SKP_OK;
}

static void handle_key(XKeyEvent *ev, int *quit)
{
	/* the character typed, shift applied (H J K L move the camera where
	 * h j k l turn it; a keymap may list a letter's lower case alone) */
	char typed[8];
	KeySym sym = 0;
	int n = XLookupString(ev, typed, (int)sizeof typed, &sym, NULL);
	int key = n == 1 && typed[0] >= 0x20 && typed[0] < 0x7f ? typed[0] : 0;
	if (sym == XK_Left || sym == XK_KP_Left)
		key = DISPLAY_KEY_LEFT;
	else if (sym == XK_Right || sym == XK_KP_Right)
		key = DISPLAY_KEY_RIGHT;
	else if (sym == XK_KP_Add)
		key = '+';
	else if (sym == XK_KP_Subtract)
		key = '-';
	if (sym == XK_q || sym == XK_Q || sym == XK_Escape)
		*quit = 1;
	else if (key && s.key_count < (int)(sizeof s.keys / sizeof s.keys[0]))
		s.keys[s.key_count++] = key;
}

/* The oldest key pressed in the window (a printable character, an
 * arrow's DISPLAY_KEY_*), 0 none. */
static int x11_key(void)
{
	if (s.key_count == 0)
		return 0;
	int k = s.keys[0];
	memmove(s.keys, s.keys + 1, sizeof s.keys[0] * (size_t)--s.key_count);
	return k;
}

/* Left: orbit (with shift: pan); middle or right: pan; 4 and 5: the wheel. */
static void handle_button(const XButtonEvent *ev, int down)
{
	if (ev->button == Button4 || ev->button == Button5) {
		s.moved.wheel += down ? (ev->button == Button4 ? 1 : -1) : 0;
		return;
	}
	if (!down) {
		s.moved.released |= s.drag != 0;
		s.drag = 0;
		return;
	}
	s.drag = ev->button == Button1 && !(ev->state & ShiftMask) ? 1 : 2;
	s.last_x = ev->x;
	s.last_y = ev->y;
}

static void handle_motion(const XMotionEvent *ev)
{
	int dx = ev->x - s.last_x, dy = ev->y - s.last_y;
	s.last_x = ev->x;
	s.last_y = ev->y;
	if (s.drag == 1) {
		s.moved.orbit_dx += dx;
		s.moved.orbit_dy += dy;
	} else if (s.drag == 2) {
		s.moved.pan_dx += dx;
		s.moved.pan_dy += dy;
	}
}

static void x11_pointer(display_pointer *moved)
{
	*moved = s.moved;
	memset(&s.moved, 0, sizeof s.moved);
}

static int x11_handle_events(int *quit)
{
	if (!s.dpy)
		return SKP_OK;
	while (XPending(s.dpy)) {
		XEvent ev;
		XNextEvent(s.dpy, &ev);
		switch (ev.type) {
		case KeyPress:
			handle_key(&ev.xkey, quit);
			break;
		case ButtonPress:
		case ButtonRelease:
			handle_button(&ev.xbutton, ev.type == ButtonPress);
			break;
		case MotionNotify:
			handle_motion(&ev.xmotion);
			break;
		case ClientMessage:
			if ((Atom)ev.xclient.data.l[0] == s.wm_delete)
				*quit = 1;
			break;
		case Expose:
		case ConfigureNotify:
			/* The main loop redraws every frame at the fixed size. */
			break;
		default:
			break;
		}
	}
	return SKP_OK;
}

const display_backend display_x11 = {
	.name = "x11",
	.init = x11_init,
	.get_proc = display_egl_get_proc,
	.present = x11_present,
	.handle_events = x11_handle_events,
	.key = x11_key,
	.pointer = x11_pointer,
	.shutdown = x11_shutdown,
};
