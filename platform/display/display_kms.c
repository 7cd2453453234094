/* Full screen on a text console: EGL on GBM, scanned out with KMS page
 * flips (after kmscube). The first present sets the CRTC; later ones flip
 * and wait only for the previous flip, so one frame renders while another
 * waits for vblank. Rotation is left to the renderer: the mode's size is
 * the framebuffer size and display_info.rotation says how to draw. */
#include "display.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <gbm.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include "display_common.h"
#include "display_egl.h"

#define MAX_CARDS 16
/* Mesa's GBM surfaces have at most 4 buffers; each gets one DRM fb. */
#define MAX_FBS 4

typedef struct kms_fb {
	struct gbm_bo *bo;
	uint32_t id;
} kms_fb;

static struct {
	int fd;
	char path[64];
	uint32_t connector_id, crtc_id;
	drmModeModeInfo mode;
	drmModeCrtc *saved_crtc;
	struct gbm_device *gbm;
	struct gbm_surface *surface;
	display_egl egl;
	kms_fb fbs[MAX_FBS];
	struct gbm_bo *scanout, *pending; /* on screen, and waiting for its flip */
	int crtc_set;
} s = { .fd = -1 };

static int find_connector(int fd, const drmModeRes *res, drmModeConnector **out)
{
	for (int i = 0; i < res->count_connectors; i++) {
		drmModeConnector *c = drmModeGetConnector(fd, res->connectors[i]);
		if (c && c->connection == DRM_MODE_CONNECTED && c->count_modes > 0) {
			*out = c;
			return 1;
		}
		drmModeFreeConnector(c);
	}
	return 0;
}

/* 1 when fd has KMS resources and a connected connector with a mode. */
static int card_has_output(int fd)
{
	drmModeRes *res = drmModeGetResources(fd);
	drmModeConnector *c = NULL;
	int ok = res && find_connector(fd, res, &c);
	drmModeFreeConnector(c);
	drmModeFreeResources(res);
	return ok;
}

static int become_master(int fd, const char *path, skp_error *err)
{
	if (drmIsMaster(fd) || drmSetMaster(fd) == 0)
		return SKP_OK;
	return skp_fail(err, SKP_ERR_IO, 0,
			"%s: another process is DRM master (a display server?): stop it or run from a text console",
			path);
}

/* cfg->device, or the first /dev/dri/card* with a connected output. */
static int open_device(const char *device, skp_error *err)
{
	if (device) {
		snprintf(s.path, sizeof s.path, "%s", device);
		s.fd = open(device, O_RDWR | O_CLOEXEC);
		if (s.fd < 0)
			return skp_fail(err, SKP_ERR_IO, 0, "%s: cannot open DRM device: %s", device, strerror(errno));
		if (!card_has_output(s.fd))
			return skp_fail(err, SKP_ERR_IO, 0, "%s: no KMS support or no connected display", device);
		return SKP_OK;
	}
	int opened = 0;
	for (int i = 0; i < MAX_CARDS; i++) {
		snprintf(s.path, sizeof s.path, "/dev/dri/card%d", i);
		int fd = open(s.path, O_RDWR | O_CLOEXEC);
		if (fd < 0)
			continue;
		opened++;
		if (card_has_output(fd)) {
			s.fd = fd;
			return SKP_OK;
		}
		close(fd);
	}
	if (!opened)
		return skp_fail(err, SKP_ERR_IO, 0,
				"no DRM device: cannot open any /dev/dri/card* (no GPU/KMS driver, or not in group video)");
	return skp_fail(err, SKP_ERR_IO, 0, "no /dev/dri/card* has a connected display");
}

static const drmModeModeInfo *pick_mode(const drmModeConnector *c, int width, int height)
{
	const drmModeModeInfo *best = &c->modes[0];
	for (int i = 0; i < c->count_modes; i++) {
		if (c->modes[i].hdisplay == width && c->modes[i].vdisplay == height)
			return &c->modes[i];
		if (c->modes[i].type & DRM_MODE_TYPE_PREFERRED)
			best = &c->modes[i];
	}
	return best;
}

/* The CRTC already driving the connector, else the first free one an
 * encoder of the connector can use. */
static uint32_t find_crtc(const drmModeRes *res, const drmModeConnector *c)
{
	drmModeEncoder *enc = c->encoder_id ? drmModeGetEncoder(s.fd, c->encoder_id) : NULL;
	uint32_t crtc = enc ? enc->crtc_id : 0;
	drmModeFreeEncoder(enc);
	for (int i = 0; !crtc && i < c->count_encoders; i++) {
		enc = drmModeGetEncoder(s.fd, c->encoders[i]);
		for (int j = 0; enc && !crtc && j < res->count_crtcs; j++)
			if (enc->possible_crtcs & (1u << j))
				crtc = res->crtcs[j];
		drmModeFreeEncoder(enc);
	}
	return crtc;
}

