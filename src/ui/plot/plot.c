/* plot.c: chart kinds, quoting, the chart itself, the visual language,
 * the scene subtitle, the history builder and the paper's table.
 * See plot.h for the contract. */
#ifdef HAVE_CONFIG_H
#include "config.h"
#endif

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "plot.h"

/* ---------------------------------------------------------------- kinds */

/* The time axis of the histories: a little room right of the last
 * sample, so no curve ends on the frame. */
#define TIME_AXIS "set xrange [0:*]\nset autoscale fix\n" \
	"set offsets 0, graph 0.03, graph 0.05, graph 0.05\n"

static const struct plot_kind_info kinds[PLOT_KIND_COUNT] = {
	[PLOT_FORCE] = {"force", "contact force P(t) for several thicknesses (Figs 2-3)",
		"t (µs)", "contact force P (kN)", TIME_AXIS "set yrange [0:*]\n"},
	[PLOT_VELOCITY] = {"velocity", "impactor velocity v(t) (Figs 4-5)",
		"t (µs)", "impactor velocity v (m/s), + towards the layer",
		TIME_AXIS "set xzeroaxis lt -1 lw 1\n"},
	[PLOT_DEFLECTION] = {"deflection", "layer deflection w(t) under the impactor (Figs 6-7)",
		"t (µs)", "deflection w (µm), + into the layer", TIME_AXIS "set yrange [0:*]\n"},
	[PLOT_RESTITUTION_THICKNESS] = {"restitution-thickness",
		"restitution R_f against h/r0, V0 = 10 and 100 m/s (Fig 8)",
		"layer thickness h / r_0", "coefficient of restitution R_f",
		"set logscale x\nset xrange [0.5:20]\nset xtics (0.5, 1, 2, 5, 10, 20)\n"
		"set yrange [0:1.05]\n"},
	[PLOT_RESTITUTION_LAMBDA] = {"restitution-lambda",
		"restitution R_f against Zener's lambda* (Fig 9)",
		"Zener's inelasticity parameter λ^*", "coefficient of restitution R_f",
		"set yrange [0:1.08]\n"},
	[PLOT_ACCURACY] = {"accuracy",
		"error of P_max, t_s, R_f against cold wall time per accuracy level",
		"wall time, cold cache (s)", "relative error",
		"set logscale xy\nset format y '10^{%L}'\nset format x '%g'\n"},
	[PLOT_HISTORY] = {"history", "P(t), v(t) and w(t) stacked on one time axis",
		"t (µs)", "", ""},
	[PLOT_RESTITUTION_VELOCITY] = {"restitution-velocity",
		"restitution R_f against V0, a curve per thickness or material pair, Zener, half-space",
		"impact velocity V_0 (m/s)", "coefficient of restitution R_f",
		"set logscale x\nset yrange [0:1.05]\nset xtics (0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100)\n"},
	[PLOT_RESTITUTION_MAP] = {"restitution-map",
		"R_f over V0 x h as a heat map with contours, from FILE (anvil sweep's rows)",
		"impact velocity V_0 (m/s)", "layer thickness h / r_0", ""},
	[PLOT_MODELS] = {"models", "the physical and the paper's contact: P(t) and R_f against h/r0",
		"t (µs)", "", ""},
};

const struct plot_kind_info *plot_kind_info(enum plot_kind k)
{
	return (unsigned)k < PLOT_KIND_COUNT ? &kinds[k] : NULL;
}

const char *plot_kind_name(enum plot_kind k)
{
	return (unsigned)k < PLOT_KIND_COUNT ? kinds[k].name : NULL;
}

const char *plot_kind_summary(enum plot_kind k)
{
	return (unsigned)k < PLOT_KIND_COUNT ? kinds[k].summary : NULL;
}

int plot_kind_parse(const char *name)
{
	for (int k = 0; name && k < PLOT_KIND_COUNT; k++)
		if (strcasecmp(name, kinds[k].name) == 0)
			return k;
	return -1;
}

/* Levenshtein distance of two short strings (longer ones count as far). */
static size_t edit_distance(const char *a, const char *b)
{
	size_t la = strlen(a), lb = strlen(b), row[64];
	if (la >= 64 || lb >= 64)
		return SIZE_MAX;
	for (size_t j = 0; j <= lb; j++)
		row[j] = j;
	for (size_t i = 1; i <= la; i++) {
		size_t diag = row[0];
		row[0] = i;
		for (size_t j = 1; j <= lb; j++) {
			size_t up = row[j];
			size_t sub = diag + (a[i - 1] != b[j - 1]);
			size_t del = (up < row[j - 1] ? up : row[j - 1]) + 1;
			row[j] = sub < del ? sub : del;
			diag = up;
		}
	}
	return row[lb];
}

