/* cmd_accuracy.c: `anvil accuracy`, one model at every accuracy level, to
 * show what each level costs and whether it keeps its promised error. */
#include <getopt.h>
#include <math.h>
#include <string.h>

#include "commands.h"
#include "common.h"
#include "output.h"

struct acc_opts {
	const char *scene, *model, *out;
	int format;
	struct cli_sets sets;
};

/* One level's run: the values and their estimated relative errors. */
struct acc_level {
	struct anvil_result r;
	double wall;     /* seconds, solver made fresh for the level */
	double rel[3];   /* P_max, t_s, R_f */
	int status;      /* of anvil_solver_run */
};

static void acc_usage(FILE *f)
{
	fputs("usage: anvil accuracy [SCENE] [-s KEY=VALUE]... [-f table|tsv|csv|json]\n"
	      "                      [-o FILE] [-m MODEL]\n"
	      "Run one model (default: layer; halfspace when h = inf) at every accuracy\n"
	      "level and compare each with the next finer one (the reference level with\n"
	      "its own error estimate).  Each level is timed cold: a fresh solver without\n"
	      "the disk cache.  Exits 1 if a level misses its target.\n"
	      "  -f, --format FORMAT  table, tsv, csv or json (default: from the extension\n"
	      "                       of -o, else the table)\n"
	      "  -o, --output FILE    write to FILE (default: standard output)\n",
	      f);
}

static const struct option acc_longopts[] = {
	{"set", required_argument, NULL, 's'},
	{"format", required_argument, NULL, 'f'},
	{"output", required_argument, NULL, 'o'},
	{"model", required_argument, NULL, 'm'},
	{"help", no_argument, NULL, 'h'},
	{NULL, 0, NULL, 0}};

/* -1 to go on, else the exit code. */
static int acc_parse(int argc, char **argv, struct acc_opts *o)
{
	int c;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, ":s:f:o:m:h", acc_longopts, NULL)) != -1) {
		switch (c) {
		case 's':
			if (cli_sets_add(&o->sets, optarg))
				return EXIT_FAIL;
			break;
		case 'f':
			o->format = out_format_parse("accuracy", optarg, OUT_ALL);
			if (o->format < 0)
				return EXIT_USAGE;
			break;
		case 'o':
			o->out = optarg;
			break;
		case 'm':
			o->model = optarg;
			break;
		case 'h':
			acc_usage(stdout);
			return EXIT_OK;
		default:
			return out_getopt_error("accuracy", c, argv);
		}
	}
	if (optind < argc)
		o->scene = argv[optind++];
	if (optind < argc)
		return out_usage("accuracy", "unexpected argument '%s'", argv[optind]);
	o->format = out_format_pick(o->format, o->out);
	return -1;
}

static int acc_run_level(struct anvil_scene sc, enum anvil_model m,
			 enum anvil_accuracy a, struct acc_level *lv)
{
	struct anvil_err err = {0};
	struct cli_progress prog = {0};
	/* A fresh solver per level, its disk cache off: the time must include
	 * making the layer response, not a hit in memory from the level before
	 * or on disk from an earlier run (which made a warm run look free). */
	struct anvil_solver *s = anvil_solver_alloc();
	if (!s || anvil_solver_set_cache_dir(s, NULL, &err)) {
		anvil_solver_free(s);
		anvil_result_init(&lv->r, m);
		cli_error("out of memory");
		return lv->status = ANVIL_ENOMEM;
	}
	anvil_solver_set_progress(s, cli_progress_cb, &prog);
	sc.accuracy = a;
	double t0 = cli_now();
	lv->status = cli_run_model(s, &sc, m, 0, &lv->r, &err);
	lv->wall = cli_now() - t0;
	cli_progress_done(&prog);
	anvil_solver_free(s);
	if (lv->status < 0)
		cli_error("%s at accuracy %s: %s", anvil_model_name(m), anvil_accuracy_name(a),
			  err.msg[0] ? err.msg : anvil_strerror(lv->status));
	return lv->status > 0 ? ANVIL_OK : lv->status;
}

/* Differences and estimates below OUT_ERR_NOISE are rounding: 0. */
static double noise_zero(double rel)
{
	return rel < OUT_ERR_NOISE ? 0.0 : rel;
}

static double rel_diff(double x, double ref)
{
	return noise_zero(fabs(x - ref) / fabs(ref));
}

/* Against the next finer level; the finest against its own estimate. */
static void acc_estimate(struct acc_level *lv, int l)
{
	const struct anvil_result *r = &lv[l].r;
	if (l + 1 < ANVIL_ACC_COUNT) {
		const struct anvil_result *f = &lv[l + 1].r;
		lv[l].rel[0] = rel_diff(r->Pmax.val, f->Pmax.val);
		lv[l].rel[1] = rel_diff(r->ts.val, f->ts.val);
		lv[l].rel[2] = rel_diff(r->Rf.val, f->Rf.val);
	} else {
		lv[l].rel[0] = noise_zero(fabs(r->Pmax.err / r->Pmax.val));
		lv[l].rel[1] = noise_zero(fabs(r->ts.err / r->ts.val));
		lv[l].rel[2] = noise_zero(fabs(r->Rf.err / r->Rf.val));
	}
}

/* "ok", "MISSED", or "n/a" when the model gives no estimate to judge;
 * "MISSED: model" when the numerics meet the target (against the next
 * finer level; the finest, own, by its estimate less the model's error)
 * and the row's own estimate misses it by the model's error (result.h,
 * model_err), which no finer level lowers. */
