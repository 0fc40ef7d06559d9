/* cmd_answer.c: `anvil thickness`, the thinnest layer that acts as a
 * half-space: the smallest h for which the layer's R_f, P_max and t_s
 * are all within a tolerance of the half-space's.
 *
 * The search: from the top of the range down in octaves until a thickness
 * misses (so every octave above the answer is checked, not only assumed:
 * the deviation need not fall monotonically), then bisection on log h
 * between the last miss and the first hit above it, down to a ratio of
 * 1 + rtol.  Each evaluation is one layer run through one solver, so its
 * response is made once and kept on disk (cache.h): asking again, or with
 * another tolerance, costs milliseconds.
 *
 * Like with like: the layer and the half-space are run with one contact
 * model ([effects] contact), set explicitly on every scene evaluated, and
 * each result's contact is checked against it.  auto is the physical
 * contact here: the scenes searched (other thicknesses) are not the
 * paper's own case, which is what auto's both is kept for (options.h);
 * both gives one answer per contact model, the paper's first (as run). */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "answer.h"
#include "commands.h"
#include "common.h"
#include "output.h"
#include "scene_keys.h"
#include "units.h"

#define THICK_MAXEVAL 64

struct thick_point {
	double hr0;               /* h / r0 */
	struct anvil_result r;    /* the layer row */
	double dev[ANSWER_NQTY];  /* |layer - halfspace| / |halfspace| */
	double worst;             /* the largest of dev (inf: no values) */
};

struct thick {
	const char *scene, *out, *curve;
	enum anvil_contact contact; /* of the search under way: PHYSICAL or PAPER */
	double tol, rtol, lo, hi; /* hi, lo in r0 */
	int format;
	struct cli_sets sets;
	struct anvil_scene sc;    /* the scene, with contact set */
	struct anvil_result hs;   /* the half-space row */
	struct out_grid *cg;      /* --curve's rows, every contact */
	struct thick_point pt[THICK_MAXEVAL];
	int n;
};

static void thick_usage(FILE *f)
{
	fputs("usage: anvil thickness [SCENE] [-s KEY=VALUE]... [--within TOL] [--rtol TOL]\n"
	      "                       [--range LO..HI] [--curve FILE] [-f FORMAT] [-o FILE]\n"
	      "The smallest layer thickness for which R_f, P_max and t_s of the layer\n"
	      "model are all within TOL of the half-space's (the layer then acts as a\n"
	      "half-space), by bisection on log h.  The layer and the half-space have\n"
	      "the same contact model (-s effects.contact=physical|paper|both; auto is\n"
	      "physical here), named in the answer; both gives an answer for each.\n"
	      "  --within TOL     relative tolerance, e.g. 1% or 0.01 (default 1%)\n"
	      "  --rtol TOL       bisection tolerance on h (default 1%)\n"
	      "  --range LO..HI   the thicknesses searched, in r0 (default 0.25..64)\n"
	      "  --curve FILE     every thickness evaluated, with its deviations\n"
	      "  -f, -o           format and file of the answer (as anvil run); the\n"
	      "                   rows end with the contact column\n",
	      f);
}

/* "1%" or "0.01". */
static int parse_fraction(const char *s, double *x)
{
	char *end;
	*x = strtod(s, &end);
	if (end != s && *end == '%' && !end[1])
		*x /= 100;
	else if (end == s || *end)
		return -1;
	return isfinite(*x) && *x > 0 && *x < 1 ? 0 : -1;
}

static int parse_range(const char *s, double *lo, double *hi)
{
	/* LO ends at the first "..": strtod alone reads "50..100" as 50. and .100 */
	const char *dots = strstr(s, "..");
	char buf[64], *end;
	if (!dots || dots == s || (size_t)(dots - s) >= sizeof buf)
		return -1;
	memcpy(buf, s, (size_t)(dots - s));
	buf[dots - s] = '\0';
	*lo = strtod(buf, &end);
	if (*end)
		return -1;
	const char *p = dots + 2;
	*hi = strtod(p, &end);
	if (end == p || (*end && strcasecmp(end, "r0")))
		return -1;
	return *lo > 0 && *hi > *lo && isfinite(*hi) ? 0 : -1;
}

