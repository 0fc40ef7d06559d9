/* cmd_run.c: `anvil run`, one impact computed with every model the scene
 * asks for, printed as a table, TSV, CSV or JSON. */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "plan.h"
#include "commands.h"
#include "common.h"
#include "output.h"
#include "plot.h"
#include "verdict.h"

/* Samples per model in --history and the charts. */
#define RUN_NHIST ANVIL_VERDICT_NHIST /* 400: the verdict takes the layer row with them (verdict.h) */

struct run_opts {
	const char *scene, *out, *history, *png;
	char *models;   /* "solver.models=..." built from -m, owned */
	int format, verbose, quiet;
	struct cli_sets sets;
};

static void run_usage(FILE *f)
{
	fputs("usage: anvil run [SCENE] [-s KEY=VALUE]... [--format table|tsv|csv|json]\n"
	      "                 [-o FILE] [--history FILE] [--png DIR] [-m MODELS] [-v] [-q]\n"
	      "Compute one impact with every model of the scene (default: the paper's\n"
	      "copper rod on a 1 r0 steel layer at 10 m/s).\n"
	      "  -s, --set KEY=VALUE  change a scene key, e.g. -s layer.thickness=5r0\n"
	      "  -f, --format FORMAT  table, tsv, csv or json (default: from the extension\n"
	      "                       of -o, .tsv .csv .json; else the table)\n"
	      "  -o, --output FILE    write the results to FILE (default: standard output)\n"
	      "      --history FILE   write the time histories of every model as TSV\n"
	      "                       ('-': standard output, when the results go to -o)\n"
	      "      --png DIR        write force, velocity and deflection charts into DIR\n"
	      "  -m, --models LIST    models to run, e.g. hertz,zener (as -s solver.models=)\n"
	      "  -v, --verbose        print the resolved scene, the plan and timings on stderr\n"
	      "  -q, --quiet          no progress, plan warnings, verdict or notes (errors\n"
	      "                       and warnings on values and accuracy still print)\n",
	      f);
}

static const struct option run_longopts[] = {
	{"set", required_argument, NULL, 's'},
	{"format", required_argument, NULL, 'f'},
	{"output", required_argument, NULL, 'o'},
	{"history", required_argument, NULL, 'H'},
	{"png", required_argument, NULL, 'P'},
	{"models", required_argument, NULL, 'm'},
	{"verbose", no_argument, NULL, 'v'},
	{"quiet", no_argument, NULL, 'q'},
	{"help", no_argument, NULL, 'h'},
	{NULL, 0, NULL, 0}};

static int run_models_set(struct run_opts *o, const char *list)
{
	size_t n = strlen(list) + sizeof "solver.models=";
	free(o->models);
	o->models = malloc(n);
	if (!o->models)
		return ANVIL_ENOMEM;
	snprintf(o->models, n, "solver.models=%s", list);
	return ANVIL_OK;
}

static int run_option(struct run_opts *o, int c, char **argv)
{
	switch (c) {
	case 's':
		return cli_sets_add(&o->sets, optarg) ? EXIT_FAIL : -1;
	case 'f':
		o->format = out_format_parse("run", optarg, OUT_ALL);
		return o->format < 0 ? EXIT_USAGE : -1;
	case 'o':
		o->out = optarg;
		return -1;
	case 'H':
		o->history = optarg;
		return -1;
	case 'P':
		o->png = optarg;
		return -1;
	case 'm':
		return run_models_set(o, optarg) ? EXIT_FAIL : -1;
	case 'v':
		o->verbose = 1;
		return -1;
	case 'q':
		o->quiet = 1;
		return -1;
	case 'h':
		run_usage(stdout);
		return EXIT_OK;
	}
	return out_getopt_error("run", c, argv);
}

