/* plot.c: gnuplot scripts with the data inline, and the pipe to gnuplot.
 * See plot.h for the contract. */
#ifdef HAVE_CONFIG_H
#include "config.h"
#endif

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "zener.h"
#include "common.h"
#include "plot.h"

#ifndef ANVIL_GNUPLOT
#define ANVIL_GNUPLOT "gnuplot"
#endif

/* ---------------------------------------------------------------- kinds */

/* Room above the curves of a history for the legend. */
#define HEADROOM "set offsets 0, 0, graph 0.2, 0\n"

/* Everything that differs between kinds, in one table.  Axis labels are
 * anvil's own text and use gnuplot's enhanced mode (r_0: subscript). */
static const struct kind_info {
	const char *name, *summary;
	const char *xlabel, *ylabel;
	const char *setup; /* gnuplot commands: ranges, scales */
	const char *key;   /* where the legend goes */
	const char *title; /* default title; %g is V0 where it applies */
	const char *what;  /* after a scene's title, which says the rest */
} kinds[PLOT_KIND_COUNT] = {
	[PLOT_FORCE] = {"force", "contact force P(t) for several thicknesses (Figs 2-3)",
		"t (µs)", "P (kN)", "set xrange [0:*]\nset yrange [0:*]\n" HEADROOM,
		"top right", "Contact force, V0 = %g m/s", "contact force"},
	[PLOT_VELOCITY] = {"velocity", "impactor velocity v(t) (Figs 4-5)",
		"t (µs)", "v (m/s)", "set xrange [0:*]\nset xzeroaxis\n" HEADROOM,
		"top right", "Impactor velocity, V0 = %g m/s", "impactor velocity"},
	[PLOT_DEFLECTION] = {"deflection", "layer deflection w(t) under the impactor (Figs 6-7)",
		"t (µs)", "w (µm)", "set xrange [0:*]\n" HEADROOM,
		"top left", "Layer deflection under the impactor, V0 = %g m/s",
		"deflection under the impactor"},
	[PLOT_RESTITUTION_THICKNESS] = {"restitution-thickness",
		"restitution R_f against h/r0, V0 = 10 and 100 m/s (Fig 8)",
		"h / r_0", "R_f",
		"set logscale x\nset xrange [0.5:20]\nset xtics (0.5, 1, 2, 5, 10, 20)\n"
		"set yrange [0:1.05]\n",
		"bottom right", "Coefficient of restitution against layer thickness",
		"restitution against thickness"},
	[PLOT_RESTITUTION_LAMBDA] = {"restitution-lambda",
		"restitution R_f against Zener's lambda* (Fig 9)",
		"λ^*", "R_f", "set xrange [0:*]\nset yrange [0:1.05]\n",
		"top right", "Coefficient of restitution against Zener's λ*",
		"restitution against λ*"},
	[PLOT_ACCURACY] = {"accuracy",
		"error of P_max, t_s, R_f against wall time per accuracy level",
		"wall time (s)", "relative error",
		"set logscale xy\nset format y '10^{%L}'\n",
		"top right", "Error of each output against wall time",
		"error against wall time"},
};

const char *plot_kind_name(enum plot_kind k)
{
	return (unsigned)k < PLOT_KIND_COUNT ? kinds[k].name : NULL;
}

const char *plot_kind_summary(enum plot_kind k)
{
	return (unsigned)k < PLOT_KIND_COUNT ? kinds[k].summary : NULL;
}

int plot_kind_parse(const char *name)
{
	for (int k = 0; name && k < PLOT_KIND_COUNT; k++)
		if (strcasecmp(name, kinds[k].name) == 0)
			return k;
	return -1;
}

/* Levenshtein distance of two short strings (longer ones count as far). */
static size_t edit_distance(const char *a, const char *b)
{
	size_t la = strlen(a), lb = strlen(b), row[64];
	if (la >= 64 || lb >= 64)
		return SIZE_MAX;
	for (size_t j = 0; j <= lb; j++)
		row[j] = j;
	for (size_t i = 1; i <= la; i++) {
		size_t diag = row[0];
		row[0] = i;
		for (size_t j = 1; j <= lb; j++) {
			size_t up = row[j];
			size_t sub = diag + (a[i - 1] != b[j - 1]);
			size_t del = (up < row[j - 1] ? up : row[j - 1]) + 1;
			row[j] = sub < del ? sub : del;
			diag = up;
		}
	}
	return row[lb];
}

const char *plot_kind_suggest(const char *name)
{
	const char *best = NULL;
	size_t bestd = SIZE_MAX, n = name ? strlen(name) : 0;
	if (n == 0)
		return NULL;
	/* A prefix ("restitution", "acc") is the likeliest intent. */
	for (int k = 0; k < PLOT_KIND_COUNT; k++)
		if (strncasecmp(name, kinds[k].name, n) == 0)
			return kinds[k].name;
	for (int k = 0; k < PLOT_KIND_COUNT; k++) {
		size_t d = edit_distance(name, kinds[k].name);
		if (d < bestd) {
			bestd = d;
			best = kinds[k].name;
		}
	}
	return bestd <= 3 && bestd < n ? best : NULL;
}

/* -------------------------------------------------------------- quoting */

size_t plot_quote(char *dst, size_t size, const char *src)
{
	size_t n = 0;
#define PUT(ch) do { if (n + 1 < size) dst[n] = (ch); n++; } while (0)
	PUT('\'');
	for (const unsigned char *p = (const unsigned char *)src; p && *p; p++) {
		if (*p == '\'')
			PUT('\'');
		/* A control character would end or corrupt the script line. */
		PUT(*p < 0x20 || *p == 0x7f ? ' ' : (char)*p);
	}
	PUT('\'');
#undef PUT
	if (size > 0)
		dst[n < size ? n : size - 1] = '\0';
	return n;
}

/* Write s quoted to f. */
static void put_quoted(FILE *f, const char *s)
{
	char small[256];
	size_t n = plot_quote(small, sizeof small, s);
	if (n < sizeof small) {
		fputs(small, f);
		return;
	}
	char *big = malloc(n + 1);
	if (!big) {
		/* Still valid gnuplot; the write error shows on the caller's ferror. */
		fputs("''", f);
		return;
	}
	plot_quote(big, n + 1, s);
	fputs(big, f);
	free(big);
}

