/* cmd_fit.c: `anvil fit`, the one unknown (layer thickness, layer
 * modulus or impact velocity) that reproduces a measured contact time,
 * restitution or peak force, with the interval the measurement's stated
 * uncertainty allows.
 *
 * The unknown x is stepped over its range on a log grid (FIT_STEPS a
 * decade) from the top down; the first cell where the model's value
 * crosses the target brackets the root (so with several roots, the largest
 * x is the answer: for a thickness, the thickest layer), which GSL's Brent solver then
 * finds in log x to FIT_XTOL.  Each evaluation runs the scene through one
 * solver, so layer responses are made once and kept (cache.h).
 *
 * The contact model (layer and halfspace models) is set on every scene
 * run and checked on every result, as anvil thickness does: auto is the
 * physical contact (the scenes tried are not the paper's own case), both
 * gives an answer per contact model, the paper's first. */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "answer.h"
#include "commands.h"
#include "common.h"
#include "output.h"
#include "scene_keys.h"
#include "units.h"

#define FIT_STEPS 6      /* grid points a decade: 47 % apart */
#define FIT_MAXGRID 200
#define FIT_XTOL 1e-5    /* Brent's tolerance on log x: 0.001 % of x */
#define FIT_MAXITER 100

/* The unknowns: key, SI unit for the scene, default range (SI; thickness
 * in r0), what the key takes (scene_keys.h: --range stays inside), how to
 * show it. */
struct fit_key {
	const char *key, *unit;
	double lo, hi, min, max;
	enum anvil_dim dim;
};
static const struct fit_key fit_keys[] = {
	{"layer.thickness", "r0", 0.25, 64, ANVIL_RANGE_H_R0, ANVIL_DIM_LENGTH},
	{"layer.E", "Pa", 1e9, 1e12, ANVIL_RANGE_E, ANVIL_DIM_PRESSURE},
	{"impact.velocity", "m/s", 0.01, 100, ANVIL_RANGE_VELOCITY, ANVIL_DIM_VELOCITY},
};
#define NKEYS ((int)(sizeof fit_keys / sizeof fit_keys[0]))

struct fit {
	const char *scene, *out, *target_arg;
	const struct fit_key *k;
	double lo, hi;
	enum answer_qty q;
	double target, terr;
	enum anvil_model model;
	enum anvil_contact contact; /* of the fit under way; AUTO: the model has its own */
	int format;
	struct cli_sets sets;
	struct anvil_scene sc;
	struct anvil_solver *s;
	double grid_x[FIT_MAXGRID], grid_v[FIT_MAXGRID];
	int ngrid;
	int st;           /* the last evaluation's status */
	char why[ANVIL_ERR_MSG]; /* the last failed evaluation's reason */
};

static void fit_usage(FILE *f)
{
	fputs("usage: anvil fit [SCENE] QTY=VALUE[+-ERR] [--for KEY] [--range LO..HI]\n"
	      "                 [-m MODEL] [-s KEY=VALUE]... [-f FORMAT] [-o FILE]\n"
	      "The value of one unknown that reproduces a measurement: QTY is ts (a time,\n"
	      "ts=62us+-1us), Rf (Rf=0.8+-0.02) or Pmax (a force, Pmax=1.2kN).\n"
	      "  --for KEY        the unknown: layer.thickness (default), layer.E,\n"
	      "                   impact.velocity\n"
	      "  --range LO..HI   where to look, in the key's unit (thickness in r0,\n"
	      "                   default 0.25..64; E in Pa, 1e9..1e12; velocity in m/s,\n"
	      "                   0.01..100)\n"
	      "  -m, --model M    the model whose value is matched (default: layer)\n"
	      "The layer and halfspace models use the scene's contact model, named in\n"
	      "the answer (-s effects.contact=physical|paper|both; auto is physical\n"
	      "here; both gives an answer for each).  Runs that fail are skipped and\n"
	      "the last one's reason given when no answer is found.\n",
	      f);
}

/* The scene at x; the quantity's value (NaN when the run failed). */
static double fit_value(struct fit *f, double x, double *err)
{
	struct anvil_result r;
	char v[64];
	snprintf(v, sizeof v, "%.17g%s", x, f->k->unit);
	f->st = answer_eval(f->s, &f->sc, f->k->key, v, f->model, &r);
	if (f->st >= 0 && r.contact != f->contact) {
		/* not the contact asked for (solver.scheme = paper has its own alone) */
		snprintf(r.why, sizeof r.why, "the %s row has the %s contact, not the %s",
			 anvil_model_name(f->model), anvil_contact_name(r.contact),
			 anvil_contact_name(f->contact));
		f->st = ANVIL_EINVAL;
	}
	if (f->st < 0)
		snprintf(f->why, sizeof f->why, "%s", r.why); /* the last failure's reason */
	struct anvil_val a = answer_value(&r, f->q);
	anvil_result_free(&r);
	if (err)
		*err = a.err;
	return f->st < 0 ? NAN : a.val;
}

