/* tui_draw.c: the TUI's screens.  Every function here only reads the model;
 * the colours live in one table. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "commands.h"
#include "common.h"
#include "tui_draw.h"
#include "tui_draw_impl.h"

/* ---- colours: one table, with what to use when there are none ---- */



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

attr_t tui_attr(int r)
{
	if (!use_color)
		return palette[r].mono;
	return (r ? COLOR_PAIR(r) : A_NORMAL) | palette[r].extra;
}

/* ---- text ---- */

/* Columns of UTF-8 text: every character anvil writes is one column wide,
 * so columns are the bytes that are not continuation bytes (10xxxxxx). */
int tui_ncols(const char *s)
{
	int n = 0;
	for (; *s; ++s)
		n += ((unsigned char)*s & 0xC0) != 0x80;
	return n;
}

/* Write s at (y, x), at most w columns. */
void tui_put(int y, int x, int w, attr_t a, const char *s)
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

void tui_putf(int y, int x, int w, attr_t a, const char *fmt, ...)
{
	char buf[1024];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(buf, sizeof buf, fmt, ap);
	va_end(ap);
	tui_put(y, x, w, a, buf);
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



static void put_cut(int y, int x, int w, attr_t a, const char *s, const struct tui_view *v);

static void draw_header(const struct tui_model *m, const struct tui_view *v)
{
	char right[160];
	bar(0, tui_attr(R_TITLE));
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
	tui_put(0, COLS - n - 1, n, tui_attr(R_TITLE), right);
	/* the file name matters more than the title: it goes first; a title
	 * cut short ends in an ellipsis, as the notes do */
	char left[sizeof m->path + sizeof m->sc.title + 32];
	snprintf(left, sizeof left, "anvil tui  %s%s  %s", m->path[0] ? m->path : "(no file)",
		 m->modified ? " [modified]" : "", m->sc.title);
	put_cut(0, 1, COLS - n - 3, tui_attr(R_TITLE), left, v);
}

static void draw_panel(const struct tui_model *m)
{
	tui_put(TOP, 0, PANEL_W, tui_attr(R_HEAD), " Scene");
	for (int f = 0; f < TUI_F_COUNT; ++f) {
		char value[64];
		int y = TOP + 1 + f;
		attr_t a = f == m->sel ? tui_attr(R_SEL) : tui_attr(R_NORMAL);
		tui_model_field_text(m, (enum tui_field)f, value, sizeof value);
		if (f == m->sel) {
			attrset(a);
			mvhline(y, 0, ' ', PANEL_W);
		}
		tui_putf(y, 0, PANEL_W, a, "%c %-9s %s", f == m->sel ? '>' : ' ',
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
		return tui_attr(R_DIM);
	if (row->state == TUI_ROW_DONE && !row->have)
		return tui_attr(R_ERROR);
	return tui_attr(R_NORMAL);
}

/* Right-align s (UTF-8) in w columns. */
void tui_put_right(int y, int x, int w, attr_t a, const char *s)
{
	int cols = tui_ncols(s);
	tui_put(y, x + (cols < w ? w - cols : 0), w, a, s);
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
	char layer[ANVIL_VERDICT_TEXT_MAX], imp[ANVIL_VERDICT_TEXT_MAX];
	int fails = tui_model_verdict(m, layer, imp, sizeof layer);
	nt->n = 0;
	if (fails >= 0) {
		nt->a[nt->n] = tui_attr(fails ? R_ERROR : R_INFO);
		snprintf(nt->text[nt->n++], NOTE_LEN, "%s", layer);
		if (imp[0]) {
			nt->a[nt->n] = tui_attr(R_ERROR);
			snprintf(nt->text[nt->n++], NOTE_LEN, "%s", imp);
		}
	}
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i) {
		const struct tui_row *row = &m->rows[tui_model_order[i]];
		const char *title = tui_model_title(tui_model_order[i]);
		if (row->state != TUI_ROW_DONE)
			continue;
		if (row->status != ANVIL_OK) {
			nt->a[nt->n] = tui_attr(row->have ? R_INFO : R_ERROR);
			snprintf(nt->text[nt->n++], NOTE_LEN, "%s: %s", title,
				 row->msg[0] ? cli_model_reason(tui_model_order[i], row->msg)
					     : anvil_strerror(row->status));
		} else if (row->have && row->res.note[0]) {
			nt->a[nt->n] = tui_attr(R_INFO);
			snprintf(nt->text[nt->n++], NOTE_LEN, "%s: %s", title, row->res.note);
		}
	}
}

/* s in w columns on one line; cut short with an ellipsis when it does
 * not fit (the notes screen has the rest). */
static void put_cut(int y, int x, int w, attr_t a, const char *s, const struct tui_view *v)
{
	const char *e = ellipsis(v);
	int ew = tui_ncols(e);
	if (tui_ncols(s) <= w || w <= ew) {
		tui_put(y, x, w, a, s);
		return;
	}
	tui_put(y, x, w - ew, a, s);
	tui_put(y, x + w - ew, ew, a, e);
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
	tui_put(TOP, TABLE_X, TABLE_LABEL_W, tui_attr(R_HEAD), "Results");
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i)
		tui_put_right(TOP, TABLE_X + TABLE_LABEL_W + i * TABLE_COL_W, TABLE_COL_W - 1,
			  tui_attr(R_HEAD), tui_model_title(tui_model_order[i]));
	for (int q = 0; q < NQUANT; ++q) {
		int y = TOP + 1 + q;
		const char *label = v->utf8 && quantities[q].label_utf8
					    ? quantities[q].label_utf8 : quantities[q].label;
		tui_put(y, TABLE_X, TABLE_LABEL_W, tui_attr(R_NORMAL), label);
		for (int i = 0; i < ANVIL_MODEL_COUNT; ++i) {
			const struct tui_row *row = &m->rows[tui_model_order[i]];
			char cell[32];
			cell_text(row, q, v, cell, sizeof cell);
			tui_put_right(y, TABLE_X + TABLE_LABEL_W + i * TABLE_COL_W,
				  TABLE_COL_W - 1, cell_attr(row), cell);
		}
	}
	draw_notes(m, v, TOP + 1 + NQUANT);
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
		tui_put(bottom - n + 1 + k, 0, w, a, buf);
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
		tui_putf(y, 0, COLS - 1, tui_attr(R_NORMAL), "%s%s %s", prompt,
		     m->edit_key[0] ? " =" : ":", m->edit);
	} else if (m->msg[0]) {
		put_wrapped(y, tui_attr(m->msg_error ? R_ERROR : R_INFO), m->msg);
	}
	/* while typing, an error about the text replaces the key hints */
	if (m->editing && m->msg[0]) {
		tui_put(LINES - 1, 0, COLS - 1, tui_attr(R_ERROR), m->msg);
		return;
	}
	bar(LINES - 1, tui_attr(R_KEYS));
	tui_put(LINES - 1, 0, COLS - 1, tui_attr(R_KEYS),
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
	int x = tui_ncols(line);
	curs_set(1);
	move(LINES - 2, x < COLS - 1 ? x : COLS - 1);
}

/* ---- the screens ---- */

/* The size message, centred; on a terminal narrower than the message its
 * words go on as many lines as they need (a 20x8 terminal must still learn
 * the size it needs). */
static void draw_small(void)
{
	char msg[96], *w[16];
	int nw = 0, len[16];
	snprintf(msg, sizeof msg, "anvil needs at least %dx%d; this terminal is %dx%d",
		 TUI_MIN_COLS, TUI_MIN_ROWS, COLS, LINES);
	for (char *t = strtok(msg, " "); t && nw < 16; t = strtok(NULL, " "))
		len[nw] = (int)strlen(t), w[nw++] = t;
	int lines = 1, cur = 0;
	for (int i = 0; i < nw; i++) {
		if (cur && cur + 1 + len[i] > COLS)
			lines++, cur = 0;
		cur += (cur ? 1 : 0) + len[i];
	}
	int y = LINES / 2 - lines / 2;
	curs_set(0);
	for (int i = 0; i < nw && y < LINES; y++) {
		char line[96] = "";
		int n = 0;
		do {
			n += snprintf(line + n, sizeof line - (size_t)n, "%s%s", n ? " " : "", w[i]);
			i++;
		} while (i < nw && n + 1 + len[i] <= COLS);
		int x = n < COLS ? (COLS - n) / 2 : 0;
		tui_put(y, x, COLS - x, tui_attr(R_ERROR), line);
	}
	if (y < LINES)
		tui_put(y, COLS > 11 ? (COLS - 11) / 2 : 0, COLS, tui_attr(R_DIM), "(q to quit)");
}

static void draw_main(const struct tui_model *m, const struct tui_view *v)
{
	draw_header(m, v);
	draw_panel(m);
	draw_table(m, v);
	tui_draw_plot(m, v, PLOT_TOP, LINES - 3);
	draw_status(m);
	place_cursor(m);
}

static void draw_help(const struct tui_model *m, const struct tui_view *v)
{
	(void)m;
	(void)v;
	bar(0, tui_attr(R_TITLE));
	tui_put(0, 1, COLS - 2, tui_attr(R_TITLE), "anvil tui: help");
	for (int i = 1; tui_help_lines[i] && i < LINES; ++i)
		tui_put(i, 2, COLS - 3, tui_attr(R_NORMAL), tui_help_lines[i]);
	curs_set(0);
}

/* The plan of the rows on screen, as `anvil plan` prints it (the same
 * function, the same object the worker ran). */
static void draw_plan(const struct tui_model *m, const struct tui_view *v)
{
	char *text = NULL;
	size_t len = 0;
	(void)v;
	bar(0, tui_attr(R_TITLE));
	tui_put(0, 1, COLS - 2, tui_attr(R_TITLE), "anvil tui: the plan (any key returns)");
	FILE *f = m->have_plan && m->plan_gen == m->gen ? open_memstream(&text, &len) : NULL;
	if (f) {
		anvil_plan_print(f, &m->plan);
		fclose(f);
	}
	if (!text) {
		tui_put(2, 2, COLS - 3, tui_attr(R_NORMAL), "no plan yet: the worker is planning");
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
		tui_put(row, 2, COLS - 3, tui_attr(R_NORMAL), line);
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
		tui_put(y++, x, w, a, line);
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
	bar(0, tui_attr(R_TITLE));
	tui_put(0, 1, COLS - 2, tui_attr(R_TITLE), "anvil tui: the notes (any key returns)");
	struct notes *nt = malloc(sizeof *nt);
	if (!nt)
		return;
	notes_collect(m, nt);
	int y = 2;
	if (!nt->n)
		tui_put(y, 2, COLS - 3, tui_attr(R_NORMAL), "no notes: every row computed is plain");
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