const char *plot_kind_suggest(const char *name)
{
	const char *best = NULL;
	size_t bestd = SIZE_MAX, n = name ? strlen(name) : 0;
	if (n == 0)
		return NULL;
	/* A prefix ("restitution", "acc") is the likeliest intent. */
	for (int k = 0; k < PLOT_KIND_COUNT; k++)
		if (strncasecmp(name, kinds[k].name, n) == 0)
			return kinds[k].name;
	for (int k = 0; k < PLOT_KIND_COUNT; k++) {
		size_t d = edit_distance(name, kinds[k].name);
		if (d < bestd) {
			bestd = d;
			best = kinds[k].name;
		}
	}
	return bestd <= 3 && bestd < n ? best : NULL;
}

int plot_format_of(const char *path)
{
	static const char *const ext[PLOT_FORMAT_COUNT] = {".png", ".svg", ".pdf"};
	size_t n = path ? strlen(path) : 0;
	for (int f = 0; f < PLOT_FORMAT_COUNT; f++)
		if (n > 4 && strcasecmp(path + n - 4, ext[f]) == 0)
			return f;
	return -1;
}

/* -------------------------------------------------------------- quoting */

size_t plot_quote(char *dst, size_t size, const char *src)
{
	const unsigned char *p = (const unsigned char *)(src ? src : "");
	size_t n = 0;
	int open = 0; /* inside a '...' piece with text in it */
#define PUT(ch) do { if (n + 1 < size) dst[n] = (ch); n++; } while (0)
	if (!*p) {
		PUT('\'');
		PUT('\'');
	}
	while (*p) {
		size_t run = strspn((const char *)p, "'");
		if (*p == '\'' && (run > 1 || !open)) {
			/* gnuplot misreads '' at the start of '...' and '''' (two
			 * doubled quotes) inside it: a run of quotes, or one that
			 * would open a piece, goes in "..." alone (quotes only:
			 * nothing there is interpreted). */
			if (open)
				PUT('\'');
			if (n > 0)
				PUT('.');
			PUT('"');
			for (; *p == '\''; p++)
				PUT('\'');
			PUT('"');
			open = 0;
			continue;
		}
		if (!open) {
			if (n > 0)
				PUT('.');
			PUT('\'');
			open = 1;
		}
		if (*p == '\'')
			PUT('\''); /* a lone quote inside: doubled */
		/* A control character would end or corrupt the script line. */
		PUT(*p < 0x20 || *p == 0x7f ? ' ' : (char)*p);
		p++;
	}
	if (open)
		PUT('\'');
#undef PUT
	if (size > 0)
		dst[n < size ? n : size - 1] = '\0';
	return n;
}

void plot_put_quoted(FILE *f, const char *s)
{
	char small[256];
	size_t n = plot_quote(small, sizeof small, s);
	if (n < sizeof small) {
		fputs(small, f);
		return;
	}
	char *big = malloc(n + 1);
	if (!big) {
		/* Still valid gnuplot; the write error shows on the caller's ferror. */
		fputs("''", f);
		return;
	}
	plot_quote(big, n + 1, s);
	fputs(big, f);
	free(big);
}

/* ------------------------------------------------------- visual language */

/* Okabe-Ito: blue, vermillion, bluish green, reddish purple, orange, sky
 * blue; distinguishable with the common colour blindnesses. */
static const char *const palette[] = {
	"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9",
};
#define PALETTE_N ((int)(sizeof palette / sizeof palette[0]))

const char *plot_colour_rgb(int colour)
{
	if (colour == PLOT_BLACK)
		return "#000000";
	if (colour < 0)
		return "#888888";
	return palette[colour % PALETTE_N];
}

int plot_h_colour(double h_r0)
{
	if (!isfinite(h_r0))
		return PLOT_BLACK;
	/* Bin edges between the paper's 1, 2, 5, 10 r0 (near their geometric
	 * means), so each of its thicknesses has a colour of its own. */
	return h_r0 <= 1.4 ? 0 : h_r0 <= 3.2 ? 1 : h_r0 <= 7 ? 2 : 3;
}

