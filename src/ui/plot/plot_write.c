/* plot_write.c: a chart as a gnuplot script, data inline.
 *
 * Every chart has the same frame: the title and the scene's subtitle on
 * top, the plot area at fixed screen margins (so charts of the same size
 * line up, and the stacked panels of `history` share one time axis), the
 * key inside where the data leave a corner free, else below. */
#ifdef HAVE_CONFIG_H
#include "config.h"
#endif

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plot.h"

/* The plot area's left and right edges, and the top (screen fractions):
 * room for the y tick labels and label, and for title and subtitle. */
#define LEFT 0.11
/* The time axis of the histories (as plot.c's TIME_AXIS) */
#define TIME_AXIS_W "set xrange [0:*]\nset autoscale fix\n" \
	"set offsets 0, graph 0.03, graph 0.05, graph 0.05\n"
#define RIGHT 0.965
#define TOP_NOSUB 0.90
#define TOP_SUB 0.865

static const char *const mark_style[PLOT_MARK_COUNT] = {
	[PLOT_LINE] = "lines lw 2 dt 1",
	[PLOT_BAND] = "lines lw 6 dt 1",
	[PLOT_DASH] = "lines lw 2 dt (9,5)",
	[PLOT_DASHDOT] = "lines lw 1.5 dt (12,4,2,4)",
	[PLOT_DOTS] = "lines lw 2.5 dt (1,4)",
	[PLOT_THIN] = "lines lw 1.2 dt 1",
	[PLOT_POINTS] = "points ps 1.6",
	[PLOT_OPEN] = "points ps 2.3 lw 1.5",
	[PLOT_LINESPOINTS] = "linespoints lw 1.2 ps 1.3",
};

/* gnuplot's point types: filled and open. */
static const int pt_filled[PLOT_PT_COUNT] = {13, 7, 5, 9};
static const int pt_open[PLOT_PT_COUNT] = {12, 6, 4, 8};

