/* cmd_plot.c: `anvil plot KIND [SCENE] [-s KEY=VALUE]... -o FILE.png`.
 *
 * Runs the models each chart needs (the paper's cases unless a scene fixes
 * them), hands the results to the builders of plot.c and renders the
 * chart with gnuplot.  A model that fails is left out of the chart and
 * reported once on stderr, so the chart shows whatever was computed. */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "params.h"
#include "zener.h"
#include "commands.h"
#include "common.h"
#include "plot.h"

/* Samples kept per history: smooth at any PNG size anvil allows. */
#define PLOT_NHIST 400
#define BATCH_MAX 64
#define SIZE_MIN 100
#define SIZE_MAX_PX 10000

/* The paper's cases: Tables 2-3 and Figs 2-9. */
static const double paper_h[] = {1, 2, 5, 10, INFINITY};
static const double paper_v[] = {10, 100};
/* Fig 8's axis, 0.5 to 20 r0, with points dense where R_f changes. */
static const double sweep_h[] = {0.5, 0.75, 1, 1.5, 2, 3, 5, 7.5, 10, 15, 20};
#define ZENER_CURVE_N 41
#define ODE_CURVE_N 45
/* Zener's ODE is cheap; this tolerance makes its curve exact on a chart. */
#define ODE_TOL 1e-10

struct plot_args {
	int kind;
	const char *scene;     /* SCENE path, or NULL */
	struct cli_sets sets;
	const char *out, *script;
	struct plot_opts opts;
	int fixed_h, fixed_v;  /* the user chose the thickness / velocity */
};

/* The models run for one chart, and what they gave. */
struct batch {
	struct anvil_solver *solver;
	struct cli_progress progress;
	unsigned warned;       /* models whose failure was already reported */
	int n;
	struct anvil_result res[BATCH_MAX];
	struct plot_run runs[BATCH_MAX];
};

static void usage(FILE *f)
{
	fputs("usage: anvil plot KIND [SCENE] [-s KEY=VALUE]... -o FILE.png [--size WxH]\n"
	      "                  [--font NAME,SIZE] [--title TEXT] [--script FILE]\n"
	      "charts (KIND):\n", f);
	for (int k = 0; k < PLOT_KIND_COUNT; k++)
		fprintf(f, "  %-22s %s\n", plot_kind_name(k), plot_kind_summary(k));
	fputs("Without SCENE a chart draws the paper's cases: h = 1, 2, 5, 10 r0 and\n"
	      "inf at the scene's V0 (restitution charts: V0 = 10 and 100 m/s).  A SCENE,\n"
	      "or -s layer.thickness=... / -s impact.velocity=..., fixes what it sets.\n"
	      "--script FILE also writes the gnuplot script ('-': standard output);\n"
	      "with --script and no -o only the script is written.\n", f);
}

/* ------------------------------------------------------------- options */

static int parse_size(const char *s, struct plot_opts *o)
{
	char *end;
	long w = strtol(s, &end, 10), h;
	if (end == s || (*end != 'x' && *end != 'X'))
		return -1;
	s = end + 1;
	h = strtol(s, &end, 10);
	if (end == s || *end || w < SIZE_MIN || w > SIZE_MAX_PX || h < SIZE_MIN ||
	    h > SIZE_MAX_PX)
		return -1;
	o->width = (int)w;
	o->height = (int)h;
	return 0;
}

static int sets_has(const struct cli_sets *s, const char *key)
{
	for (int i = 0; i < s->n; i++) {
		size_t n = strcspn(s->v[i], "=");
		if (n == strlen(key) && strncasecmp(s->v[i], key, n) == 0)
			return 1;
	}
	return 0;
}

static int unknown_kind(const char *name)
{
	const char *near = plot_kind_suggest(name);
	char list[256] = "";
	for (int k = 0; k < PLOT_KIND_COUNT; k++)
		snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s",
			 k ? ", " : "", plot_kind_name(k));
	if (near)
		cli_error("plot: unknown chart '%s' (did you mean '%s'?); charts: %s",
			  name, near, list);
	else
		cli_error("plot: unknown chart '%s'; charts: %s", name, list);
	return EXIT_USAGE;
}