enum plot_point plot_v_point(double V0)
{
	/* The paper's two velocities, 10 and 100 m/s, either side of 30. */
	return V0 <= 30 ? PLOT_PT_DIAMOND : PLOT_PT_CIRCLE;
}

/* ---------------------------------------------------------------- chart */

void plot_chart_init(struct plot_chart *c, enum plot_kind kind)
{
	memset(c, 0, sizeof *c);
	c->kind = kind;
}

void plot_chart_free(struct plot_chart *c)
{
	for (int i = 0; i < c->nseries; i++) {
		free(c->s[i].own);
		c->s[i].own = NULL;
	}
	c->nseries = 0;
}

int plot_chart_add(struct plot_chart *c, const char *label,
		   enum plot_mark mark, int colour, const double *x,
		   const double *y, size_t n, double xs, double ys, int copy)
{
	if (c->nseries >= PLOT_MAX_SERIES || (unsigned)mark >= PLOT_MARK_COUNT)
		return ANVIL_EINVAL;
	struct plot_series *s = &c->s[c->nseries];
	memset(s, 0, sizeof *s);
	if (copy && n > 0) {
		if (!(s->own = malloc(2 * n * sizeof *s->own)))
			return ANVIL_ENOMEM;
		memcpy(s->own, x, n * sizeof *x);
		memcpy(s->own + n, y, n * sizeof *y);
		x = s->own;
		y = s->own + n;
	}
	snprintf(s->label, sizeof s->label, "%s", label ? label : "");
	s->mark = mark;
	s->colour = colour;
	s->n = n;
	s->x = x;
	s->y = y;
	s->xs = xs;
	s->ys = ys;
	c->nseries++;
	return ANVIL_OK;
}

void plot_chart_key(struct plot_chart *c, const char *label,
		    enum plot_mark mark, int colour, enum plot_point point)
{
	for (int i = 0; i < c->nkeys; i++)
		if (strcmp(c->keys[i].label, label) == 0)
			return;
	if (c->nkeys >= PLOT_MAX_KEYS)
		return;
	struct plot_key *k = &c->keys[c->nkeys++];
	snprintf(k->label, sizeof k->label, "%s", label);
	k->mark = mark;
	k->colour = colour;
	k->point = point;
}

struct plot_note *plot_chart_note(struct plot_chart *c, double x, double y, int colour,
				  const char *text)
{
	if (c->nnotes >= PLOT_MAX_NOTES)
		return NULL;
	struct plot_note *n = &c->notes[c->nnotes++];
	n->x = x;
	n->y = y;
	n->colour = colour;
	n->panel = 0;
	n->below = n->left = 0;
	snprintf(n->text, sizeof n->text, "%s", text);
	return n;
}

/* A length in mm, shortest exact-looking form ("4 mm", "0.5 mm"). */
static void put_mm(char *buf, size_t len, double m)
{
	snprintf(buf, len, "%.3g mm", m * 1e3);
}

/* Whether the text names word (case aside): a material's name in a title. */
static int names(const char *text, const char *word)
{
	size_t n = strlen(word);
	if (!n)
		return 0;
	for (; *text; text++)
		if (!strncasecmp(text, word, n))
			return 1;
	return 0;
}

