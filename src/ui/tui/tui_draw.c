/* tui_draw.c: the TUI's screens.  Every function here only reads the model;
 * the colours live in one table. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "tui_draw.h"
#include "tui_plot.h"

/* ---- colours: one table, with what to use when there are none ---- */

enum role {
	R_NORMAL, R_TITLE, R_HEAD, R_SEL, R_DIM, R_ERROR, R_INFO, R_KEYS,
	R_SERIES0, R_SERIES1, R_SERIES2, R_SERIES3, R_COUNT
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
	/* curves: without colour, attributes keep them apart */
	[R_SERIES0] = {COLOR_RED, -1, A_BOLD, A_BOLD},
	[R_SERIES1] = {COLOR_GREEN, -1, A_BOLD, A_NORMAL},
	[R_SERIES2] = {COLOR_YELLOW, -1, A_BOLD, A_UNDERLINE},
	[R_SERIES3] = {COLOR_MAGENTA, -1, A_BOLD, A_DIM},
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
			snprintf(buf, n, "%s%.4g", row->status == ANVIL_ETOL ? "~" : "", x);
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

static void draw_notes(const struct tui_model *m, int y)
{
	int w = COLS - TABLE_X, used = 0;
	for (int i = 0; i < ANVIL_MODEL_COUNT && used < NOTES_ROWS; ++i) {
		const struct tui_row *row = &m->rows[tui_model_order[i]];
		const char *title = tui_model_title(tui_model_order[i]);
		if (row->state != TUI_ROW_DONE)
			continue;
		if (row->status != ANVIL_OK)
			putf(y + used++, TABLE_X, w, attr(row->have ? R_INFO : R_ERROR),
			     "%s: %s", title, row->msg[0] ? row->msg : anvil_strerror(row->status));
		else if (row->have && row->res.note[0])
			putf(y + used++, TABLE_X, w, attr(R_INFO), "%s: %s", title,
			     row->res.note);
	}
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
	draw_notes(m, TOP + 1 + NQUANT);
}

/* ---- the plot ---- */

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

/* The range over every curve shown, always including y = 0. */
static int plot_range(const struct tui_model *m, double r[4])
{
	int any = 0;
	r[0] = 0;
	r[1] = r[2] = r[3] = 0;
	for (int k = 0; k < ANVIL_MODEL_COUNT; ++k) {
		const struct tui_row *row = &m->rows[k];
		if (!plottable(row))
			continue;
		const struct anvil_history *h = &row->res.hist;
		const double *y = quantity_data(h, m->quantity);
		for (size_t i = 0; i < h->n; ++i) {
			if (!isfinite(h->t[i]) || !isfinite(y[i]))
				continue;
			r[1] = fmax(r[1], h->t[i]);
			r[2] = fmin(r[2], y[i]);
			r[3] = fmax(r[3], y[i]);
		}
		any = 1;
	}
	return any;
}

static void draw_legend(const struct tui_model *m, const struct tui_view *v, int y)
{
	char head[64];
	snprintf(head, sizeof head, "%s [%s] vs t [%s]", tui_quantity_name(m->quantity),
		 v->utf8 && m->quantity == TUI_Q_DEFLECTION ? "\xc2\xb5m"
							    : tui_quantity_unit(m->quantity),
		 v->utf8 ? "\xc2\xb5s" : "us");
	put(y, 1, COLS - 2, attr(R_HEAD), head);
	int x = 1 + ncols(head) + 2;
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i) {
		const struct tui_row *row = &m->rows[tui_model_order[i]];
		const char *title = tui_model_title(tui_model_order[i]);
		char sample[4] = {tui_canvas_glyph(i), '\0'};
		if (!plottable(row))
			continue;
		put(y, x + 1, 1, attr(R_SERIES0 + i), v->utf8 ? "\xe2\x96\xa0" : sample);
		put(y, x + 3, COLS - x - 3, attr(R_NORMAL), title);
		x += 4 + (int)strlen(title);
	}
}