/* ---------------------------------------------------------------- chart */

void plot_chart_init(struct plot_chart *c, enum plot_kind kind)
{
	memset(c, 0, sizeof *c);
	c->kind = kind;
}

void plot_chart_free(struct plot_chart *c)
{
	for (int i = 0; i < c->nseries; i++) {
		free(c->s[i].own);
		c->s[i].own = NULL;
	}
	c->nseries = 0;
}

int plot_chart_add(struct plot_chart *c, const char *label,
		   enum plot_mark mark, int colour, const double *x,
		   const double *y, size_t n, double xs, double ys, int copy)
{
	if (c->nseries >= PLOT_MAX_SERIES || (unsigned)mark >= PLOT_MARK_COUNT)
		return ANVIL_EINVAL;
	struct plot_series *s = &c->s[c->nseries];
	memset(s, 0, sizeof *s);
	if (copy && n > 0) {
		if (!(s->own = malloc(2 * n * sizeof *s->own)))
			return ANVIL_ENOMEM;
		memcpy(s->own, x, n * sizeof *x);
		memcpy(s->own + n, y, n * sizeof *y);
		x = s->own;
		y = s->own + n;
	}
	snprintf(s->label, sizeof s->label, "%s", label);
	s->mark = mark;
	s->colour = colour;
	s->n = n;
	s->x = x;
	s->y = y;
	s->xs = xs;
	s->ys = ys;
	c->nseries++;
	return ANVIL_OK;
}

void plot_chart_scene_title(struct plot_chart *c, const char *scene_title)
{
	if (scene_title && scene_title[0])
		snprintf(c->title, sizeof c->title, "%.*s: %s", ANVIL_TITLE_MAX,
			 scene_title, kinds[c->kind].what);
}

static const char *const model_label[ANVIL_MODEL_COUNT] = {
	[ANVIL_MODEL_HERTZ] = "quasi-static Hertz",
	[ANVIL_MODEL_ZENER] = "Zener",
	[ANVIL_MODEL_LAYER] = "layer",
	[ANVIL_MODEL_HALFSPACE] = "half-space",
};

/* Colours of the models when one scene is drawn (by_thickness = 0). */
static const int model_colour[ANVIL_MODEL_COUNT] = {
	[ANVIL_MODEL_HERTZ] = PLOT_GREY,
	[ANVIL_MODEL_ZENER] = 2,
	[ANVIL_MODEL_LAYER] = 0,
	[ANVIL_MODEL_HALFSPACE] = 1,
};

/* Index of key in seen[0..*n), appended when new: one colour per value. */
static int index_of(double *seen, int *n, int max, double key)
{
	for (int i = 0; i < *n; i++)
		if (seen[i] == key)
			return i;
	if (*n < max)
		seen[(*n)++] = key;
	return *n - 1;
}

static int ok_run(const struct plot_run *run)
{
	return run->r != NULL && (unsigned)run->model < ANVIL_MODEL_COUNT;
}

static int chart_done(struct plot_chart *c, int st)
{
	if (!st && c->nseries == 0)
		st = ANVIL_EINVAL;
	return st;
}

/* ------------------------------------------------------------- builders */

static const double *history_y(const struct anvil_history *h,
			       enum plot_kind kind, double *ys)
{
	switch (kind) {
	case PLOT_FORCE:
		*ys = 1e-3; /* N -> kN */
		return h->P;
	case PLOT_VELOCITY:
		*ys = 1.0;
		return h->v;
	default:
		*ys = 1e6; /* m -> um */
		return h->w;
	}
}

static void history_style(const struct plot_run *run, enum plot_kind kind,
			  int by_thickness, double *hs, int *nh, char *label,
			  size_t len, enum plot_mark *mark, int *colour)
{
	const char *name = model_label[run->model];
	*mark = run->model == ANVIL_MODEL_ZENER ? PLOT_DASH
		: run->model == ANVIL_MODEL_HERTZ ? PLOT_THIN : PLOT_LINE;
	*colour = model_colour[run->model];
	/* Hertz's layer is rigid: say why its deflection is a flat zero. */
	snprintf(label, len, "%s%s", name, run->model == ANVIL_MODEL_HERTZ &&
		 kind == PLOT_DEFLECTION ? ", w = 0" : "");
	if (!by_thickness || run->model == ANVIL_MODEL_HERTZ)
		return;
	/* Hertz's rigid layer has no thickness; everyone else is coloured
	 * by it, so a layer and its Zener plate share a colour. */
	*colour = index_of(hs, nh, PLOT_MAX_SERIES, run->h_r0);
	if (isfinite(run->h_r0))
		snprintf(label, len, "%s, h = %g r_0", name, run->h_r0);
}

int plot_chart_history(struct plot_chart *c, enum plot_kind kind,
		       const struct plot_run *runs, int n, int by_thickness)
{
	double hs[PLOT_MAX_SERIES];
	int nh = 0, st = ANVIL_OK;
	plot_chart_init(c, kind);
	if (kind != PLOT_FORCE && kind != PLOT_VELOCITY && kind != PLOT_DEFLECTION)
		return ANVIL_EINVAL;
	snprintf(c->title, sizeof c->title, kinds[kind].title, n > 0 ? runs[0].V0 : 0.0);
	/* One scene: its thickness belongs in the title, not in each label. */
	if (!by_thickness && n > 0 && isfinite(runs[0].h_r0))
		snprintf(c->title + strlen(c->title), sizeof c->title - strlen(c->title),
			 ", h = %g r0", runs[0].h_r0);
	for (int i = 0; i < n && !st; i++) {
		const struct plot_run *run = &runs[i];
		char label[PLOT_LABEL_MAX];
		enum plot_mark mark;
		int colour;
		double ys;
		if (!ok_run(run) || run->r->hist.n == 0)
			continue;
		history_style(run, kind, by_thickness, hs, &nh, label, sizeof label,
			      &mark, &colour);
		const double *y = history_y(&run->r->hist, kind, &ys);
		st = plot_chart_add(c, label, mark, colour, run->r->hist.t, y,
				    run->r->hist.n, 1e6, ys, 0);
	}
	return chart_done(c, st);
}