struct fit_fn {
	struct fit *f;
	double target;
};

static double brent_f(double u, void *p)
{
	struct fit_fn *fn = p;
	return fit_value(fn->f, exp(u), NULL) - fn->target;
}

/* The root of value(x) = target in [a, b] (a bracket), by Brent on log x. */
static int fit_brent(struct fit *f, double target, double a, double b, double *x)
{
	struct fit_fn fn = {f, target};
	gsl_function F = {brent_f, &fn};
	gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	int st = s ? gsl_root_fsolver_set(s, &F, log(a), log(b)) : GSL_ENOMEM;
	for (int i = 0; !st && i < FIT_MAXITER; i++) {
		if ((st = gsl_root_fsolver_iterate(s)))
			break;
		double lo = gsl_root_fsolver_x_lower(s), hi = gsl_root_fsolver_x_upper(s);
		if (gsl_root_test_interval(lo, hi, FIT_XTOL, 0) == GSL_SUCCESS) {
			*x = exp(gsl_root_fsolver_root(s));
			gsl_root_fsolver_free(s);
			return ANVIL_OK;
		}
	}
	gsl_root_fsolver_free(s);
	return ANVIL_ENUM;
}

/* The grid (filled from the top down) cell [i, i+1] where the values
 * first cross target, or -1. */
static int fit_cell(const struct fit *f, double target)
{
	for (int i = 0; i + 1 < f->ngrid; i++) {
		double a = f->grid_v[i] - target, b = f->grid_v[i + 1] - target;
		if (isfinite(a) && isfinite(b) && (a == 0 || a * b < 0))
			return i;
	}
	return -1;
}

static void fit_grid(struct fit *f)
{
	double step = pow(10, 1.0 / FIT_STEPS);
	int n = (int)ceil(log(f->hi / f->lo) / log(step) - 1e-9);
	if (n > FIT_MAXGRID - 1)
		n = FIT_MAXGRID - 1;
	f->ngrid = 0;
	/* from the top: thick layers are the cheap ones (short contacts) */
	for (int i = n; i >= 0; i--) {
		double x = i == n ? f->hi : i == 0 ? f->lo : f->lo * pow(f->hi / f->lo, (double)i / n);
		f->grid_x[f->ngrid] = x;
		f->grid_v[f->ngrid++] = fit_value(f, x, NULL);
		/* stop once every target has been crossed */
		if (fit_cell(f, f->target - f->terr) >= 0 && fit_cell(f, f->target) >= 0 &&
		    fit_cell(f, f->target + f->terr) >= 0)
			break;
	}
}

static int fit_solve(struct fit *f, double target, double *x)
{
	int i = fit_cell(f, target);
	if (i < 0)
		return ANVIL_ENOTFOUND;
	if (f->grid_v[i] == target) {
		*x = f->grid_x[i];
		return ANVIL_OK;
	}
	return fit_brent(f, target, fmin(f->grid_x[i], f->grid_x[i + 1]), fmax(f->grid_x[i], f->grid_x[i + 1]), x);
}

/* x for people: "1.03 r0 = 4.12 mm", "205 GPa", "3.1 m/s". */
static void fit_show(const struct fit *f, double x, char *buf, size_t n)
{
	char u[40];
	if (f->k->dim == ANVIL_DIM_LENGTH) {
		anvil_units_format(x * f->sc.radius, ANVIL_DIM_LENGTH, u, sizeof u);
		snprintf(buf, n, "%.4g r0 = %s", x, u);
	} else {
		anvil_units_format(x, f->k->dim, buf, n);
	}
}

