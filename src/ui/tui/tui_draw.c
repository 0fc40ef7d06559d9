/* tui_draw.c: the TUI's screens.  Every function here only reads the model;
 * the colours live in one table. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "params.h"
#include "commands.h"
#include "common.h"
#include "plot.h"
#include "problem.h"
#include "zener.h"
#include "tui_draw.h"
#include "tui_plot.h"

/* ---- colours: one table, with what to use when there are none ---- */

enum role {
	R_NORMAL, R_TITLE, R_HEAD, R_SEL, R_DIM, R_ERROR, R_INFO, R_KEYS,
	R_SERIES0, R_SERIES1, R_SERIES2, R_SERIES3, R_SERIES4, R_COUNT
};

static const struct {
	short fg, bg;   /* -1: the terminal's default */
	attr_t extra;   /* added to the colour pair */
	attr_t mono;    /* without colours (NO_COLOR, or none to be had) */
} palette[R_COUNT] = {
	[R_NORMAL] = {-1, -1, A_NORMAL, A_NORMAL},
	[R_TITLE] = {COLOR_WHITE, COLOR_BLUE, A_BOLD, A_REVERSE},
	[R_HEAD] = {COLOR_YELLOW, -1, A_BOLD, A_BOLD},
	[R_SEL] = {COLOR_BLACK, COLOR_CYAN, A_NORMAL, A_REVERSE},
	[R_DIM] = {-1, -1, A_DIM, A_DIM},
	[R_ERROR] = {COLOR_RED, -1, A_BOLD, A_BOLD},
	[R_INFO] = {COLOR_GREEN, -1, A_NORMAL, A_NORMAL},
	[R_KEYS] = {COLOR_BLACK, COLOR_WHITE, A_NORMAL, A_REVERSE},
	/* curves: the PNG charts' colours of thickness (plot_h_colour: blue,
	 * vermillion, bluish green, reddish purple), the nearest curses has,
	 * and the default colour where the PNGs use black (the half-space,
	 * Hertz, Zener's curves); without colour, attributes keep them apart */
	[R_SERIES0] = {COLOR_BLUE, -1, A_BOLD, A_BOLD},
	[R_SERIES1] = {COLOR_RED, -1, A_BOLD, A_NORMAL},
	[R_SERIES2] = {COLOR_GREEN, -1, A_BOLD, A_UNDERLINE},
	[R_SERIES3] = {COLOR_MAGENTA, -1, A_BOLD, A_DIM},
	[R_SERIES4] = {-1, -1, A_BOLD, A_BOLD},
};

static int use_color;

void tui_draw_init(struct tui_view *v, int want_color, int utf8)
{
	v->utf8 = utf8;
	v->color = want_color && has_colors() && start_color() == OK;
	use_color = v->color;
	if (!v->color)
		return;
	int defaults = use_default_colors() == OK;
	for (int r = 1; r < R_COUNT; ++r) {
		short fg = palette[r].fg, bg = palette[r].bg;
		if (!defaults) { /* no "default" colour: assume white on black */
			fg = fg < 0 ? COLOR_WHITE : fg;
			bg = bg < 0 ? COLOR_BLACK : bg;
		}
		init_pair((short)r, fg, bg);
	}
}

static attr_t attr(int r)
{
	if (!use_color)
		return palette[r].mono;
	return (r ? COLOR_PAIR(r) : A_NORMAL) | palette[r].extra;
}

/* ---- text ---- */

/* Columns of UTF-8 text: every character anvil writes is one column wide,
 * so columns are the bytes that are not continuation bytes (10xxxxxx). */
static int ncols(const char *s)
{
	int n = 0;
	for (; *s; ++s)
		n += ((unsigned char)*s & 0xC0) != 0x80;
	return n;
}

