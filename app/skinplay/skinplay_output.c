/* What --output writes, every K-th frame shown: DIR/frame_NNNNNN.png, or
 * one video file (F.mp4: H.264, F.webm: VP9; skinplay_opts.c tells them
 * apart) whose frame i is display frame i x K, at the virtual display's
 * rate over K, so that the video lasts as long as the frames it shows took
 * on the show's clock: the clip's duration. A video is written headless
 * only, where frame n shows n / --display-rate s exactly; it becomes F
 * only once whole (video_writer.h), so a run that fails leaves nothing. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli_inputs.h"
#include "cli_quiet.h"
#include "png_writer.h"
#include "skinplay.h"

#ifdef SKP_VIDEO
/* The video's frame rate, display_rate / every, as a fraction: whole and
 * thousandths of a hertz exactly (--display-rate 29.97: 2997/100). */
static void video_rate(const play_opts *o, int *num, int *den)
{
	long n = lround(o->display_rate * 1000.0), d = 1000 * o->every;
	long a = n, b = d;
	while (b) {
		long t = a % b;
		a = b;
		b = t;
	}
	*num = (int)(n / a);
	*den = (int)(d / a);
}

static int open_video(skinplay *p)
{
	skp_error err;
	int num, den;
	if (!p->headless) {
		fprintf(stderr, "skinplay: %s: a video is written headless (--platform surfaceless or osmesa), where frame "
			"n shows the motion at n/--display-rate s; on %s write PNG frames with -o DIR\n", p->o.out_dir,
			p->disp->name);
		return -1;
	}
	if (cli_output_check(p->o.out_dir) < 0 || cli_output_file_check(p->o.out_dir, 0) < 0)
		return -1;
	video_rate(&p->o, &num, &den);
	p->video = video_writer_open(p->o.out_dir, p->info.width, p->info.height, num, den, &err);
	if (!p->video) {
		fprintf(stderr, "skinplay: %s\n", err.msg);
		return -1;
	}
	fprintf(cli_note(), "skinplay: %s: %s (%s), %dx%d, %g frames a second%s\n", p->o.out_dir,
		video_writer_codec(p->video), video_writer_encoder(p->video), p->info.width, p->info.height,
		(double)num / den, p->o.every > 1 ? " (every --every frame of the display's)" : "");
	return 0;
}

static int add_video(skinplay *p)
{
	skp_error err;
	if (video_writer_add_rgba(p->video, p->rgba, 1, &err) != SKP_OK) {
		fprintf(stderr, "skinplay: %s\n", err.msg);
		return -1;
	}
	return 0;
}

#endif

int output_close(skinplay *p, int keep)
{
#ifdef SKP_VIDEO
	skp_error err;
	video_writer *v = p->video;
	p->video = NULL;
	if (!v)
		return 0;
	if (!keep) {
		video_writer_abort(v);
		return 0;
	}
	long n = video_writer_frames(v);
	int num, den;
	video_rate(&p->o, &num, &den);
	if (video_writer_close(v, &err) != SKP_OK) {
		fprintf(stderr, "skinplay: %s\n", err.msg);
		return -1;
	}
	fprintf(cli_note(), "skinplay: %s: %ld frames, %.3f s\n", p->o.out_dir, n, (double)n * den / num);
#else
	(void)p, (void)keep; /* no video in this build: nothing is open */
#endif
	return 0;
}

int output_open(skinplay *p)
{
	if (!p->o.out_dir)
		return 0;
	if (p->info.width > SKP_DISPLAY_MAX_W || p->info.height > SKP_DISPLAY_MAX_H) {
		fprintf(stderr, "skinplay: --out reads frames back into %dx%d at most (board limit); %s shows %dx%d\n",
			SKP_DISPLAY_MAX_W, SKP_DISPLAY_MAX_H, p->info.name, p->info.width, p->info.height);
		return -1;
	}
#ifdef SKP_VIDEO
	if (p->o.video)
		return open_video(p);
#endif
	if (mkdir(p->o.out_dir, 0755) != 0 && errno != EEXIST) {
		fprintf(stderr, "skinplay: %s: %s\n", p->o.out_dir, strerror(errno));
		return -1;
	}
	return 0;
}

static int write_png(skinplay *p, long n)
{
	char path[1024];
	skp_error err;
	snprintf(path, sizeof path, "%s/frame_%06ld.png", p->o.out_dir, n);
	if (cli_output_check(path) < 0)
		return -1;
	if (png_write_rgba(path, p->rgba, p->info.width, p->info.height, PNG_WRITE_BOTTOM_UP | PNG_WRITE_FAST, &err) != 0) {
		fprintf(stderr, "skinplay: %s: %s\n", path, err.msg);
		return -1;
	}
	return 0;
}

int output_frame(skinplay *p, long n)
{
	render_read_rgba(&p->r, p->rgba);
#ifdef SKP_VIDEO
	if (p->o.video && add_video(p) < 0)
		return -1;
#endif
	if (!p->o.video && write_png(p, n) < 0)
		return -1;
	if (p->o.sheet_path)
		sheet_add(&p->contact, p->rgba, p->info.width, p->info.height);
	return 0;
}