/* -1 to go on, else the exit code. */
static int run_parse(int argc, char **argv, struct run_opts *o)
{
	int c, code;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, ":s:f:o:m:vqh", run_longopts, NULL)) != -1)
		if ((code = run_option(o, c, argv)) >= 0)
			return code;
	if (optind < argc)
		o->scene = argv[optind++];
	if (optind < argc)
		return out_usage("run", "unexpected argument '%s'", argv[optind]);
	if (o->quiet && o->verbose)
		return out_usage("run", "-q and -v contradict each other: give one");
	o->format = out_format_pick(o->format, o->out);
	/* -m comes last so that it wins over any -s solver.models. */
	if (o->models && cli_sets_add(&o->sets, o->models))
		return EXIT_FAIL;
	return -1;
}

struct run_progress {
	struct cli_progress shown;
	int quiet;
};

static int run_progress_cb(void *ctx, double fraction, const char *what)
{
	struct run_progress *p = ctx;
	return p->quiet ? 0 : cli_progress_cb(&p->shown, fraction, what);
}

/* Run every model of the scene into res (n of them, each to be freed).
 * Returns the exit code so far; *tol is set when a model missed its
 * accuracy but still gave values. */
/* "MODEL: message", without repeating the model when the core's message
 * already starts with it. */
static const char *model_message(enum anvil_model m, const struct anvil_err *err, int st)
{
	static char buf[ANVIL_ERR_MSG + 32];
	const char *msg = err->msg[0] ? err->msg : anvil_strerror(st);
	snprintf(buf, sizeof buf, "%s: %s", anvil_model_name(m), cli_model_reason(m, msg));
	return buf;
}

/* The solver's warnings (a corrupt cache file ignored...) are not errors. */
static void run_warn(void *ctx, const char *msg)
{
	(void)ctx;
	cli_error("warning: %s", msg);
}

/* A row that failed: every value NaN (printed "-", never a zero taken for
 * a result), its reason as the row's note. */
static void run_failed_row(struct anvil_result *r)
{
	struct anvil_val none = {NAN, NAN};
	r->ts = r->tmax = r->Pmax = r->Vs = r->Rf = r->Ea = none;
	r->lambda_star = r->Rf_star = NAN;
	r->ncontacts = 0;
	anvil_result_free(r); /* the history: a failed row has none */
	snprintf(r->note, sizeof r->note, "not computed: %.290s",
		 cli_model_reason(r->model, r->why[0] ? r->why : "failed"));
}

static int run_models(struct anvil_solver *s, const struct anvil_plan *pl,
		      const struct anvil_scene *sc, const struct run_opts *o,
		      struct anvil_result *res, int *n, int *tol, int *failed)
{
	struct run_progress prog = {.quiet = o->quiet};
	size_t nhist = o->history || o->png ? RUN_NHIST : 0;
	int code = EXIT_OK;
	anvil_solver_set_progress(s, run_progress_cb, &prog);
	anvil_solver_set_warn(s, run_warn, NULL);
	/* each model; with [effects] contact = both, the paper's layer and
	 * halfspace rows before the physical ones */
	for (int k = 0; k < 2 * ANVIL_MODEL_COUNT && code == EXIT_OK; k++) {
		struct anvil_err err = {0};
		int m = k / 2, paper = k % 2 == 0;
		if (!(anvil_scene_models(sc) & (1u << m)) || (paper && !pl->paper[m].run))
			continue;
		memset(&prog.shown, 0, sizeof prog.shown);
		/* no row's values depend on its history (the error runs keep
		 * their passes' nodes, impact.h hist_nodes): the row the verdict
		 * reads carries its samples, and a quasi-static verdict then
		 * needs no second run (yield.c quasi_static_verdict) */
		size_t nh = !paper && !o->quiet && m == (int)anvil_verdict_model(pl) ? RUN_NHIST : nhist;
		int st = anvil_solver_run_contact(s, pl, (enum anvil_model)m,
						  paper ? ANVIL_CONTACT_PAPER : ANVIL_CONTACT_AUTO,
						  nh, &res[*n], &err);
		cli_progress_done(&prog.shown);
		(*n)++;
		if (st > 0) {
			/* The values are there, with their error estimates: show them,
			 * but do not let a script take them for converged ones. */
			cli_error("warning: %s", model_message((enum anvil_model)m, &err, st));
			*tol = 1;
		} else if (st) {
			/* A failure has no values: its row says why, and the other
			 * models still run and print (the exit status says it). */
			cli_error("%s", model_message((enum anvil_model)m, &err, st));
			run_failed_row(&res[*n - 1]);
			*failed = 1;
		} else if (o->verbose) {
			fprintf(stderr, "anvil: %s: %.3g s\n",
				anvil_model_name((enum anvil_model)m), res[*n - 1].seconds);
		}
	}
	/* prog dies with this frame: the solver runs on (the verdict) without it */
	anvil_solver_set_progress(s, NULL, NULL);
	return code;
}

