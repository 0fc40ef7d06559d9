/* plot.h: charts through gnuplot (outside the core).
 *
 * The chart module writes gnuplot scripts, with the data inline, to any
 * FILE *; a pipe to a gnuplot process is one sink among others, so scripts
 * can be tested as text.
 *
 * A chart is built in three steps:
 *   1. the caller runs the models and describes each run (struct plot_run);
 *   2. a builder (plot_chart_history, ..._rf_thickness, ..._rf_lambda,
 *      ..._accuracy) turns the runs into series of points with labels,
 *      line styles and axis units (us, kN, m/s, um);
 *   3. plot_write() prints the gnuplot script; plot_png() pipes it to
 *      gnuplot and writes the PNG atomically.
 *
 * Text from users (titles, font names) never reaches gnuplot as code: it
 * is quoted with plot_quote() and drawn `noenhanced`.  Output file names
 * never reach gnuplot at all: gnuplot writes the PNG to its standard
 * output, which anvil points at a temporary file renamed into place. */
#ifndef ANVIL_UI_PLOT_H
#define ANVIL_UI_PLOT_H

#include <stddef.h>
#include <stdio.h>

#include "result.h"
#include "scene.h"

/* The charts `anvil plot KIND` draws (the paper's figures in brackets). */
enum plot_kind {
	PLOT_FORCE,                 /* P(t), Figs 2-3 */
	PLOT_VELOCITY,              /* v(t), Figs 4-5 */
	PLOT_DEFLECTION,            /* w(t), Figs 6-7 */
	PLOT_RESTITUTION_THICKNESS, /* R_f against h/r0, Fig 8 */
	PLOT_RESTITUTION_LAMBDA,    /* R_f against lambda*, Fig 9 */
	PLOT_ACCURACY,              /* error against wall time per level */
	PLOT_KIND_COUNT
};

/* "force", "restitution-lambda", ...; NULL out of range. */
const char *plot_kind_name(enum plot_kind k);
/* One line describing the chart, for help texts. */
const char *plot_kind_summary(enum plot_kind k);
/* The kind named exactly (case-insensitively) by name, or -1. */
int plot_kind_parse(const char *name);
/* The kind name closest to a misspelt name (for "did you mean"), or NULL
 * when none is close. */
const char *plot_kind_suggest(const char *name);

/* Quote src as a gnuplot single-quoted string, quotes included, into dst
 * (size bytes, always terminated when size > 0).  Inside gnuplot single
 * quotes nothing is interpreted except '' (a literal quote), so every '
 * is doubled; control characters (newline, tab, ESC, DEL, ...) cannot be
 * kept on one script line and become spaces.  Returns the length of the
 * full quoted string, like snprintf: >= size means it was cut short. */
size_t plot_quote(char *dst, size_t size, const char *src);

/* How a series is drawn: an index into a table of gnuplot styles. */
enum plot_mark {
	PLOT_LINE,        /* solid line: the transform models */
	PLOT_DASH,        /* dashed line: Zener */
	PLOT_THIN,        /* thin line: quasi-static Hertz, Zener's ODE */
	PLOT_DOT,         /* dotted line: a limit (the half-space's R_f) */
	PLOT_DIAMONDS,    /* points: Fig 9, V0 = 10 m/s */
	PLOT_CIRCLES,     /* points: Fig 9, V0 = 100 m/s */
	PLOT_LINESPOINTS, /* points joined by lines */
	PLOT_MARK_COUNT
};

#define PLOT_LABEL_MAX 96
#define PLOT_TITLE_MAX 256
#define PLOT_MAX_SERIES 24
#define PLOT_GREY (-1) /* colour index of reference curves */

struct plot_series {
	char label[PLOT_LABEL_MAX]; /* legend text: built by anvil, enhanced */
	enum plot_mark mark;
	int colour;                 /* palette index, or PLOT_GREY */
	size_t n;
	const double *x, *y;        /* n points, SI; borrowed or in own */
	double xs, ys;              /* factors to the axis units (1e6: s -> us) */
	double *own;                /* storage this series owns, or NULL */
};

/* A word written beside a point (the accuracy levels' names). */
#define PLOT_MAX_NOTES 8
struct plot_note {
	double x, y;   /* in axis units */
	char text[24]; /* anvil's own text */
};

