/* cmd_table.c: `anvil table`, the layout of the paper's Tables 2 and 3 with
 * our values beside the printed ones, so that every difference is in view. */
#include <getopt.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "commands.h"
#include "common.h"
#include "output.h"

#define NTHICK 5
#define NROWS 11

/* Tables 2 and 3 of Pyr'yev et al. 2024 exactly as printed (misprints
 * included: doc/paper-notes.md names them), copied from shared/paper/tables.tsv so
 * the binary needs no file at run time.  E_a in J for both tables (the
 * paper prints Table 2's in mJ).  Columns in the order of table_rows. */
static const struct paper_column {
	double V0;
	const char *v[NROWS];
} paper[2][NTHICK] = {
	{{10, {"46.00", "46.5", "17.00", "16.7", "6.856", "6.812", "3.44", "0.344", "0.6330", "0.3368", "0.538"}},
	 {10, {"41.00", "40.8", "19.00", "19.00", "9.639", "9.7345", "7.68", "0.768", "0.1582", "0.7618", "0.250"}},
	 {10, {"40.20", "39.8", "20.00", "19.65", "10.83", "10.048", "9.65", "0.965", "0.025", "0.9574", "0.0420"}},
	 {10, {"40.20", "39.6", "20.02", "19.5", "10.98", "11.26", "9.98", "0.998", "0.0063", "0.9892", "0.00244"}},
	 {10, {"40.4", "40.8", "20.02", "19.65", "11.00", "11.32", "10.0", "1.00", "0.0016", "0.9973", "0.00"}}},
	{{100, {"34.3", "34.05", "10.08", "10.00", "86.9", "87.28", "17.67", "0.177", "1.0032", "0.1782", "59.1"}},
	 {100, {"27.40", "26.3", "12.16", "11.75", "134.3", "142.45", "65.67", "0.657", "0.2508", "0.6498", "34.7"}},
	 {100, {"26.72", "25.1", "13.12", "12.4", "158.8", "172.3", "93.52", "0.935", "0.0401", "0.9333", "7.65"}},
	 {100, {"26.72", "24.5", "13.28", "12.5", "161.5", "177.8", "98.65", "0.986", "0.0100", "0.9829", "1.64"}},
	 {100, {"27.0", "24.98", "13.28", "12.5", "161.5", "179.", "99.13", "0.991", "0.0025", "0.9957", "1.06"}}},
};

/* h/r0 of the paper's columns; infinity is the half-space. */
static const double thickness[NTHICK] = {1, 2, 5, 10, INFINITY};

/* The paper's rows: unstarred ones come from the transform models (layer,
 * halfspace for h = inf), starred ones from Zener's thin plate. */
static const struct table_row {
	const char *label, *name;
	int starred;
	double scale;
	size_t off;
	const char *fmt;
} table_rows[NROWS] = {
#define TR(f) offsetof(struct anvil_result, f)
	{"t_s/us", "ts_us", 0, 1e6, TR(ts), "%.2f"},
	{"t*_s/us", "ts_star_us", 1, 1e6, TR(ts), "%.2f"},
	{"t_max/us", "tmax_us", 0, 1e6, TR(tmax), "%.2f"},
	{"t*_max/us", "tmax_star_us", 1, 1e6, TR(tmax), "%.2f"},
	{"P_max/kN", "Pmax_kN", 0, 1e-3, TR(Pmax), "%#.4g"},
	{"P*_max/kN", "Pmax_star_kN", 1, 1e-3, TR(Pmax), "%#.4g"},
	{"V_s/(m/s)", "Vs", 0, 1, TR(Vs), "%.2f"},
	{"R_f", "Rf", 0, 1, TR(Rf), "%.3f"},
	{"lambda*", "lambda_star", 1, 1, TR(lambda_star), "%.4f"},
	{"R*_f", "Rf_star", 1, 1, TR(Rf_star), "%.4f"},
	{"E_a/J", "Ea_J", 0, 1, TR(Ea), "%#.3g"},
#undef TR
};

/* Our two results for one column; ok[] is 0 where the model failed. */
struct table_cell {
	struct anvil_result r[2]; /* [0] unstarred model, [1] zener */
	int ok[2];
};

struct table_opts {
	const char *v0, *out;
	int format;
	struct cli_sets sets;
};

static void table_usage(FILE *f)
{
	fputs("usage: anvil table [--v0 V] [-f table|tsv|csv|json] [-o FILE] [-s KEY=VALUE]...\n"
	      "The paper's Tables 2 (V0 = 10 m/s) and 3 (V0 = 100 m/s): each cell is\n"
	      "\"ours (paper)\"; unstarred rows from the layer model (halfspace at\n"
	      "h = inf), starred rows from Zener's thin-plate model.\n"
	      "  -f, --format FORMAT  table, tsv, csv or json (default: from the extension\n"
	      "                       of -o, else the table)\n"
	      "  -o, --output FILE    write to FILE (default: standard output)\n",
	      f);
}

