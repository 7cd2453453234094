#include "video_writer.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>

#include "atomic_file.h"

/* libavformat 61 (FFmpeg 7, Debian 13) hands the write callback const
 * bytes; 59 and 60 (FFmpeg 5 and 6, Debian 12) did not. */
#if LIBAVFORMAT_VERSION_MAJOR >= 61
#define AVIO_BYTES const uint8_t
#else
#define AVIO_BYTES uint8_t
#endif

struct video_writer {
	atomic_file af;
	char path[PATH_MAX];     /* as the caller named it (af.path: links followed) */
	AVFormatContext *oc;
	AVCodecContext *c;
	AVStream *st;
	struct SwsContext *sws;
	AVFrame *frame;
	AVPacket *pkt;
	int width, height;
	long frames;
	int io_errno;            /* the first write or seek that failed */
};

/* The container and its codec, by the file's name. */
typedef struct video_kind {
	const char *ext, *muxer, *what;
	enum AVCodecID codec;
	const char *const *encoders; /* tried in turn, then any encoder of the codec */
} video_kind;

static const char *const h264_encoders[] = { "libx264", "libopenh264", NULL };
static const char *const vp9_encoders[] = { "libvpx-vp9", NULL };
static const video_kind kinds[] = {
	{ ".mp4", "mp4", "H.264", AV_CODEC_ID_H264, h264_encoders },
	{ ".webm", "webm", "VP9", AV_CODEC_ID_VP9, vp9_encoders },
};

static const video_kind *kind_of(const char *path)
{
	const char *dot = strrchr(path, '.');
	for (size_t i = 0; dot && i < sizeof kinds / sizeof kinds[0]; i++)
		if (!strcasecmp(dot, kinds[i].ext))
			return &kinds[i];
	return NULL;
}

/* libav's own error lines, kept for the message instead of printed: the
 * last one said at AV_LOG_ERROR or worse. */
static char av_said[160];

static void keep_av_errors(void *avcl, int level, const char *fmt, va_list vl)
{
	int prefix = 0;
	if (level > AV_LOG_ERROR)
		return;
	av_log_format_line2(avcl, level, fmt, vl, av_said, sizeof av_said, &prefix);
	size_t n = strlen(av_said);
	while (n && (av_said[n - 1] == '\n' || av_said[n - 1] == '\r'))
		av_said[--n] = '\0';
}

/* What libav said about a failure with code e: its log line when it gave
 * one, else the code's text. */
static const char *why(int e)
{
	static char text[AV_ERROR_MAX_STRING_SIZE];
	if (av_said[0])
		return av_said;
	av_strerror(e, text, sizeof text);
	return text;
}

/* The file, through atomic_file's descriptor (the mp4 muxer seeks back to
 * write its index). */
static int io_write(void *opaque, AVIO_BYTES *buf, int size)
{
	video_writer *v = opaque;
	for (int done = 0; done < size;) {
		ssize_t n = write(v->af.fd, buf + done, (size_t)(size - done));
		if (n < 0 && errno == EINTR)
			continue;
		if (n <= 0) {
			v->io_errno = n < 0 ? errno : EIO;
			return AVERROR(v->io_errno);
		}
		done += (int)n;
	}
	return size;
}

static int64_t io_seek(void *opaque, int64_t offset, int whence)
{
	video_writer *v = opaque;
	struct stat st;
	if (whence & AVSEEK_SIZE)
		return fstat(v->af.fd, &st) == 0 ? (int64_t)st.st_size : AVERROR(errno);
	off_t at = lseek(v->af.fd, (off_t)offset, whence & ~AVSEEK_FORCE);
	if (at < 0) {
		v->io_errno = errno;
		return AVERROR(errno);
	}
	return (int64_t)at;
}

static void free_all(video_writer *v)
{
	if (v->oc && v->oc->pb) {
		av_freep(&v->oc->pb->buffer);
		avio_context_free(&v->oc->pb);
	}
	avformat_free_context(v->oc);
	avcodec_free_context(&v->c);
	sws_freeContext(v->sws);
	av_frame_free(&v->frame);
	av_packet_free(&v->pkt);
	if (v->af.fd >= 0)
		close(v->af.fd);
	free(v);
}

/* The encoder's settings: quality for the size, speed for a batch run. */
static void tune(AVCodecContext *c, enum AVCodecID id)
{
	if (id == AV_CODEC_ID_H264) {
		av_opt_set(c->priv_data, "preset", "fast", 0);
		av_opt_set(c->priv_data, "crf", "20", 0);
	} else {
		av_opt_set(c->priv_data, "deadline", "good", 0);
		av_opt_set(c->priv_data, "cpu-used", "4", 0);
		av_opt_set(c->priv_data, "row-mt", "1", 0);
		av_opt_set(c->priv_data, "crf", "32", 0);
		c->bit_rate = 0;
	}
}

