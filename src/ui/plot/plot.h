/* plot.h: charts through gnuplot (outside the core).
 *
 * The chart module writes gnuplot scripts, with the data inline, to any
 * FILE *; a pipe to a gnuplot process is one sink among others, so scripts
 * can be tested as text.
 *
 * A chart is built in three steps:
 *   1. the caller runs the models and describes each run (struct plot_run);
 *   2. a builder (plot_chart_history, ..._rf_thickness, ..._rf_lambda,
 *      ..._accuracy) turns the runs into series of points with a style
 *      (below), a key and axis units (µs, kN, m/s, µm);
 *   3. plot_write() prints the gnuplot script; plot_save() pipes it to
 *      gnuplot and writes the PNG, SVG or PDF atomically.
 *
 * One visual language for every chart (PNG and TUI):
 *   colour      = the layer thickness h/r0, by value (plot_h_colour): the
 *                 same thickness has the same colour in every chart; the
 *                 half-space (h = inf) is black (its band grey).  Okabe-Ito colours, safe
 *                 with the common colour blindnesses.
 *   line style  = the model: the transform models solid (the half-space
 *                 a wide band drawn first, so that a thick layer lying on
 *                 it stays visible), Zener's plate dashed, Zener's ODE
 *                 dash-dot, rigid quasi-static Hertz dotted black.
 *   marker      = the velocity: diamonds at the first (10 m/s), circles at
 *                 the second (100 m/s), as in the paper's Fig. 9; filled
 *                 for anvil's values, open for the paper's printed values.
 * Where the thickness is the x axis (R_f against h) the curves are black
 * and only the marked thickness and the paper's points carry its colour.
 * So the charts stay legible in greyscale: style and marker alone tell the
 * models and velocities apart, labels and the key the thicknesses.
 *
 * Text: anvil's own labels use gnuplot's enhanced mode (V_0, R_f, λ^*).
 * Text from users (titles, font names, scene and material names) never
 * reaches gnuplot as code: it is quoted with plot_quote() and drawn
 * `noenhanced`.  Output file names never reach gnuplot at all: gnuplot
 * writes the image to its standard output, which anvil points at a
 * temporary file renamed into place.
 *
 * Errors: every function returns a status and leaves a one-line message in
 * a struct anvil_err; nothing here prints (the callers decide). */
#ifndef ANVIL_UI_PLOT_H
#define ANVIL_UI_PLOT_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

#include "result.h"
#include "scene.h"
#include "status.h"

