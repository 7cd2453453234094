/* One frame: for each panel the grid and shadow, the body, the skeleton
 * overlay and the label; then the HUD over the whole screen. */
#include <math.h>
#include <string.h>

#include "render_font.h"
#include "render_internal.h"

/* A floor under the grid makes the blob shadow readable. */
static void draw_floor(renderer *r, const mat4 *vp, float cx, float cz, float e, float y)
{
	float q[18] = { cx - e, y, cz - e,  cx - e, y, cz + e,  cx + e, y, cz + e,
			cx - e, y, cz - e,  cx + e, y, cz + e,  cx + e, y, cz - e };
	static const float floor_rgba[4] = { 0.27f, 0.29f, 0.33f, 1.0f };
	render_flat(r, vp, floor_rgba, GL_TRIANGLES, q, 6, 1.0f);
}

/* p (xyz) in clip space */
static void to_clip(const mat4 *vp, const float *p, float c[4])
{
	const float *m = vp->m;
	for (int k = 0; k < 4; k++)
		c[k] = m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k];
}

/* Cuts the line a-b (xyz each) to the view (Liang-Barsky in clip space);
 * 0 when none of it is in view. Mesa 24's llvmpipe (Debian 13) draws a
 * floor line that runs far out of the view, as the close-ups' do, as a fan
 * of wide triangles across the picture. */
static int keep_in_view(const mat4 *vp, float *a, float *b)
{
	float ca[4], cb[4], t0 = 0.0f, t1 = 1.0f;
	to_clip(vp, a, ca);
	to_clip(vp, b, cb);
	for (int k = 0; k < 6; k++) {
		/* the distance inside plane k: w - x, w + x, w - y, ... */
		float s = k & 1 ? 1.0f : -1.0f;
		float da = ca[3] + s * ca[k / 2], db = cb[3] + s * cb[k / 2];
		if (da < 0 && db < 0)
			return 0;
		if (da < 0)
			t0 = fmaxf(t0, da / (da - db));
		else if (db < 0)
			t1 = fminf(t1, da / (da - db));
	}
	if (t0 >= t1)
		return 0;
	float from[3], to[3];
	for (int k = 0; k < 3; k++) {
		from[k] = a[k] + t0 * (b[k] - a[k]);
		to[k] = a[k] + t1 * (b[k] - a[k]);
	}
	memcpy(a, from, sizeof from);
	memcpy(b, to, sizeof to);
	return 1;
}

void render_grid_and_shadow(renderer *r, const mat4 *vp, vec3 root)
{
	const gl_api *gl = r->gl;
	float step = r->cam.height * 0.25f, y = r->floor_y;
	float cx = floorf(r->cam.target.x / step) * step, cz = floorf(r->cam.target.z / step) * step;
	const int half = 16;
	int n = 0;
	draw_floor(r, vp, cx, cz, (float)half * step, y - 0.001f * r->cam.height);
	for (int i = -half; i <= half; i++) {
		float o = (float)i * step, e = (float)half * step;
		float l[12] = { cx + o, y, cz - e, cx + o, y, cz + e, cx - e, y, cz + o, cx + e, y, cz + o };
		for (int k = 0; k < 12; k += 6)
			if (keep_in_view(vp, l + k, l + k + 3)) {
				memcpy(r->misc + n, l + k, 6 * sizeof(float));
				n += 6;
			}
	}
	static const float grid_rgba[4] = { 0.40f, 0.43f, 0.49f, 1.0f };
	render_flat(r, vp, grid_rgba, GL_LINES, r->misc, n / 3, 1.0f);

	/* the blob: a quad on the floor under the root, alpha from the centre */
	float s = r->cam.height * 0.32f, h = y + 0.002f * r->cam.height;
	float q[30] = { /* counter-clockwise seen from above */
		root.x - s, h, root.z - s, -1, -1,  root.x - s, h, root.z + s, -1, 1,
		root.x + s, h, root.z + s, 1, 1,    root.x - s, h, root.z - s, -1, -1,
		root.x + s, h, root.z + s, 1, 1,    root.x + s, h, root.z - s, 1, -1,
	};
	gl->UseProgram(r->prog[SHADER_SHADOW]);
	gl->UniformMatrix4fv(render_loc[SHADER_SHADOW][U_MVP], 1, GL_FALSE, vp->m);
	gl->Uniform1f(render_loc[SHADER_SHADOW][U_STRENGTH], 0.55f);
	gl->Enable(GL_BLEND);
	gl->BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
	gl->DepthMask(GL_FALSE);
	render_stream(r, q, 30);
	render_attrib(gl, ATTR_POS, 3, 20, 0);
	render_attrib(gl, ATTR_UV, 2, 20, 12);
	gl->DrawArrays(GL_TRIANGLES, 0, 6);
	render_disable_attribs(gl);
	gl->DepthMask(GL_TRUE);
	gl->Disable(GL_BLEND);
}

