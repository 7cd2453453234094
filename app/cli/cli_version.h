/* --version for both programs: what was built, from which revision, for
 * which board, with which kernels and backends (GNU's first line, "NAME
 * VERSION", is what help2man reads for the man pages). */
#ifndef CLI_VERSION_H
#define CLI_VERSION_H

/* Prints the version text for program prog to stdout. */
void cli_print_version(const char *prog);

/* 1 when argv[1] asks for the version (--version or -V after prog). */
int cli_wants_version(int argc, char **argv);

#endif
