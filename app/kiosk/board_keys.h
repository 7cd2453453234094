/* The board config's parts outside board_config.c: the helpers its key
 * parsers share, and the keys of a device's part in an installation
 * (board_install.c). Private to app/kiosk. */
#ifndef BOARD_KEYS_H
#define BOARD_KEYS_H

#include "board_config.h"
#include "ini.h"

/* "key 'K' in [S]: expected EXPECTED, found 'V'" */
skp_status board_bad(skp_error *err, const ini_entry *e, const char *expected);

/* The index of v among names (case aside), or -1. */
int board_pick(const char *v, const char *const *names, int n);

/* [show] sync, epoch, buttons; [wall]; [camera]. */
skp_status board_show_sync_key(board_config *c, const ini_entry *e, skp_error *err);
skp_status board_wall_key(board_config *c, const ini_entry *e, skp_error *err);
skp_status board_camera_key(board_config *c, const ini_entry *e, skp_error *err);

#endif
