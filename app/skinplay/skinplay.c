/* skinplay: the device app. Streams an AMC clip, poses the skeleton, skins
 * the body with the chosen algorithm (CPU kernels or the vertex shader) and
 * renders it on a display or headless, optionally writing PNG frames. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "board_config.h"
#include "cli_inputs.h"
#include "cli_quiet.h"
#include "cli_version.h"
#include "clock.h"
#include "mem_report.h"
#include "setup_bind.h"
#include "signals.h"
#include "skinplay.h"

/* Which kernels each panel runs, and where (GPU when asked and it fits). */
static void choose_paths(skinplay *p)
{
	static const skin_algo one[3] = { SKIN_LBS, SKIN_DQBS, SKIN_DQBS_FIXED };
	p->panel_count = p->o.algo == SKIN_COMPARE ? 2 : 1;
	p->algo[0] = p->o.algo == SKIN_COMPARE ? SKIN_LBS : one[p->o.algo];
	p->algo[1] = SKIN_DQBS;
	for (int i = 0; i < p->panel_count; i++) {
		p->gpu[i] = p->o.gpu && p->render_ready && render_gpu_fits(&p->r, p->algo[i]);
		if (p->o.gpu && !p->gpu[i])
			fprintf(stderr, "skin: %s on the CPU: %s\n", skin_algo_name(p->algo[i]),
				p->algo[i] == SKIN_DQBS_FIXED
					? "the fixed-point kernel has no shader"
					: "the skeleton's bone uniforms exceed GLES 2.0's 128 vertex vectors");
	}
}

/* Skinning threads when the board has the cores and the mesh the size for
 * them to pay (the board's [skin] split_verts; auto: the first frames try
 * them against one thread); otherwise, or when they cannot start, the
 * frame loop's thread skins alone. */
static void start_workers(skinplay *p)
{
	int n = p->o.threads > 0 ? p->o.threads : workers_cpu_count();
	int split = p->kiosk.board.split_verts;
	if (n < 2 || (split != BOARD_SPLIT_AUTO && p->skin.soa.count < split))
		return;
	p->pool = workers_start(n);
	if (!p->pool) {
		fprintf(stderr, "skinplay: cannot start %d skinning threads: skinning on one\n", n);
		return;
	}
	if (split == BOARD_SPLIT_AUTO)
		runtime_skin_measure_workers(&p->skin, p->pool);
	else
		runtime_skin_use_workers(&p->skin, p->pool);
}

/* Once, when the measurement of start_workers has chosen: what it chose. */
static void log_measured_threads(skinplay *p)
{
	double one, pool;
	if (p->threads_logged || runtime_skin_measured(&p->skin, &one, &pool) < 0)
		return;
	p->threads_logged = 1;
	int kept = runtime_skin_threads(&p->skin) > 1;
	fprintf(cli_note(), "skinplay: a kernel run took %.3f ms on %d threads, %.3f on one: skinning on %s\n", pool,
		workers_count(p->pool), one, kept ? "all of them" : "one");
}

/* The body's texture to the GPU as --texture says, and said: how big,
 * how it went (ETC1 as packed, or decoded to RGB565), or why not. */
static int set_texture(skinplay *p)
{
	skp_error err;
	const tex_image *t = &p->body.texture;
	if (p->body.texture_skipped)
		fprintf(stderr, "skinplay: the image's texture is larger than this board keeps (%d pixels a side): "
			"the body plays in its colours\n", SKP_MAX_TEXTURE_SIDE);
	if (!p->body.mesh.textured || p->o.texture == 2)
		return 0;
	if (render_set_texture(&p->r, &p->body.mesh, t, p->o.texture == 0, &err) != SKP_OK) {
		fprintf(stderr, "skinplay: renderer: %s\n", err.msg);
		return -1;
	}
	fprintf(cli_note(), "texture: %dx%d, %d levels, %s%s\n", t->width, t->height, t->chain.levels,
		p->r.tex_path, p->r.tex_path[0] == 'E' ? " (the GPU samples the blocks as packed)"
						       : " (decoded at start-up)");
	return 0;
}

