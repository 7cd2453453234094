/* What skinplay checks before it plays an image, in one place so that
 * skintool info and skintool pack run the very same checks: the header and
 * directory (at open), the skeleton and the bound body as loaded and as
 * they mean (app/image/image_accept.h), and each clip (its quantisation,
 * its meaning, its frame count) - a clip that fails is skipped, not the
 * image. */
#include <string.h>

#include "show_source.h"
#include "fk.h"
#include "image_accept.h"

int image_accept_body(skp_image *im, bound_body *body, skp_error *err)
{
	static float values[SKP_MAX_DOF];
	long number;
	im->texture = &body->texture;
	if (skp_image_load_skel(im, &body->skel, err) != SKP_OK || skp_accept_skel(&body->skel, err) != SKP_OK ||
	    skp_image_load_bind(im, &body->skel, &body->mesh, &body->weights, values, &number, err) != SKP_OK)
		return -1;
	body->texture_skipped = im->texture_skipped;
	/* values are all 0 for the rest pose; a derived bind pose has number -1 */
	fk_pose(&body->skel, values, &body->pose);
	if (skp_accept_body(&body->skel, &body->pose, &body->mesh, err) != SKP_OK)
		return -1;
	memcpy(body->pose_value, values, sizeof body->pose_value);
	body->pose_frame = number;
	body->arms_raised = 0;
	body->fitted = 0;
	body->automatic = 0;
	return 0;
}

int image_accept_clip(skp_image *im, const skel *s, int clip, skp_error *err)
{
	static float qmin[SKP_MAX_DOF], qstep[SKP_MAX_DOF];
	skp_error_clear(err);
	if (skp_image_load_quant(im, clip, qmin, qstep, err) != SKP_OK ||
	    skp_accept_clip(s, &im->clip[clip], qmin, qstep, err) != SKP_OK)
		return -1;
	return skp_image_check_frames(im, clip, err) == SKP_OK ? 0 : -1;
}

int show_accept_body(show_image *img, bound_body *body, skp_error *err)
{
	return image_accept_body(&img->im, body, err);
}

int show_accept_clip(show_image *img, const skel *s, int clip, skp_error *err)
{
	return image_accept_clip(&img->im, s, clip, err);
}