/* Layer runs of velocity V0 as points sorted by h/r0. */
static int rf_layer_points(struct plot_chart *c, const struct plot_run *runs,
			   int n, double V0, int colour)
{
	double x[PLOT_MAX_SERIES * 4], y[PLOT_MAX_SERIES * 4];
	size_t m = 0;
	for (int i = 0; i < n; i++) {
		const struct plot_run *run = &runs[i];
		if (!ok_run(run) || run->model != ANVIL_MODEL_LAYER || run->V0 != V0 ||
		    !isfinite(run->h_r0) || m == sizeof x / sizeof x[0])
			continue;
		size_t j = m++;
		for (; j > 0 && x[j - 1] > run->h_r0; j--) {
			x[j] = x[j - 1];
			y[j] = y[j - 1];
		}
		x[j] = run->h_r0;
		y[j] = run->r->Rf;
	}
	if (m == 0)
		return ANVIL_OK;
	char label[PLOT_LABEL_MAX];
	snprintf(label, sizeof label, "layer, V_0 = %g m/s", V0);
	return plot_chart_add(c, label, PLOT_LINESPOINTS, colour, x, y, m, 1, 1, 1);
}

/* The half-space's R_f at velocity V0 as a level across the h axis. */
static int rf_halfspace_level(struct plot_chart *c, const struct plot_run *runs,
			      int n, double V0, int colour)
{
	for (int i = 0; i < n; i++) {
		const struct plot_run *run = &runs[i];
		if (!ok_run(run) || run->model != ANVIL_MODEL_HALFSPACE || run->V0 != V0)
			continue;
		/* The ends of the h axis of kinds[PLOT_RESTITUTION_THICKNESS]. */
		double x[2] = {0.5, 20}, y[2] = {run->r->Rf, run->r->Rf};
		char label[PLOT_LABEL_MAX];
		snprintf(label, sizeof label, "half-space, V_0 = %g m/s", V0);
		return plot_chart_add(c, label, PLOT_DOT, colour, x, y, 2, 1, 1, 1);
	}
	return ANVIL_OK;
}

int plot_chart_rf_thickness(struct plot_chart *c, const struct plot_run *runs,
			    int n, const struct plot_curve *zener, int nzener)
{
	double vs[PLOT_MAX_SERIES];
	int nv = 0, st = ANVIL_OK;
	plot_chart_init(c, PLOT_RESTITUTION_THICKNESS);
	snprintf(c->title, sizeof c->title, "%s", kinds[c->kind].title);
	for (int i = 0; i < n; i++)
		index_of(vs, &nv, PLOT_MAX_SERIES, runs[i].V0);
	for (int i = 0; i < nzener; i++)
		index_of(vs, &nv, PLOT_MAX_SERIES, zener[i].V0);
	for (int g = 0; g < nv && !st; g++) {
		st = rf_layer_points(c, runs, n, vs[g], g);
		if (!st)
			st = rf_halfspace_level(c, runs, n, vs[g], g);
		for (int i = 0; i < nzener && !st; i++) {
			char label[PLOT_LABEL_MAX];
			if (zener[i].V0 != vs[g] || zener[i].n == 0)
				continue;
			snprintf(label, sizeof label, "Zener R_f^*, V_0 = %g m/s", vs[g]);
			st = plot_chart_add(c, label, PLOT_DASH, g, zener[i].x,
					    zener[i].y, zener[i].n, 1, 1, 1);
		}
	}
	return chart_done(c, st);
}

/* Zener's fit (54) sampled over [0, xmax]. */
#define RF_FIT_POINTS 56
static int rf_fit_line(struct plot_chart *c, double xmax)
{
	double x[RF_FIT_POINTS], y[RF_FIT_POINTS];
	for (int i = 0; i < RF_FIT_POINTS; i++) {
		x[i] = xmax * i / (RF_FIT_POINTS - 1);
		y[i] = anvil_zener_rf_fit(x[i]);
	}
	/* Colour 6 of the palette is black: the paper's solid line. */
	return plot_chart_add(c, "Zener's fit R_f^* = exp(-1.7191 λ^*), eq. (54)",
			      PLOT_LINE, 6, x, y, RF_FIT_POINTS, 1, 1, 1);
}

/* The computed runs of velocity V0 as points at (lambda*, R_f). */
static int rf_lambda_points(struct plot_chart *c, const struct plot_run *runs,
			    int n, double V0, int g)
{
	double x[PLOT_MAX_SERIES * 4], y[PLOT_MAX_SERIES * 4];
	size_t m = 0;
	unsigned models = 0;
	for (int i = 0; i < n && m < sizeof x / sizeof x[0]; i++) {
		const struct plot_run *run = &runs[i];
		if (!ok_run(run) || run->V0 != V0 ||
		    (run->model != ANVIL_MODEL_LAYER && run->model != ANVIL_MODEL_HALFSPACE))
			continue;
		models |= 1u << run->model;
		x[m] = run->lambda_star;
		y[m++] = run->r->Rf;
	}
	if (m == 0)
		return ANVIL_OK;
	char label[PLOT_LABEL_MAX];
	/* The half-space sits at lambda* = 0: say it is among the points. */
	snprintf(label, sizeof label, "%s, V_0 = %g m/s",
		 models == 1u << ANVIL_MODEL_LAYER ? "layer"
		 : models == 1u << ANVIL_MODEL_HALFSPACE ? "half-space"
		 : "layer and half-space", V0);
	return plot_chart_add(c, label, g == 0 ? PLOT_DIAMONDS : PLOT_CIRCLES, g,
			      x, y, m, 1, 1, 1);
}

/* The lambda* axis reaches past the paper's largest case (1.0032) and
 * past every point and curve given. */
static double rf_lambda_xmax(const struct plot_run *runs, int n,
			     const struct plot_curve *ode)
{
	double xmax = 1.1;
	for (int i = 0; i < n; i++)
		if (ok_run(&runs[i]) && 1.05 * runs[i].lambda_star > xmax)
			xmax = 1.05 * runs[i].lambda_star;
	for (size_t i = 0; ode && i < ode->n; i++)
		if (ode->x[i] > xmax)
			xmax = ode->x[i];
	return xmax;
}

