/* tui_plot.c: rasterise polylines into braille or ASCII character cells. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tui_plot.h"

/* Braille dot numbering (Unicode U+2800 block): bit of dot (x, y) in a
 * 2 x 4 cell.  Dots 1-3 and 4-6 are the first three rows of the left and
 * right columns; dots 7 and 8 the bottom row, added later to the standard,
 * hence the odd bits. */
static const unsigned char braille_bit[4][2] = {
	{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};

static const char glyphs[TUI_CANVAS_SERIES] = {'*', 'o', '+', 'x',
					       '#', '@', '%', '&'};

/* Lines further off the canvas than this many canvas sizes are clamped, so
 * a wild value cannot make the rasteriser walk millions of dots. */
#define CLAMP_SIZES 4

char tui_canvas_glyph(int series)
{
	return glyphs[((unsigned)series) % TUI_CANVAS_SERIES];
}

int tui_canvas_init(struct tui_canvas *c, int cols, int rows,
		    enum tui_canvas_mode mode)
{
	memset(c, 0, sizeof *c);
	if (cols < 1 || rows < 1)
		return -1;
	size_t n = (size_t)cols * (size_t)rows;
	c->bits = malloc(n);
	c->series = malloc(n);
	if (!c->bits || !c->series) {
		tui_canvas_free(c);
		return -1;
	}
	c->cols = cols;
	c->rows = rows;
	c->mode = mode;
	c->xdots = mode == TUI_CANVAS_BRAILLE ? 2 : 1;
	c->ydots = mode == TUI_CANVAS_BRAILLE ? 4 : 1;
	tui_canvas_range(c, 0, 1, 0, 1);
	tui_canvas_clear(c);
	return 0;
}

void tui_canvas_free(struct tui_canvas *c)
{
	if (!c)
		return;
	free(c->bits);
	free(c->series);
	c->bits = NULL;
	c->series = NULL;
	c->cols = c->rows = 0;
}

void tui_canvas_clear(struct tui_canvas *c)
{
	size_t n = (size_t)c->cols * (size_t)c->rows;
	memset(c->bits, 0, n);
	memset(c->series, -1, n);
}

static void widen(double *a, double *b)
{
	if (*b > *a)
		return;
	double d = *a != 0 ? 0.5 * fabs(*a) : 0.5;
	*a -= d;
	*b += d;
}

void tui_canvas_range(struct tui_canvas *c, double x0, double x1, double y0,
		      double y1)
{
	widen(&x0, &x1);
	widen(&y0, &y1);
	c->x0 = x0;
	c->x1 = x1;
	c->y0 = y0;
	c->y1 = y1;
}

void tui_canvas_dot(struct tui_canvas *c, int series, int dx, int dy)
{
	if (dx < 0 || dy < 0 || dx >= c->cols * c->xdots || dy >= c->rows * c->ydots)
		return;
	size_t i = (size_t)(dy / c->ydots) * (size_t)c->cols + (size_t)(dx / c->xdots);
	if (c->mode == TUI_CANVAS_BRAILLE)
		c->bits[i] |= braille_bit[dy % 4][dx % 2];
	else
		c->bits[i] = 1;
	c->series[i] = (signed char)(((unsigned)series) % TUI_CANVAS_SERIES);
}

/* Data -> dot coordinates; the range's ends map onto the outermost dots. */
static long to_dot(double v, double lo, double hi, int ndots, int flip)
{
	double f = (v - lo) / (hi - lo);
	if (flip)
		f = 1 - f;
	double d = f * (ndots - 1);
	double lim = (double)CLAMP_SIZES * ndots;
	if (d < -lim)
		d = -lim;
	if (d > lim)
		d = lim;
	return lround(d);
}

/* Bresenham: every dot between the two ends, both included; the dash
 * pattern counts dots along the whole polyline (*k). */
static void line(struct tui_canvas *c, int series, long xa, long ya, long xb,
		 long yb, unsigned pattern, unsigned *k)
{
	long dx = labs(xb - xa), dy = -labs(yb - ya);
	long sx = xa < xb ? 1 : -1, sy = ya < yb ? 1 : -1;
	long e = dx + dy;
	for (;;) {
		if ((pattern >> (*k)++ % 8) & 1u)
			tui_canvas_dot(c, series, (int)xa, (int)ya);
		if (xa == xb && ya == yb)
			break;
		long e2 = 2 * e;
		if (e2 >= dy) {
			e += dy;
			xa += sx;
		}
		if (e2 <= dx) {
			e += dx;
			ya += sy;
		}
	}
}

void tui_canvas_polyline(struct tui_canvas *c, int series, const double *x,
			 const double *y, size_t n)
{
	tui_canvas_polyline_dash(c, series, x, y, n, TUI_DASH_SOLID);
}

int tui_canvas_xdot(const struct tui_canvas *c, double x)
{
	return (int)to_dot(x, c->x0, c->x1, c->cols * c->xdots, 0);
}

int tui_canvas_ydot(const struct tui_canvas *c, double y)
{
	return (int)to_dot(y, c->y0, c->y1, c->rows * c->ydots, 1);
}

void tui_canvas_polyline_dash(struct tui_canvas *c, int series, const double *x,
			      const double *y, size_t n, unsigned pattern)
{
	int nx = c->cols * c->xdots, ny = c->rows * c->ydots;
	long px = 0, py = 0;
	int have = 0;
	unsigned k = 0;
	if (!(pattern & 0xFFu))
		pattern = TUI_DASH_SOLID;
	for (size_t i = 0; i < n; ++i) {
		if (!isfinite(x[i]) || !isfinite(y[i])) {
			have = 0;
			continue;
		}
		long qx = to_dot(x[i], c->x0, c->x1, nx, 0);
		long qy = to_dot(y[i], c->y0, c->y1, ny, 1);
		if (have)
			line(c, series, px, py, qx, qy, pattern, &k);
		else
			tui_canvas_dot(c, series, (int)qx, (int)qy);
		px = qx;
		py = qy;
		have = 1;
	}
}

int tui_canvas_cell(const struct tui_canvas *c, int col, int row, char out[4])
{
	if (col < 0 || row < 0 || col >= c->cols || row >= c->rows) {
		strcpy(out, " ");
		return -1;
	}
	size_t i = (size_t)row * (size_t)c->cols + (size_t)col;
	unsigned b = c->bits[i];
	if (!b) {
		strcpy(out, " ");
		return -1;
	}
	if (c->mode == TUI_CANVAS_BRAILLE) {
		/* UTF-8 of U+2800 + b: 1110 0010, 10 1000 bb, 10 bbbbbb */
		out[0] = (char)0xE2;
		out[1] = (char)(0xA0 | (b >> 6));
		out[2] = (char)(0x80 | (b & 0x3F));
		out[3] = '\0';
	} else {
		out[0] = tui_canvas_glyph(c->series[i]);
		out[1] = '\0';
	}
	return c->series[i];
}

void tui_canvas_row(const struct tui_canvas *c, int row, char *buf, size_t len)
{
	size_t k = 0;
	if (!len)
		return;
	for (int col = 0; col < c->cols; ++col) {
		char cell[4];
		tui_canvas_cell(c, col, row, cell);
		size_t n = strlen(cell);
		if (k + n >= len)
			break;
		memcpy(buf + k, cell, n);
		k += n;
	}
	buf[k] = '\0';
}

/* Linear ticks: the smallest step of 1, 2, 5 x 10^k giving at most max. */
static int linear_ticks(double lo, double hi, int max, double *out)
{
	static const double m[] = {1, 2, 5};
	double span = hi - lo, step = 0;
	for (int e = (int)floor(log10(span / max)) - 1; !(step > 0); e++)
		for (int i = 0; i < 3 && !(step > 0); i++)
			if (floor(span / (m[i] * pow(10, e)) + 1e-9) + 1 <= max)
				step = m[i] * pow(10, e);
	int n = 0;
	for (double t = ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step && n < max; t += step)
		out[n++] = fabs(t) < 1e-12 * step ? 0 : t;
	return n;
}

int tui_ticks(double lo, double hi, int log, int max, double *out)
{
	if (!isfinite(lo) || !isfinite(hi) || !(hi > lo) || max < 1 || (log && !(lo > 0)))
		return 0;
	if (!log)
		return linear_ticks(lo, hi, max, out);
	/* 1, 2, 5 per decade when they fit */
	static const double m[] = {1, 2, 5};
	int n = 0, e0 = (int)floor(log10(lo)), e1 = (int)ceil(log10(hi));
	for (int e = e0; e <= e1 && n <= max; e++)
		for (int i = 0; i < 3 && n <= max; i++) {
			double t = m[i] * pow(10, e);
			if (t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9) && n++ < max)
				out[n - 1] = t;
		}
	if (n <= max)
		return n;
	/* else the decades, every step-th (multiples of step, so 10^0 is one)
	 * across the whole axis: 8 decades of a w axis on 7 rows of ticks
	 * lost their top ones when cut at max */
	int nd = 0;
	for (int e = e0; e <= e1; e++)
		nd += pow(10, e) >= lo * (1 - 1e-9) && pow(10, e) <= hi * (1 + 1e-9);
	int step = (nd + max - 1) / max;
	n = 0;
	for (int e = e0; e <= e1 && n < max; e++) {
		double t = pow(10, e);
		if (((e % step) + step) % step == 0 && t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9))
			out[n++] = t;
	}
	return n;
}
