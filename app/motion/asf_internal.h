/* The parser's state, shared by asf.c (the file, then the skeleton it
 * makes) and asf_sections.c (a line of each section) only. */
#ifndef ASF_INTERNAL_H
#define ASF_INTERNAL_H

#include "asf.h"

typedef enum asf_section {
	SEC_NONE, SEC_UNITS, SEC_DOC, SEC_ROOT, SEC_BONEDATA, SEC_HIERARCHY, SEC_SKIP
} asf_section;

typedef struct asf_state {
	skel *s;
	skp_error *err;
	long line;
	asf_section sec;
	int in_block;            /* between begin and end */
	skel_bone *bone;         /* bone being read in :bonedata */
	int limits_left;         /* limit values still expected for `bone` */
	int limit_pos;
	int dof_set;
	int root_seen, bonedata_seen, hierarchy_seen;
	uint8_t has_parent[SKP_MAX_BONES];
} asf_state;

/* One line of tokens t[0..n) (n >= 1): a ':' keyword starts a section,
 * any other line is read by the section it is in. */
skp_status asf_line(asf_state *st, char **t, int n);

#endif
