#include "show_watch.h"

#include <string.h>
#include <sys/stat.h>

#include "cli_error.h"
#include "cli_say.h"

static show_slot_state slot_now(const char *path)
{
	struct stat st;
	show_slot_state s;
	memset(&s, 0, sizeof s);
	if (stat(path, &st) == 0) {
		s.exists = 1;
		s.dev = st.st_dev;
		s.ino = st.st_ino;
		s.size = st.st_size;
		s.mtime = st.st_mtim;
	}
	return s;
}

static int same(const show_slot_state *a, const show_slot_state *b)
{
	return a->exists == b->exists && a->dev == b->dev && a->ino == b->ino && a->size == b->size &&
	       a->mtime.tv_sec == b->mtime.tv_sec && a->mtime.tv_nsec == b->mtime.tv_nsec;
}

void show_watch_init(show_watch *w, const char *const *paths, int count)
{
	memset(w, 0, sizeof *w);
	w->paths = paths;
	w->count = count < SHOW_MAX_SLOTS ? count : SHOW_MAX_SLOTS;
	for (int i = 0; i < w->count; i++)
		w->seen[i] = w->last[i] = slot_now(paths[i]);
}

/* 1 when the file holds a whole image: every block as packed or rebuilt
 * from parity, the data matching the header's digest. */
static int whole_image(const char *path)
{
	static show_image probe;
	skp_error err;
	skp_error_clear(&err);
	skp_image_verdict v = { 0, 0, -1 };
	int ok = show_image_open(&probe, path, &err) == 0;
	if (ok) {
		show_image_verify(&probe, NULL, NULL, &v);
		ok = v.beyond == 0 && v.digest == 1;
	}
	show_image_close(&probe);
	if (!ok)
		cli_warn("image: %s changed but holds no whole image (%s): playing on until it changes again\n",
			cli_shown(path), v.beyond ? "blocks beyond repair" : v.digest == 0 ? "its digest does not match"
									  : err.msg);
	return ok;
}

int show_watch_poll(show_watch *w, uint64_t now, int whole_only)
{
	if (now < w->next_look)
		return 0;
	w->next_look = now + SHOW_WATCH_POLL_NS;
	for (int i = 0; i < w->count; i++) {
		show_slot_state s = slot_now(w->paths[i]);
		if (!same(&s, &w->last[i])) {
			w->last[i] = s;
			w->changed_at = now;
		}
	}
	if (!w->changed_at || now - w->changed_at < SHOW_WATCH_SETTLE_NS)
		return 0;
	int news = 0;
	for (int i = 0; i < w->count; i++) {
		if (same(&w->seen[i], &w->last[i]))
			continue;
		w->seen[i] = w->last[i]; /* judged: not again until it changes */
		if (w->last[i].exists && (!whole_only || whole_image(w->paths[i])))
			news = 1;
	}
	return news;
}
