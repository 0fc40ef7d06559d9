/* cmd_materials.c: `anvil materials`, the built-in materials with the wave
 * speeds that decide how a layer answers an impact. */
#include <getopt.h>

#include "material.h"
#include "commands.h"
#include "common.h"
#include "output.h"

static void materials_usage(FILE *f)
{
	fputs("usage: anvil materials [--format table|tsv]\n"
	      "List the built-in materials: E, nu, rho, the wave speeds c1, c2, cR,\n"
	      "the yield stress (- when unknown) and where the numbers come from.\n",
	      f);
}

static const struct option materials_longopts[] = {
	{"format", required_argument, NULL, 'f'},
	{"help", no_argument, NULL, 'h'},
	{NULL, 0, NULL, 0}};

static void materials_row(struct out_grid *g, const struct anvil_material *m,
			  enum out_format fmt)
{
	int table = fmt == OUT_TABLE;
	char b[40];
	out_grid_cell(g, "%s", m->name);
	out_grid_cell(g, "%s", out_num(b, m->E * 1e-9, table ? "%.4g" : NULL));
	out_grid_cell(g, "%s", out_num(b, m->nu, table ? "%.3g" : NULL));
	out_grid_cell(g, "%s", out_num(b, m->rho, table ? "%.0f" : NULL));
	out_grid_cell(g, "%s", out_num(b, anvil_material_c1(m), table ? "%.0f" : NULL));
	out_grid_cell(g, "%s", out_num(b, anvil_material_c2(m), table ? "%.0f" : NULL));
	out_grid_cell(g, "%s", out_num(b, anvil_material_cr(m), table ? "%.0f" : NULL));
	if (m->yield > 0)
		out_grid_cell(g, "%s", out_num(b, m->yield * 1e-6, table ? "%.4g" : NULL));
	else
		out_grid_cell(g, "-");
	out_grid_cell(g, "%s", m->source ? m->source : "-");
}

static int materials_print(enum out_format fmt)
{
	static const char *const head[] = {"name", "E_GPa", "nu", "rho_kg_m3", "c1_m_s",
					   "c2_m_s", "cR_m_s", "yield_MPa", "source"};
	const int ncol = (int)(sizeof head / sizeof head[0]);
	struct out_grid *g = out_grid_alloc(ncol);
	int st;
	if (!g) {
		cli_error("out of memory");
		return EXIT_FAIL;
	}
	out_grid_left(g, ncol - 1);
	for (int i = 0; i < ncol; i++)
		out_grid_cell(g, "%s", head[i]);
	for (int i = 0; i < anvil_material_count(); i++)
		materials_row(g, anvil_material_at(i), fmt);
	st = out_grid_print(g, fmt, stdout);
	out_grid_free(g);
	if (st || fflush(stdout)) {
		cli_error("materials: %s", anvil_strerror(st ? st : ANVIL_EIO));
		return EXIT_FAIL;
	}
	return EXIT_OK;
}

int anvil_cmd_materials(int argc, char **argv)
{
	int c, fmt = OUT_TABLE;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, ":f:h", materials_longopts, NULL)) != -1) {
		if (c == 'h') {
			materials_usage(stdout);
			return EXIT_OK;
		}
		if (c != 'f')
			return out_getopt_error("materials", c, argv);
		fmt = out_format_parse("materials", optarg,
				       OUT_ALLOW(OUT_TABLE) | OUT_ALLOW(OUT_TSV));
		if (fmt < 0)
			return EXIT_USAGE;
	}
	if (optind < argc)
		return out_usage("materials", "unexpected argument '%s'", argv[optind]);
	return materials_print((enum out_format)fmt);
}
