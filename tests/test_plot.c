/* test_plot.c: the chart scripts as text, from fixed synthetic results.
 *
 * Each generated script is compared with tests/plot-expected/NAME.gp,
 * ignoring only trailing whitespace.  After a deliberate change of the
 * generator, regenerate the expected files with
 *   PLOT_EXPECTED_UPDATE=1 tests/test_plot
 * and review the diff.  Also: gnuplot quoting of hostile text, kind names,
 * and every error a builder or the writer can return. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tap.h"
#include "plot.h"
#include "tui_plot.h"

#define NPTS 5

/* A result of model m whose history is a small, exact, made-up curve. */
static void fake_result(struct anvil_result *r, enum anvil_model m, double scale)
{
	anvil_result_init(r, m);
	if (anvil_history_alloc(&r->hist, NPTS))
		abort();
	for (int i = 0; i < NPTS; i++) {
		r->hist.t[i] = 1e-5 * i * scale;
		r->hist.P[i] = 1000.0 * i * (NPTS - 1 - i) * scale;
		r->hist.v[i] = 10.0 - 4.0 * i * scale;
		r->hist.w[i] = 1e-6 * i * scale;
		r->hist.W[i] = r->hist.alpha[i] = 0;
	}
	r->Rf.val = 0.5 * scale;
	r->Pmax.val = 4000 * scale;
	r->ts.val = 4e-5 * scale;
}

static char *slurp(const char *path)
{
	FILE *f = fopen(path, "r");
	char *buf = NULL;
	size_t len = 0;
	if (!f)
		return NULL;
	FILE *m = open_memstream(&buf, &len);
	int c;
	while ((c = fgetc(f)) != EOF)
		fputc(c, m);
	fclose(f);
	fclose(m);
	return buf;
}

/* The next line of *p without its trailing whitespace, into line. */
static int next_line(const char **p, char *line, size_t size)
{
	if (!**p)
		return 0;
	size_t n = strcspn(*p, "\n");
	size_t keep = n;
	while (keep > 0 && strchr(" \t\r", (*p)[keep - 1]))
		keep--;
	snprintf(line, size, "%.*s", (int)keep, *p);
	*p += n + ((*p)[n] == '\n');
	return 1;
}

/* Equal up to trailing whitespace on each line and trailing blank lines. */
static int same_text(const char *got, const char *want, int *lineno)
{
	char a[4096], b[4096];
	*lineno = 0;
	for (;;) {
		++*lineno;
		int ga = next_line(&got, a, sizeof a), gb = next_line(&want, b, sizeof b);
		if (!ga && !gb)
			return 1;
		if (!ga)
			a[0] = '\0';
		if (!gb)
			b[0] = '\0';
		if (strcmp(a, b) != 0) {
			diag("line %d: got  '%s'", *lineno, a);
			diag("line %d: want '%s'", *lineno, b);
			return 0;
		}
	}
}

static void is_script(const struct plot_chart *c, const struct plot_opts *o,
		      const char *name)
{
	char *got = NULL, path[1024];
	size_t len = 0;
	const char *top = getenv("top_srcdir");
	FILE *m = open_memstream(&got, &len);
	int st = plot_write(m, c, o), line;
	fclose(m);
	snprintf(path, sizeof path, "%s/tests/plot-expected/%s.gp", top ? top : ".", name);
	if (getenv("PLOT_EXPECTED_UPDATE")) {
		FILE *f = fopen(path, "w");
		ok(f && fputs(got, f) >= 0 && fclose(f) == 0, "%s: expected file rewritten", path);
		free(got);
		return;
	}
	char *want = slurp(path);
	ok(st == ANVIL_OK && want && same_text(got, want, &line),
	   "script '%s' matches %s", name, path);
	if (!want)
		diag("cannot read %s (set top_srcdir)", path);
	free(got);
	free(want);
}

/* TAP's skip: counted as passed, with the reason. */
static void skip_test(const char *what, const char *why)
{
	printf("ok %d # SKIP %s: %s\n", ++tap_n, what, why);
	fflush(stdout);
}

/* Figs 2-3 style: two thicknesses, the half-space, Zener, Hertz, and a
 * failed layer run that must not show. */