static int fit_none(const struct fit *f, double target)
{
	double vmin = INFINITY, vmax = -INFINITY;
	int failed = 0;
	char a[64], b[64], t[64], lo[64], hi[64];
	for (int i = 0; i < f->ngrid; i++) {
		if (!isfinite(f->grid_v[i])) {
			failed++;
			continue;
		}
		vmin = fmin(vmin, f->grid_v[i]);
		vmax = fmax(vmax, f->grid_v[i]);
	}
	answer_format(f->q, target, t, sizeof t);
	fit_show(f, f->lo, lo, sizeof lo);
	fit_show(f, f->hi, hi, sizeof hi);
	if (vmin > vmax) {
		cli_error("fit: no %s in %s .. %s gives a value: every run failed (%s)", f->k->key, lo, hi,
			  f->why);
		return EXIT_FAIL;
	}
	answer_format(f->q, vmin, a, sizeof a);
	answer_format(f->q, vmax, b, sizeof b);
	cli_error("fit: no %s in %s .. %s gives %s = %s with the %s model%s%s: %s is %s .. %s there%s%s "
		  "(another --range, model or value?)", f->k->key, lo, hi, answer_qty_name[f->q], t,
		  anvil_model_name(f->model), f->contact ? ", contact " : "",
		  f->contact ? anvil_contact_name(f->contact) : "", answer_qty_name[f->q], a, b,
		  failed ? "; some runs failed: " : "", failed ? f->why : "");
	return EXIT_FAIL;
}

#define FIT_NCOL 10

/* The contact's name for the answer: "-" for a model with its own. */
static const char *fit_contact_name(const struct fit *f)
{
	return f->contact ? anvil_contact_name(f->contact) : "-";
}

/* The answer of one contact: sentences for people into o, a row for
 * programs into g (its header made by the caller). */
static void fit_print(struct fit *f, FILE *o, struct out_grid *g, double x, double xlo, double xhi)
{
	char sx[64], slo[64] = "-", shi[64] = "-", t[64], dt[64], e[64], cn[48] = "";
	double verr = NAN;
	fit_value(f, x, &verr);
	/* the solver's error of the value, carried to x by the local slope */
	int i = fit_cell(f, f->target);
	double slope = (f->grid_v[i + 1] - f->grid_v[i]) / (f->grid_x[i + 1] - f->grid_x[i]);
	double xerr = fabs(verr / slope);
	fit_show(f, x, sx, sizeof sx);
	if (f->terr > 0) {
		fit_show(f, fmin(xlo, xhi), slo, sizeof slo);
		fit_show(f, fmax(xlo, xhi), shi, sizeof shi);
	}
	answer_format(f->q, f->target, t, sizeof t);
	answer_format(f->q, f->terr, dt, sizeof dt);
	answer_format(f->q, verr, e, sizeof e);
	if (f->contact)
		snprintf(cn, sizeof cn, ", %s contact", anvil_contact_name(f->contact));
	if (f->format == OUT_TABLE) {
		fprintf(o, "%s = %s gives %s = %s (%s model%s)\n", f->k->key, sx, answer_qty_name[f->q], t,
			anvil_model_name(f->model), cn);
		if (f->terr > 0)
			fprintf(o, "%s = %s +- %s allows %s = %s .. %s\n", answer_qty_name[f->q], t, dt, f->k->key,
				isfinite(xlo) ? slo : "(beyond the range)", isfinite(xhi) ? shi : "(beyond the range)");
		fprintf(o, "accuracy: Brent on log x to %g; the solver's %s +- %s moves x by %.2g %s\n",
			FIT_XTOL, answer_qty_name[f->q], e, xerr, f->k->unit);
		return;
	}
	char a[40];
	out_grid_cell(g, "%s", f->k->key);
	out_grid_cell(g, "%s", f->k->unit);
	double v[3] = {x, f->terr > 0 ? fmin(xlo, xhi) : NAN, f->terr > 0 ? fmax(xlo, xhi) : NAN};
	for (int k = 0; k < 3; k++)
		out_grid_cell(g, "%s", out_num(a, v[k], NULL));
	out_grid_cell(g, "%s", answer_qty_name[f->q]);
	out_grid_cell(g, "%s", out_num(a, f->target, NULL));
	out_grid_cell(g, "%s", out_num(a, f->terr, NULL));
	out_grid_cell(g, "%s", out_num(a, xerr, NULL));
	out_grid_cell(g, "%s", fit_contact_name(f));
}

/* The fit of contact f->contact (set on f->sc). */
static int fit_one(struct fit *f, FILE *o, struct out_grid *g)
{
	double x, xlo = NAN, xhi = NAN;
	f->why[0] = '\0';
	fit_grid(f);
	int st = fit_solve(f, f->target, &x);
	if (st == ANVIL_ENOTFOUND)
		return fit_none(f, f->target);
	if (st) {
		cli_error("fit: the root finder failed near the bracket%s%s (%s)", f->contact ? ", contact " : "",
			  f->contact ? anvil_contact_name(f->contact) : "", f->why);
		return EXIT_FAIL;
	}
	/* ends of the interval: not found is beyond the range (NaN) */
	if (f->terr > 0 && fit_solve(f, f->target - f->terr, &xlo))
		xlo = NAN;
	if (f->terr > 0 && fit_solve(f, f->target + f->terr, &xhi))
		xhi = NAN;
	fit_print(f, o, g, x, xlo, xhi);
	return EXIT_OK;
}

