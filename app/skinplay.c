/* skinplay: the device app. Streams an AMC clip against its ASF skeleton
 * and poses it every frame; rendering arrives with the renderer. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "fk.h"
#include "cli_common.h"

typedef struct play_opts {
	const char *asf, *amc;
	long frames;        /* frames to play, -1: the whole clip once */
	double fps;         /* clip rate; CMU and HDM05 capture at 120 Hz */
	int realtime;       /* pace to fps instead of running flat out */
} play_opts;

static int usage(void)
{
	fprintf(stderr, "usage: skinplay --asf SKELETON.asf --amc MOTION.amc [--frames N] [--fps F] [--realtime]\n");
	return 1;
}

static int parse_args(int argc, char **argv, play_opts *o)
{
	*o = (play_opts){ NULL, NULL, -1, 120.0, 0 };
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];
		const char *v = i + 1 < argc ? argv[i + 1] : NULL;
		if (strcmp(a, "--asf") == 0 && v)
			o->asf = argv[++i];
		else if (strcmp(a, "--amc") == 0 && v)
			o->amc = argv[++i];
		else if (strcmp(a, "--frames") == 0) {
			if (tool_parse_long("--frames", v, &o->frames) < 0)
				return -1;
			i++;
		} else if (strcmp(a, "--fps") == 0 && v) {
			o->fps = atof(argv[++i]);
			if (!(o->fps > 0.0))
				return usage(), -1;
		} else if (strcmp(a, "--realtime") == 0)
			o->realtime = 1;
		else
			return fprintf(stderr, "skinplay: unknown option '%s'\n", a), usage(), -1;
	}
	if (!o->asf || !o->amc)
		return usage(), -1;
	return 0;
}

int main(int argc, char **argv)
{
	static skel s;
	static tool_motion m;
	static amc_frame f;
	static skel_pose pose;
	play_opts o;

	if (parse_args(argc, argv, &o) < 0 || tool_load_skel(o.asf, &s) < 0)
		return 1;
	if (tool_motion_open(&m, o.amc, &s) < 0)
		return 1;
	uint64_t start = clock_now_ns(), last_log = start, decode_ns = 0, pose_ns = 0;
	long played = 0, since_log = 0;
	int r = 0;
	while (o.frames < 0 || played < o.frames) {
		uint64_t t0 = clock_now_ns();
		r = tool_motion_next(&m, &f);
		if (r <= 0)
			break;
		uint64_t t1 = clock_now_ns();
		fk_pose(&s, f.value, &pose);
		uint64_t t2 = clock_now_ns();
		decode_ns += t1 - t0;
		pose_ns += t2 - t1;
		played++;
		since_log++;
		if (o.realtime)
			clock_sleep_until_ns(start + (uint64_t)((double)played * 1e9 / o.fps));
		if (t2 - last_log >= 1000000000u) {
			double secs = (double)(t2 - last_log) * 1e-9;
			fprintf(stderr, "frame %ld: %.1f fps, decode %.3f ms, pose %.3f ms\n", f.number,
				since_log / secs, decode_ns * 1e-6 / since_log, pose_ns * 1e-6 / since_log);
			last_log = t2;
			since_log = 0;
			decode_ns = pose_ns = 0;
		}
	}
	tool_motion_close(&m);
	if (r < 0)
		return 1;
	double total = (double)(clock_now_ns() - start) * 1e-9;
	fprintf(stderr, "played %ld frames of %s in %.3f s; root at (%.3f, %.3f, %.3f)\n", played, o.amc,
		total, pose.tip[0].x, pose.tip[0].y, pose.tip[0].z);
	return 0;
}