void render_skeleton(renderer *r, const mat4 *vp, const skel_pose *pose)
{
	const gl_api *gl = r->gl;
	int n = 0;
	for (int b = 1; b < r->bone_count && n + 6 <= (int)(sizeof r->misc / 4); b++) {
		vec3 a = pose->head[b], t = pose->tip[b];
		float l[6] = { a.x, a.y, a.z, t.x, t.y, t.z };
		memcpy(r->misc + n, l, sizeof l);
		n += 6;
	}
	static const float bone_rgba[4] = { 1.0f, 0.85f, 0.1f, 1.0f };
	gl->Disable(GL_DEPTH_TEST);
	render_use_flat(r, vp, bone_rgba, 5.0f);
	render_stream(r, r->misc, n);
	render_attrib(gl, ATTR_POS, 3, 12, 0);
	gl->LineWidth(2.0f);
	gl->DrawArrays(GL_LINES, 0, n / 3);
	gl->DrawArrays(GL_POINTS, 0, n / 3);
	gl->LineWidth(1.0f);
	render_disable_attribs(gl);
	gl->Enable(GL_DEPTH_TEST);
}

void render_upload(renderer *r, const render_frame *f)
{
	const gl_api *gl = r->gl;
	GLsizeiptr bytes = (GLsizeiptr)r->vert_count * 12;
	for (int i = 0; i < f->panel_count && i < RENDER_MAX_PANELS; i++) {
		if (!f->panel[i].pos)
			continue;
		gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_skinned[i]);
		gl->BufferSubData(GL_ARRAY_BUFFER, 0, bytes, f->panel[i].pos);
		if (f->panel[i].nrm)
			gl->BufferSubData(GL_ARRAY_BUFFER, bytes, bytes, f->panel[i].nrm);
		else
			gl->BufferSubData(GL_ARRAY_BUFFER, bytes, bytes / 2, f->panel[i].nrm16);
	}
	r->diff_ready = 0;
	if (f->view == RENDER_VIEW_DIFFERENCE && f->diff)
		render_diff_upload(r, f->diff, f->diff_signed);
}

static int text_scale(int logical_h)
{
	int s = logical_h / 240;
	return s < 1 ? 1 : s;
}

/* Where the text goes, worked out once a frame for every panel: one size
 * per role (the methods' names, the visitor's sentences), the largest at
 * which each panel's fits its width, and the bands at the foot and the top
 * that the body is framed clear of. Logical pixels. */
typedef struct layout {
	int hud;                 /* HUD line scale */
	int label, caption;      /* 0: not drawn */
	int foot;                /* the band under the body: labels, captions */
	int top;                 /* the band over it: HUD lines, the legend */
	int legend, legend_rows; /* the weights legend's scale and rows (0: none) */
} layout;

static int fit_scale(const render_frame *f, int n, int panel_w, int scale, int caption)
{
	for (int i = 0; i < n; i++) {
		const char *s = caption ? f->caption[i] : f->panel[i].label;
		while (s && scale > 1 && render_text_width(s, scale) > panel_w - 8)
			scale--;
	}
	return scale;
}

static const char legend_title[] = "WEIGHTS: EACH BONE ITS COLOUR, MIXED WHERE BONES SHARE THE SKIN:";

/* Lays the legend's words (its title, then each bone with skin) out in
 * rows of width w from pen x0; returns the rows. draw: also draws them
 * from row y0. */