/* what layer.thickness takes in r0 (scene_keys.h): --range stays inside */
static const double h_r0_lim[2] = { ANVIL_RANGE_H_R0 };

static const struct option thick_longopts[] = {
	{"set", required_argument, NULL, 's'},   {"within", required_argument, NULL, 'w'},
	{"rtol", required_argument, NULL, 't'},  {"range", required_argument, NULL, 'r'},
	{"curve", required_argument, NULL, 'c'}, {"format", required_argument, NULL, 'f'},
	{"output", required_argument, NULL, 'o'}, {"help", no_argument, NULL, 'h'},
	{NULL, 0, NULL, 0}};

static int thick_option(struct thick *t, int c, char **argv)
{
	switch (c) {
	case 's':
		return cli_sets_add(&t->sets, optarg) ? EXIT_FAIL : -1;
	case 'w':
		return parse_fraction(optarg, &t->tol)
			       ? out_usage("thickness", "--within %s: expected a tolerance such as 1%% or 0.01", optarg)
			       : -1;
	case 't':
		return parse_fraction(optarg, &t->rtol)
			       ? out_usage("thickness", "--rtol %s: expected a tolerance such as 1%% or 0.01", optarg)
			       : -1;
	case 'r':
		if (parse_range(optarg, &t->lo, &t->hi))
			return out_usage("thickness", "--range %s: expected LO..HI in r0, e.g. 0.5..32", optarg);
		if (t->lo < h_r0_lim[0] || t->hi > h_r0_lim[1])
			return out_usage("thickness", "--range %s: layer.thickness takes %g..%g r0", optarg,
					 h_r0_lim[0], h_r0_lim[1]);
		return -1;
	case 'c':
		t->curve = optarg;
		return -1;
	case 'f':
		t->format = out_format_parse("thickness", optarg, OUT_ALL);
		return t->format < 0 ? EXIT_USAGE : -1;
	case 'o':
		t->out = optarg;
		return -1;
	case 'h':
		thick_usage(stdout);
		return EXIT_OK;
	}
	return out_getopt_error("thickness", c, argv);
}

/* The layer at h = hr0 r0, compared with the half-space. */
static struct thick_point *thick_eval(struct thick *t, struct anvil_solver *s, double hr0)
{
	for (int i = 0; i < t->n; i++)
		if (t->pt[i].hr0 == hr0)
			return &t->pt[i];
	if (t->n == THICK_MAXEVAL)
		return NULL;
	struct thick_point *p = &t->pt[t->n++];
	char v[64];
	snprintf(v, sizeof v, "%.17gr0", hr0);
	p->hr0 = hr0;
	int st = answer_eval(s, &t->sc, "layer.thickness", v, ANVIL_MODEL_LAYER, &p->r);
	if (st >= 0 && p->r.contact != t->contact) {
		/* not like with like (solver.scheme = paper has its contact alone) */
		snprintf(p->r.why, sizeof p->r.why, "the layer row has the %s contact, not the %s",
			 anvil_contact_name(p->r.contact), anvil_contact_name(t->contact));
		p->r.status = st = ANVIL_EINVAL;
	}
	p->worst = 0;
	for (int q = 0; q < ANSWER_NQTY; q++) {
		double a = answer_value(&p->r, (enum answer_qty)q).val,
		       b = answer_value(&t->hs, (enum answer_qty)q).val;
		p->dev[q] = st < 0 ? INFINITY : fabs(a - b) / fabs(b);
		if (!(p->dev[q] <= p->worst))
			p->worst = isnan(p->dev[q]) ? INFINITY : p->dev[q];
	}
	return p;
}

