/* cmd_plot.c: `anvil plot KIND [SCENE] [-s KEY=VALUE]... -o FILE.png|svg|pdf`.
 *
 * Runs the models each chart needs (the paper's cases unless a scene fixes
 * them), hands the results to the builders of plot.c and renders the
 * chart with gnuplot.  A model that fails is left out of the chart and
 * reported once on stderr, so the chart shows whatever was computed.
 * The plot library never prints: its messages are printed here. */
#include <dirent.h>
#include <getopt.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>

#include "params.h"
#include "zener.h"
#include "commands.h"
#include "common.h"
#include "plot.h"
#include "plot_sweep.h"

/* Samples kept per history: smooth at any PNG size anvil allows. */
#define PLOT_NHIST 400
#define BATCH_MAX 64
#define SIZE_MIN 100
#define SIZE_MAX_PX 10000

/* The paper's cases: Tables 2-3 and Figs 2-9. */
static const double paper_h[] = {1, 2, 5, 10, INFINITY};
static const double paper_v[] = {10, 100};
/* Fig 8's axis, 0.5 to 20 r0: SWEEP_N layer runs log-spaced (a ratio of
 * 40^(1/16) = 1.26 between neighbours; the responses are cached, keyed by
 * h/r0), joined by a monotone cubic (Steffen: no overshoot) in log h drawn
 * with SWEEP_DENSE points.  The markers are the computed values; between
 * them the curve is an interpolation, measured against runs at the 16
 * midpoints of the paper's case: within 0.005 in R_f at 10 m/s (the worst
 * at h = 0.56 r0, where R_f = 0.015 turns up), within 0.001 at 100 m/s. */
