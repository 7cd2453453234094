#include "cli_inputs.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli_error.h"
#include "cli_program.h"
#include "storage_file.h"

#define MAX_INPUTS 640

typedef struct input {
	dev_t dev;
	ino_t ino;
	char word[96];     /* as the command line said it, for the message */
} input;

static input inputs[MAX_INPUTS];
static int input_count;

void cli_inputs_reset(void)
{
	input_count = 0;
}

static int add_file(const char *path, const char *word)
{
	struct stat st;
	if (stat(path, &st) != 0 || S_ISDIR(st.st_mode))
		return 0;
	if (input_count < MAX_INPUTS) {
		input *in = &inputs[input_count++];
		in->dev = st.st_dev;
		in->ino = st.st_ino;
		snprintf(in->word, sizeof in->word, "%s", word);
	}
	return 1;
}

void cli_inputs_add(const char *path)
{
	char part[4096];
	const char *first = strchr(path, ':'), *last = strrchr(path, ':');
	if (add_file(path, path) || !first || strlen(path) >= sizeof part)
		return;
	snprintf(part, sizeof part, "%.*s", (int)(last - path), path);   /* P.amc:F */
	if (!add_file(part, path))
		add_file(first + 1, path);                                  /* script:FILE */
}

int cli_output_file_check(const char *path, int block_ok)
{
	struct stat st;
	if (stat(path, &st) != 0 || S_ISREG(st.st_mode) || (block_ok && S_ISBLK(st.st_mode)))
		return 0;
	fprintf(stderr, "%s: %s is %s: %s; not written\n", cli_program(), cli_shown(path),
		S_ISBLK(st.st_mode) ? "a block device" : storage_file_kind(path),
		block_ok ? "an image goes to a file or a block device" : "this output is a file");
	return -1;
}

int cli_output_check(const char *path)
{
	struct stat st;
	if (stat(path, &st) != 0)
		return 0;   /* not there yet: no input */

	for (int i = 0; i < input_count; i++)
		if (inputs[i].dev == st.st_dev && inputs[i].ino == st.st_ino) {
			fprintf(stderr, "%s: %s is also an input (%s): not written; name another output\n", cli_program(),
				path, inputs[i].word);
			return -1;
		}
	return 0;
}
