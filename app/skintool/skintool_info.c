/* skintool info show.skn
 * Prints a flash image's header (its id included), sections, parity and
 * clips, then checks every block: data blocks by their frame, parity
 * blocks against their group, the copies against what they copy, and the
 * data against the header's digest. Each bad block is named with what it
 * held and whether it can be rebuilt (`skintool repair`). Exit status 0
 * when every block is good, 2 when the image is damaged, 1 when it cannot
 * be read at all. */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "cli_error.h"
#include "show_source.h"
#include "skintool_cmds.h"
#include "tool_args.h"
#include "tool_state.h"

static void print_hex(const char *label, const uint8_t *p, int n)
{
	printf("%s", label);
	for (int i = 0; i < n; i++)
		printf("%02x", p[i]);
	printf("\n");
}

static void print_parity(const skp_image_header *h)
{
	if (h->parity_blocks == 0)
		printf("  parity      none (packed with --parity none)\n");
	else
		printf("  parity      blocks %lu..%lu: %lu groups of up to %lu data blocks (block b in group b mod %lu)\n",
		       (unsigned long)h->data_blocks, (unsigned long)(h->data_blocks + h->parity_blocks - 1),
		       (unsigned long)h->parity_blocks,
		       (unsigned long)((h->data_blocks + h->parity_blocks - 1) / h->parity_blocks),
		       (unsigned long)h->parity_blocks);
	printf("  copies      directory: blocks %lu..%lu; header: block %lu; parity and copies %.1f%% more\n",
	       (unsigned long)h->dir_copy, (unsigned long)(h->copy_block - 1), (unsigned long)h->copy_block,
	       100.0 * (h->block_count - h->data_blocks) / h->data_blocks);
}

/* The sequence, with the date it stands for when it is a unix time (pack's
 * default), and a word when that date lies ahead of this machine's clock:
 * a pack on a machine whose clock ran ahead beats every image packed
 * before that date. */
static void print_sequence(uint64_t seq)
{
	printf("  sequence    %llu", (unsigned long long)seq);
	time_t t = (time_t)seq, now = time(NULL);
	struct tm tm;
	char when[32];
	if (seq >= (uint64_t)SKP_IMAGE_SEQUENCE_CLOCK_FLOOR && seq <= 0xffffffffULL && gmtime_r(&t, &tm)) {
		strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", &tm);
		printf(" (packed %s", when);
		if (t > now + 86400)
			printf(": ahead of this machine's clock, so it beats every image packed before then; a pack on "
			       "a machine whose clock ran ahead? skintool pack --sequence N sets one");
		printf(")");
	}
	printf("\n");
}

static void print_header(const show_image *s)
{
	const skp_image_header *h = &s->im.hdr;
	static const char *const names[] = { "skeleton", "bind", "directory", "clips" };
	printf("%s: skinplay image, format version %u\n", s->path, (unsigned)h->version);
	print_hex("  id          ", h->id, SKP_IMAGE_ID_BYTES);
	print_sequence(h->sequence);
	printf("  blocks      %lu of %lu bytes (%llu bytes), CRC-32 each; header CRC %08lx\n",
	       (unsigned long)h->block_count, (unsigned long)h->block_size,
	       (unsigned long long)h->block_count * h->block_size, (unsigned long)h->crc);
	print_hex(s->im.digest_first ? "  digest      root of the blocks' digests " : "  digest      SHA-256 of the data blocks ",
		  h->digest, SKP_IMAGE_DIGEST_BYTES);
	printf("  needs       %lu bones, %lu dofs, %lu vertices, %lu triangles, %lu influences, %lu clips\n",
	       (unsigned long)h->bones, (unsigned long)h->dofs, (unsigned long)h->verts, (unsigned long)h->tris,
	       (unsigned long)h->influences, (unsigned long)h->clips);
	printf("  section     header: block 0%s\n", s->im.header_from_parity ? " (bad, and its copy: rebuilt from parity)"
						   : s->im.header_from_copy ? " (bad: read from its copy)" : "");
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		const skp_image_section *sec = &h->sec[i];
		printf("  section     %s: blocks %lu..%lu", names[i], (unsigned long)sec->first,
		       (unsigned long)(sec->first + sec->count) - (sec->count > 0));
		if (i != SKP_SEC_CLIPS)
			printf(", %lu bytes", (unsigned long)sec->bytes);
		printf("\n");
	}
	if (s->im.digest_first)
		printf("  section     block digests: blocks %lu..%lu, a SHA-256 leaf for each of blocks 1..%lu%s\n",
		       (unsigned long)s->im.digest_first, (unsigned long)h->data_blocks - 1,
		       (unsigned long)s->im.digest_first - 1,
		       s->im.digests ? "" : " (NOT the header's root: blocks checked by CRC alone)");
	print_parity(h);
}

