/* The renderer: a lit body (skinned on the CPU or in the vertex shader), a
 * ground grid with a soft blob shadow, a camera following the root (and,
 * given the space the body takes over the clip, framing all of it above the
 * captions), a skeleton overlay, a weight view with its colour legend, a
 * HUD, and a compare view with two algorithms side by side. OpenGL ES 2.0
 * through gl_api; no allocation: the renderer is one struct the caller owns
 * (keep it static). */
#ifndef RENDER_H
#define RENDER_H

#include "camera.h"
#include "render_closeup.h"
#include "fk.h"
#include "gl_api.h"
#include "render_shaders.h"
#include "skin.h"
#include "tex_image.h"

#define RENDER_MAX_PANELS 2
#define RENDER_HUD_LINES 4
#define RENDER_MAX_TEXT 512     /* glyphs drawn per frame */
#define RENDER_CAMERA_AZIMUTH 0.45f /* the usual view: front, a little from the body's left */

/* One side of the picture: which algorithm, and for CPU skinning the
 * skinned positions and normals (xyz per vertex): float normals, or
 * 16-bit snorm ones from the compact kernels (nrm16, when nrm is NULL). */
typedef struct render_panel {
	skin_algo algo;
	const float *pos, *nrm;  /* pos NULL: skin on the GPU from the bone uniforms */
	const int16_t *nrm16;
	const char *label;       /* drawn at the top of the panel in compare view */
} render_panel;

/* The compare view's close-up: beside each panel's body a magnified inset
 * of one joint, seen by the same camera in both panels (render_closeup.h
 * picks the joint and moves that camera). */
typedef struct render_closeup {
	int joint;               /* the bone whose head is looked at; -1 (or no title): no inset */
	vec3 focus;              /* where on it the methods part (skin_diff_focus) */
	float span;              /* how far round they part (skin_diff_focus's reach); 0: CLOSEUP_SPAN of the body */
	const char *title;       /* over the insets: "LEFT WRIST" */
	const char *note;        /* under them, what the joint did ("TWISTED 178 DEG"); may be NULL */
	const char *effect[RENDER_MAX_PANELS]; /* under each inset, what the skin did; may be NULL */
} render_closeup;

typedef struct render_frame {
	const skel_pose *pose;   /* posed skeleton (overlay, camera) */
	const skin_bones *bones; /* this frame's bone transforms (GPU skinning) */
	render_panel panel[RENDER_MAX_PANELS];
	int panel_count;         /* 1, or 2 for the compare view */
	render_view view;
	const char *hud[RENDER_HUD_LINES]; /* top-left text, NULL lines skipped */
	/* the visitor's screen: each panel's label large (one panel too) with
	 * a sentence above it, and a badge (PAUSED) across the top */
	int visitor;
	const char *caption[RENDER_MAX_PANELS];
	const char *badge;
	float dt;                /* seconds since the previous frame (camera) */
	render_closeup closeup;
	/* RENDER_VIEW_DIFFERENCE: per vertex, how far LBS lies from DQBS
	 * (diff_signed 0), or the skin's distance to its bone less the bound
	 * one (1: negative thinner), in the skeleton's units; NULL: the body's
	 * own colour */
	const float *diff;
	int diff_signed;
	/* the character alone on a see-through background: no floor, grid,
	 * shadow, close-up, labels or HUD (headless frames for compositing) */
	int transparent;
	/* a wall (render_set_wall): where the root is at the clip's start, x
	 * and z; the camera stays on it, so a figure travelling crosses from
	 * screen to screen */
	vec3 anchor;
} render_frame;

/* A video wall (render_wall.c): columns x rows screens, this device the
 * one at column, row (0-based, from the top left); bezel: the picture
 * hidden behind two neighbouring screens' frames, in pixels of a screen.
 * columns 0: no wall. */
typedef struct render_wall {
	int columns, rows, column, row, bezel;
} render_wall;

/* The device's own camera (board.ini [camera]): pitch in radians from
 * above, distance times the framing one, aim the point looked at from the
 * body's centre in body heights. */
typedef struct render_view_cam {
	float pitch, distance;
	vec3 aim;
} render_view_cam;

typedef struct renderer {
	const gl_api *gl;
	int width, height, rotation;
	int vert_count, index_count, bone_count;
	const skel *skel;
	GLuint prog[6];
	GLuint vbo_static;       /* bind pos, nrm, weight colour, bones, weights */
	GLuint vbo_skinned[RENDER_MAX_PANELS];
	GLuint ibo, vbo_misc, font_tex;
	int font_w;
	float floor_y;
	follow_camera cam;
	int framed;              /* render_set_extent was called: frame the box */
	vec3 ext_lo, ext_hi;     /* the box framed now (eased towards the goal), */
	vec3 goal_lo, goal_hi;   /* and the one asked for: x, z from the root */
	uint8_t bone_used[SKP_MAX_BONES]; /* bones with skin: the weights legend */
	mat4 screen;             /* rotation for screens mounted sideways */
	render_wall wall;        /* this screen's tile of a wall (render_set_wall) */
	closeup_camera inset;    /* the close-up's camera */
	float mm_per_unit;       /* the difference view's legend (render_set_units) */
	int size_assumed;        /* the units gave no human size: the body taken as 1.75 m */
	GLuint vbo_diff;         /* the difference view's colours, RGBA8 per vertex */
	GLuint vbo_look;         /* the body's own colours, RGB8 per vertex (render_set_colours) */
	int look_ready;          /* vbo_look holds them: drawn instead of the skin colour */
	GLuint vbo_uv, vbo_sampled, body_tex; /* the body's texture (render_set_texture) */
	int tex_ready;           /* they hold it: multiplied into the colours */
	const char *tex_path;    /* how it went to the GPU: "ETC1" or "RGB565" */
	int diff_ready;          /* vbo_diff holds this frame's */
	uint8_t diff_rgba[4 * SKP_MAX_VERTS];
	float misc[6 * 1024];    /* grid, shadow and overlay vertices */
	float text[RENDER_MAX_TEXT * 6 * 5];
	float bone_uniforms[RENDER_BONE_VEC4S * 4];
} renderer;

