/* tui_draw_plot.c: the plot under the results table (tui_draw.h): the
 * histories, R_f against lambda* with Zener's curve, R_f against h/r0.
 * Only reads the model. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "plot.h"
#include "zener.h"
#include "tui_draw.h"
#include "tui_draw_impl.h"
#include "tui_plot.h"

/* ---- the plot ----
 *
 * The same visual language as the PNG charts (plot.h): colour = the
 * thickness h/r0 (the default colour for the half-space and for Hertz,
 * black in the PNGs), line style = the model (layer solid, Zener dashed,
 * Hertz dotted).  Ticks along the left and bottom edges. */

#define TICKS_MAX 12
#define RF_CURVE_N 60
#define ODE_N 60
#define ODE_TOL 1e-8 /* R_f to 1e-8: exact at any terminal's resolution */

/* A canvas on the screen, and the colour role of each of its series. */
struct area {
	struct tui_canvas c;
	int top, rows, cols;
	int role[TUI_CANVAS_SERIES];
	int xlog;            /* x given to the canvas as log10 */
	int ylog;            /* y too (a force or w axis, plot_force_log) */
	int yabs;            /* with ylog: |y| (a w that changes sign) */
};

static const double *quantity_data(const struct anvil_history *h,
				   enum tui_quantity q)
{
	return q == TUI_Q_FORCE ? h->P : q == TUI_Q_VELOCITY ? h->v : h->w;
}

/* SI -> the unit shown on the axis; w_mm: w in mm (else um) */
static double quantity_scale(enum tui_quantity q, int w_mm)
{
	return q == TUI_Q_FORCE ? 1e-3 : q == TUI_Q_DEFLECTION ? (w_mm ? 1e3 : 1e6) : 1;
}

static int plottable(const struct tui_row *row)
{
	return row->state != TUI_ROW_OFF && row->have && row->res.hist.n > 1;
}

static int has_value(const struct tui_row *row)
{
	return row->state != TUI_ROW_OFF && row->have && isfinite(row->res.Rf.val);
}

/* The colour role of thickness h/r0, as plot_h_colour. */
static int h_role(double h_r0)
{
	int c = plot_h_colour(h_r0);
	return c < 0 ? R_SERIES4 : R_SERIES0 + c;
}

static double scene_h_r0(const struct tui_model *m)
{
	const struct anvil_scene *sc = tui_model_scene(m);
	return anvil_scene_h(sc) / sc->radius;
}

/* A model's curve: colour role and dash, as in the PNGs. */
static int model_role(enum anvil_model k, double h_r0)
{
	return k == ANVIL_MODEL_LAYER || k == ANVIL_MODEL_ZENER ? h_role(h_r0) : R_SERIES4;
}

static unsigned model_dash(enum anvil_model k)
{
	return k == ANVIL_MODEL_ZENER ? TUI_DASH_DASHED
		: k == ANVIL_MODEL_HERTZ ? TUI_DASH_DOTTED : TUI_DASH_SOLID;
}

/* A legend sample of a dash: a line piece, or the series' glyph. */
static const char *dash_sample(const struct tui_view *v, unsigned dash, int series,
			       char ascii[2])
{
	ascii[0] = tui_canvas_glyph(series);
	ascii[1] = '\0';
	if (!v->utf8)
		return ascii;
	return dash == TUI_DASH_DASHED ? "\xe2\x95\x8d" /* ╍ */
		: dash == TUI_DASH_DOTTED ? "\xe2\x94\x88" /* ┈ */ : "\xe2\x94\x81"; /* ━ */
}

/* One legend entry at *x on row y: a sample, then the text. */
static void legend_item(int y, int *x, attr_t a, const char *sample, const char *text)
{
	if (*x >= COLS - 4)
		return;
	tui_put(y, *x, 1, a, sample);
	tui_put(y, *x + 2, COLS - *x - 2, tui_attr(R_NORMAL), text);
	*x += 4 + tui_ncols(text);
}

