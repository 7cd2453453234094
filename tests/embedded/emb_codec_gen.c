/* emb_codec_gen OUT.h: the integer-made compressed clip of
 * tests/support/codec_synth.h, its segments coded on the host by
 * app/encode's segment coder, as C arrays for emb_skin.c, which decodes
 * them on the board (the codec checksum, compared with the host's). */
#include <stdio.h>
#include <stdlib.h>

#include "codec_synth.h"
#include "encode_segment.h"

int main(int argc, char **argv)
{
	static codec_clip c;
	static int32_t q[CODEC_SYNTH_FRAMES * CODEC_SYNTH_TRACKS];
	if (argc != 2) {
		fprintf(stderr, "usage: emb_codec_gen OUT.h\n");
		return 2;
	}
	codec_synth_clip(&c);
	codec_synth_q(q);
	FILE *out = fopen(argv[1], "w");
	if (!out) {
		perror(argv[1]);
		return 1;
	}
	uint32_t segs = codec_segments(&c), at = 0;
	fprintf(out, "/* made by tests/embedded/emb_codec_gen.c */\n#define EMB_CODEC_SEGMENTS %lu\n",
		(unsigned long)segs);
	fprintf(out, "static const uint32_t emb_codec_offset[%lu] = {", (unsigned long)segs + 1);
	enc_bits all[CODEC_SYNTH_FRAMES / CODEC_SYNTH_SEGMENT + 1] = { { 0 } };
	for (uint32_t s = 0; s < segs; s++) {
		long first = (long)s * CODEC_SYNTH_SEGMENT;
		int len = (int)(CODEC_SYNTH_FRAMES - first < CODEC_SYNTH_SEGMENT ? CODEC_SYNTH_FRAMES - first : CODEC_SYNTH_SEGMENT);
		enc_segment(&c, q, CODEC_SYNTH_TRACKS, first, len, &all[s]);
		if (all[s].failed)
			return fprintf(stderr, "emb_codec_gen: out of memory\n"), 1;
		fprintf(out, " %lu,", (unsigned long)at);
		at += (uint32_t)all[s].len;
	}
	fprintf(out, " %lu };\nstatic const uint8_t emb_codec_bytes[%lu] = {", (unsigned long)at, (unsigned long)at);
	for (uint32_t s = 0, n = 0; s < segs; s++) {
		for (size_t i = 0; i < all[s].len; i++, n++)
			fprintf(out, "%s%u,", n % 24 ? " " : "\n\t", (unsigned)all[s].buf[i]);
		enc_bits_free(&all[s]);
	}
	fprintf(out, "\n};\n");
	return fclose(out) == 0 ? 0 : 1;
}