static void test_force(void)
{
	struct anvil_result r[6];
	struct plot_chart c;
	struct plot_opts o;
	fake_result(&r[0], ANVIL_MODEL_LAYER, 1.0);
	fake_result(&r[1], ANVIL_MODEL_LAYER, 0.8);
	fake_result(&r[2], ANVIL_MODEL_HALFSPACE, 1.1);
	fake_result(&r[3], ANVIL_MODEL_ZENER, 0.9);
	fake_result(&r[4], ANVIL_MODEL_HERTZ, 1.2);
	anvil_result_init(&r[5], ANVIL_MODEL_LAYER);
	struct plot_run runs[] = {
		{&r[0], ANVIL_MODEL_LAYER, 1, 10, 0.633},
		{NULL, ANVIL_MODEL_LAYER, 2, 10, 0.158},
		{&r[1], ANVIL_MODEL_LAYER, 5, 10, 0.025},
		{&r[2], ANVIL_MODEL_HALFSPACE, INFINITY, 10, 0},
		{&r[3], ANVIL_MODEL_ZENER, 1, 10, 0.633},
		{&r[4], ANVIL_MODEL_HERTZ, 1, 10, 0.633},
		{&r[5], ANVIL_MODEL_LAYER, 7, 10, 0.01}, /* no history: not drawn */
	};
	plot_opts_default(&o);
	ok(plot_chart_history(&c, PLOT_FORCE, runs, 7) == ANVIL_OK, "force chart built");
	ok(c.nseries == 5, "five series (failed and history-less runs left out)");
	ok(c.s[0].mark == PLOT_BAND && c.s[0].colour == PLOT_BLACK,
	   "the half-space first, a black band under the rest");
	ok(c.s[1].colour == plot_h_colour(1) && c.s[3].colour == c.s[1].colour &&
	   c.s[3].mark == PLOT_DASH && c.s[2].colour == plot_h_colour(5) &&
	   c.s[2].colour != c.s[1].colour, "colour by thickness, Zener dashed in its colour");
	ok(c.s[4].mark == PLOT_DOTS && c.s[4].colour == PLOT_BLACK, "Hertz dotted black");
	ok(c.nkeys == 6 && strcmp(c.keys[0].label, "h = 1 r_0") == 0 &&
	   c.keys[2].mark == PLOT_BAND, "key: three thicknesses, then three model styles");
	is_script(&c, &o, "force");
	plot_chart_free(&c);
	/* One scene: a hostile title, a font, a size. */
	o.title = "it's \"x\"\nsystem(\"touch /tmp/pwned\") `touch /tmp/pwned` @GPVAL ^_{}\\";
	o.font = "Serif,9'";
	o.width = 640;
	o.height = 400;
	ok(plot_chart_history(&c, PLOT_DEFLECTION, runs + 2, 4) == ANVIL_OK,
	   "deflection chart of one scene built");
	ok(c.nseries == 3, "deflection: Hertz's w = 0 is not drawn");
	ok(c.nkeys > 0 && strstr(c.keys[c.nkeys - 1].label, "not drawn") != NULL,
	   "deflection: the key says why Hertz is missing");
	is_script(&c, &o, "deflection-scene");
	plot_chart_free(&c);
	ok(plot_chart_history(&c, PLOT_VELOCITY, runs + 1, 1) == ANVIL_EINVAL,
	   "history of only failed runs: ANVIL_EINVAL");
	plot_opts_default(&o);
	o.height = 1000;
	ok(plot_chart_history(&c, PLOT_HISTORY, runs, 6) == ANVIL_OK, "history chart built");
	ok(c.nseries == 3 * 5 - 1, "history: three panels of five runs, Hertz's w left out");
	is_script(&c, &o, "history");
	plot_chart_free(&c);
	for (int i = 0; i < 6; i++)
		anvil_result_free(&r[i]);
}

/* Issue 11: a thin plate's P beside the rigid anvil's.  Peaks more than
 * 20 times apart put P on a log axis (plot_force_log), else linear. */
/* A drop weight's three rows on h = 0.1 r0 at 5 m/s: the layer, Hertz's
 * rigid anvil and the half-space (fake histories, scaled by the caller). */
static void drop_weight(struct anvil_result r[3], struct plot_run runs[3])
{
	static const enum anvil_model m[3] = {ANVIL_MODEL_LAYER, ANVIL_MODEL_HERTZ,
					      ANVIL_MODEL_HALFSPACE};
	for (int i = 0; i < 3; i++) {
		fake_result(&r[i], m[i], 1.0);
		runs[i] = (struct plot_run){&r[i], m[i], m[i] == ANVIL_MODEL_HALFSPACE ? INFINITY : 0.1,
					    5, 0};
	}
}

static void test_force_log(void)
{
	double range[2] = {-1, -1};
	double near[3] = {4000, 300, 0}, far[3] = {105e3, 78.3, 0}, edge[2] = {2000, 100};
	ok(plot_force_log(near, 3, range) == 0 && range[0] == -1, "peaks 13x apart: linear");
	ok(plot_force_log(edge, 2, range) == 0, "exactly 20x apart: linear");
	int lg = plot_force_log(far, 3, range);
	ok(lg == 1 && range[0] == 0.783 && range[1] == 1.5 * 105e3,
	   "105 kN beside 78.3 N: log from a hundredth of the smaller (%g N) to 1.5 times the "
	   "larger (%g N); a zero peak ignored", range[0], range[1]);
	struct anvil_result r[3];
	struct plot_run runs[3];
	struct plot_chart c;
	struct plot_opts o;
	drop_weight(r, runs);
	for (int i = 0; i < NPTS; i++) /* the rigid anvils 100 times the layer */
		r[1].hist.P[i] *= 100, r[2].hist.P[i] *= 90;
	plot_opts_default(&o);
	int st = plot_chart_history(&c, PLOT_FORCE, runs, 3);
	ok(st == ANVIL_OK && c.force_log[0] == 0.04 &&
		   c.force_log[1] == 1.5 * 400,
	   "force chart of peaks 4 and 400 kN: log P over [%g, %g] kN", c.force_log[0],
	   c.force_log[1]);
	is_script(&c, &o, "force-log");
	plot_chart_free(&c);
	o.height = 1000;
	ok(plot_chart_history(&c, PLOT_HISTORY, runs, 3) == ANVIL_OK && c.force_log[1] > 0,
	   "history chart: its P panel log too");
	is_script(&c, &o, "history-log");
	plot_chart_free(&c);
	ok(plot_chart_history(&c, PLOT_VELOCITY, runs, 3) == ANVIL_OK && c.force_log[1] == 0,
	   "a velocity chart has no force axis");
	plot_chart_free(&c);
	for (int i = 0; i < 3; i++)
		anvil_result_free(&r[i]);
}

