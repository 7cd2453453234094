/* The positional arguments and numbers of both programs' command lines
 * (the options themselves are cli_opts.h's). */
#ifndef CLI_ARGS_H
#define CLI_ARGS_H

/* Puts arg into the first of the n slots still NULL; -1 after reporting
 * "CMD: unexpected argument" when every slot is taken. */
int cli_take_positional(const char *cmd, const char **const *slots, int n, const char *arg);

/* Parses a whole decimal integer argument; -1 (reported) when it is not. */
int cli_parse_long(const char *opt, const char *text, long *out);

#endif