int plot_chart_rf_lambda(struct plot_chart *c, const struct plot_run *runs,
			 int n, const struct plot_curve *ode)
{
	double vs[PLOT_MAX_SERIES];
	int nv = 0, st;
	plot_chart_init(c, PLOT_RESTITUTION_LAMBDA);
	snprintf(c->title, sizeof c->title, "%s", kinds[c->kind].title);
	st = rf_fit_line(c, rf_lambda_xmax(runs, n, ode));
	if (!st && ode && ode->n > 0)
		st = plot_chart_add(c, "Zener's ODE (49)", PLOT_THIN, PLOT_GREY,
				    ode->x, ode->y, ode->n, 1, 1, 1);
	for (int i = 0; i < n; i++)
		if (ok_run(&runs[i]))
			index_of(vs, &nv, PLOT_MAX_SERIES, runs[i].V0);
	for (int g = 0; g < nv && !st; g++)
		st = rf_lambda_points(c, runs, n, vs[g], g);
	return chart_done(c, st);
}

static void add_note(struct plot_chart *c, double x, double y, const char *text)
{
	if (c->nnotes < PLOT_MAX_NOTES) {
		struct plot_note *n = &c->notes[c->nnotes++];
		n->x = x;
		n->y = y;
		snprintf(n->text, sizeof n->text, "%s", text);
	}
}

/* Output o (0 P_max, 1 t_s, 2 R_f) of a result and its error estimate. */
static double acc_value(const struct anvil_result *r, int o, double *err)
{
	switch (o) {
	case 0:
		*err = r->Pmax_err;
		return r->Pmax;
	case 1:
		*err = r->ts_err;
		return r->ts;
	default:
		*err = r->Rf_err;
		return r->Rf;
	}
}

/* Relative error of output o at level i: against the next finer level
 * that succeeded, else the level's own estimate. */
static double acc_error(const struct plot_run *runs, int i, int o)
{
	double e, x = acc_value(runs[i].r, o, &e);
	for (int j = i + 1; j < ANVIL_ACC_COUNT; j++)
		if (ok_run(&runs[j])) {
			double f = acc_value(runs[j].r, o, &e);
			return fabs(x - f) / fabs(f);
		}
	return fabs(e) / fabs(x);
}

int plot_chart_accuracy(struct plot_chart *c,
			const struct plot_run runs[ANVIL_ACC_COUNT])
{
	static const char *const outputs[] = {"P_{max}", "t_s", "R_f"};
	int st = ANVIL_OK;
	plot_chart_init(c, PLOT_ACCURACY);
	snprintf(c->title, sizeof c->title, "%s", kinds[c->kind].title);
	for (int o = 0; o < 3 && !st; o++) {
		double x[ANVIL_ACC_COUNT], y[ANVIL_ACC_COUNT];
		int level[ANVIL_ACC_COUNT];
		size_t m = 0;
		for (int i = 0; i < ANVIL_ACC_COUNT; i++) {
			if (!ok_run(&runs[i]))
				continue;
			/* A log axis has no place for a zero or undefined error. */
			double e = acc_error(runs, i, o), t = runs[i].r->seconds;
			if (isfinite(e) && e > 0 && isfinite(t) && t > 0) {
				level[m] = i;
				x[m] = t;
				y[m++] = e;
			}
		}
		if (m > 0)
			st = plot_chart_add(c, outputs[o], PLOT_LINESPOINTS, o, x, y, m, 1, 1, 1);
		for (size_t i = 0; o == 0 && i < m; i++)
			add_note(c, x[i], y[i], anvil_accuracy_name(level[i]));
	}
	return chart_done(c, st);
}

/* --------------------------------------------------------------- writer */

/* Okabe-Ito colours: distinguishable with the common colour blindnesses. */
static const char *const palette[] = {
	"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000",
};
#define PALETTE_N ((int)(sizeof palette / sizeof palette[0]))
#define GREY "#808080"
#define KEY_INSIDE_MAX 6

static const char *const mark_style[PLOT_MARK_COUNT] = {
	[PLOT_LINE] = "lines lw 2",
	[PLOT_DASH] = "lines lw 1.5 dt 2",
	[PLOT_THIN] = "lines lw 1",
	[PLOT_DOT] = "lines lw 1.5 dt 3",
	[PLOT_DIAMONDS] = "points pt 13 ps 1.8",
	[PLOT_CIRCLES] = "points pt 7 ps 1.5",
	[PLOT_LINESPOINTS] = "linespoints lw 1.5 pt 7 ps 1",
};

void plot_opts_default(struct plot_opts *o)
{
	o->width = 800;
	o->height = 600;
	o->font = NULL;
	o->title = NULL;
}

static int finite_point(const struct plot_series *s, size_t i)
{
	return isfinite(s->x[i] * s->xs) && isfinite(s->y[i] * s->ys);
}

static int series_drawn(const struct plot_series *s)
{
	for (size_t i = 0; i < s->n; i++)
		if (finite_point(s, i))
			return 1;
	return 0;
}

static void write_terminal(FILE *f, const char *term, const struct plot_opts *o)
{
	fprintf(f, "\tset terminal %s size %d,%d enhanced", term, o->width, o->height);
	if (o->font && o->font[0]) {
		fputs(" font ", f);
		put_quoted(f, o->font);
	}
	fputc('\n', f);
}

static void write_header(FILE *f, const struct plot_chart *c,
			 const struct plot_opts *o)
{
	const struct kind_info *k = &kinds[c->kind];
	fprintf(f, "# anvil chart '%s': a gnuplot script with its data inline.\n"
		"# Render with: gnuplot THIS_FILE > %s.png\n", k->name, k->name);
	fputs("set encoding utf8\n", f);
	/* pngcairo draws antialiased lines; libgd's png is the fallback. */
	fputs("if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n", f);
	write_terminal(f, "pngcairo", o);
	fputs("} else {\n", f);
	write_terminal(f, "png", o);
	fputs("}\n", f);
	/* No `set output`: the PNG goes to standard output, so no file name
	 * ever passes through gnuplot. */
	fputs("set title ", f);
	put_quoted(f, o->title && o->title[0] ? o->title : c->title);
	/* User text is drawn as is: enhanced mode would interpret ^_@&{}\. */
	fputs(" noenhanced\n", f);
	fputs("set xlabel ", f);
	put_quoted(f, k->xlabel);
	fputs("\nset ylabel ", f);
	put_quoted(f, k->ylabel);
	/* Many curves (the paper's ten): a legend inside would hide some.
	 * Outside, left-aligned; cairo's text is narrower than gnuplot's
	 * estimate, hence the negative width. */
	fprintf(f, "\nset grid\nset key %s box opaque\n%s",
		c->nseries > KEY_INSIDE_MAX ? "outside right top Left reverse width -3"
		: k->key, k->setup);
}