/* A script as text (plot_write into memory); the caller frees it. */
static char *script_text(const struct plot_chart *c, const struct plot_opts *o)
{
	char *got = NULL;
	size_t len = 0;
	FILE *m = open_memstream(&got, &len);
	int st = plot_write(m, c, o);
	fclose(m);
	if (st) {
		free(got);
		return NULL;
	}
	return got;
}

/* A drop weight's plate w beside the half-space's: the deflection axis
 * takes the force's 20x rule (plot_deflection_log), |w| where a curve
 * changes sign (the physical contact's half-space), w where none does,
 * linear and not cut at 0 when the peaks are near. */
static void test_deflection_log(void)
{
	double range[2] = {-1, -1};
	int abs = -1;
	double drop[2] = {0.64, 0.47e-6}, dlow[2] = {0, -0.47e-6};
	double paper[2] = {105e-6, 8.8e-6}, plow[2] = {0, 0};
	double zen[2] = {105e-6, 1.5e-6};
	ok(plot_deflection_log(paper, plow, 2, range, &abs) == 0 && range[0] == -1 && abs == -1,
	   "w peaks 12x apart: linear");
	int lg = plot_deflection_log(zen, plow, 2, range, &abs);
	ok(lg == 1 && abs == 0 &&
		   range[0] == 0.01 * 1.5e-6 && range[1] == 1.5 * 105e-6,
	   "70x apart, every w >= 0: log w over [%g, %g] m", range[0], range[1]);
	ok(plot_deflection_log(drop, dlow, 2, range, &abs) == 1 && abs == 1 &&
		   range[0] == 0.01 * 0.47e-6,
	   "640 mm beside +-0.47 um: log, |w| (a curve changes sign)");
	struct anvil_result r[3];
	struct plot_run runs[3];
	struct plot_chart c;
	struct plot_opts o;
	drop_weight(r, runs);
	static const double hs_w[NPTS] = {0, -0.5e-6, 0, 0.5e-6, 0.25e-6};
	for (int i = 0; i < NPTS; i++) { /* the plate 4 mm; the half-space +-0.5 um */
		r[0].hist.w[i] *= 1000;
		r[2].hist.w[i] = hs_w[i];
	}
	plot_opts_default(&o);
	int st = plot_chart_history(&c, PLOT_DEFLECTION, runs, 3);
	ok(st == ANVIL_OK && c.w_in_mm && c.w_abs && c.w_log[0] == 0.01 * 0.5e-3 &&
		   c.w_log[1] == 1.5 * 4,
	   "deflection chart, 4 mm beside +-0.5 um: log |w| over [%g, %g] mm", c.w_log[0],
	   c.w_log[1]);
	int drawn = c.nseries == 2, pos = 1;
	for (int i = 0; drawn && i < c.nseries; i++)
		for (size_t j = 0; j < c.s[i].n; j++)
			pos &= c.s[i].y[j] >= 0;
	ok(drawn && pos && c.s[0].y[1] == 0.5e-6, "  |w| drawn: the half-space's -0.5 um at 0.5");
	char *txt = script_text(&c, &o);
	ok(txt && strstr(txt, "set ylabel 'deflection |w| (mm), log scale'") &&
		   strstr(txt, "set logscale y\nset yrange [5e-06:6]"),
	   "  labelled |w|, log scale");
	free(txt);
	is_script(&c, &o, "deflection-log");
	plot_chart_free(&c);
	o.height = 1000;
	ok(plot_chart_history(&c, PLOT_HISTORY, runs, 3) == ANVIL_OK && c.w_log[1] > 0 &&
		   (txt = script_text(&c, &o)) && strstr(txt, "set ylabel '|w| (mm), log'"),
	   "history chart: its w panel log |w| too");
	free(txt);
	plot_chart_free(&c);
	/* near peaks, one below 0: linear, the dip kept (the kind's [0:*] lifted) */
	for (int i = 0; i < NPTS; i++)
		r[2].hist.w[i] = 1e-3 * i * (i - 2);
	o.height = 600;
	ok(plot_chart_history(&c, PLOT_DEFLECTION, runs, 3) == ANVIL_OK && c.w_log[1] == 0 &&
		   c.w_neg && (txt = script_text(&c, &o)) &&
		   strstr(txt, "set yrange [0:*]\nset yrange [*:*]") &&
		   strstr(txt, "deflection w (mm), + into the layer"),
	   "peaks near, a curve below 0: linear, not cut at 0, w");
	free(txt);
	plot_chart_free(&c);
	for (int i = 0; i < 3; i++)
		anvil_result_free(&r[i]);
}