#define SWEEP_N 17
#define SWEEP_DENSE 160
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
	const char *paper;     /* --paper FILE: the paper's tables.tsv */
	const char *materials, *velocities; /* restitution-velocity: --materials, --velocities */
	int fixed_h, fixed_v;  /* the user chose the thickness / velocity */
	int sized;             /* --size given */
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
	fputs("usage: anvil plot KIND [SCENE] [-s KEY=VALUE]... -o FILE.png|.svg|.pdf\n"
	      "                  [--size WxH] [--font NAME,SIZE] [--title TEXT]\n"
	      "                  [--script FILE] [--paper TABLES.tsv]\n"
	      "                  [--materials IMP/LAYER,...] [--velocities SPEC]\n"
	      "charts (KIND):\n", f);
	for (int k = 0; k < PLOT_KIND_COUNT; k++)
		fprintf(f, "  %-22s %s\n", plot_kind_name(k), plot_kind_summary(k));
	fputs("Without SCENE a chart draws the paper's cases: h = 1, 2, 5, 10 r0 and\n"
	      "inf at the scene's V0 (restitution charts: V0 = 10 and 100 m/s).  A SCENE,\n"
	      "or -s layer.thickness=... / -s impact.velocity=..., fixes what it sets.\n"
	      "--script FILE also writes the gnuplot script ('-': standard output);\n"
	      "with --script and no -o only the script is written.  The image type\n"
	      "follows -o's extension.  --paper names the paper's tables.tsv (the\n"
	      "restitution charts show its printed values).\n"
	      "restitution-velocity: a curve per thickness (1, 2, 5, 10 r0, or the scene's),\n"
	      "or with --materials copper/steel,steel/steel,glass (IMPACTOR/LAYER, or\n"
	      "LAYER with the scene's impactor; at most 6) a curve per material pair at\n"
	      "the scene's thickness; --velocities as anvil sweep's (default\n"
	      "1..100m/s:13:log).  Its contact model is the scene's (auto: physical).\n", f);
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
		cli_error("plot: -o -: an image cannot go to standard output; give a file name");
		return EXIT_USAGE;
	}
	if (a->out && plot_format_of(a->out) < 0) {
		cli_error("plot: -o %s: unknown image type; name it .png, .svg or .pdf", a->out);
		return EXIT_USAGE;
	}
	if (a->out)
		a->opts.format = (enum plot_format)plot_format_of(a->out);
	/* Three stacked panels need the height of three charts, nearly. */
	if (a->kind == PLOT_HISTORY && !a->sized)
		a->opts.height = 1000;
	if ((a->materials || a->velocities) && a->kind != PLOT_RESTITUTION_VELOCITY) {
		cli_error("plot: %s is for restitution-velocity only", a->materials ? "--materials" : "--velocities");
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
			return a->sized = 1, -1;
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
	case 'R':
		a->paper = optarg;
		return -1;
	case 'M':
		a->materials = optarg;
		return -1;
	case 'V':
		a->velocities = optarg;
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
		{"paper", required_argument, NULL, 'R'},
		{"materials", required_argument, NULL, 'M'},
		{"velocities", required_argument, NULL, 'V'},
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

/* The solver's statuses whose result holds usable values: success and the
 * positive warnings (ANVIL_WTOL); failures are negative. */
static int usable(int st)
{
	return st >= 0;
}

/* Report a model's trouble once per chart, not once per case. */
static void batch_warn(struct batch *b, enum anvil_model m, int st,
		       const struct anvil_err *err)
{
	if (b->warned & (1u << m))
		return;
	b->warned |= 1u << m;
	const char *why = err->msg[0] ? err->msg : anvil_strerror(st);
	if (usable(st) && err->msg[0])
		cli_error("plot: %s (drawn with its best values)", why);
	else if (usable(st))
		cli_error("plot: %s model: %s (drawn with its best values)", anvil_model_name(m), why);
	else
		cli_error("plot: %s model left out of the chart: %s", anvil_model_name(m), why);
}

/* Run model m for sc with solver s if the scene asks for it; record the
 * run.  Only what makes the chart impossible (memory, cancel) is
 * returned.  Every solver call of the plot command goes through here. */
static int batch_run_with(struct batch *b, struct anvil_solver *s,
			  const struct anvil_scene *sc, enum anvil_model m, size_t nhist)
{
	struct anvil_err err = {0};
	if (!(sc->models & (1u << m)))
		return ANVIL_OK;
	if (b->n == BATCH_MAX) {
		cli_error("plot: more than %d model runs for one chart", BATCH_MAX);
		return ANVIL_EINVAL;
	}
	struct anvil_result *r = &b->res[b->n];
	int st = cli_run_model(s, sc, m, nhist, r, &err);
	cli_progress_done(&b->progress);
	b->runs[b->n++] = (struct plot_run){usable(st) ? r : NULL, m,
		anvil_scene_h(sc) / sc->radius, sc->velocity, case_lambda(sc)};
	if (st == ANVIL_ENOMEM || st == ANVIL_ECANCEL) {
		cli_error("plot: %s", anvil_strerror(st));
		return st;
	}
	if (st)
		batch_warn(b, m, st, &err);
	return ANVIL_OK;
}

static int batch_run(struct batch *b, const struct anvil_scene *sc,
		     enum anvil_model m, size_t nhist)
{
	return batch_run_with(b, b->solver, sc, m, nhist);
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
	sc.models |= 1u << ANVIL_MODEL_LAYER | 1u << ANVIL_MODEL_HALFSPACE;
	return batch_run(b, &sc, isfinite(anvil_scene_h(&sc)) ? ANVIL_MODEL_LAYER
			 : ANVIL_MODEL_HALFSPACE, 0);
}

/* Zener's R*_f (eq. 54) against h/r0 at one velocity, over [x0, x1]. */
static int zener_curve(const struct anvil_scene *base, double V0, double x0, double x1,
		       double *x, double *y, struct plot_curve *c)
{
	struct anvil_scene sc = *base;
	int st = ANVIL_OK;
	for (int i = 0; i < ZENER_CURVE_N && !st; i++) {
		struct anvil_params p;
		x[i] = x0 * pow(x1 / x0, (double)i / (ZENER_CURVE_N - 1));
		if (!(st = set_case(&sc, x[i], V0)))
			st = anvil_params_from_scene(&p, &sc, NULL);
		y[i] = st ? NAN : p.Rf_star;
	}
	*c = (struct plot_curve){sc.velocity, ZENER_CURVE_N, x, y};
	return st;
}

/* The layer's R_f at velocity V0 through the computed runs: a monotone
 * cubic (Steffen: no overshoot between points) in log h, SWEEP_DENSE
 * points over the computed span.  n = 0 when fewer than 3 points. */
static void layer_curve(const struct batch *b, double V0, double *x, double *y,
			struct plot_curve *c)
{
	double lh[BATCH_MAX], rf[BATCH_MAX];
	size_t m = 0;
	*c = (struct plot_curve){V0, 0, x, y};
	for (int i = 0; i < b->n; i++) {
		const struct plot_run *r = &b->runs[i];
		if (!r->r || r->model != ANVIL_MODEL_LAYER || r->V0 != V0)
			continue;
		size_t j = 0;
		while (j < m && lh[j] < log(r->h_r0))
			j++;
		if (j < m && lh[j] == log(r->h_r0))
			continue; /* the scene's own h on the sweep: once */
		memmove(lh + j + 1, lh + j, (m - j) * sizeof *lh);
		memmove(rf + j + 1, rf + j, (m - j) * sizeof *rf);
		lh[j] = log(r->h_r0);
		rf[j] = r->r->Rf.val;
		m++;
	}
	gsl_interp *in = m >= 3 ? gsl_interp_alloc(gsl_interp_steffen, m) : NULL;
	if (!in || gsl_interp_init(in, lh, rf, m)) {
		gsl_interp_free(in);
		return;
	}
	for (int i = 0; i < SWEEP_DENSE; i++) {
		/* fmin: rounding must not step past the last point (GSL_EDOM) */
		double t = fmin(lh[0] + (lh[m - 1] - lh[0]) * i / (SWEEP_DENSE - 1), lh[m - 1]);
		x[i] = exp(t);
		y[i] = gsl_interp_eval(in, lh, rf, t, NULL);
	}
	c->n = SWEEP_DENSE;
	gsl_interp_free(in);
}

/* The paper's printed values, or NULL after saying they are missing. */
static const struct plot_paper *paper_values(const struct plot_args *a,
					     struct plot_paper *p, struct plot_chart *c)
{
	struct anvil_err err = {0};
	if (!plot_paper_load(p, a->paper, &err))
		return p;
	cli_error("plot: %s; drawn without them", err.msg);
	snprintf(c->footnote, sizeof c->footnote, "paper values not found");
	return NULL;
}

static int chart_rf_thickness(struct plot_chart *c, struct batch *b,
			      const struct anvil_scene *base, const struct plot_args *a)
{
	const double *vs;
	int nv = case_list(a->fixed_v, paper_v, NELEM(paper_v), &vs), st = ANVIL_OK;
	double zx[NELEM(paper_v)][ZENER_CURVE_N], zy[NELEM(paper_v)][ZENER_CURVE_N];
	double lx[NELEM(paper_v)][SWEEP_DENSE], ly[NELEM(paper_v)][SWEEP_DENSE];
	struct plot_curve zc[NELEM(paper_v)], lc[NELEM(paper_v)];
	struct plot_paper paper;
	const struct plot_paper *p = paper_values(a, &paper, c);
	/* A thickness the user fixed is marked, and computed exactly. */
	double mark = a->fixed_h ? anvil_scene_h(base) / base->radius : NAN;
	double x0 = isfinite(mark) ? fmin(0.5, mark / 1.5) : 0.5;
	double x1 = isfinite(mark) ? fmax(20, mark * 1.5) : 20;
	for (int v = 0; v < nv && !st; v++) {
		for (int i = 0; i < SWEEP_N && !st; i++)
			st = run_rf_case(b, base, 0.5 * pow(40.0, (double)i / (SWEEP_N - 1)), vs[v]);
		if (!st && isfinite(mark))
			st = run_rf_case(b, base, mark, vs[v]);
		if (!st)
			st = run_rf_case(b, base, INFINITY, vs[v]);
		if (!st)
			st = zener_curve(base, vs[v], x0, x1, zx[v], zy[v], &zc[v]);
		if (!st)
			layer_curve(b, b->runs[b->n - 1].V0, lx[v], ly[v], &lc[v]);
	}
	if (st)
		return st;
	/* The builder starts a new chart: keep what paper_values said. */
	char note[PLOT_TITLE_MAX];
	snprintf(note, sizeof note, "%s", c->footnote);
	st = built(c, plot_chart_rf_thickness(c, b->runs, b->n, lc, nv, zc, nv, p,
					      base->radius, mark));
	if (!st && note[0])
		snprintf(c->footnote, sizeof c->footnote, "%s", note);
	return st;
}

/* Zener's ODE R_f over [0, lmax], log-spaced from lmin when lmin > 0. */
static int ode_curve(double lmin, double lmax, double *x, double *y, struct plot_curve *c)
{
	for (int i = 0; i < ODE_CURVE_N; i++) {
		struct anvil_zener_sol sol;
		struct anvil_err err = {0};
		double f = (double)i / (ODE_CURVE_N - 1);
		x[i] = lmin > 0 ? lmin * pow(lmax / lmin, f) : lmax * f;
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
	double x[ODE_CURVE_N], y[ODE_CURVE_N], lmin = INFINITY, lmax = 1.1;
	struct plot_curve ode;
	struct plot_paper paper;
	const struct plot_paper *p = paper_values(a, &paper, c);
	for (int v = 0; v < nv && !st; v++)
		for (int i = 0; i < nh && !st; i++)
			st = run_rf_case(b, base, hs[i], vs[v]);
	/* The ODE curve spans every case and the paper's, as the fit does. */
	for (int i = 0; i < b->n; i++) {
		if (b->runs[i].lambda_star > 0)
			lmin = fmin(lmin, b->runs[i].lambda_star);
		lmax = fmax(lmax, 1.1 * b->runs[i].lambda_star);
	}
	for (int i = 0; p && i < p->n; i++)
		if (p->row[i].lambda_star > 0)
			lmin = fmin(lmin, p->row[i].lambda_star);
	/* log axis (plot_rf.c): from the decade below the smallest lambda* */
	lmin = isfinite(lmin) && lmax / lmin > 10 ? pow(10, floor(log10(lmin))) : 0;
	if (!st)
		st = ode_curve(lmin, lmax, x, y, &ode);
	if (st)
		return st;
	char note[PLOT_TITLE_MAX];
	snprintf(note, sizeof note, "%s", c->footnote);
	st = built(c, plot_chart_rf_lambda(c, b->runs, b->n, &ode, p));
	if (!st && note[0])
		snprintf(c->footnote, sizeof c->footnote, "%s", note);
	return st;
}

/* Remove the files of a private cache directory, then the directory. */
static void remove_dir(const char *dir)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	char path[4096];
	while (d && (e = readdir(d)))
		if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") &&
		    snprintf(path, sizeof path, "%s/%s", dir, e->d_name) < (int)sizeof path)
			unlink(path);
	if (d)
		closedir(d);
	rmdir(dir);
}

