/* Acclaim AMC motion, streamed: one frame at a time through a text_lines
 * reader, so memory use does not grow with the clip. */
#ifndef AMC_H
#define AMC_H

#include "skel.h"
#include "skp_error.h"
#include "text_lines.h"

typedef struct amc_frame {
	long number;                 /* frame number as written in the file */
	long line;                   /* line of that number, for messages */
	/* Bone b's i-th dof is value[bone[b].dof_offset + i]: rotations in
	 * radians, translations in ASF length units. Absent bones stay 0. */
	float value[SKP_MAX_DOF];
} amc_frame;

typedef struct amc_stream {
	const skel *s;
	text_lines *tl;
	int angle_in_degrees;        /* :DEGREES / :RADIANS, else the ASF's unit */
	double length_factor;        /* translations and `l` in the ASF's :units length */
	long pending_number;         /* number line read ahead, or -1 */
	long pending_line;
	int at_end;
	int hint;                    /* next bone expected: exporters repeat their order */
	uint8_t seen[SKP_MAX_BONES];
	int last_bones;              /* bones the previous frame listed */
	long cut_frame, cut_line;    /* a last frame cut short and dropped, else -1 */
} amc_stream;

/* Frame numbers an image stores (i32) and playback counts with. */
#define AMC_MAX_FRAME_NUMBER 2147483647L

void amc_open(amc_stream *a, const skel *s, text_lines *tl);

/* Returns 1 with the next frame in *f, 0 after the last frame, or a
 * negative skp_status (err names the line and what was expected). A last
 * frame that lists fewer bones than the one before it (the file was cut
 * short) is dropped: 0, with its number and line in cut_frame, cut_line. */
int amc_next(amc_stream *a, amc_frame *f, skp_error *err);

#endif