/* Fig 8: layer points at two thicknesses and two velocities, a dense
 * layer curve, the half-space level, Zener's curves, the paper's values
 * and a marked thickness. */
static void test_rf_thickness(void)
{
	struct anvil_result r[5];
	struct plot_chart c;
	struct plot_opts o;
	double zx[] = {0.5, 1, 2, 5, 20}, z10[] = {0.02, 0.34, 0.76, 0.96, 0.997},
	       z100[] = {0.003, 0.18, 0.65, 0.93, 0.995}, lx[] = {1, 1.5, 2},
	       ly[] = {0.344, 0.6, 0.77};
	struct plot_curve zc[] = {{10, 5, zx, z10}, {100, 5, zx, z100}};
	struct plot_curve lc[] = {{10, 3, lx, ly}};
	struct plot_paper paper = {2, {{10, 1, 0.344, 0.633, 0.3368, 6.856, 46},
				       {100, INFINITY, 0.991, 0.0025, 0.9957, 161.5, 27}}};
	for (int i = 0; i < 5; i++)
		anvil_result_init(&r[i], i < 4 ? ANVIL_MODEL_LAYER : ANVIL_MODEL_HALFSPACE);
	r[0].Rf.val = 0.77, r[1].Rf.val = 0.344, r[2].Rf.val = 0.657, r[3].Rf.val = 0.177, r[4].Rf.val = 0.991;
	struct plot_run runs[] = {
		{&r[0], ANVIL_MODEL_LAYER, 2, 10, 0.158},
		{&r[1], ANVIL_MODEL_LAYER, 1, 10, 0.633}, /* out of order on purpose */
		{NULL, ANVIL_MODEL_LAYER, 5, 10, 0.025},
		{&r[2], ANVIL_MODEL_LAYER, 2, 100, 0.25},
		{&r[3], ANVIL_MODEL_LAYER, 1, 100, 1.0},
		{&r[4], ANVIL_MODEL_HALFSPACE, INFINITY, 100, 0},
	};
	plot_opts_default(&o);
	ok(plot_chart_rf_thickness(&c, runs, 6, lc, 1, zc, 2, &paper, 0.004, 30) == ANVIL_OK,
	   "restitution-thickness built");
	ok(strstr(c.setup, "set xrange [0.5:45]") != NULL,
	   "the axis widens to show a marked thickness of 30 r0");
	ok(strstr(c.setup, "set x2range [2:180]") != NULL && strstr(c.setup, "r_0 = 4 mm"),
	   "second axis in mm, r0 stated");
	int open = 0;
	for (int i = 0; i < c.nseries; i++)
		open += c.s[i].mark == PLOT_OPEN;
	ok(open == 1, "the paper's finite-h value as an open marker (the half-space is a level)");
	is_script(&c, &o, "restitution-thickness");
	plot_chart_free(&c);
	ok(plot_chart_rf_thickness(&c, runs + 2, 1, NULL, 0, NULL, 0, NULL, 0.004, NAN) ==
	   ANVIL_EINVAL, "restitution-thickness with nothing computed: ANVIL_EINVAL");
	plot_chart_free(&c);
	open = 0;
	ok(plot_chart_rf_thickness(&c, runs + 3, 3, NULL, 0, NULL, 0, &paper, 0.004, NAN) ==
	   ANVIL_OK, "restitution-thickness at 100 m/s only");
	for (int i = 0; i < c.nseries; i++)
		open += c.s[i].mark == PLOT_OPEN;
	ok(open == 0, "the paper's values at 10 m/s are not drawn on a 100 m/s chart");
	plot_chart_free(&c);
}

/* Fig 9: the paper's lambda* and R_f as if computed, an ODE curve and the
 * paper's values. */