/* Fill an open output and push it to the disk without committing it, so
 * that a full disk shows up before any file is put in place; a write that
 * failed while filling (st, ANVIL_EIO: output larger than the stream's
 * buffer) is said too (qa7: --history /dev/full exited 1 without a word). */
static int run_fill(struct cli_out *o, const char *path, int st)
{
	if (st == ANVIL_EIO || (!st && (fflush(o->f) != 0 || ferror(o->f)))) {
		cli_write_failed(path);
		st = ANVIL_EIO;
	}
	return st;
}

/* Write both outputs, then put them in place: files are filled and
 * flushed first and standard output is written last, so a failure leaves
 * no file behind and prints no half result. */
static int run_write(const struct anvil_scene *sc, const struct run_opts *o,
		     const struct anvil_result *res, int n, struct cli_out *out,
		     struct cli_out *hist)
{
	enum out_format fmt = (enum out_format)o->format;
	int to_file = out->f != stdout, st = ANVIL_OK;
	if (o->history)
		st = run_fill(hist, o->history, out_history(hist->f, res, n));
	if (!st && to_file)
		st = run_fill(out, o->out, out_results(out->f, fmt, sc, res, n));
	if (!st && o->history)
		st = cli_out_commit(hist);
	/* the table on standard output: its own write failure said here (a
	 * history's was said by run_fill: not again as standard output's) */
	if (!st && !to_file && sc->output.table &&
	    (st = out_results(out->f, fmt, sc, res, n)) == ANVIL_EIO)
		cli_write_failed(NULL);
	if (!st)
		st = cli_out_commit(out);
	if (st) {
		cli_out_abort(hist);
		cli_out_abort(out);
		if (st == ANVIL_ENOMEM)
			cli_error("out of memory");
	}
	return st ? EXIT_FAIL : EXIT_OK;
}

static int run_png(const struct anvil_scene *sc, const struct run_opts *o,
		   const struct anvil_result *res, int n)
{
	char paths[4096] = "";
	struct anvil_err err = {0};
	if (plot_run_charts(o->png, sc, res, n, paths, sizeof paths, &err)) {
		cli_error("%s", err.msg);
		return EXIT_FAIL;
	}
	if (!o->quiet && paths[0])
		fprintf(stderr, "%s%s", paths, paths[strlen(paths) - 1] == '\n' ? "" : "\n");
	return EXIT_OK;
}

/* The plan the rows will run from, before the work, on stderr: with -v
 * the whole of it, else (not with -q) its warnings (super-seismic, out of
 * range), one line each; the verdict is run_verdict's. */
static void run_plan(const struct anvil_plan *pl, const struct run_opts *o)
{
	if (o->quiet)
		return;
	if (o->verbose) {
		fputs("# plan\n", stderr);
		anvil_plan_print(stderr, pl);
	} else {
		anvil_plan_warnings_line(stderr, pl, "anvil: warning: ");
	}
}

/* The verdict on the layer (verdict.h), one line on stderr (not with -q),
 * and a second on the impactor when it yields or cracks:
 * from the layer or half-space row's field when the run has that row (the
 * solver's cache holds its responses), else quasi-static Hertz.  A failed
 * verdict is said, and does not fail the run. */