static void print_clips(const show_image *s)
{
	for (int i = 0; i < s->im.clip_count; i++) {
		const skp_image_clip *c = &s->im.clip[i];
		printf("  clip %d      %s: %lu frames at %g fps (%.2f s), frames %ld..%ld, blocks %lu..%lu "
		       "(frames from %lu) ",
		       i, c->name, (unsigned long)c->frame_count, (double)c->fps, c->frame_count / (double)c->fps,
		       (long)c->first_number, (long)c->first_number + (long)c->frame_count - 1,
		       (unsigned long)c->quant_first, (unsigned long)(c->frames_first + c->frame_blocks) - 1,
		       (unsigned long)c->frames_first);
		if (c->coded)
			printf("(compressed: %.1f bytes a frame in %lu segments, shell error worst %.4f cm), ",
			       c->stream_bytes / (double)c->frame_count, (unsigned long)c->segments, (double)c->shell_err);
		else
			printf("(%u frames per block), ", (unsigned)c->frames_per_block);
		printf("worst-case error %.3g rad (%.3g deg), %.3g length units\n", (double)c->max_rot_err,
		       (double)c->max_rot_err * 57.29577951308232, (double)c->max_trans_err);
	}
}

/* What a bad block held, so the message says what is lost, and whether it
 * comes back. */
static void bad_block(void *ctx, uint32_t b, const skp_block_report *r)
{
	const show_image *s = ctx;
	const skp_image_header *h = &s->im.hdr;
	printf("block %lu bad: %s (%s", (unsigned long)b,
	       r->role == SKP_ROLE_PARITY && r->state == SKP_BLOCK_CRC ? "does not match its group"
									: skp_block_state_name(r->state),
	       skp_block_report_what(r));
	if (r->role == SKP_ROLE_DATA && (r->kind == SKP_KIND_QUANT || r->kind == SKP_KIND_FRAMES)) {
		const skp_image_clip *c = &s->im.clip[r->item];
		printf(" of clip %s", c->name);
		if (r->kind == SKP_KIND_FRAMES && c->coded) {
			long room = (long)skp_image_stream_room(h->block_size);
			long first = (long)(b - c->frames_first) * room;
			printf(", compressed stream bytes %ld..%ld", first, first + room - 1);
		} else if (r->kind == SKP_KIND_FRAMES) {
			long first = (long)(b - c->frames_first) * c->frames_per_block;
			long last = first + c->frames_per_block - 1;
			if (last >= (long)c->frame_count)
				last = (long)c->frame_count - 1;
			printf(", frames %ld..%ld", first + c->first_number, last + c->first_number);
		}
	}
	if ((r->role == SKP_ROLE_DATA || r->role == SKP_ROLE_PARITY) && h->parity_blocks)
		printf(", parity group %lu", (unsigned long)r->group);
	printf("): %s\n", r->repairable ? "repairable"
		 : r->role == SKP_ROLE_DIR_COPY ? "beyond repair (the directory is bad too)"
		 : h->parity_blocks == 0 ? "beyond repair (no parity)"
		 : "beyond repair (another block of its group is bad)");
}