static void test_rf_lambda(void)
{
	static const double lam[] = {0.633, 0.158, 0.025, 0.0063, 0, 1.003, 0.251, 0.040, 0.010, 0};
	static const double rf[] = {0.344, 0.768, 0.965, 0.998, 1.0, 0.177, 0.657, 0.935, 0.986, 0.991};
	static const double hh[] = {1, 2, 5, 10, INFINITY};
	double ox[] = {0.001, 0.5, 1.1}, oy[] = {1, 0.43, 0.16};
	struct plot_curve ode = {0, 3, ox, oy};
	struct plot_paper paper = {1, {{10, 2, 0.768, 0.1582, 0.7618, 9.639, 41}}};
	struct anvil_result r[10];
	struct plot_run runs[10];
	struct plot_chart c;
	struct plot_opts o;
	for (int i = 0; i < 10; i++) {
		int half = i % 5 == 4;
		enum anvil_model m = half ? ANVIL_MODEL_HALFSPACE : ANVIL_MODEL_LAYER;
		anvil_result_init(&r[i], m);
		r[i].Rf.val = rf[i];
		runs[i] = (struct plot_run){&r[i], m, hh[i % 5], i < 5 ? 10 : 100, lam[i]};
	}
	plot_opts_default(&o);
	ok(plot_chart_rf_lambda(&c, runs, 10, &ode, &paper) == ANVIL_OK, "restitution-lambda built");
	ok(c.nseries == 2 + 10 + 1, "fit line, ODE line, ten cases, one paper value");
	ok(strstr(c.setup, "set logscale x") && strstr(c.setup, "set xrange [0.001:"),
	   "lambda* from 0.0063 to 1: a log axis from the decade below");
	ok(c.s[2].colour == plot_h_colour(1) && c.s[2].point == PLOT_PT_DIAMOND &&
	   c.s[7].point == PLOT_PT_CIRCLE && c.s[6].colour == PLOT_BLACK,
	   "markers: colour by h/r0, diamond at 10 m/s, circle at 100, half-space black");
	ok(c.s[6].x[0] == 0.001, "the half-space (lambda* = 0) at the log axis' left end");
	ok(c.s[12].mark == PLOT_OPEN && c.s[12].colour == plot_h_colour(2),
	   "the paper's value open, in its thickness' colour");
	is_script(&c, &o, "restitution-lambda");
	plot_chart_free(&c);
	/* Before the transform models exist: Zener's curves alone still draw. */
	runs[0].r = NULL;
	ok(plot_chart_rf_lambda(&c, runs, 1, NULL, NULL) == ANVIL_OK && c.nseries == 1 &&
	   strstr(c.setup, "logscale") == NULL,
	   "restitution-lambda without computed cases: the fit line only, linear axis");
	plot_chart_free(&c);
}

/* Accuracy: four levels, the second failed, errors relative to the next
 * finer level that ran; the finest uses its own estimate. */
static void test_accuracy(void)
{
	struct anvil_result r[ANVIL_ACC_COUNT];
	struct plot_run runs[ANVIL_ACC_COUNT];
	struct plot_chart c;
	struct plot_opts o;
	static const double P[] = {10500, 0, 10010, 10000}, secs[] = {0.01, 0.05, 0.4, 3.2};
	for (int i = 0; i < ANVIL_ACC_COUNT; i++) {
		anvil_result_init(&r[i], ANVIL_MODEL_LAYER);
		r[i].Pmax.val = P[i];
		r[i].ts.val = 4e-5 * (1 + 1e-3 / (i + 1));
		r[i].Rf.val = 0.34;             /* equal: no error to draw on a log axis */
		r[i].seconds = secs[i];
		runs[i] = (struct plot_run){i == 1 ? NULL : &r[i], ANVIL_MODEL_LAYER, 1, 10, 0.633};
	}
	r[3].Pmax.err = 1.0;
	r[3].ts.err = 4e-10;
	r[3].Rf.err = 3.4e-6;
	plot_opts_default(&o);
	ok(plot_chart_accuracy(&c, runs) == ANVIL_OK, "accuracy chart built");
	int targets = 1;
	for (int i = 0; i < ANVIL_ACC_COUNT; i++)
		targets &= c.s[i].n == 2 && c.s[i].y[0] == anvil_accuracy_target(i) &&
			   c.s[i].colour == i;
	ok(targets, "each level's target as a line in the level's colour");
	is_rel(c.s[4].y[0], 490.0 / 10010.0, 1e-12, "draft P_max error against 'fine'");
	ok(c.s[4].colour == 0 && c.s[4].x[0] == 0.01, "draft's point in its colour, at its time");
	is_rel(c.s[6].y[0], 1e-4, 1e-12, "reference P_max error: its own estimate");
	is_script(&c, &o, "accuracy");
	plot_chart_free(&c);
}

/* The key: below a history, inside a free corner of the restitution
 * charts; image formats by extension. */
static void test_layout(void)
{
	struct plot_chart c;
	struct plot_opts o;
	double x[2] = {0, 1e-5}, y[2] = {0, 1};
	char *text = NULL;
	size_t len = 0;
	plot_opts_default(&o);
	plot_chart_init(&c, PLOT_FORCE);
	plot_chart_add(&c, "", PLOT_LINE, 0, x, y, 2, 1e6, 1e-3, 0);
	plot_chart_key(&c, "a", PLOT_LINE, 0, 0);
	plot_chart_key(&c, "a", PLOT_LINE, 1, 0);
	ok(c.nkeys == 1, "a key entry is added once");
	o.format = PLOT_PDF;
	FILE *m = open_memstream(&text, &len);
	ok(plot_write(m, &c, &o) == ANVIL_OK && fclose(m) == 0 &&
	   strstr(text, "\nset key at screen 0.5,") && strstr(text, "pdfcairo size 8in,6in") &&
	   strstr(text, "keyentry with lines"),
	   "history: the key below, as key entries; PDF in inches");
	free(text);
	c.kind = PLOT_RESTITUTION_LAMBDA;
	o.format = PLOT_SVG;
	m = open_memstream(&text, &len);
	ok(plot_write(m, &c, &o) == ANVIL_OK && fclose(m) == 0 &&
	   strstr(text, "\nset key inside bottom left") && strstr(text, "set terminal svg size 800,600"),
	   "restitution-lambda: the key inside; SVG");
	free(text);
	plot_chart_free(&c);
	ok(plot_format_of("a.PNG") == PLOT_PNG && plot_format_of("x/b.svg") == PLOT_SVG &&
	   plot_format_of("c.pdf") == PLOT_PDF && plot_format_of("d.jpg") == -1 &&
	   plot_format_of(".png") == -1 && plot_format_of(NULL) == -1,
	   "image format by extension");
}