struct plot_chart {
	enum plot_kind kind;
	char title[PLOT_TITLE_MAX]; /* default title, drawn noenhanced */
	int nseries, nnotes;
	struct plot_series s[PLOT_MAX_SERIES];
	struct plot_note notes[PLOT_MAX_NOTES];
};

/* Empty chart of a kind; plot_chart_free releases what the series own
 * (the chart struct is the caller's).  free(NULL)-like: safe twice. */
void plot_chart_init(struct plot_chart *c, enum plot_kind kind);
void plot_chart_free(struct plot_chart *c);

/* Title the chart "SCENE TITLE: what it shows" (the scene's title says
 * the rest); an empty or NULL scene_title keeps the chart's own title. */
void plot_chart_scene_title(struct plot_chart *c, const char *scene_title);

/* Add a series of n points.  With copy = 0 x and y are borrowed (they must
 * outlive the chart); with copy = 1 they are copied into storage the
 * series owns.  Returns ANVIL_OK, ANVIL_ENOMEM, or ANVIL_EINVAL when the
 * chart is full. */
int plot_chart_add(struct plot_chart *c, const char *label,
		   enum plot_mark mark, int colour, const double *x,
		   const double *y, size_t n, double xs, double ys, int copy);

/* One model run of one case, as the charts see it. */
struct plot_run {
	const struct anvil_result *r; /* NULL: the model failed (not drawn) */
	enum anvil_model model;
	double h_r0;        /* layer thickness / r0, INFINITY for a half-space */
	double V0;          /* impact velocity, m/s */
	double lambda_star; /* Zener's lambda* of the case, eq (53) */
};

/* A curve computed outside the chart (Zener's R*_f against h/r0 at one
 * velocity, Zener's ODE R_f against lambda*). */
struct plot_curve {
	double V0;          /* the velocity it belongs to, or 0 */
	size_t n;
	const double *x, *y;
};

/* The builders.  Each starts from plot_chart_init, adds one series per
 * run (or group of runs) that has something to draw, and skips runs with
 * r == NULL (failed models).  Histories are borrowed: runs[i].r must
 * outlive the chart; everything else is copied.  They return ANVIL_OK,
 * ANVIL_ENOMEM, or ANVIL_EINVAL when the chart has no series at all. */

/* P(t), v(t) or w(t) (kind PLOT_FORCE, PLOT_VELOCITY, PLOT_DEFLECTION) of
 * every run with a history.  by_thickness = 1 (the paper's figures):
 * one colour per thickness, labels "layer, h = 2 r_0", Zener dashed in
 * its thickness's colour, Hertz thin grey; by_thickness = 0 (one scene):
 * one colour per model, labels the model names. */
int plot_chart_history(struct plot_chart *c, enum plot_kind kind,
		       const struct plot_run *runs, int n, int by_thickness);

/* R_f against h/r0 (Fig 8): per velocity, the layer runs as points joined
 * by lines, the half-space run as a dotted level, and the Zener curve
 * (R*_f of eq. (54)) of the same velocity dashed. */
int plot_chart_rf_thickness(struct plot_chart *c, const struct plot_run *runs,
			    int n, const struct plot_curve *zener, int nzener);

/* R_f against lambda* (Fig 9): Zener's fit exp(-1.7191 lambda*) as a
 * line, Zener's ODE (may be NULL) as a thin line, and the runs as points,
 * diamonds for the first velocity and circles for the second. */
int plot_chart_rf_lambda(struct plot_chart *c, const struct plot_run *runs,
			 int n, const struct plot_curve *ode);

/* Error of P_max, t_s and R_f against wall time, log-log: runs[i] is the
 * run at accuracy level i (i < ANVIL_ACC_COUNT); the error of a level is
 * the relative change to the next finer level that succeeded, the finest
 * uses its own error estimate.  The levels' names label the P_max points. */
int plot_chart_accuracy(struct plot_chart *c,
			const struct plot_run runs[ANVIL_ACC_COUNT]);

/* How the PNG looks. */
struct plot_opts {
	int width, height;   /* pixels */
	const char *font;    /* "NAME,SIZE", or NULL/"" for gnuplot's default */
	const char *title;   /* replaces the chart's title; NULL/"": keep it */
};
void plot_opts_default(struct plot_opts *o); /* 800 x 600, default font */

