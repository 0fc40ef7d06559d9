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

#include "tap.h"
#include "plot.h"

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
	r->Rf = 0.5 * scale;
	r->Pmax = 4000 * scale;
	r->ts = 4e-5 * scale;
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
	ok(plot_chart_history(&c, PLOT_FORCE, runs, 7, 1) == ANVIL_OK, "force chart built");
	ok(c.nseries == 5, "five series (failed and history-less runs left out)");
	is_script(&c, &o, "force");
	plot_chart_free(&c);
	/* One scene: colours by model; a hostile title, a font, a size. */
	o.title = "it's \"x\"\nsystem(\"touch /tmp/pwned\") `touch /tmp/pwned` @GPVAL ^_{}\\";
	o.font = "Serif,9'";
	o.width = 640;
	o.height = 400;
	ok(plot_chart_history(&c, PLOT_DEFLECTION, runs + 2, 4, 0) == ANVIL_OK,
	   "deflection chart of one scene built");
	is_script(&c, &o, "deflection-scene");
	plot_chart_free(&c);
	ok(plot_chart_history(&c, PLOT_VELOCITY, runs + 1, 1, 1) == ANVIL_EINVAL,
	   "history of only failed runs: ANVIL_EINVAL");
	ok(plot_chart_history(&c, PLOT_ACCURACY, runs, 1, 1) == ANVIL_EINVAL,
	   "history builder refuses a non-history kind");
	for (int i = 0; i < 6; i++)
		anvil_result_free(&r[i]);
}

/* Fig 8: layer points at three thicknesses and two velocities, the
 * half-space level, and Zener's curves. */
static void test_rf_thickness(void)
{
	struct anvil_result r[5];
	struct plot_chart c;
	struct plot_opts o;
	double zx[] = {0.5, 1, 2, 5, 20}, z10[] = {0.02, 0.34, 0.76, 0.96, 0.997},
	       z100[] = {0.003, 0.18, 0.65, 0.93, 0.995};
	struct plot_curve zc[] = {{10, 5, zx, z10}, {100, 5, zx, z100}};
	for (int i = 0; i < 5; i++)
		anvil_result_init(&r[i], i < 4 ? ANVIL_MODEL_LAYER : ANVIL_MODEL_HALFSPACE);
	r[0].Rf = 0.77, r[1].Rf = 0.344, r[2].Rf = 0.657, r[3].Rf = 0.177, r[4].Rf = 0.991;
	struct plot_run runs[] = {
		{&r[0], ANVIL_MODEL_LAYER, 2, 10, 0.158},
		{&r[1], ANVIL_MODEL_LAYER, 1, 10, 0.633}, /* out of order on purpose */
		{NULL, ANVIL_MODEL_LAYER, 5, 10, 0.025},
		{&r[2], ANVIL_MODEL_LAYER, 2, 100, 0.25},
		{&r[3], ANVIL_MODEL_LAYER, 1, 100, 1.0},
		{&r[4], ANVIL_MODEL_HALFSPACE, INFINITY, 100, 0},
	};
	plot_opts_default(&o);
	ok(plot_chart_rf_thickness(&c, runs, 6, zc, 2) == ANVIL_OK, "restitution-thickness built");
	is_script(&c, &o, "restitution-thickness");
	plot_chart_free(&c);
	ok(plot_chart_rf_thickness(&c, runs + 2, 1, NULL, 0) == ANVIL_EINVAL,
	   "restitution-thickness with nothing computed: ANVIL_EINVAL");
}