/* The encoder named opened for the size and rate, or NULL (*e: why). */
static AVCodecContext *try_encoder(const AVCodec *codec, enum AVCodecID id, int w, int h, AVRational rate,
				   int global, int *e)
{
	AVCodecContext *c = avcodec_alloc_context3(codec);
	if (!c) {
		*e = AVERROR(ENOMEM);
		return NULL;
	}
	c->width = w;
	c->height = h;
	c->pix_fmt = AV_PIX_FMT_YUV420P;
	c->framerate = rate;
	c->time_base = av_inv_q(rate);
	c->color_range = AVCOL_RANGE_MPEG;
	c->colorspace = AVCOL_SPC_BT709;
	c->color_primaries = AVCOL_PRI_BT709;
	c->color_trc = AVCOL_TRC_BT709;
	if (global)
		c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
	tune(c, id);
	if ((*e = avcodec_open2(c, codec, NULL)) == 0)
		return c;
	avcodec_free_context(&c);
	return NULL;
}

/* The kind's encoders in turn, then whichever encoder of its codec
 * libavcodec prefers (a hardware one may not open here). */
static AVCodecContext *open_encoder(const video_kind *k, int w, int h, AVRational rate, int global, int *e)
{
	AVCodecContext *c = NULL;
	*e = AVERROR_ENCODER_NOT_FOUND;
	for (int i = 0; !c && k->encoders[i]; i++) {
		const AVCodec *codec = avcodec_find_encoder_by_name(k->encoders[i]);
		if (codec)
			c = try_encoder(codec, k->codec, w, h, rate, global, e);
	}
	const AVCodec *any = avcodec_find_encoder(k->codec);
	for (int i = 0; any && k->encoders[i]; i++)
		if (!strcmp(any->name, k->encoders[i]))
			any = NULL; /* tried above */
	if (!c && any)
		c = try_encoder(any, k->codec, w, h, rate, global, e);
	return c;
}