/* The paper's table: read when ../shared is there; errors named. */
static void test_paper(void)
{
	struct plot_paper p;
	struct anvil_err err = {0};
	const char *top = getenv("top_srcdir");
	char path[1024];
	snprintf(path, sizeof path, "%s/../shared/paper/tables.tsv", top ? top : ".");
	FILE *f = fopen(path, "r");
	if (!f) {
		skip_test("the paper's table", "no ../shared/paper/tables.tsv");
	} else {
		fclose(f);
		ok(plot_paper_load(&p, path, &err) == ANVIL_OK && p.n == 10 && p.row[0].V0 == 10 &&
		   p.row[0].h_r0 == 1 && p.row[0].Rf == 0.344 && isinf(p.row[4].h_r0) &&
		   p.row[9].lambda_star == 0.0025, "the paper's ten cases read");
	}
	ok(plot_paper_load(&p, "/nonexistent/tables.tsv", &err) == ANVIL_ENOTFOUND &&
	   strstr(err.msg, "paper values not found"), "missing table: ANVIL_ENOTFOUND, said");
	char tmp[] = "/tmp/anvil-test-paper-XXXXXX";
	int fd = mkstemp(tmp);
	f = fd >= 0 ? fdopen(fd, "w") : NULL;
	if (f) {
		fputs("# c\nV0\th_r0\tRf\tlambda_star\tRf_star\tPmax_kN\tts_us\n"
		      "10\t1\t0.3\t0.6\t0.3\t6\t46\n10\t2\tx\t0.1\t0.7\t9\t41\n", f);
		fclose(f);
	}
	ok(f && plot_paper_load(&p, tmp, &err) == ANVIL_EPARSE && strstr(err.msg, ":4: Rf") &&
	   p.n == 0, "a bad number: ANVIL_EPARSE naming file, line and column");
	if (!strstr(err.msg, ":4: Rf"))
		diag("got: %s", err.msg);
	unlink(tmp);
}

/* The scene named in the subtitle. */
static void test_subtitle(void)
{
	struct anvil_scene sc;
	struct plot_chart c;
	anvil_scene_default(&sc);
	plot_chart_init(&c, PLOT_FORCE);
	plot_chart_subtitle(&c, &sc, 0, 0);
	ok(strstr(c.subtitle, sc.title) && strstr(c.subtitle, "r₀ = 4 mm") &&
	   strstr(c.subtitle, "V₀ = 10 m/s") && strstr(c.subtitle, "h = "),
	   "subtitle: the scene's title, r0, h and V0");
	if (!strstr(c.subtitle, "r₀ = 4 mm"))
		diag("subtitle: %s", c.subtitle);
	plot_chart_subtitle(&c, &sc, 1, 1);
	ok(!strstr(c.subtitle, "V₀") && !strstr(c.subtitle, "h = "),
	   "subtitle: what the chart varies is left out");
}

static void test_writer_errors(void)
{
	struct plot_chart c;
	struct plot_opts o;
	double x[2] = {NAN, 1}, y[2] = {1, INFINITY};
	FILE *null = fopen("/dev/null", "w");
	plot_opts_default(&o);
	plot_chart_init(&c, PLOT_FORCE);
	ok(plot_write(null, &c, &o) == ANVIL_EINVAL, "empty chart: ANVIL_EINVAL");
	ok(plot_chart_add(&c, "nan", PLOT_LINE, 0, x, y, 2, 1, 1, 1) == ANVIL_OK, "series added");
	ok(plot_write(null, &c, &o) == ANVIL_EINVAL, "only undefined points: ANVIL_EINVAL");
	for (int i = 1; i < PLOT_MAX_SERIES; i++)
		plot_chart_add(&c, "s", PLOT_LINE, 0, x, y, 2, 1, 1, 0);
	ok(plot_chart_add(&c, "one too many", PLOT_LINE, 0, x, y, 2, 1, 1, 0) == ANVIL_EINVAL,
	   "a full chart refuses a series");
	ok(plot_chart_add(&c, "bad mark", PLOT_MARK_COUNT, 0, x, y, 2, 1, 1, 0) == ANVIL_EINVAL,
	   "an unknown mark is refused");
	plot_chart_free(&c);
	plot_chart_free(&c);
	ok(c.nseries == 0, "plot_chart_free twice is harmless");
	fclose(null);
}