/* Octaves down from hi to the first miss, then bisection.  *found: the
 * smallest hit (NULL when hi misses); *miss: the miss below it (NULL
 * when even lo hits). */
static int thick_search(struct thick *t, struct anvil_solver *s, struct thick_point **found,
			struct thick_point **miss)
{
	struct thick_point *hit = NULL, *p;
	*miss = NULL;
	for (double h = t->hi;; h /= 2) {
		if (h < t->lo)
			h = t->lo;
		if (!(p = thick_eval(t, s, h)))
			return ANVIL_ENOMEM;
		if (p->worst > t->tol) {
			*miss = p;
			break;
		}
		hit = p;
		if (h == t->lo)
			break;
	}
	/* bisection on log h: the answer lies in (miss, hit] */
	while (hit && *miss && hit->hr0 / (*miss)->hr0 > 1 + t->rtol) {
		double h = sqrt(hit->hr0 * (*miss)->hr0);
		double hr0_hit = hit->hr0, hr0_miss = (*miss)->hr0;
		if (!(p = thick_eval(t, s, h)))
			return ANVIL_ENOMEM;
		/* t->pt may not move (a fixed array): pointers stay valid */
		if (p->worst > t->tol)
			*miss = p;
		else
			hit = p;
		if (hit->hr0 == hr0_hit && (*miss)->hr0 == hr0_miss)
			break; /* h rounds to an end: as close as doubles go */
	}
	*found = hit;
	return ANVIL_OK;
}

static int point_cmp(const void *a, const void *b)
{
	const struct thick_point *x = a, *y = b;
	return (x->hr0 > y->hr0) - (x->hr0 < y->hr0);
}

#define CURVE_NCOL 13

/* The thicknesses of this contact's search, sorted, into t->cg. */
static void thick_curve_add(struct thick *t)
{
	struct thick_point sorted[THICK_MAXEVAL];
	char a[40];
	static const char *const head[CURVE_NCOL] = {"h_r0", "h_m", "Rf", "Rf_err", "Pmax_kN", "Pmax_err_kN",
						     "ts_us", "ts_err_us", "dev_ts", "dev_Rf", "dev_Pmax",
						     "within", "contact"};
	if (!t->cg) {
		if (!(t->cg = out_grid_alloc(CURVE_NCOL)))
			return; /* reported when written */
		out_grid_text(t->cg, CURVE_NCOL - 1);
		for (int i = 0; i < CURVE_NCOL; i++)
			out_grid_cell(t->cg, "%s", head[i]);
	}
	memcpy(sorted, t->pt, (size_t)t->n * sizeof *sorted);
	qsort(sorted, (size_t)t->n, sizeof *sorted, point_cmp);
	for (int i = 0; i < t->n; i++) {
		const struct thick_point *p = &sorted[i];
		double v[11] = {p->hr0, p->hr0 * t->sc.radius, p->r.Rf.val, p->r.Rf.err, 1e-3 * p->r.Pmax.val,
				1e-3 * p->r.Pmax.err, 1e6 * p->r.ts.val, 1e6 * p->r.ts.err,
				p->dev[ANSWER_TS], p->dev[ANSWER_RF], p->dev[ANSWER_PMAX]};
		for (int k = 0; k < 11; k++)
			out_grid_cell(t->cg, "%s", out_num(a, v[k], NULL));
		out_grid_cell(t->cg, "%d", p->worst <= t->tol);
		out_grid_cell(t->cg, "%s", anvil_contact_name(t->contact));
	}
}

static int thick_curve_write(struct thick *t)
{
	struct cli_out o;
	enum out_format fmt = (enum out_format)out_format_pick(-1, t->curve);
	if (!t->cg)
		return ANVIL_ENOMEM;
	int st = cli_out_open(&o, t->curve);
	if (!st && (st = out_grid_print(t->cg, fmt == OUT_TABLE ? OUT_TSV : fmt, o.f)))
		cli_out_abort(&o);
	else if (!st)
		st = cli_out_commit(&o);
	return st;
}