/* Write s at (y, x), at most w columns. */
static void put(int y, int x, int w, attr_t a, const char *s)
{
	int cols = 0;
	size_t n = 0;
	if (w <= 0 || y < 0 || y >= LINES || x < 0 || x >= COLS)
		return;
	for (; s[n]; ++n) {
		if (((unsigned char)s[n] & 0xC0) != 0x80 && cols++ == w)
			break;
	}
	attrset(a);
	mvaddnstr(y, x, s, (int)n);
	attrset(A_NORMAL);
}

static void putf(int y, int x, int w, attr_t a, const char *fmt, ...)
	__attribute__((format(printf, 5, 6)));
static void putf(int y, int x, int w, attr_t a, const char *fmt, ...)
{
	char buf[1024];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(buf, sizeof buf, fmt, ap);
	va_end(ap);
	put(y, x, w, a, buf);
}

/* A bar across the screen: the row filled with attribute a. */
static void bar(int y, attr_t a)
{
	attrset(a);
	mvhline(y, 0, ' ', COLS);
	attrset(A_NORMAL);
}

static const char *ellipsis(const struct tui_view *v)
{
	return v->utf8 ? "\xe2\x80\xa6" : "...";
}

/* ---- layout of the main screen (80 x 24 at least) ---- */

enum {
	PANEL_W = 26,                 /* the parameter panel, columns 0-25 */
	TABLE_X = 27,                 /* the results table */
	TABLE_LABEL_W = 9,
	TABLE_COL_W = 11,
	TOP = 1,                      /* first row under the title bar */
	NOTES_ROWS = 3,               /* solver messages under the table */
	PLOT_TOP = TOP + 1 + TUI_F_COUNT + 1,
	PLOT_LEFT = 9                 /* y-axis labels */
};

static void draw_header(const struct tui_model *m, const struct tui_view *v)
{
	char right[160];
	bar(0, attr(R_TITLE));
	if (tui_model_busy(m))
		snprintf(right, sizeof right, "computing%s %3.0f%% %s", ellipsis(v),
			 100 * m->progress, m->progress_what);
	else if (m->run_computed)
		snprintf(right, sizeof right, "last run %.3g %s%s",
			 m->run_seconds < 1 ? 1e3 * m->run_seconds : m->run_seconds,
			 m->run_seconds < 1 ? "ms" : "s", m->run_cached ? " (+cache)" : "");
	else
		snprintf(right, sizeof right, "%s", m->run_cached ? "from cache" : "");
	int n = (int)strlen(right);
	if (n > COLS / 2)
		n = COLS / 2;
	put(0, COLS - n - 1, n, attr(R_TITLE), right);
	/* the file name matters more than the title: it goes first */
	putf(0, 1, COLS - n - 3, attr(R_TITLE), "anvil tui  %s%s  %s",
	     m->path[0] ? m->path : "(no file)", m->modified ? " [modified]" : "",
	     m->sc.title);
}

static void draw_panel(const struct tui_model *m)
{
	put(TOP, 0, PANEL_W, attr(R_HEAD), " Scene");
	for (int f = 0; f < TUI_F_COUNT; ++f) {
		char value[64];
		int y = TOP + 1 + f;
		attr_t a = f == m->sel ? attr(R_SEL) : attr(R_NORMAL);
		tui_model_field_text(m, (enum tui_field)f, value, sizeof value);
		if (f == m->sel) {
			attrset(a);
			mvhline(y, 0, ' ', PANEL_W);
		}
		putf(y, 0, PANEL_W, a, "%c %-9s %s", f == m->sel ? '>' : ' ',
		     tui_field_label((enum tui_field)f), value);
	}
}

/* The results table's rows: a label (ASCII and UTF-8), the factor from SI
 * to the unit shown, and where the number is. */