/* One level of the accuracy chart, cold: a new solver with a private,
 * empty cache directory, so the time is the work the level costs. */
static int accuracy_level(struct batch *b, const struct anvil_scene *sc, enum anvil_model m)
{
	char dir[] = "/tmp/anvil-plot-cold-XXXXXX";
	struct anvil_err err = {0};
	struct anvil_solver *s = anvil_solver_alloc();
	int st = s ? ANVIL_OK : ANVIL_ENOMEM;
	if (!st && !mkdtemp(dir)) {
		cli_error("plot: cannot make a temporary cache directory: %s", strerror(errno));
		st = ANVIL_EIO;
	}
	if (!st && (st = anvil_solver_set_cache_dir(s, dir, &err)))
		cli_error("plot: %s", err.msg);
	if (!st) {
		anvil_solver_set_progress(s, cli_progress_cb, &b->progress);
		st = batch_run_with(b, s, sc, m, 0);
	}
	if (s && dir[sizeof dir - 2] != 'X')
		remove_dir(dir);
	anvil_solver_free(s);
	return st;
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
			st = accuracy_level(b, &sc, m);
		else
			cli_error("plot: %s", err.msg);
	}
	if (st)
		return st;
	st = built(c, plot_chart_accuracy(c, b->runs));
	if (!st)
		snprintf(c->title, sizeof c->title,
			 "Error against cold wall time, accuracy draft to reference (%s model)",
			 anvil_model_name(m));
	return st;
}