/* The contact models to fit with: none of its own for hertz and zener;
 * else the scene's (auto: physical; both: the paper's, then physical). */
static int fit_contacts(const struct fit *f, enum anvil_contact c[2])
{
	if (f->model != ANVIL_MODEL_LAYER && f->model != ANVIL_MODEL_HALFSPACE) {
		c[0] = ANVIL_CONTACT_AUTO;
		return 1;
	}
	c[0] = f->sc.effects.contact == ANVIL_CONTACT_PAPER || f->sc.effects.contact == ANVIL_CONTACT_BOTH
		       ? ANVIL_CONTACT_PAPER
		       : ANVIL_CONTACT_PHYSICAL;
	c[1] = ANVIL_CONTACT_PHYSICAL;
	return f->sc.effects.contact == ANVIL_CONTACT_BOTH ? 2 : 1;
}

/* Every contact's fit; one that fails leaves the others (exit 1). */
static int fit_go(struct fit *f)
{
	static const char *const head[FIT_NCOL] = {"key", "unit", "value", "lo", "hi", "quantity",
						   "target_si", "target_err_si", "value_err", "contact"};
	enum anvil_contact cs[2];
	struct cli_out o;
	struct out_grid *g = f->format == OUT_TABLE ? NULL : out_grid_alloc(FIT_NCOL);
	int nc = fit_contacts(f, cs), code = EXIT_OK, answered = 0;
	if ((f->format != OUT_TABLE && !g) || !(f->s = anvil_solver_alloc()) || cli_out_open(&o, f->out)) {
		out_grid_free(g);
		anvil_solver_free(f->s);
		return EXIT_FAIL;
	}
	if (g) {
		out_grid_text(g, 0);
		out_grid_text(g, 1);
		out_grid_text(g, 5);
		out_grid_text(g, FIT_NCOL - 1);
		for (int k = 0; k < FIT_NCOL; k++)
			out_grid_cell(g, "%s", head[k]);
	}
	for (int k = 0; k < nc; k++) {
		if (cs[k])
			f->contact = f->sc.effects.contact = cs[k];
		int c = fit_one(f, o.f, g);
		answered += c == EXIT_OK;
		if (c != EXIT_OK)
			code = c;
	}
	if (!answered || (g && out_grid_print(g, (enum out_format)f->format, o.f))) {
		cli_out_abort(&o); /* nothing half-written */
		code = EXIT_FAIL;
	} else if (cli_out_commit(&o)) {
		code = EXIT_FAIL;
	}
	out_grid_free(g);
	anvil_solver_free(f->s);
	return code;
}

/* "ts=62us+-1us" (also "±"). */
static int fit_target(struct fit *f, const char *arg)
{
	struct anvil_err err = {0};
	char buf[128], *pm;
	const char *eq = strchr(arg, '=');
	int q;
	for (q = 0; eq && q < ANSWER_NQTY; q++)
		if ((size_t)(eq - arg) == strlen(answer_qty_name[q]) && !strncmp(arg, answer_qty_name[q], (size_t)(eq - arg)))
			break;
	if (!eq || q == ANSWER_NQTY)
		return out_usage("fit", "'%s': expected ts=TIME, Rf=NUMBER or Pmax=FORCE, e.g. ts=62us+-1us", arg);
	f->q = (enum answer_qty)q;
	snprintf(buf, sizeof buf, "%s", eq + 1);
	int wide = 0;
	if ((pm = strstr(buf, "+-")) || (pm = strstr(buf, "\xc2\xb1")))
		wide = 2; /* "+-" and UTF-8 "±" are both two bytes */
	if (pm && !pm[wide]) /* qa7: "ts=: expected a time ..., got ''" */
		return out_usage("fit", "'%s': nothing after +-: give the uncertainty, e.g. ts=62us+-1us", arg);
	if (pm)
		*pm = '\0';
	if (answer_parse(f->q, buf, &f->target, &err) ||
	    (pm && answer_parse(f->q, pm + wide, &f->terr, &err))) {
		fprintf(stderr, "anvil fit: %s\n", err.msg);
		return EXIT_USAGE;
	}
	if (f->terr < 0 || !isfinite(f->target))
		return out_usage("fit", "'%s': the uncertainty must be positive", arg);
	/* no run gives these (qa7: searched the whole range to say so) */
	if (f->q == ANSWER_RF ? !(f->target >= 0 && f->target <= 1) : !(f->target > 0))
		return out_usage("fit", "'%s': %s", arg,
				 f->q == ANSWER_RF ? "a restitution lies in 0 .. 1" : "must be > 0");
	return -1;
}