void plot_chart_subtitle(struct plot_chart *c, const struct anvil_scene *sc,
			 int vary_h, int vary_v)
{
	char r0[32], h[128], v[48];
	double hm = anvil_scene_h(sc);
	put_mm(r0, sizeof r0, sc->radius);
	/* Unicode subscripts: the subtitle holds user text, drawn noenhanced. */
	if (vary_h)
		snprintf(h, sizeof h, "%s", "");
	else if (isfinite(hm)) {
		char hh[24];
		put_mm(hh, sizeof hh, hm);
		snprintf(h, sizeof h, ", h = %s = %.3g r₀", hh, hm / sc->radius);
	} else
		snprintf(h, sizeof h, " (half-space)");
	if (vary_v)
		v[0] = '\0';
	else
		snprintf(v, sizeof v, ", V₀ = %.3g m/s", sc->velocity);
	char m[32];
	if (sc->mass >= 1.0)
		snprintf(m, sizeof m, "m = %.3g kg", sc->mass);
	else
		snprintf(m, sizeof m, "m = %.3g g", sc->mass * 1e3);
	/* The title anvil made for a changed scene (anvil_scene_title) already
	 * gives m, r0, V0 and h in the same 3 digits: said once.  It names
	 * one h and V0, so a chart that varies either builds its own. */
	const char *title = sc->title;
	if (!sc->title_set && !anvil_scene_is_paper_case(sc)) {
		if (!vary_h && !vary_v) {
			snprintf(c->subtitle, sizeof c->subtitle, "%.*s", 200, title);
			return;
		}
		title = "";
	}
	/* A title that names both materials (the examples' do) is not said
	 * twice; a long one is cut: the subtitle is one line. */
	int k;
	if (names(title, sc->impactor.mat.name) && names(title, sc->layer.mat.name))
		k = snprintf(c->subtitle, sizeof c->subtitle, "%.*s: %s, r₀ = %s%s%s", 100,
			     title, m, r0, h, v);
	else
		k = snprintf(c->subtitle, sizeof c->subtitle, "%.*s%s%s impactor (%s, "
			     "r₀ = %s) on %s%s%s%s", 100, title, title[0] ? ": " : "",
			     sc->impactor.mat.name, m, r0, sc->layer.mat.name,
			     isfinite(hm) || vary_h ? " layer" : "", h, v);
	if (k >= (int)sizeof c->subtitle)
		c->subtitle[sizeof c->subtitle - 1] = '\0';
}

void plot_chart_subtitle_materials(struct plot_chart *c, const struct anvil_scene *sc,
				   int mass_in_key)
{
	char r0[32], h[80], hh[24], m[32] = ""; /* room for them all in the subtitle */
	double hm = anvil_scene_h(sc);
	put_mm(r0, sizeof r0, sc->radius);
	put_mm(hh, sizeof hh, hm);
	if (isfinite(hm))
		snprintf(h, sizeof h, "on a layer, h = %s = %.3g r₀", hh, hm / sc->radius);
	else
		snprintf(h, sizeof h, "on a half-space");
	/* Not the scene's title: it names the scene's own materials. */
	if (!mass_in_key)
		snprintf(m, sizeof m, "%.4g g ", sc->mass * 1e3);
	snprintf(c->subtitle, sizeof c->subtitle, "%simpactor, r₀ = %s, %s; materials (impactor on layer)%s "
		 "in the key", m, r0, h, mass_in_key ? " and masses" : "");
}

/* ------------------------------------------------------------- builders */

static const char *const model_label[ANVIL_MODEL_COUNT] = {
	[ANVIL_MODEL_HERTZ] = "Hertz, rigid layer",
	[ANVIL_MODEL_ZENER] = "Zener's plate",
	[ANVIL_MODEL_LAYER] = "layer (transform)",
	[ANVIL_MODEL_HALFSPACE] = "half-space",
};

static int ok_run(const struct plot_run *run)
{
	return run->r != NULL && (unsigned)run->model < ANVIL_MODEL_COUNT;
}

static const double *history_y(const struct anvil_history *h, int panel,
				const struct plot_chart *c, double *ys)
{
	switch (panel) {
	case 0:
		*ys = c->force_in_n ? 1.0 : 1e-3; /* N, or N -> kN */
		return h->P;
	case 1:
		*ys = 1.0;
		return h->v;
	default:
		*ys = c->w_in_mm ? 1e3 : 1e6; /* m -> mm or um */
		return h->w;
	}
}

/* The model's line: transform solid (the half-space a band under the
 * rest), Zener dashed, Hertz dotted black. */
static enum plot_mark model_mark(enum anvil_model m)
{
	return m == ANVIL_MODEL_ZENER ? PLOT_DASH : m == ANVIL_MODEL_HERTZ ? PLOT_DOTS
		: m == ANVIL_MODEL_HALFSPACE ? PLOT_BAND : PLOT_LINE;
}

static int run_colour(const struct plot_run *run)
{
	if (run->model == ANVIL_MODEL_HERTZ)
		return PLOT_BLACK; /* rigid: no thickness */
	return plot_h_colour(run->model == ANVIL_MODEL_HALFSPACE ? INFINITY : run->h_r0);
}