static void is_quoted(const char *in, const char *want, const char *what)
{
	char buf[256];
	size_t n = plot_quote(buf, sizeof buf, in);
	ok(strcmp(buf, want) == 0 && n == strlen(want), "quote %s", what);
	if (strcmp(buf, want) != 0)
		diag("got %s, want %s", buf, want);
}

/* Undo the quoting the way gnuplot reads it; -1 if it is not one
 * well-formed expression: pieces joined by '.', each "..." of quotes
 * only, or '...' with text that neither starts with '' nor holds two
 * doubled quotes in a row (gnuplot misreads both). */
static int unquote(const char *q, char *out)
{
	for (int first = 1; *q; first = 0) {
		if (!first && *q++ != '.')
			return -1;
		if (*q == '"') {
			size_t k = strspn(q + 1, "'");
			if (k == 0 || q[1 + k] != '"')
				return -1;
			memset(out, '\'', k);
			out += k;
			q += k + 2;
			continue;
		}
		if (*q++ != '\'')
			return -1;
		if (*q == '\'' && q[1] == '\'')
			return -1; /* '' at the start */
		if (*q == '\'') { /* the empty string, alone */
			q++;
			if (!first || *q)
				return -1;
			break;
		}
		for (;; q++) {
			if (!*q || (unsigned char)*q < 0x20 || *q == 0x7f)
				return -1;
			if (*q == '\'' && q[1] == '\'' && q[2] == '\'' && q[3] == '\'')
				return -1;
			if (*q == '\'' && q[1] == '\'')
				q++; /* a doubled quote: one */
			else if (*q == '\'') {
				q++;
				break;
			}
			*out++ = *q;
		}
	}
	*out = '\0';
	return 0;
}

static void test_quote(void)
{
	char buf[8];
	is_quoted("Copper on steel", "'Copper on steel'", "plain text");
	is_quoted("it's", "'it''s'", "a quote is doubled");
	/* gnuplot misreads a leading '' and two doubled quotes in a row (the
	 * old doubling gave '''''' for two quotes): such runs go in "...". */
	is_quoted("''", "\"''\"", "two quotes: a double-quoted piece");
	is_quoted("'x", "\"'\".'x'", "a leading quote");
	is_quoted("a''b", "'a'.\"''\".'b'", "two quotes inside");
	is_quoted("''it's'", "\"''\".'it''s'''", "leading quotes, then text with quotes");
	is_quoted("a\nb\tc\rd\x1b[31m\x7f", "'a b c d [31m '", "control characters become spaces");
	is_quoted("system(\"touch /tmp/pwned\") `touch /tmp/pwned`",
		  "'system(\"touch /tmp/pwned\") `touch /tmp/pwned`'",
		  "system() and backticks stay inert text in single quotes");
	is_quoted("^_@&{}\\ $x", "'^_@&{}\\ $x'", "enhanced-text and macro characters kept as text");
	is_quoted("µs λ*", "'µs λ*'", "UTF-8 kept");
	is_quoted("", "''", "empty string");
	is_quoted(NULL, "''", "NULL");
	ok(plot_quote(buf, sizeof buf, "abcdefghij") == 12 && strcmp(buf, "'abcdef") == 0,
	   "cut short: terminated, full length returned");
	ok(plot_quote(NULL, 0, "it's") == 7, "size 0: only the length");
	/* Random bytes, deterministic: always one well-formed string that
	 * reads back as the input with control characters as spaces. */
	unsigned seed = 12345;
	int good = 1;
	for (int t = 0; t < 2000 && good; t++) {
		char in[40], want[40], q[100], back[100];
		int n = t % 39;
		for (int i = 0; i < n; i++) {
			seed = seed * 1103515245u + 12345u;
			/* one byte in four a quote: runs of them, at the start too */
			in[i] = (seed >> 12) % 4 == 0 ? '\'' : (char)(1 + (seed >> 16) % 255);
			unsigned char u = (unsigned char)in[i];
			want[i] = u < 0x20 || u == 0x7f ? ' ' : in[i];
		}
		in[n] = want[n] = '\0';
		plot_quote(q, sizeof q, in);
		good = unquote(q, back) == 0 && strcmp(back, want) == 0;
	}
	ok(good, "2000 random strings quote to one inert gnuplot string each");
}

static void test_kinds(void)
{
	ok(plot_kind_parse("restitution-lambda") == PLOT_RESTITUTION_LAMBDA, "kind by name");
	ok(plot_kind_parse("FORCE") == PLOT_FORCE, "kind names ignore case");
	ok(plot_kind_parse("forces") == -1 && plot_kind_parse(NULL) == -1, "unknown kind: -1");
	ok(plot_kind_suggest("forse") && strcmp(plot_kind_suggest("forse"), "force") == 0,
	   "did you mean 'force'");
	ok(plot_kind_suggest("restitution") &&
	   strncmp(plot_kind_suggest("restitution"), "restitution-", 12) == 0,
	   "a prefix suggests a kind");
	ok(plot_kind_suggest("xyzzy-plugh") == NULL, "nothing close: no suggestion");
	int named = 1;
	for (int k = 0; k < PLOT_KIND_COUNT; k++)
		named &= plot_kind_parse(plot_kind_name(k)) == k && plot_kind_summary(k) != NULL;
	ok(named && plot_kind_name(PLOT_KIND_COUNT) == NULL, "every kind has a name and summary");
}