/* The positional arguments: KIND and an optional SCENE. */
static int parse_positional(struct plot_args *a, int argc, char **argv)
{
	if (optind >= argc) {
		cli_error("plot: missing the chart KIND (try 'anvil plot --help')");
		return EXIT_USAGE;
	}
	if ((a->kind = plot_kind_parse(argv[optind])) < 0)
		return unknown_kind(argv[optind]);
	if (optind + 1 < argc)
		a->scene = argv[optind + 1];
	if (optind + 2 < argc) {
		cli_error("plot: unexpected argument '%s'", argv[optind + 2]);
		return EXIT_USAGE;
	}
	return -1;
}

/* What the options ask for, checked together. */
static int check_args(struct plot_args *a)
{
	if (!a->out && !a->script) {
		cli_error("plot: missing -o FILE.png (or --script FILE)");
		return EXIT_USAGE;
	}
	if (a->out && strcmp(a->out, "-") == 0) {
		cli_error("plot: -o -: a PNG cannot go to standard output; give a file name");
		return EXIT_USAGE;
	}
	a->fixed_h = a->scene || sets_has(&a->sets, "layer.thickness");
	a->fixed_v = a->scene || sets_has(&a->sets, "impact.velocity");
	return -1;
}

static int parse_option(struct plot_args *a, int c, char **argv)
{
	switch (c) {
	case 'o':
		a->out = optarg;
		return -1;
	case 's':
		return cli_sets_add(&a->sets, optarg) ? EXIT_FAIL : -1;
	case 'S':
		if (!parse_size(optarg, &a->opts))
			return -1;
		cli_error("plot: --size '%s': expected WIDTHxHEIGHT in pixels, %d to %d, e.g. 800x600",
			  optarg, SIZE_MIN, SIZE_MAX_PX);
		return EXIT_USAGE;
	case 'F':
		a->opts.font = optarg;
		return -1;
	case 'T':
		a->opts.title = optarg;
		return -1;
	case 'P':
		a->script = optarg;
		return -1;
	case 'h':
		usage(stdout);
		return EXIT_OK;
	case ':':
		cli_error("plot: option '%s' needs a value", argv[optind - 1]);
		return EXIT_USAGE;
	default:
		cli_error("plot: unknown option '%s' (try 'anvil plot --help')",
			  argv[optind - 1]);
		return EXIT_USAGE;
	}
}

/* Returns -1 to go on, else the exit code. */
static int parse_args(struct plot_args *a, int argc, char **argv)
{
	static const struct option longs[] = {
		{"output", required_argument, NULL, 'o'},
		{"set", required_argument, NULL, 's'},
		{"size", required_argument, NULL, 'S'},
		{"font", required_argument, NULL, 'F'},
		{"title", required_argument, NULL, 'T'},
		{"script", required_argument, NULL, 'P'},
		{"help", no_argument, NULL, 'h'},
		{NULL, 0, NULL, 0},
	};
	int c, code;
	plot_opts_default(&a->opts);
	/* Our own messages, and a fresh scan whatever parsed argv before. */
	opterr = 0;
	optind = 0;
	while ((c = getopt_long(argc, argv, ":o:s:h", longs, NULL)) != -1)
		if ((code = parse_option(a, c, argv)) >= 0)
			return code;
	if ((code = parse_positional(a, argc, argv)) >= 0)
		return code;
	return check_args(a);
}

/* --------------------------------------------------------------- runs */

static int set_key(struct anvil_scene *sc, const char *key, const char *fmt,
		   double x)
{
	char value[64];
	struct anvil_err err = {0};
	if (isinf(x))
		snprintf(value, sizeof value, "inf");
	else
		snprintf(value, sizeof value, fmt, x);
	int st = anvil_scene_set(sc, key, value, "plot", 0, &err);
	if (st)
		cli_error("plot: %s", err.msg[0] ? err.msg : anvil_strerror(st));
	return st;
}