/* --- contactB: anvil plot models --- */

/* R_f against h/r0 of the two contact models: the paper's thicknesses and
 * the ends of Fig 8's axis. */
static const double models_h[] = {0.5, 1, 2, 5, 10, 20};
#define MODELS_NH ((int)(sizeof models_h / sizeof models_h[0]))

/* The scene with contact c and thickness h/r0 (INFINITY: half-space);
 * the model it runs then. */
static enum anvil_model models_scene(struct anvil_scene *sc, const struct anvil_scene *base,
				     enum anvil_contact c, double h)
{
	*sc = *base;
	sc->effects.contact = c;
	sc->thickness = h;
	sc->thickness_per_r0 = isfinite(h);
	enum anvil_model m = isfinite(h) ? ANVIL_MODEL_LAYER : ANVIL_MODEL_HALFSPACE;
	sc->models |= 1u << m; /* this chart is about that model */
	return m;
}

static int chart_models(struct plot_chart *c, struct batch *b, const struct anvil_scene *base)
{
	static const enum anvil_contact cm[2] = {ANVIL_CONTACT_PHYSICAL, ANVIL_CONTACT_PAPER};
	double h0 = anvil_scene_h(base) / base->radius, x[2][MODELS_NH], y[2][MODELS_NH];
	struct plot_curve rf[2] = {{0, 0, NULL, NULL}, {0, 0, NULL, NULL}};
	struct anvil_scene sc;
	int st = ANVIL_OK, nh;
	/* P(t): the scene's thickness and the half-space, each contact */
	for (int k = 0; k < 2 && !st; k++)
		for (int i = 0; i < (isfinite(h0) ? 2 : 1) && !st; i++) {
			enum anvil_model m = models_scene(&sc, base, cm[k], i ? INFINITY : h0);
			st = batch_run(b, &sc, m, PLOT_NHIST);
		}
	nh = b->n;
	for (int k = 0; k < 2 && !st; k++) {
		rf[k] = (struct plot_curve){base->velocity, 0, x[k], y[k]};
		for (int i = 0; i < MODELS_NH && !st; i++) {
			enum anvil_model m = models_scene(&sc, base, cm[k], models_h[i]);
			st = batch_run(b, &sc, m, 0);
			if (!st && b->runs[b->n - 1].r) {
				x[k][rf[k].n] = models_h[i];
				y[k][rf[k].n++] = b->runs[b->n - 1].r->Rf.val;
			}
		}
	}
	return st ? st : built(c, plot_chart_models(c, b->runs, nh, rf));
}
/* --- end contactB --- */

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
	case PLOT_RESTITUTION_VELOCITY: /* plot_sweep.c, on every core */
		st = plot_sweep_rf_velocity(c, sc, a->fixed_h, a->materials, a->velocities);
		return st == EXIT_USAGE ? ANVIL_EPARSE : st ? ANVIL_EINVAL : ANVIL_OK;
	case PLOT_MODELS:
		return chart_models(c, b, sc);
	default:
		st = runs_history(b, sc, a);
		return st ? st : built(c, plot_chart_history(c, a->kind, b->runs, b->n));
	}
}