static void run_verdict(struct anvil_solver *s, const struct anvil_plan *pl,
			const struct anvil_result *res, int n, const struct run_opts *o)
{
	struct anvil_verdict v;
	struct anvil_err err = {0};
	char line[ANVIL_VERDICT_TEXT_MAX];
	struct run_progress prog = {.quiet = o->quiet};
	if (o->quiet)
		return;
	/* the layer (half-space) row as the plan runs it, already computed
	 * (a quasi-static verdict is at its P_max: no second run) */
	const struct anvil_result *layer = NULL;
	enum anvil_model vm = anvil_verdict_model(pl);
	for (int i = 0; i < n && !layer; i++)
		if (res[i].model == vm && res[i].contact == pl->row[vm].contact)
			layer = &res[i];
	unsigned waves = (1u << ANVIL_MODEL_LAYER) | (1u << ANVIL_MODEL_HALFSPACE);
	/* a searched field takes seconds on a plate at speed: shown as the
	 * rows' work is (prog dies with this frame: unset after) */
	anvil_solver_set_progress(s, run_progress_cb, &prog);
	int st = pl->pb.run & waves ? anvil_solver_verdict_with(s, pl, layer, &v, &err)
				    : anvil_verdict_make(&pl->pb, NULL, &v, &err);
	cli_progress_done(&prog.shown);
	anvil_solver_set_progress(s, NULL, NULL);
	if (st < 0) {
		cli_error("warning: no verdict on the layer: %s",
			  err.msg[0] ? err.msg : anvil_strerror(st));
		return;
	}
	anvil_verdict_text(&v, line, sizeof line);
	cli_error("%s", line);
	if (v.imp.fate == ANVIL_HERTZ_ELASTIC)
		return; /* the impactor's line only when it fails: one line otherwise */
	anvil_verdict_impactor_text(&v, line, sizeof line);
	cli_error("%s", line);
}

/* R_f outside [0, 1] (beyond its error estimate) is no rebound: the
 * contact ended with the impactor still moving into the layer, which will
 * strike again.  Said in the row's note and on stderr; returns 1 if any. */
static int run_unphysical(struct anvil_result *res, int n)
{
	static const char why[] = "R_f outside 0..1: the contact ends with the impactor "
				  "still moving in: re-contact not modelled";
	int any = 0;
	for (int i = 0; i < n; i++) {
		struct anvil_result *r = &res[i];
		double tol = (isfinite(r->Rf.err) ? fabs(r->Rf.err) : 0) + 1e-9;
		if (!isfinite(r->Rf.val) || (r->Rf.val >= -tol && r->Rf.val <= 1 + tol))
			continue;
		size_t len = strlen(r->note);
		snprintf(r->note + len, sizeof r->note - len, "%s%s", len ? "; " : "", why);
		cli_error("warning: %s: %s", anvil_model_name(r->model), why);
		any = 1;
	}
	return any;
}

/* The model's layer is unbounded: when its bending spreads over more than
 * RUN_REACH_WARN thicknesses during the contact, a real plate's size and
 * supports are likely to matter; one line on stderr (not with -q).  The
 * paper's own case spreads over 8.6 h. */
#define RUN_REACH_WARN 10.0
static void run_reach(const struct anvil_scene *sc, const struct anvil_result *res, int n,
		      const struct run_opts *o)
{
	const struct anvil_result *r = out_reach_row(res, n);
	double h = anvil_scene_h(sc);
	if (o->quiet || !r || !(r->reach_bend > RUN_REACH_WARN * h))
		return;
	char ts[24], lb[24], l2[24];
	cli_error("warning: %s: during the %s contact the bending spreads over %s (%.3g h): the "
		  "result is an unbounded layer's; a plate narrower than %s, or supported within %s "
		  "of the impact, answers otherwise",
		  anvil_model_name(r->model), out_duration(ts, sizeof ts, r->ts.val),
		  out_length(lb, sizeof lb, r->reach_bend), r->reach_bend / h,
		  out_length(l2, sizeof l2, 2.0 * r->reach_bend), lb);
}