static int area_init(struct area *a, const struct tui_view *v, int top, int bottom)
{
	memset(a, 0, sizeof *a);
	a->top = top + 1;
	a->rows = bottom - top - 1;
	a->cols = COLS - PLOT_LEFT - 1;
	return a->rows >= 2 && a->cols >= 8 &&
	       !tui_canvas_init(&a->c, a->cols, a->rows, v->utf8 ? TUI_CANVAS_BRAILLE
							       : TUI_CANVAS_ASCII);
}

/* log10 of x > 0, else NaN (a break in the line) */
static double log_or_nan(double x)
{
	return x > 0 ? log10(x) : NAN;
}

static void area_line(struct area *a, int series, int role, const double *x,
		      const double *y, size_t n, unsigned dash)
{
	enum { NS = RF_CURVE_N > ODE_N ? RF_CURVE_N : ODE_N };
	double sx[NS], sy[NS], *lx = sx, *ly = sy, *own = NULL;
	a->role[series % TUI_CANVAS_SERIES] = role;
	if (a->xlog || a->ylog) { /* a history's samples on the heap; the charts' on the stack */
		if (n > NS && !(own = malloc(2 * n * sizeof *own)))
			return; /* out of memory: the curve is left out */
		if (own)
			lx = own, ly = own + n;
		for (size_t i = 0; i < n; i++) {
			lx[i] = a->xlog ? log_or_nan(x[i]) : x[i];
			ly[i] = a->ylog ? log_or_nan(a->yabs ? fabs(y[i]) : y[i]) : y[i];
		}
		x = lx;
		y = ly;
	}
	tui_canvas_polyline_dash(&a->c, series, x, y, n, dash);
	free(own);
}

static void area_draw(const struct area *a)
{
	for (int row = 0; row < a->c.rows; ++row)
		for (int col = 0; col < a->c.cols; ++col) {
			char cell[4];
			int s = tui_canvas_cell(&a->c, col, row, cell);
			if (s >= 0)
				tui_put(a->top + row, PLOT_LEFT + col, 1, tui_attr(a->role[s]), cell);
		}
}

/* A glyph over the canvas at data point (x, y): a mark. */
static void area_mark(const struct area *a, double x, double y, attr_t at, const char *g)
{
	if (a->xlog)
		x = log_or_nan(x);
	if (a->ylog)
		y = log_or_nan(y);
	if (!isfinite(x) || !isfinite(y))
		return;
	int col = tui_canvas_xdot(&a->c, x) / a->c.xdots;
	int row = tui_canvas_ydot(&a->c, y) / a->c.ydots;
	if (col >= 0 && col < a->c.cols && row >= 0 && row < a->c.rows)
		tui_put(a->top + row, PLOT_LEFT + col, 1, at, g);
}

/* Ticks on the left edge (y in display units = data * ys) and under the
 * bottom edge (x, log or linear, in display units = data * xs), the x
 * axis' name at the right end. */
