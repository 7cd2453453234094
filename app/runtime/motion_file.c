#include "motion_file.h"

#include <string.h>

#include "asf.h"
#include "bvh.h"
#include "cli_error.h"
#include "cli_say.h"
#include "text_tokens.h"

static int open_lines(const char *path, file_reader *fr, text_lines *tl)
{
	int rc = file_reader_open(fr, path);
	if (rc < 0) {
		cli_error_errno(path, "open", rc);
		return -1;
	}
	text_lines_init(tl, file_reader_as_reader(fr));
	return 0;
}

int motion_load_skel(const char *path, skel *out)
{
	static file_reader fr;
	static text_lines tl;
	static bvh_layout layout;
	skp_error err;

	if (open_lines(path, &fr, &tl) < 0)
		return -1;
	skp_status rc = bvh_is_path(path) ? bvh_parse(out, &layout, &tl, &err) : asf_parse(out, &tl, &err);
	file_reader_close(&fr);
	if (rc != SKP_OK) {
		cli_error(path, &err);
		return -1;
	}
	return 0;
}

/* -1 when a and b have the same joints and channels (a BVH file against
 * the skeleton read from another), else the first joint that differs. */
static int same_joints(const skel *a, const skel *b)
{
	for (int i = 0; i < a->count || i < b->count; i++) {
		if (i >= a->count || i >= b->count || strcmp(a->bone[i].name, b->bone[i].name) ||
		    a->bone[i].parent != b->bone[i].parent || a->bone[i].channel_count != b->bone[i].channel_count ||
		    memcmp(a->bone[i].channel, b->bone[i].channel, a->bone[i].channel_count))
			return i;
	}
	return -1;
}

int motion_file_open(motion_file *m, const char *path, const skel *s)
{
	/* a loop reopens the same file: its cut frame is reported once */
	if (m->path != path)
		m->warned_cut = 0;
	m->path = path;
	m->is_bvh = bvh_is_path(path);
	if (open_lines(path, &m->file, &m->lines) < 0)
		return -1;
	if (!m->is_bvh) {
		amc_open(&m->stream, s, &m->lines);
		return 0;
	}
	/* the file's own hierarchy, which must be the skeleton's */
	skp_error err;
	if (bvh_parse(&m->bvh_skel, &m->layout, &m->lines, &err) != SKP_OK) {
		cli_error(path, &err);
		file_reader_close(&m->file);
		return -1;
	}
	int bad = same_joints(&m->bvh_skel, s);
	if (bad >= 0) {
		cli_warn("%s: its HIERARCHY is not the skeleton's (joint %d, '%s')\n", path, bad,
			bad < m->bvh_skel.count ? m->bvh_skel.bone[bad].name : "");
		file_reader_close(&m->file);
		return -1;
	}
	bvh_open(&m->bvh, s, &m->layout, &m->lines);
	return 0;
}

int motion_file_read(motion_file *m, amc_frame *f, skp_error *err)
{
	int r = m->is_bvh ? bvh_next(&m->bvh, f, err) : amc_next(&m->stream, f, err);
	if (r == 0 && m->is_bvh && m->bvh.cut_frames > 0 && !m->warned_cut) {
		cli_warn("%s: warning: the file ends %ld frames short of its Frames: %ld\n", m->path,
			m->bvh.cut_frames, m->layout.frames);
		m->warned_cut = 1;
	}
	if (r == 0 && !m->is_bvh && m->stream.cut_frame >= 0 && !m->warned_cut) {
		cli_warn("%s:%ld: warning: frame %ld is cut short (the file ends inside it): dropped\n",
			m->path, m->stream.cut_line, m->stream.cut_frame);
		m->warned_cut = 1;
	}
	return r;
}

int motion_file_next(motion_file *m, amc_frame *f)
{
	skp_error err;
	int r = motion_file_read(m, f, &err);
	if (r < 0) {
		cli_error(m->path, &err);
		return -1;
	}
	return r;
}

void motion_file_close(motion_file *m)
{
	file_reader_close(&m->file);
}

long motion_file_count(const char *path, const skel *s)
{
	static motion_file m;
	static amc_frame f;
	if (motion_file_open(&m, path, s) < 0)
		return -1;
	long n = 0;
	int r;
	while ((r = motion_file_next(&m, &f)) > 0)
		n++;
	motion_file_close(&m);
	return r < 0 ? -1 : n;
}

static void no_frame(const char *path, long number, long first, long last)
{
	if (first < 0)
		cli_warn("%s: no frames\n", path);
	else
		cli_warn("%s: no frame %ld (the file has frames %ld..%ld)\n", path, number,
			first, last);
}

int motion_read_frame(const char *path, const skel *s, long number, amc_frame *f)
{
	static motion_file m;
	if (motion_file_open(&m, path, s) < 0)
		return -1;
	int r;
	long first = -1, last = -1;
	while ((r = motion_file_next(&m, f)) > 0) {
		if (first < 0)
			first = f->number;
		last = f->number;
		if (number < 0 || f->number == number)
			break;
	}
	motion_file_close(&m);
	if (r < 0)
		return -1;
	if (r == 0) {
		no_frame(path, number, first, last);
		return -1;
	}
	return 0;
}

void motion_bvh_slots(const char **skeleton, const char **motion, const char **next)
{
	if (!*skeleton || !bvh_is_path(*skeleton) || (*motion && bvh_is_path(*motion)))
		return;
	if (next && !*next)
		*next = *motion;
	*motion = *skeleton;
}