/* --platform none: nothing drawn and no GL; the clock, the show and its
 * logs run as headless (a soak of days of frames in minutes). */
static int no_display(const skinplay *p)
{
	return p->o.platform && !strcmp(p->o.platform, "none");
}

static int setup(skinplay *p)
{
	if (p->o.image_count && show_open(&p->show, p->o.image, p->o.image_count, &p->body) < 0) {
		p->no_show = 1; /* a kiosk waits for one (skinplay_wait.c) */
		return -1;
	}
	show_watch_init(&p->watch, p->o.image, p->o.image_count);
	if (!p->o.image_count && setup_bind_load(&p->o.bind, p->o.asf, p->o.mesh, &p->body) < 0)
		return -1;
	if (runtime_skin_init(&p->skin, &p->body.skel, &p->body.pose, &p->body.mesh, &p->body.weights,
			   p->o.image_count ? show_path(&p->show) : p->o.mesh ? p->o.mesh : "generated body") < 0)
		return -1;
	start_workers(p);
	if (p->o.streams == BOARD_STREAMS_COMPACT)
		runtime_skin_use_compact(&p->skin);
	float floor_y = clips_first(p);
	if (isnan(floor_y))
		return -1;
	if (no_display(p)) {
		p->headless = 1;
		choose_paths(p);
		if (p->o.out_dir)
			fprintf(stderr, "skinplay: --platform none draws nothing: no --output\n");
		return p->o.out_dir ? -1 : 0;
	}
	if (open_display(p) < 0)
		return -1;
	skp_error err;
	const mesh *m = &p->body.mesh;
	if (render_init(&p->r, &p->gl, p->info.width, p->info.height, p->info.rotation, &p->body.skel,
			&p->skin.soa, (const uint32_t (*)[3])m->tri, m->tri_count, floor_y, &err) != SKP_OK) {
		fprintf(stderr, "skinplay: renderer: %s\n", err.msg);
		return -1;
	}
	render_set_colours(&p->r, m->coloured ? (const uint8_t (*)[3])m->colour : NULL);
	if (set_texture(p) < 0)
		return -1;
	render_set_yaw(&p->r, p->yaw, 1);
	render_set_view(&p->r, &p->o.view_cam);
	p->view_home = p->o.view_cam;
	render_set_wall(&p->r, &p->o.wall);
	p->render_ready = 1;
	closeup_setup(p);
	clips_frame(p, 1);
	choose_paths(p);
	sheet_init(&p->contact, p->info.width, p->info.height);
	return output_open(p);
}

/* " on 2 threads" when the CPU kernels share the mesh, ", compact
 * streams" when LBS and DQBS read them, else "" */
static const char *threads_note(const skinplay *p)
{
	static char note[48];
	int n = runtime_skin_threads(&p->skin), at = 0;
	note[0] = '\0';
	if (n > 1)
		at = snprintf(note, sizeof note, " on %d threads", n);
	if (p->skin.use_compact)
		snprintf(note + at, sizeof note - (size_t)at, ", compact streams");
	return note;
}

static void skin_panels(skinplay *p, render_frame *f)
{
	uint64_t t1 = clock_now_ns();
	runtime_skin_pose(&p->skin, &p->skin.pose);
	uint64_t t2 = clock_now_ns();
	stage_add(&p->stages, STAGE_BONES, t2 - t1);
	f->panel_count = p->panel_count;
	for (int i = 0; i < p->panel_count; i++) {
		f->panel[i].algo = p->algo[i];
		f->panel[i].label = p->panel_count > 1 ? (i ? "DQBS" : "LBS") : NULL;
		int compact = runtime_skin_compact(&p->skin, p->algo[i]);
		f->panel[i].pos = p->gpu[i] ? NULL : p->pos[i];
		f->panel[i].nrm = p->gpu[i] || compact ? NULL : p->nrm[i];
		f->panel[i].nrm16 = p->gpu[i] || !compact ? NULL : p->nrm16[i];
		if (!p->gpu[i]) {
			uint64_t t3 = clock_now_ns();
			if (compact)
				runtime_skin_run16(&p->skin, p->algo[i], p->pos[i], p->nrm16[i]);
			else
				runtime_skin_run(&p->skin, p->algo[i], p->pos[i], p->nrm[i]);
			stage_add(&p->stages, STAGE_SKIN, clock_now_ns() - t3);
		}
	}
	log_measured_threads(p);
	f->pose = &p->skin.pose;
	/* the wall's camera stays where the clip starts */
	f->anchor = p->o.root == BOARD_ROOT_IN_PLACE ? p->eng.origin : vec3_add(p->eng.first_root, p->eng.travel);
	f->bones = &p->skin.bones;
	uint64_t t4 = clock_now_ns();
	closeup_frame(p, f);
	stage_add(&p->stages, STAGE_SKIN, clock_now_ns() - t4);
}