static const struct {
	const char *label, *label_utf8;
	double scale;
	size_t off;
	int zener_only; /* Zener's parameters describe no other model */
} quantities[] = {
	{"t_s   us", "t_s   \xc2\xb5s", 1e6, offsetof(struct anvil_result, ts), 0},
	{"t_max us", "t_max \xc2\xb5s", 1e6, offsetof(struct anvil_result, tmax), 0},
	{"P_max kN", NULL, 1e-3, offsetof(struct anvil_result, Pmax), 0},
	{"V_s  m/s", NULL, 1, offsetof(struct anvil_result, Vs), 0},
	{"R_f", NULL, 1, offsetof(struct anvil_result, Rf), 0},
	{"E_a   mJ", NULL, 1e3, offsetof(struct anvil_result, Ea), 0},
	{"lambda*", "\xce\xbb*", 1, offsetof(struct anvil_result, lambda_star), 1},
	{"R_f*", NULL, 1, offsetof(struct anvil_result, Rf_star), 1},
	{"time  ms", NULL, 1e3, offsetof(struct anvil_result, seconds), 0},
};
#define NQUANT ((int)(sizeof quantities / sizeof quantities[0]))

/* Magnitudes no quantity of an impact reaches (seconds, newtons, joules,
 * m/s in the units shown): beyond them a number is garbage (1.797e-299 for
 * an unset field), shown as "-" rather than as a value. */
#define CELL_TINY 1e-100
#define CELL_HUGE 1e100

static void cell_text(const struct tui_row *row, int q, const struct tui_view *v,
		      char *buf, size_t n)
{
	if (row->state == TUI_ROW_OFF ||
	    (quantities[q].zener_only && row->res.model != ANVIL_MODEL_ZENER)) {
		snprintf(buf, n, "-");
	} else if (!row->have) {
		/* a refusal says so: its zeros would read as computed ones */
		snprintf(buf, n, "%s", row->state == TUI_ROW_PENDING ? ellipsis(v)
				       : row->status != ANVIL_OK ? "refused" : "n/a");
	} else {
		double x = *(const double *)((const char *)&row->res + quantities[q].off);
		x *= quantities[q].scale;
		if (!isfinite(x) || fabs(x) > CELL_HUGE || (x != 0 && fabs(x) < CELL_TINY))
			snprintf(buf, n, "-");
		else
			snprintf(buf, n, "%s%.4g", row->status > 0 ? "~" : "", x);
	}
}

static attr_t cell_attr(const struct tui_row *row)
{
	if (row->state == TUI_ROW_PENDING)
		return attr(R_DIM);
	if (row->state == TUI_ROW_DONE && !row->have)
		return attr(R_ERROR);
	return attr(R_NORMAL);
}

/* Right-align s (UTF-8) in w columns. */
static void put_right(int y, int x, int w, attr_t a, const char *s)
{
	int cols = ncols(s);
	put(y, x + (cols < w ? w - cols : 0), w, a, s);
}

/* The notes under the table, in order: the verdict (verdict.h; in the
 * error colour when a body yields or cracks), then each computed row's
 * refusal or note.  The main screen shows the first NOTES_ROWS, one line
 * each; the notes screen ('n') shows them all, wrapped. */
#define NOTES_MAX (2 + ANVIL_MODEL_COUNT)
#define NOTE_LEN 1024
struct notes {
	int n;
	attr_t a[NOTES_MAX];
	char text[NOTES_MAX][NOTE_LEN];
};

static void notes_collect(const struct tui_model *m, struct notes *nt)
{
	char layer[320], imp[320];
	int fails = tui_model_verdict(m, layer, imp, sizeof layer);
	nt->n = 0;
	if (fails >= 0) {
		nt->a[nt->n] = attr(fails ? R_ERROR : R_INFO);
		snprintf(nt->text[nt->n++], NOTE_LEN, "%s", layer);
		if (imp[0]) {
			nt->a[nt->n] = attr(R_ERROR);
			snprintf(nt->text[nt->n++], NOTE_LEN, "%s", imp);
		}
	}
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i) {
		const struct tui_row *row = &m->rows[tui_model_order[i]];
		const char *title = tui_model_title(tui_model_order[i]);
		if (row->state != TUI_ROW_DONE)
			continue;
		if (row->status != ANVIL_OK) {
			nt->a[nt->n] = attr(row->have ? R_INFO : R_ERROR);
			snprintf(nt->text[nt->n++], NOTE_LEN, "%s: %s", title,
				 row->msg[0] ? cli_model_reason(tui_model_order[i], row->msg)
					     : anvil_strerror(row->status));
		} else if (row->have && row->res.note[0]) {
			nt->a[nt->n] = attr(R_INFO);
			snprintf(nt->text[nt->n++], NOTE_LEN, "%s: %s", title, row->res.note);
		}
	}
}

