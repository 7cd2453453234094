/* Display backends end to end: bring one up, load the GL entry points,
 * draw with a GLSL ES 1.00 program, read the pixels back exactly and
 * round-trip them through a PNG. surfaceless and osmesa must work on any
 * machine with Mesa (llvmpipe); x11 runs under Xvfb when it is installed;
 * kms can only be checked to fail cleanly without a DRM device. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "display.h"
#include "gl_api.h"
#include "png_writer.h"
#include "test_xvfb.h"

#define W 64
#define H 48

#if defined(__SANITIZE_ADDRESS__)
/* libOSMesa never frees the framebuffer OSMesaMakeCurrent makes (it has no
 * call to do so): tests/lsan.supp names it, when run from the tree. */
const char *__lsan_default_options(void);
const char *__lsan_default_options(void)
{
	return access("tests/lsan.supp", R_OK) == 0 ? "suppressions=tests/lsan.supp" : "";
}
#endif

static const char *const vertex_src =
	"#version 100\n"
	"attribute vec2 pos;\n"
	"void main() { gl_Position = vec4(pos, 0.0, 1.0); }\n";
static const char *const fragment_src =
	"#version 100\n"
	"precision mediump float;\n"
	"uniform vec4 color;\n"
	"void main() { gl_FragColor = color; }\n";

/* Clear blue, triangle (255, 51, 0): both exact in 8 bits (0.2 * 255 = 51). */
static const uint8_t clear_rgba[4] = { 0, 0, 255, 255 };
static const uint8_t tri_rgba[4] = { 255, 51, 0, 255 };

static uint8_t pixels[W * H * 4], png_pixels[W * H * 4];

static GLuint compile(gl_api *gl, GLenum type, const char *src)
{
	char log[512] = "";
	GLint ok = 0;
	GLuint sh = gl->CreateShader(type);
	gl->ShaderSource(sh, 1, &src, NULL);
	gl->CompileShader(sh);
	gl->GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
	if (!ok) {
		gl->GetShaderInfoLog(sh, sizeof log, NULL, log);
		fail_msg("%s shader does not compile: %s", type == GL_VERTEX_SHADER ? "vertex" : "fragment", log);
	}
	return sh;
}

static GLuint link_program(gl_api *gl)
{
	char log[512] = "";
	GLint ok = 0;
	GLuint prog = gl->CreateProgram();
	GLuint vs = compile(gl, GL_VERTEX_SHADER, vertex_src), fs = compile(gl, GL_FRAGMENT_SHADER, fragment_src);
	gl->AttachShader(prog, vs);
	gl->AttachShader(prog, fs);
	gl->BindAttribLocation(prog, 0, "pos");
	gl->LinkProgram(prog);
	gl->GetProgramiv(prog, GL_LINK_STATUS, &ok);
	if (!ok) {
		gl->GetProgramInfoLog(prog, sizeof log, NULL, log);
		fail_msg("program does not link: %s", log);
	}
	gl->DeleteShader(vs);
	gl->DeleteShader(fs);
	return prog;
}

/* Clears, then draws the triangle over the top-left half (above the
 * diagonal from bottom-left to top-right) and reads back bottom-up rows. */
static void draw_scene(gl_api *gl)
{
	static const GLfloat tri[] = { -1, 1, 1, 1, -1, -1 };
	GLuint prog = link_program(gl), vbo;

	gl->GenBuffers(1, &vbo);
	gl->BindBuffer(GL_ARRAY_BUFFER, vbo);
	gl->BufferData(GL_ARRAY_BUFFER, sizeof tri, tri, GL_STATIC_DRAW);
	gl->ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
	gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	gl->UseProgram(prog);
	gl->Uniform4f(gl->GetUniformLocation(prog, "color"), 1.0f, 0.2f, 0.0f, 1.0f);
	gl->EnableVertexAttribArray(0);
	gl->VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, NULL);
	gl->DrawArrays(GL_TRIANGLES, 0, 3);
	gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
	gl->ReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
	assert_int_equal(gl->GetError(), GL_NO_ERROR);
	gl->DisableVertexAttribArray(0);
	gl->DeleteBuffers(1, &vbo);
	gl->DeleteProgram(prog);
}

/* Every pixel clearly off the diagonal has exactly its colour. */
static void check_pixels(const char *backend)
{
	int inside = 0, outside = 0;
	for (int y = 0; y < H; y++) {
		for (int x = 0; x < W; x++) {
			float nx = (x + 0.5f) * 2.0f / W - 1.0f, ny = (y + 0.5f) * 2.0f / H - 1.0f;
			if (ny - nx > -0.1f && ny - nx < 0.1f)
				continue;
			const uint8_t *want = ny > nx ? tri_rgba : clear_rgba, *p = &pixels[(y * W + x) * 4];
			if (memcmp(p, want, 4) != 0)
				fail_msg("%s: pixel (%d, %d) from the bottom is %d %d %d %d, want %d %d %d %d", backend,
					 x, y, p[0], p[1], p[2], p[3], want[0], want[1], want[2], want[3]);
			*(ny > nx ? &inside : &outside) += 1;
		}
	}
	assert_true(inside > W * H / 3 && outside > W * H / 3);
}