/* The scene's [output] for what the command line leaves unset. */
static void run_output(struct run_opts *o, const struct anvil_scene *sc)
{
	if (!o->history && sc->output.histories[0])
		o->history = sc->output.histories;
	if (!o->png && sc->output.charts[0])
		o->png = sc->output.charts;
}

static int run_scene(struct run_opts *o)
{
	struct anvil_scene sc;
	struct anvil_result res[2 * ANVIL_MODEL_COUNT]; /* a paper twin per model at most */
	struct cli_out out = {0}, hist = {0};
	int n = 0, tol = 0, failed = 0, code;
	int st = cli_scene_q(&sc, o->scene, o->sets.v, o->sets.n, o->quiet);
	if (st)
		return cli_exit_code(st);
	if (!anvil_scene_models(&sc)) {
		cli_error("no model to run (set solver.models or use -m; [effects] may switch them off)");
		return EXIT_USAGE;
	}
	if (o->verbose && anvil_scene_write(&sc, stderr))
		return EXIT_FAIL;
	run_output(o, &sc);
	/* [output] field is only written for a map: points need --at */
	if (sc.output.field[0] && sc.effects.field != ANVIL_FIELDMODE_MAP) {
		cli_error("run: [output] field = %s needs [effects] field = map (the field at "
			  "points: anvil field --at)", sc.output.field);
		return EXIT_USAGE;
	}
	/* Two tables mixed on one stream would parse as neither. */
	if (o->history && !strcmp(o->history, "-") && (!o->out || !strcmp(o->out, "-")) &&
	    sc.output.table) {
		cli_error("run: the history and the results cannot both go to standard output: "
			  "give -o FILE for the results (or [output] table = off)");
		return EXIT_USAGE;
	}
	/* The scene read once into a plan: -v prints it, every row runs it. */
	struct anvil_plan pl;
	struct anvil_err err = {0};
	struct anvil_solver *s = anvil_solver_alloc();
	if (!s) {
		cli_error("out of memory");
		return EXIT_FAIL;
	}
	if ((st = cli_plan(&sc, anvil_solver_cache(s), &pl, &err))) {
		cli_error("%s", err.msg[0] ? err.msg : anvil_strerror(st));
		anvil_solver_free(s);
		return cli_exit_code(st);
	}
	run_plan(&pl, o);
	/* Open the outputs first: a bad path fails before minutes of work. */
	if (cli_out_open(&out, o->out)) {
		anvil_solver_free(s);
		return EXIT_FAIL;
	}
	if (o->history && cli_out_open(&hist, o->history)) {
		cli_out_abort(&out);
		anvil_solver_free(s);
		return EXIT_FAIL;
	}
	code = run_models(s, &pl, &sc, o, res, &n, &tol, &failed);
	if (!code)
		run_verdict(s, &pl, res, n, o);
	anvil_solver_free(s);
	if (!code) {
		tol |= run_unphysical(res, n);
		run_reach(&sc, res, n, o);
	}
	if (code) {
		cli_out_abort(&hist);
		cli_out_abort(&out);
	} else {
		code = run_write(&sc, o, res, n, &out, &hist);
	}
	if (!code && o->png)
		code = run_png(&sc, o, res, n);
	if (!code && sc.output.field[0])
		code = anvil_field_map_file(&sc, sc.output.field, o->quiet);
	for (int i = 0; i < n; i++)
		anvil_result_free(&res[i]);
	return code ? code : tol || failed ? EXIT_FAIL : EXIT_OK;
}

int anvil_cmd_run(int argc, char **argv)
{
	struct run_opts o = {.format = -1};
	int code = run_parse(argc, argv, &o);
	if (code < 0)
		code = run_scene(&o);
	cli_sets_free(&o.sets);
	free(o.models);
	return code;
}
