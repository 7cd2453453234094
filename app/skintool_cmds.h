/* skintool commands: each takes the arguments after its name. */
#ifndef SKINTOOL_CMDS_H
#define SKINTOOL_CMDS_H

int cmd_fk(int argc, char **argv);

#endif