static const char *acc_verdict(const struct acc_level *lv, double target, int own)
{
	int known = 0, missed = 0;
	/* the finest level's errors are its own estimate: the model's in it */
	double m = own ? lv->r.model_err : 0.0;
	for (int i = 0; i < 3; i++) {
		if (isnan(lv->rel[i]))
			continue;
		known = 1;
		missed |= lv->rel[i] - m > target;
	}
	if (!missed && lv->status == ANVIL_WTOL)
		return lv->r.model_err > target ? "MISSED: model" : "MISSED";
	return missed ? "MISSED" : known ? "ok" : "n/a";
}

static int acc_print(struct acc_level *lv, enum anvil_model m, enum out_format fmt,
		     FILE *f)
{
	static const char *const head[] = {"level", "target", "time_s", "Pmax_kN", "ts_us",
					   "Rf", "Pmax_rel_err", "ts_rel_err", "Rf_rel_err",
					   "status"};
	static const char *const label[] = {"level", "target", "time/s", "P_max/kN", "t_s/us",
					    "R_f", "err P_max", "err t_s", "err R_f", "status"};
	const int ncol = (int)(sizeof head / sizeof head[0]), t = fmt == OUT_TABLE;
	struct out_grid *g = out_grid_alloc(ncol);
	int missed = 0;
	double model = 0;
	char b[40];
	out_grid_text(g, ncol - 1);
	for (int i = 0; i < ncol; i++)
		out_grid_cell(g, "%s", t ? label[i] : head[i]);
	for (int l = 0; l < ANVIL_ACC_COUNT; l++) {
		double target = anvil_accuracy_target((enum anvil_accuracy)l);
		const char *v = acc_verdict(&lv[l], target, l == ANVIL_ACC_COUNT - 1);
		missed |= !strncmp(v, "MISSED", 6);
		if (!strcmp(v, "MISSED: model"))
			model = fmax(model, lv[l].r.model_err);
		out_grid_cell(g, "%s", anvil_accuracy_name((enum anvil_accuracy)l));
		out_grid_cell(g, "%s", out_num(b, target, t ? "%.0e" : NULL));
		out_grid_cell(g, "%s", out_num(b, lv[l].wall, t ? "%.3g" : NULL));
		out_grid_cell(g, "%s", out_num(b, lv[l].r.Pmax.val * 1e-3, t ? "%.7g" : NULL));
		out_grid_cell(g, "%s", out_num(b, lv[l].r.ts.val * 1e6, t ? "%.7g" : NULL));
		out_grid_cell(g, "%s", out_num(b, lv[l].r.Rf.val, t ? "%.7g" : NULL));
		for (int i = 0; i < 3; i++)
			out_grid_cell(g, "%s", out_err(b, lv[l].rel[i], t ? "%.1e" : NULL));
		out_grid_cell(g, "%s", v);
	}
	int st = out_grid_print(g, fmt, f);
	out_grid_free(g);
	if (!st && t)
		fprintf(f, "\nmodel %s; errors relative, each level against the next finer one,\n"
			"the reference level by its own estimate (below %.0e: rounding, shown as 0);\n"
			"times cold (no disk cache)\n",
			anvil_model_name(m), OUT_ERR_NOISE);
	if (!st && t && model > 0)
		fprintf(f, "MISSED: model: the numerics meet the target, but the model's own error\n"
			"(%.1e relative: what the physical contact's remainder leaves out, its\n"
			"third order and the contact's supersonic start, or the reflections the\n"
			"row leaves out) is above it: no finer level lowers it\n",
			model);
	if (st) {
		cli_error("accuracy: %s", anvil_strerror(st));
		return -1;
	}
	return missed ? EXIT_FAIL : EXIT_OK;
}

static int acc_model(const struct acc_opts *o, const struct anvil_scene *sc)
{
	if (!o->model)
		return isinf(anvil_scene_h(sc)) ? ANVIL_MODEL_HALFSPACE : ANVIL_MODEL_LAYER;
	int m = anvil_model_parse(o->model);
	if (m < 0)
		out_usage("accuracy", "-m: unknown model '%s'; one of: hertz, zener, layer, halfspace",
			  o->model);
	return m;
}

static int acc_main(const struct acc_opts *o)
{
	struct anvil_scene sc;
	struct acc_level lv[ANVIL_ACC_COUNT];
	struct cli_out out;
	int st = cli_scene(&sc, o->scene, o->sets.v, o->sets.n), code = EXIT_FAIL, n = 0;
	if (st)
		return cli_exit_code(st);
	int m = acc_model(o, &sc);
	if (m < 0)
		return EXIT_USAGE;
	/* opened first: a bad path fails before the work */
	if (cli_out_open(&out, o->out))
		return EXIT_FAIL;
	memset(lv, 0, sizeof lv);
	for (st = ANVIL_OK; !st && n < ANVIL_ACC_COUNT; n++)
		st = acc_run_level(sc, (enum anvil_model)m, (enum anvil_accuracy)n, &lv[n]);
	if (!st) {
		for (int l = 0; l < ANVIL_ACC_COUNT; l++)
			acc_estimate(lv, l);
		code = acc_print(lv, (enum anvil_model)m, (enum out_format)o->format, out.f);
		if (code < 0 || cli_out_commit(&out))
			code = EXIT_FAIL;
	}
	cli_out_abort(&out);
	for (int l = 0; l < n; l++)
		anvil_result_free(&lv[l].r);
	return code;
}

int anvil_cmd_accuracy(int argc, char **argv)
{
	struct acc_opts o = {.format = -1};
	int code = acc_parse(argc, argv, &o);
	if (code < 0)
		code = acc_main(&o);
	cli_sets_free(&o.sets);
	return code;
}
