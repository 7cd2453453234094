/* The playback engine: clock in, pose out. Each call to play_update says
 * what time it is and gets the pose at clip time (now - clip start) x
 * speed, interpolated between the captured frames around it (play_cursor)
 * whatever the render rate. At the end of a pass it loops (or holds the
 * last frame); a loop, a restart and a clip change crossfade from the pose
 * on screen over blend_ms in local rotation space. Root motion is taken
 * out (in place: the character stays where it started) or kept, carried
 * across loops so a walk goes on instead of jumping back (travel).
 *
 * No allocation, no I/O: frames come through play_source callbacks and
 * time is passed in, so tests drive it with a fake clock and a
 * microcontroller builds it as it is. */
#ifndef PLAY_ENGINE_H
#define PLAY_ENGINE_H

#include "fk.h"
#include "play_clock.h"
#include "play_cursor.h"

typedef enum play_root_mode { PLAY_ROOT_IN_PLACE, PLAY_ROOT_TRAVEL } play_root_mode;

#define PLAY_SPEED_MIN 0.1
#define PLAY_SPEED_MAX 4.0
#define PLAY_BLEND_MS_MAX 10000
#define PLAY_BLEND_MS_DEFAULT 300

typedef struct play_config {
	double speed;            /* clip seconds a second, PLAY_SPEED_MIN..MAX */
	uint32_t blend_ms;       /* crossfade at a loop, restart or clip change; 0: cut */
	int root;                /* play_root_mode */
	int loop;                /* 1: loop at the end; 0: hold the last frame */
} play_config;

/* speed 1, blend 300 ms, in place, looping */
void play_config_defaults(play_config *c);

typedef struct play_engine {
	const skel *s;
	play_config cfg;
	play_clock clock;
	play_cursor cur;
	int started;             /* a clip is open */
	int shown;               /* a pose has been computed (fades start from it) */
	uint64_t clip_start;     /* active time of clip time 0 of this pass, ns */
	long pass;               /* loops completed in this clip */
	/* the crossfade */
	int fading;
	uint64_t fade_start;     /* active time it began */
	skel_local from;         /* the pose shown when it began */
	/* root motion: horizontal = x and z (y is up) */
	int have_origin;
	vec3 origin;             /* in place: where the root stays */
	vec3 first_root;         /* the clip's first frame's root */
	vec3 travel;             /* travel: added to this pass's root */
	/* what was computed last */
	skel_local sampled;      /* the clip's pose at clip_time, root placed */
	skel_local local;        /* ... after the crossfade: what is shown */
	skel_pose pose;
	double clip_time;        /* seconds into the clip */
	long number;             /* the captured frame at or before clip_time (its number) */
} play_engine;

void play_init(play_engine *e, const skel *s, const play_config *cfg);

/* Starts src from its first frame at time now; when a pose was shown
 * before (a loop of the shell's, a restart, the next clip), it fades from
 * that pose. SKP_OK, or the source's error (the engine keeps the old
 * pose). */
skp_status play_start(play_engine *e, const play_source *src, uint64_t now, skp_error *err);

/* The pose at time now into e->pose (and e->local, e->clip_time,
 * e->number). On a source error the last pose stays and the error is
 * returned; playing on is up to the caller. */
skp_status play_update(play_engine *e, uint64_t now, skp_error *err);

/* The clip's pose at clip_time seconds (clamped to the clip), no clock,
 * no crossfade: skintool fk --time. Into e->pose as play_update. */
skp_status play_sample_at(play_engine *e, double clip_time, skp_error *err);

/* Moves the clip's clock so that time now is clip_time seconds into the
 * clip (skinplay --start); the next play_update shows it. */
void play_set_clip_time(play_engine *e, double clip_time, uint64_t now);

/* Moves the clip's clock to clip_time at time now as play_set_clip_time
 * does, crossfading from the pose shown: a device that was off the show's
 * clock (a late start, a pause, a stall) joins it without a jump. */
void play_rejoin(play_engine *e, double clip_time, uint64_t now);

/* Pause (1) or resume (0) at time now: clip and fade stand still. */
void play_pause(play_engine *e, int paused, uint64_t now);

/* The clip's length in seconds: its frames over its rate. */
double play_duration(const play_engine *e);

/* Display frames a pass takes at hz frames a second and the engine's
 * speed: the display frames whose time is within the clip (02_01's 343
 * frames at 120 Hz: 172 at 60 Hz, 344 at speed 0.5). */
long play_pass_frames(const play_engine *e, double hz);
/* The same for a pass that starts from clip time `from` seconds. */
long play_pass_frames_from(const play_engine *e, double hz, double from);

#endif