/* The key: one entry per thickness (colour), one per model (style). */
static void history_keys(struct plot_chart *c, const struct plot_run *runs, int n)
{
	for (int i = 0; i < n; i++) {
		const struct plot_run *r = &runs[i];
		char label[PLOT_LABEL_MAX];
		if (!ok_run(r) || r->r->hist.n == 0 || r->model == ANVIL_MODEL_HERTZ)
			continue;
		if (r->model == ANVIL_MODEL_HALFSPACE || !isfinite(r->h_r0))
			snprintf(label, sizeof label, "half-space, h = ∞");
		else
			snprintf(label, sizeof label, "h = %.3g r_0", r->h_r0);
		plot_chart_key(c, label, r->model == ANVIL_MODEL_HALFSPACE ? PLOT_BAND : PLOT_LINE,
			       run_colour(r), 0);
	}
	for (int m = ANVIL_MODEL_COUNT - 1; m >= 0; m--)
		for (int i = 0; i < n; i++)
			if (ok_run(&runs[i]) && runs[i].r->hist.n > 0 &&
			    runs[i].model == (enum anvil_model)m && m != ANVIL_MODEL_HALFSPACE) {
				plot_chart_key(c, model_label[m], model_mark(m), PLOT_BLACK, 0);
				break;
			}
}

/* The time axis' unit for the longest history of runs: us up to 20 ms,
 * ms up to 20 s, else s (a 0.5 s drop-weight contact read in us is
 * "500000").  Returns the scale from s; sets c->tlabel.  When the longest
 * history outlasts the shortest feature LOG_TIME_RATIO times, a shorter
 * history or a force's rise (twice its peak's time: a 227 g ball on 3.2 mm
 * glass peaks at 37 us of 8.4 ms, beside the half-space's 0.25 ms), a
 * linear axis squeezes it into its first pixels: the axis is logarithmic
 * then, from a hundredth of that feature (P ~ t^(3/2) is at 1e-3 of its
 * peak there). */
#define LOG_TIME_RATIO 20.0
static double history_time_unit(struct plot_chart *c, const struct plot_run *runs, int n)
{
	double tmax = 0, tmin = INFINITY, ts;
	for (int i = 0; i < n; i++) {
		const struct anvil_history *h = ok_run(&runs[i]) ? &runs[i].r->hist : NULL;
		if (!h || h->n < 2)
			continue;
		size_t k = 0;
		for (size_t j = 1; j < h->n; j++)
			if (h->P[j] > h->P[k])
				k = j;
		double end = h->t[h->n - 1], rise = 2.0 * h->t[k];
		tmax = fmax(tmax, end);
		if (end > 0)
			tmin = fmin(tmin, rise > 0 ? fmin(end, rise) : end);
	}
	int lg = tmin < INFINITY && tmax > LOG_TIME_RATIO * tmin;
	if (tmax <= 20e-3) {
		c->tlabel = lg ? "t (µs), log scale" : "t (µs)";
		ts = 1e6;
	} else if (tmax <= 20.0) {
		c->tlabel = lg ? "t (ms), log scale" : "t (ms)";
		ts = 1e3;
	} else {
		c->tlabel = lg ? "t (s), log scale" : "t (s)";
		ts = 1.0;
	}
	if (lg)
		snprintf(c->setup, sizeof c->setup,
			 "set logscale x\nset xrange [%.6g:%.6g]\nset format x '%%g'\n",
			 0.01 * tmin * ts, 1.3 * tmax * ts);
	return ts;
}

/* P in N when every history peaks below 1 kN: a thin plate's 0.31 kN read
 * "0.25" on the axis, whose four characters pushed the label off the
 * image's edge; in N it reads "250". */
static int force_unit_n(const struct plot_run *runs, int n)
{
	double top = 0;
	for (int i = 0; i < n; i++)
		if (ok_run(&runs[i]))
			for (size_t j = 0; j < runs[i].r->hist.n; j++)
				top = fmax(top, runs[i].r->hist.P[j]);
	return top > 0 && top < 1e3;
}

/* w in mm beyond 1 mm: a drop weight pushes an unbounded plate 0.25 m,
 * "250000" um on the axis pushed its label off the image's edge. */
static int w_unit_mm(const struct plot_run *runs, int n)
{
	double top = 0;
	for (int i = 0; i < n; i++)
		if (ok_run(&runs[i]))
			for (size_t j = 0; j < runs[i].r->hist.n; j++)
				top = fmax(top, fabs(runs[i].r->hist.w[j]));
	return top > 1e-3;
}