/* Prints a run of blocks [from, to] in state st (not OK). */
static void print_bad_run(uint32_t from, uint32_t to, skp_block_state st)
{
	if (from == to)
		printf("block %lu bad: %s\n", (unsigned long)from, skp_block_state_name(st));
	else
		printf("blocks %lu..%lu bad: %s\n", (unsigned long)from, (unsigned long)to, skp_block_state_name(st));
}

static skp_block_state raw_state(storage_file *sf, uint32_t b, uint32_t bs, uint8_t *buf)
{
	int n = sf->bd.read(sf, b, buf);
	return n < 0 ? SKP_BLOCK_IO : n < (int)bs ? SKP_BLOCK_SHORT : skp_block_crc_ok(buf, bs) ? SKP_BLOCK_OK : SKP_BLOCK_CRC;
}

/* The header is not trusted: find the block size under which most blocks
 * of the first SKP_IMAGE_FIND_BARREN bytes check, then name the blocks
 * whose CRC fails at that size, runs of them as ranges. None checking
 * there at any size: no image, said at once (a zero-filled 2 GiB slot is
 * not read to its end). */
static long scan_raw(storage_file *sf)
{
	static uint8_t buf[SKP_IMAGE_BLOCK_SIZE];
	uint32_t best = SKP_IMAGE_DEFAULT_BLOCK;
	long best_good = 0, bad = 0;
	for (uint32_t bs = SKP_IMAGE_MIN_BLOCK; bs <= SKP_IMAGE_BLOCK_SIZE; bs *= 2) {
		long good = 0;
		storage_file_set_block_size(sf, bs);
		uint32_t look = sf->bd.block_count < SKP_IMAGE_FIND_BARREN / bs ? sf->bd.block_count : SKP_IMAGE_FIND_BARREN / bs;
		for (uint32_t b = 0; b < look; b++)
			good += raw_state(sf, b, bs, buf) == SKP_BLOCK_OK;
		if (good > best_good)
			best_good = good, best = bs;
	}
	if (best_good == 0) {
		printf("verify: no block of the first %u MiB checks at any block size: not an image (zero-filled, or "
		       "another file)\n", SKP_IMAGE_FIND_BARREN >> 20);
		return 1;
	}
	storage_file_set_block_size(sf, best);
	uint32_t run = 0;
	skp_block_state run_st = SKP_BLOCK_OK;
	for (uint32_t b = 0; b <= sf->bd.block_count; b++) {
		skp_block_state st = b < sf->bd.block_count ? raw_state(sf, b, best, buf) : SKP_BLOCK_OK;
		if (st != run_st && run_st != SKP_BLOCK_OK)
			print_bad_run(run, b - 1, run_st);
		if (st != run_st)
			run = b, run_st = st;
		bad += st != SKP_BLOCK_OK;
	}
	printf("verify: %lu blocks of %lu bytes (block size found from their CRCs): %ld bad\n",
	       (unsigned long)sf->bd.block_count, (unsigned long)best, bad);
	return bad;
}

/* The body's texture as the device keeps it, and how many vertices
 * sample it. */
static void say_texture(const bound_body *body)
{
	const mesh *m = &body->mesh;
	if (body->texture_skipped)
		printf("texture: larger than this board keeps (%d pixels a side): the body plays in its colours\n",
		       SKP_MAX_TEXTURE_SIDE);
	if (!m->textured)
		return;
	int sampled = 0;
	for (int v = 0; v < m->vert_count; v++)
		sampled += m->sampled[v] != 0;
	printf("texture: %dx%d ETC1, %d mip levels, %lu bytes; %d of %d vertices sample it\n", body->texture.width,
	       body->texture.height, body->texture.chain.levels, (unsigned long)body->texture.chain.etc1_bytes, sampled,
	       m->vert_count);
}

/* What skinplay checks before playing (show_accept.c), so that info and
 * skinplay never disagree: 1 when the body is refused (nothing would play)
 * or a clip cannot play (each listed). */