/* Uploads the bound body: bind-pose vertices and influences from soa,
 * triangles (vertex indices must fit 16 bits: GLES 2.0), and builds the
 * shaders. floor_y is the ground height (the lowest point of the body in
 * its first frame). */
skp_status render_init(renderer *r, const gl_api *gl, int width, int height, int rotation,
		       const skel *s, const skin_soa *soa, const uint32_t (*tri)[3], int tri_count,
		       float floor_y, skp_error *err);

/* The body's own base colours (sRGB, one per vertex of the bound body,
 * mesh.colour), drawn in the plain and compare views, lit as the skin
 * colour is; rgb NULL: the skin colour again. */
void render_set_colours(renderer *r, const uint8_t (*rgb)[3]);

/* The body's base colour texture (m->textured: its uv and sampled, t's
 * ETC1 mip chain), multiplied into its colours in the plain and compare
 * views. etc1: 1 to hand the blocks to a GPU that samples ETC1 (the
 * Raspberry Pi's; r->tex_path "ETC1"), 0 to decode each level to RGB565
 * first ("RGB565", what a GPU without ETC1 gets either way). m not
 * textured, or t NULL: no texture. Fails on a GL error or a chain that
 * does not decode. */
skp_status render_set_texture(renderer *r, const mesh *m, const tex_image *t, int etc1, skp_error *err);

/* 1 when the skeleton's bone uniforms for algo fit GLES 2.0's guaranteed
 * vertex uniforms, so GPU skinning can be used. */
int render_gpu_fits(const renderer *r, skin_algo algo);

/* Sends the CPU-skinned vertices of every panel to the GPU (apart from
 * render_draw so the two can be timed separately). */
void render_upload(renderer *r, const render_frame *f);

/* Moves the cameras (the body's, the close-up's, the framed box) by the
 * frame's dt, then draws it. */
void render_draw(renderer *r, const render_frame *f);

/* Moves the cameras as render_draw would, drawing nothing: a headless run
 * skips the frames it does not write, and the next one it draws is the
 * same picture as if every frame had been drawn. */
void render_advance(renderer *r, const render_frame *f);

/* Reads the frame back as RGBA8, bottom row first (glReadPixels order). */
void render_read_rgba(const renderer *r, uint8_t *rgba);

void render_shutdown(renderer *r);

/* The space the body takes (the joints over a whole clip, with room for
 * the flesh round them): y as it is, x and z from the root's horizontal
 * position, which the camera follows. From then on the camera frames all
 * of it, feet and head, above the captions at the foot of each panel and
 * below the HUD; a larger box is taken at once (nothing leaves the
 * picture), a smaller one eased into over the next frames, or at once. */
void render_set_extent(renderer *r, vec3 lo, vec3 hi, int immediate);

/* A renderer for text alone (render_draw_notice): when there is no body to
 * show (no valid show in any image slot), the screen still says why. */
skp_status render_init_notice(renderer *r, const gl_api *gl, int width, int height, int rotation, skp_error *err);

/* Clears the screen and draws the lines centred, the first larger. */
void render_draw_notice(renderer *r, const char *const *lines, int count);

/* The skeleton's length unit in millimetres (0: unknown), so that the
 * difference view's legend reads in millimetres at the body's real size;
 * a body outside 1..2.5 m tall by that unit is taken as 1.75 m (and the
 * legend says so). */
void render_set_units(renderer *r, float mm_per_unit);

/* The difference view's colour of each of n values (the skeleton's
 * units; mm_per_unit turns them into millimetres) as RGBA8: a scale from
 * none to 40 mm, or for a signed change -30 to +30 mm (blue thinner, grey
 * as bound, red thicker). Apart from the upload, for the benchmark. */
void render_diff_colours(const float *diff, int n, float mm_per_unit, int is_signed, uint8_t *rgba);

/* Turns the camera yaw radians about the vertical from the usual view (a
 * body facing +z seen from the front, RENDER_CAMERA_AZIMUTH to its left):
 * smoothly over the next frames, or at once. */
void render_set_yaw(renderer *r, float yaw, int immediate);

/* The device's own camera, instead of the usual pitch, distance and aim. */
void render_set_view(renderer *r, const render_view_cam *v);

/* Makes this screen draw its tile of the wall w (columns 0: the whole
 * picture again): the camera frames the body for the whole wall's shape,
 * and the tiles of all its screens side by side equal one render at the
 * wall's size. No labels' bands in a wall: the picture runs on across. */
void render_set_wall(renderer *r, const render_wall *w);

/* The wall's size in screens (bezels included) across and up, and the
 * projection that makes this screen's tile of it fill the screen
 * (multiplied after the whole wall's). */
void render_wall_span(const render_wall *w, int width, int height, float *sx, float *sy);
mat4 render_wall_tile(const render_wall *w, int width, int height);

#endif