static void draw_axes(const struct tui_model *m, const struct tui_view *v,
		      const double r[4], int top, int bottom)
{
	double ys = quantity_scale(m->quantity);
	putf(top, 0, PLOT_LEFT - 1, attr(R_DIM), "%8.3g", r[3] * ys);
	putf(bottom, 0, PLOT_LEFT - 1, attr(R_DIM), "%8.3g", r[2] * ys);
	put(bottom + 1, PLOT_LEFT, 1, attr(R_DIM), "0");
	char t[32];
	snprintf(t, sizeof t, "%.4g %s", r[1] * 1e6, v->utf8 ? "\xc2\xb5s" : "us");
	put_right(bottom + 1, PLOT_LEFT, COLS - PLOT_LEFT - 1, attr(R_DIM), t);
}

static void draw_canvas(const struct tui_canvas *c, int top)
{
	for (int row = 0; row < c->rows; ++row)
		for (int col = 0; col < c->cols; ++col) {
			char cell[4];
			int s = tui_canvas_cell(c, col, row, cell);
			if (s >= 0)
				put(top + row, PLOT_LEFT + col, 1, attr(R_SERIES0 + s % 4), cell);
		}
}

static void draw_plot(const struct tui_model *m, const struct tui_view *v,
		      int top, int bottom)
{
	struct tui_canvas c;
	double r[4];
	int rows = bottom - top - 1, cols = COLS - PLOT_LEFT - 1;
	draw_legend(m, v, top);
	if (!plot_range(m, r)) {
		putf((top + bottom) / 2, PLOT_LEFT, cols, attr(R_DIM), "%s",
		     tui_model_busy(m) ? "computing" : "no histories to plot");
		return;
	}
	if (rows < 1 || tui_canvas_init(&c, cols, rows, v->utf8 ? TUI_CANVAS_BRAILLE
								: TUI_CANVAS_ASCII))
		return;
	tui_canvas_range(&c, r[0], r[1], r[2], r[3]);
	/* backwards, so the first model of the legend ends up on top */
	for (int i = ANVIL_MODEL_COUNT - 1; i >= 0; --i) {
		const struct tui_row *row = &m->rows[tui_model_order[i]];
		if (plottable(row))
			tui_canvas_polyline(&c, i, row->res.hist.t,
					    quantity_data(&row->res.hist, m->quantity),
					    row->res.hist.n);
	}
	draw_canvas(&c, top + 1);
	draw_axes(m, v, r, top + 1, top + rows);
	tui_canvas_free(&c);
}

/* ---- the bottom lines ---- */

/* A message too long for one line, wrapped at spaces onto the lines above
 * bottom (over the foot of the plot), at most STATUS_MAX_LINES. */
#define STATUS_MAX_LINES 4
static void put_wrapped(int bottom, attr_t a, const char *msg)
{
	const char *line[STATUS_MAX_LINES];
	int len[STATUS_MAX_LINES], n = 0, w = COLS - 1;
	const char *p = msg;
	while (*p && n < STATUS_MAX_LINES) {
		int cols = 0, cut = -1, i = 0;
		for (; p[i] && cols < w; i++) {
			cols += ((unsigned char)p[i] & 0xC0) != 0x80;
			if (p[i] == ' ')
				cut = i;
		}
		while (p[i] && ((unsigned char)p[i] & 0xC0) == 0x80)
			i++; /* never split a character */
		if (p[i] && cut > 0)
			i = cut; /* break at the last space */
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
		"a accuracy  v plot  p png  s save  ? help  q quit";
	static const char keys_short[] =
		"hjkl/arrows HL:coarse Enter:edit m:mat a:acc v:plot p:png s:save ?:help q:quit";
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

static void (*const screens[])(const struct tui_model *, const struct tui_view *) = {
	[TUI_SCREEN_MAIN] = draw_main,
	[TUI_SCREEN_HELP] = draw_help,
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