/* The charts `anvil plot KIND` draws (the paper's figures in brackets). */
enum plot_kind {
	PLOT_FORCE,                 /* P(t), Figs 2-3 */
	PLOT_VELOCITY,              /* v(t), Figs 4-5 */
	PLOT_DEFLECTION,            /* w(t), Figs 6-7 */
	PLOT_RESTITUTION_THICKNESS, /* R_f against h/r0, Fig 8 */
	PLOT_RESTITUTION_LAMBDA,    /* R_f against lambda*, Fig 9 */
	PLOT_ACCURACY,              /* error against wall time per level */
	PLOT_HISTORY,               /* P, v and w stacked, one time axis */
	PLOT_RESTITUTION_VELOCITY,  /* R_f against V0 per thickness (sweeps) */
	PLOT_RESTITUTION_MAP,       /* R_f over V0 x h from a sweep's file */
	PLOT_MODELS,                /* the two contact models: P(t) | R_f(h/r0) */
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

/* The image formats, chosen by the output file's extension. */
enum plot_format { PLOT_PNG, PLOT_SVG, PLOT_PDF, PLOT_FORMAT_COUNT };
/* The format of path by its extension (.png, .svg, .pdf, any case), or -1
 * for another or no extension. */
int plot_format_of(const char *path);

/* Quote src as a gnuplot string expression into dst (size bytes, always
 * terminated when size > 0).  Inside gnuplot single quotes nothing is
 * interpreted except '' (a literal quote), so a lone ' is doubled; but
 * gnuplot misreads '' at the start of a string and two doubled quotes in
 * a row, so a run of quotes, or a quote that would start a string, goes
 * in a double-quoted piece of quotes alone, concatenated:
 * "'".'x' for 'x, 'a'."''".'b' for a''b.  Control characters (newline,
 * tab, ESC, DEL, ...) cannot be kept on one script line and become
 * spaces.  Returns the length of the full expression, like snprintf:
 * >= size means it was cut short. */
size_t plot_quote(char *dst, size_t size, const char *src);

/* How a series is drawn; the colour and marker come with it. */
enum plot_mark {
	PLOT_LINE,        /* solid line: the transform models */
	PLOT_BAND,        /* wide solid line drawn under the others: half-space */
	PLOT_DASH,        /* dashed line: Zener's plate */
	PLOT_DASHDOT,     /* dash-dot line: Zener's ODE */
	PLOT_DOTS,        /* dotted line: quasi-static Hertz, a level */
	PLOT_THIN,        /* thin solid line: a target, a fit */
	PLOT_POINTS,      /* filled markers: anvil's values */
	PLOT_OPEN,        /* open markers: the paper's printed values */
	PLOT_LINESPOINTS, /* filled markers joined by thin lines */
	PLOT_MARK_COUNT
};

/* Markers: the velocity's (diamond, circle) and more for other uses. */
enum plot_point { PLOT_PT_DIAMOND, PLOT_PT_CIRCLE, PLOT_PT_SQUARE,
		  PLOT_PT_TRIANGLE, PLOT_PT_COUNT };

#define PLOT_LABEL_MAX 96
#define PLOT_TITLE_MAX 256
#define PLOT_MAX_SERIES 32
#define PLOT_MAX_KEYS 12
#define PLOT_MAX_NOTES 16
/* Colours besides the palette's indices 0 .. 5. */
#define PLOT_BLACK (-1)
#define PLOT_GREY (-2)

/* The colour of thickness h/r0: 0 blue (h <= 1.4 r0), 1 vermillion
 * (<= 3.2), 2 bluish green (<= 7), 3 reddish purple (finite), PLOT_BLACK
 * for the half-space.  The bins hold the paper's 1, 2, 5, 10 r0. */
int plot_h_colour(double h_r0);
/* The marker of velocity V0: diamond at or below 30 m/s, circle above. */
enum plot_point plot_v_point(double V0);
/* The palette's colour as "#rrggbb" (for the TUI's nearest colour). */
const char *plot_colour_rgb(int colour);

struct plot_series {
	char label[PLOT_LABEL_MAX]; /* key text (anvil's own, enhanced), or
				       "": not in the key */
	enum plot_mark mark;
	int colour;                 /* palette index, PLOT_BLACK, PLOT_GREY */
	enum plot_point point;      /* for the marker styles */
	int panel;                  /* PLOT_HISTORY: 0 P, 1 v, 2 w */
	size_t n;
	const double *x, *y;        /* n points, SI; borrowed or in own */
	double xs, ys;              /* factors to the axis units (1e6: s -> us) */
	double *own;                /* storage this series owns, or NULL */
};

/* A key entry with no data: the key tells colours and styles apart once,
 * not once per curve. */
struct plot_key {
	char label[PLOT_LABEL_MAX]; /* anvil's own text, enhanced */
	enum plot_mark mark;
	int colour;
	enum plot_point point;
};

/* A word written beside a point (levels' names, thicknesses). */
struct plot_note {
	double x, y;   /* in axis units */
	char text[40]; /* anvil's own text, enhanced */
	int colour;
	int panel;
	int below;     /* 1: written under the point, else above it */
	int left;      /* 1: written left of the point, else right of it */
};

struct plot_chart {
	enum plot_kind kind;
	char title[PLOT_TITLE_MAX];    /* anvil's own text, enhanced */
	char subtitle[PLOT_TITLE_MAX]; /* the scene: user text, noenhanced */
	char footnote[PLOT_TITLE_MAX]; /* under the plot, anvil's, enhanced */
	char setup[512];               /* extra gnuplot commands (ranges) */
	const char *tlabel;            /* a history's time axis ("t (ms)"); NULL: the kind's */
	int force_in_n;                /* a history's P in N (peaks below 1 kN), else kN */
	int w_in_mm;                   /* a history's w in mm (beyond 1 mm), else um */
	double force_log[2];           /* a history's P axis logarithmic over [lo, hi]
					  in its unit (plot_force_log); 0: linear */
	double w_log[2];               /* a history's w axis logarithmic over [lo, hi]
					  in its unit (plot_deflection_log); 0: linear */
	int w_abs;                     /* with w_log: a curve changes sign, |w| drawn */
	int w_neg;                     /* linear w with a curve below 0: not cut at 0 */
	int nseries, nkeys, nnotes;
	struct plot_series s[PLOT_MAX_SERIES];
	struct plot_key keys[PLOT_MAX_KEYS];
	struct plot_note notes[PLOT_MAX_NOTES];
};

/* Empty chart of a kind; plot_chart_free releases what the series own
 * (the chart struct is the caller's).  free(NULL)-like: safe twice. */
void plot_chart_init(struct plot_chart *c, enum plot_kind kind);
void plot_chart_free(struct plot_chart *c);

/* Name the scene in the subtitle: "TITLE: copper impactor, m = 12.2 g,
 * r₀ = 4 mm, on a steel layer, h = 8 mm = 2 r₀, V₀ = 10 m/s"; vary_h and
 * vary_v replace h and V0 by what the chart varies. */
void plot_chart_subtitle(struct plot_chart *c, const struct anvil_scene *sc,
			 int vary_h, int vary_v);

/* Add a series of n points.  With copy = 0 x and y are borrowed (they must
 * outlive the chart); with copy = 1 they are copied into storage the
 * series owns.  Returns ANVIL_OK, ANVIL_ENOMEM, or ANVIL_EINVAL when the
 * chart is full.  The point and panel are set afterwards if needed. */
int plot_chart_add(struct plot_chart *c, const char *label,
		   enum plot_mark mark, int colour, const double *x,
		   const double *y, size_t n, double xs, double ys, int copy);
/* A key entry (ignored when the key is full or it is already there). */
void plot_chart_key(struct plot_chart *c, const char *label,
		    enum plot_mark mark, int colour, enum plot_point point);
/* A note at (x, y) in axis units; NULL (nothing added) when the chart's
 * notes are full. */
struct plot_note *plot_chart_note(struct plot_chart *c, double x, double y, int colour,
				  const char *text);

/* One model run of one case, as the charts see it. */
struct plot_run {
	const struct anvil_result *r; /* NULL: the model failed (not drawn) */
	enum anvil_model model;
	double h_r0;        /* layer thickness / r0, INFINITY for a half-space */
	double V0;          /* impact velocity, m/s */
	double lambda_star; /* Zener's lambda* of the case, eq (53) */
};

/* A curve computed outside the chart (Zener's R*_f against h/r0 at one
 * velocity, Zener's ODE R_f against lambda*, the layer's R_f against
 * h/r0). */
struct plot_curve {
	double V0;          /* the velocity it belongs to, or 0 */
	size_t n;
	const double *x, *y;
};

/* The paper's printed values (Tables 2-3): one row per case. */
#define PLOT_PAPER_MAX 16
struct plot_paper {
	int n;
	struct plot_paper_row {
		double V0, h_r0, Rf, lambda_star, Rf_star, Pmax_kN, ts_us;
	} row[PLOT_PAPER_MAX];
};
/* Read tables.tsv (tab separated, '#' comments, a header naming the
 * columns V0 h_r0 Rf lambda_star Rf_star Pmax_kN ts_us).  ANVIL_ENOTFOUND
 * when the file is missing, ANVIL_EPARSE (file, line, column named) for a
 * bad one.  Path NULL: $ANVIL_PAPER_TABLES, else
 * shared/paper/tables.tsv beside the anvil binary's folder's parent
 * (../shared of a worktree). */
int plot_paper_load(struct plot_paper *p, const char *path, struct anvil_err *err);

/* The builders.  Each starts from plot_chart_init, adds one series per
 * run (or group of runs) that has something to draw, and skips runs with
 * r == NULL (failed models).  Histories are borrowed: runs[i].r must
 * outlive the chart; everything else is copied.  They return ANVIL_OK,
 * ANVIL_ENOMEM, or ANVIL_EINVAL when the chart has no series at all. */

/* The two contact models side by side (PLOT_MODELS; effects.contact in
 * man anvil, MODELS): left, P(t) of every run with a history, colour by
 * thickness, the physical contact solid and the paper's dashed (each run's
 * r->contact); right, R_f against h/r0 of the two, rf[0] physical, rf[1]
 * the paper's (black, as on every thickness axis). */
int plot_chart_models(struct plot_chart *c, const struct plot_run *runs, int n,
		      const struct plot_curve rf[2]);

/* The force axis of histories whose peaks (peak[i], N; those not > 0
 * ignored) differ more than PLOT_LOG_FORCE_RATIO times: a linear axis
 * lays the smaller on its zero line (a thin plate's 0.08 kN beside the
 * rigid anvil's 105 kN), so it is logarithmic over range[0] .. range[1]
 * N, a hundredth of the smallest peak (P ~ t^(3/2) leaves the axis at a
 * twentieth of the peak's time) to 1.5 times the largest.  Returns 1 then,
 * else 0 (range untouched).  The charts' and the TUI's rule. */
#define PLOT_LOG_FORCE_RATIO 20.0
int plot_force_log(const double *peak, int n, double range[2]);

/* The deflection axis: plot_force_log's rule over the curves' largest
 * |w| (peak[i], m).  A log axis has no room for w <= 0, and with the
 * physical contact w changes sign (the half-space's is the radiation lag
 * beyond Hertz's dent, -0.47 .. +0.47 um beside a drop weight's plate's
 * 640 mm): when a curve goes below 0 (low[i] < 0, its least w) *abs = 1
 * and the axis is |w|'s, labelled so; else *abs = 0.  Returns 1 for a log
 * axis over range[0] .. range[1] m, else 0 (range and *abs untouched).
 * The charts' and the TUI's rule. */
int plot_deflection_log(const double *peak, const double *low, int n, double range[2],
			int *abs);

/* P(t), v(t) or w(t) (kind PLOT_FORCE, PLOT_VELOCITY, PLOT_DEFLECTION) of
 * every run with a history, or all three stacked (PLOT_HISTORY).  Colour
 * by thickness, style by model (see the top); Hertz's w = 0 is left out
 * and said in the footnote; P on a log axis (force_log, "log scale" in
 * its label) by plot_force_log, w (or |w|) by plot_deflection_log. */
int plot_chart_history(struct plot_chart *c, enum plot_kind kind,
		       const struct plot_run *runs, int n);

/* R_f against h/r0 (Fig 8): per velocity, layer (a curve through the
 * computed runs, each run a marker), the half-space as a dotted level,
 * Zener's R*_f (eq. 54) dashed; the paper's layer values (paper may be
 * NULL; only the rows of the velocities drawn) as open markers;
 * mark_h_r0 (NaN: none) marked by a vertical line in its colour.  r0 (m) labels the second axis in mm. */
int plot_chart_rf_thickness(struct plot_chart *c, const struct plot_run *runs,
			    int n, const struct plot_curve *layer, int nlayer,
			    const struct plot_curve *zener, int nzener,
			    const struct plot_paper *paper, double r0,
			    double mark_h_r0);

/* R_f against lambda* (Fig 9): Zener's fit exp(-1.7191 lambda*) solid,
 * Zener's ODE (may be NULL) dash-dot, the runs as filled markers coloured
 * by h/r0 and labelled with it, the paper's values (paper may be NULL) as
 * open markers.  The lambda* axis is logarithmic when the points span
 * more than a decade; the half-space (lambda* = 0) then sits at its left
 * end, labelled so. */
int plot_chart_rf_lambda(struct plot_chart *c, const struct plot_run *runs,
			 int n, const struct plot_curve *ode,
			 const struct plot_paper *paper);

/* Error of P_max, t_s and R_f against wall time, log-log: runs[i] is the
 * run at accuracy level i (i < ANVIL_ACC_COUNT), timed cold; the error of
 * a level is the relative change to the next finer level that succeeded,
 * the finest uses its own error estimate.  Each level's target is a thin
 * line in the level's colour, its points in the same colour. */
int plot_chart_accuracy(struct plot_chart *c,
			const struct plot_run runs[ANVIL_ACC_COUNT]);

/* R_f against V0, log V0 (PLOT_RESTITUTION_VELOCITY): per thickness (its
 * colour) the layer solid through its runs (filled markers), Zener's plate
 * dashed in the same colour; the half-space a band under them.  Runs of
 * other models are ignored. */
int plot_chart_rf_velocity(struct plot_chart *c, const struct plot_run *runs, int n);

/* The same with one curve per group of runs (group[i] of runs[i], 0 .. ngroups-1;
 * a material pair, at one thickness), labelled label[group] in the key:
 * colour by group (palette order, not by thickness: the thickness is one),
 * the layer solid through filled markers, Zener's plate dashed, the
 * group's half-space a band in a light tint of its colour under them.
 * At most PLOT_MAX_GROUPS groups (ANVIL_EINVAL beyond). */
#define PLOT_MAX_GROUPS 6
int plot_chart_rf_velocity_groups(struct plot_chart *c, const struct plot_run *runs, int n,
				  const int *group, const char *const *label, int ngroups);
/* The subtitle of a chart whose curves differ in their materials: the
 * scene without them, nor its title, which names them, nor the mass when
 * mass_in_key (a ball's follows its material) ("impactor m =
 * 12.2 g, r₀ = 4 mm, on a layer, h = 4 mm = 1 r₀; materials (impactor on
 * layer) in the key"). */
void plot_chart_subtitle_materials(struct plot_chart *c, const struct anvil_scene *sc,
				   int mass_in_key);

struct plot_opts;
/* R_f over V0 x h/r0 (PLOT_RESTITUTION_MAP): a heat map on log axes with
 * contours every 0.1, the colours those of the field maps (viridis).
 * rf holds nh x nv values, row by row in h (NaN: a failed run, a hole). */
struct plot_rf_map {
	char title[PLOT_TITLE_MAX];    /* anvil's own text, enhanced */
	char subtitle[PLOT_TITLE_MAX]; /* user text (noenhanced) */
	size_t nv, nh;
	const double *v0, *h_r0, *rf; /* borrowed, v0 and h_r0 increasing */
};
/* The script (data inline, image to standard output); ANVIL_EINVAL when
 * the grid is under 2 x 2 or has no finite value, ANVIL_EIO. */
int plot_rf_map_write(FILE *f, const struct plot_rf_map *m, const struct plot_opts *o);
/* Script to script_path, image to path, as plot_save. */
int plot_rf_map_save(const struct plot_rf_map *m, const struct plot_opts *o, const char *path,
		     const char *script_path, struct anvil_err *err);

/* How the image looks, and how its making can be stopped. */
struct plot_opts {
	int width, height;   /* pixels (PDF: 100 pixels an inch) */
	const char *font;    /* "NAME,SIZE", or NULL/"" for the default */
	const char *title;   /* replaces the chart's title; NULL/"": keep it */
	enum plot_format format;
	/* While gnuplot runs, *cancel != 0 (a signal handler's flag) kills it,
	 * removes the temporary file and returns ANVIL_ECANCEL.  NULL: none. */
	const volatile sig_atomic_t *cancel;
};
void plot_opts_default(struct plot_opts *o); /* 800 x 600 PNG, default font */

/* Write the whole gnuplot script for c (the terminal of o->format,
 * writing to standard output; the data inline as datablocks).
 * ANVIL_OK, ANVIL_EINVAL when c has no point to draw, ANVIL_EIO. */
int plot_write(FILE *f, const struct plot_chart *c,
	       const struct plot_opts *o);

/* The gnuplot program: $ANVIL_GNUPLOT if set and not empty, else the one
 * configure found. */
const char *plot_gnuplot_path(void);
/* ANVIL_OK if the gnuplot program exists and is executable, else
 * ANVIL_EEXTERN with a message naming it (so a chart fails before its
 * work). */
int plot_gnuplot_check(struct anvil_err *err);

/* Run gnuplot on the script (len bytes) and write the image it prints to
 * path atomically: nothing is left there, nor a temporary file nor a
 * gnuplot process, if anything fails or o->cancel is raised.  Returns
 * ANVIL_OK; ANVIL_EEXTERN (gnuplot missing or failing: its own first
 * words in the message), ANVIL_EIO, ANVIL_ECANCEL, ANVIL_EINVAL (no path). */
int plot_render(const char *script, size_t len, const char *path,
		const struct plot_opts *o, struct anvil_err *err);

/* Write c's script to script_path (if not NULL; "-" is standard output)
 * and render it to path (if not NULL).  Statuses as plot_render. */
int plot_save(const struct plot_chart *c, const struct plot_opts *o,
	      const char *path, const char *script_path, struct anvil_err *err);

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

/* The gnuplot script of a heat map (data inline, image to standard
 * output, as plot_write).  ANVIL_EINVAL when there is no finite value,
 * ANVIL_EIO. */
int plot_heatmap_write(FILE *f, const struct plot_heatmap *hm,
		       const struct plot_opts *o);

/* Script to script_path (if not NULL, "-" standard output) and image to
 * path (if not NULL), as plot_save. */
int plot_heatmap_save(const struct plot_heatmap *hm, const struct plot_opts *o,
		      const char *path, const char *script_path,
		      struct anvil_err *err);

/* Write the charts of one run (histories of every model in res that has
 * them: force, velocity, deflection) into directory dir as PNG files.
 * The paths written are listed, one per line, into paths (may be NULL).
 * Statuses as plot_render, plus ANVIL_EIO when dir cannot be made. */
int plot_run_charts(const char *dir, const struct anvil_scene *sc,
		    const struct anvil_result *res, int nres, char *paths,
		    size_t paths_len, struct anvil_err *err);

/* ---- internal, shared by the plot_*.c files --------------------------- */

/* Everything that differs between kinds (plot.c). */
struct plot_kind_info {
	const char *name, *summary;
	const char *xlabel, *ylabel; /* enhanced */
	const char *setup;           /* gnuplot commands: ranges, scales */
};
const struct plot_kind_info *plot_kind_info(enum plot_kind k);
/* Write s to f as plot_quote makes it. */
void plot_put_quoted(FILE *f, const char *s);
/* The terminal lines for o (plot_write.c). */
void plot_write_terminal(FILE *f, const struct plot_opts *o);
/* Script into a malloc'd buffer through write_fn, then script file and
 * image (plot_gnuplot.c). */
int plot_emit(const char *buf, size_t len, const struct plot_opts *o,
	      const char *path, const char *script_path, struct anvil_err *err);

#endif
