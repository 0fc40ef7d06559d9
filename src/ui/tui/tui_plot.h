/* tui_plot.h: a character-cell canvas for the TUI's in-terminal plot.
 *
 * Pure: no curses.  Polylines in data coordinates are rasterised into a
 * grid of cells; each cell holds a set of dots and the series that drew
 * there last (for its colour).  Two modes:
 *   braille: each cell is a 2 x 4 dot Unicode braille pattern (U+2800 +
 *            bits), for UTF-8 terminals;
 *   ascii:   each cell is one dot, drawn with the series' glyph, so that
 *            curves stay distinguishable without colour or Unicode.
 * Row 0 is the top; y grows upwards in data space. */
#ifndef ANVIL_UI_TUI_PLOT_H
#define ANVIL_UI_TUI_PLOT_H

#include <stddef.h>

enum tui_canvas_mode { TUI_CANVAS_ASCII, TUI_CANVAS_BRAILLE };

#define TUI_CANVAS_SERIES 8 /* series indices 0 .. 7 */

struct tui_canvas {
	int cols, rows;           /* size in cells */
	enum tui_canvas_mode mode;
	int xdots, ydots;         /* dots per cell: 2 x 4 or 1 x 1 */
	double x0, x1, y0, y1;    /* data range mapped onto the grid */
	unsigned char *bits;      /* cols * rows dot patterns */
	signed char *series;      /* cols * rows: last series drawn, -1 none */
};

/* Allocate a cols x rows canvas (both >= 1), cleared, range [0,1]^2.
 * Returns 0, or -1 when out of memory or the size is bad; free with
 * tui_canvas_free (a failed init leaves nothing to free). */
int tui_canvas_init(struct tui_canvas *c, int cols, int rows,
		    enum tui_canvas_mode mode);
void tui_canvas_free(struct tui_canvas *c); /* NULL or freed: no-op */
void tui_canvas_clear(struct tui_canvas *c);

/* The data range shown; a zero-width range is widened so nothing divides
 * by zero. */
void tui_canvas_range(struct tui_canvas *c, double x0, double x1, double y0,
		      double y1);

/* Set one dot (dot coordinates, (0,0) top left); out of range: ignored. */
void tui_canvas_dot(struct tui_canvas *c, int series, int dx, int dy);
/* Rasterise the polyline (x[i], y[i]), i < n, as series (0 .. 7).
 * Segments with a NaN end are skipped; points outside the range are
 * clipped dot by dot. */
void tui_canvas_polyline(struct tui_canvas *c, int series, const double *x,
			 const double *y, size_t n);

/* Dash patterns, as in the PNG charts: bit k (k = 0 .. 7) says whether
 * the k-th dot of every 8 along a line is drawn. */
#define TUI_DASH_SOLID 0xFFu
#define TUI_DASH_DASHED 0x3Fu /* 6 on, 2 off: Zener's plate */
#define TUI_DASH_DOTTED 0x11u /* 1 on, 3 off: Hertz, a level */
/* tui_canvas_polyline with a dash pattern (0: solid). */
void tui_canvas_polyline_dash(struct tui_canvas *c, int series, const double *x,
			      const double *y, size_t n, unsigned pattern);

/* The dot column (x) or row (y) of a data value, as polylines map them;
 * for axis ticks and marks. */
int tui_canvas_xdot(const struct tui_canvas *c, double x);
int tui_canvas_ydot(const struct tui_canvas *c, double y);

/* Tick values for an axis over [lo, hi], at most max of them, into out:
 * 1, 2 or 5 times a power of ten apart (linear), or at 1, 2, 5 times the
 * powers of ten, thinned to the decades when too many (log = 1, lo > 0).
 * Returns the count (0 when the range is empty or not finite). */
int tui_ticks(double lo, double hi, int log, int max, double *out);

/* The text of cell (col, row) into out (NUL-terminated, at most 3 bytes of
 * UTF-8): a braille character, the series' ASCII glyph, or " " when empty.
 * Returns the series that drew the cell last, -1 when empty. */
int tui_canvas_cell(const struct tui_canvas *c, int col, int row, char out[4]);
/* A whole row as text into buf (len bytes, truncated, NUL-terminated);
 * for tests and dumps. */
void tui_canvas_row(const struct tui_canvas *c, int row, char *buf, size_t len);

/* The ASCII glyph of a series ('*', 'o', '+', 'x', ...). */
char tui_canvas_glyph(int series);

#endif
