/* tui_draw_impl.h: what the screens (tui_draw.c) and the plot under the
 * table (tui_draw_plot.c) share: the colour roles, the main screen's
 * layout and the text primitives.  Internal to the TUI. */
#ifndef ANVIL_UI_TUI_DRAW_IMPL_H
#define ANVIL_UI_TUI_DRAW_IMPL_H

#include <curses.h>

#include "tui_draw.h"
#include "tui_model.h"

/* The colour roles (tui_draw.c's palette). */
enum role {
	R_NORMAL, R_TITLE, R_HEAD, R_SEL, R_DIM, R_ERROR, R_INFO, R_KEYS,
	R_SERIES0, R_SERIES1, R_SERIES2, R_SERIES3, R_SERIES4, R_COUNT
};

/* The main screen's layout (80 x 24 at least). */
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

/* The attribute of role r: its colour pair, or its monochrome attribute. */
attr_t tui_attr(int r);
/* Columns of UTF-8 text (every character anvil writes is one column). */
int tui_ncols(const char *s);
/* Write s at (y, x), at most w columns; formatted; right-aligned in w. */
void tui_put(int y, int x, int w, attr_t a, const char *s);
void tui_putf(int y, int x, int w, attr_t a, const char *fmt, ...)
	__attribute__((format(printf, 5, 6)));
void tui_put_right(int y, int x, int w, attr_t a, const char *s);

/* The plot of m->plot between rows top and bottom (tui_draw_plot.c). */
void tui_draw_plot(const struct tui_model *m, const struct tui_view *v, int top, int bottom);

#endif