int plot_force_log(const double *peak, int n, double range[2])
{
	double lo = INFINITY, hi = 0;
	for (int i = 0; i < n; i++)
		if (peak[i] > 0 && isfinite(peak[i])) {
			lo = fmin(lo, peak[i]);
			hi = fmax(hi, peak[i]);
		}
	if (!(hi > PLOT_LOG_FORCE_RATIO * lo))
		return 0;
	range[0] = 0.01 * lo;
	range[1] = 1.5 * hi;
	return 1;
}

/* The chart's P axis: plot_force_log over the peaks of the runs drawn, in
 * the axis' unit. */
static void force_axis(struct plot_chart *c, const struct plot_run *runs, int n)
{
	double peak[PLOT_MAX_SERIES], range[2];
	int k = 0;
	for (int i = 0; i < n && k < PLOT_MAX_SERIES; i++) {
		if (!ok_run(&runs[i]) || runs[i].r->hist.n == 0)
			continue;
		peak[k] = 0;
		for (size_t j = 0; j < runs[i].r->hist.n; j++)
			peak[k] = fmax(peak[k], runs[i].r->hist.P[j]);
		k++;
	}
	if (plot_force_log(peak, k, range)) {
		double ys = c->force_in_n ? 1.0 : 1e-3;
		c->force_log[0] = range[0] * ys;
		c->force_log[1] = range[1] * ys;
	}
}

int plot_deflection_log(const double *peak, const double *low, int n, double range[2],
			int *abs)
{
	if (!plot_force_log(peak, n, range))
		return 0;
	*abs = 0;
	for (int i = 0; i < n; i++)
		*abs |= low[i] < 0;
	return 1;
}

/* The chart's w axis: plot_deflection_log over the curves drawn (not
 * Hertz's w = 0), in the axis' unit.  Linear, a curve below 0 keeps its
 * dip: the kind's [0:*] would cut it off. */
static void deflection_axis(struct plot_chart *c, const struct plot_run *runs, int n)
{
	double peak[PLOT_MAX_SERIES] = {0}, low[PLOT_MAX_SERIES] = {0}, range[2];
	int k = 0;
	for (int i = 0; i < n && k < PLOT_MAX_SERIES; i++) {
		const struct anvil_history *h = ok_run(&runs[i]) ? &runs[i].r->hist : NULL;
		if (!h || h->n == 0 || runs[i].model == ANVIL_MODEL_HERTZ)
			continue;
		peak[k] = low[k] = 0;
		for (size_t j = 0; j < h->n; j++) {
			peak[k] = fmax(peak[k], fabs(h->w[j]));
			low[k] = fmin(low[k], h->w[j]);
		}
		c->w_neg |= low[k] < 0;
		k++;
	}
	if (plot_deflection_log(peak, low, k, range, &c->w_abs)) {
		double ys = c->w_in_mm ? 1e3 : 1e6;
		c->w_log[0] = range[0] * ys;
		c->w_log[1] = range[1] * ys;
	}
}

/* One run's curve in one panel (0 P, 1 v, 2 w), time scaled by ts. */
static int history_curve(struct plot_chart *c, const struct plot_run *run, int panel, double ts)
{
	double ys;
	const double *y = history_y(&run->r->hist, panel, c, &ys);
	size_t n = run->r->hist.n;
	int abs = panel == 2 && c->w_log[1] > 0 && c->w_abs; /* |w|, copied */
	int st = plot_chart_add(c, "", model_mark(run->model), run_colour(run),
				run->r->hist.t, y, n, ts, ys, abs);
	if (st)
		return st;
	struct plot_series *s = &c->s[c->nseries - 1];
	s->panel = panel;
	for (size_t j = 0; abs && j < n; j++)
		s->own[n + j] = fabs(s->own[n + j]);
	return ANVIL_OK;
}

