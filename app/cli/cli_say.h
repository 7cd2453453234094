/* What the frame's path (app/runtime) and binding at start-up (app/setup)
 * say while they work, said here so that those modules hold no stdio: a
 * note (a choice made for the user's files, a slot chosen; silenced by
 * --quiet, cli_quiet.h) or a warning (a damaged block held, a fallback the
 * user did not ask for, a refusal, a report asked for on stderr: always
 * printed). printf's format; a line may take several calls. */
#ifndef CLI_SAY_H
#define CLI_SAY_H

#if defined(__GNUC__)
#define CLI_SAY_FORMAT __attribute__((format(printf, 1, 2)))
#else
#define CLI_SAY_FORMAT
#endif

void cli_say(const char *fmt, ...) CLI_SAY_FORMAT;
void cli_warn(const char *fmt, ...) CLI_SAY_FORMAT;

#endif