static void write_block(FILE *f, int id, const struct plot_series *s)
{
	fprintf(f, "$d%d << EOD\n", id);
	for (size_t i = 0; i < s->n; i++)
		if (finite_point(s, i))
			fprintf(f, "%.6g %.6g\n", s->x[i] * s->xs, s->y[i] * s->ys);
	fputs("EOD\n", f);
}

static void write_notes(FILE *f, const struct plot_chart *c)
{
	for (int i = 0; i < c->nnotes; i++) {
		const struct plot_note *n = &c->notes[i];
		if (!isfinite(n->x) || !isfinite(n->y))
			continue;
		fprintf(f, "set label %d ", i + 1);
		put_quoted(f, n->text);
		fprintf(f, " at %.6g,%.6g offset char 0.6,0.8 noenhanced\n", n->x, n->y);
	}
}

static void write_plot(FILE *f, const struct plot_chart *c)
{
	const char *sep = "plot ";
	for (int i = 0; i < c->nseries; i++) {
		const struct plot_series *s = &c->s[i];
		if (!series_drawn(s))
			continue;
		fprintf(f, "%s$d%d using 1:2 with %s lc rgb '%s' title ", sep, i + 1,
			mark_style[s->mark],
			s->colour < 0 ? GREY : palette[s->colour % PALETTE_N]);
		put_quoted(f, s->label);
		sep = ", \\\n     ";
	}
	fputc('\n', f);
}

int plot_write(FILE *f, const struct plot_chart *c, const struct plot_opts *o)
{
	int any = 0;
	for (int i = 0; i < c->nseries; i++)
		any |= series_drawn(&c->s[i]);
	if (!any || (unsigned)c->kind >= PLOT_KIND_COUNT)
		return ANVIL_EINVAL;
	write_header(f, c, o);
	write_notes(f, c);
	for (int i = 0; i < c->nseries; i++)
		if (series_drawn(&c->s[i]))
			write_block(f, i + 1, &c->s[i]);
	write_plot(f, c);
	return fflush(f) == 0 && !ferror(f) ? ANVIL_OK : ANVIL_EIO;
}

/* ---------------------------------------------------------- the gnuplot */

const char *plot_gnuplot_path(void)
{
	const char *p = getenv("ANVIL_GNUPLOT");
	return p && p[0] ? p : ANVIL_GNUPLOT;
}

static void gnuplot_missing(const char *prog, int e)
{
	cli_error("cannot run gnuplot '%s': %s (install gnuplot, or set ANVIL_GNUPLOT to its path)",
		  prog, strerror(e));
}

/* Is prog executable, directly or through PATH (as execvp finds it)? */
static int find_program(const char *prog)
{
	if (strchr(prog, '/'))
		return access(prog, X_OK) == 0 ? 0 : errno;
	const char *path = getenv("PATH");
	char buf[PATH_MAX];
	for (const char *p = path ? path : "/usr/bin:/bin"; ; p++) {
		size_t n = strcspn(p, ":");
		int len = snprintf(buf, sizeof buf, "%.*s%s%s", (int)n, p,
				   n ? "/" : "", prog);
		if (len > 0 && (size_t)len < sizeof buf && access(buf, X_OK) == 0)
			return 0;
		p += n;
		if (!*p)
			return ENOENT;
	}
}

int plot_gnuplot_check(void)
{
	const char *prog = plot_gnuplot_path();
	int e = find_program(prog);
	if (e)
		gnuplot_missing(prog, e);
	return e ? 1 : 0;
}

/* A running gnuplot: its script pipe, its stderr, and what it said. */
struct gp_proc {
	pid_t pid;
	int in, err;
	int status;     /* from waitpid */
	int exec_errno; /* gnuplot could not be started (or talked to) */
	char msg[4096];
	size_t nmsg;
};

static void close_fd(int *fd)
{
	if (*fd >= 0)
		close(*fd);
	*fd = -1;
}

static void cloexec(int fd)
{
	fcntl(fd, F_SETFD, fcntl(fd, F_GETFD) | FD_CLOEXEC);
}

/* The child: script on stdin, PNG to out_fd, stderr to the parent; an
 * exec failure is reported as errno through the close-on-exec pipe ex. */
static void gp_child(const char *prog, int in, int out_fd, int err, int ex)
{
	char *argv[] = {(char *)prog, (char *)"--default-settings", NULL};
	if (dup2(in, 0) >= 0 && dup2(out_fd, 1) >= 0 && dup2(err, 2) >= 0)
		execvp(prog, argv);
	int e = errno;
	if (write(ex, &e, sizeof e) < 0)
		_exit(126);
	_exit(127);
}

/* Start gnuplot.  Returns 0, or an errno value (exec failure included). */
static int gp_spawn(struct gp_proc *g, const char *prog, int out_fd)
{
	int in[2], er[2], ex[2], e = 0;
	g->pid = -1;
	g->in = g->err = -1;
	g->nmsg = 0;
	g->msg[0] = '\0';
	if (pipe(in) < 0)
		return errno;
	if (pipe(er) < 0 || pipe(ex) < 0) {
		e = errno;
		close(in[0]);
		close(in[1]);
		return e;
	}
	int fds[] = {in[0], in[1], er[0], er[1], ex[0], ex[1], out_fd};
	for (size_t i = 0; i < sizeof fds / sizeof fds[0]; i++)
		cloexec(fds[i]);
	g->pid = fork();
	if (g->pid == 0)
		gp_child(prog, in[0], out_fd, er[1], ex[1]);
	if (g->pid < 0)
		e = errno;
	close(in[0]);
	close(er[1]);
	close(ex[1]);
	/* EOF: exec succeeded; an int: exec failed with that errno. */
	if (g->pid > 0 && read(ex[0], &e, sizeof e) != (ssize_t)sizeof e)
		e = 0;
	close(ex[0]);
	g->in = in[1];
	g->err = er[0];
	if (e) {
		close_fd(&g->in);
		close_fd(&g->err);
		if (g->pid > 0)
			waitpid(g->pid, NULL, 0);
		g->pid = -1;
	}
	return e;
}