#define ANSWER_NCOL 9

/* The answer of one contact: a sentence for people into f, one row for
 * programs into g (header made by the caller). */
static void thick_print(struct thick *t, FILE *f, struct out_grid *g, const struct thick_point *hit,
			const struct thick_point *miss)
{
	char hm[40], buf[3][64], hs[3][64];
	const char *cn = anvil_contact_name(t->contact);
	for (int q = 0; q < ANSWER_NQTY; q++) {
		answer_format((enum answer_qty)q, answer_value(&hit->r, (enum answer_qty)q).val, buf[q], 64);
		answer_format((enum answer_qty)q, answer_value(&t->hs, (enum answer_qty)q).val, hs[q], 64);
	}
	anvil_units_format(hit->hr0 * t->sc.radius, ANVIL_DIM_LENGTH, hm, sizeof hm);
	if (t->format == OUT_TABLE) {
		fprintf(f, "%s contact: h = %.4g r0 = %s: R_f, P_max and t_s within %g%% of the "
			"half-space's (same contact)\n", cn, hit->hr0, hm, 100 * t->tol);
		for (int q = 0; q < ANSWER_NQTY; q++)
			fprintf(f, "  %-4s %s (half-space %s, %+.3g%%)\n", answer_qty_name[q], buf[q], hs[q],
				100 * (answer_value(&hit->r, (enum answer_qty)q).val -
				       answer_value(&t->hs, (enum answer_qty)q).val) /
					answer_value(&t->hs, (enum answer_qty)q).val);
		if (miss)
			fprintf(f, "accuracy: bisection on log h to %g%%: h = %.4g r0 is not within; the "
				"solver's error estimates at h: R_f +-%.2g, t_s +-%.2g us, P_max +-%.2g kN\n",
				100 * t->rtol, miss->hr0, hit->r.Rf.err, 1e6 * hit->r.ts.err, 1e-3 * hit->r.Pmax.err);
		else
			fprintf(f, "(the bottom of the range, %g r0: thinner layers were not tried)\n", t->lo);
		return;
	}
	char a[40];
	double v[ANSWER_NCOL - 1] = {hit->hr0, hit->hr0 * t->sc.radius, miss ? miss->hr0 : NAN, t->tol, t->rtol,
				     hit->dev[ANSWER_TS], hit->dev[ANSWER_RF], hit->dev[ANSWER_PMAX]};
	for (int i = 0; i < ANSWER_NCOL - 1; i++)
		out_grid_cell(g, "%s", out_num(a, v[i], NULL));
	out_grid_cell(g, "%s", cn);
}

/* The search and answer for contact t->contact (set on t->sc). */
static int thick_one(struct thick *t, FILE *f, struct out_grid *g)
{
	struct thick_point *hit = NULL, *miss = NULL;
	struct anvil_solver *s = anvil_solver_alloc();
	struct anvil_err err = {0};
	const char *cn = anvil_contact_name(t->contact);
	int code = EXIT_OK;
	if (!s)
		return EXIT_FAIL;
	t->n = 0;
	if (cli_run_model(s, &t->sc, ANVIL_MODEL_HALFSPACE, 0, &t->hs, &err) < 0) {
		cli_error("thickness: %s contact: the half-space: %s", cn, t->hs.why);
		code = EXIT_FAIL;
	} else if (t->hs.contact != t->contact) {
		cli_error("thickness: the half-space row has the %s contact, not the %s (solver.scheme = "
			  "paper has the paper's contact alone)", anvil_contact_name(t->hs.contact), cn);
		code = EXIT_FAIL;
	} else if (thick_search(t, s, &hit, &miss)) {
		cli_error("out of memory");
		code = EXIT_FAIL;
	} else if (!hit) {
		cli_error("thickness: %s contact: even h = %g r0 is not within %g%% of the half-space "
			  "(worst deviation %.3g%%%s%s): widen --range or loosen --within",
			  cn, t->hi, 100 * t->tol, 100 * miss->worst, miss->r.status < 0 ? ": " : "",
			  miss->r.status < 0 ? miss->r.why : "");
		code = EXIT_FAIL;
	} else {
		thick_print(t, f, g, hit, miss);
	}
	if (t->curve && t->n)
		thick_curve_add(t);
	for (int i = 0; i < t->n; i++)
		anvil_result_free(&t->pt[i].r);
	anvil_result_free(&t->hs);
	anvil_solver_free(s);
	return code;
}

