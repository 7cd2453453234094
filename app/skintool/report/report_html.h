/* The report page's pictures (report_html_pictures.c): the worst frames
 * as the kiosk shows them, their close-ups and difference views, and the
 * scenes' pictures with what to look at; the joints behind the volume
 * (report_html_joints.c); the helpers the page's files share
 * (report_html_text.c). Private to
 * report/. */
#ifndef REPORT_HTML_H
#define REPORT_HTML_H

#include <stdio.h>

#include "report.h"

/* s with the HTML-special characters escaped. */
void report_html_escape(FILE *f, const char *s);

/* The name of the skeleton's bone joint, "?" out of range. */
const char *report_html_joint(const report *r, int joint);

/* "Which bends carry it": the joints behind each algorithm's worst volume. */
void report_html_joints(FILE *f, const report *r);

/* "Where LBS fails: the worst frames", each frame's three pictures. */
void report_html_stills(FILE *f, const report *r);

/* A scene at its strongest pose, with what to look at. */
void report_html_scene_picture(FILE *f, const report_scene_still *s);

#endif
