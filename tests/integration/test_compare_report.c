/* `skintool compare` through the real command line, on CMU clips with the
 * generated body:
 *   - metrics.csv's first five columns are exactly what `skintool metrics`
 *     prints for the same inputs (the body written by `skintool mannequin`);
 *     the region columns lie within the global range;
 *   - LBS's worst frame loses more volume than DQBS's, DQBS keeps within
 *     1% on every frame (the acceptance), and the page's verdicts
 *     say what metrics.csv shows;
 *   - "where the volume goes": the share of the joint listed first, checked
 *     by running `skintool metrics` on that frame written out again with
 *     the joint's rotations zeroed (the generated body's bind pose);
 *   - the synthetic scenes in the page match `skintool metrics --scene`
 *     and the analytic |cos(a/2)|;
 *   - the renders are real pictures whose LBS and DQBS halves differ, on
 *     the page: the twist scene's close-up shows LBS's candy wrapper and
 *     DQBS's whole cylinder, each worst frame's close-up rings where the
 *     two differ, the difference view colours the body;
 *   - the page renders in headless Chromium (skipped without it).
 * make test runs three short clips; SKP_COMPARE_ALL=1 runs every clip in
 * mocap/cmu. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "png_writer.h"
#include "test_paths.h"

#define METRICS_HEADER "frame,algo,volume_ratio,min_radius_ratio,max_radius_ratio"
#define REGION_HEADER ",elbows_min,elbows_max,knees_min,knees_max,shoulders_min,shoulders_max," \
	"hips_min,hips_max,wrists_min,wrists_max"

static char workdir[] = "/tmp/skp_compare_XXXXXX";
static char last_report[1024];   /* a report directory for the picture tests */