int plot_chart_history(struct plot_chart *c, enum plot_kind kind,
		       const struct plot_run *runs, int n)
{
	int st = ANVIL_OK, hertz = 0, p0, p1;
	plot_chart_init(c, kind);
	switch (kind) {
	case PLOT_FORCE: p0 = p1 = 0; break;
	case PLOT_VELOCITY: p0 = p1 = 1; break;
	case PLOT_DEFLECTION: p0 = p1 = 2; break;
	case PLOT_HISTORY: p0 = 0, p1 = 2; break;
	default: return ANVIL_EINVAL;
	}
	static const char *const what[] = {"Contact force P(t)", "Impactor velocity v(t)",
		"Deflection w(t) of the layer under the impactor"};
	snprintf(c->title, sizeof c->title, "%s, V_0 = %.3g m/s",
		 kind == PLOT_HISTORY ? "Contact force, impactor velocity and deflection"
		 : what[p0], n > 0 ? runs[0].V0 : 0.0);
	double ts = history_time_unit(c, runs, n);
	c->force_in_n = force_unit_n(runs, n);
	c->w_in_mm = w_unit_mm(runs, n);
	if (p0 == 0)
		force_axis(c, runs, n);
	if (p1 == 2)
		deflection_axis(c, runs, n);
	/* The half-space first: its band goes under the layers. */
	for (int pass = 0; pass < 2; pass++)
		for (int i = 0; i < n && !st; i++) {
			const struct plot_run *run = &runs[i];
			if (!ok_run(run) || run->r->hist.n == 0 ||
			    (run->model == ANVIL_MODEL_HALFSPACE) != (pass == 0))
				continue;
			for (int p = p0; p <= p1 && !st; p++) {
				/* Hertz's layer is rigid: w = 0 on the axis says nothing. */
				if (run->model == ANVIL_MODEL_HERTZ && p == 2) {
					hertz = 1;
					continue;
				}
				st = history_curve(c, run, p, ts);
			}
		}
	if (st || c->nseries == 0)
		return st ? st : ANVIL_EINVAL;
	history_keys(c, runs, n);
	/* Hertz in the key says why it is missing from w(t). */
	for (int i = 0; hertz && i < c->nkeys; i++)
		if (c->keys[i].mark == PLOT_DOTS)
			snprintf(c->keys[i].label, sizeof c->keys[i].label, "%s",
				 kind == PLOT_DEFLECTION ? "Hertz, rigid: w = 0, not drawn"
				 : "Hertz, rigid layer (w = 0)");
	return ANVIL_OK;
}

/* ---------------------------------------------- contactB: the two models */

int plot_chart_models(struct plot_chart *c, const struct plot_run *runs, int n,
		      const struct plot_curve rf[2])
{
	int st = ANVIL_OK, any_hs = 0;
	plot_chart_init(c, PLOT_MODELS);
	snprintf(c->title, sizeof c->title,
		 "The physical and the paper's contact model, V_0 = %g m/s", n > 0 ? runs[0].V0 : 0.0);
	double ts = history_time_unit(c, runs, n);
	for (int i = 0; i < n && !st; i++) {
		const struct plot_run *run = &runs[i];
		if (!ok_run(run) || run->r->hist.n == 0)
			continue;
		int paper = run->r->contact == ANVIL_CONTACT_PAPER;
		st = plot_chart_add(c, "", paper ? PLOT_DASH : PLOT_LINE, run_colour(run),
				    run->r->hist.t, run->r->hist.P, run->r->hist.n, ts, 1e-3, 0);
		if (!st)
			c->s[c->nseries - 1].panel = 0;
		any_hs |= !isfinite(run->h_r0) || run->model == ANVIL_MODEL_HALFSPACE;
	}
	for (int k = 0; k < 2 && !st; k++) {
		if (rf[k].n == 0)
			continue;
		st = plot_chart_add(c, "", k ? PLOT_DASH : PLOT_LINESPOINTS, PLOT_BLACK, rf[k].x,
				    rf[k].y, rf[k].n, 1.0, 1.0, 1);
		if (!st) {
			c->s[c->nseries - 1].panel = 1;
			c->s[c->nseries - 1].point = PLOT_PT_DIAMOND;
		}
	}
	if (st || c->nseries == 0)
		return st ? st : ANVIL_EINVAL;
	for (int i = 0; i < n; i++) { /* the thicknesses' colours, once each */
		char label[PLOT_LABEL_MAX];
		if (!ok_run(&runs[i]) || runs[i].r->hist.n == 0)
			continue;
		if (!isfinite(runs[i].h_r0) || runs[i].model == ANVIL_MODEL_HALFSPACE)
			snprintf(label, sizeof label, "half-space, h = ∞");
		else
			snprintf(label, sizeof label, "h = %.3g r_0", runs[i].h_r0);
		plot_chart_key(c, label, PLOT_LINE, run_colour(&runs[i]), 0);
	}
	(void)any_hs;
	plot_chart_key(c, "physical contact", PLOT_LINE, PLOT_BLACK, 0);
	plot_chart_key(c, "paper's contact", PLOT_DASH, PLOT_BLACK, 0);
	return ANVIL_OK;
}

