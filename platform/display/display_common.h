/* Helpers shared by the display backends; not for the rest of skinplay. */
#ifndef DISPLAY_COMMON_H
#define DISPLAY_COMMON_H

#include "display.h"

/* Size within 1..max and a rotation of 0/90/180/270. */
int display_check_config(const display_config *cfg, int max_w, int max_h, skp_error *err);
int display_check_rotation(int rotation, skp_error *err);

/* 1 when word is one of the space separated words of list (extension
 * strings); list may be NULL. */
int display_has_word(const char *list, const char *word);

#endif