static int set_case(struct anvil_scene *sc, double h_r0, double V0)
{
	int st = isnan(h_r0) ? ANVIL_OK : set_key(sc, "layer.thickness", "%.17g r0", h_r0);
	return st || isnan(V0) ? st : set_key(sc, "impact.velocity", "%.17g m/s", V0);
}

static double case_lambda(const struct anvil_scene *sc)
{
	struct anvil_params p;
	return anvil_params_from_scene(&p, sc, NULL) ? NAN : p.lambda_star;
}

/* Report a model's trouble once per chart, not once per case. */
static void batch_warn(struct batch *b, enum anvil_model m, int st,
		       const struct anvil_err *err)
{
	if (b->warned & (1u << m))
		return;
	b->warned |= 1u << m;
	const char *why = err->msg[0] ? err->msg : anvil_strerror(st);
	if (st > 0 && err->msg[0])
		cli_error("plot: %s (drawn with its best values)", why);
	else if (st > 0)
		cli_error("plot: %s model: %s (drawn with its best values)", anvil_model_name(m), why);
	else
		cli_error("plot: %s model left out of the chart: %s", anvil_model_name(m), why);
}

/* Run model m for sc if the scene asks for it; record the run.  Only
 * what makes the chart impossible (memory, cancel) is returned. */
static int batch_run(struct batch *b, const struct anvil_scene *sc,
		     enum anvil_model m, size_t nhist)
{
	struct anvil_err err = {0};
	if (!(sc->models & (1u << m)))
		return ANVIL_OK;
	if (b->n == BATCH_MAX) {
		cli_error("plot: more than %d model runs for one chart", BATCH_MAX);
		return ANVIL_EINVAL;
	}
	struct anvil_result *r = &b->res[b->n];
	int st = cli_run_model(b->solver, sc, m, nhist, r, &err);
	cli_progress_done(&b->progress);
	b->runs[b->n++] = (struct plot_run){st < 0 ? NULL : r, m,
		anvil_scene_h(sc) / sc->radius, sc->velocity, case_lambda(sc)};
	if (st == ANVIL_ENOMEM || st == ANVIL_ECANCEL) {
		cli_error("plot: %s", anvil_strerror(st));
		return st;
	}
	if (st)
		batch_warn(b, m, st, &err);
	return ANVIL_OK;
}

static struct batch *batch_alloc(void)
{
	struct batch *b = calloc(1, sizeof *b);
	if (b && !(b->solver = anvil_solver_alloc())) {
		free(b);
		b = NULL;
	}
	if (b)
		anvil_solver_set_progress(b->solver, cli_progress_cb, &b->progress);
	else
		cli_error("plot: out of memory");
	return b;
}

static void batch_free(struct batch *b)
{
	if (!b)
		return;
	for (int i = 0; i < b->n; i++)
		anvil_result_free(&b->res[i]);
	anvil_solver_free(b->solver);
	free(b);
}

/* The thicknesses and velocities of a chart: the paper's, or the scene's
 * (NaN: leave the scene's value). */
static int case_list(int fixed, const double *paper, int npaper,
		     const double **list)
{
	static const double keep[] = {NAN};
	*list = fixed ? keep : paper;
	return fixed ? 1 : npaper;
}

#define NELEM(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* Figs 2-7: the transform model per thickness, then Zener, then Hertz, so
 * the legend reads in that order. */
static int runs_history(struct batch *b, const struct anvil_scene *base,
			const struct plot_args *a)
{
	static const enum anvil_model order[] = {ANVIL_MODEL_LAYER, ANVIL_MODEL_HALFSPACE,
		ANVIL_MODEL_ZENER, ANVIL_MODEL_HERTZ};
	int st = ANVIL_OK;
	if (a->fixed_h) {
		for (int i = 0; i < NELEM(order) && !st; i++)
			/* A layer of infinite thickness is the half-space, run anyway. */
			if (order[i] != ANVIL_MODEL_LAYER || isfinite(anvil_scene_h(base)))
				st = batch_run(b, base, order[i], PLOT_NHIST);
		return st;
	}
	for (int pass = 0; pass < 2 && !st; pass++)
		for (int i = 0; i < NELEM(paper_h) && !st; i++) {
			struct anvil_scene sc = *base;
			int thick = isfinite(paper_h[i]);
			if (pass == 1 && !thick)
				continue; /* Zener's plate needs a thickness */
			if (!(st = set_case(&sc, paper_h[i], NAN)))
				st = batch_run(b, &sc, pass ? ANVIL_MODEL_ZENER
					       : thick ? ANVIL_MODEL_LAYER : ANVIL_MODEL_HALFSPACE,
					       PLOT_NHIST);
		}
	return st ? st : batch_run(b, base, ANVIL_MODEL_HERTZ, PLOT_NHIST);
}