/* --pose-digest: FNV-1a over the joints of every pose shown. */
static void pose_digest_add(skinplay *p)
{
	const uint8_t *b = (const uint8_t *)p->skin.pose.tip;
	size_t n = sizeof p->skin.pose.tip[0] * (size_t)p->body.skel.count;
	if (!p->digest)
		p->digest = 1469598103934665603ull;
	for (size_t i = 0; i < n; i++)
		p->digest = (p->digest ^ b[i]) * 1099511628211ull;
}

/* The status line: every second of the first minute (start-up, and any
 * short run whole), then once an hour, so that months on a kiosk do not
 * fill the journal; the last one always. */
#define STATUS_EVERY_SECOND_NS 60000000000ull

static int status_due(skinplay *p, uint64_t now, int last)
{
	uint64_t since = now - p->stages.start_ns;
	if (!last && since >= STATUS_EVERY_SECOND_NS && now - p->status_at < SKP_RATELIMIT_HOUR)
		return 0;
	if (!last && !p->status_hourly && since >= STATUS_EVERY_SECOND_NS) {
		fprintf(cli_note(), "skinplay: status lines from now on once an hour\n");
		p->status_hourly = 1;
	}
	p->status_at = now;
	return 1;
}

/* What the summary line says was played: the clip, or the clips a show
 * went through in turn (counting a clip again when the show looped). */
static const char *played_what(const skinplay *p, char *buf, size_t cap)
{
	if (p->o.amc)
		return p->o.amc;
	if (p->clips_started < 2)
		return p->clip;
	snprintf(buf, cap, "%d clips in turn (%s first, %s last)", p->clips_started, p->first_clip, p->clip);
	return buf;
}

/* The stages in the status and summary lines: decode (and pose), skin
 * (bone transforms and kernels), upload, draw. */
#define TIMES_FMT "decode %.2f ms, skin %.2f ms, upload %.2f ms, draw %.2f ms"
#define TIMES(t, mean) mean(t, STAGE_POSE, STAGE_POSE), mean(t, STAGE_BONES, STAGE_SKIN), \
	mean(t, STAGE_UPLOAD, STAGE_UPLOAD), mean(t, STAGE_DRAW, STAGE_DRAW)

/* The last second's status line (when due), and a new second from now. */
static void log_second(skinplay *p, uint64_t now, int last)
{
	const stage_times *t = &p->stages;
	double fps = stage_window_fps(t, now);
	if (status_due(p, now, last)) {
		fprintf(cli_note(), "frame %ld: clip %.3f s, %.1f fps, " TIMES_FMT, shown_number(p), shown_time(p), fps,
			TIMES(t, stage_window_ms));
		/* a run of known length (headless, --frames: make soak): how far, how long left */
		if (p->budget > 0 && fps > 0)
			fprintf(cli_note(), "; %ld of %ld shown (%.1f%%), %.0f s left", p->shown, p->budget,
				100.0 * (double)p->shown / (double)p->budget, (double)(p->budget - p->shown) / fps);
		fputc('\n', cli_note());
	}
	stage_window_reset(&p->stages, now);
}

/* The frame skinned, then drawn and presented; or, when it is not to be
 * seen (paint 0), only its cameras moved. */