static int fit_range(struct fit *f, const char *s)
{
	/* LO ends at the first "..": strtod alone reads "50..100" as 50. and .100 */
	const char *dots = strstr(s, "..");
	char lo[64], *end;
	if (!dots || dots == s || (size_t)(dots - s) >= sizeof lo)
		return -1;
	memcpy(lo, s, (size_t)(dots - s));
	lo[dots - s] = '\0';
	f->lo = strtod(lo, &end);
	if (*end)
		return -1;
	const char *p = dots + 2;
	f->hi = strtod(p, &end);
	return end != p && !*end && f->lo > 0 && f->hi > f->lo && isfinite(f->hi) ? 0 : -1;
}

static const struct option fit_longopts[] = {
	{"set", required_argument, NULL, 's'},    {"for", required_argument, NULL, 'k'},
	{"range", required_argument, NULL, 'r'},  {"model", required_argument, NULL, 'm'},
	{"format", required_argument, NULL, 'f'}, {"output", required_argument, NULL, 'o'},
	{"help", no_argument, NULL, 'h'},         {NULL, 0, NULL, 0}};

static int fit_option(struct fit *f, int c, char **argv, const char **range)
{
	int m;
	switch (c) {
	case 's':
		return cli_sets_add(&f->sets, optarg) ? EXIT_FAIL : -1;
	case 'k':
		f->k = NULL;
		for (int i = 0; i < NKEYS; i++)
			if (!strcmp(optarg, fit_keys[i].key))
				f->k = &fit_keys[i];
		return f->k ? -1 : out_usage("fit", "--for %s: one of layer.thickness, layer.E, impact.velocity", optarg);
	case 'r':
		*range = optarg;
		return -1;
	case 'm':
		if ((m = anvil_model_parse(optarg)) < 0)
			return out_usage("fit", "--model %s: one of hertz, zener, layer, halfspace", optarg);
		f->model = (enum anvil_model)m;
		return -1;
	case 'f':
		f->format = out_format_parse("fit", optarg, OUT_ALL);
		return f->format < 0 ? EXIT_USAGE : -1;
	case 'o':
		f->out = optarg;
		return -1;
	case 'h':
		fit_usage(stdout);
		return EXIT_OK;
	}
	return out_getopt_error("fit", c, argv);
}

static int fit_parse(struct fit *f, int argc, char **argv)
{
	const char *range = NULL;
	int c, code;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, "-:s:m:f:o:h", fit_longopts, NULL)) != -1) {
		if (c == 1 && strchr(optarg, '=')) {
			if (f->target_arg)
				return out_usage("fit", "'%s': one measurement at a time", optarg);
			f->target_arg = optarg;
		} else if (c == 1 && !f->scene) {
			f->scene = optarg;
		} else if (c == 1) {
			return out_usage("fit", "unexpected argument '%s'", optarg);
		} else if ((code = fit_option(f, c, argv, &range)) >= 0) {
			return code;
		}
	}
	if (!f->target_arg)
		return out_usage("fit", "no measurement: give ts=TIME, Rf=NUMBER or Pmax=FORCE");
	if ((code = fit_target(f, f->target_arg)) >= 0)
		return code;
	f->lo = f->k->lo;
	f->hi = f->k->hi;
	if (range && fit_range(f, range))
		return out_usage("fit", "--range %s: expected LO..HI in %s, e.g. %g..%g", range, f->k->unit,
				 f->k->lo, f->k->hi);
	if (f->lo < f->k->min || f->hi > f->k->max)
		return out_usage("fit", "--range %s: %s takes %g..%g %s", range, f->k->key, f->k->min,
				 f->k->max, f->k->unit);
	f->format = out_format_pick(f->format, f->out);
	return -1;
}

int anvil_cmd_fit(int argc, char **argv)
{
	struct fit *f = calloc(1, sizeof *f);
	if (!f)
		return EXIT_FAIL;
	f->k = &fit_keys[0];
	f->model = ANVIL_MODEL_LAYER;
	f->format = -1;
	int code = fit_parse(f, argc, argv);
	if (code < 0) {
		int st = cli_scene(&f->sc, f->scene, f->sets.v, f->sets.n);
		code = st ? cli_exit_code(st) : fit_go(f);
	}
	cli_sets_free(&f->sets);
	free(f);
	return code;
}