static void area_ticks(const struct area *a, const struct tui_view *v, double ys,
		       double xs, const char *xname)
{
	double t[TICKS_MAX];
	double ylo = a->ylog ? pow(10, a->c.y0) * ys : a->c.y0 * ys;
	double yhi = a->ylog ? pow(10, a->c.y1) * ys : a->c.y1 * ys;
	int n = tui_ticks(ylo, yhi, a->ylog, a->rows / 3 + 2 < TICKS_MAX
			  ? a->rows / 3 + 2 : TICKS_MAX, t);
	for (int i = 0; i < n; i++) {
		double y = a->ylog ? log10(t[i] / ys) : t[i] / ys;
		int row = tui_canvas_ydot(&a->c, y) / a->c.ydots;
		tui_putf(a->top + row, 0, PLOT_LEFT - 2, tui_attr(R_DIM), "%7.4g", t[i]);
		tui_put(a->top + row, PLOT_LEFT - 1, 1, tui_attr(R_DIM), v->utf8 ? "\xe2\x94\xa4" : "+");
	}
	int y = a->top + a->rows, name = tui_ncols(xname), last = -1;
	double lo = a->xlog ? pow(10, a->c.x0) * xs : a->c.x0 * xs;
	double hi = a->xlog ? pow(10, a->c.x1) * xs : a->c.x1 * xs;
	n = tui_ticks(lo, hi, a->xlog, a->cols / 7 < TICKS_MAX ? a->cols / 7 : TICKS_MAX, t);
	for (int i = 0; i < n; i++) {
		char s[24];
		double x = a->xlog ? log10(t[i] / xs) : t[i] / xs;
		int col = PLOT_LEFT + tui_canvas_xdot(&a->c, x) / a->c.xdots;
		snprintf(s, sizeof s, "%g", t[i]);
		int x0 = col - tui_ncols(s) / 2;
		if (x0 <= last || x0 + tui_ncols(s) >= COLS - name - 2)
			continue;
		tui_put(y, x0, tui_ncols(s), tui_attr(R_DIM), s);
		last = x0 + tui_ncols(s);
	}
	tui_put_right(y, PLOT_LEFT, COLS - PLOT_LEFT - 1, tui_attr(R_HEAD), xname);
}

/* The range over every curve shown, always including y = 0; r[4] the
 * shortest feature (a history's end, or twice its peak's time) for the
 * time axis (log_time). */
static int plot_range(const struct tui_model *m, double r[5])
{
	int any = 0;
	r[0] = 0;
	r[1] = r[2] = r[3] = 0;
	r[4] = INFINITY;
	for (int k = 0; k < ANVIL_MODEL_COUNT; ++k) {
		const struct tui_row *row = &m->rows[k];
		if (!plottable(row))
			continue;
		const struct anvil_history *h = &row->res.hist;
		const double *y = quantity_data(h, m->quantity);
		size_t kp = 0;
		for (size_t i = 0; i < h->n; ++i) {
			if (!isfinite(h->t[i]) || !isfinite(y[i]))
				continue;
			r[1] = fmax(r[1], h->t[i]);
			r[2] = fmin(r[2], y[i]);
			r[3] = fmax(r[3], y[i]);
			if (h->P[i] > h->P[kp])
				kp = i;
		}
		double end = h->t[h->n - 1], rise = 2.0 * h->t[kp];
		if (end > 0)
			r[4] = fmin(r[4], rise > 0 ? fmin(end, rise) : end);
		any = 1;
	}
	return any;
}

/* The time axis as the charts have it (plot.c, history_time_unit): log
 * when the longest history is over 20 times the shortest feature (a drop
 * weight's seconds beside a Hertz pulse's microseconds, which a linear
 * axis squeezes into its first column), from a hundredth of that
 * feature; the unit the longest history reads best in. */
static double log_time(double r[5], int *lg, const char **name, const struct tui_view *v)
{
	*lg = isfinite(r[4]) && r[1] > 20.0 * r[4];
	if (*lg)
		r[0] = 0.01 * r[4], r[1] *= 1.3;
	if (r[1] <= 20e-3) {
		*name = *lg ? (v->utf8 ? "t [\xc2\xb5s], log" : "t [us], log")
			    : (v->utf8 ? "t [\xc2\xb5s]" : "t [us]");
		return 1e6;
	}
	if (r[1] <= 20.0) {
		*name = *lg ? "t [ms], log" : "t [ms]";
		return 1e3;
	}
	*name = *lg ? "t [s], log" : "t [s]";
	return 1.0;
}

/* The P or w axis as the charts have it (plot_force_log,
 * plot_deflection_log): log when the rows' peaks differ more than 20
 * times (a thin plate's 0.08 kN beside the rigid anvil's 105 kN lay on
 * the zero line; its 640 mm beside the half-space's 0.47 um), |w| then
 * when a row's w changes sign (*abs); range in SI.  *w_mm: w beyond 1 mm
 * in mm, as the charts (250000 um does not fit the ticks' 7 columns). */
