#include "show_source.h"

#include <errno.h>
#include <string.h>

#include "cli_error.h"
#include "cli_say.h"
#include "play_policy.h"
#include "skp_format.h"

/* n bytes of the file from offset at into buf; how many came. */
static long read_at(storage_file *sf, uint64_t at, uint8_t *buf, long n)
{
	skp_reader rd = storage_file_reader(sf);
	sf->pos = at;
	long got = 0, k;
	while (got < n && (k = rd.read(rd.ctx, buf + got, (size_t)(n - got))) > 0)
		got += k;
	return got;
}

/* The image's block size from its header copy: at the end of the file,
 * else searched for (bytes after the image, block 0 lost). 0: none. */
static uint32_t copy_block_size(storage_file *sf)
{
	static uint8_t tail[SKP_IMAGE_TAIL], win[16384];
	skp_image_header h;
	uint64_t at;
	if (sf->size >= sizeof tail && read_at(sf, sf->size - sizeof tail, tail, sizeof tail) == (long)sizeof tail &&
	    skp_image_copy_at(tail, sf->size - sizeof tail, &h))
		return h.block_size;
	skp_reader rd = storage_file_reader(sf);
	return skp_image_find_copy(rd, win, sizeof win, &h, &at) ? h.block_size : 0;
}

int show_storage_open(storage_file *sf, const char *path)
{
	static uint8_t head[SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_HEADER_SIZE];
	int rc = storage_file_open(sf, path, SKP_IMAGE_DEFAULT_BLOCK);
	if (rc < 0)
		return rc;
	/* block 0's header when whole (its CRC), else its copy's */
	long n = read_at(sf, 0, head, sizeof head);
	uint32_t bs = n > 0 ? skp_image_block_size_hint(head, (uint32_t)n) : 0;
	if (!bs)
		bs = copy_block_size(sf);
	if (bs && bs <= SKP_IMAGE_BLOCK_SIZE)
		storage_file_set_block_size(sf, bs);
	return 0;
}

int show_image_open(show_image *s, const char *path, skp_error *err)
{
	s->path = path;
	int rc = show_storage_open(&s->sf, path);
	if (rc == -EINVAL) {
		skp_fail(err, SKP_ERR_IO, 0, "%s, not an image file or a partition", storage_file_kind(path));
		return -1;
	}
	if (rc < 0) {
		skp_fail(err, SKP_ERR_IO, 0, "cannot open: %s", strerror(-rc));
		return -1;
	}
	if (skp_image_open(&s->im, &s->sf.bd, err) != SKP_OK) {
		storage_file_close(&s->sf);
		return -1;
	}
	return 0;
}

void show_image_close(show_image *s)
{
	if (s->path)
		storage_file_close(&s->sf);
	s->path = NULL;
}

void show_image_verify(show_image *s, void (*bad)(void *ctx, uint32_t block, const skp_block_report *r),
		       void *ctx, skp_image_verdict *v)
{
	static uint8_t buf[SKP_IMAGE_BLOCK_SIZE];
	skp_image_verify(&s->im, buf, bad, ctx, v);
}

void show_image_warn(const show_image *s)
{
	if (s->im.missing)
		cli_warn("image: %s: the storage ends %lu block%s before the image (its copies or parity): "
			"it plays; skintool repair writes them again\n", s->path, (unsigned long)s->im.missing,
			s->im.missing == 1 ? "" : "s");
}

static void refuse(const char *path, const skp_error *err)
{
	if (err->block >= 0)
		cli_warn("image: %s refused: block %ld: %s\n", path, err->block, err->msg);
	else
		cli_warn("image: %s refused: %s\n", path, err->msg);
}

/* Opens every slot; newest (largest sequence) first into order[]. */
static int by_sequence(show_source *s, const char *const *paths, int n, int order[])
{
	uint64_t seq[SHOW_MAX_SLOTS] = { 0 };
	uint8_t opened[SHOW_MAX_SLOTS] = { 0 };
	skp_error err;
	for (int i = 0; i < n && i < SHOW_MAX_SLOTS; i++) {
		s->slot[i].im.on_rebuild = show_log_rebuild;
		s->slot[i].im.on_rebuild_ctx = &s->slot[i];
		if (show_image_open(&s->slot[i], paths[i], &err) < 0) {
			refuse(paths[i], &err);
			continue;
		}
		opened[i] = 1;
		seq[i] = s->slot[i].im.hdr.sequence;
	}
	return play_slots_by_sequence(seq, opened, n < SHOW_MAX_SLOTS ? n : SHOW_MAX_SLOTS, order);
}

static void close_others(show_source *s, int keep)
{
	for (int i = 0; i < s->slot_count; i++)
		if (i != keep)
			show_image_close(&s->slot[i]);
}

/* Every clip of img checked (its skeleton sk); one that cannot play is
 * skipped, with a line saying why when loud. Returns how many can play. */
static int accept_clips(show_source *s, show_image *img, const skel *sk, int loud)
{
	skp_error err;
	int playable = 0;
	for (int c = 0; c < img->im.clip_count; c++) {
		s->playable[c] = show_accept_clip(img, sk, c, &err) == 0;
		playable += s->playable[c];
		if (s->playable[c] || !loud)
			continue;
		if (err.block >= 0)
			cli_warn("image: clip %s skipped: block %ld: %s\n", img->im.clip[c].name, err.block, err.msg);
		else
			cli_warn("image: clip %s skipped: %s\n", img->im.clip[c].name, err.msg);
	}
	return playable;
}

/* Of several slots, why an accepted one should yield to an older one: a
 * block beyond repair, data that does not match its digest, no clip that
 * can play. 0 when it is whole (one slot is always whole: it plays
 * whatever survives). */