void plot_opts_default(struct plot_opts *o)
{
	o->width = 800;
	o->height = 600;
	o->font = NULL;
	o->title = NULL;
	o->format = PLOT_PNG;
	o->cancel = NULL;
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

static void terminal_line(FILE *f, const char *term, const char *size,
			  const struct plot_opts *o)
{
	fprintf(f, "%sset terminal %s size %s enhanced", o->format == PLOT_PNG ? "\t" : "",
		term, size);
	if (o->font && o->font[0]) {
		fputs(" font ", f);
		plot_put_quoted(f, o->font);
	}
	fputs(o->format == PLOT_SVG ? " background '#ffffff'\n" : "\n", f);
}

void plot_write_terminal(FILE *f, const struct plot_opts *o)
{
	char px[64], in[64];
	snprintf(px, sizeof px, "%d,%d", o->width, o->height);
	/* pdfcairo measures in inches: 100 pixels an inch. */
	snprintf(in, sizeof in, "%gin,%gin", o->width / 100.0, o->height / 100.0);
	fputs("set encoding utf8\n", f);
	switch (o->format) {
	case PLOT_SVG:
		terminal_line(f, "svg", px, o);
		break;
	case PLOT_PDF:
		terminal_line(f, "pdfcairo", in, o);
		break;
	default:
		/* pngcairo draws antialiased lines; libgd's png is the fallback. */
		fputs("if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n", f);
		terminal_line(f, "pngcairo", px, o);
		fputs("} else {\n", f);
		terminal_line(f, "png", px, o);
		fputs("}\n", f);
	}
}

static const char *style_colour(int colour)
{
	return plot_colour_rgb(colour);
}

/* The band of a reference (the half-space, black) is drawn grey, so a
 * curve of a thick layer lying on it shows inside it (opaque: the svg
 * terminal has no alpha). */
static const char *mark_colour(enum plot_mark mark, int colour)
{
	static char tint[PLOT_MAX_GROUPS][8];
	if (mark != PLOT_BAND || colour == PLOT_GREY)
		return style_colour(colour);
	if (colour == PLOT_BLACK)
		return "#8c8c8c";
	/* A coloured band (a material pair's half-space): its colour mixed
	 * half and half with white, so the pair's curve in full colour shows
	 * on it. */
	unsigned rgb[3];
	char *t = tint[(unsigned)colour % PLOT_MAX_GROUPS];
	if (sscanf(style_colour(colour), "#%2x%2x%2x", &rgb[0], &rgb[1], &rgb[2]) != 3)
		return style_colour(colour);
	snprintf(t, 8, "#%02x%02x%02x", (rgb[0] % 256 + 255) / 2 % 256, (rgb[1] % 256 + 255) / 2 % 256,
		 (rgb[2] % 256 + 255) / 2 % 256);
	return t;
}

/* "with STYLE lc rgb 'C' [pt N]" of a mark. */
static void put_style(FILE *f, enum plot_mark mark, int colour, enum plot_point pt)
{
	fprintf(f, "with %s lc rgb '%s'", mark_style[mark], mark_colour(mark, colour));
	if (mark == PLOT_POINTS || mark == PLOT_LINESPOINTS)
		fprintf(f, " pt %d", pt_filled[(unsigned)pt % PLOT_PT_COUNT]);
	else if (mark == PLOT_OPEN)
		fprintf(f, " pt %d", pt_open[(unsigned)pt % PLOT_PT_COUNT]);
}

static double frame_bottom(const struct plot_chart *c, const struct plot_opts *o);

/* Title (user text noenhanced, anvil's enhanced) and the scene's subtitle,
 * as labels at fixed screen heights. */
static void write_titles(FILE *f, const struct plot_chart *c, const struct plot_opts *o)
{
	int user = o->title && o->title[0];
	fputs("set label 1001 ", f);
	plot_put_quoted(f, user ? o->title : c->title);
	fprintf(f, " at screen 0.5, screen 0.965 center font ',13'%s\n",
		user ? " noenhanced" : "");
	if (c->subtitle[0]) {
		/* One line across the image: cairo's sans takes up to 0.70 pixel
		 * per point of size per character. */
		size_t chars = 0;
		for (const char *p = c->subtitle; *p; p++)
			chars += ((unsigned char)*p & 0xc0) != 0x80; /* UTF-8 lead bytes */
		double pt = fmax(6, fmin(10, 0.97 * o->width / (0.70 * (double)chars)));
		fputs("set label 1002 ", f);
		plot_put_quoted(f, c->subtitle);
		fprintf(f, " at screen 0.5, screen 0.92 center font ',%.1f' noenhanced\n", pt);
	}
	if (c->footnote[0]) {
		/* At the bottom edge, under a key below. */
		fputs("set label 1003 ", f);
		plot_put_quoted(f, c->footnote);
		fputs(" at screen 0.99, screen 0.01 right font ',9' tc rgb '#555555'\n", f);
	}
}

/* Where the key goes: a free corner, else below the plot (NULL). */
static const char *key_inside(enum plot_kind k)
{
	switch (k) {
	case PLOT_RESTITUTION_THICKNESS:
		return "inside bottom right vertical Left reverse width 1";
	case PLOT_RESTITUTION_LAMBDA:
		return "inside bottom left vertical Left reverse width 1";
	default:
		return NULL;
	}
}

/* The bottom of the plot area (screen fraction): the x tick labels and
 * label (about 64 pixels), and a key below of 2 columns at least, 20
 * pixels a row at gnuplot's font size 10. */
static double frame_bottom(const struct plot_chart *c, const struct plot_opts *o)
{
	int rows = key_inside(c->kind) || c->kind == PLOT_MODELS ? 0 : (c->nkeys + 1) / 2;
	double px = 64 + 20.0 * rows + (rows ? 10 : 0) + (c->footnote[0] ? 16 : 0);
	return fmin(0.45, px / (o->height > 0 ? o->height : 600));
}

static void write_frame(FILE *f, const struct plot_chart *c, const struct plot_opts *o)
{
	const char *in = key_inside(c->kind);
	fprintf(f, "set lmargin at screen %g\nset rmargin at screen %g\n"
		"set tmargin at screen %g\nset bmargin at screen %.4g\n", LEFT, RIGHT,
		c->subtitle[0] ? TOP_SUB : TOP_NOSUB, frame_bottom(c, o));
	fputs("set grid lc rgb '#dddddd'\nset tics out nomirror\nset border 3\n", f);
	/* Below: anchored at the bottom edge; narrower columns than gnuplot's
	 * estimate, as cairo's text is. */
	fputs("set key ", f);
	if (in)
		fputs(in, f);
	else
		fprintf(f, "at screen 0.5, screen %.4g center bottom horizontal maxcols 5 "
			"width -3 Left reverse", c->footnote[0] ? 0.008 + 16.0 /
			(o->height > 0 ? o->height : 600) : 0.008);
	fputs(" box lc rgb '#bbbbbb' lw 1 opaque samplen 3.5 spacing 1.1 font ',10'\n", f);
}

static void write_notes(FILE *f, const struct plot_chart *c, int panel)
{
	for (int i = 0; i < c->nnotes; i++) {
		const struct plot_note *n = &c->notes[i];
		if (n->panel != panel || !isfinite(n->x) || !isfinite(n->y))
			continue;
		fprintf(f, "set label %d ", i + 1);
		plot_put_quoted(f, n->text);
		fprintf(f, " at %.6g,%.6g %s offset char %s,%s font ',9' tc rgb '%s' front\n",
			n->x, n->y, n->left ? "right" : "left", n->left ? "-0.7" : "0.7",
			n->below ? "-0.9" : "0.8", style_colour(n->colour));
	}
}

static void write_block(FILE *f, int id, const struct plot_series *s)
{
	fprintf(f, "$d%d << EOD\n", id);
	for (size_t i = 0; i < s->n; i++)
		if (finite_point(s, i))
			fprintf(f, "%.6g %.6g\n", s->x[i] * s->xs, s->y[i] * s->ys);
	fputs("EOD\n", f);
}

/* The plot command of one panel (-1: every series); the key entries go
 * with the panel that has the key. */
static void write_plot(FILE *f, const struct plot_chart *c, int panel, int keys)
{
	const char *sep = "plot ";
	for (int i = 0; i < c->nseries; i++) {
		const struct plot_series *s = &c->s[i];
		if (!series_drawn(s) || (panel >= 0 && s->panel != panel))
			continue;
		fprintf(f, "%s$d%d using 1:2 ", sep, i + 1);
		put_style(f, s->mark, s->colour, s->point);
		if (s->label[0]) {
			fputs(" title ", f);
			plot_put_quoted(f, s->label);
		} else
			fputs(" notitle", f);
		sep = ", \\\n     ";
	}
	for (int i = 0; keys && i < c->nkeys; i++) {
		const struct plot_key *k = &c->keys[i];
		fprintf(f, "%skeyentry ", sep);
		put_style(f, k->mark, k->colour, k->point);
		fputs(" title ", f);
		plot_put_quoted(f, k->label);
		sep = ", \\\n     ";
	}
	fputc('\n', f);
}

/* A log y axis over range (set when range[1] > 0), after the panel's own
 * setup; powers of ten as 10^n: "0.001" pushed the axis label off the
 * image. */
static void write_log_y(FILE *f, const double range[2])
{
	if (range[1] > 0)
		fprintf(f, "set logscale y\nset yrange [%.6g:%.6g]\nset format y '10^{%%L}'\n",
			range[0], range[1]);
}

/* A history's log P axis (plot_force_log). */
static void write_force_log(FILE *f, const struct plot_chart *c)
{
	write_log_y(f, c->force_log);
}

/* A history's w axis (plot_deflection_log): log as P's; linear with a
 * curve below 0, not cut at 0. */
static void write_deflection_axis(FILE *f, const struct plot_chart *c)
{
	if (c->w_log[1] > 0)
		write_log_y(f, c->w_log);
	else if (c->w_neg)
		fputs("set yrange [*:*]\n", f);
}

/* "w (µm)", "|w| (mm), log scale": the w axis' name, unit and scale. */
static void deflection_label(char *buf, size_t n, const struct plot_chart *c, int chart)
{
	int lg = c->w_log[1] > 0;
	snprintf(buf, n, "%s%s (%s)%s", chart ? "deflection " : "", lg && c->w_abs ? "|w|" : "w",
		 c->w_in_mm ? "mm" : "µm",
		 lg ? (chart ? ", log scale" : ", log") : chart ? ", + into the layer" : "");
}

static void write_axes(FILE *f, const struct plot_chart *c, const struct plot_kind_info *k)
{
	char ylabel[PLOT_LABEL_MAX];
	fputs("set xlabel ", f);
	plot_put_quoted(f, c->tlabel ? c->tlabel : k->xlabel);
	fputs("\nset ylabel ", f);
	snprintf(ylabel, sizeof ylabel, "%s", k->ylabel);
	if (c->kind == PLOT_FORCE)
		snprintf(ylabel, sizeof ylabel, "contact force P (%s)%s", c->force_in_n ? "N" : "kN",
			 c->force_log[1] > 0 ? ", log scale" : "");
	else if (c->kind == PLOT_DEFLECTION)
		deflection_label(ylabel, sizeof ylabel, c, 1);
	plot_put_quoted(f, ylabel);
	fputc('\n', f);
}

/* P, v and w stacked: one time axis, tick labels on the bottom panel. */
static void write_history(FILE *f, const struct plot_chart *c, double top, double bottom)
{
	static const enum plot_kind panels[3] = {PLOT_FORCE, PLOT_VELOCITY, PLOT_DEFLECTION};
	char wlabel[PLOT_LABEL_MAX];
	deflection_label(wlabel, sizeof wlabel, c, 0);
	const char *const ylabels[3] = {c->force_log[1] > 0 ? (c->force_in_n ? "P (N), log" : "P (kN), log")
							    : c->force_in_n ? "P (N)" : "P (kN)",
					"v (m/s)", wlabel};
	const double gap = 0.02, h = (top - bottom - 2 * gap) / 3;
	fputs("set multiplot\n", f);
	for (int p = 0; p < 3; p++) {
		double t = top - p * (h + gap);
		fprintf(f, "# panel %d: %s\nset tmargin at screen %g\nset bmargin at screen %g\n",
			p + 1, plot_kind_name(panels[p]), t, t - h);
		/* The titles are drawn with the first panel only. */
		fprintf(f, "%sset ylabel '%s'\n%s%s", p ? "unset label\n" : "", ylabels[p],
			plot_kind_info(panels[p])->setup, c->setup);
		if (p == 0)
			write_force_log(f, c);
		else if (p == 2)
			write_deflection_axis(f, c);
		if (p < 2)
			fputs("set format x ''\nunset xlabel\nset key off\n", f);
		else
			fprintf(f, "set format x '%%g'\nset xlabel '%s'\nset key on\n",
				c->tlabel ? c->tlabel : "t (µs)");
		write_notes(f, c, p);
		write_plot(f, c, p, p == 2);
		if (p == 0 && c->force_log[1] > 0)
			fputs("unset logscale y\nset format y '%g'\n", f);
		fputs("unset offsets\nunset xzeroaxis\nset autoscale y\n", f);
	}
	fputs("unset multiplot\n", f);
}

/* contactB: the two contact models side by side, P(t) left, R_f(h/r0)
 * right (plot_chart_models). */
static void write_models(FILE *f, const struct plot_chart *c, double top, double bottom)
{
	const double mid = 0.5 * (LEFT + RIGHT), gap = 0.045;
	fputs("set multiplot\n", f);
	fprintf(f, "# panel 1: P(t)\nset lmargin at screen %g\nset rmargin at screen %g\n"
		"set tmargin at screen %g\nset bmargin at screen %g\n", LEFT, mid - gap, top, bottom);
	fprintf(f, "set xlabel '%s'\n", c->tlabel ? c->tlabel : "t (µs)");
	fputs("set ylabel 'contact force P (kN)'\n" TIME_AXIS_W
	      "set yrange [0:*]\nset key off\n", f);
	write_plot(f, c, 0, 0);
	fprintf(f, "# panel 2: R_f against h/r0\nunset label\nunset offsets\nset autoscale\n"
		"set lmargin at screen %g\nset rmargin at screen %g\n", mid + gap, RIGHT);
	fputs("set xlabel 'layer thickness h / r_0'\nset ylabel 'coefficient of restitution R_f'\n"
	      "set logscale x\nset xrange [0.4:25]\nset xtics (0.5, 1, 2, 5, 10, 20)\n"
	      "set yrange [0:1.05]\n"
	      "set key inside right bottom vertical Left reverse width 1\n", f);
	write_plot(f, c, 1, 1);
	fputs("unset multiplot\n", f);
}

int plot_write(FILE *f, const struct plot_chart *c, const struct plot_opts *o)
{
	const struct plot_kind_info *k = plot_kind_info(c->kind);
	int any = 0;
	for (int i = 0; i < c->nseries; i++)
		any |= series_drawn(&c->s[i]);
	if (!any || !k)
		return ANVIL_EINVAL;
	fprintf(f, "# anvil chart '%s': a gnuplot script with its data inline.\n"
		"# Render with: gnuplot THIS_FILE > %s.png\n", k->name, k->name);
	plot_write_terminal(f, o);
	/* No `set output`: the image goes to standard output, so no file name
	 * ever passes through gnuplot. */
	write_titles(f, c, o);
	write_frame(f, c, o);
	for (int i = 0; i < c->nseries; i++)
		if (series_drawn(&c->s[i]))
			write_block(f, i + 1, &c->s[i]);
	if (c->kind == PLOT_HISTORY) {
		write_history(f, c, c->subtitle[0] ? TOP_SUB : TOP_NOSUB, frame_bottom(c, o));
	} else if (c->kind == PLOT_MODELS) {
		write_models(f, c, c->subtitle[0] ? TOP_SUB : TOP_NOSUB, frame_bottom(c, o));
	} else {
		write_axes(f, c, k);
		fputs(k->setup, f);
		fputs(c->setup, f);
		if (c->kind == PLOT_FORCE)
			write_force_log(f, c);
		else if (c->kind == PLOT_DEFLECTION)
			write_deflection_axis(f, c);
		write_notes(f, c, 0);
		write_plot(f, c, -1, 1);
	}
	return fflush(f) == 0 && !ferror(f) ? ANVIL_OK : ANVIL_EIO;
}
