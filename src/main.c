/* main.c: picks the face of anvil from the first argument. */
#include <malloc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "config.h"
#include "commands.h"
#include "common.h"
#include "scene.h"

struct command {
	const char *name;
	int (*fn)(int argc, char **argv);
	const char *summary;
};

static const struct command commands[] = {
	{"run", anvil_cmd_run, "compute one impact with every model of a scene"},
	{"table", anvil_cmd_table, "the paper's Tables 2 and 3, ours beside the printed values"},
	{"materials", anvil_cmd_materials, "list the built-in materials"},
	{"accuracy", anvil_cmd_accuracy, "run a model at every accuracy level and check the targets"},
	{"plot", anvil_cmd_plot, "draw a chart (PNG, SVG or PDF) with gnuplot"},
	{"tui", anvil_cmd_tui, "the interactive terminal interface"},
	{"plan", anvil_cmd_plan, "how 'run' will compute a scene, and why (nothing is run)"},
	{"field", anvil_cmd_field, "displacements and stresses inside the layer over time"},
	{"map", anvil_cmd_map, "a displacement or stress over the layer at one instant"},
	{"sweep", anvil_cmd_sweep, "many scenes as rows: lists and ranges of keys, on all cores"},
	{"merge", anvil_cmd_merge, "join the shards of a sweep into its table"},
	{"thickness", anvil_cmd_thickness, "the thinnest layer that acts as a half-space"},
	{"fit", anvil_cmd_fit, "the thickness, modulus or velocity that gives a measured value"},
	{"dem", anvil_cmd_dem, "a restitution table against velocity for a DEM code"},
};
#define NCOMMANDS ((int)(sizeof commands / sizeof commands[0]))

static void usage(FILE *f)
{
	fputs("usage: anvil COMMAND [ARGS...]\n"
	      "       anvil --help | --version\n"
	      "Impact of a rod or ball-ended impactor on an elastic layer.\n\n"
	      "commands:\n",
	      f);
	for (int i = 0; i < NCOMMANDS; i++)
		fprintf(f, "  %-10s %s\n", commands[i].name, commands[i].summary);
	fputs("\nWithout a command: the TUI on a terminal, else 'anvil run'.\n"
	      "'anvil COMMAND --help' describes a command; 'man anvil' tells all\n"
	      "(before 'make install': man ./man/anvil.1 in the source tree).\n"
	      "--strict, with any command: implausible scene values are errors.\n",
	      f);
}

/* Edit distance, for "did you mean": commands are short, so the O(n m)
 * table fits on the stack. */
static int distance(const char *a, const char *b)
{
	int row[32], n = (int)strlen(b);
	if (n > 30 || strlen(a) > 30)
		return 99;
	for (int j = 0; j <= n; j++)
		row[j] = j;
	for (int i = 1; a[i - 1]; i++) {
		int diag = row[0];
		row[0] = i;
		for (int j = 1; j <= n; j++) {
			int up = row[j], best = diag + (a[i - 1] != b[j - 1]);
			if (up + 1 < best)
				best = up + 1;
			if (row[j - 1] + 1 < best)
				best = row[j - 1] + 1;
			diag = up;
			row[j] = best;
		}
	}
	return row[n];
}

static int unknown(const char *name)
{
	const char *best = NULL;
	int bestd = 3; /* more than two edits away is no suggestion */
	for (int i = 0; i < NCOMMANDS; i++) {
		int d = distance(name, commands[i].name);
		/* An abbreviation ("mat") is as good as one typo. */
		if (name[0] && strncmp(name, commands[i].name, strlen(name)) == 0)
			d = 1;
		if (d < bestd) {
			bestd = d;
			best = commands[i].name;
		}
	}
	if (best)
		cli_error("unknown command '%s'; did you mean '%s'? (see anvil --help)", name, best);
	else
		cli_error("unknown command '%s' (see anvil --help)", name);
	return EXIT_USAGE;
}

/* --strict is global: taken out of argv wherever it is (up to a "--"),
 * so that every command accepts it.  Returns the new argc. */
static int take_strict(int argc, char **argv)
{
	int j = 1;
	for (int i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--"))
			for (; i < argc; i++)
				argv[j++] = argv[i];
		else if (!strcmp(argv[i], "--strict"))
			cli_strict = 1;
		else
			argv[j++] = argv[i];
	}
	argv[j] = NULL;
	return j;
}

/* --complete-keys (hidden, for completion/anvil.bash): every scene key as
 * SECTION.KEY, one a line, read from the default scene as a scene file
 * writes it, so the list is the parser's own.  Material sections are
 * left out: their keys need a name. */
static int complete_keys(void)
{
	struct anvil_scene sc;
	char *buf = NULL, sec[64] = "", line[256];
	size_t len = 0;
	FILE *m = open_memstream(&buf, &len);
	if (!m)
		return EXIT_FAIL;
	anvil_scene_default(&sc);
	/* overrides are written only when set: set them to their own values */
	struct anvil_body *b[2] = {&sc.impactor, &sc.layer};
	for (int i = 0; i < 2; i++) {
		b[i]->E = b[i]->mat.E;
		b[i]->nu = b[i]->mat.nu;
		b[i]->rho = b[i]->mat.rho;
		b[i]->yield = b[i]->mat.yield;
	}
	int st = anvil_scene_write(&sc, m);
	fclose(m);
	FILE *in = st || !buf ? NULL : fmemopen(buf, len, "r");
	while (in && fgets(line, sizeof line, in)) {
		char key[64];
		if (sscanf(line, "[%63[a-z]]", sec) == 1)
			continue;
		if (line[0] == '[')
			sec[0] = '\0'; /* [material NAME] */
		else if (sec[0] && sscanf(line, "%63[A-Za-z_0-9] =", key) == 1)
			printf("%s.%s\n", sec, key);
	}
	if (in)
		fclose(in);
	free(buf);
	return st ? EXIT_FAIL : EXIT_OK;
}

int main(int argc, char **argv)
{
	static char *run_argv[] = {"run", NULL}, *tui_argv[] = {"tui", NULL};
	/* The heap grows and gives back 16 MB at a time: a warm physical row
	 * frees and allocates its impacts' arrays (a few 100 kB) five times,
	 * and the default 128 kB pad gave each back to the kernel, to be
	 * faulted in again: 30 brk calls, the kernel a sixth of the row's
	 * time, an eighth with the pad.  At most 16 MB more stay resident. */
	mallopt(M_TOP_PAD, 16 << 20);
	cli_init();
	argc = take_strict(argc, argv);
	if (argc < 2) {
		if (isatty(STDIN_FILENO) && isatty(STDOUT_FILENO))
			return anvil_cmd_tui(1, tui_argv);
		cli_signals_install();
		return anvil_cmd_run(1, run_argv);
	}
	const char *cmd = argv[1];
	/* the TUI restores the terminal first: it has its own handlers */
	if (strcmp(cmd, "tui") != 0)
		cli_signals_install();
	if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h") || !strcmp(cmd, "help")) {
		usage(stdout);
		return EXIT_OK;
	}
	if (!strcmp(cmd, "--complete-keys"))
		return complete_keys();
	if (!strcmp(cmd, "--version")) {
		printf("anvil %s\n", PACKAGE_VERSION);
		return EXIT_OK;
	}
	for (int i = 0; i < NCOMMANDS; i++)
		if (!strcmp(cmd, commands[i].name))
			return commands[i].fn(argc - 1, argv + 1);
	if (cmd[0] == '-') {
		cli_error("unknown option '%s' (see anvil --help)", cmd);
		return EXIT_USAGE;
	}
	return unknown(cmd);
}
