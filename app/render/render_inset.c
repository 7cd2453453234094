/* The compare view's close-up inset: beside each panel's body, on the same
 * side in both panels (the two panels' pictures differ where the skinning
 * does, and nowhere else), the joint where
 * LBS and DQBS part most, magnified, seen by the one close-up camera in
 * both panels with the same light: what differs between the two insets
 * is the skinning alone. The joint is ringed on each body. */
#include <math.h>
#include <string.h>

#include "render_font.h"
#include "render_internal.h"

#define INSET_SHARE 64      /* percent of the panel's width */
#define INSET_MIN_PX 48     /* smaller than this: no inset */

static int line_h(int scale)
{
	return (FONT_CELL_H + 3) * scale;
}

/* The largest text scale up to want at which every inset text fits w. */
static int inset_scale(const render_frame *f, int n, int w, int want)
{
	const char *texts[2 + RENDER_MAX_PANELS] = { f->closeup.title, f->closeup.note };
	for (int i = 0; i < n && i < RENDER_MAX_PANELS; i++)
		texts[2 + i] = f->closeup.effect[i];
	for (int t = 0; t < 2 + RENDER_MAX_PANELS; t++)
		while (texts[t] && want > 1 && render_text_width(texts[t], want) > w - 4)
			want--;
	return want < 1 ? 1 : want;
}

int render_closeup_on(const renderer *r, const render_frame *f)
{
	const render_closeup *c = &f->closeup;
	return f->panel_count >= 2 && c->title && c->joint >= 0 && c->joint < r->bone_count;
}

int render_inset_split(const renderer *r, const render_frame *f, int n, render_rect area, const render_bands *b,
		       render_rect *body, render_rect *inset)
{
	int lw, lh;
	*body = area;
	if (n < 2 || !render_closeup_on(r, f))
		return 0;
	render_logical_size(r, &lw, &lh);
	int iw = area.w * INSET_SHARE / 100, ts = inset_scale(f, n, iw, b->scale + 1);
	int above = line_h(ts), below = 2 * line_h(ts) + ts;
	int bottom = area.y + b->foot, top = area.y + area.h - (area.y + area.h == lh ? b->top : 0);
	int room = top - bottom - above - below, side = iw - 4 * ts < room ? iw - 4 * ts : room;
	if (side < INSET_MIN_PX)
		return 0;
	int col = area.x + area.w - iw;
	*inset = (render_rect){ col + (iw - side) / 2, bottom + below + (room - side) / 2, side, side };
	*body = (render_rect){ area.x, area.y, area.w - iw, area.h };
	return 1;
}

/* A quad over the whole viewport at the far plane, drawn whatever the
 * depth: the inset's backdrop, and its depth cleared for the body. */
static void backdrop(renderer *r, const float rgba[4])
{
	const gl_api *gl = r->gl;
	const float z = 0.9999f;
	float q[18] = { -1, -1, z, 1, -1, z, 1, 1, z, -1, -1, z, 1, 1, z, -1, 1, z };
	gl->DepthFunc(GL_ALWAYS);
	render_flat(r, &r->screen, rgba, GL_TRIANGLES, q, 6, 1.0f);
	gl->DepthFunc(GL_LESS);
}

static void outline(renderer *r, const float rgba[4])
{
	const gl_api *gl = r->gl;
	const float e = 0.995f;
	float l[12] = { -e, -e, 0, e, -e, 0, e, e, 0, -e, e, 0 };
	gl->Disable(GL_DEPTH_TEST);
	render_flat(r, &r->screen, rgba, GL_LINE_LOOP, l, 4, 2.0f);
	gl->Enable(GL_DEPTH_TEST);
}

/* Text centred over the inset's width, row y from the top of area. */
static void centred(renderer *r, render_rect area, render_rect inset, int y, int scale, const char *s,
		    const float rgba[4])
{
	/* on a screen too small for it at the smallest scale: left out */
	if (s && render_text_width(s, scale) <= area.w * INSET_SHARE / 100)
		render_text(r, area, inset.x - area.x + (inset.w - render_text_width(s, scale)) / 2, y, scale, s, rgba);
}

static const float ring_rgba[4] = { 1.0f, 0.78f, 0.15f, 1.0f };

void render_inset_draw(renderer *r, const render_frame *f, int panel, render_rect area, render_rect inset,
		       const render_bands *b)
{
	static const float note_rgba[4] = { 0.95f, 0.95f, 0.90f, 1.0f }, effect_rgba[4] = { 0.80f, 0.86f, 0.95f, 1.0f };
	static const float column_rgba[4] = { 0.16f, 0.18f, 0.23f, 1.0f }, inset_rgba[4] = { 0.22f, 0.24f, 0.30f, 1.0f };
	int n = f->panel_count < RENDER_MAX_PANELS ? f->panel_count : RENDER_MAX_PANELS;
	int iw = area.w * INSET_SHARE / 100;
	render_rect column = { area.x + area.w - iw, area.y, iw, area.h };
	render_set_viewport(r, column);
	backdrop(r, column_rgba);
	render_set_viewport(r, inset);
	backdrop(r, inset_rgba);
	mat4 cam = closeup_camera_matrix(&r->inset, r->inset.span, 1.0f);
	mat4 vp = mat4_mul(&r->screen, &cam);
	render_body_seen(r, &vp, f, panel, r->inset.azimuth);
	outline(r, ring_rgba);
	render_set_viewport(r, area);
	int ts = inset_scale(f, n, iw, b->scale + 1);
	int top = area.y + area.h - (inset.y + inset.h), under = area.y + area.h - inset.y;
	centred(r, area, inset, top - line_h(ts) + ts, ts, f->closeup.title, ring_rgba);
	centred(r, area, inset, under + 2 * ts, ts, f->closeup.note, note_rgba);
	centred(r, area, inset, under + 2 * ts + line_h(ts), ts, f->closeup.effect[panel], effect_rgba);
}

void render_inset_ring(renderer *r, const mat4 *vp)
{
	const gl_api *gl = r->gl;
	enum { SEGMENTS = 40 };
	vec3 at = r->inset.target;
	float radius = r->inset.span, az = r->cam.azimuth;
	vec3 side = vec3_make(cosf(az), 0.0f, -sinf(az)), up = vec3_make(0.0f, 1.0f, 0.0f);
	for (int i = 0; i < SEGMENTS; i++) {
		float a = 6.2831853f * (float)i / SEGMENTS;
		vec3 p = vec3_madd(vec3_madd(at, side, radius * cosf(a)), up, radius * sinf(a));
		r->misc[3 * i] = p.x, r->misc[3 * i + 1] = p.y, r->misc[3 * i + 2] = p.z;
	}
	gl->Disable(GL_DEPTH_TEST);
	render_flat(r, vp, ring_rgba, GL_LINE_LOOP, r->misc, SEGMENTS, 2.0f);
	gl->Enable(GL_DEPTH_TEST);
}