/* Keep the first part of gnuplot's stderr; drain the rest. */
static void gp_read_err(struct gp_proc *g)
{
	char buf[1024];
	ssize_t k = read(g->err, buf, sizeof buf);
	if (k <= 0) {
		if (k == 0 || errno != EINTR)
			close_fd(&g->err);
		return;
	}
	size_t room = sizeof g->msg - 1 - g->nmsg;
	size_t take = (size_t)k < room ? (size_t)k : room;
	memcpy(g->msg + g->nmsg, buf, take);
	g->nmsg += take;
	g->msg[g->nmsg] = '\0';
}

/* Write the script while reading stderr, so that neither pipe can fill
 * and block the other side. */
static int gp_talk(struct gp_proc *g, const char *script, size_t len)
{
	size_t off = 0;
	if (len == 0)
		close_fd(&g->in);
	while (g->in >= 0 || g->err >= 0) {
		struct pollfd p[2] = {{.fd = g->in, .events = POLLOUT},
				      {.fd = g->err, .events = POLLIN}};
		if (poll(p, 2, -1) < 0) {
			if (errno == EINTR)
				continue;
			return errno;
		}
		if (p[1].revents)
			gp_read_err(g);
		if (!p[0].revents)
			continue;
		/* At most PIPE_BUF bytes: a write POLLOUT allows never blocks. */
		size_t chunk = len - off < PIPE_BUF ? len - off : PIPE_BUF;
		ssize_t k = p[0].revents & POLLOUT ? write(g->in, script + off, chunk) : -1;
		if (k > 0)
			off += (size_t)k;
		/* gnuplot gone (EPIPE, POLLERR): its status tells why. */
		if (off == len || (k < 0 && errno != EINTR && errno != EAGAIN))
			close_fd(&g->in);
	}
	return 0;
}

/* Print gnuplot's own words, after anvil's one line. */
static void gp_show_msg(const struct gp_proc *g)
{
	const char *m = g->msg;
	while (*m == '\n')
		m++;
	if (*m)
		fprintf(stderr, "%s%s", m, m[strlen(m) - 1] == '\n' ? "" : "\n");
}

static int png_signature_ok(int fd)
{
	static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
	unsigned char buf[8];
	return pread(fd, buf, sizeof buf, 0) == (ssize_t)sizeof buf &&
	       memcmp(buf, sig, sizeof sig) == 0;
}

/* Run gnuplot to completion: 0 when it exited 0 having written a PNG.
 * Prints nothing: the caller removes its half file first. */
static int gp_run(struct gp_proc *g, const char *script, size_t len, int out_fd)
{
	struct sigaction ign = {.sa_handler = SIG_IGN}, old;
	/* A gnuplot that dies early must not take anvil down with SIGPIPE. */
	sigemptyset(&ign.sa_mask);
	sigaction(SIGPIPE, &ign, &old);
	g->status = 0;
	g->exec_errno = gp_spawn(g, plot_gnuplot_path(), out_fd);
	if (!g->exec_errno) {
		g->exec_errno = gp_talk(g, script, len);
		close_fd(&g->in);
		close_fd(&g->err);
		while (waitpid(g->pid, &g->status, 0) < 0 && errno == EINTR)
			;
	}
	sigaction(SIGPIPE, &old, NULL);
	return g->exec_errno || !WIFEXITED(g->status) || WEXITSTATUS(g->status) != 0 ||
	       !png_signature_ok(out_fd);
}

/* One line naming gnuplot, then gnuplot's own words. */
static void gp_report(const struct gp_proc *g, const char *png_path)
{
	const char *prog = plot_gnuplot_path();
	if (g->exec_errno)
		gnuplot_missing(prog, g->exec_errno);
	else if (WIFSIGNALED(g->status))
		cli_error("gnuplot (%s) was killed by signal %d while drawing %s",
			  prog, WTERMSIG(g->status), png_path);
	else if (WEXITSTATUS(g->status) == 0)
		cli_error("gnuplot (%s) wrote no PNG image for %s", prog, png_path);
	else
		cli_error("gnuplot (%s) failed with exit status %d while drawing %s%s",
			  prog, WEXITSTATUS(g->status), png_path, g->msg[0] ? ":" : "");
	if (!g->exec_errno)
		gp_show_msg(g);
}

int plot_render(const char *script, size_t len, const char *png_path)
{
	struct cli_out out;
	struct gp_proc g;
	if (!png_path || strcmp(png_path, "-") == 0) {
		cli_error("a PNG needs a file name, not standard output");
		return 1;
	}
	if (cli_out_open(&out, png_path))
		return 1;
	/* Anything buffered would be written twice: by us and by the child. */
	fflush(out.f);
	if (gp_run(&g, script, len, fileno(out.f))) {
		/* First remove the half file: printing may end us (SIGPIPE). */
		cli_out_abort(&out);
		gp_report(&g, png_path);
		return 1;
	}
	return cli_out_commit(&out) ? 1 : 0;
}

static int write_script_file(const char *path, const char *buf, size_t len)
{
	struct cli_out out;
	if (cli_out_open(&out, path))
		return 1;
	if (fwrite(buf, 1, len, out.f) != len) {
		cli_error("%s: write failed", path);
		cli_out_abort(&out);
		return 1;
	}
	return cli_out_commit(&out) ? 1 : 0;
}

int plot_png(const struct plot_chart *c, const struct plot_opts *o,
	     const char *png_path, const char *script_path)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *m = open_memstream(&buf, &len);
	int st = m ? plot_write(m, c, o) : ANVIL_ENOMEM, code = 1;
	if (m && fclose(m) != 0 && !st)
		st = ANVIL_ENOMEM;
	if (st == ANVIL_EINVAL)
		cli_error("%s chart: nothing to draw (no model computed a result)",
			  plot_kind_name(c->kind));
	else if (st)
		cli_error("%s chart: %s", plot_kind_name(c->kind), anvil_strerror(st));
	else if (!(script_path && write_script_file(script_path, buf, len)))
		code = png_path ? plot_render(buf, len, png_path) : 0;
	free(buf);
	return code;
}

