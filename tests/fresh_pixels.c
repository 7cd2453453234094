/* The fresh-machine check's look at `make run`'s pictures: how many pixels
 * of a PNG are the body's skin (red over green over blue, as the renderer
 * lights its skin colour; the floor, grid, shadow and background are blue
 * grey, the HUD's text as red as it is green). Built and run there by
 * tests/fresh_machine.sh:
 *
 *   fresh_pixels FILE.png MIN_PERCENT
 *
 * prints the count and exits 0 when the skin covers at least MIN_PERCENT
 * of the picture, 1 when less, 2 when the file cannot be read. */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int is_skin(const unsigned char *p)
{
	return p[0] > 40 && p[0] > p[1] + 8 && p[1] > p[2] && p[0] > p[2] + 15;
}

int main(int argc, char **argv)
{
	if (argc != 3) {
		fprintf(stderr, "usage: fresh_pixels FILE.png MIN_PERCENT\n");
		return 2;
	}
	png_image img;
	memset(&img, 0, sizeof img);
	img.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&img, argv[1])) {
		fprintf(stderr, "fresh_pixels: %s: %s\n", argv[1], img.message);
		return 2;
	}
	img.format = PNG_FORMAT_RGB;
	unsigned char *buf = malloc(PNG_IMAGE_SIZE(img));
	if (!buf || !png_image_finish_read(&img, NULL, buf, 0, NULL)) {
		fprintf(stderr, "fresh_pixels: %s: %s\n", argv[1], buf ? img.message : "out of memory");
		free(buf);
		return 2;
	}
	size_t n = (size_t)img.width * img.height, skin = 0;
	for (size_t i = 0; i < n; i++)
		skin += is_skin(buf + 3 * i);
	free(buf);
	double percent = 100.0 * (double)skin / (double)n, min = atof(argv[2]);
	printf("%s: %zu of %zu pixels skin-coloured (%.2f%%, at least %.2f%% wanted)\n", argv[1], skin, n, percent, min);
	return percent >= min ? 0 : 1;
}