/* gnuplot itself reads each quoted string back as the text (when gnuplot
 * is installed): the test of the quoting that matters. */
static void test_quote_gnuplot(void)
{
	static const char *const texts[] = {"'x", "''", "'", "it's", "''it's'", "a''b",
		"x'", "`echo no`", "@GPVAL_VERSION", "\\ \" \\n", "µs λ*", "end'''"};
	const int n = (int)(sizeof texts / sizeof texts[0]);
	char tmp[] = "/tmp/anvil-test-quote-XXXXXX", cmd[256], line[256];
	int fd = mkstemp(tmp), same = 1;
	FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
	if (!f || access("/usr/bin/gnuplot", X_OK) != 0) {
		if (f)
			fclose(f);
		unlink(tmp);
		skip_test("quotes read back by gnuplot", "no /usr/bin/gnuplot");
		return;
	}
	fputs("set print '-'\n", f);
	for (int i = 0; i < n; i++) {
		char q[256];
		plot_quote(q, sizeof q, texts[i]);
		fprintf(f, "print %s\n", q);
	}
	fclose(f);
	snprintf(cmd, sizeof cmd, "/usr/bin/gnuplot %s 2>&1", tmp);
	FILE *p = popen(cmd, "r");
	for (int i = 0; i < n && same; i++) {
		int got = p && fgets(line, sizeof line, p) != NULL;
		if (got)
			line[strcspn(line, "\n")] = '\0';
		same = got && strcmp(line, texts[i]) == 0;
		if (!same)
			diag("text %d: want [%s], gnuplot printed [%s]", i, texts[i], got ? line : "");
	}
	if (p)
		pclose(p);
	unlink(tmp);
	ok(same, "gnuplot reads every quoted text back exactly");
}

/* The TUI's charts: ticks along the edges, dashes as in the PNGs. */
static void test_tui_chart(void)
{
	double t[12];
	int n = tui_ticks(0, 1.05, 0, 3, t);
	ok(n == 3 && t[0] == 0 && t[1] == 0.5 && t[2] == 1, "ticks 0, 0.5, 1 for R_f");
	n = tui_ticks(0, 47, 0, 6, t);
	ok(n == 5 && t[1] == 10 && t[4] == 40, "ticks every 10 us up to 47");
	n = tui_ticks(-10.4, 10.2, 0, 6, t);
	ok(n == 5 && t[0] == -10 && t[2] == 0 && t[4] == 10, "ticks across zero: -10 .. 10 by 5");
	n = tui_ticks(0.5, 20, 1, 10, t);
	ok(n == 6 && t[0] == 0.5 && t[3] == 5 && t[5] == 20, "log ticks 0.5 1 2 5 10 20");
	n = tui_ticks(1e-3, 1.5, 1, 5, t);
	ok(n == 4 && t[0] == 1e-3 && t[3] == 1, "too many on a log axis: the decades");
	n = tui_ticks(4.7e-6, 957, 1, 7, t);
	ok(n == 4 && t[0] == 1e-4 && t[1] == 1e-2 && t[3] == 100,
	   "8 decades on 7 ticks: every other decade over the whole axis (%d: %g .. %g)", n,
	   t[0], t[n - 1]);
	ok(tui_ticks(1, 1, 0, 5, t) == 0 && tui_ticks(0, 1, 1, 5, t) == 0 &&
	   tui_ticks(0, NAN, 0, 5, t) == 0, "empty, non-positive log or undefined range: none");
	struct tui_canvas c;
	double x[2] = {0, 1}, y[2] = {0.5, 0.5};
	int dots[3] = {0};
	unsigned dash[3] = {TUI_DASH_SOLID, TUI_DASH_DASHED, TUI_DASH_DOTTED};
	for (int k = 0; k < 3; k++) {
		if (tui_canvas_init(&c, 8, 1, TUI_CANVAS_BRAILLE))
			break;
		tui_canvas_polyline_dash(&c, 0, x, y, 2, dash[k]);
		for (int i = 0; i < 8; i++)
			dots[k] += __builtin_popcount(c.bits[i]);
		tui_canvas_free(&c);
	}
	ok(dots[0] == 16 && dots[1] == 12 && dots[2] == 4,
	   "16 dots of a line: all solid, 12 dashed (6 of 8), 4 dotted (1 of 4)");
}

int main(void)
{
	plan(100);
	test_force();
	test_force_log();
	test_deflection_log();
	test_rf_thickness();
	test_rf_lambda();
	test_accuracy();
	test_layout();
	test_paper();
	test_subtitle();
	test_writer_errors();
	test_quote();
	test_quote_gnuplot();
	test_kinds();
	test_tui_chart();
	return done_testing();
}
