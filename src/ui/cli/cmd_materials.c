/* cmd_materials.c: `anvil materials`, the built-in materials with the wave
 * speeds that decide how a layer answers an impact. */
#include <getopt.h>
#include <math.h>

#include "material.h"
#include "commands.h"
#include "common.h"
#include "output.h"

static void materials_usage(FILE *f)
{
	fputs("usage: anvil materials [-f table|tsv|csv|json] [-o FILE]\n"
	      "List the built-in materials: E, nu, rho, the wave speeds c1, c2, cR,\n"
	      "the yield stress (- when unknown) and where the numbers come from.\n"
	      "  -f, --format FORMAT  table, tsv, csv or json (default: from the extension\n"
	      "                       of -o, else the table)\n"
	      "  -o, --output FILE    write to FILE (default: standard output)\n",
	      f);
}

static const struct option materials_longopts[] = {
	{"format", required_argument, NULL, 'f'},
	{"output", required_argument, NULL, 'o'},
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
	/* unknown yield: "-" in the table, nan (JSON null) for programs */
	out_grid_cell(g, "%s", out_num(b, m->yield > 0 ? m->yield * 1e-6 : NAN,
				       table ? "%.4g" : NULL));
	out_grid_cell(g, "%s", m->source ? m->source : "-");
}

static int materials_print(enum out_format fmt, const char *path)
{
	struct cli_out out;
	static const char *const head[] = {"name", "E_GPa", "nu", "rho_kg_m3", "c1_m_s",
					   "c2_m_s", "cR_m_s", "yield_MPa", "source"};
	const int ncol = (int)(sizeof head / sizeof head[0]);
	struct out_grid *g = out_grid_alloc(ncol);
	int st;
	if (!g) {
		cli_error("out of memory");
		return EXIT_FAIL;
	}
	out_grid_text(g, ncol - 1);
	for (int i = 0; i < ncol; i++)
		out_grid_cell(g, "%s", head[i]);
	for (int i = 0; i < anvil_material_count(); i++)
		materials_row(g, anvil_material_at(i), fmt);
	if (cli_out_open(&out, path)) {
		out_grid_free(g);
		return EXIT_FAIL;
	}
	st = out_grid_print(g, fmt, out.f);
	out_grid_free(g);
	if (st) {
		cli_error("materials: %s", anvil_strerror(st));
		cli_out_abort(&out);
		return EXIT_FAIL;
	}
	return cli_out_commit(&out) ? EXIT_FAIL : EXIT_OK;
}

int anvil_cmd_materials(int argc, char **argv)
{
	int c, fmt = -1;
	const char *path = NULL;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, ":f:o:h", materials_longopts, NULL)) != -1) {
		if (c == 'h') {
			materials_usage(stdout);
			return EXIT_OK;
		}
		if (c == 'o') {
			path = optarg;
			continue;
		}
		if (c != 'f')
			return out_getopt_error("materials", c, argv);
		if ((fmt = out_format_parse("materials", optarg, OUT_ALL)) < 0)
			return EXIT_USAGE;
	}
	if (optind < argc)
		return out_usage("materials", "unexpected argument '%s'", argv[optind]);
	return materials_print((enum out_format)out_format_pick(fmt, path), path);
}
