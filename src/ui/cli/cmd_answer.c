/* cmd_answer.c: direct answers (placeholder while being written). */
#include "commands.h"
int anvil_cmd_thickness(int argc, char **argv) { (void)argc; (void)argv; return 1; }
int anvil_cmd_fit(int argc, char **argv) { (void)argc; (void)argv; return 1; }
int anvil_cmd_dem(int argc, char **argv) { (void)argc; (void)argv; return 1; }
