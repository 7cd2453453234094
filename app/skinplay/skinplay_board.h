/* skinplay's board (skinplay_board.c): board.ini's settings merged into
 * skinplay's options, and the kiosk's shell (app/runtime/kiosk_shell.h)
 * started with them. */
#ifndef SKINPLAY_BOARD_H
#define SKINPLAY_BOARD_H

#include "kiosk_shell.h"
#include "skinplay_opts.h"

/* After play_parse: loads --board (display settings not given on the
 * command line come from it; its problems are said and the defaults kept,
 * the first in board_note), the defaults neither says, then picks the
 * input (--input, else the board's, else none) and installs the signal
 * handlers. 0, or -1 after reporting. */
int skinplay_board_setup(kiosk_shell *k, play_opts *o, int argc, char **argv);

/* When skinplay is ready to show frames: the shell started with the
 * options' method, view and display rate (kiosk_shell_start). */
int skinplay_kiosk_start(kiosk_shell *k, const play_opts *o, int headless, int clip_count);

#endif