static int draw_one(skinplay *p, double fps, render_frame *f, int paint)
{
	char lines[3][128];
	skp_error err;
	skin_panels(p, f);
	if (!paint) {
		render_advance(&p->r, f);
		return 0;
	}
	uint64_t t1 = clock_now_ns();
	render_upload(&p->r, f);
	uint64_t t2 = clock_now_ns();
	hud_text(p, f, fps, lines);
	render_draw(&p->r, f);
	memset(f->hud, 0, sizeof f->hud); /* the lines live on this stack frame */
	p->gl.Finish();
	uint64_t t3 = clock_now_ns();
	stage_add(&p->stages, STAGE_UPLOAD, t2 - t1);
	stage_add(&p->stages, STAGE_DRAW, t3 - t2);
	if (p->disp->present(&err) != 0) {
		fprintf(stderr, "skinplay: %s: %s\n", p->disp->name, err.msg);
		return -1;
	}
	stage_add(&p->stages, STAGE_SWAP, clock_now_ns() - t3);
	return 0;
}

/* The buttons' state machine (kiosk_shell.h) drives what is shown. */
static void apply_input(skinplay *p, render_frame *f, unsigned act)
{
	const controls_state *s = &p->kiosk.ps;
	act = sync_button(p, act);
	p->o.algo = (skin_algo)s->algo;
	p->o.view = f->view = (render_view)s->view;
	p->o.gpu = s->gpu;
	if (act & (KIOSK_ACT_ALGO | KIOSK_ACT_GPU))
		choose_paths(p);
	if (act & KIOSK_ACT_PLAY) {
		/* headless, at the scripted time itself (script time is display
		 * time): a run pauses on the same pose however it is rendered */
		uint64_t at = p->kiosk.play_ms * 1000000u;
		play_pause(&p->eng, !s->playing, p->headless && at < p->now ? at : p->now);
	}
	if (act & (KIOSK_ACT_RESTART | KIOSK_ACT_CLIP))
		clips_restart(p, act & KIOSK_ACT_CLIP ? s->clip : -1);
	keys_time(p, act);
	camera_key(p, act);
}

/* The next key typed in the window, else on the terminal (--input
 * keyboard); 0 none. */
static int next_key(const skinplay *p)
{
	int key = p->disp && p->disp->key ? p->disp->key() : 0;
	const input_backend *in = p->kiosk.in_started ? p->kiosk.in : NULL;
	return key ? key : in && in->key ? in->key() : 0;
}

/* Headless with --every: the frames drawn are the ones written, and the
 * upload and draw times are theirs. */
static const char *drawn_note(const skinplay *p, long shown)
{
	static char note[80];
	long drawn = p->stages.ran[STAGE_DRAW];
	if (!p->disp || drawn >= shown)
		return "";
	snprintf(note, sizeof note, "; %ld drawn, the ones written", drawn);
	return note;
}