/* s in w columns on one line; cut short with an ellipsis when it does
 * not fit (the notes screen has the rest). */
static void put_cut(int y, int x, int w, attr_t a, const char *s, const struct tui_view *v)
{
	const char *e = ellipsis(v);
	int ew = ncols(e);
	if (ncols(s) <= w || w <= ew) {
		put(y, x, w, a, s);
		return;
	}
	put(y, x, w - ew, a, s);
	put(y, x + w - ew, ew, a, e);
}

static void draw_notes(const struct tui_model *m, const struct tui_view *v, int y)
{
	struct notes *nt = malloc(sizeof *nt);
	if (!nt)
		return;
	notes_collect(m, nt);
	for (int i = 0; i < nt->n && i < NOTES_ROWS; ++i)
		put_cut(y + i, TABLE_X, COLS - TABLE_X, nt->a[i], nt->text[i], v);
	free(nt);
}

static void draw_table(const struct tui_model *m, const struct tui_view *v)
{
	put(TOP, TABLE_X, TABLE_LABEL_W, attr(R_HEAD), "Results");
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i)
		put_right(TOP, TABLE_X + TABLE_LABEL_W + i * TABLE_COL_W, TABLE_COL_W - 1,
			  attr(R_HEAD), tui_model_title(tui_model_order[i]));
	for (int q = 0; q < NQUANT; ++q) {
		int y = TOP + 1 + q;
		const char *label = v->utf8 && quantities[q].label_utf8
					    ? quantities[q].label_utf8 : quantities[q].label;
		put(y, TABLE_X, TABLE_LABEL_W, attr(R_NORMAL), label);
		for (int i = 0; i < ANVIL_MODEL_COUNT; ++i) {
			const struct tui_row *row = &m->rows[tui_model_order[i]];
			char cell[32];
			cell_text(row, q, v, cell, sizeof cell);
			put_right(y, TABLE_X + TABLE_LABEL_W + i * TABLE_COL_W,
				  TABLE_COL_W - 1, cell_attr(row), cell);
		}
	}
	draw_notes(m, v, TOP + 1 + NQUANT);
}

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
};

static const double *quantity_data(const struct anvil_history *h,
				   enum tui_quantity q)
{
	return q == TUI_Q_FORCE ? h->P : q == TUI_Q_VELOCITY ? h->v : h->w;
}