static int pick_output(const display_config *cfg, skp_error *err)
{
	drmModeRes *res = drmModeGetResources(s.fd);
	drmModeConnector *c = NULL;
	int rc = SKP_OK;

	if (!res || !find_connector(s.fd, res, &c)) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "%s: no connected display", s.path);
		goto done;
	}
	s.connector_id = c->connector_id;
	s.mode = *pick_mode(c, cfg->width, cfg->height);
	s.crtc_id = find_crtc(res, c);
	if (!s.crtc_id) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "%s: no CRTC for connector %u", s.path,
			      (unsigned)c->connector_id);
		goto done;
	}
	s.saved_crtc = drmModeGetCrtc(s.fd, s.crtc_id);
done:
	drmModeFreeConnector(c);
	drmModeFreeResources(res);
	return rc;
}

static int create_surface(skp_error *err)
{
	static const EGLint attribs[] = {
		EGL_SURFACE_TYPE, EGL_WINDOW_BIT,
		EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
		EGL_ALPHA_SIZE, 0,
		EGL_DEPTH_SIZE, 24,
		EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
		EGL_NONE
	};
	int w = s.mode.hdisplay, h = s.mode.vdisplay, rc;

	s.gbm = gbm_create_device(s.fd);
	if (!s.gbm)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: gbm_create_device failed", s.path);
	s.surface = gbm_surface_create(s.gbm, (uint32_t)w, (uint32_t)h, GBM_FORMAT_XRGB8888,
				       GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
	if (!s.surface)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: cannot create a %dx%d GBM scanout surface", s.path, w, h);
	rc = display_egl_open(&s.egl, EGL_PLATFORM_GBM_KHR, "EGL_KHR_platform_gbm", s.gbm, attribs,
			      GBM_FORMAT_XRGB8888, err);
	if (rc != SKP_OK)
		return rc;
	s.egl.surface = eglCreateWindowSurface(s.egl.dpy, s.egl.config, (EGLNativeWindowType)s.surface, NULL);
	if (s.egl.surface == EGL_NO_SURFACE)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: EGL window surface on GBM failed (%s)", s.path,
				display_egl_error());
	return display_egl_bind(&s.egl, s.egl.surface, w, h, err);
}

static kms_fb *fb_slot(struct gbm_bo *bo)
{
	for (int i = 0; i < MAX_FBS; i++)
		if (s.fbs[i].bo == bo)
			return &s.fbs[i];
	return NULL;
}

static void fb_destroy(struct gbm_bo *bo, void *data)
{
	kms_fb *fb = data;
	(void)bo;
	if (s.fd >= 0 && fb->id)
		drmModeRmFB(s.fd, fb->id);
	fb->bo = NULL;
	fb->id = 0;
}

/* The DRM framebuffer of a GBM buffer, made the first time it is seen and
 * dropped when GBM destroys the buffer. */
static int fb_for_bo(struct gbm_bo *bo, uint32_t *id, skp_error *err)
{
	kms_fb *fb = fb_slot(bo);
	if (fb) {
		*id = fb->id;
		return SKP_OK;
	}
	fb = fb_slot(NULL);
	if (!fb)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "%s: GBM surface has more than %d buffers", s.path, MAX_FBS);
	uint32_t handles[4] = { gbm_bo_get_handle(bo).u32 }, pitches[4] = { gbm_bo_get_stride(bo) };
	uint32_t offsets[4] = { 0 };
	if (drmModeAddFB2(s.fd, gbm_bo_get_width(bo), gbm_bo_get_height(bo), GBM_FORMAT_XRGB8888, handles,
			  pitches, offsets, &fb->id, 0) != 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: drmModeAddFB2 failed: %s", s.path, strerror(errno));
	fb->bo = bo;
	gbm_bo_set_user_data(bo, fb, fb_destroy);
	*id = fb->id;
	return SKP_OK;
}

static void page_flip_done(int fd, unsigned frame, unsigned sec, unsigned usec, void *data)
{
	(void)fd, (void)frame, (void)sec, (void)usec, (void)data;
	if (s.scanout)
		gbm_surface_release_buffer(s.surface, s.scanout);
	s.scanout = s.pending;
	s.pending = NULL;
}

static int read_drm_events(void)
{
	drmEventContext ev = { .version = 2, .page_flip_handler = page_flip_done };
	return drmHandleEvent(s.fd, &ev) == 0 ? SKP_OK : SKP_ERR_IO;
}

static int wait_for_flip(skp_error *err)
{
	while (s.pending) {
		struct pollfd p = { .fd = s.fd, .events = POLLIN };
		int n = poll(&p, 1, 1000);
		if (n < 0 && errno == EINTR)
			continue;
		if (n <= 0)
			return skp_fail(err, SKP_ERR_IO, 0, "%s: page flip did not complete%s", s.path,
					n == 0 ? " within 1 s" : "");
		if (read_drm_events() != SKP_OK)
			return skp_fail(err, SKP_ERR_IO, 0, "%s: drmHandleEvent failed", s.path);
	}
	return SKP_OK;
}