static int legend_words(renderer *r, render_rect full, int scale, int y0, int draw)
{
	static const float title_rgba[4] = { 0.95f, 0.95f, 0.85f, 1.0f };
	int x0 = 4 * scale, x = x0, rows = 1, line = (FONT_CELL_H + 2) * scale, space = (FONT_GLYPH_W + 1) * scale;
	for (int b = -1; b < r->bone_count; b++) {
		if (b >= 0 && !r->bone_used[b])
			continue;
		const char *word = b < 0 ? legend_title : r->skel->bone[b].name;
		int w = render_text_width(word, scale);
		if (x > x0 && x + w > full.w - x0) {
			x = x0;
			rows++;
		}
		if (draw) {
			vec3 c = b < 0 ? vec3_make(title_rgba[0], title_rgba[1], title_rgba[2]) : render_bone_color(b);
			float rgba[4] = { c.x, c.y, c.z, 1.0f };
			render_text(r, full, x, y0 + (rows - 1) * line, scale, word, rgba);
		}
		x += w + space;
	}
	return rows;
}

/* Panel i of n: side by side, or on a portrait screen one above the other
 * (the first on top), so each body is as large as it can be. GL's y. */
static render_rect panel_rect(int i, int n, int lw, int lh)
{
	if (lh > lw) {
		int y0 = (n - 1 - i) * lh / n, y1 = (n - i) * lh / n;
		return (render_rect){ 0, y0, lw, y1 - y0 };
	}
	return (render_rect){ i * lw / n, 0, (i + 1) * lw / n - i * lw / n, lh };
}

static layout lay_out(renderer *r, const render_frame *f, int n, int lw, int lh)
{
	layout l;
	memset(&l, 0, sizeof l);
	l.hud = text_scale(lh);
	int panel_w = panel_rect(0, n, lw, lh).w;
	if ((n > 1 || f->visitor) && f->panel[0].label) {
		l.label = fit_scale(f, n, panel_w, l.hud + (f->visitor ? 3 : 1), 0);
		l.foot = (FONT_CELL_H + 4) * l.label;
		if (f->visitor && f->caption[0]) {
			l.caption = fit_scale(f, n, panel_w, l.hud + 1, 1);
			l.foot += (FONT_CELL_H + 3) * l.caption;
		}
		l.foot += 2 * l.hud;
	}
	/* the HUD's lines from the top (the notice below them and the PAUSED
	 * badge come and go: the body is not moved for them) */
	int lines = 0;
	for (int i = 0; i < RENDER_HUD_LINES - 1; i++)
		if (f->hud[i])
			lines = i + 1;
	l.top = lines ? (4 + lines * (FONT_CELL_H + 2)) * l.hud : 0;
	if (f->view == RENDER_VIEW_WEIGHTS) {
		render_rect full = { 0, 0, lw, lh };
		l.legend = (l.hud + 1) / 2;
		l.legend_rows = legend_words(r, full, l.legend, 0, 0);
	} else if (f->view == RENDER_VIEW_DIFFERENCE && f->diff) {
		l.legend = l.hud;
		l.legend_rows = RENDER_DIFF_LEGEND_ROWS;
	}
	if (l.legend_rows)
		l.top += (2 + l.legend_rows * (FONT_CELL_H + 2)) * l.legend;
	/* a tiny screen, or the character alone: the body first */
	if (l.top + l.foot > panel_rect(0, n, lw, lh).h / 2 || f->transparent)
		l.top = l.foot = 0;
	return l;
}

/* The panel's label at its foot, centred; on the visitor's screen with the
 * panel's sentence above it. */
static void draw_label(renderer *r, const render_frame *f, const layout *l, int i, render_rect area)
{
	static const float label_rgba[4] = { 1, 1, 1, 1 }, caption_rgba[4] = { 0.95f, 0.85f, 0.55f, 1 };
	const char *label = f->panel[i].label;
	int y = area.h - (FONT_CELL_H + 4) * l->label;
	render_text(r, area, (area.w - render_text_width(label, l->label)) / 2, y, l->label, label, label_rgba);
	const char *caption = l->caption ? f->caption[i] : NULL;
	if (caption)
		render_text(r, area, (area.w - render_text_width(caption, l->caption)) / 2, y - (FONT_CELL_H + 3) * l->caption,
			    l->caption, caption, caption_rgba);
}

/* Eases the framed box towards the one asked for: it grows fast (time
 * constant 0.15 s: within the 300 ms crossfade a new clip's pose takes
 * to arrive, so the body stays in the picture and the camera never cuts),
 * and shrinks over the camera's 0.6 s. */