static int accept(show_image *s)
{
	TOOL_STATE(bound_body, body);
	skp_error err;
	if (show_accept_body(s, body, &err) < 0) {
		if (err.block >= 0)
			printf("accept: refused: block %ld: %s\n", err.block, err.msg);
		else
			printf("accept: refused: %s\n", err.msg);
		return 1;
	}
	int playable = 0;
	for (int c = 0; c < s->im.clip_count; c++) {
		if (show_accept_clip(s, &body->skel, c, &err) == 0) {
			playable++;
			continue;
		}
		printf("accept: clip %d %s cannot play: ", c, s->im.clip[c].name);
		if (err.block >= 0)
			printf("block %ld: ", err.block);
		printf("%s\n", err.msg);
	}
	printf("accept: skeleton and body good, %d of %d clips can play\n", playable, s->im.clip_count);
	say_texture(body);
	return playable < s->im.clip_count;
}

static int refused(show_image *s, const skp_error *err)
{
	if (err->block >= 0)
		printf("%s: block %ld bad: %s\n", s->path, err->block, err->msg);
	else
		printf("%s: %s\n", s->path, err->msg);
	if (err->code == SKP_ERR_LIMIT)
		return 2;
	int rc = show_storage_open(&s->sf, s->path);
	if (rc < 0)
		return 2;
	scan_raw(&s->sf);
	storage_file_close(&s->sf);
	return 2;
}

static const cli_command info_command = {
	.prog = "skintool info",
	.usage = "SHOW.skn",
	.about = "Prints an image's header (its id), sections and clips, accepts its body and clips as skinplay\n"
		 "would, and checks every block (CRC, id, parity, the copies) and the digest (`skintool repair`\n"
		 "rebuilds what parity and the copies allow).",
	.exit2 = "a damaged image: a bad block, a digest that does not match, the body or a clip refused",
	.examples = (const cli_example[]){
		{ "Check an image before it goes to the kiosk",
		  "skintool info show.skn" },
		{ NULL, NULL },
	},
};

int cmd_info(int argc, char **argv)
{
	static show_image s;
	skp_error err;
	const char *path;
	int rc = tool_one_file(&info_command, argc, argv, &path);
	if (rc != 0)
		return rc < 0;
	if (show_image_open(&s, path, &err) < 0) {
		if (err.code == SKP_ERR_IO && err.block < 0) {
			fprintf(stderr, "%s: %s\n", path, err.msg);
			return 1;
		}
		return refused(&s, &err);
	}
	print_header(&s);
	print_clips(&s);
	int refused_body = accept(&s);
	skp_image_verdict v;
	show_image_verify(&s, bad_block, &s, &v);
	if (v.bad == 0)
		printf("verify: %lu blocks: all good, 0 bad\n", (unsigned long)s.im.hdr.block_count);
	else if (v.beyond == 0 && v.digest > 0)
		printf("verify: %lu blocks: %ld bad, all repairable (skintool repair %s)\n",
		       (unsigned long)s.im.hdr.block_count, v.bad, cli_shown(s.path));
	else /* repair commits only an image that matches its digest: it would refuse */
		printf("verify: %lu blocks: %ld bad, %ld rebuildable one by one, %ld beyond repair; not repairable as a "
		       "whole (%s): pack the show again\n", (unsigned long)s.im.hdr.block_count, v.bad, v.bad - v.beyond,
		       v.beyond, v.beyond ? "blocks beyond repair" : "the data would not match the image's digest");
	printf("digest: %s\n", v.digest > 0 ? (s.im.digest_first ? "every data block matches its own digest, and "
								    "the digests the root"
								  : "the data blocks match it")
				: v.digest < 0 ? "not checked (a data block is beyond repair)"
				: "MISMATCH: a data block was altered and keeps a good CRC (not this image as packed)");
	if (s.im.missing)
		printf("note: the storage ends %lu blocks before the image (counted bad above)\n",
		       (unsigned long)s.im.missing);
	if (s.sf.bd.block_count > s.im.hdr.block_count)
		printf("note: %lu blocks after the image's end (ignored)\n",
		       (unsigned long)(s.sf.bd.block_count - s.im.hdr.block_count));
	show_image_close(&s);
	return v.bad || v.digest == 0 || refused_body ? 2 : 0;
}