/* ----------------------------------------------------- one run's charts */

static void paths_append(char *paths, size_t len, const char *path)
{
	size_t used = strlen(paths);
	if (used + strlen(path) + 2 <= len)
		snprintf(paths + used, len - used, "%s\n", path);
}

static int run_chart(const char *dir, enum plot_kind kind,
		     const struct plot_run *runs, int n, const char *title,
		     const struct plot_opts *o, char *paths, size_t paths_len)
{
	struct plot_chart c;
	char path[PATH_MAX];
	int code = 1;
	if (snprintf(path, sizeof path, "%s/%s.png", dir, plot_kind_name(kind)) >=
	    (int)sizeof path) {
		cli_error("%s: directory name too long", dir);
		return 1;
	}
	int st = plot_chart_history(&c, kind, runs, n, 0);
	plot_chart_scene_title(&c, title);
	if (st == ANVIL_EINVAL)
		cli_error("%s: no model kept a history to draw", path);
	else if (st)
		cli_error("%s: %s", path, anvil_strerror(st));
	else if ((code = plot_png(&c, o, path, NULL)) == 0 && paths)
		paths_append(paths, paths_len, path);
	plot_chart_free(&c);
	return code;
}

int plot_run_charts(const char *dir, const struct anvil_scene *sc,
		    const struct anvil_result *res, int nres, char *paths,
		    size_t paths_len)
{
	static const enum plot_kind run_kinds[] = {PLOT_FORCE, PLOT_VELOCITY, PLOT_DEFLECTION};
	struct plot_run runs[ANVIL_MODEL_COUNT * 2];
	struct plot_opts o;
	int n = 0;
	if (paths && paths_len)
		paths[0] = '\0';
	if (plot_gnuplot_check())
		return 1;
	if (mkdir(dir, 0777) < 0 && errno != EEXIST) {
		cli_error("%s: cannot create directory: %s", dir, strerror(errno));
		return 1;
	}
	for (int i = 0; i < nres && n < (int)(sizeof runs / sizeof runs[0]); i++)
		runs[n++] = (struct plot_run){&res[i], res[i].model,
			anvil_scene_h(sc) / sc->radius, sc->velocity, res[i].lambda_star};
	plot_opts_default(&o);
	for (size_t k = 0; k < sizeof run_kinds / sizeof run_kinds[0]; k++)
		if (run_chart(dir, run_kinds[k], runs, n, sc->title, &o, paths, paths_len))
			return 1;
	return 0;
}

/* ------------------------------------------------------------ heat maps */

static void front_add(struct plot_front *f, double r, double z)
{
	if (f->n < PLOT_FRONT_POINTS) {
		f->r[f->n] = r;
		f->z[f->n] = z;
		f->n++;
	}
}

/* Does any point of the front lie in the map's extent? */
static int front_visible(const struct plot_heatmap *hm, const struct plot_front *f)
{
	for (size_t i = 0; i < f->n; i++)
		if (f->r[i] >= hm->r_lo && f->r[i] <= hm->r_hi && f->z[i] >= hm->z_lo &&
		    f->z[i] <= hm->z_hi)
			return 1;
	return 0;
}

/* The envelope of spheres of radius R about the disk r <= r0 in the plane
 * z = zs: flat (z = zs + dir R) under the disk, a quarter circle about its
 * rim beyond; dir = +1 goes down from the surface, -1 up from the image of
 * the surface in the bottom face (the reflection). */
static void front_envelope(struct plot_heatmap *hm, enum plot_front_kind kind,
			   const char *label, double R, double r0, double zs, int dir)
{
	struct plot_front *f = &hm->fronts[hm->nfronts];
	if (hm->nfronts >= PLOT_MAX_FRONTS || !(R > 0))
		return;
	memset(f, 0, sizeof *f);
	f->kind = kind;
	snprintf(f->label, sizeof f->label, "%s", label);
	front_add(f, 0, zs + dir * R);
	for (int i = 0; i < PLOT_FRONT_POINTS - 1; i++) {
		double th = 0.5 * M_PI * i / (PLOT_FRONT_POINTS - 2);
		front_add(f, r0 + R * sin(th), zs + dir * R * cos(th));
	}
	if (front_visible(hm, f))
		hm->nfronts++;
}

void plot_heatmap_fronts(struct plot_heatmap *hm, double t, double r0, double c1,
			 double c2, double cR, double h)
{
	front_envelope(hm, PLOT_FRONT_P, "P wave, c_1 t", c1 * t, r0, 0, 1);
	front_envelope(hm, PLOT_FRONT_S, "S wave, c_2 t", c2 * t, r0, 0, 1);
	/* the reflections exist once the direct front has reached the bottom */
	if (isfinite(h) && c1 * t > h)
		front_envelope(hm, PLOT_FRONT_PP, "P reflected from the bottom", c1 * t, r0, 2 * h, -1);
	if (isfinite(h) && c2 * t > h)
		front_envelope(hm, PLOT_FRONT_SS, "S reflected from the bottom", c2 * t, r0, 2 * h, -1);
	snprintf(hm->note, sizeof hm->note,
		 "wave fronts from the patch: c_1 t = %.3g mm, c_2 t = %.3g mm, c_R t = %.3g mm",
		 c1 * t * 1e3, c2 * t * 1e3, cR * t * 1e3);
	/* Rayleigh: a tick on the surface */
	double rr = r0 + cR * t;
	if (hm->nfronts < PLOT_MAX_FRONTS && rr >= hm->r_lo && rr <= hm->r_hi && hm->z_lo == 0) {
		struct plot_front *f = &hm->fronts[hm->nfronts++];
		memset(f, 0, sizeof *f);
		f->kind = PLOT_FRONT_R;
		snprintf(f->label, sizeof f->label, "Rayleigh wave, c_R t");
		front_add(f, rr, 0);
		front_add(f, rr, 0.08 * (hm->z_hi - hm->z_lo));
	}
}

