/* commands.h: the subcommands of `anvil`; each takes the arguments after
 * its own name (argv[0] is the command name) and returns an exit code
 * (0 ok, 1 failure, 2 usage or input error). */
#ifndef ANVIL_UI_COMMANDS_H
#define ANVIL_UI_COMMANDS_H

#include <stdio.h>

int anvil_cmd_run(int argc, char **argv);       /* src/ui/cmd_run.c */
int anvil_cmd_table(int argc, char **argv);     /* src/ui/cmd_table.c */
int anvil_cmd_materials(int argc, char **argv); /* src/ui/cmd_materials.c */
int anvil_cmd_accuracy(int argc, char **argv);  /* src/ui/cmd_accuracy.c */
int anvil_cmd_plot(int argc, char **argv);      /* src/ui/cmd_plot.c */
int anvil_cmd_tui(int argc, char **argv);       /* src/ui/tui.c */
int anvil_cmd_plan(int argc, char **argv);      /* src/ui/cmd_plan.c */
int anvil_cmd_field(int argc, char **argv);     /* src/ui/cmd_field.c */
int anvil_cmd_map(int argc, char **argv);       /* src/ui/cmd_field.c */

/* The plan as `anvil plan` prints it (also for `anvil run -v`). */
struct anvil_plan;
void anvil_plan_print(FILE *f, const struct anvil_plan *pl); /* src/ui/cmd_plan.c */

#endif