/* A signal during rendering: plot_render ends gnuplot and removes its
 * temporary file; the signal is then raised again with its default
 * action, so the exit status tells what happened. */
static volatile sig_atomic_t render_signal;

static void on_render_signal(int sig)
{
	render_signal = sig;
}

static int render(const struct plot_chart *c, struct plot_args *a)
{
	static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
	struct sigaction sa = {.sa_handler = on_render_signal}, old[3];
	struct anvil_err err = {0};
	sigemptyset(&sa.sa_mask);
	for (int i = 0; i < 3; i++)
		sigaction(sigs[i], &sa, &old[i]);
	a->opts.cancel = &render_signal;
	int st = plot_save(c, &a->opts, a->out, a->script, &err);
	for (int i = 0; i < 3; i++)
		sigaction(sigs[i], &old[i], NULL);
	if (st)
		cli_error("%s", err.msg);
	if (st == ANVIL_ECANCEL && render_signal)
		raise(render_signal);
	return st ? EXIT_FAIL : EXIT_OK;
}

/* 1 when x is one of the n values of list (to 1e-9 relative; inf too). */
static int in_list(double x, const double *list, int n)
{
	for (int i = 0; i < n; i++)
		if (x == list[i] || (isfinite(list[i]) && fabs(x - list[i]) <= 1e-9 * fabs(list[i])))
			return 1;
	return 0;
}

