/* ASF/AMC out. Each bone keeps its direction, length, axis and channels; a
 * bone whose head is off its parent's tip (a BVH joint branching from the
 * middle of its parent's segment, skel_bone.offset) gets tx ty tz, written
 * in every frame as that offset plus any translation of its own, because
 * an ASF bone always starts at its parent's tip. */
#include <math.h>
#include <string.h>

#include "convert.h"
#include "motion_file.h"

#define DEG_PER_RAD 57.295779513082320876798

static const char *const channel_name[SKEL_MAX_CHANNELS] = { "rx", "ry", "rz", "tx", "ty", "tz", "l" };

/* ASF calls its root "root", whatever a BVH called it. */
static const char *bone_name(const skel *s, int b)
{
	return b == 0 ? "root" : s->bone[b].name;
}

static int has_offset(const skel_bone *b)
{
	return b->offset.x != 0.0f || b->offset.y != 0.0f || b->offset.z != 0.0f;
}

static int has_channel(const skel_bone *b, int c)
{
	return memchr(b->channel, c, b->channel_count) != NULL;
}

/* A bone with an offset gets the translations it lacks, first. */
static int out_channels(const skel_bone *b, uint8_t *ch)
{
	int n = 0;
	if (has_offset(b))
		for (int c = SKEL_TX; c <= SKEL_TZ; c++)
			if (!has_channel(b, c))
				ch[n++] = (uint8_t)c;
	memcpy(ch + n, b->channel, b->channel_count);
	return n + b->channel_count;
}

static void write_channels(FILE *f, const char *key, const skel_bone *b, int upper)
{
	uint8_t ch[SKEL_MAX_CHANNELS + 3];
	int n = out_channels(b, ch);
	if (!n)
		return;
	fprintf(f, "   %s", key);
	for (int i = 0; i < n; i++) {
		fputc(' ', f);
		for (const char *c = channel_name[ch[i]]; *c; c++)
			fputc(upper ? *c - 'a' + 'A' : *c, f);
	}
	fputc('\n', f);
}

static void write_axis(FILE *f, const char *key, const skel *s, const skel_bone *b, int with_order)
{
	vec3 a = b->axis_angle;
	double k = s->angle_in_degrees ? 1.0 : DEG_PER_RAD;
	fprintf(f, "   %s %.9g %.9g %.9g", key, a.x * k, a.y * k, a.z * k);
	if (with_order)
		fprintf(f, " %c%c%c", 'X' + b->axis_order[0], 'X' + b->axis_order[1], 'X' + b->axis_order[2]);
	fputc('\n', f);
}

void convert_write_asf(FILE *f, const skel *s)
{
	const skel_bone *r = &s->bone[0];
	fprintf(f, "# Acclaim skeleton written by skintool convert\n:version 1.10\n:name %s\n", s->name);
	/* lengths were divided by the source's :units length as they were read */
	fprintf(f, ":units\n  mass %.9g\n  length 1.0\n  angle deg\n", (double)s->mass_scale);
	fprintf(f, ":root\n");
	write_channels(f, "order", r, 1);
	fprintf(f, "   axis %c%c%c\n", 'X' + r->axis_order[0], 'X' + r->axis_order[1], 'X' + r->axis_order[2]);
	fprintf(f, "   position %.9g %.9g %.9g\n", (double)s->root_position.x, (double)s->root_position.y,
		(double)s->root_position.z);
	write_axis(f, "orientation", s, r, 0);
	fprintf(f, ":bonedata\n");
	for (int b = 1; b < s->count; b++) {
		const skel_bone *bone = &s->bone[b];
		fprintf(f, "  begin\n   id %d\n   name %s\n", b, bone->name);
		fprintf(f, "   direction %.9g %.9g %.9g\n", (double)bone->direction.x, (double)bone->direction.y,
			(double)bone->direction.z);
		fprintf(f, "   length %.9g\n", (double)bone->length);
		write_axis(f, "axis", s, bone, 1);
		write_channels(f, "dof", bone, 0);
		fprintf(f, "  end\n");
	}
	fprintf(f, ":hierarchy\n  begin\n");
	for (int p = 0; p < s->count; p++) {
		int any = 0;
		for (int c = 1; c < s->count; c++) {
			if (s->bone[c].parent != p)
				continue;
			if (!any++)
				fprintf(f, "    %s", bone_name(s, p));
			fprintf(f, " %s", s->bone[c].name);
		}
		if (any)
			fputc('\n', f);
	}
	fprintf(f, "  end\n");
}

static void write_bone_values(FILE *f, const skel_bone *b, const char *name, const float *v)
{
	uint8_t ch[SKEL_MAX_CHANNELS + 3];
	int n = out_channels(b, ch), added = n - b->channel_count;
	fprintf(f, "%s", name);
	for (int i = 0; i < n; i++) {
		int c = ch[i];
		double x = i < added ? 0.0 : v[i - added];
		if (c >= SKEL_TX && c <= SKEL_TZ) {
			/* the offset is world-space at rest; ASF translates in the axis frame */
			vec3 o = quat_rotate(quat_conj(b->axis_rot), b->offset);
			x += c == SKEL_TX ? o.x : c == SKEL_TY ? o.y : o.z;
		} else if (c <= SKEL_RZ) {
			x *= DEG_PER_RAD;
		}
		fprintf(f, " %.9g", x);
	}
	fputc('\n', f);
}

long convert_write_amc(FILE *f, const skel *s, motion_file *m)
{
	static amc_frame fr;
	fprintf(f, "# written by skintool convert\n:FULLY-SPECIFIED\n:DEGREES\n");
	long n = 0;
	int r;
	while ((r = motion_file_next(m, &fr)) > 0) {
		fprintf(f, "%ld\n", ++n);
		for (int b = 0; b < s->count; b++) {
			uint8_t ch[SKEL_MAX_CHANNELS + 3];
			if (out_channels(&s->bone[b], ch) > 0)
				write_bone_values(f, &s->bone[b], bone_name(s, b), fr.value + s->bone[b].dof_offset);
		}
	}
	return r < 0 ? -1 : n;
}