static const struct option table_longopts[] = {
	{"v0", required_argument, NULL, 'V'},
	{"format", required_argument, NULL, 'f'},
	{"output", required_argument, NULL, 'o'},
	{"set", required_argument, NULL, 's'},
	{"help", no_argument, NULL, 'h'},
	{NULL, 0, NULL, 0}};

/* -1 to go on, else the exit code. */
static int table_parse(int argc, char **argv, struct table_opts *o)
{
	int c;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, ":s:f:o:h", table_longopts, NULL)) != -1) {
		switch (c) {
		case 'V':
			o->v0 = optarg;
			break;
		case 's':
			if (cli_sets_add(&o->sets, optarg))
				return EXIT_FAIL;
			break;
		case 'f':
			o->format = out_format_parse("table", optarg, OUT_ALL);
			if (o->format < 0)
				return EXIT_USAGE;
			break;
		case 'o':
			o->out = optarg;
			break;
		case 'h':
			table_usage(stdout);
			return EXIT_OK;
		default:
			return out_getopt_error("table", c, argv);
		}
	}
	if (optind < argc)
		return out_usage("table", "unexpected argument '%s'", argv[optind]);
	o->format = out_format_pick(o->format, o->out);
	return -1;
}

/* The printed column for velocity V0 and thickness index j, or NULL. */
static const struct paper_column *paper_find(double V0, int j)
{
	for (int i = 0; i < 2; i++)
		if (fabs(V0 - paper[i][j].V0) <= 1e-9 * V0)
			return &paper[i][j];
	return NULL;
}

/* Set a key through the scene's own parser, so the scene stays consistent
 * (a thickness in r0 follows the radius, units are read as everywhere). */
static int table_set(struct anvil_scene *sc, const char *key, const char *value,
		     const char *origin)
{
	struct anvil_err err = {0};
	int st = anvil_scene_set(sc, key, value, origin, 0, &err);
	if (st)
		cli_error("%s", err.msg[0] ? err.msg : anvil_strerror(st));
	return st;
}

static int table_thickness(struct anvil_scene *sc, double h_r0)
{
	char h[32] = "inf";
	if (!isinf(h_r0))
		snprintf(h, sizeof h, "%g r0", h_r0);
	return table_set(sc, "layer.thickness", h, "table");
}

/* Run both models for one column.  A failed model leaves ok[k] = 0 and its
 * first message in *why (printed once at the end). */
static void table_compute(struct anvil_solver *s, const struct anvil_scene *sc,
			  struct table_cell *cell, char *why, size_t whylen)
{
	enum anvil_model m[2] = {isinf(anvil_scene_h(sc)) ? ANVIL_MODEL_HALFSPACE
							   : ANVIL_MODEL_LAYER,
				 ANVIL_MODEL_ZENER};
	for (int k = 0; k < 2; k++) {
		struct anvil_err err = {0};
		struct cli_progress prog = {0};
		anvil_solver_set_progress(s, cli_progress_cb, &prog);
		int st = cli_run_model(s, sc, m[k], 0, &cell->r[k], &err);
		cli_progress_done(&prog);
		/* a warning (WTOL) still carries the best values: show them. */
		cell->ok[k] = st >= 0;
		if (st && !why[0])
			snprintf(why, whylen, "%s: %s", anvil_model_name(m[k]),
				 err.msg[0] ? err.msg : anvil_strerror(st));
	}
}

static double table_ours(const struct table_cell *cell, const struct table_row *row)
{
	int k = row->starred;
	if (!cell->ok[k])
		return NAN;
	const char *p = (const char *)&cell->r[k] + row->off;
	return row->scale * *(const double *)(const void *)p;
}

static void table_human(struct out_grid *g, const struct table_cell *cells, double V0)
{
	char b[40];
	out_grid_cell(g, "V0 = %g m/s", V0);
	for (int j = 0; j < NTHICK; j++)
		out_grid_cell(g, isinf(thickness[j]) ? "h = inf" : "h = %g r0", thickness[j]);
	for (int i = 0; i < NROWS; i++) {
		out_grid_cell(g, "%s", table_rows[i].label);
		for (int j = 0; j < NTHICK; j++) {
			const struct paper_column *p = paper_find(V0, j);
			double x = table_ours(&cells[j], &table_rows[i]);
			out_grid_cell(g, "%s (%s)", isnan(x) ? "n/a" : out_num(b, x, table_rows[i].fmt),
				      p ? p->v[i] : "-");
		}
	}
}

static void table_machine(struct out_grid *g, const struct table_cell *cells, double V0)
{
	char b[40], h[40];
	for (int i = 0; i < NROWS; i++) {
		for (int j = 0; j < NTHICK; j++) {
			const struct paper_column *p = paper_find(V0, j);
			out_grid_cell(g, "%s", out_num(b, V0, NULL));
			out_grid_cell(g, "%s", table_rows[i].name);
			out_grid_cell(g, "%s", out_num(h, thickness[j], NULL));
			out_grid_cell(g, "%s", out_num(b, table_ours(&cells[j], &table_rows[i]), NULL));
			out_grid_cell(g, "%s", p ? p->v[i] : "nan");
		}
	}
}