static int log_axis(const struct tui_model *m, double range[2], int *abs, int *w_mm)
{
	double peak[ANVIL_MODEL_COUNT] = {0}, low[ANVIL_MODEL_COUNT] = {0}, top = 0;
	int n = 0, q = m->quantity;
	*abs = *w_mm = 0;
	if (q != TUI_Q_FORCE && q != TUI_Q_DEFLECTION)
		return 0;
	for (int k = 0; k < ANVIL_MODEL_COUNT; ++k) {
		const struct tui_row *row = &m->rows[k];
		if (!plottable(row))
			continue;
		const double *y = quantity_data(&row->res.hist, m->quantity);
		for (size_t i = 0; i < row->res.hist.n; ++i) {
			peak[n] = fmax(peak[n], fabs(y[i]));
			low[n] = fmin(low[n], y[i]);
		}
		top = fmax(top, peak[n]);
		n++;
	}
	if (q == TUI_Q_FORCE)
		return plot_force_log(peak, n, range);
	*w_mm = top > 1e-3;
	return plot_deflection_log(peak, low, n, range, abs);
}

static void history_legend(const struct tui_model *m, const struct tui_view *v, int y,
			   const struct area *a, int w_mm)
{
	char head[64];
	double h = scene_h_r0(m);
	int w = m->quantity == TUI_Q_DEFLECTION;
	snprintf(head, sizeof head, "%s [%s%s] vs t",
		 w && a->yabs ? "|w|(t)" : tui_quantity_name(m->quantity),
		 w && w_mm ? "mm" : w && v->utf8 ? "\xc2\xb5m" : tui_quantity_unit(m->quantity),
		 a->ylog ? ", log" : "");
	tui_put(y, 1, COLS - 2, tui_attr(R_HEAD), head);
	int x = 1 + tui_ncols(head) + 2;
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i) {
		enum anvil_model k = tui_model_order[i];
		char ascii[2];
		/* Hertz's rigid anvil has w = 0, which a log axis cannot draw:
		 * the legend says so, as the charts' key does */
		int unseen = w && a->ylog && k == ANVIL_MODEL_HERTZ;
		if (plottable(&m->rows[k]))
			legend_item(y, &x, tui_attr(model_role(k, h)),
				    dash_sample(v, model_dash(k), i, ascii),
				    unseen ? "Hertz (w = 0)" : tui_model_title(k));
	}
}

static void draw_history(const struct tui_model *m, const struct tui_view *v,
			 int top, int bottom)
{
	struct area a, axis = {0};
	double r[5], h = scene_h_r0(m), fr[2];
	int w_mm, ylog = log_axis(m, fr, &axis.yabs, &w_mm);
	axis.ylog = ylog;
	history_legend(m, v, top, &axis, w_mm);
	if (!plot_range(m, r)) {
		tui_putf((top + bottom) / 2, PLOT_LEFT, COLS - PLOT_LEFT - 1, tui_attr(R_DIM), "%s",
		     tui_model_busy(m) ? "computing" : "no histories to plot");
		return;
	}
	if (!area_init(&a, v, top, bottom))
		return;
	const char *tname;
	double ts = log_time(r, &a.xlog, &tname, v);
	a.yabs = axis.yabs;
	if ((a.ylog = ylog))
		r[2] = log10(fr[0]), r[3] = log10(fr[1]);
	if (a.xlog)
		tui_canvas_range(&a.c, log10(r[0]), log10(r[1]), r[2], r[3]);
	else
		tui_canvas_range(&a.c, r[0], r[1], r[2], r[3]);
	/* backwards, so the first model of the legend ends up on top */
	for (int i = ANVIL_MODEL_COUNT - 1; i >= 0; --i) {
		enum anvil_model k = tui_model_order[i];
		const struct tui_row *row = &m->rows[k];
		if (plottable(row))
			area_line(&a, i, model_role(k, h), row->res.hist.t,
				  quantity_data(&row->res.hist, m->quantity), row->res.hist.n,
				  model_dash(k));
	}
	area_draw(&a);
	area_ticks(&a, v, quantity_scale(m->quantity, w_mm), ts, tname);
	tui_canvas_free(&a.c);
}