/* The PNG is top-down; pixels are bottom-up. */
static void check_png_round_trip(const char *backend)
{
	char path[] = "/tmp/skp_display_XXXXXX.png";
	skp_error err;
	int w = 0, h = 0, fd = mkstemps(path, 4);

	assert_true(fd >= 0);
	close(fd);
	if (png_write_rgba(path, pixels, W, H, PNG_WRITE_BOTTOM_UP, &err) != SKP_OK)
		fail_msg("%s: %s", backend, err.msg);
	memset(png_pixels, 0, sizeof png_pixels);
	int rc = png_read_rgba(path, png_pixels, sizeof png_pixels, &w, &h, &err);
	unlink(path);
	if (rc != SKP_OK)
		fail_msg("%s: %s", backend, err.msg);
	assert_int_equal(w, W);
	assert_int_equal(h, H);
	for (int y = 0; y < H; y++)
		assert_memory_equal(&png_pixels[y * W * 4], &pixels[(H - 1 - y) * W * 4], W * 4);
}

/* init, draw, check, present, shutdown; unless must_start, skips (saying
 * why) when the backend cannot start here. */
static void exercise(const display_backend *b, const char *device, int must_start)
{
	display_config cfg = { W, H, device, 90 };
	display_info info;
	skp_error err;
	gl_api gl;

	memset(&info, 0, sizeof info);
	if (b->init(&cfg, &info, &err) != SKP_OK) {
		if (must_start)
			fail_msg("%s: cannot start: %s", b->name, err.msg);
		print_message("%s: cannot start: %s\n", b->name, err.msg);
		skip();
	}
	print_message("%s: GL_RENDERER %s\n", b->name, info.gl_renderer);
	assert_int_equal(info.width, W);
	assert_int_equal(info.height, H);
	assert_int_equal(info.rotation, 90);
	assert_string_equal(info.name, b->name);
	assert_true(info.gl_renderer && info.gl_renderer[0]);
	if (gl_api_load(&gl, b->get_proc, &err) != SKP_OK)
		fail_msg("%s: %s", b->name, err.msg);
	draw_scene(&gl);
	check_pixels(b->name);
	check_png_round_trip(b->name);
	if (b->present(&err) != SKP_OK)
		fail_msg("%s: present: %s", b->name, err.msg);
	int quit = 0;
	assert_int_equal(b->handle_events(&quit), SKP_OK);
	assert_int_equal(quit, 0);
	b->shutdown();
}

/* The board's backend of that name; the test is skipped on a board that
 * does not build it (board.mk: DISPLAYS). */
static const display_backend *backend(const char *name)
{
	const display_backend *b = display_find(name);
	if (!b) {
		print_message("%s: not built for this board\n", name);
		skip();
	}
	return b;
}

static void test_surfaceless(void **state)
{
	(void)state;
	exercise(backend("surfaceless"), NULL, 0);
	/* A second start after shutdown, at another size. */
	display_config cfg = { 32, 16, NULL, 0 };
	display_info info;
	skp_error err;
	assert_int_equal(backend("surfaceless")->init(&cfg, &info, &err), SKP_OK);
	backend("surfaceless")->shutdown();
}

static void test_osmesa(void **state)
{
	(void)state;
	exercise(backend("osmesa"), NULL, 0);
}

static void test_bad_configs_are_refused(void **state)
{
	display_config big = { 8000, 8000, NULL, 0 }, rot = { W, H, NULL, 45 }, empty = { 0, H, NULL, 0 };
	display_info info;
	skp_error err;
	(void)state;
	assert_int_equal(backend("osmesa")->init(&big, &info, &err), SKP_ERR_LIMIT);
	assert_non_null(strstr(err.msg, "8000x8000"));
	assert_int_equal(backend("surfaceless")->init(&rot, &info, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "rotation 45"));
	assert_int_equal(backend("kms")->init(&rot, &info, &err), SKP_ERR_RANGE);
	assert_int_equal(backend("x11")->init(&empty, &info, &err), SKP_ERR_RANGE);
}

static void test_kms_fails_cleanly_without_drm(void **state)
{
	display_config cfg = { W, H, "/nonexistent/dri/card0", 0 };
	display_info info;
	skp_error err;
	struct stat st;
	(void)state;

	assert_int_equal(backend("kms")->init(&cfg, &info, &err), SKP_ERR_IO);
	print_message("kms: %s\n", err.msg);
	assert_non_null(strstr(err.msg, "/nonexistent/dri/card0"));
	/* The automatic search, only where it cannot take over a real screen. */
	if (stat("/dev/dri", &st) == 0) {
		print_message("kms: /dev/dri exists: automatic device search not tried\n");
		return;
	}
	cfg.device = NULL;
	assert_int_equal(backend("kms")->init(&cfg, &info, &err), SKP_ERR_IO);
	print_message("kms: %s\n", err.msg);
	assert_non_null(strstr(err.msg, "/dev/dri/card"));
	assert_int_equal(backend("kms")->available(), 0);
}

