#include "rig_jpeg.h"

#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

#include "rig_limits.h"

#define JPEG_DAMAGED "is truncated or damaged"

int rig_jpeg_is(const void *bytes, size_t n)
{
	static const uint8_t start[3] = { 0xFF, 0xD8, 0xFF };   /* SOI, then the first marker */
	return n >= sizeof start && !memcmp(bytes, start, sizeof start);
}

/* libjpeg's error manager, with where its errors jump to: the library's
 * own exits the process. */
typedef struct jpeg_failure {
	struct jpeg_error_mgr mgr;
	jmp_buf jump;
} jpeg_failure;

static void jump_back(j_common_ptr cinfo)
{
	longjmp(((jpeg_failure *)cinfo->err)->jump, 1);
}

/* Messages are the caller's to give: the importer says one sentence per
 * texture. Warnings are still counted (num_warnings). */
static void say_nothing(j_common_ptr cinfo)
{
	(void)cinfo;
}

/* Every row of the image begun in cinfo into out->rgba, RGBA8. */
static void read_rows(struct jpeg_decompress_struct *cinfo, rig_jpeg_pixels *out)
{
	/* one RGB row in libjpeg's pool: freed with cinfo, after a jump too */
	JSAMPARRAY row = (*cinfo->mem->alloc_sarray)((j_common_ptr)cinfo, JPOOL_IMAGE, 3 * cinfo->output_width, 1);
	size_t w = cinfo->output_width;
	while (cinfo->output_scanline < cinfo->output_height) {
		uint8_t *to = out->rgba + 4 * w * cinfo->output_scanline;
		if (jpeg_read_scanlines(cinfo, row, 1) != 1)
			break;   /* only a suspending source returns none (ours never do);
				  * jpeg_finish_decompress calls the rows missing an error */
		for (size_t x = 0; x < w; x++) {
			memcpy(to + 4 * x, row[0] + 3 * x, 3);
			to[4 * x + 3] = 255;
		}
	}
}

/* The decode proper, from the source set in cinfo; a libjpeg error jumps
 * back to the setjmp below. Only out (the caller's) and cinfo's own
 * memory change after it, so nothing here is left indeterminate by the
 * jump. */
static int decode(struct jpeg_decompress_struct *cinfo, jpeg_failure *fail, rig_jpeg_pixels *out, const char **why)
{
	if (setjmp(fail->jump)) {
		free(out->rgba);
		out->rgba = NULL;
		*why = JPEG_DAMAGED;
		return 0;
	}
	jpeg_read_header(cinfo, TRUE);
	if (!rig_limits_texture_fits(cinfo->image_width, cinfo->image_height, why))
		return 0;
	if (cinfo->jpeg_color_space == JCS_CMYK || cinfo->jpeg_color_space == JCS_YCCK) {
		*why = "is a CMYK JPEG (RGB and grey ones are read)";
		return 0;
	}
	cinfo->out_color_space = JCS_RGB;   /* grey ones too */
	jpeg_start_decompress(cinfo);
	out->rgba = malloc(4 * (size_t)cinfo->output_width * cinfo->output_height);
	if (!out->rgba) {
		*why = JPEG_DAMAGED;   /* as a PNG too large for the memory left says */
		return 0;
	}
	read_rows(cinfo, out);
	jpeg_finish_decompress(cinfo);
	if (fail->mgr.num_warnings) {
		/* "Premature end of JPEG file", corrupt data skipped: the pixels
		 * past it are libjpeg's grey or garbage */
		free(out->rgba);
		out->rgba = NULL;
		*why = JPEG_DAMAGED;
		return 0;
	}
	out->w = (int)cinfo->output_width;
	out->h = (int)cinfo->output_height;
	return 1;
}

int rig_jpeg_read(const void *bytes, size_t n, FILE *f, rig_jpeg_pixels *out, const char **why)
{
	struct jpeg_decompress_struct cinfo;
	jpeg_failure fail;
	out->rgba = NULL;
	out->w = out->h = 0;
	cinfo.err = jpeg_std_error(&fail.mgr);
	fail.mgr.error_exit = jump_back;
	fail.mgr.output_message = say_nothing;
	/* jpeg_create_decompress itself may fail (no memory) and jump */
	if (setjmp(fail.jump)) {
		jpeg_destroy_decompress(&cinfo);
		*why = JPEG_DAMAGED;
		return 0;
	}
	jpeg_create_decompress(&cinfo);
	if (bytes)
		jpeg_mem_src(&cinfo, (const unsigned char *)bytes, (unsigned long)n);
	else
		jpeg_stdio_src(&cinfo, f);
	int ok = decode(&cinfo, &fail, out, why);
	jpeg_destroy_decompress(&cinfo);
	return ok;
}