/* Zener's ODE R_f(lambda*), the same for every scene: solved once. */
static int ode_curve(const double **x, const double **y)
{
	static double ox[ODE_N], oy[ODE_N];
	static int n = -1;
	if (n < 0) {
		n = 0;
		for (int i = 0; i < ODE_N; i++) {
			struct anvil_zener_sol sol;
			double l = 1e-4 * pow(4e4, (double)i / (ODE_N - 1)); /* 1e-4 .. 4 */
			if (anvil_zener_solve(l, ODE_TOL, &sol, NULL) == ANVIL_OK) {
				ox[n] = l;
				oy[n++] = sol.rf;
			}
		}
	}
	*x = ox;
	*y = oy;
	return n;
}

static void draw_rf_lambda(const struct tui_model *m, const struct tui_view *v,
			   int top, int bottom)
{
	struct anvil_params p;
	struct area a;
	double fx[RF_CURVE_N], fy[RF_CURVE_N], h = scene_h_r0(m);
	const double *ox, *oy;
	char ascii[2], text[96];
	int x = 1, ok = anvil_params_from_scene(&p, tui_model_scene(m), NULL) == ANVIL_OK;
	double lam = ok ? p.lambda_star : NAN;
	double lo = lam > 0 && lam < 1e-3 ? pow(10, floor(log10(lam))) : 1e-3;
	double hi = fmax(1.5, lam > 0 ? 1.5 * lam : 0);
	tui_put(top, x, COLS - 2, tui_attr(R_HEAD), v->utf8 ? "R_f vs \xce\xbb* (log)" : "R_f vs lambda* (log)");
	x += 22;
	legend_item(top, &x, tui_attr(R_SERIES4), dash_sample(v, TUI_DASH_SOLID, 0, ascii), "Zener fit");
	legend_item(top, &x, tui_attr(R_SERIES4), dash_sample(v, TUI_DASH_DASHED, 1, ascii), "Zener ODE");
	if (!area_init(&a, v, top, bottom))
		return;
	a.xlog = 1;
	tui_canvas_range(&a.c, log10(lo), log10(hi), 0, 1.05);
	for (int i = 0; i < RF_CURVE_N; i++) {
		fx[i] = lo * pow(hi / lo, (double)i / (RF_CURVE_N - 1));
		fy[i] = anvil_zener_rf_fit(fx[i]);
	}
	area_line(&a, 0, R_SERIES4, fx, fy, RF_CURVE_N, TUI_DASH_SOLID);
	int nodes = ode_curve(&ox, &oy);
	area_line(&a, 1, R_SERIES4, ox, oy, (size_t)nodes, TUI_DASH_DASHED);
	/* The scene: a dotted line at its lambda*, a mark on the fit. */
	double vx[2] = {lam, lam}, vy[2] = {0, 1.05};
	if (lam > 0)
		area_line(&a, 2, h_role(h), vx, vy, 2, TUI_DASH_DOTTED);
	area_draw(&a);
	area_mark(&a, lam, ok ? p.Rf_star : NAN, tui_attr(h_role(h)), v->utf8 ? "\xe2\x97\x86" : "X");
	const struct tui_row *layer = &m->rows[ANVIL_MODEL_LAYER];
	if (has_value(layer))
		area_mark(&a, lam, layer->res.Rf.val, tui_attr(h_role(h)), v->utf8 ? "\xe2\x97\x8f" : "O");
	const char *name = v->utf8 ? "\xce\xbb*" : "lambda*";
	int k = lam > 0 ? snprintf(text, sizeof text, "this scene: %s = %.3g, R*_f = %.3g",
				   name, lam, p.Rf_star)
		: snprintf(text, sizeof text, "this scene: half-space, %s = 0", name);
	if (has_value(layer) && k > 0 && (size_t)k < sizeof text)
		snprintf(text + k, sizeof text - (size_t)k, ", layer R_f = %.3g", layer->res.Rf.val);
	legend_item(top, &x, tui_attr(h_role(h)), v->utf8 ? "\xe2\x97\x86" : "X", text);
	area_ticks(&a, v, 1, 1, v->utf8 ? "\xce\xbb*" : "lambda*");
	tui_canvas_free(&a.c);
}

