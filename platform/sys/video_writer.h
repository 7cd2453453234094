/* A video file from RGBA8 frames through libavformat and libavcodec:
 * NAME.mp4 is H.264 (libx264, else another H.264 encoder this libavcodec
 * has, such as libopenh264), NAME.webm is VP9 (libvpx-vp9), both yuv420p
 * (BT.709, limited range; swscale converts). Frame i lasts 1/rate s from
 * i/rate s, so a video of n frames lasts n/rate s whatever the encoder
 * buffers. The file is written as atomic_file.h writes (an unnamed
 * temporary in its directory that becomes NAME only once whole and
 * synced): a run that fails or is killed leaves nothing, and a NAME that
 * was there stays until the new one replaces it. Built where the board
 * has the libraries (board.mk: VIDEO; the Makefile defines SKP_VIDEO). */
#ifndef VIDEO_WRITER_H
#define VIDEO_WRITER_H

#include <stdint.h>

#include "skp_error.h"

typedef struct video_writer video_writer;

/* Opens path (.mp4 or .webm, any case) for width x height frames (both
 * even: yuv420p halves them) at rate_num/rate_den frames a second. NULL
 * with err filled (an unknown name, an odd size, no encoder, a directory
 * that cannot take the file). */
video_writer *video_writer_open(const char *path, int width, int height, int rate_num, int rate_den,
				skp_error *err);

/* Encodes the next frame: width x height RGBA8 pixels, rows packed;
 * bottom_up as png_write_rgba's (glReadPixels' order). Alpha is dropped. */
int video_writer_add_rgba(video_writer *v, const uint8_t *rgba, int bottom_up, skp_error *err);

/* The encoder's name ("libx264") and the codec's ("h264", "vp9"). */
const char *video_writer_encoder(const video_writer *v);
const char *video_writer_codec(const video_writer *v);

/* Frames added so far. */
long video_writer_frames(const video_writer *v);

/* Drains the encoder, finishes the container and makes the file path.
 * Frees v whatever happens; on failure (err filled) nothing is left. */
int video_writer_close(video_writer *v, skp_error *err);

/* Drops the video (path keeps what it held) and frees v. NULL is fine. */
void video_writer_abort(video_writer *v);

#endif