/* Report a builder's failure (the runs report their own). */
static int built(const struct plot_chart *c, int st)
{
	if (st == ANVIL_EINVAL)
		cli_error("plot: %s chart: nothing to draw: every model it needs failed",
			  plot_kind_name(c->kind));
	else if (st)
		cli_error("plot: %s chart: %s", plot_kind_name(c->kind), anvil_strerror(st));
	return st;
}

/* One case of the restitution charts: the layer, or the half-space. */
static int run_rf_case(struct batch *b, const struct anvil_scene *base,
		       double h, double V0)
{
	struct anvil_scene sc = *base;
	int st = set_case(&sc, h, V0);
	if (st)
		return st;
	return batch_run(b, &sc, isfinite(anvil_scene_h(&sc)) ? ANVIL_MODEL_LAYER
			 : ANVIL_MODEL_HALFSPACE, 0);
}

/* Zener's R*_f (eq. 54) against h/r0 at one velocity. */
static int zener_curve(const struct anvil_scene *base, double V0, double *x,
		       double *y, struct plot_curve *c)
{
	struct anvil_scene sc = *base;
	int st = ANVIL_OK;
	for (int i = 0; i < ZENER_CURVE_N && !st; i++) {
		struct anvil_params p;
		x[i] = 0.5 * pow(40.0, (double)i / (ZENER_CURVE_N - 1)); /* 0.5 .. 20 */
		if (!(st = set_case(&sc, x[i], V0)))
			st = anvil_params_from_scene(&p, &sc, NULL);
		y[i] = st ? NAN : p.Rf_star;
	}
	*c = (struct plot_curve){sc.velocity, ZENER_CURVE_N, x, y};
	return st;
}

static int chart_rf_thickness(struct plot_chart *c, struct batch *b,
			      const struct anvil_scene *base, const struct plot_args *a)
{
	const double *vs;
	int nv = case_list(a->fixed_v, paper_v, NELEM(paper_v), &vs), st = ANVIL_OK;
	double zx[NELEM(paper_v)][ZENER_CURVE_N], zy[NELEM(paper_v)][ZENER_CURVE_N];
	struct plot_curve zc[NELEM(paper_v)];
	for (int v = 0; v < nv && !st; v++) {
		for (int i = 0; i < NELEM(sweep_h) && !st; i++)
			st = run_rf_case(b, base, sweep_h[i], vs[v]);
		if (!st)
			st = run_rf_case(b, base, INFINITY, vs[v]);
		if (!st)
			st = zener_curve(base, vs[v], zx[v], zy[v], &zc[v]);
	}
	return st ? st : built(c, plot_chart_rf_thickness(c, b->runs, b->n, zc, nv));
}

/* Zener's ODE R_f over [0, lmax]. */
static int ode_curve(double lmax, double *x, double *y, struct plot_curve *c)
{
	for (int i = 0; i < ODE_CURVE_N; i++) {
		struct anvil_zener_sol sol;
		struct anvil_err err = {0};
		x[i] = lmax * i / (ODE_CURVE_N - 1);
		int st = anvil_zener_solve(x[i], ODE_TOL, &sol, &err);
		if (st) {
			cli_error("plot: Zener's ODE at lambda* = %g: %s", x[i],
				  err.msg[0] ? err.msg : anvil_strerror(st));
			return st;
		}
		y[i] = sol.rf;
	}
	*c = (struct plot_curve){0, ODE_CURVE_N, x, y};
	return ANVIL_OK;
}