static void test_x11_without_server(void **state)
{
	display_config cfg = { W, H, ":4077", 0 };
	display_info info;
	skp_error err;
	(void)state;
	assert_int_equal(backend("x11")->init(&cfg, &info, &err), SKP_ERR_IO);
	assert_non_null(strstr(err.msg, "cannot open display ':4077'"));
}

static pid_t xvfb_pid;

static void test_x11_under_xvfb(void **state)
{
	char name[16];
	(void)state;
	xvfb_pid = test_xvfb_start("320x240x24", name, sizeof name);
	if (!xvfb_pid) {
		print_message("x11: Xvfb not installed or did not start (apt-get install xvfb)\n");
		skip();
	}
	exercise(backend("x11"), name, 1);
}

/* A teardown, so that Xvfb stops even when the test fails. */
static int stop_xvfb(void **state)
{
	(void)state;
	backend("x11")->shutdown();
	test_xvfb_stop(xvfb_pid);
	xvfb_pid = 0;
	return 0;
}

static void test_find_and_auto(void **state)
{
	(void)state;
	static const char *const names[] = { "surfaceless", "osmesa", "kms", "x11" };
	for (int i = 0; i < 4; i++)
		assert_string_equal(backend(names[i])->name, names[i]);
	assert_null(display_find("wayland"));
	assert_null(display_find(NULL));
	setenv("DISPLAY", ":4077", 1);
	assert_ptr_equal(display_auto(), backend("x11"));
	unsetenv("DISPLAY");
	setenv("WAYLAND_DISPLAY", "wayland-0", 1);
	assert_ptr_equal(display_auto(), backend("surfaceless"));
	unsetenv("WAYLAND_DISPLAY");
	assert_ptr_equal(display_auto(), backend("kms")->available() ? backend("kms") : backend("surfaceless"));
}

/* display_open: an unknown name refused with the ones built, headless
 * starts surfaceless, a named backend that cannot start does not fall
 * back (the user asked for it). */
static void test_open(void **state)
{
	display_config cfg = { W, H, "/nonexistent/dri/card0", 0 };
	display_info info;
	skp_error err, first;
	(void)state;
	assert_null(display_open("wayland", &cfg, &info, &first, &err));
	assert_non_null(strstr(err.msg, "unknown platform 'wayland'"));
	assert_non_null(strstr(err.msg, "surfaceless osmesa kms x11"));
	assert_int_equal(first.code, SKP_OK);
	assert_ptr_equal(display_open("headless", &cfg, &info, &first, &err), backend("surfaceless"));
	assert_int_equal(first.code, SKP_OK);
	assert_int_equal(info.width, W);
	backend("surfaceless")->shutdown();
	assert_null(display_open("kms", &cfg, &info, &first, &err));
	assert_non_null(strstr(err.msg, "/nonexistent/dri/card0"));
	assert_int_equal(first.code, SKP_OK);
}

static void test_png_errors(void **state)
{
	skp_error err;
	int w, h;
	(void)state;
	memset(pixels, 7, sizeof pixels);
	assert_int_equal(png_write_rgba("/nonexistent/dir/x.png", pixels, W, H, 0, &err), SKP_ERR_IO);
	assert_non_null(strstr(err.msg, "/nonexistent/dir/x.png"));
	assert_int_equal(png_read_rgba("/nonexistent/dir/x.png", pixels, sizeof pixels, &w, &h, &err), SKP_ERR_IO);
	char path[] = "/tmp/skp_png_XXXXXX.png";
	int fd = mkstemps(path, 4);
	assert_true(fd >= 0);
	close(fd);
	assert_int_equal(png_write_rgba(path, pixels, W, H, 0, &err), SKP_OK);
	assert_int_equal(png_read_rgba(path, png_pixels, W * H * 4 - 1, &w, &h, &err), SKP_ERR_LIMIT);
	assert_non_null(strstr(err.msg, "64x48"));
	assert_int_equal(png_read_rgba(path, png_pixels, sizeof png_pixels, &w, &h, &err), SKP_OK);
	assert_memory_equal(png_pixels, pixels, sizeof pixels);
	unlink(path);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_surfaceless),
		cmocka_unit_test(test_osmesa),
		cmocka_unit_test(test_bad_configs_are_refused),
		cmocka_unit_test(test_kms_fails_cleanly_without_drm),
		cmocka_unit_test(test_x11_without_server),
		cmocka_unit_test_teardown(test_x11_under_xvfb, stop_xvfb),
		cmocka_unit_test(test_find_and_auto),
		cmocka_unit_test(test_open),
		cmocka_unit_test(test_png_errors),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
