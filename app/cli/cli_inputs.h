/* The files a command reads, so that it never writes over one: every file
 * its command line names (option values and files, cli_parse records
 * them; --output, --out and --sheet name outputs) and the ones found on
 * the way (a rig's weights file), each by device and inode, so another
 * name for the same file (a hard link, a symbolic link, ./x for x) is the
 * same input. Every output is checked before it is written. */
#ifndef CLI_INPUTS_H
#define CLI_INPUTS_H

/* Forgets the inputs (a new command line). */
void cli_inputs_reset(void);

/* Records path when it names an existing file; a word that does not but
 * holds a ':' is tried as FILE:N (--bind-pose P.amc:F) and KIND:FILE
 * (--input script:FILE). */
void cli_inputs_add(const char *path);

/* 0 when writing path loses no input; -1 after saying on stderr which
 * input it is ("PATH: is also an input (WORD): not written"). */
int cli_output_check(const char *path);

/* 0 when path can take a file written whole (atomic_file.h): not there
 * yet, a file, or with block_ok a block device (an image's raw slot); -1
 * after saying what it is instead (a character device, a FIFO, a socket,
 * a directory). Symbolic links are followed: their target is written. */
int cli_output_file_check(const char *path, int block_ok);

#endif