/* One line per kind of front; black on the light diverging palette,
 * magenta on the dark sequential one (white would vanish in the key). */
static const char *const front_style[PLOT_FRONT_KIND_COUNT] = {
	[PLOT_FRONT_P] = "lw 2 dt 1", [PLOT_FRONT_S] = "lw 2 dt 2",
	[PLOT_FRONT_PP] = "lw 1.5 dt 4", [PLOT_FRONT_SS] = "lw 1.5 dt 3",
	[PLOT_FRONT_R] = "lw 4 dt 1",
};

/* The largest |v|, and the range of the finite values. */
static int heat_range(const struct plot_heatmap *hm, double *lo, double *hi, double *amax)
{
	int any = 0;
	*lo = INFINITY;
	*hi = -INFINITY;
	for (size_t i = 0; hm->v && i < hm->nr * hm->nz; i++)
		if (isfinite(hm->v[i])) {
			any = 1;
			*lo = fmin(*lo, hm->v[i]);
			*hi = fmax(*hi, hm->v[i]);
		}
	*amax = fmax(fabs(*lo), fabs(*hi));
	return any;
}

static void heat_header(FILE *f, const struct plot_heatmap *hm, const struct plot_opts *o)
{
	double lo, hi, amax, dz = hm->z_hi - hm->z_lo, dr = hm->r_hi - hm->r_lo;
	heat_range(hm, &lo, &hi, &amax);
	fputs("# anvil heat map: a gnuplot script with its data inline.\n"
	      "# Render with: gnuplot THIS_FILE > map.png\nset encoding utf8\n"
	      "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n", f);
	write_terminal(f, "pngcairo", o);
	fputs("} else {\n", f);
	write_terminal(f, "png", o);
	fputs("}\nset title ", f);
	put_quoted(f, o->title && o->title[0] ? o->title : hm->title);
	fputs(" noenhanced\nset xlabel 'r (mm)'\nset ylabel 'depth z (mm)'\nset cblabel ", f);
	put_quoted(f, hm->cblabel);
	/* depth downwards; true proportions unless the strip is extreme */
	fprintf(f, "\nset xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\n", hm->r_lo * 1e3,
		hm->r_hi * 1e3, hm->z_hi * 1e3, hm->z_lo * 1e3);
	if (dr > 0 && dz > 0 && dz / dr > 0.2 && dz / dr < 5)
		fputs("set size ratio -1\n", f);
	fputs("set key outside bottom center horizontal\nset tics out\n", f);
	/* the note heads the key; without a front in the key, it stands alone */
	if (hm->note[0] && hm->nfronts > 0) {
		fputs("set key title ", f);
		put_quoted(f, hm->note);
		fputc('\n', f);
	} else if (hm->note[0]) {
		fputs("set label 1 ", f);
		put_quoted(f, hm->note);
		fputs(" at screen 0.5, screen 0.02 center font ',9'\n", f);
	}
	if (hm->diverging)
		fprintf(f, "set palette defined (0 '#2166ac', 0.5 '#f7f7f7', 1 '#b2182b')\n"
			"set cbrange [%.6g:%.6g]\n", -amax, amax > 0 ? amax : 1.0);
	else
		fputs("set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', "
		      "0.75 '#5ec962', 1 '#fde725')\n", f);
}

static void heat_data(FILE *f, const struct plot_heatmap *hm)
{
	fputs("$map << EOD\n", f);
	for (size_t iz = 0; iz < hm->nz; iz++) {
		double z = hm->nz > 1 ? hm->z_lo + (hm->z_hi - hm->z_lo) * iz / (hm->nz - 1) : hm->z_lo;
		for (size_t ir = 0; ir < hm->nr; ir++) {
			double r = hm->nr > 1 ? hm->r_lo + (hm->r_hi - hm->r_lo) * ir / (hm->nr - 1) : hm->r_lo;
			double v = hm->v[iz * hm->nr + ir];
			if (isfinite(v))
				fprintf(f, "%.6g %.6g %.6g\n", r * 1e3, z * 1e3, v);
			else
				fprintf(f, "%.6g %.6g NaN\n", r * 1e3, z * 1e3);
		}
		fputc('\n', f);
	}
	fputs("EOD\n", f);
	for (int i = 0; i < hm->nfronts; i++) {
		fprintf(f, "$front%d << EOD\n", i + 1);
		for (size_t j = 0; j < hm->fronts[i].n; j++)
			fprintf(f, "%.6g %.6g\n", hm->fronts[i].r[j] * 1e3, hm->fronts[i].z[j] * 1e3);
		fputs("EOD\n", f);
	}
}

int plot_heatmap_write(FILE *f, const struct plot_heatmap *hm, const struct plot_opts *o)
{
	double lo, hi, amax;
	if (hm->nr < 2 || hm->nz < 2 || !heat_range(hm, &lo, &hi, &amax))
		return ANVIL_EINVAL;
	heat_header(f, hm, o);
	heat_data(f, hm);
	fputs("plot $map using 1:2:3 with image notitle", f);
	for (int i = 0; i < hm->nfronts; i++) {
		fprintf(f, ", \\\n     $front%d using 1:2 with lines %s lc rgb '%s' title ", i + 1,
			front_style[hm->fronts[i].kind % PLOT_FRONT_KIND_COUNT],
			hm->diverging ? "#000000" : "#ff00ff");
		put_quoted(f, hm->fronts[i].label);
	}
	fputc('\n', f);
	return fflush(f) == 0 && !ferror(f) ? ANVIL_OK : ANVIL_EIO;
}

int plot_heatmap_png(const struct plot_heatmap *hm, const struct plot_opts *o,
		     const char *png_path, const char *script_path)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *m = open_memstream(&buf, &len);
	int st = m ? plot_heatmap_write(m, hm, o) : ANVIL_ENOMEM, code = 1;
	if (m && fclose(m) != 0 && !st)
		st = ANVIL_ENOMEM;
	if (st == ANVIL_EINVAL)
		cli_error("map: nothing to draw (no finite value on a grid of at least 2 x 2)");
	else if (st)
		cli_error("map: %s", anvil_strerror(st));
	else if (!(script_path && write_script_file(script_path, buf, len)))
		code = png_path ? plot_render(buf, len, png_path) : 0;
	free(buf);
	return code;
}