static int chart_rf_lambda(struct plot_chart *c, struct batch *b,
			   const struct anvil_scene *base, const struct plot_args *a)
{
	const double *hs, *vs;
	int nh = case_list(a->fixed_h, paper_h, NELEM(paper_h), &hs);
	int nv = case_list(a->fixed_v, paper_v, NELEM(paper_v), &vs), st = ANVIL_OK;
	double x[ODE_CURVE_N], y[ODE_CURVE_N], lmax = 1.1;
	struct plot_curve ode;
	for (int v = 0; v < nv && !st; v++)
		for (int i = 0; i < nh && !st; i++)
			st = run_rf_case(b, base, hs[i], vs[v]);
	/* The ODE curve spans every case, as the fit line does. */
	for (int i = 0; i < b->n; i++)
		if (1.05 * b->runs[i].lambda_star > lmax)
			lmax = 1.05 * b->runs[i].lambda_star;
	if (!st)
		st = ode_curve(lmax, x, y, &ode);
	return st ? st : built(c, plot_chart_rf_lambda(c, b->runs, b->n, &ode));
}

static int chart_accuracy(struct plot_chart *c, struct batch *b,
			  const struct anvil_scene *base)
{
	enum anvil_model m = isfinite(anvil_scene_h(base)) ? ANVIL_MODEL_LAYER
		: ANVIL_MODEL_HALFSPACE;
	int st = ANVIL_OK;
	for (int i = 0; i < ANVIL_ACC_COUNT && !st; i++) {
		struct anvil_scene sc = *base;
		struct anvil_err err = {0};
		sc.models |= 1u << m; /* this chart is about that model */
		st = anvil_scene_set(&sc, "solver.accuracy", anvil_accuracy_name(i),
				     "plot", 0, &err);
		if (!st)
			st = batch_run(b, &sc, m, 0);
		else
			cli_error("plot: %s", err.msg);
	}
	if (st)
		return st;
	st = built(c, plot_chart_accuracy(c, b->runs));
	if (!st)
		snprintf(c->title, sizeof c->title,
			 "%s model: error against wall time, accuracy draft to reference",
			 anvil_model_name(m));
	return st;
}

/* Runs the models of a.kind and builds its chart. */
static int build_chart(struct plot_chart *c, struct batch *b,
		       const struct anvil_scene *sc, const struct plot_args *a)
{
	int st;
	plot_chart_init(c, a->kind);
	switch (a->kind) {
	case PLOT_RESTITUTION_THICKNESS:
		return chart_rf_thickness(c, b, sc, a);
	case PLOT_RESTITUTION_LAMBDA:
		return chart_rf_lambda(c, b, sc, a);
	case PLOT_ACCURACY:
		return chart_accuracy(c, b, sc);
	default:
		st = runs_history(b, sc, a);
		return st ? st : built(c, plot_chart_history(c, a->kind, b->runs, b->n,
							    !a->fixed_h));
	}
}

static int plot_scene(struct plot_args *a)
{
	struct anvil_scene sc;
	struct plot_chart c;
	struct batch *b;
	int st = cli_scene(&sc, a->scene, a->sets.v, a->sets.n), code = EXIT_FAIL;
	if (st)
		return cli_exit_code(st);
	/* Fail on a missing gnuplot before minutes of layer runs. */
	if (a->out && plot_gnuplot_check())
		return EXIT_FAIL;
	if (!(b = batch_alloc()))
		return EXIT_FAIL;
	st = build_chart(&c, b, &sc, a);
	if (!st) {
		/* A scene's own title goes in front of the chart's. */
		if (a->scene)
			plot_chart_scene_title(&c, sc.title);
		code = plot_png(&c, &a->opts, a->out, a->script);
	}
	plot_chart_free(&c);
	batch_free(b);
	return code;
}

int anvil_cmd_plot(int argc, char **argv)
{
	struct plot_args a = {0};
	int code = parse_args(&a, argc, argv);
	if (code < 0)
		code = plot_scene(&a);
	cli_sets_free(&a.sets);
	return code;
}
