/* skintool commands: each takes the arguments after its name. */
#ifndef SKINTOOL_CMDS_H
#define SKINTOOL_CMDS_H

int cmd_fk(int argc, char **argv);
int cmd_convert(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_bind(int argc, char **argv);
int cmd_mannequin(int argc, char **argv);
int cmd_skin(int argc, char **argv);
int cmd_metrics(int argc, char **argv);
int cmd_compare(int argc, char **argv);
int cmd_pack(int argc, char **argv);
int cmd_view(int argc, char **argv);
int cmd_info(int argc, char **argv);
int cmd_repair(int argc, char **argv);
int cmd_bench_image(int argc, char **argv);
int cmd_bench_parse(int argc, char **argv);

#endif