static int kms_present(skp_error *err)
{
	uint32_t fb = 0;
	int rc;

	if (!eglSwapBuffers(s.egl.dpy, s.egl.surface))
		return skp_fail(err, SKP_ERR_IO, 0, "%s: eglSwapBuffers failed (%s)", s.path, display_egl_error());
	struct gbm_bo *bo = gbm_surface_lock_front_buffer(s.surface);
	if (!bo)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: no GBM front buffer", s.path);
	if ((rc = fb_for_bo(bo, &fb, err)) != SKP_OK || (rc = wait_for_flip(err)) != SKP_OK)
		goto release;
	if (!s.crtc_set) {
		if (drmModeSetCrtc(s.fd, s.crtc_id, fb, 0, 0, &s.connector_id, 1, &s.mode) != 0) {
			rc = skp_fail(err, SKP_ERR_IO, 0, "%s: drmModeSetCrtc %ux%u failed: %s", s.path,
				      (unsigned)s.mode.hdisplay, (unsigned)s.mode.vdisplay, strerror(errno));
			goto release;
		}
		s.crtc_set = 1;
		s.scanout = bo;
		return SKP_OK;
	}
	if (drmModePageFlip(s.fd, s.crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, NULL) != 0) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "%s: drmModePageFlip failed: %s", s.path, strerror(errno));
		goto release;
	}
	s.pending = bo;
	return SKP_OK;
release:
	gbm_surface_release_buffer(s.surface, bo);
	return rc;
}

static void restore_crtc(void)
{
	drmModeCrtc *c = s.saved_crtc;
	if (c && s.crtc_set)
		drmModeSetCrtc(s.fd, c->crtc_id, c->buffer_id, c->x, c->y, &s.connector_id, 1, &c->mode);
	drmModeFreeCrtc(c);
	s.saved_crtc = NULL;
	s.crtc_set = 0;
}

static void kms_shutdown(void)
{
	if (s.fd >= 0)
		wait_for_flip(NULL);
	restore_crtc();
	if (s.scanout)
		gbm_surface_release_buffer(s.surface, s.scanout);
	s.scanout = s.pending = NULL;
	display_egl_close(&s.egl);
	/* Destroying the surface destroys its buffers, whose fb_destroy
	 * removes the DRM framebuffers: the fd must still be open. */
	if (s.surface)
		gbm_surface_destroy(s.surface);
	if (s.gbm)
		gbm_device_destroy(s.gbm);
	s.surface = NULL;
	s.gbm = NULL;
	if (s.fd >= 0) {
		drmDropMaster(s.fd);
		close(s.fd);
	}
	s.fd = -1;
}

static int kms_init(const display_config *cfg, display_info *out, skp_error *err)
{
	int rc;

	if (!cfg)
		return skp_fail(err, SKP_ERR_RANGE, 0, "display: no configuration");
	if ((rc = display_check_rotation(cfg->rotation, err)) != SKP_OK)
		return rc;
	if ((rc = open_device(cfg->device, err)) != SKP_OK)
		goto fail;
	if ((rc = become_master(s.fd, s.path, err)) != SKP_OK)
		goto fail;
	if ((rc = pick_output(cfg, err)) != SKP_OK || (rc = create_surface(err)) != SKP_OK)
		goto fail;
	out->width = s.mode.hdisplay;
	out->height = s.mode.vdisplay;
	out->rotation = cfg->rotation;
	out->name = "kms";
	out->gl_renderer = s.egl.renderer;
	return SKP_OK;
fail:
	kms_shutdown();
	return rc;
}

static int kms_handle_events(int *quit)
{
	(void)quit;
	/* Only page flip events arrive here; keys come from the terminal. */
	struct pollfd p = { .fd = s.fd, .events = POLLIN };
	if (s.fd < 0 || poll(&p, 1, 0) <= 0)
		return SKP_OK;
	return read_drm_events();
}

static int kms_available(void)
{
	char path[32];
	for (int i = 0; i < MAX_CARDS; i++) {
		snprintf(path, sizeof path, "/dev/dri/card%d", i);
		int fd = open(path, O_RDWR | O_CLOEXEC);
		if (fd < 0)
			continue;
		int ok = card_has_output(fd) && (drmIsMaster(fd) || drmSetMaster(fd) == 0);
		close(fd);
		if (ok)
			return 1;
	}
	return 0;
}

const display_backend display_kms = {
	.name = "kms",
	.available = kms_available,
	.init = kms_init,
	.get_proc = display_egl_get_proc,
	.present = kms_present,
	.handle_events = kms_handle_events,
	.shutdown = kms_shutdown,
};
