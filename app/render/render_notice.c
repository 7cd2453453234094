/* A screen of text and nothing else, for a kiosk with nothing it can play. */
#include "render_font.h"
#include "render_internal.h"

/* The largest scale up to want at which s fits the width. */
static int fit(const char *s, int want, int w)
{
	while (want > 1 && render_text_width(s, want) > w - 16)
		want--;
	return want;
}

void render_draw_notice(renderer *r, const char *const *lines, int count)
{
	static const float title_rgba[4] = { 1.0f, 0.8f, 0.2f, 1.0f }, text_rgba[4] = { 0.95f, 0.95f, 0.85f, 1.0f };
	const gl_api *gl = r->gl;
	int lw, lh;
	render_logical_size(r, &lw, &lh);
	gl->Viewport(0, 0, r->width, r->height);
	gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
	gl->ClearColor(0.13f, 0.15f, 0.19f, 1.0f);
	gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
	render_rect full = { 0, 0, lw, lh };
	render_set_viewport(r, full);
	int base = lh / 240 > 1 ? lh / 240 : 1, y = lh / 3;
	for (int i = 0; i < count; i++) {
		int s = fit(lines[i], i == 0 ? base + 2 : base, lw);
		render_text(r, full, (lw - render_text_width(lines[i], s)) / 2, y, s, lines[i], i == 0 ? title_rgba : text_rgba);
		y += (FONT_CELL_H + 4) * s + (i == 0 ? FONT_CELL_H * base : 0);
	}
}