/* RGBA to BT.709 limited-range yuv420p, same size. */
static int start_conversion(video_writer *v)
{
	v->sws = sws_getContext(v->width, v->height, AV_PIX_FMT_RGBA, v->width, v->height, AV_PIX_FMT_YUV420P,
				SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, NULL, NULL, NULL);
	v->frame = av_frame_alloc();
	v->pkt = av_packet_alloc();
	if (!v->sws || !v->frame || !v->pkt)
		return AVERROR(ENOMEM);
	const int *bt709 = sws_getCoefficients(SWS_CS_ITU709);
	sws_setColorspaceDetails(v->sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
	v->frame->format = AV_PIX_FMT_YUV420P;
	v->frame->width = v->width;
	v->frame->height = v->height;
	return av_frame_get_buffer(v->frame, 0);
}

/* The container on the temporary file, its one stream, its header. */
static int start_container(video_writer *v, const video_kind *k, AVRational rate, const char *path, skp_error *err)
{
	int e = avformat_alloc_output_context2(&v->oc, NULL, k->muxer, NULL);
	if (e < 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: no %s muxer in this libavformat: %s", path, k->muxer, why(e));
	const int io_size = 1 << 16;
	uint8_t *buf = av_malloc(io_size);
	v->oc->pb = buf ? avio_alloc_context(buf, io_size, 1, v, NULL, io_write, io_seek) : NULL;
	if (!v->oc->pb) {
		av_free(buf);
		return skp_fail(err, SKP_ERR_IO, 0, "%s: out of memory", path);
	}
	v->oc->flags |= AVFMT_FLAG_CUSTOM_IO;
	v->c = open_encoder(k, v->width, v->height, rate, (v->oc->oformat->flags & AVFMT_GLOBALHEADER) != 0, &e);
	if (!v->c)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: no %s encoder opens in this libavcodec (Debian: libavcodec59 "
				"or later with %s): %s", path, k->what, k->encoders[0], why(e));
	v->st = avformat_new_stream(v->oc, NULL);
	if (!v->st || (e = avcodec_parameters_from_context(v->st->codecpar, v->c)) < 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: cannot add the video stream", path);
	v->st->time_base = v->c->time_base;
	v->st->avg_frame_rate = rate;
	if ((e = avformat_write_header(v->oc, NULL)) < 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: cannot write the %s header: %s", path, k->muxer,
				v->io_errno ? strerror(v->io_errno) : why(e));
	return SKP_OK;
}

video_writer *video_writer_open(const char *path, int width, int height, int rate_num, int rate_den,
				skp_error *err)
{
	const video_kind *k = path ? kind_of(path) : NULL;
	if (!k) {
		skp_fail(err, SKP_ERR_RANGE, 0, "%s: a video is NAME.mp4 (H.264) or NAME.webm (VP9)", path ? path : "");
		return NULL;
	}
	if (width < 2 || height < 2 || width % 2 || height % 2 || rate_num < 1 || rate_den < 1) {
		skp_fail(err, SKP_ERR_RANGE, 0, "%s: %s in yuv420p needs an even width and height, not %dx%d "
			 "(--size 960x540, say)", path, k->what, width, height);
		return NULL;
	}
	video_writer *v = calloc(1, sizeof *v);
	if (!v) {
		skp_fail(err, SKP_ERR_IO, 0, "%s: out of memory", path);
		return NULL;
	}
	v->width = width;
	v->height = height;
	v->af.fd = -1;
	snprintf(v->path, sizeof v->path, "%s", path);
	av_log_set_callback(keep_av_errors);
	av_said[0] = '\0';
	int e = atomic_file_open(&v->af, path);
	if (e < 0) {
		skp_fail(err, SKP_ERR_IO, 0, "%s: cannot create: %s", path, strerror(-e));
		v->af.fd = -1;
		free_all(v);
		return NULL;
	}
	AVRational rate = { rate_num, rate_den };
	if (start_container(v, k, rate, path, err) != SKP_OK) {
		video_writer_abort(v);
		return NULL;
	}
	if ((e = start_conversion(v)) < 0) {
		skp_fail(err, SKP_ERR_IO, 0, "%s: cannot convert RGBA to yuv420p: %s", path, why(e));
		video_writer_abort(v);
		return NULL;
	}
	return v;
}

/* Every packet the encoder has ready into the container; each frame lasts
 * one tick of the frame rate (the last one too: that is the duration). */
static int drain(video_writer *v, skp_error *err)
{
	int e;
	while ((e = avcodec_receive_packet(v->c, v->pkt)) == 0) {
		if (v->pkt->duration <= 0)
			v->pkt->duration = 1;
		av_packet_rescale_ts(v->pkt, v->c->time_base, v->st->time_base);
		v->pkt->stream_index = v->st->index;
		if ((e = av_interleaved_write_frame(v->oc, v->pkt)) < 0)
			return skp_fail(err, SKP_ERR_IO, 0, "%s: cannot write: %s", v->path,
					v->io_errno ? strerror(v->io_errno) : why(e));
	}
	if (e != AVERROR(EAGAIN) && e != AVERROR_EOF)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: the %s encoder failed: %s", v->path, v->c->codec->name,
				why(e));
	return SKP_OK;
}

int video_writer_add_rgba(video_writer *v, const uint8_t *rgba, int bottom_up, skp_error *err)
{
	int stride = v->width * 4;
	const uint8_t *src[4] = { bottom_up ? rgba + (size_t)stride * (size_t)(v->height - 1) : rgba, NULL, NULL, NULL };
	int strides[4] = { bottom_up ? -stride : stride, 0, 0, 0 };
	av_said[0] = '\0'; /* what libav says now is about this frame */
	int e = av_frame_make_writable(v->frame);
	if (e < 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: %s", v->path, why(e));
	sws_scale(v->sws, src, strides, 0, v->height, v->frame->data, v->frame->linesize);
	v->frame->pts = v->frames;
	if ((e = avcodec_send_frame(v->c, v->frame)) < 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s: the %s encoder failed: %s", v->path, v->c->codec->name,
				why(e));
	v->frames++;
	return drain(v, err);
}

const char *video_writer_encoder(const video_writer *v)
{
	return v->c->codec->name;
}

const char *video_writer_codec(const video_writer *v)
{
	return avcodec_get_name(v->c->codec_id);
}

long video_writer_frames(const video_writer *v)
{
	return v->frames;
}

int video_writer_close(video_writer *v, skp_error *err)
{
	av_said[0] = '\0';
	int e = avcodec_send_frame(v->c, NULL);
	if (e < 0) {
		skp_fail(err, SKP_ERR_IO, 0, "%s: the %s encoder failed: %s", v->path, v->c->codec->name, why(e));
		video_writer_abort(v);
		return SKP_ERR_IO;
	}
	if (drain(v, err) != SKP_OK) {
		video_writer_abort(v);
		return SKP_ERR_IO;
	}
	if ((e = av_write_trailer(v->oc)) < 0 || (avio_flush(v->oc->pb), v->io_errno)) {
		skp_fail(err, SKP_ERR_IO, 0, "%s: cannot write: %s", v->path,
			 v->io_errno ? strerror(v->io_errno) : why(e));
		video_writer_abort(v);
		return SKP_ERR_IO;
	}
	if ((e = atomic_file_commit(&v->af)) < 0) {
		skp_fail(err, SKP_ERR_IO, 0, "%s: cannot write: %s", v->path, strerror(-e));
		video_writer_abort(v);
		return SKP_ERR_IO;
	}
	free_all(v);
	return SKP_OK;
}

void video_writer_abort(video_writer *v)
{
	if (!v)
		return;
	if (v->af.fd >= 0)
		atomic_file_abort(&v->af);
	free_all(v);
}