static float ease_down(float now, float goal, float grow, float shrink)
{
	return now + (goal - now) * (goal < now ? grow : shrink);
}

static float ease_up(float now, float goal, float grow, float shrink)
{
	return now + (goal - now) * (goal > now ? grow : shrink);
}

static void ease_extent(renderer *r, float dt)
{
	float k = camera_ease(dt), g = camera_ease_in(dt, 0.15f);
	vec3 *lo = &r->ext_lo, *hi = &r->ext_hi, glo = r->goal_lo, ghi = r->goal_hi;
	*lo = vec3_make(ease_down(lo->x, glo.x, g, k), ease_down(lo->y, glo.y, g, k), ease_down(lo->z, glo.z, g, k));
	*hi = vec3_make(ease_up(hi->x, ghi.x, g, k), ease_up(hi->y, ghi.y, g, k), ease_up(hi->z, ghi.z, g, k));
}

/* The panel's camera: the box the body takes, placed at the followed root
 * and stretched to where the root is now (travelling, the camera lags it),
 * between the bands (the top one where the panel meets the screen's top);
 * without one, the camera following the body. */
static mat4 panel_camera(const renderer *r, const layout *l, render_rect area, int lh, vec3 root, vec3 anchor)
{
	float aspect = (float)area.w / (float)area.h, sx = 1.0f, sy = 1.0f;
	int wall = r->wall.columns > 0;
	if (wall) /* framed for the whole wall's shape, then this screen's tile */
		render_wall_span(&r->wall, area.w, area.h, &sx, &sy);
	mat4 tile = wall ? render_wall_tile(&r->wall, area.w, area.h) : mat4_identity(), m;
	if (!r->framed) {
		m = camera_matrix(&r->cam, aspect * sx / sy);
		return mat4_mul(&tile, &m);
	}
	vec3 at = vec3_make(r->cam.target.x, 0.0f, r->cam.target.z), now = vec3_make(root.x, 0.0f, root.z);
	if (wall)
		at = now = vec3_make(anchor.x, 0.0f, anchor.z);
	vec3 lo = vec3_min(vec3_add(r->ext_lo, at), vec3_add(r->ext_lo, now));
	vec3 hi = vec3_max(vec3_add(r->ext_hi, at), vec3_add(r->ext_hi, now));
	int top = area.y + area.h == lh ? l->top : 0;
	float bottom = -1.0f + 2.0f * (float)l->foot / (float)area.h, ceiling = 1.0f - 2.0f * (float)top / (float)area.h;
	if (wall)
		bottom = -1.0f, ceiling = 1.0f;
	m = camera_frame_box(&r->cam, lo, hi, aspect * sx / sy, bottom, ceiling);
	return mat4_mul(&tile, &m);
}

/* The body (beside its close-up, in the compare view), its overlays, its
 * label. */
static void draw_panel(renderer *r, const render_frame *f, const layout *l, int i, render_rect area, int lh)
{
	render_bands bands = { l->foot, l->top, l->hud };
	render_rect body, inset;
	int n = f->panel_count < 1 ? 1 : f->panel_count;
	int closeup = !f->transparent && render_inset_split(r, f, n, area, &bands, &body, &inset);
	if (!closeup)
		body = area;
	render_set_viewport(r, body);
	mat4 cam = panel_camera(r, l, body, lh, f->pose->tip[0], f->anchor);
	mat4 vp = mat4_mul(&r->screen, &cam);
	if (!f->transparent)
		render_grid_and_shadow(r, &vp, f->pose->tip[0]);
	render_body(r, &vp, f, i);
	if (f->view == RENDER_VIEW_SKELETON)
		render_skeleton(r, &vp, f->pose);
	if (closeup) {
		render_inset_ring(r, &vp);
		render_inset_draw(r, f, i, area, inset, &bands);
	}
	render_set_viewport(r, area);
	if (l->label && !f->transparent)
		draw_label(r, f, l, i, area);
}

/* The close-up's camera, once a frame for both panels: it snaps to the
 * first joint shown, then glides. */