/* SI -> the unit shown on the axis */
static double quantity_scale(enum tui_quantity q)
{
	return q == TUI_Q_FORCE ? 1e-3 : q == TUI_Q_DEFLECTION ? 1e6 : 1;
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
	put(y, *x, 1, a, sample);
	put(y, *x + 2, COLS - *x - 2, attr(R_NORMAL), text);
	*x += 4 + ncols(text);
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

static void area_line(struct area *a, int series, int role, const double *x,
		      const double *y, size_t n, unsigned dash)
{
	double sx[RF_CURVE_N > ODE_N ? RF_CURVE_N : ODE_N], *lx = sx, *own = NULL;
	a->role[series % TUI_CANVAS_SERIES] = role;
	if (a->xlog) { /* a history's samples on the heap; the charts' on the stack */
		if (n > sizeof sx / sizeof sx[0] && !(lx = own = malloc(n * sizeof *lx)))
			return; /* out of memory: the curve is left out */
		for (size_t i = 0; i < n; i++)
			lx[i] = x[i] > 0 ? log10(x[i]) : NAN;
		x = lx;
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
				put(a->top + row, PLOT_LEFT + col, 1, attr(a->role[s]), cell);
		}
}

/* A glyph over the canvas at data point (x, y): a mark. */
static void area_mark(const struct area *a, double x, double y, attr_t at, const char *g)
{
	if (a->xlog)
		x = x > 0 ? log10(x) : NAN;
	if (!isfinite(x) || !isfinite(y))
		return;
	int col = tui_canvas_xdot(&a->c, x) / a->c.xdots;
	int row = tui_canvas_ydot(&a->c, y) / a->c.ydots;
	if (col >= 0 && col < a->c.cols && row >= 0 && row < a->c.rows)
		put(a->top + row, PLOT_LEFT + col, 1, at, g);
}

/* Ticks on the left edge (y in display units = data * ys) and under the
 * bottom edge (x, log or linear, in display units = data * xs), the x
 * axis' name at the right end. */
static void area_ticks(const struct area *a, const struct tui_view *v, double ys,
		       double xs, const char *xname)
{
	double t[TICKS_MAX];
	int n = tui_ticks(a->c.y0 * ys, a->c.y1 * ys, 0, a->rows / 3 + 2 < TICKS_MAX
			  ? a->rows / 3 + 2 : TICKS_MAX, t);
	for (int i = 0; i < n; i++) {
		int row = tui_canvas_ydot(&a->c, t[i] / ys) / a->c.ydots;
		putf(a->top + row, 0, PLOT_LEFT - 2, attr(R_DIM), "%7.4g", t[i]);
		put(a->top + row, PLOT_LEFT - 1, 1, attr(R_DIM), v->utf8 ? "\xe2\x94\xa4" : "+");
	}
	int y = a->top + a->rows, name = ncols(xname), last = -1;
	double lo = a->xlog ? pow(10, a->c.x0) * xs : a->c.x0 * xs;
	double hi = a->xlog ? pow(10, a->c.x1) * xs : a->c.x1 * xs;
	n = tui_ticks(lo, hi, a->xlog, a->cols / 7 < TICKS_MAX ? a->cols / 7 : TICKS_MAX, t);
	for (int i = 0; i < n; i++) {
		char s[24];
		double x = a->xlog ? log10(t[i] / xs) : t[i] / xs;
		int col = PLOT_LEFT + tui_canvas_xdot(&a->c, x) / a->c.xdots;
		snprintf(s, sizeof s, "%g", t[i]);
		int x0 = col - ncols(s) / 2;
		if (x0 <= last || x0 + ncols(s) >= COLS - name - 2)
			continue;
		put(y, x0, ncols(s), attr(R_DIM), s);
		last = x0 + ncols(s);
	}
	put_right(y, PLOT_LEFT, COLS - PLOT_LEFT - 1, attr(R_HEAD), xname);
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

static void history_legend(const struct tui_model *m, const struct tui_view *v, int y)
{
	char head[64];
	double h = scene_h_r0(m);
	snprintf(head, sizeof head, "%s [%s] vs t", tui_quantity_name(m->quantity),
		 v->utf8 && m->quantity == TUI_Q_DEFLECTION ? "\xc2\xb5m"
							    : tui_quantity_unit(m->quantity));
	put(y, 1, COLS - 2, attr(R_HEAD), head);
	int x = 1 + ncols(head) + 2;
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i) {
		enum anvil_model k = tui_model_order[i];
		char ascii[2];
		if (plottable(&m->rows[k]))
			legend_item(y, &x, attr(model_role(k, h)),
				    dash_sample(v, model_dash(k), i, ascii), tui_model_title(k));
	}
}

static void draw_history(const struct tui_model *m, const struct tui_view *v,
			 int top, int bottom)
{
	struct area a;
	double r[5], h = scene_h_r0(m);
	history_legend(m, v, top);
	if (!plot_range(m, r)) {
		putf((top + bottom) / 2, PLOT_LEFT, COLS - PLOT_LEFT - 1, attr(R_DIM), "%s",
		     tui_model_busy(m) ? "computing" : "no histories to plot");
		return;
	}
	if (!area_init(&a, v, top, bottom))
		return;
	const char *tname;
	double ts = log_time(r, &a.xlog, &tname, v);
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
	area_ticks(&a, v, quantity_scale(m->quantity), ts, tname);
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
	put(top, x, COLS - 2, attr(R_HEAD), v->utf8 ? "R_f vs \xce\xbb* (log)" : "R_f vs lambda* (log)");
	x += 22;
	legend_item(top, &x, attr(R_SERIES4), dash_sample(v, TUI_DASH_SOLID, 0, ascii), "Zener fit");
	legend_item(top, &x, attr(R_SERIES4), dash_sample(v, TUI_DASH_DASHED, 1, ascii), "Zener ODE");
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
	area_mark(&a, lam, ok ? p.Rf_star : NAN, attr(h_role(h)), v->utf8 ? "\xe2\x97\x86" : "X");
	const struct tui_row *layer = &m->rows[ANVIL_MODEL_LAYER];
	if (has_value(layer))
		area_mark(&a, lam, layer->res.Rf.val, attr(h_role(h)), v->utf8 ? "\xe2\x97\x8f" : "O");
	const char *name = v->utf8 ? "\xce\xbb*" : "lambda*";
	int k = lam > 0 ? snprintf(text, sizeof text, "this scene: %s = %.3g, R*_f = %.3g",
				   name, lam, p.Rf_star)
		: snprintf(text, sizeof text, "this scene: half-space, %s = 0", name);
	if (has_value(layer) && k > 0 && (size_t)k < sizeof text)
		snprintf(text + k, sizeof text - (size_t)k, ", layer R_f = %.3g", layer->res.Rf.val);
	legend_item(top, &x, attr(h_role(h)), v->utf8 ? "\xe2\x97\x86" : "X", text);
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
	put(top, x, COLS - 2, attr(R_HEAD), "R_f vs h/r0 (log)");
	x += 19;
	legend_item(top, &x, attr(R_SERIES4), dash_sample(v, TUI_DASH_DASHED, 0, ascii),
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
		legend_item(top, &x, attr(R_SERIES4), dash_sample(v, TUI_DASH_DOTTED, 1, ascii),
			    "half-space");
	}
	double vx[2] = {h, h}, vy[2] = {0, 1.05};
	if (isfinite(h))
		area_line(&a, 2, h_role(h), vx, vy, 2, TUI_DASH_DOTTED);
	area_draw(&a);
	if (has_value(layer) && isfinite(h))
		area_mark(&a, h, layer->res.Rf.val, attr(h_role(h)), v->utf8 ? "\xe2\x97\x8f" : "O");
	if (isfinite(h))
		snprintf(text, sizeof text, "this scene: h = %.3g r0%s", h,
			 has_value(layer) ? "" : " (layer R_f: not computed)");
	else
		snprintf(text, sizeof text, "this scene: half-space");
	if (has_value(layer) && isfinite(h)) {
		size_t k = strlen(text);
		snprintf(text + k, sizeof text - k, ", layer R_f = %.3g", layer->res.Rf.val);
	}
	legend_item(top, &x, attr(h_role(h)), v->utf8 ? "\xe2\x97\x8f" : "O", text);
	area_ticks(&a, v, 1, 1, "h/r0");
	tui_canvas_free(&a.c);
}

static void draw_plot(const struct tui_model *m, const struct tui_view *v,
		      int top, int bottom)
{
	if (m->quantity == TUI_Q_RF_LAMBDA)
		draw_rf_lambda(m, v, top, bottom);
	else if (m->quantity == TUI_Q_RF_THICKNESS)
		draw_rf_thickness(m, v, top, bottom);
	else
		draw_history(m, v, top, bottom);
}

/* ---- the bottom lines ---- */

/* How many bytes of p make its first line in w columns: up to the last
 * space that fits when p goes on, never inside a UTF-8 character. */
static int line_break(const char *p, int w)
{
	int cols = 0, cut = -1, i = 0;
	for (; p[i] && cols < w; i++) {
		cols += ((unsigned char)p[i] & 0xC0) != 0x80;
		if (p[i] == ' ')
			cut = i;
	}
	while (p[i] && ((unsigned char)p[i] & 0xC0) == 0x80)
		i++;
	return p[i] && cut > 0 ? cut : i;
}

/* A message too long for one line, wrapped at spaces onto the lines above
 * bottom (over the foot of the plot), at most STATUS_MAX_LINES. */
#define STATUS_MAX_LINES 4
static void put_wrapped(int bottom, attr_t a, const char *msg)
{
	const char *line[STATUS_MAX_LINES];
	int len[STATUS_MAX_LINES], n = 0, w = COLS - 1;
	const char *p = msg;
	while (*p && n < STATUS_MAX_LINES) {
		int i = line_break(p, w);
		line[n] = p;
		len[n++] = i;
		p += i;
		while (*p == ' ')
			p++;
	}
	for (int k = 0; k < n; k++) {
		char buf[ANVIL_ERR_MSG + 1];
		snprintf(buf, sizeof buf, "%.*s", len[k], line[k]);
		size_t l = strlen(buf);
		if (k + 1 == n && *p && l > 3) /* more than fits */
			strcpy(buf + l - 3, "...");
		bar(bottom - n + 1 + k, A_NORMAL);
		put(bottom - n + 1 + k, 0, w, a, buf);
	}
}

static void draw_status(const struct tui_model *m)
{
	static const char keys_long[] =
		"arrows/hjkl select+change  H/L coarse  Enter type  m material  "
		"a accuracy  v plot  n notes  p png  s save  ? help  q quit";
	static const char keys_short[] =
		"hjkl HL:coarse Enter:edit m:mat a:acc v:plot n:notes p:png s:save ?:help q:quit";
	static const char keys_edit[] =
		"Enter apply  Esc cancel  Backspace delete  Ctrl-U clear";
	int y = LINES - 2;
	if (m->editing) {
		const char *prompt = m->edit_key[0] ? m->edit_key : "set KEY=VALUE";
		putf(y, 0, COLS - 1, attr(R_NORMAL), "%s%s %s", prompt,
		     m->edit_key[0] ? " =" : ":", m->edit);
	} else if (m->msg[0]) {
		put_wrapped(y, attr(m->msg_error ? R_ERROR : R_INFO), m->msg);
	}
	/* while typing, an error about the text replaces the key hints */
	if (m->editing && m->msg[0]) {
		put(LINES - 1, 0, COLS - 1, attr(R_ERROR), m->msg);
		return;
	}
	bar(LINES - 1, attr(R_KEYS));
	put(LINES - 1, 0, COLS - 1, attr(R_KEYS),
	    m->editing ? keys_edit
		       : (int)sizeof keys_long - 1 < COLS ? keys_long : keys_short);
}

/* The cursor sits at the end of the text being typed, hidden otherwise. */
static void place_cursor(const struct tui_model *m)
{
	if (!m->editing) {
		curs_set(0);
		return;
	}
	char line[TUI_EDIT_MAX + 80];
	const char *prompt = m->edit_key[0] ? m->edit_key : "set KEY=VALUE";
	snprintf(line, sizeof line, "%s%s %s", prompt, m->edit_key[0] ? " =" : ":",
		 m->edit);
	int x = ncols(line);
	curs_set(1);
	move(LINES - 2, x < COLS - 1 ? x : COLS - 1);
}

/* ---- the screens ---- */

static void draw_small(void)
{
	char msg[96];
	snprintf(msg, sizeof msg, "anvil needs at least %dx%d; this terminal is %dx%d",
		 TUI_MIN_COLS, TUI_MIN_ROWS, COLS, LINES);
	int n = (int)strlen(msg);
	int x = n < COLS ? (COLS - n) / 2 : 0;
	curs_set(0);
	put(LINES / 2, x, COLS - x, attr(R_ERROR), msg);
	put(LINES / 2 + 1, COLS > 14 ? (COLS - 14) / 2 : 0, COLS, attr(R_DIM),
	    "(q to quit)");
}

static void draw_main(const struct tui_model *m, const struct tui_view *v)
{
	draw_header(m, v);
	draw_panel(m);
	draw_table(m, v);
	draw_plot(m, v, PLOT_TOP, LINES - 3);
	draw_status(m);
	place_cursor(m);
}

static void draw_help(const struct tui_model *m, const struct tui_view *v)
{
	(void)m;
	(void)v;
	bar(0, attr(R_TITLE));
	put(0, 1, COLS - 2, attr(R_TITLE), "anvil tui: help");
	for (int i = 1; tui_help_lines[i] && i < LINES; ++i)
		put(i, 2, COLS - 3, attr(R_NORMAL), tui_help_lines[i]);
	curs_set(0);
}

/* The plan of the rows on screen, as `anvil plan` prints it (the same
 * function, the same object the worker ran). */
static void draw_plan(const struct tui_model *m, const struct tui_view *v)
{
	char *text = NULL;
	size_t len = 0;
	(void)v;
	bar(0, attr(R_TITLE));
	put(0, 1, COLS - 2, attr(R_TITLE), "anvil tui: the plan (any key returns)");
	FILE *f = m->have_plan && m->plan_gen == m->gen ? open_memstream(&text, &len) : NULL;
	if (f) {
		anvil_plan_print(f, &m->plan);
		fclose(f);
	}
	if (!text) {
		put(2, 2, COLS - 3, attr(R_NORMAL), "no plan yet: the worker is planning");
		curs_set(0);
		return;
	}
	int row = 1;
	for (char *line = text, *nl; *line && row < LINES; line = nl + 1, ++row) {
		nl = strchr(line, '\n');
		if (!nl)
			nl = line + strlen(line) - 1;
		else
			*nl = '\0';
		put(row, 2, COLS - 3, attr(R_NORMAL), line);
	}
	free(text);
	curs_set(0);
}

/* Lines of s, wrapped at spaces to w columns, from row y down to row
 * bottom; returns the next free row. */
static int put_block(int y, int bottom, int x, int w, attr_t a, const char *s)
{
	while (*s && y <= bottom) {
		int i = line_break(s, w);
		char line[NOTE_LEN];
		snprintf(line, sizeof line, "%.*s", i, s);
		put(y++, x, w, a, line);
		s += i;
		while (*s == ' ')
			s++;
	}
	return y;
}

/* Every note in full: the main screen cuts them at its width. */
static void draw_notes_screen(const struct tui_model *m, const struct tui_view *v)
{
	(void)v;
	bar(0, attr(R_TITLE));
	put(0, 1, COLS - 2, attr(R_TITLE), "anvil tui: the notes (any key returns)");
	struct notes *nt = malloc(sizeof *nt);
	if (!nt)
		return;
	notes_collect(m, nt);
	int y = 2;
	if (!nt->n)
		put(y, 2, COLS - 3, attr(R_NORMAL), "no notes: every row computed is plain");
	for (int i = 0; i < nt->n && y < LINES; ++i)
		y = put_block(y, LINES - 1, 2, COLS - 3, nt->a[i], nt->text[i]) + 1;
	free(nt);
	curs_set(0);
}

static void (*const screens[])(const struct tui_model *, const struct tui_view *) = {
	[TUI_SCREEN_MAIN] = draw_main,
	[TUI_SCREEN_HELP] = draw_help,
	[TUI_SCREEN_PLAN] = draw_plan,
	[TUI_SCREEN_NOTES] = draw_notes_screen,
};

void tui_draw(const struct tui_model *m, const struct tui_view *v)
{
	erase();
	if (COLS < TUI_MIN_COLS || LINES < TUI_MIN_ROWS)
		draw_small();
	else
		screens[m->screen](m, v);
	refresh();
}