/* The contact models to answer for: the scene's, resolved (see the top). */
static int thick_contacts(const struct thick *t, enum anvil_contact c[2])
{
	switch (t->sc.effects.contact) {
	case ANVIL_CONTACT_BOTH:
		c[0] = ANVIL_CONTACT_PAPER;
		c[1] = ANVIL_CONTACT_PHYSICAL;
		return 2;
	case ANVIL_CONTACT_PAPER:
		c[0] = ANVIL_CONTACT_PAPER;
		return 1;
	default:
		c[0] = ANVIL_CONTACT_PHYSICAL;
		return 1;
	}
}

/* Every contact's answer, the others still given when one fails (exit 1). */
static int thick_go(struct thick *t)
{
	static const char *const head[ANSWER_NCOL] = {"h_r0", "h_m", "h_below_r0", "within", "rtol",
						      "dev_ts", "dev_Rf", "dev_Pmax", "contact"};
	enum anvil_contact cs[2];
	struct cli_out o;
	struct out_grid *g = t->format == OUT_TABLE ? NULL : out_grid_alloc(ANSWER_NCOL);
	int nc = thick_contacts(t, cs), code = EXIT_OK, answered = 0;
	if ((t->format != OUT_TABLE && !g) || cli_out_open(&o, t->out)) {
		out_grid_free(g);
		return EXIT_FAIL;
	}
	if (g) {
		out_grid_text(g, ANSWER_NCOL - 1);
		for (int i = 0; i < ANSWER_NCOL; i++)
			out_grid_cell(g, "%s", head[i]);
	}
	for (int k = 0; k < nc; k++) {
		t->contact = t->sc.effects.contact = cs[k];
		int c = thick_one(t, o.f, g);
		answered += c == EXIT_OK;
		if (c != EXIT_OK)
			code = c;
	}
	if (!answered || (g && out_grid_print(g, (enum out_format)t->format, o.f))) {
		cli_out_abort(&o); /* nothing half-written */
		code = EXIT_FAIL;
	} else if (cli_out_commit(&o)) {
		code = EXIT_FAIL;
	}
	if (t->curve && t->cg && thick_curve_write(t))
		code = EXIT_FAIL;
	out_grid_free(g);
	out_grid_free(t->cg);
	return code;
}

int anvil_cmd_thickness(int argc, char **argv)
{
	struct thick *t = calloc(1, sizeof *t);
	int c, code = -1;
	if (!t)
		return EXIT_FAIL;
	t->tol = 0.01;
	t->rtol = 0.01;
	t->lo = 0.25;
	t->hi = 64;
	t->format = -1;
	opterr = 0;
	optind = 1;
	while (code < 0 && (c = getopt_long(argc, argv, ":s:f:o:h", thick_longopts, NULL)) != -1)
		code = thick_option(t, c, argv);
	if (code < 0 && optind < argc)
		t->scene = argv[optind++];
	if (code < 0 && optind < argc)
		code = out_usage("thickness", "unexpected argument '%s'", argv[optind]);
	if (code < 0) {
		t->format = out_format_pick(t->format, t->out);
		int st = cli_scene(&t->sc, t->scene, t->sets.v, t->sets.n);
		code = st ? cli_exit_code(st) : thick_go(t);
	}
	cli_sets_free(&t->sets);
	free(t);
	return code;
}