static void draw_rf_thickness(const struct tui_model *m, const struct tui_view *v,
			      int top, int bottom)
{
	struct anvil_scene sc = *tui_model_scene(m);
	struct area a;
	double zx[RF_CURVE_N], zy[RF_CURVE_N], h = scene_h_r0(m);
	char ascii[2], text[96];
	int x = 1;
	double lo = isfinite(h) ? fmin(0.5, h / 1.5) : 0.5, hi = isfinite(h) ? fmax(20, 1.5 * h) : 20;
	tui_put(top, x, COLS - 2, tui_attr(R_HEAD), "R_f vs h/r0 (log)");
	x += 19;
	legend_item(top, &x, tui_attr(R_SERIES4), dash_sample(v, TUI_DASH_DASHED, 0, ascii),
		    "Zener R*_f");
	if (!area_init(&a, v, top, bottom))
		return;
	a.xlog = 1;
	tui_canvas_range(&a.c, log10(lo), log10(hi), 0, 1.05);
	/* Zener's R*_f (54) of this scene at every thickness: cheap, live. */
	sc.thickness_per_r0 = 1;
	for (int i = 0; i < RF_CURVE_N; i++) {
		struct anvil_params p;
		sc.thickness = zx[i] = lo * pow(hi / lo, (double)i / (RF_CURVE_N - 1));
		zy[i] = anvil_params_from_scene(&p, &sc, NULL) ? NAN : p.Rf_star;
	}
	area_line(&a, 0, R_SERIES4, zx, zy, RF_CURVE_N, TUI_DASH_DASHED);
	const struct tui_row *half = &m->rows[ANVIL_MODEL_HALFSPACE];
	const struct tui_row *layer = &m->rows[ANVIL_MODEL_LAYER];
	if (has_value(half)) {
		double hx[2] = {lo, hi}, hy[2] = {half->res.Rf.val, half->res.Rf.val};
		area_line(&a, 1, R_SERIES4, hx, hy, 2, TUI_DASH_DOTTED);
		legend_item(top, &x, tui_attr(R_SERIES4), dash_sample(v, TUI_DASH_DOTTED, 1, ascii),
			    "half-space");
	}
	double vx[2] = {h, h}, vy[2] = {0, 1.05};
	if (isfinite(h))
		area_line(&a, 2, h_role(h), vx, vy, 2, TUI_DASH_DOTTED);
	area_draw(&a);
	if (has_value(layer) && isfinite(h))
		area_mark(&a, h, layer->res.Rf.val, tui_attr(h_role(h)), v->utf8 ? "\xe2\x97\x8f" : "O");
	if (isfinite(h))
		snprintf(text, sizeof text, "this scene: h = %.3g r0%s", h,
			 has_value(layer) ? "" : " (layer R_f: not computed)");
	else
		snprintf(text, sizeof text, "this scene: half-space");
	if (has_value(layer) && isfinite(h)) {
		size_t k = strlen(text);
		snprintf(text + k, sizeof text - k, ", layer R_f = %.3g", layer->res.Rf.val);
	}
	legend_item(top, &x, tui_attr(h_role(h)), v->utf8 ? "\xe2\x97\x8f" : "O", text);
	area_ticks(&a, v, 1, 1, "h/r0");
	tui_canvas_free(&a.c);
}

void tui_draw_plot(const struct tui_model *m, const struct tui_view *v,
		      int top, int bottom)
{
	if (m->quantity == TUI_Q_RF_LAMBDA)
		draw_rf_lambda(m, v, top, bottom);
	else if (m->quantity == TUI_Q_RF_THICKNESS)
		draw_rf_thickness(m, v, top, bottom);
	else
		draw_history(m, v, top, bottom);
}