/* Write the whole gnuplot script for c (terminal pngcairo, else png,
 * writing to standard output; the data inline as datablocks).
 * ANVIL_OK, ANVIL_EINVAL when c has no point to draw, ANVIL_EIO. */
int plot_write(FILE *f, const struct plot_chart *c,
	       const struct plot_opts *o);

/* The gnuplot program: $ANVIL_GNUPLOT if set and not empty, else the one
 * configure found. */
const char *plot_gnuplot_path(void);
/* 0 if the gnuplot program exists and is executable, else 1 after
 * printing one line naming gnuplot (so a chart fails before its work). */
int plot_gnuplot_check(void);

/* Run gnuplot on the script (len bytes) and write the PNG it prints to
 * png_path atomically (nothing is left there if anything fails).
 * Returns 0, or 1 after printing one line naming gnuplot followed by
 * gnuplot's own error output. */
int plot_render(const char *script, size_t len, const char *png_path);

/* Write c's script to script_path (if not NULL; "-" is standard output)
 * and render it to png_path (if not NULL).  0, or 1 with the error
 * printed. */
int plot_png(const struct plot_chart *c, const struct plot_opts *o,
	     const char *png_path, const char *script_path);

/* ---- heat maps (`anvil map`) ------------------------------------------------
 *
 * A quantity over the (r, z) half-plane at one instant, z (depth) drawn
 * downwards, with the wave fronts of that instant drawn over it. */

#define PLOT_FRONT_POINTS 48
#define PLOT_MAX_FRONTS 8

/* The kinds of wave front, each with its own line. */
enum plot_front_kind { PLOT_FRONT_P, PLOT_FRONT_S, PLOT_FRONT_PP, PLOT_FRONT_SS,
		       PLOT_FRONT_R, PLOT_FRONT_KIND_COUNT };

/* A wave front: a polyline in (r, z), metres, with a legend label. */
struct plot_front {
	enum plot_front_kind kind;
	char label[PLOT_LABEL_MAX]; /* anvil's own text, enhanced */
	size_t n;
	double r[PLOT_FRONT_POINTS], z[PLOT_FRONT_POINTS];
};

struct plot_heatmap {
	char title[PLOT_TITLE_MAX];   /* drawn noenhanced */
	char cblabel[PLOT_LABEL_MAX]; /* colour bar, anvil's own text, enhanced */
	size_t nr, nz;
	double r_lo, r_hi, z_lo, z_hi; /* the grid's extent, m */
	const double *v;   /* nz x nr values in the colour bar's unit, row by
			      row in z (borrowed); NaN: not drawn */
	int diverging;     /* signed quantity: colours symmetric about 0 */
	int nfronts;
	struct plot_front fronts[PLOT_MAX_FRONTS];
	char note[PLOT_TITLE_MAX];   /* a line under the map (enhanced), or "" */
};

/* The fronts at time t (s) of waves leaving the loaded patch (a disk of
 * radius r0 on z = 0): P (speed c1) and S (c2), each the envelope of the
 * spheres from the patch (flat under it, a quarter circle around its rim),
 * their reflections from the bottom face z = h (none for h = INFINITY),
 * and the Rayleigh front on the surface at r = r0 + cR t.  Only fronts that
 * cross the map's extent are added; the note says how far c1 t, c2 t and
 * cR t have come. */
void plot_heatmap_fronts(struct plot_heatmap *hm, double t, double r0, double c1,
			 double c2, double cR, double h);

/* The gnuplot script of a heat map (data inline, PNG to standard output,
 * as plot_write).  ANVIL_EINVAL when there is no finite value, ANVIL_EIO. */
int plot_heatmap_write(FILE *f, const struct plot_heatmap *hm,
		       const struct plot_opts *o);

/* Script to script_path (if not NULL, "-" standard output) and PNG to
 * png_path (if not NULL), as plot_png.  0, or 1 with the error printed. */
int plot_heatmap_png(const struct plot_heatmap *hm, const struct plot_opts *o,
		     const char *png_path, const char *script_path);

/* Write the charts of one run (histories of every model in res that has
 * them: force, velocity, deflection) into directory dir as PNG files.
 * The paths written are listed, one per line, into paths (may be NULL).
 * Returns 0, or 1 after printing a one-line error naming gnuplot. */
int plot_run_charts(const char *dir, const struct anvil_scene *sc,
		    const struct anvil_result *res, int nres, char *paths,
		    size_t paths_len);

#endif
