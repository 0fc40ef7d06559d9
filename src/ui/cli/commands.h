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
int anvil_cmd_sweep(int argc, char **argv);     /* src/ui/cli/cmd_sweep.c */
int anvil_cmd_merge(int argc, char **argv);     /* src/ui/cli/cmd_merge.c */
int anvil_cmd_thickness(int argc, char **argv); /* src/ui/cli/cmd_answer.c */
int anvil_cmd_fit(int argc, char **argv);       /* src/ui/cli/cmd_answer.c */
int anvil_cmd_dem(int argc, char **argv);       /* src/ui/cli/cmd_answer.c */

/* What `anvil map SCENE -o path` writes (von Mises at t_max, the default
 * grid; format from the extension, else TSV), for `anvil run` when the
 * scene has [effects] field = map and [output] field = path.  Returns an
 * exit code. */
struct anvil_scene;
int anvil_field_map_file(const struct anvil_scene *sc, const char *path,
			 int quiet); /* src/ui/cli/cmd_field.c */

/* The plan as `anvil plan` prints it (also for `anvil run -v`). */
struct anvil_plan;
void anvil_plan_print(FILE *f, const struct anvil_plan *pl); /* src/ui/cmd_plan.c */
/* The plan's warnings, one line each (with their figures) after prefix
 * (`anvil run` on stderr). */
void anvil_plan_warnings_line(FILE *f, const struct anvil_plan *pl, const char *prefix);

#endif