static int play(skinplay *p)
{
	stage_start(&p->stages, clock_now_ns());
	render_frame f;
	memset(&f, 0, sizeof f);
	f.view = p->o.view;
	f.transparent = p->o.transparent;
	double fps = 0;
	long shown = 0;
	int quit = 0, r = 1;
	/* headless: the clip once, frames held by a pause included, so a
	 * scripted pause cannot keep a batch run going for ever */
	sync_begin(p);
	long budget = p->o.frames >= 0 ? p->o.frames : p->headless ? clips_pass_frames(p) : -1;
	p->budget = budget;
	p->eng.cfg.loop = budget < 0 || p->o.frames >= 0 || clips_show_loops(p);
	uint64_t prev = 0;
	while (!quit && (budget < 0 || shown < budget)) {
		unsigned act = kiosk_shell_frame(&p->kiosk, shown) | slots_news(p);
		if (act & (KIOSK_ACT_QUIT | KIOSK_ACT_RELOAD)) {
			p->reload = !(act & KIOSK_ACT_QUIT);
			break;
		}
		p->now = skinplay_frame_time(p, shown);
		if (act)
			apply_input(p, &f, act);
		sync_frame(p, shown);
		uint64_t t0 = clock_now_ns();
		if (clips_pose(p) < 0) {
			r = -1;
			break;
		}
		stage_add(&p->stages, STAGE_POSE, clock_now_ns() - t0);
		f.dt = (float)((double)(p->now - prev) * 1e-9);
		prev = p->now;
		if (p->o.pose_digest)
			pose_digest_add(p);
		/* headless with --output, a frame not written is not drawn */
		int write = p->o.out_dir && shown % p->o.every == 0, paint = write || !p->headless || !p->o.out_dir;
		if (p->disp && draw_one(p, fps, &f, paint) < 0)
			return -1;
		p->drift = ((double)p->now - (double)(clock_now_ns() - p->wall0)) * 1e-9;
		p->shown = ++shown;
		uint64_t t_png = clock_now_ns();
		if (write && output_frame(p, shown) < 0)
			return -1;
		if (paint)
			stage_add(&p->stages, STAGE_SWAP, clock_now_ns() - t_png);
		stage_frame_done(&p->stages, shown_number(p));
		if (p->disp && p->disp->handle_events)
			p->disp->handle_events(&quit);
		for (int key; (key = next_key(p)) != 0;) {
			unsigned keyed = kiosk_shell_key(&p->kiosk, key, shown);
			quit |= (keyed & KIOSK_ACT_QUIT) != 0;
			apply_input(p, &f, keyed);
		}
		camera_pointer(p);
		uint64_t now = clock_now_ns();
		if (now - p->stages.window_ns >= 1000000000u) {
			fps = stage_window_fps(&p->stages, now);
			log_second(p, now, 0);
		}
	}
	if (r < 0)
		return -1;
	log_second(p, clock_now_ns(), 1);
	double secs = (double)(clock_now_ns() - p->stages.start_ns) * 1e-9;
	char what[192];
	fprintf(cli_note(), "played %ld frames of %s in %.2f s: %.1f fps; per frame " TIMES_FMT " (%s, %dx%d, %s skinning%s%s)\n",
		shown, played_what(p, what, sizeof what), secs, shown / secs, TIMES(&p->stages, stage_run_ms),
		p->disp ? p->disp->name : "none", p->info.width, p->info.height, p->gpu[0] ? "GPU" : "CPU",
		threads_note(p), drawn_note(p, shown));
	if (p->o.pose_digest)
		fprintf(stderr, "poses: %ld shown, digest %016llx\n", shown, (unsigned long long)p->digest);
	if (p->o.report_timing)
		stage_report(&p->stages);
	if (output_close(p, 1) < 0)
		return -1;
	if (p->o.sheet_path && sheet_write(&p->contact, p->o.sheet_path) < 0)
		return -1;
	return 0;
}

int main(int argc, char **argv)
{
	static skinplay p;
	if (cli_wants_version(argc, argv))
		return cli_print_version("skinplay"), 0;
	int rc = play_parse(&p.o, argc, argv);
	if (rc != 0)
		return rc < 0 ? 1 : 0;
	if (p.o.print_platform) {
		puts(display_auto()->name);
		return 0;
	}
	if (skinplay_board_setup(&p.kiosk, &p.o, argc, argv) < 0)
		return 1;
	if (setup(&p) != 0)
		rc = p.no_show ? wait_for_show(&p) : 1;
	else
		rc = skinplay_kiosk_start(&p.kiosk, &p.o, p.headless, p.o.image_count ? show_clip_count(&p.show) : 1) == 0 &&
		     play(&p) == 0 ? 0 : 1;
	/* headless, the show had nothing to play: the held frame was rendered,
	 * the status says the show is damaged (a kiosk keeps holding instead) */
	if (rc == 0 && p.hold && !p.reload)
		rc = 2;
	if (p.reload && rc == 0)
		signals_hold();
	output_close(&p, 0); /* a video a failed run began: dropped */
	kiosk_shell_shutdown(&p.kiosk);
	clip_file_close(&p.text);
	show_close(&p.show);
	if (p.o.report_memory)
		mem_report(stderr);
	if (p.disp) {
		render_shutdown(&p.r);
		p.disp->shutdown();
	}
	if (p.pool)
		workers_stop(p.pool);
	if (p.reload && rc == 0) {
		/* a new show: start over as a fresh process (same pid for systemd) */
		execv("/proc/self/exe", argv);
		fprintf(stderr, "skinplay: re-executing for SIGHUP: %s\n", strerror(errno));
		return 1;
	}
	return rc;
}