/* Fig 9: the paper's lambda* and R_f as if computed, and an ODE curve. */
static void test_rf_lambda(void)
{
	static const double lam[] = {0.633, 0.158, 0.025, 0.0063, 0, 1.003, 0.251, 0.040, 0.010, 0};
	static const double rf[] = {0.344, 0.768, 0.965, 0.998, 1.0, 0.177, 0.657, 0.935, 0.986, 0.991};
	double ox[] = {0, 0.5, 1.1}, oy[] = {1, 0.43, 0.16};
	struct plot_curve ode = {0, 3, ox, oy};
	struct anvil_result r[10];
	struct plot_run runs[10];
	struct plot_chart c;
	struct plot_opts o;
	for (int i = 0; i < 10; i++) {
		int half = i % 5 == 4;
		enum anvil_model m = half ? ANVIL_MODEL_HALFSPACE : ANVIL_MODEL_LAYER;
		anvil_result_init(&r[i], m);
		r[i].Rf = rf[i];
		runs[i] = (struct plot_run){&r[i], m, half ? INFINITY : 1, i < 5 ? 10 : 100, lam[i]};
	}
	plot_opts_default(&o);
	ok(plot_chart_rf_lambda(&c, runs, 10, &ode) == ANVIL_OK, "restitution-lambda built");
	ok(c.nseries == 4, "fit line, ODE line, diamonds, circles");
	is_script(&c, &o, "restitution-lambda");
	plot_chart_free(&c);
	/* Before the transform models exist: Zener's curves alone still draw. */
	runs[0].r = NULL;
	ok(plot_chart_rf_lambda(&c, runs, 1, NULL) == ANVIL_OK && c.nseries == 1,
	   "restitution-lambda without computed cases: the fit line only");
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
		r[i].Pmax = P[i];
		r[i].ts = 4e-5 * (1 + 1e-3 / (i + 1));
		r[i].Rf = 0.34;             /* equal: no error to draw on a log axis */
		r[i].seconds = secs[i];
		runs[i] = (struct plot_run){i == 1 ? NULL : &r[i], ANVIL_MODEL_LAYER, 1, 10, 0.633};
	}
	r[3].Pmax_err = 1.0;
	r[3].ts_err = 4e-10;
	r[3].Rf_err = 3.4e-6;
	plot_opts_default(&o);
	ok(plot_chart_accuracy(&c, runs) == ANVIL_OK, "accuracy chart built");
	is_rel(c.s[0].y[0], 490.0 / 10010.0, 1e-12, "draft P_max error against 'fine'");
	is_rel(c.s[0].y[2], 1e-4, 1e-12, "reference P_max error: its own estimate");
	is_script(&c, &o, "accuracy");
	plot_chart_free(&c);
}

/* The paper's ten curves: the legend moves outside the plot. */
static void test_many_series(void)
{
	struct plot_chart c;
	struct plot_opts o;
	double x[2] = {0, 1e-5}, y[2] = {0, 1};
	char *text = NULL;
	size_t len = 0;
	plot_opts_default(&o);
	plot_chart_init(&c, PLOT_FORCE);
	for (int i = 0; i < 10; i++)
		plot_chart_add(&c, "s", PLOT_LINE, i, x, y, 2, 1e6, 1e-3, 0);
	FILE *m = open_memstream(&text, &len);
	ok(plot_write(m, &c, &o) == ANVIL_OK && fclose(m) == 0 &&
	   strstr(text, "\nset key outside right top") != NULL,
	   "ten series: the legend goes outside");
	free(text);
	plot_chart_free(&c);
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
 * well-formed single-quoted string. */
static int unquote(const char *q, char *out)
{
	size_t n = strlen(q);
	if (n < 2 || q[0] != '\'' || q[n - 1] != '\'')
		return -1;
	for (size_t i = 1; i < n - 1; i++) {
		if ((unsigned char)q[i] < 0x20 || q[i] == 0x7f)
			return -1;
		if (q[i] == '\'' && q[++i] != '\'')
			return -1; /* a lone quote would end the string early */
		*out++ = q[i];
	}
	*out = '\0';
	return 0;
}

static void test_quote(void)
{
	char buf[8];
	is_quoted("Copper on steel", "'Copper on steel'", "plain text");
	is_quoted("it's", "'it''s'", "a quote is doubled");
	is_quoted("''", "''''''", "two quotes");
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
			in[i] = (char)(1 + (seed >> 16) % 255);
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

int main(void)
{
	plan(44);
	test_force();
	test_rf_thickness();
	test_rf_lambda();
	test_accuracy();
	test_many_series();
	test_writer_errors();
	test_quote();
	test_kinds();
	return done_testing();
}
