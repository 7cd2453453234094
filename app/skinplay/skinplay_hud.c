/* skinplay's text on screen: the visitor's captions and buttons, the
 * engineer's lines (algorithm, clip, frame, rate, clock) and notices. */
#include <stdio.h>

#include "skinplay.h"

/* The visitor's screen: what each method is, what to look at, the buttons. */
static const char *const visitor_caption[SKIN_ALGO_COUNT] = {
	"elbows and twisting wrists lose volume",
	"volume kept, joints may bulge",
	"dual quaternions in integer maths",
};
static const char *const visitor_name[SKIN_ALGO_COUNT] = {
	"LINEAR BLEND", "DUAL QUATERNION", "DUAL QUATERNION (FIXED)",
};

static void visitor_hud(skinplay *p, render_frame *f)
{
	f->visitor = 1;
	for (int i = 0; i < p->panel_count; i++) {
		f->panel[i].label = visitor_name[p->algo[i]];
		f->caption[i] = visitor_caption[p->algo[i]];
	}
	f->hud[0] = keys_legend(p, 0);
	f->badge = p->kiosk.ps.playing ? NULL : "PAUSED";
}

/* The captured frame on screen (its number in the file) and the clip time. */
long shown_number(const skinplay *p)
{
	return p->hold ? 0 : p->eng.number;
}

double shown_time(const skinplay *p)
{
	return p->hold ? 0.0 : p->eng.clip_time;
}

void hud_text(skinplay *p, render_frame *f, double fps, char lines[3][128])
{
	f->visitor = 0;
	f->badge = NULL;
	for (int i = 0; i < RENDER_HUD_LINES; i++)
		f->hud[i] = NULL;
	/* a skipped clip, no clip at all: said on screen, not only in the log */
	f->hud[3] = p->now < p->notice_until ? p->notice : NULL;
	if (p->o.hud == BOARD_HUD_VISITOR) {
		visitor_hud(p, f);
		return;
	}
	if (p->o.hud == BOARD_HUD_OFF)
		return;
	/* the engineer sees what the board file got wrong while no notice shows */
	if (!f->hud[3] && p->kiosk.board_note[0])
		f->hud[3] = p->kiosk.board_note;
	if (!f->hud[3])
		f->hud[3] = keys_legend(p, 1);
	const char *where = p->gpu[0] ? "GPU" : "CPU";
	if (p->panel_count > 1)
		snprintf(lines[0], 128, "COMPARE LBS | DQBS  %s  %s", where, render_view_name(p->o.view));
	else
		snprintf(lines[0], 128, "%s  %s  %s", skin_algo_name(p->algo[0]), where, render_view_name(p->o.view));
	unsigned long rebuilt = p->o.image_count ? show_rebuilt(&p->show) : 0;
	int at = snprintf(lines[1], 128, "%s  FRAME %ld  %.2f S", p->clip, shown_number(p), shown_time(p));
	if (rebuilt)
		snprintf(lines[1] + at, 128 - (size_t)at, "  REBUILT %lu", rebuilt);
	/* no rate before the first second is measured; on a screen CLOCK,
	 * how far the pose runs from the wall clock; headless the show's
	 * time and the image's number, as its PNG is named */
	char rate[32] = "- FPS", clock[64] = "";
	if (fps > 0)
		snprintf(rate, sizeof rate, "%.1f FPS", fps);
	if (p->headless)
		snprintf(clock, sizeof clock, "  SHOW %.2f S  IMAGE %ld", (double)p->now * 1e-9, p->shown + 1);
	else if (fps > 0)
		snprintf(clock, sizeof clock, "  CLOCK %+.3f S", p->drift);
	snprintf(lines[2], 128, "%s%s%s%s", rate, clock, p->kiosk.ps.playing ? "" : "  PAUSED",
		 p->o.sync != 1 ? "" : p->sync_unsynced ? "  SYNC: OWN CLOCK" : "  SYNC");
	f->hud[0] = lines[0];
	f->hud[1] = lines[1];
	f->hud[2] = p->o.hud_fps ? lines[2] : NULL;
}
