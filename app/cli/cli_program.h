/* "skinplay" or "skintool": the program whose command line cli_parse
 * read last, for messages that only know an option's name. */
#ifndef CLI_PROGRAM_H
#define CLI_PROGRAM_H

/* prog's first word ("skintool pack" -> "skintool"). */
void cli_set_program(const char *prog);
const char *cli_program(void);

#endif