static void table_free(struct table_cell *cells, int n)
{
	for (int j = 0; j < n; j++)
		for (int k = 0; k < 2; k++)
			anvil_result_free(&cells[j].r[k]);
}

/* The human table of one velocity goes out at once; machine rows gather
 * in *all (one header, one JSON array for both velocities). */
static int table_print(const struct table_cell *cells, double V0, enum out_format fmt,
		       int first, struct out_grid **all, FILE *f)
{
	static const char *const head[] = {"V0_m_s", "quantity", "h_r0", "ours", "paper"};
	int st = ANVIL_OK;
	if (fmt != OUT_TABLE) {
		if (!*all && (*all = out_grid_alloc(5)) != NULL) {
			out_grid_text(*all, 1);
			for (int i = 0; i < 5; i++)
				out_grid_cell(*all, "%s", head[i]);
		}
		if (!*all)
			st = ANVIL_ENOMEM;
		else
			table_machine(*all, cells, V0);
	} else {
		struct out_grid *g = out_grid_alloc(1 + NTHICK);
		table_human(g, cells, V0);
		if (!first)
			fputc('\n', f);
		st = out_grid_print(g, fmt, f);
		out_grid_free(g);
	}
	if (st && st != ANVIL_EIO) /* a write: said with its file (anvil_cmd_table) */
		cli_error("table: %s", anvil_strerror(st));
	return st;
}

/* One table (one velocity): compute every column, then print.  Returns a
 * core status; a model failing is not one (its cells say n/a). */
static int table_one(struct anvil_solver *s, struct anvil_scene sc, const char *v0,
		     enum out_format fmt, int first, struct out_grid **all, FILE *f,
		     char *why, size_t whylen)
{
	struct table_cell cells[NTHICK];
	int st = table_set(&sc, "impact.velocity", v0, "--v0"), n = 0;
	memset(cells, 0, sizeof cells);
	for (; !st && n < NTHICK; n++) {
		struct anvil_scene col = sc;
		st = table_thickness(&col, thickness[n]);
		if (!st)
			table_compute(s, &col, &cells[n], why, whylen);
	}
	if (!st)
		st = table_print(cells, sc.velocity, fmt, first, all, f);
	table_free(cells, n);
	return st;
}

/* Both tables (or the one of --v0) into out. */
static int table_all(struct anvil_solver *s, const struct anvil_scene *sc,
		     const struct table_opts *o, FILE *f, char *why, size_t whylen)
{
	static const char *const both[] = {"10 m/s", "100 m/s"};
	struct out_grid *all = NULL;
	enum out_format fmt = (enum out_format)o->format;
	int st = ANVIL_OK;
	/* One solver for both tables: layer responses are reused across V0. */
	for (int i = 0; !st && i < 2; i++)
		if (!o->v0 || i == 0)
			st = table_one(s, *sc, o->v0 ? o->v0 : both[i], fmt, i == 0, &all, f,
				       why, whylen);
	if (!st && all && (st = out_grid_print(all, fmt, f)) && st != ANVIL_EIO)
		cli_error("table: %s", anvil_strerror(st));
	out_grid_free(all);
	if (!st && fmt == OUT_TABLE)
		fprintf(f, "\nours (paper): paper values in parentheses; doc/paper-notes.md (in the\n"
			"source) lists the known misprints.\n"
			"Unstarred rows: model layer (halfspace at h = inf); starred rows: zener.\n");
	return st;
}

int anvil_cmd_table(int argc, char **argv)
{
	struct table_opts o = {.format = -1};
	struct anvil_scene sc;
	struct anvil_solver *s = NULL;
	struct cli_out out = {0};
	char why[ANVIL_ERR_MSG + 32] = "";
	int code = table_parse(argc, argv, &o), st = ANVIL_OK;
	if (code >= 0)
		goto done;
	if ((st = cli_scene(&sc, NULL, o.sets.v, o.sets.n)))
		goto done;
	sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's tables: its contact model */
	if ((st = cli_out_open(&out, o.out)))
		goto done;
	if (!(s = anvil_solver_alloc())) {
		cli_error("out of memory");
		st = ANVIL_ENOMEM;
		goto done;
	}
	st = table_all(s, &sc, &o, out.f, why, sizeof why);
	if (st == ANVIL_EIO) /* qa7: was "table: input/output error" */
		cli_write_failed(o.out);
	if (!st)
		st = cli_out_commit(&out);
done:
	cli_out_abort(&out);
	if (code < 0)
		code = st ? cli_exit_code(st) : why[0] ? EXIT_FAIL : EXIT_OK;
	if (!st && why[0])
		cli_error("%s (its cells show n/a)", why);
	anvil_solver_free(s);
	cli_sets_free(&o.sets);
	return code;
}