static double now_s(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* Runs cmd (stdout to out when not NULL); returns the exit status. */
static int sh(const char *cmd, const char *out)
{
	char full[8192];
	snprintf(full, sizeof full, "%s >%s 2>%s/stderr.txt", cmd, out ? out : "/dev/null", workdir);
	int st = system(full);
	assert_true(WIFEXITED(st));
	return WEXITSTATUS(st);
}

static char *slurp(const char *path)
{
	char *text = test_read_file(path, NULL);
	if (!text)
		fail_msg("cannot read %s", path);
	return text;
}

/* Cuts each line after its fifth field. */
static void first_five_columns(char *text)
{
	char *w = text;
	for (char *r = text; *r;) {
		int commas = 0;
		while (*r && *r != '\n') {
			if (*r == ',' && ++commas == 5) {
				while (*r && *r != '\n')
					r++;
				break;
			}
			*w++ = *r++;
		}
		if (*r == '\n')
			*w++ = *r++;
	}
	*w = '\0';
}

typedef struct clip_stats {
	long rows;
	double vol_min[3], vol_max[3];
} clip_stats;

static int algo_index(const char *name)
{
	return !strcmp(name, "lbs") ? 0 : !strcmp(name, "dqbs") ? 1 : !strcmp(name, "dqbs-fixed") ? 2 : -1;
}

/* Parses metrics.csv (header checked), checks each region's range lies in
 * the global one, and collects the volume extremes per algorithm. */
static void parse_report_csv(char *text, clip_stats *s)
{
	char *save, *line = strtok_r(text, "\n", &save);
	assert_non_null(line);
	assert_string_equal(line, METRICS_HEADER REGION_HEADER);
	for (int a = 0; a < 3; a++)
		s->vol_min[a] = INFINITY, s->vol_max[a] = -INFINITY;
	s->rows = 0;
	while ((line = strtok_r(NULL, "\n", &save))) {
		char algo[16];
		long frame;
		double vol, rmin, rmax;
		int used;
		if (sscanf(line, "%ld,%15[^,],%lf,%lf,%lf%n", &frame, algo, &vol, &rmin, &rmax, &used) != 5)
			fail_msg("bad row '%s'", line);
		int a = algo_index(algo);
		assert_true(a >= 0);
		s->vol_min[a] = fmin(s->vol_min[a], vol);
		s->vol_max[a] = fmax(s->vol_max[a], vol);
		const char *p = line + used;
		for (int k = 0; k < 10; k++) {
			assert_true(*p == ',');
			p++;
			if (*p == ',' || *p == '\0')
				continue; /* a region the skeleton lacks */
			char *end;
			double v = strtod(p, &end);
			assert_true(end != p);
			if (v < rmin - 1e-6 || v > rmax + 1e-6)
				fail_msg("region value %f outside %f..%f in '%s'", v, rmin, rmax, line);
			p = end;
		}
		assert_true(*p == '\0');
		s->rows++;
	}
}

/* The text of the element with this id, tags included, up to its end. */
static const char *element(const char *html, const char *id)
{
	char key[128];
	snprintf(key, sizeof key, "id=\"%s\"", id);
	const char *p = strstr(html, key);
	if (!p)
		fail_msg("the page has no element %s", id);
	return p;
}

static void check_verdicts(const char *html, const clip_stats *s, const char *clip)
{
	double dev = fmax(fabs(1 - s->vol_min[1]), fabs(s->vol_max[1] - 1));
	double loss_l = fmax(0, 1 - s->vol_min[0]), loss_d = fmax(0, 1 - s->vol_min[1]);
	int within = dev <= 0.01, loses_more = loss_l > loss_d;
	const char *v = element(html, "verdict-dqbs-volume");
	const char *b = strstr(v, "<b>");
	assert_non_null(b);
	if (strncmp(b + 3, within ? "yes<" : "no<", within ? 4 : 3) != 0)
		fail_msg("%s: DQBS deviation %.4f%%: the page's verdict disagrees", clip, 100 * dev);
	v = element(html, "verdict-lbs-loss");
	b = strstr(v, "<b>");
	assert_non_null(b);
	assert_true(strncmp(b + 3, loses_more ? "yes<" : "no<", loses_more ? 4 : 3) == 0);
	/* the paper's claim: LBS's worst frame loses more than DQBS's, and
	 * DQBS (on the generated body, volume-balanced) keeps within 1% */
	if (!loses_more)
		fail_msg("%s: LBS loses %.3f%%, DQBS %.3f%%", clip, 100 * loss_l, 100 * loss_d);
	if (!within)
		fail_msg("%s: DQBS deviates %.3f%% on its worst frame", clip, 100 * dev);
	print_message("%-10s DQBS volume %.4f..%.4f (within 1%%: %s), LBS %.4f..%.4f: LBS loses %.2f%%, DQBS %.2f%%\n",
		      clip, s->vol_min[1], s->vol_max[1], within ? "yes" : "NO", s->vol_min[0], s->vol_max[0],
		      100 * loss_l, 100 * loss_d);
	/* skin passing through itself at DQBS's worst frame: counted twice by
	 * the signed volume, so the space taken up is the deviation minus it */
	const char *o = strstr(html, "id=\"dqbs-overlap\">");
	if (o) {
		double dev_signed = fabs(1 - s->vol_min[1]) >= fabs(s->vol_max[1] - 1) ? 100 * (s->vol_min[1] - 1)
										      : 100 * (s->vol_max[1] - 1);
		double pct = strtod(o + strlen("id=\"dqbs-overlap\">"), NULL);
		const char *u = strstr(o, "takes up is ");
		assert_non_null(u);
		double space = strtod(u + strlen("takes up is "), NULL);
		if (!(pct > 0 && fabs(space - (dev_signed - pct)) <= 0.011))
			fail_msg("%s: overlap %.2f%%, space %.2f%% for a DQBS deviation of %.2f%%", clip, pct, space,
				 dev_signed);
		print_message("%-10s at DQBS's worst frame (%+.2f%%) %.2f%% is skin passing through itself\n", clip,
			      dev_signed, pct);
	}
}

static int is_frame_number(const char *line)
{
	return line[0] >= '0' && line[0] <= '9' && strspn(line, "0123456789 \t") == strlen(line);
}

static int is_bone_line(const char *line, const char *bone)
{
	size_t n = strlen(bone);
	return strncmp(line, bone, n) == 0 && (line[n] == ' ' || line[n] == '\t');
}

/* The AMC's lines before its first frame, and frame `frame`'s lines after
 * its number, each ending in a newline. */
static void read_frame_text(const char *amc, long frame, char *header, size_t hsize, char *block, size_t bsize)
{
	char *text = slurp(amc), *save;
	int before = 1, in = 0;
	header[0] = block[0] = '\0';
	for (char *line = strtok_r(text, "\r\n", &save); line; line = strtok_r(NULL, "\r\n", &save)) {
		if (is_frame_number(line)) {
			before = 0;
			in = atol(line) == frame;
			continue;
		}
		char *dst = before ? header : in ? block : NULL;
		size_t size = before ? hsize : bsize;
		if (dst && strlen(dst) + strlen(line) + 2 < size)
			strcat(strcat(dst, line), "\n");
	}
	free(text);
	assert_true(block[0] != '\0');
}

/* Writes frame `frame` of amc to out twice, as frames 1 and 2, the second
 * with every value on bone's line zeroed. */
static void write_straightened(const char *amc, long frame, const char *bone, const char *out)
{
	char header[4096], block[8192], *save;
	read_frame_text(amc, frame, header, sizeof header, block, sizeof block);
	FILE *f = fopen(out, "w");
	assert_non_null(f);
	fprintf(f, "%s1\n%s2\n", header, block);
	for (char *line = strtok_r(block, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
		if (!is_bone_line(line, bone)) {
			fprintf(f, "%s\n", line);
			continue;
		}
		fputs(bone, f);
		for (char *t = line + strlen(bone); (t = strpbrk(t, " \t")); t += strspn(t, " \t"))
			if (t[strspn(t, " \t")])
				fputs(" 0", f);
		fputc('\n', f);
	}
	assert_int_equal(fclose(f), 0);
}

/* The values on bone's line in frame `frame` of amc; their count, -1 when
 * the frame has no such line. */
static int amc_values(const char *amc, long frame, const char *bone, double *v, int max)
{
	char header[4096], block[8192], *save;
	read_frame_text(amc, frame, header, sizeof header, block, sizeof block);
	for (char *line = strtok_r(block, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
		if (!is_bone_line(line, bone))
			continue;
		int n = 0;
		for (char *t = line + strlen(bone), *e; n < max && (v[n] = strtod(t, &e), e != t); t = e)
			n++;
		return n;
	}
	return -1;
}

/* Limits of bone's k-th dof as the ASF writes them. */
static int asf_limits(const char *asf_text, const char *bone, int k, double *lo, double *hi)
{
	char key[96];
	snprintf(key, sizeof key, "name %s", bone);
	const char *p = asf_text;
	while ((p = strstr(p, key)) && p[strlen(key)] != ' ' && p[strlen(key)] != '\r' && p[strlen(key)] != '\n')
		p++;
	const char *l = p ? strstr(p, "limits") : NULL, *end = p ? strstr(p, "\n  end") : NULL;
	if (!l || (end && l > end))
		return -1;
	for (int i = 0; i <= k; i++) {
		if (!(l = strchr(l, '(')) || sscanf(l, "(%lf %lf)", lo, hi) != 2)
			return -1;
		l++;
	}
	return 0;
}

static double past_limits(double v, double lo, double hi)
{
	double best = INFINITY;
	for (int k = -3; k <= 3; k++) {
		double w = v + 360.0 * k;
		best = fmin(best, w < lo ? lo - w : w > hi ? w - hi : 0.0);
	}
	return best;
}

/* Every row of the DQBS joint table: the rotations as the AMC has them,
 * and the ASF-limit column as the ASF's limits give it (modulo 360). */
static void check_joint_limits(const char *html, const char *asf, const char *amc, const char *clip)
{
	const char *t = strstr(html, "id=\"joints-dqbs\" data-frame=\"");
	if (!t)
		return;
	long frame = atol(t + strlen("id=\"joints-dqbs\" data-frame=\""));
	const char *end = strstr(t, "</table>");
	char *asf_text = slurp(asf);
	int rows = 0, past_rows = 0;
	for (const char *row = strstr(t, "<tr><td><code>"); row && row < end; row = strstr(row + 1, "<tr><td><code>")) {
		char bone[64], rot[256], limit[256];
		assert_int_equal(sscanf(row, "<tr><td><code>%63[^<]</code></td><td>%255[^<]</td><td%255[^<]", bone, rot,
					limit), 3);
		double want[8];
		int n = amc_values(amc, frame, bone, want, 8), k = 0;
		assert_true(n > 0);
		double worst = 0;
		int worst_k = -1;
		char axis[8][4];
		for (const char *r = rot; k < n; k++) {
			double deg;
			int used;
			assert_int_equal(sscanf(r, " %3[rxyz] %lf%n", axis[k], &deg, &used), 2);
			if (fabs(deg - want[k]) > 0.051)
				fail_msg("%s frame %ld: %s %s %.1f on the page, %.4f in the AMC", clip, frame, bone, axis[k],
					 deg, want[k]);
			double lo, hi;
			if (asf_limits(asf_text, bone, k, &lo, &hi) == 0 && past_limits(want[k], lo, hi) > worst)
				worst = past_limits(want[k], lo, hi), worst_k = k;
			r += used;
			if (*r == ',')
				r++;
		}
		const char *past = strstr(limit, "past");
		if ((worst_k >= 0) != (past != NULL))
			fail_msg("%s frame %ld: %s is %.1f past its limits, the page says '%s'", clip, frame, bone, worst, limit);
		if (past) {
			char shown_axis[4];
			double shown;
			assert_int_equal(sscanf(strchr(limit, '>') + 1, "%3s %lf", shown_axis, &shown), 2);
			if (strcmp(shown_axis, axis[worst_k]) != 0 || fabs(shown - worst) > 0.051)
				fail_msg("%s: %s %s %.1f past on the page, %s %.3f by the ASF", clip, bone, shown_axis, shown,
					 axis[worst_k], worst);
			past_rows++;
		}
		rows++;
	}
	free(asf_text);
	assert_true(rows > 0);
	print_message("%-10s DQBS frame %ld: %d joints listed, %d past their ASF limits\n", clip, frame, rows,
		      past_rows);
}

/* The DQBS table's first joint: its share as the page gives it against
 * skintool metrics on the frame with and without that joint's bend. */
static void check_joint_share(const char *html, const char *asf, const char *amc, const char *body,
			      const char *clip)
{
	const char *t = strstr(html, "id=\"joints-dqbs\" data-frame=\"");
	if (!t)
		return; /* no joint moves the volume by 0.05% */
	long frame = atol(t + strlen("id=\"joints-dqbs\" data-frame=\""));
	const char *row = strstr(t, "<tr><td><code>");
	assert_non_null(row);
	row += strlen("<tr><td><code>");
	char bone[64];
	assert_int_equal(sscanf(row, "%63[^<]", bone), 1);
	const char *end = strstr(row, "</tr>"), *cell = end;
	while (cell > row && strncmp(cell, "<td>", 4) != 0)
		cell--;
	double page = strtod(cell + 4, NULL);
	char path[1200], csv[1200], cmd[4096];
	snprintf(path, sizeof path, "%s/straightened.amc", workdir);
	snprintf(csv, sizeof csv, "%s/straightened.csv", workdir);
	write_straightened(amc, frame, bone, path);
	snprintf(cmd, sizeof cmd, "%s metrics %s %s %s --algo dqbs", test_tool_path("skintool"), asf, path, body);
	assert_int_equal(sh(cmd, csv), 0);
	char *out = slurp(csv);
	double v[2];
	const char *l1 = strchr(out, '\n'), *l2 = l1 ? strchr(l1 + 1, '\n') : NULL;
	assert_non_null(l2);
	assert_int_equal(sscanf(l1 + 1, "1,dqbs,%lf", &v[0]), 1);
	assert_int_equal(sscanf(l2 + 1, "2,dqbs,%lf", &v[1]), 1);
	free(out);
	double share = 100 * (v[0] - v[1]);
	if (!(fabs(share - page) <= 0.0051))
		fail_msg("%s frame %ld: straightening %s changes DQBS's volume by %.3f%%, the page says %.2f%%",
			 clip, frame, bone, share, page);
	print_message("%-10s DQBS frame %ld: %s's bend %+.2f%% of the volume (page %+.2f%%)\n", clip, frame,
		      bone, share, page);
}

/* One clip: compare, then metrics on the same body, then the checks. */
static void check_clip(const char *asf, const char *amc, const char *clip)
{
	char dir[1024], body[1024], cmd[4096], path[1200], metrics[1024];
	snprintf(dir, sizeof dir, "%s/%s", workdir, clip);
	snprintf(body, sizeof body, "%s/%s.obj", workdir, clip);
	snprintf(metrics, sizeof metrics, "%s/%s_metrics.csv", workdir, clip);
	double t0 = now_s();
	snprintf(cmd, sizeof cmd, "%s compare %s %s -o %s", test_tool_path("skintool"), asf, amc, dir);
	assert_int_equal(sh(cmd, NULL), 0);
	double t1 = now_s();
	snprintf(cmd, sizeof cmd, "%s mannequin %s -o %s", test_tool_path("skintool"), asf, body);
	assert_int_equal(sh(cmd, NULL), 0);
	snprintf(cmd, sizeof cmd, "%s metrics %s %s %s", test_tool_path("skintool"), asf, amc, body);
	assert_int_equal(sh(cmd, metrics), 0);
	double t2 = now_s();

	snprintf(path, sizeof path, "%s/metrics.csv", dir);
	char *csv = slurp(path), *ref = slurp(metrics);
	char *five = slurp(path);
	first_five_columns(five);
	if (strcmp(five, ref) != 0)
		fail_msg("%s: metrics.csv's first columns differ from skintool metrics", clip);
	free(five);
	free(ref);
	clip_stats s;
	parse_report_csv(csv, &s);
	free(csv);
	assert_true(s.rows > 0 && s.rows % 3 == 0);

	snprintf(path, sizeof path, "%s/index.html", dir);
	char *html = slurp(path);
	check_verdicts(html, &s, clip);
	check_joint_share(html, asf, amc, body, clip);
	check_joint_limits(html, asf, amc, clip);
	free(html);
	print_message("%-10s %ld frames: compare %.2f s, metrics %.2f s\n", clip, s.rows / 3, t1 - t0, t2 - t1);
	snprintf(last_report, sizeof last_report, "%s", dir);
}

static void test_short_clips(void **state)
{
	(void)state;
	static const char *const clips[][2] = { { "09", "09_06" }, { "02", "02_01" }, { "backflip", "backflip" } };
	if (!test_data_path("mocap/cmu/09.asf"))
		skip();
	for (size_t i = 0; i < sizeof clips / sizeof clips[0]; i++) {
		char rel[256], asf[1024], amc[1024];
		snprintf(rel, sizeof rel, "mocap/cmu/%s.asf", clips[i][0]);
		snprintf(asf, sizeof asf, "%s", test_data_path(rel));
		snprintf(rel, sizeof rel, "mocap/cmu/%s.amc", clips[i][1]);
		snprintf(amc, sizeof amc, "%s", test_data_path(rel));
		check_clip(asf, amc, clips[i][1]);
	}
}

/* SKP_COMPARE_ALL=1: every AMC in mocap/cmu with its skeleton (NN.asf for
 * NN_MM.amc, else the same name). */
static void test_every_clip(void **state)
{
	(void)state;
	const char *root = test_data_path("mocap/cmu");
	if (!root || !getenv("SKP_COMPARE_ALL"))
		skip();
	char dir_path[1024];
	snprintf(dir_path, sizeof dir_path, "%s", root);
	DIR *d = opendir(dir_path);
	assert_non_null(d);
	struct dirent *e;
	int clips = 0;
	while ((e = readdir(d))) {
		size_t n = strlen(e->d_name);
		if (n < 5 || strcmp(e->d_name + n - 4, ".amc") != 0)
			continue;
		char name[256], asf[1300], amc[1300];
		snprintf(name, sizeof name, "%.*s", (int)(n - 4), e->d_name);
		snprintf(amc, sizeof amc, "%s/%s", dir_path, e->d_name);
		char *us = strchr(name, '_');
		snprintf(asf, sizeof asf, "%s/%.*s.asf", dir_path, us ? (int)(us - name) : (int)strlen(name), name);
		check_clip(asf, amc, name);
		clips++;
	}
	closedir(d);
	assert_true(clips > 0);
}

/* The page's twist and bend tables against skintool metrics --scene. */
static void test_scene_tables(void **state)
{
	(void)state;
	if (!last_report[0])
		skip();
	char path[1200], cmd[2048], out[1200];
	snprintf(path, sizeof path, "%s/index.html", last_report);
	char *html = slurp(path);
	static const char *const kinds[2] = { "twist", "bend" };
	for (int k = 0; k < 2; k++)
		for (int angle = 45; angle <= 180; angle += 45) {
			snprintf(out, sizeof out, "%s/scene.csv", workdir);
			snprintf(cmd, sizeof cmd, "%s metrics --scene %s --angle %d", test_tool_path("skintool"),
				 kinds[k], angle);
			assert_int_equal(sh(cmd, out), 0);
			char *csv = slurp(out);
			double vol[3], rmin[3], rmax[3];
			char *line = strchr(csv, '\n');
			for (int a = 0; a < 3; a++) {
				long frame;
				char algo[16];
				assert_int_equal(sscanf(line + 1, "%ld,%15[^,],%lf,%lf,%lf", &frame, algo, &vol[a],
							&rmin[a], &rmax[a]), 5);
				line = strchr(line + 1, '\n');
			}
			free(csv);
			char row[512];
			if (k == 0)
				snprintf(row, sizeof row, "<tr><td>%d&deg;</td><td>%.6f</td><td>%.6f</td><td>1</td><td>%.6f</td>"
					 "<td>%.6f</td><td>%.6f</td><td>%.6f</td><td>%.6f</td></tr>", angle,
					 fabs(cos(angle * M_PI / 360)), rmin[0], rmin[1], rmin[2], vol[0], vol[1], vol[2]);
			else
				snprintf(row, sizeof row, "<tr><td>%d&deg;</td><td>%.6f</td><td>%.6f</td><td>%.6f</td><td>%.6f</td>"
					 "<td>%.6f</td><td>%.6f</td><td>%.6f</td><td>%.6f</td></tr>", angle, rmin[0],
					 rmin[1], rmin[2], rmax[0], rmax[1], vol[0], vol[1], vol[2]);
			if (!strstr(html, row))
				fail_msg("the page lacks the %s %d row %s", kinds[k], angle, row);
			if (k == 0) {
				assert_true(fabs(rmin[0] - fabs(cos(angle * M_PI / 360))) < 1e-3);
				assert_true(fabs(rmin[1] - 1) < 1e-3);
			}
		}
	free(html);
}

static uint8_t img[2000 * 1400 * 4];

static double luminance_stddev(const uint8_t *px, int w, int x0, int x1, int y0, int y1)
{
	double sum = 0, sum2 = 0, n = 0;
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++) {
			const uint8_t *p = px + 4 * ((size_t)y * (size_t)w + (size_t)x);
			double l = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
			sum += l, sum2 += l * l, n++;
		}
	return sqrt(fmax(0, sum2 / n - (sum / n) * (sum / n)));
}

/* ---- the pictures ---------------------------------------------------- */

static uint8_t img2[2000 * 1400 * 4];

typedef struct picture {
	const uint8_t *px;
	int w, h;
} picture;

static picture load_png(const char *dir, const char *name, uint8_t *buf)
{
	char path[1200];
	skp_error err;
	picture p = { buf, 0, 0 };
	snprintf(path, sizeof path, "%s/%s", dir, name);
	if (png_read_rgba(path, buf, (int)sizeof img, &p.w, &p.h, &err) != 0)
		fail_msg("%s: %s", path, err.msg);
	return p;
}

static const uint8_t *pixel(const picture *p, int x, int y)
{
	return p->px + 4 * ((size_t)y * (size_t)p->w + (size_t)x);
}

static int colour_distance(const uint8_t *a, const uint8_t *b)
{
	return abs(a[0] - b[0]) + abs(a[1] - b[1]) + abs(a[2] - b[2]);
}

/* The renderer's gold (the inset's outline and title, its ring on the
 * body: 1.0, 0.78, 0.15) and the report's ring (255, 196, 0, opaque at
 * its core). */
static int is_gold(const uint8_t *p)
{
	return abs(p[0] - 255) <= 10 && abs(p[1] - 199) <= 12 && abs(p[2] - 38) <= 14;
}

static int is_ring(const uint8_t *p)
{
	return p[0] >= 245 && p[1] >= 182 && p[1] <= 206 && p[2] <= 22;
}

/* Lit skin: red over green over blue, none far below the red (the
 * backgrounds are bluish grey; the difference view's yellow and red are
 * saturated). */
static int is_skin(const uint8_t *p)
{
	return !is_gold(p) && !is_ring(p) && p[0] > p[2] + 35 && p[0] >= p[1] && p[1] > p[2] &&
	       100 * p[2] > 45 * p[0] && 100 * p[1] > 65 * p[0];
}

/* The difference view's colours: dark blue (no difference) and cyan;
 * green, yellow, red (they part by 15 mm and more). */
static int is_diff_blue(const uint8_t *p)
{
	return p[2] > p[0] + 50 && p[2] > 90;
}

static int is_diff_warm(const uint8_t *p)
{
	return !is_gold(p) && (p[1] > p[2] + 40 || p[0] > p[2] + 90) && !is_skin(p);
}

typedef struct rect {
	int x, y, w, h;
} rect;

/* The close-up inset between columns x0 and x1: the square outlined in
 * gold (rows and columns with long gold runs). 0 when there is none. */
static int find_inset(const picture *p, int x0, int x1, rect *r)
{
	int top = -1, bottom = -1, left = -1, right = -1;
	for (int y = 0; y < p->h; y++) {
		int n = 0;
		for (int x = x0; x < x1; x++)
			n += is_gold(pixel(p, x, y));
		if (n >= 80) {
			top = top < 0 ? y : top;
			bottom = y;
		}
	}
	if (top < 0 || bottom - top < 40)
		return 0;
	for (int x = x0; x < x1; x++) {
		int n = 0;
		for (int y = top; y <= bottom; y++)
			n += is_gold(pixel(p, x, y));
		if (n >= 80) {
			left = left < 0 ? x : left;
			right = x;
		}
	}
	if (left < 0 || right - left < 40)
		return 0;
	/* inside the outline */
	*r = (rect){ left + 4, top + 4, right - left - 7, bottom - top - 7 };
	return 1;
}

/* Both halves' insets, the same size, one half-width apart. */
static void find_insets(const picture *p, const char *name, rect in[2])
{
	int hw = p->w / 2;
	for (int i = 0; i < 2; i++)
		if (!find_inset(p, i * hw + hw / 3, (i + 1) * hw, &in[i]))
			fail_msg("%s: no close-up inset in the %s half", name, i ? "right" : "left");
	assert_true(abs(in[1].x - in[0].x - hw) <= 1 && abs(in[1].y - in[0].y) <= 1);
	assert_true(abs(in[1].w - in[0].w) <= 1 && abs(in[1].h - in[0].h) <= 1);
}

typedef struct counts {
	long total, skin[2], blue[2], warm[2], differ;
} counts;

/* Inside r (left half) and the same place in the right half. */
static counts count_in(const picture *p, rect r)
{
	counts c = { 0 };
	int hw = p->w / 2;
	for (int y = r.y; y < r.y + r.h; y++)
		for (int x = r.x; x < r.x + r.w; x++) {
			const uint8_t *a = pixel(p, x, y), *b = pixel(p, x + hw, y);
			c.total++;
			c.differ += colour_distance(a, b) > 60;
			for (int i = 0; i < 2; i++) {
				const uint8_t *q = i ? b : a;
				c.skin[i] += is_skin(q);
				c.blue[i] += is_diff_blue(q);
				c.warm[i] += is_diff_warm(q);
			}
		}
	return c;
}

/* The page shows the picture. */
static void assert_on_page(const char *html, const char *png)
{
	char key[160];
	snprintf(key, sizeof key, "<img src=\"%s\"", png);
	if (!strstr(html, key))
		fail_msg("index.html does not show %s", png);
}

/* Real pictures (not flat) whose halves differ on the body; a whole-body
 * one (not near) equal where the body is not (same camera, same floor). */
static void check_halves(const picture *p, const char *name, int near)
{
	int hw = p->w / 2;
	double sd = luminance_stddev(p->px, p->w, 0, p->w, 0, p->h);
	long differ = 0, total = 0;
	for (int y = p->h / 8; y < p->h * 7 / 8; y++) /* between the HUD and the panel labels */
		for (int x = 0; x < hw - 1; x++) {
			differ += colour_distance(pixel(p, x, y), pixel(p, x + hw, y)) > 30;
			total++;
		}
	print_message("%s: %dx%d, luminance stddev %.1f, %ld of %ld pixels differ between the halves\n", name, p->w,
		      p->h, sd, differ, total);
	assert_true(sd > 10.0);
	assert_true(differ > 100);           /* the skinning differs */
	if (!near)
		assert_true(differ < total / 3); /* but it is the same pose and camera */
}

/* The twist scene at 180 degrees: in the close-ups the LBS cylinder is
 * pinched to a point at the joint (the candy wrapper), DQBS's whole. */
static void check_twist_scene(const char *dir)
{
	picture p = load_png(dir, "scene_twist.png", img);
	check_halves(&p, "scene_twist.png", 0);
	rect in[2];
	find_insets(&p, "scene_twist.png", in);
	counts c = count_in(&p, in[0]);
	/* the thinnest column of skin near the middle of each inset: the joint
	 * ring, which the close-up is centred on */
	long thin[2] = { in[0].h, in[0].h };
	for (int i = 0; i < 2; i++)
		for (int x = in[i].x + in[i].w * 2 / 5; x < in[i].x + in[i].w * 3 / 5; x++) {
			long n = 0;
			for (int y = in[i].y; y < in[i].y + in[i].h; y++)
				n += is_skin(pixel(&p, x, y));
			thin[i] = n < thin[i] ? n : thin[i];
		}
	print_message("scene_twist.png: insets %dx%d at x %d and %d; skin %.0f%% (LBS) and %.0f%% (DQBS) of them, "
		      "%.0f%% of their pixels differ; the joint's column of skin %ld px (LBS), %ld px (DQBS)\n",
		      in[0].w, in[0].h, in[0].x, in[1].x, 100.0 * c.skin[0] / c.total, 100.0 * c.skin[1] / c.total,
		      100.0 * c.differ / c.total, thin[0], thin[1]);
	assert_true(c.skin[0] > c.total / 10 && c.skin[1] > c.total / 10); /* both show the cylinder */
	assert_true(c.differ > c.total / 7);                               /* and differ substantially */
	assert_true(c.skin[1] > c.skin[0] + c.total / 10);                 /* LBS lost skin at the joint */
	assert_true(thin[1] > in[1].h * 3 / 10);                           /* DQBS: the cylinder's diameter */
	assert_true(thin[0] < in[0].h / 10);                               /* LBS: the candy wrapper's waist */
}

/* The bend scene: a real picture, its close-ups differing. */
static void check_bend_scene(const char *dir)
{
	picture p = load_png(dir, "scene_bend.png", img);
	check_halves(&p, "scene_bend.png", 0);
	rect in[2];
	find_insets(&p, "scene_bend.png", in);
	counts c = count_in(&p, in[0]);
	print_message("scene_bend.png: skin %.0f%% (LBS) and %.0f%% (DQBS) of the insets, %.0f%% of their pixels "
		      "differ\n", 100.0 * c.skin[0] / c.total, 100.0 * c.skin[1] / c.total, 100.0 * c.differ / c.total);
	assert_true(c.skin[0] > c.total / 10 && c.skin[1] > c.total / 10);
	assert_true(c.differ > c.total / 20);
	assert_true(c.skin[1] > c.skin[0]); /* DQBS's knuckle bulges where LBS's elbow is flat */
}

/* A worst frame's close-up: the report's ring, at the same place in both
 * halves, encloses where the two pictures differ. */
static void check_ring_encloses(const char *dir, const char *name)
{
	picture p = load_png(dir, name, img);
	int hw = p.w / 2;
	double cx[2] = { 0, 0 }, cy[2] = { 0, 0 }, n[2] = { 0, 0 };
	for (int y = 0; y < p.h; y++)
		for (int x = 0; x < p.w; x++)
			if (is_ring(pixel(&p, x, y))) {
				int i = x >= hw;
				cx[i] += x, cy[i] += y, n[i]++;
			}
	if (n[0] < 200 || n[1] < 200)
		fail_msg("%s: no ring (%.0f and %.0f ring pixels)", name, n[0], n[1]);
	for (int i = 0; i < 2; i++)
		cx[i] /= n[i], cy[i] /= n[i];
	assert_true(fabs(cx[1] - cx[0] - hw) < 2.0 && fabs(cy[1] - cy[0]) < 2.0);
	double radius = 0;
	for (int y = 0; y < p.h; y++)
		for (int x = 0; x < hw; x++)
			if (is_ring(pixel(&p, x, y)))
				radius += hypot(x - cx[0], y - cy[0]);
	radius /= n[0];
	/* where the halves differ, the ring's band and the HUD and labels
	 * left out: how densely inside the ring and outside, and their
	 * centre, weighted by how much they differ */
	long inside = 0, outside = 0, area_in = 0, area_out = 0;
	double wx = 0, wy = 0, wsum = 0;
	for (int y = p.h / 10; y < p.h * 9 / 10; y++)
		for (int x = 0; x < hw - 1; x++) {
			double d = hypot(x - cx[0], y - cy[0]);
			if (fabs(d - radius) < 8.0)
				continue;
			int dist = colour_distance(pixel(&p, x, y), pixel(&p, x + hw, y)), differ = dist > 60;
			area_in += d < radius;
			area_out += d > radius;
			inside += differ && d < radius;
			outside += differ && d > radius;
			if (differ)
				wx += (double)dist * x, wy += (double)dist * y, wsum += dist;
		}
	double dens_in = (double)inside / (double)area_in, dens_out = area_out ? (double)outside / (double)area_out : 0;
	double off = wsum > 0 ? hypot(wx / wsum - cx[0], wy / wsum - cy[0]) : INFINITY;
	print_message("%s: ring at (%.0f, %.0f) radius %.0f px; %.0f%% of it differs between the halves, %.0f%% "
		      "outside it; where they differ centred %.0f px (%.2f radii) from the ring's centre\n", name, cx[0],
		      cy[0], radius, 100.0 * dens_in, 100.0 * dens_out, off, off / radius);
	assert_true(radius > 20.0 && radius < p.h / 2);
	assert_true(inside > 200);                 /* the two differ in the ring */
	assert_true(dens_in > 1.5 * dens_out);     /* more than elsewhere */
	assert_true(off < 0.75 * radius);          /* and centred inside the ring */
}

/* The difference view: the body coloured (no skin), blue where LBS and
 * DQBS agree, warm somewhere in the close-up where they part; the body
 * view of the same frame shows skin there. */
static void check_difference(const char *dir, const char *body_png, const char *diff_png)
{
	picture b = load_png(dir, body_png, img), d = load_png(dir, diff_png, img2);
	assert_int_equal(b.w, d.w);
	assert_int_equal(b.h, d.h);
	rect ib[2], id[2];
	find_insets(&b, body_png, ib);
	find_insets(&d, diff_png, id);
	counts cb = count_in(&b, ib[0]), cd = count_in(&d, id[0]);
	print_message("%s: in the close-up %.1f%% blue, %.1f%% warm, %.1f%% skin (LBS; DQBS %.1f%%, %.1f%%, %.1f%%); "
		      "%s: %.1f%% skin, %.1f%% blue\n", diff_png, 100.0 * cd.blue[0] / cd.total,
		      100.0 * cd.warm[0] / cd.total, 100.0 * cd.skin[0] / cd.total, 100.0 * cd.blue[1] / cd.total,
		      100.0 * cd.warm[1] / cd.total, 100.0 * cd.skin[1] / cd.total, body_png,
		      100.0 * cb.skin[0] / cb.total, 100.0 * cb.blue[0] / cb.total);
	assert_true(cb.skin[0] > cb.total / 20 && cb.blue[0] < cb.total / 100);
	/* (the ramp's red, shaded, passes for skin in a few pixels) */
	assert_true(cd.skin[0] < cd.total / 25 && cd.skin[1] < cd.total / 25);
	assert_true(cd.blue[0] + cd.warm[0] > cd.total / 20 && cd.blue[1] + cd.warm[1] > cd.total / 20);
	assert_true(cd.warm[0] > 50 && cd.warm[1] > 50);
}

/* The report's pictures: on disk, on the page, and showing what they
 * say they show. */
static void check_pictures(const char *dir, int stills)
{
	char path[1200], name[64];
	snprintf(path, sizeof path, "%s/index.html", dir);
	char *html = slurp(path);
	assert_on_page(html, "scene_twist.png");
	assert_on_page(html, "scene_bend.png");
	for (int i = 1; i <= stills; i++) {
		static const char *const kinds[3] = { "", "_closeup", "_difference" };
		for (int k = 0; k < 3; k++) {
			snprintf(name, sizeof name, "worst_%d%s.png", i, kinds[k]);
			assert_on_page(html, name);
		}
		snprintf(name, sizeof name, "worst_%d_closeup.png", i);
		check_ring_encloses(dir, name);
	}
	/* the scenes' pictures beside their tables */
	const char *twist_table = strstr(html, "id=\"scene-twist\""), *bend_table = strstr(html, "id=\"scene-bend\"");
	const char *twist_pic = strstr(html, "src=\"scene_twist.png\""), *bend_pic = strstr(html, "src=\"scene_bend.png\"");
	assert_true(twist_table && bend_table && twist_pic && bend_pic);
	assert_true(twist_table < twist_pic && twist_pic < bend_table && bend_table < bend_pic);
	assert_non_null(strstr(twist_pic, "the candy wrapper"));
	free(html);
	picture p = load_png(dir, "worst_1.png", img);
	check_halves(&p, "worst_1.png", 0);
	p = load_png(dir, "worst_1_closeup.png", img);
	check_halves(&p, "worst_1_closeup.png", 1);
	check_difference(dir, "worst_1.png", "worst_1_difference.png");
	check_twist_scene(dir);
	check_bend_scene(dir);
}

static void test_renders(void **state)
{
	(void)state;
	if (!last_report[0])
		skip();
	check_pictures(last_report, 4);
}

/* The text of the paragraph with this id, tags stripped. */
static void paragraph(const char *page, const char *id, char *out, size_t cap)
{
	char key[96];
	snprintf(key, sizeof key, "id=\"%s\">", id);
	const char *p = strstr(page, key);
	assert_non_null(p);
	p += strlen(key);
	const char *end = strstr(p, "</p>");
	assert_non_null(end);
	size_t n = 0;
	for (int tag = 0; p < end && n + 1 < cap; p++) {
		if (*p == '<')
			tag = 1;
		else if (*p == '>')
			tag = 0;
		else if (!tag)
			out[n++] = *p;
	}
	out[n] = '\0';
}

/* The MakeHuman body on 131_04: the summary names where DQBS keeps more
 * volume around a joint than LBS and where it swells more, with figures;
 * the renders are of different joint regions; the page's total time is
 * the command's last line's. */
static void test_joint_truths(void **state)
{
	(void)state;
	const char *asf = test_data_path("mocap/cmu/131.asf");
	if (!asf)
		skip();
	char cmd[8192], dir[1100], asf_path[1024], amc[1024], mesh[1024];
	snprintf(asf_path, sizeof asf_path, "%s", asf);
	snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/131_04.amc"));
	snprintf(mesh, sizeof mesh, "%s", test_data_path("mesh/makehuman/base.obj"));
	snprintf(dir, sizeof dir, "%s/truths", workdir);
	snprintf(cmd, sizeof cmd, "%s compare %s %s --mesh %s --renders 3 -o %s", test_tool_path("skintool"), asf_path,
		 amc, mesh, dir);
	assert_int_equal(sh(cmd, NULL), 0);
	char path[1200], keeps[2048], swells[2048];
	snprintf(path, sizeof path, "%s/index.html", dir);
	char *page = slurp(path);
	paragraph(page, "verdict-dqbs-keeps", keeps, sizeof keeps);
	paragraph(page, "verdict-dqbs-bulges", swells, sizeof swells);
	print_message("%s\n%s\n", keeps, swells);
	/* a region named with DQBS's and LBS's figures */
	assert_non_null(strstr(keeps, "% against "));
	assert_non_null(strstr(swells, "% against "));
	/* three renders, three joint regions */
	char region[3][32];
	const char *p = page;
	for (int i = 0; i < 3; i++) {
		p = strstr(p, "<h3>");
		assert_non_null(p);
		p = strstr(p, "&mdash; ");
		assert_non_null(p);
		assert_int_equal(sscanf(p, "&mdash; %31s", region[i]), 1);
	}
	assert_true(strcmp(region[0], region[1]) && strcmp(region[0], region[2]) && strcmp(region[1], region[2]));
	/* the close-ups ringed where LBS and DQBS part, the difference view */
	check_pictures(dir, 3);
	/* the timings agree */
	snprintf(path, sizeof path, "%s/stderr.txt", workdir);
	char *err = slurp(path);
	const char *t = strstr(err, "total ");
	double total = 0, page_total = 0;
	assert_non_null(t);
	assert_int_equal(sscanf(t, "total %lf s", &total), 1);
	const char *q = strstr(page, "this page included, took ");
	assert_non_null(q);
	assert_int_equal(sscanf(q, "this page included, took %lf s", &page_total), 1);
	assert_true(total == page_total);
	free(err);
	free(page);
}

/* Headless Chromium's screenshot of the page: a real, mostly light page
 * with text, tables and pictures in it. */
static void test_page_in_chromium(void **state)
{
	(void)state;
	if (access("/usr/bin/chromium", X_OK) != 0 || !last_report[0])
		skip();
	char cmd[4096], shot[1200], profile[1200], url[1200];
	snprintf(shot, sizeof shot, "%s/screenshot.png", workdir);
	snprintf(profile, sizeof profile, "%s/chromium-profile", workdir);
	if (last_report[0] == '/')
		snprintf(url, sizeof url, "file://%s/index.html", last_report);
	else
		snprintf(url, sizeof url, "file://%s/%s/index.html", getcwd(cmd, sizeof cmd), last_report);
	snprintf(cmd, sizeof cmd, "timeout 120 /usr/bin/chromium --headless --no-sandbox --disable-gpu "
		 "--disable-background-networking --disable-component-update --disable-sync --no-first-run "
		 "--hide-scrollbars --user-data-dir=%s --screenshot=%s --window-size=1200,2000 %s",
		 profile, shot, url);
	double t0 = now_s();
	assert_int_equal(sh(cmd, NULL), 0);
	skp_error err;
	int w, h;
	if (png_read_rgba(shot, img, sizeof img, &w, &h, &err) != 0)
		fail_msg("%s: %s", shot, err.msg);
	assert_int_equal(w, 1200);
	assert_int_equal(h, 2000);
	long dark = 0, light = 0, colour = 0;
	for (long i = 0; i < (long)w * h; i++) {
		const uint8_t *p = img + 4 * i;
		int mx = p[0] > p[1] ? (p[0] > p[2] ? p[0] : p[2]) : (p[1] > p[2] ? p[1] : p[2]);
		int mn = p[0] < p[1] ? (p[0] < p[2] ? p[0] : p[2]) : (p[1] < p[2] ? p[1] : p[2]);
		dark += mx < 90;
		light += mn > 220;
		colour += mx - mn > 60;
	}
	double sd = luminance_stddev(img, w, 0, w, 0, h);
	print_message("chromium screenshot %dx%d in %.1f s: stddev %.1f, %ld dark, %ld light, %ld coloured pixels\n",
		      w, h, now_s() - t0, sd, dark, light, colour);
	assert_true(sd > 20.0);
	assert_true(light > (long)w * h / 4);  /* the page, not a blank or error screen */
	assert_true(dark > 2000);              /* text and the renders' backgrounds */
	assert_true(colour > 2000);            /* the skin and the chart lines */
}

static void expect_fail(const char *args, const char *message)
{
	char cmd[2048], err[1200];
	snprintf(cmd, sizeof cmd, "%s %s", test_tool_path("skintool"), args);
	assert_int_equal(sh(cmd, NULL), 1);
	snprintf(err, sizeof err, "%s/stderr.txt", workdir);
	char *text = slurp(err);
	if (!strstr(text, message))
		fail_msg("'skintool %s' said '%s', expected '%s'", args, text, message);
	free(text);
}

/* The volume on a body with parts: a box inside the body is left out of
 * the volume (the volume column and the elbow region's volume are the
 * plain body's to the digit, the page says what was measured), and a body whose parts each have a hole (the
 * generated arm's two tubes, every 400th face taken out) has no volume: both
 * volume verdicts say "not measured" instead of yes or no. */
static void write_variant(const char *body_obj, const char *out, int inner_box, int drop_faces)
{
	char *text = slurp(body_obj);
	FILE *f = fopen(out, "w");
	assert_non_null(f);
	fputs("g body\n", f);
	int verts = 0, faces = 0;
	for (char *line = text; *line;) {
		char *end = strchr(line, '\n');
		size_t n = end ? (size_t)(end - line + 1) : strlen(line);
		verts += line[0] == 'v' && line[1] == ' ';
		faces += line[0] == 'f' && line[1] == ' ';
		if (!(drop_faces && line[0] == 'f' && faces % 400 == 1) && line[0] != 'g' && line[0] != 'o')
			fwrite(line, 1, n, f);
		line += n;
	}
	if (inner_box) {
		/* a closed box, faces outward, inside the forearm */
		static const float c[8][3] = { { 2.7f, -0.05f, -0.05f }, { 2.8f, -0.05f, -0.05f }, { 2.8f, 0.05f, -0.05f },
					       { 2.7f, 0.05f, -0.05f }, { 2.7f, -0.05f, 0.05f }, { 2.8f, -0.05f, 0.05f },
					       { 2.8f, 0.05f, 0.05f }, { 2.7f, 0.05f, 0.05f } };
		static const int q[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 },
					     { 2, 3, 7, 6 }, { 1, 2, 6, 5 }, { 0, 4, 7, 3 } };
		for (int k = 0; k < 8; k++)
			fprintf(f, "v %g %g %g\n", (double)c[k][0], (double)c[k][1], (double)c[k][2]);
		for (int k = 0; k < 6; k++)
			fprintf(f, "f %d %d %d %d\n", verts + 1 + q[k][0], verts + 1 + q[k][1], verts + 1 + q[k][2],
				verts + 1 + q[k][3]);
	}
	fclose(f);
	free(text);
}

static char *compare_page(const char *obj, const char *name, char **csv)
{
	char cmd[4096], dir[1100], path[1200];
	snprintf(dir, sizeof dir, "%s/%s", workdir, name);
	snprintf(cmd, sizeof cmd, "%s compare %s/arm.asf %s/arm.amc --mesh %s --balance off "
		 "--group body --renders 0 -o %s 2>/dev/null", test_tool_path("skintool"), workdir, workdir, obj, dir);
	assert_int_equal(sh(cmd, NULL), 0);
	snprintf(path, sizeof path, "%s/metrics.csv", dir);
	*csv = slurp(path);
	first_five_columns(*csv);
	snprintf(path, sizeof path, "%s/index.html", dir);
	return slurp(path);
}

static void test_parts_and_holes(void **state)
{
	(void)state;
	char cmd[4096], made[1100], body[1100], inner[1100], open[1100];
	snprintf(made, sizeof made, "%s/tiny_made.obj", workdir);
	snprintf(body, sizeof body, "%s/tiny_body.obj", workdir);
	snprintf(inner, sizeof inner, "%s/tiny_inner.obj", workdir);
	snprintf(open, sizeof open, "%s/tiny_open.obj", workdir);
	/* the tiny arm with CMU's names, so that its lower bone is an elbow
	 * region (report.c) and the region volumes are measured too */
	for (int i = 0; i < 2; i++) {
		static const char *const ext[2] = { "asf", "amc" };
		char arm[1100];
		snprintf(cmd, sizeof cmd, "sed 's/\\<upper\\>/lhumerus/g; s/\\<lower\\>/lradius/g' tests/data/tiny.%s",
			 ext[i]);
		snprintf(arm, sizeof arm, "%s/arm.%s", workdir, ext[i]);
		assert_int_equal(sh(cmd, arm), 0);
	}
	snprintf(cmd, sizeof cmd, "%s mannequin %s/arm.asf -o %s", test_tool_path("skintool"), workdir, made);
	assert_int_equal(sh(cmd, NULL), 0);
	write_variant(made, body, 0, 0);
	write_variant(made, inner, 1, 0);
	write_variant(made, open, 0, 1);
	char *plain_csv, *inner_csv, *open_csv;
	char *plain = compare_page(body, "plain", &plain_csv), *with_box = compare_page(inner, "inner", &inner_csv);
	char *holed = compare_page(open, "open", &open_csv);
	assert_null(strstr(plain, "id=\"volume-parts\""));
	/* the generated arm is two closed parts: a ball at the shoulder, the forearm */
	if (!strstr(with_box, "Measured on the mesh's 2 outer closed parts of 3; 1 inside them (joint balls, eyes, "
			      "teeth) left out."))
		fail_msg("the page does not say what its volume was measured on");
	assert_string_equal(plain_csv, inner_csv);
	/* the elbow's own volume leaves the box out too (it took 18.29% to
	 * 17.53% when counted) */
	const char *elbow_plain = strstr(element(plain, "region-volume"), "<tr><td>elbows</td><td>");
	const char *elbow_inner = strstr(element(with_box, "region-volume"), "<tr><td>elbows</td><td>");
	assert_non_null(elbow_plain);
	assert_non_null(elbow_inner);
	assert_true(strchr(elbow_plain + strlen("<tr><td>elbows</td><td>"), '%') != NULL);
	assert_int_equal(strcspn(elbow_plain, "\n"), strcspn(elbow_inner, "\n"));
	assert_memory_equal(elbow_plain, elbow_inner, strcspn(elbow_plain, "\n"));
	const char *v = element(holed, "verdict-dqbs-volume");
	static const char unmeasured[] = "<b>not measured</b> &mdash; no part of the mesh is closed (";
	assert_true(strncmp(strstr(v, "<b>"), unmeasured, strlen(unmeasured)) == 0);
	v = element(holed, "verdict-lbs-loss");
	assert_true(strncmp(strstr(v, "<b>"), "<b>not measured</b>", strlen("<b>not measured</b>")) == 0);
	free(plain), free(with_box), free(holed);
	free(plain_csv), free(inner_csv), free(open_csv);
}

static void test_bad_arguments(void **state)
{
	(void)state;
	char args[2048];
	expect_fail("compare tests/data/tiny.asf tests/data/tiny.amc", "skintool compare: give SKELETON MOTION and -o DIR");
	expect_fail("compare tests/data/tiny.asf", "skintool compare: give SKELETON MOTION and -o DIR");
	snprintf(args, sizeof args, "compare tests/data/tiny.asf tests/data/tiny.amc --bogus -o %s/x", workdir);
	expect_fail(args, "unknown option '--bogus'");
	snprintf(args, sizeof args, "compare tests/data/tiny.asf tests/data/tiny.amc --renders 99 -o %s/x", workdir);
	expect_fail(args, "--renders takes 0 to");
	snprintf(args, sizeof args, "compare tests/data/missing.asf tests/data/tiny.amc -o %s/x", workdir);
	expect_fail(args, "missing.asf");
	snprintf(args, sizeof args, "compare tests/data/tiny.asf tests/data/tiny.amc --mesh missing.obj -o %s/x",
		 workdir);
	expect_fail(args, "missing.obj");
	expect_fail("compare tests/data/tiny.asf tests/data/tiny.amc -o /proc/no/such/dir", "/proc/no/such/dir");
}

static int setup(void **state)
{
	(void)state;
	return mkdtemp(workdir) ? 0 : -1;
}

static int teardown(void **state)
{
	(void)state;
	char cmd[1200];
	if (getenv("SKP_KEEP_REPORT")) {
		fprintf(stderr, "reports kept in %s\n", workdir);
		return 0;
	}
	snprintf(cmd, sizeof cmd, "rm -rf %s", workdir);
	return system(cmd) == 0 ? 0 : -1;
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_short_clips),
		cmocka_unit_test(test_every_clip),
		cmocka_unit_test(test_scene_tables),
		cmocka_unit_test(test_renders),
		cmocka_unit_test(test_joint_truths),
		cmocka_unit_test(test_page_in_chromium),
		cmocka_unit_test(test_parts_and_holes),
		cmocka_unit_test(test_bad_arguments),
	};
	return cmocka_run_group_tests_name("compare_report", tests, setup, teardown);
}