/* ---------------------------------------------------------- paper table */

/* The binary's folder (Linux /proc/self/exe), into buf; 0 or -1. */
static int exe_dir(char *buf, size_t len)
{
	ssize_t k = readlink("/proc/self/exe", buf, len - 1);
	if (k <= 0)
		return -1;
	buf[k] = '\0';
	char *slash = strrchr(buf, '/');
	if (!slash)
		return -1;
	*slash = '\0';
	return 0;
}

static const char *const paper_cols[] = {"V0", "h_r0", "Rf", "lambda_star", "Rf_star",
					 "Pmax_kN", "ts_us"};
#define PAPER_NCOLS 7

/* The column index of each wanted name in a header line; -1 if absent. */
static int paper_header(char *line, int idx[PAPER_NCOLS])
{
	int col = 0;
	for (int j = 0; j < PAPER_NCOLS; j++)
		idx[j] = -1;
	for (char *tok = strtok(line, "\t\n"); tok; tok = strtok(NULL, "\t\n"), col++)
		for (int j = 0; j < PAPER_NCOLS; j++)
			if (strcmp(tok, paper_cols[j]) == 0)
				idx[j] = col;
	for (int j = 0; j < PAPER_NCOLS; j++)
		if (idx[j] < 0)
			return j;
	return -1;
}

static int paper_row(char *line, const int idx[PAPER_NCOLS], struct plot_paper_row *r)
{
	double *out[PAPER_NCOLS] = {&r->V0, &r->h_r0, &r->Rf, &r->lambda_star, &r->Rf_star,
				    &r->Pmax_kN, &r->ts_us};
	int col = 0, got = 0;
	for (char *tok = strtok(line, "\t\n"); tok; tok = strtok(NULL, "\t\n"), col++)
		for (int j = 0; j < PAPER_NCOLS; j++)
			if (idx[j] == col) {
				char *end;
				*out[j] = strtod(tok, &end);
				if (end == tok || *end)
					return -1 - j;
				got++;
			}
	return got == PAPER_NCOLS ? 0 : -1 - PAPER_NCOLS;
}

static int paper_read(struct plot_paper *p, FILE *f, const char *path, struct anvil_err *err)
{
	char line[1024];
	int idx[PAPER_NCOLS], header = 0, lineno = 0;
	while (fgets(line, sizeof line, f)) {
		lineno++;
		if (line[0] == '#' || line[0] == '\n')
			continue;
		if (!header) {
			int miss = paper_header(line, idx);
			if (miss >= 0)
				return anvil_err_set(err, ANVIL_EPARSE, "%s:%d: no column '%s'",
						     path, lineno, paper_cols[miss]);
			header = 1;
			continue;
		}
		if (p->n == PLOT_PAPER_MAX)
			return anvil_err_set(err, ANVIL_EPARSE, "%s:%d: more than %d rows",
					     path, lineno, PLOT_PAPER_MAX);
		int bad = paper_row(line, idx, &p->row[p->n]);
		if (bad)
			return anvil_err_set(err, ANVIL_EPARSE, "%s:%d: %s: not a number",
					     path, lineno, -1 - bad < PAPER_NCOLS
					     ? paper_cols[-1 - bad] : "a column");
		p->n++;
	}
	return header ? ANVIL_OK
		: anvil_err_set(err, ANVIL_EPARSE, "%s: no header line", path);
}

int plot_paper_load(struct plot_paper *p, const char *path, struct anvil_err *err)
{
	char buf[PATH_MAX];
	const char *env = getenv("ANVIL_PAPER_TABLES");
	memset(p, 0, sizeof *p);
	if (!path && env && env[0])
		path = env;
	if (!path) {
		char dir[PATH_MAX - 64];
		if (exe_dir(dir, sizeof dir))
			return anvil_err_set(err, ANVIL_ENOTFOUND, "paper values not found");
		snprintf(buf, sizeof buf, "%s/../shared/paper/tables.tsv", dir);
		path = buf;
	}
	FILE *f = fopen(path, "r");
	if (!f)
		return anvil_err_set(err, ANVIL_ENOTFOUND, "paper values not found (%s: %s)",
				     path, strerror(errno));
	int st = paper_read(p, f, path, err);
	fclose(f);
	if (st)
		p->n = 0;
	return st;
}