/* The paper's figures: no SCENE, the paper's bodies (the default scene's
 * impactor, layer, mass, r0), one of its velocities and, when -s fixes
 * it, one of its thicknesses.  -s keys that move the scene off them make
 * it the user's scene, which `anvil run` gives the physical contact
 * (problem.c, contact = auto): so does the chart. */
static int paper_figure(const struct anvil_scene *sc, const struct plot_args *a)
{
	struct anvil_scene d, def;
	if (a->scene)
		return 0;
	anvil_scene_default(&def);
	d = *sc;
	d.thickness = def.thickness;
	d.thickness_per_r0 = def.thickness_per_r0;
	d.velocity = def.velocity;
	return anvil_scene_is_paper_case(&d) && in_list(sc->velocity, paper_v, NELEM(paper_v)) &&
	       (!a->fixed_h || in_list(anvil_scene_h(sc) / sc->radius, paper_h, NELEM(paper_h)));
}

static int plot_scene(struct plot_args *a)
{
	struct anvil_scene sc;
	struct plot_chart c;
	struct anvil_err err = {0};
	struct batch *b;
	if (a->kind == PLOT_RESTITUTION_MAP) /* SCENE is a sweep's rows: plot_sweep.c */
		return plot_sweep_rf_map(a->scene, &a->opts, a->out, a->script);
	int st = cli_scene(&sc, a->scene, a->sets.v, a->sets.n), code = EXIT_FAIL;
	if (st)
		return cli_exit_code(st);
	/* The paper's figures with the paper's values beside them: its contact
	 * model, unless the scene names one (models draws both).  Histories
	 * of any other scene (a SCENE, or -s keys off the paper's cases: a
	 * 2 kg rod on h = 0.1 r0) are not the paper's figure: the contact of
	 * its 'anvil run' rows (auto: physical), so that the chart shows what
	 * the table says (a ball on a thin plate peaked at 0.53 kN on the
	 * chart, the paper's contact, and 0.31 kN in the table). */
	int history = a->kind == PLOT_FORCE || a->kind == PLOT_VELOCITY ||
		      a->kind == PLOT_DEFLECTION || a->kind == PLOT_HISTORY;
	if (sc.effects.contact == ANVIL_CONTACT_AUTO && a->kind != PLOT_MODELS &&
	    a->kind != PLOT_RESTITUTION_VELOCITY) /* not the paper's: auto, physical */
		sc.effects.contact = history && !paper_figure(&sc, a) ? ANVIL_CONTACT_PHYSICAL
								       : ANVIL_CONTACT_PAPER;
	/* Fail on a missing gnuplot before minutes of layer runs. */
	if (a->out && plot_gnuplot_check(&err)) {
		cli_error("%s", err.msg);
		return EXIT_FAIL;
	}
	if (!(b = batch_alloc()))
		return EXIT_FAIL;
	st = build_chart(&c, b, &sc, a);
	if (!st) {
		int vary_h = a->kind == PLOT_RESTITUTION_THICKNESS || a->kind == PLOT_MODELS ||
			     (!a->fixed_h && a->kind != PLOT_ACCURACY);
		/* (a history chart's title gives V0: not said again below it) */
		int vary_v = a->kind == PLOT_RESTITUTION_VELOCITY || history ||
			     (!a->fixed_v && (a->kind == PLOT_RESTITUTION_THICKNESS ||
					      a->kind == PLOT_RESTITUTION_LAMBDA));
		if (!a->materials) /* with them, plot_sweep.c wrote it */
			plot_chart_subtitle(&c, &sc, vary_h, vary_v);
		enum anvil_contact cm = sc.effects.contact;
		unsigned waves = 1u << ANVIL_MODEL_LAYER | 1u << ANVIL_MODEL_HALFSPACE;
		if (history && !c.footnote[0] && (anvil_scene_models(&sc) & waves) &&
		    (cm == ANVIL_CONTACT_PAPER || cm == ANVIL_CONTACT_PHYSICAL))
			snprintf(c.footnote, sizeof c.footnote,
				 "layer and half-space with the %s contact (effects.contact)",
				 cm == ANVIL_CONTACT_PAPER ? "paper's" : "physical");
		code = render(&c, a);
	} else if (st == ANVIL_EPARSE) {
		code = EXIT_USAGE;
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
