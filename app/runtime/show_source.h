/* The show source for both programs: animation played from packed flash
 * images (app/image/image_format.h) instead of ASF/AMC text.
 *
 * Given one or more image slots (skinplay --image PATH, repeatable), it
 * plays the newest valid one: slots are tried by decreasing header
 * sequence; one that fails acceptance (show_accept.c: header, skeleton,
 * bound body, directory; every check made before anything plays) is
 * refused with a message, and with more than one slot a slot with a block
 * beyond repair yields to an intact older one, so an update cut short by
 * power loss never bricks the display. Blocks that fail their check are
 * rebuilt from parity or the copies, logged once each. A clip whose frames or
 * quantisation cannot be read is skipped, not the image. It fills the
 * bound body as setup_bind_load does and hands out amc_frames: a frame lost
 * in a block beyond repair is replaced by the last good frame, each such
 * block logged once as "image: block N bad (CRC mismatch), holding frame
 * F", and each pass over a clip that lost or rebuilt anything ends with one
 * summary line. */
#ifndef SHOW_SOURCE_H
#define SHOW_SOURCE_H

#include "cli_bind_args.h"
#include "image_survey.h"
#include "play_image_source.h"
#include "runtime_body.h"
#include "skp_ratelimit.h"
#include "storage_file.h"

#define SHOW_MAX_SLOTS   4
#define SHOW_MAX_LOGGED 64   /* bad blocks remembered for log-once */

/* One image file opened (header and directory checked). */
typedef struct show_image {
	const char *path;
	storage_file sf;
	skp_image im;
	long logged[SHOW_MAX_LOGGED];   /* blocks logged (rebuilt or lost): once each */
	int logged_count;
	unsigned long unlisted;         /* damaged blocks past the table: counted */
} show_image;

/* Acceptance (show_accept.c, app/image/image_accept.h): the skeleton and
 * the bound body into body, loaded and judged; each clip of skeleton s:
 * its quantisation, its meaning and its frame count. The same for any
 * opened image (pack judges what it wrote). Return 0, or -1 with err
 * filled. */
int image_accept_body(skp_image *im, bound_body *body, skp_error *err);
int image_accept_clip(skp_image *im, const skel *s, int clip, skp_error *err);
int show_accept_body(show_image *img, bound_body *body, skp_error *err);
int show_accept_clip(show_image *img, const skel *s, int clip, skp_error *err);

/* 1 the first time block is named for img (log it), else 0; bounded. */
int show_log_once(show_image *img, long block);

/* skp_image's on_rebuild for a show_image: one log line per block. */
void show_log_rebuild(void *ctx, uint32_t block);

/* Opens an image file as storage with the image's own block size: the
 * header's, or SKP_IMAGE_DEFAULT_BLOCK when block 0 does not say (then the
 * reader reports what is wrong with it). Returns 0 or -errno. */
int show_storage_open(storage_file *sf, const char *path);

/* Returns 0, or -1 with the reason in err (nothing printed). */
int show_image_open(show_image *s, const char *path, skp_error *err);
void show_image_close(show_image *s);

/* Checks every block of an opened image (CRC, id, index, kind; parity
 * against its group; the copies against what they copy) and the digest;
 * calls bad (when non-NULL) for each bad block. */
void show_image_verify(show_image *s, void (*bad)(void *ctx, uint32_t block, const skp_block_report *r),
		       void *ctx, skp_image_verdict *v);

/* Says on stderr what an opened image lacks but plays without: the blocks
 * missing at its end (header copy, directory copy, parity). */
void show_image_warn(const show_image *s);

typedef struct show_source {
	show_image slot[SHOW_MAX_SLOTS];
	int slot_count;
	int active;                 /* slot playing */
	int clip;                   /* clip playing, -1 none */
	uint8_t playable[SKP_IMAGE_MAX_CLIPS];  /* accepted clips of the active slot */
	play_image_source clip_src; /* the clip playing, as the engine's source */
	unsigned long pass_rebuilt; /* im.rebuilt when the pass began */
	uint64_t now;               /* skinplay's clock (ns), set each frame: log lines */
	skp_ratelimit pass_said;    /* a pass's summary line: the first, then hourly */
	bound_body *body;           /* filled by show_open (the slot choice) */
} show_source;

/* Opens the newest valid slot of paths[0..n-1] (app/play's slot policy)
 * and fills body (skeleton, bind pose, mesh, weights). Returns 0, or -1
 * after reporting on stderr. */
int show_open(show_source *s, const char *const *paths, int n, bound_body *body);

int show_clip_count(const show_source *s);

/* The first playable clip at or after from (wrapping round), -1 if none. */
int show_next_playable(const show_source *s, int from);

/* Blocks rebuilt from parity since the show was opened (the HUD's count). */
unsigned long show_rebuilt(const show_source *s);
const skp_image_clip *show_clip(const show_source *s, int i);
const char *show_path(const show_source *s);

/* Selects the clip named name (NULL: the first that can play). Returns 0
 * with *src ready for the playback engine (a frame lost in a bad block is
 * held and logged once per block; each pass that lost or rebuilt anything
 * ends with a summary line), or -1 after reporting. */
int show_select_clip(show_source *s, const char *name, play_source *src);

void show_close(show_source *s);


#endif