static void follow_closeup(renderer *r, const render_frame *f)
{
	int j = f->closeup.joint;
	if (!render_closeup_on(r, f)) {
		r->inset.started = 0;
		r->inset.span = 0.0f;
		return;
	}
	int up = r->skel->bone[j].parent;
	vec3 axis = vec3_sub(f->pose->tip[j], f->pose->head[j]);
	vec3 parent = up >= 0 ? vec3_sub(f->pose->tip[up], f->pose->head[up]) : vec3_make(0.0f, 0.0f, 0.0f);
	closeup_camera_follow(&r->inset, f->closeup.focus, axis, parent, r->cam.azimuth, f->dt, 0);
	float want = closeup_span_want(f->closeup.span, axis, parent, r->cam.height);
	float *span = &r->inset.span;
	*span = *span <= 0.0f ? want : *span + (want - *span) * camera_ease_in(f->dt, CLOSEUP_EASE_S);
}

/* A line between the two panels: down the middle, or across on a portrait
 * screen. */
static void draw_divider(renderer *r, int lw, int lh)
{
	static const float line_rgba[4] = { 0.8f, 0.8f, 0.8f, 1.0f };
	mat4 px = mat4_ortho(0, (float)lw, 0, (float)lh, -1, 1);
	mat4 m = mat4_mul(&r->screen, &px);
	float x = (float)lw / 2, y = (float)lh / 2;
	float line[6] = { x, 0, 0, x, (float)lh, 0 };
	if (lh > lw) {
		float across[6] = { 0, y, 0, (float)lw, y, 0 };
		memcpy(line, across, sizeof line);
	}
	render_flat(r, &m, line_rgba, GL_LINES, line, 2, 1.0f);
}

/* The HUD lines at the top left, the legend under them, the badge. */
static void draw_hud(renderer *r, const render_frame *f, const layout *l, render_rect full)
{
	static const float hud_rgba[4] = { 0.95f, 0.95f, 0.85f, 1.0f }, badge_rgba[4] = { 1.0f, 0.8f, 0.2f, 1.0f };
	int s = l->hud, line = (FONT_CELL_H + 2) * s;
	for (int i = 0; i < RENDER_HUD_LINES; i++)
		if (f->hud[i])
			render_text(r, full, 4 * s, 4 * s + i * line, s, f->hud[i], hud_rgba);
	int legend_y = l->top - (l->legend_rows * (FONT_CELL_H + 2)) * l->legend;
	if (l->legend_rows && f->view == RENDER_VIEW_WEIGHTS)
		legend_words(r, full, l->legend, legend_y, 1);
	else if (l->legend_rows)
		render_diff_legend(r, full, l->legend, legend_y, f->diff_signed);
	if (f->badge) {
		int bs = s + 3;
		render_text(r, full, (full.w - render_text_width(f->badge, bs)) / 2, 8 * s + 2 * line, bs, f->badge, badge_rgba);
	}
}

void render_advance(renderer *r, const render_frame *f)
{
	if (r->framed) {
		ease_extent(r, f->dt);
		camera_follow(&r->cam, f->pose->tip[0], f->dt);
	} else {
		camera_follow(&r->cam, fk_tip_centre(f->pose, r->bone_count), f->dt);
	}
	follow_closeup(r, f);
}

void render_draw(renderer *r, const render_frame *f)
{
	const gl_api *gl = r->gl;
	int lw, lh;
	render_logical_size(r, &lw, &lh);
	render_advance(r, f);
	gl->Enable(GL_DEPTH_TEST);
	gl->Enable(GL_CULL_FACE);
	gl->CullFace(GL_BACK);
	gl->Viewport(0, 0, r->width, r->height);
	gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
	if (f->transparent)
		gl->ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
	else
		gl->ClearColor(0.13f, 0.15f, 0.19f, 1.0f);
	gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	/* keep the cleared, opaque alpha: blended shadow and text must not
	 * make screenshots see-through; on a see-through background the body
	 * (alpha 1) writes its own */
	if (!f->transparent)
		gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
	int n = f->panel_count < 1 ? 1 : f->panel_count;
	layout l = lay_out(r, f, n, lw, lh);
	for (int i = 0; i < n; i++)
		draw_panel(r, f, &l, i, panel_rect(i, n, lw, lh), lh);
	render_rect full = { 0, 0, lw, lh };
	render_set_viewport(r, full);
	if (f->transparent)
		return;
	if (n > 1)
		draw_divider(r, lw, lh);
	draw_hud(r, f, &l, full);
}