static int slot_flawed(show_source *s, show_image *img, const skel *sk, int several)
{
	skp_image_verdict v = { 0, 0, 1 };
	if (!several)
		return 0;
	show_image_verify(img, NULL, NULL, &v);
	if (v.beyond)
		cli_warn("image: %s has %ld blocks beyond repair: trying an older slot\n", img->path, v.beyond);
	else if (v.digest == 0)
		cli_warn("image: %s does not match its digest (a block altered with a good CRC): trying an older slot\n",
			img->path);
	else if (accept_clips(s, img, sk, 0) == 0)
		cli_warn("image: %s has no clip that can play: trying an older slot\n", img->path);
	else
		return 0;
	return 1;
}

/* The slot policy's checks (app/play/play_policy.h), with their messages:
 * the body accepted (into s->body), and a flaw an intact older slot wins
 * over. */
static int slot_accept(void *ctx, int i)
{
	show_source *s = ctx;
	skp_error err;
	if (show_accept_body(&s->slot[i], s->body, &err) == 0)
		return 1;
	refuse(s->slot[i].path, &err);
	return 0;
}

static long slot_damaged(void *ctx, int i)
{
	show_source *s = ctx;
	return slot_flawed(s, &s->slot[i], &s->body->skel, 1);
}

int show_open(show_source *s, const char *const *paths, int n, bound_body *body)
{
	int order[SHOW_MAX_SLOTS];
	memset(s, 0, sizeof *s);
	s->clip = -1;
	s->body = body;
	skp_ratelimit_init(&s->pass_said, SKP_RATELIMIT_HOUR);
	s->slot_count = n < SHOW_MAX_SLOTS ? n : SHOW_MAX_SLOTS;
	int k = by_sequence(s, paths, n, order);
	play_slot_checks checks = { s, slot_accept, slot_damaged };
	s->active = play_slot_choose(order, k, n, &checks);
	if (s->active < 0) {
		cli_warn("image: no valid image among %d slot%s\n", n, n > 1 ? "s" : "");
		close_others(s, -1);
		return -1;
	}
	close_others(s, s->active);
	show_image *img = &s->slot[s->active];
	cli_say("image: playing %s (sequence %llu, %d clip%s, a body of %d vertices)\n", img->path,
		(unsigned long long)img->im.hdr.sequence, img->im.clip_count, img->im.clip_count == 1 ? "" : "s",
		body->mesh.vert_count);
	show_image_warn(img);
	accept_clips(s, img, &body->skel, 1);
	return 0;
}

int show_next_playable(const show_source *s, int from)
{
	return play_next_playable(s->playable, show_clip_count(s), from);
}

unsigned long show_rebuilt(const show_source *s)
{
	return s->active < 0 ? 0 : s->slot[s->active].im.rebuilt;
}

int show_clip_count(const show_source *s)
{
	return s->active < 0 ? 0 : s->slot[s->active].im.clip_count;
}

const skp_image_clip *show_clip(const show_source *s, int i)
{
	return &s->slot[s->active].im.clip[i];
}

const char *show_path(const show_source *s)
{
	return s->active < 0 ? "" : s->slot[s->active].path;
}

/* A frame held over a bad block: one line per block, ever. */
static void log_lost(void *ctx, long block, const char *why, long held)
{
	show_source *s = ctx;
	if (show_log_once(&s->slot[s->active], block))
		cli_warn("image: block %ld bad (%s), holding frame %ld\n", block, why, held);
}

/* One line for a pass over the clip that lost or rebuilt anything: what a
 * dying card costs stays visible in the journal without a line per frame. */
static void log_pass(void *ctx)
{
	show_source *s = ctx;
	unsigned long rebuilt = s->slot[s->active].im.rebuilt - s->pass_rebuilt, lost = s->clip_src.pass_lost, held;
	/* a short clip loops thousands of times an hour: the first such pass,
	 * then one line an hour (with how many passes went unsaid) */
	if ((lost || rebuilt) && skp_ratelimit_take(&s->pass_said, s->now, &held)) {
		char since[64] = "";
		if (held)
			skp_format(since, sizeof since, " (and %lu passes like it since the last line)", held);
		cli_warn("image: clip %s: %lu frame%s held over bad blocks, %lu block%s rebuilt this pass%s\n",
			 s->clip_src.stream.c.name, lost, lost == 1 ? "" : "s", rebuilt, rebuilt == 1 ? "" : "s", since);
	}
	s->pass_rebuilt = s->slot[s->active].im.rebuilt;
}

int show_select_clip(show_source *s, const char *name, play_source *src)
{
	show_image *img = &s->slot[s->active];
	skp_error err;
	int c = name ? skp_image_find_clip(&img->im, name) : show_next_playable(s, 0);
	if (!name && c < 0) {
		cli_warn("%s: no clip can play\n", img->path);
		return -1;
	}
	if (c < 0 || c >= img->im.clip_count) {
		cli_warn("%s: no clip '%s' (%d clips)\n", cli_shown(img->path), cli_shown(name),
			img->im.clip_count);
		return -1;
	}
	if (!s->playable[c]) {
		cli_warn("%s: clip %s cannot play (see above)\n", img->path, img->im.clip[c].name);
		return -1;
	}
	s->clip_src.on_lost = log_lost;
	s->clip_src.on_rewind = log_pass;
	s->clip_src.ctx = s;
	if (play_image_source_open(&s->clip_src, &img->im, c, &err) != SKP_OK) {
		cli_error(img->path, &err);
		return -1;
	}
	s->clip = c;
	s->pass_rebuilt = img->im.rebuilt;
	*src = play_image_source_get(&s->clip_src);
	return 0;
}

void show_close(show_source *s)
{
	for (int i = 0; i < s->slot_count; i++)
		show_image_close(&s->slot[i]);
	s->active = -1;
}
