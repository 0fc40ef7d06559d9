/* plot_rf.c: the restitution charts (R_f against h/r0, against lambda*
 * and, from sweeps, against V0) and the accuracy chart.  See plot.h for the contract. */
#ifdef HAVE_CONFIG_H
#include "config.h"
#endif

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zener.h"
#include "plot.h"

static int ok_run(const struct plot_run *run)
{
	return run->r != NULL && (unsigned)run->model < ANVIL_MODEL_COUNT;
}

/* Index of key in seen[0..*n), appended when new. */
static int index_of(double *seen, int *n, int max, double key)
{
	for (int i = 0; i < *n; i++)
		if (seen[i] == key)
			return i;
	if (*n < max)
		seen[(*n)++] = key;
	return *n - 1;
}

/* The last series added gets marker pt. */
static void set_point(struct plot_chart *c, enum plot_point pt)
{
	c->s[c->nseries - 1].point = pt;
}

static void velocity_key(struct plot_chart *c, double V0, enum plot_mark mark)
{
	char label[PLOT_LABEL_MAX];
	snprintf(label, sizeof label, "V_0 = %g m/s (anvil)", V0);
	plot_chart_key(c, label, mark, PLOT_BLACK, plot_v_point(V0));
}

/* ----------------------------------------------------- R_f against h/r0 */

#define RF_H_MIN 0.5
#define RF_H_MAX 20.0

/* Layer runs of velocity V0 as markers, sorted by h/r0, and joined when
 * no dense curve is given. */
static int rf_layer_points(struct plot_chart *c, const struct plot_run *runs,
			   int n, double V0, int join)
{
	double x[PLOT_MAX_SERIES * 4], y[PLOT_MAX_SERIES * 4];
	size_t m = 0;
	for (int i = 0; i < n; i++) {
		const struct plot_run *run = &runs[i];
		if (!ok_run(run) || run->model != ANVIL_MODEL_LAYER || run->V0 != V0 ||
		    !isfinite(run->h_r0) || m == sizeof x / sizeof x[0])
			continue;
		size_t j = m++;
		for (; j > 0 && x[j - 1] > run->h_r0; j--) {
			x[j] = x[j - 1];
			y[j] = y[j - 1];
		}
		x[j] = run->h_r0;
		y[j] = run->r->Rf.val;
	}
	if (m == 0)
		return ANVIL_OK;
	int st = plot_chart_add(c, "", join ? PLOT_LINESPOINTS : PLOT_POINTS, PLOT_BLACK,
				x, y, m, 1, 1, 1);
	if (!st)
		set_point(c, plot_v_point(V0));
	return st;
}

/* The half-space's R_f at velocity V0 as a level across the h axis. */
static int rf_halfspace_level(struct plot_chart *c, const struct plot_run *runs,
			      int n, double V0, const double xr[2])
{
	for (int i = 0; i < n; i++) {
		const struct plot_run *run = &runs[i];
		if (!ok_run(run) || run->model != ANVIL_MODEL_HALFSPACE || run->V0 != V0)
			continue;
		double y[2] = {run->r->Rf.val, run->r->Rf.val};
		plot_chart_key(c, "half-space (h = ∞)", PLOT_DOTS, PLOT_BLACK, 0);
		return plot_chart_add(c, "", PLOT_DOTS, PLOT_BLACK, xr, y, 2, 1, 1, 1);
	}
	return ANVIL_OK;
}

/* Is V0 one of the velocities drawn (vs[0 .. nv))? */
static int drawn_v(const double *vs, int nv, double V0)
{
	for (int i = 0; i < nv; i++)
		if (vs[i] == V0)
			return 1;
	return 0;
}

/* The paper's layer values at the velocities drawn as open markers,
 * coloured by thickness. */
static int paper_points_h(struct plot_chart *c, const struct plot_paper *p,
			  const double *vs, int nv)
{
	int st = ANVIL_OK, any = 0;
	for (int i = 0; p && i < p->n && !st; i++) {
		const struct plot_paper_row *r = &p->row[i];
		if (!isfinite(r->h_r0) || !drawn_v(vs, nv, r->V0))
			continue;
		any = 1;
		st = plot_chart_add(c, "", PLOT_OPEN, plot_h_colour(r->h_r0), &r->h_r0,
				    &r->Rf, 1, 1, 1, 1);
		if (!st)
			set_point(c, plot_v_point(r->V0));
	}
	if (any)
		plot_chart_key(c, "paper's printed values (Tables 2-3)", PLOT_OPEN,
			       PLOT_BLACK, PLOT_PT_DIAMOND);
	return st;
}

/* A vertical line at the scene's thickness, in its colour; its label on
 * the side with room (the axis is logarithmic: compare in log). */
static int rf_mark(struct plot_chart *c, double h, const double xr[2])
{
	double x[2] = {h, h}, y[2] = {0, 1.05};
	char text[40];
	if (!isfinite(h) || !(h > 0))
		return ANVIL_OK;
	snprintf(text, sizeof text, "this scene: h = %.3g r_0", h);
	/* R_f rises with h and the key sits bottom right: the label goes
	 * high on the left of the axis, at mid height, leftwards, on the right. */
	int right = log(h / xr[0]) > 0.6 * log(xr[1] / xr[0]);
	struct plot_note *n = plot_chart_note(c, h, right ? 0.5 : 0.93, plot_h_colour(h), text);
	if (n)
		n->left = right;
	return plot_chart_add(c, "", PLOT_THIN, plot_h_colour(h), x, y, 2, 1, 1, 1);
}

/* Ticks 1, 2, 5 times the powers of ten within [lo, hi], as a gnuplot
 * tick list ("1, 2, 5, 10"); returns the length written. */
static int nice_tics(char *buf, size_t len, double lo, double hi)
{
	static const double m[] = {1, 2, 5};
	int k = 0;
	for (int e = (int)floor(log10(lo)); e <= (int)ceil(log10(hi)); e++)
		for (int i = 0; i < 3; i++) {
			double v = m[i] * pow(10, e);
			if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9) && (size_t)k + 24 < len)
				k += snprintf(buf + k, len - (size_t)k, "%s%g", k ? ", " : "", v);
		}
	return k;
}

/* The h/r0 axis: 0.5 .. 20 r0, wider to show a marked thickness; the
 * second axis in mm. */
static void rf_h_axis(struct plot_chart *c, double r0, double mark, double xr[2])
{
	xr[0] = RF_H_MIN;
	xr[1] = RF_H_MAX;
	if (isfinite(mark) && mark > 0) {
		xr[0] = fmin(xr[0], mark / 1.5);
		xr[1] = fmax(xr[1], mark * 1.5);
	}
	int k = snprintf(c->setup, sizeof c->setup, "set xrange [%.6g:%.6g]\n", xr[0], xr[1]);
	if (r0 > 0 && isfinite(r0) && k > 0) {
		/* Room above for the second axis. */
		k += snprintf(c->setup + k, sizeof c->setup - (size_t)k,
			      "set tmargin at screen 0.78\nset x2tics (");
		k += nice_tics(c->setup + k, sizeof c->setup - (size_t)k, xr[0] * r0 * 1e3,
			       xr[1] * r0 * 1e3);
		/* Both axes logarithmic and proportional: the same scale.
		 * (gnuplot cannot `set link` to a log axis.) */
		snprintf(c->setup + k, sizeof c->setup - (size_t)k,
			 ") nomirror\nset logscale x2\nset x2range [%.6g:%.6g]\n"
			 "set xtics nomirror\nset border 7\n"
			 "set x2label 'h (mm), with r_0 = %.3g mm'\n",
			 xr[0] * r0 * 1e3, xr[1] * r0 * 1e3, r0 * 1e3);
	}
}

static int rf_thickness_group(struct plot_chart *c, const struct plot_run *runs, int n,
			      const struct plot_curve *layer, int nlayer,
			      const struct plot_curve *zener, int nzener, double V0,
			      const double xr[2])
{
	int st = ANVIL_OK, dense = 0;
	for (int i = 0; i < nlayer && !st; i++)
		if (layer[i].V0 == V0 && layer[i].n > 1) {
			dense = 1;
			st = plot_chart_add(c, "", PLOT_LINE, PLOT_BLACK, layer[i].x,
					    layer[i].y, layer[i].n, 1, 1, 1);
			plot_chart_key(c, "layer, through anvil's points", PLOT_LINE,
				       PLOT_BLACK, 0);
		}
	if (!st)
		st = rf_layer_points(c, runs, n, V0, !dense);
	if (!st)
		velocity_key(c, V0, PLOT_POINTS);
	if (!st)
		st = rf_halfspace_level(c, runs, n, V0, xr);
	for (int i = 0; i < nzener && !st; i++) {
		if (zener[i].V0 != V0 || zener[i].n == 0)
			continue;
		st = plot_chart_add(c, "", PLOT_DASH, PLOT_BLACK, zener[i].x, zener[i].y,
				    zener[i].n, 1, 1, 1);
		plot_chart_key(c, "Zener's R_f^* = exp(-1.7191 λ^*), eq. (54)", PLOT_DASH,
			       PLOT_BLACK, 0);
	}
	return st;
}

int plot_chart_rf_thickness(struct plot_chart *c, const struct plot_run *runs,
			    int n, const struct plot_curve *layer, int nlayer,
			    const struct plot_curve *zener, int nzener,
			    const struct plot_paper *paper, double r0,
			    double mark_h_r0)
{
	double vs[PLOT_MAX_SERIES], xr[2];
	int nv = 0, st = ANVIL_OK, any = 0;
	plot_chart_init(c, PLOT_RESTITUTION_THICKNESS);
	snprintf(c->title, sizeof c->title,
		 "Coefficient of restitution R_f against layer thickness h");
	rf_h_axis(c, r0, mark_h_r0, xr);
	for (int i = 0; i < n; i++)
		if (ok_run(&runs[i]))
			index_of(vs, &nv, PLOT_MAX_SERIES, runs[i].V0), any = 1;
	/* The key in reading order: the layer, its markers, then the rest. */
	if (nlayer > 0)
		plot_chart_key(c, "layer, through anvil's points", PLOT_LINE, PLOT_BLACK, 0);
	for (int g = 0; g < nv; g++)
		velocity_key(c, vs[g], PLOT_POINTS);
	for (int g = 0; g < nv && !st; g++)
		st = rf_thickness_group(c, runs, n, layer, nlayer, zener, nzener, vs[g], xr);
	if (!any)
		return st ? st : ANVIL_EINVAL;
	if (!st)
		st = paper_points_h(c, paper, vs, nv);
	if (!st)
		st = rf_mark(c, mark_h_r0, xr);
	return st;
}

/* ------------------------------------------------- R_f against lambda* */

#define RF_FIT_POINTS 80

/* Zener's fit (54) over [x0, x1], log-spaced when log. */
static int rf_fit_line(struct plot_chart *c, double x0, double x1, int log)
{
	double x[RF_FIT_POINTS], y[RF_FIT_POINTS];
	for (int i = 0; i < RF_FIT_POINTS; i++) {
		double f = (double)i / (RF_FIT_POINTS - 1);
		x[i] = log ? x0 * pow(x1 / x0, f) : x0 + (x1 - x0) * f;
		y[i] = anvil_zener_rf_fit(x[i]);
	}
	plot_chart_key(c, "Zener's fit R_f^* = exp(-1.7191 λ^*), eq. (54)", PLOT_LINE,
		       PLOT_BLACK, 0);
	return plot_chart_add(c, "", PLOT_LINE, PLOT_BLACK, x, y, RF_FIT_POINTS, 1, 1, 1);
}

/* The range of the positive lambda* of the runs, the paper and the ODE. */
static void lambda_span(const struct plot_run *runs, int n, const struct plot_paper *p,
			double *lo, double *hi)
{
	*lo = INFINITY;
	*hi = 1.1; /* past the paper's largest case, 1.0032 */
	for (int i = 0; i < n; i++)
		if (ok_run(&runs[i]) && runs[i].lambda_star > 0) {
			*lo = fmin(*lo, runs[i].lambda_star);
			*hi = fmax(*hi, 1.1 * runs[i].lambda_star);
		}
	for (int i = 0; p && i < p->n; i++)
		if (p->row[i].lambda_star > 0)
			*lo = fmin(*lo, p->row[i].lambda_star);
}

/* One marker per run, coloured by thickness; the half-space (lambda* = 0)
 * at x0, the axis' left end. */
static int rf_lambda_points(struct plot_chart *c, const struct plot_run *runs,
			    int n, double x0, int log)
{
	int st = ANVIL_OK, half = 0;
	for (int i = 0; i < n && !st; i++) {
		const struct plot_run *run = &runs[i];
		if (!ok_run(run) || (run->model != ANVIL_MODEL_LAYER &&
				     run->model != ANVIL_MODEL_HALFSPACE))
			continue;
		double h = run->model == ANVIL_MODEL_HALFSPACE ? INFINITY : run->h_r0;
		double x = log && !(run->lambda_star > 0) ? x0 : run->lambda_star;
		char text[40];
		half |= !isfinite(h);
		st = plot_chart_add(c, "", PLOT_POINTS, plot_h_colour(h), &x, &run->r->Rf.val,
				    1, 1, 1, 1);
		if (st)
			break;
		set_point(c, plot_v_point(run->V0));
		velocity_key(c, run->V0, PLOT_POINTS);
		if (isfinite(h)) {
			snprintf(text, sizeof text, "%g r_0", h);
			struct plot_note *note = plot_chart_note(c, x, run->r->Rf.val,
								 plot_h_colour(h), text);
			/* the two velocities' labels on either side of the curve */
			if (note)
				note->below = plot_v_point(run->V0) == PLOT_PT_CIRCLE;
		}
	}
	if (half && log)
		plot_chart_note(c, x0, 0.9, PLOT_BLACK, "half-space, λ^* = 0");
	return st;
}

static int paper_points_lambda(struct plot_chart *c, const struct plot_paper *p,
			       const struct plot_run *runs, int n)
{
	double vs[PLOT_MAX_SERIES];
	int st = ANVIL_OK, nv = 0, any = 0;
	for (int i = 0; i < n; i++)
		if (ok_run(&runs[i]))
			index_of(vs, &nv, PLOT_MAX_SERIES, runs[i].V0);
	for (int i = 0; p && i < p->n && !st; i++) {
		const struct plot_paper_row *r = &p->row[i];
		/* Before any run: all of them, the paper's figure alone. */
		if (nv > 0 && !drawn_v(vs, nv, r->V0))
			continue;
		any = 1;
		st = plot_chart_add(c, "", PLOT_OPEN, plot_h_colour(r->h_r0), &r->lambda_star,
				    &r->Rf, 1, 1, 1, 1);
		if (!st)
			set_point(c, plot_v_point(r->V0));
	}
	if (any)
		plot_chart_key(c, "paper's printed values (Tables 2-3)", PLOT_OPEN,
			       PLOT_BLACK, PLOT_PT_DIAMOND);
	return st;
}

int plot_chart_rf_lambda(struct plot_chart *c, const struct plot_run *runs,
			 int n, const struct plot_curve *ode,
			 const struct plot_paper *paper)
{
	double lo, hi;
	plot_chart_init(c, PLOT_RESTITUTION_LAMBDA);
	snprintf(c->title, sizeof c->title,
		 "Coefficient of restitution R_f against Zener's λ^* (the paper's Fig. 9)");
	lambda_span(runs, n, paper, &lo, &hi);
	/* Points spanning decades crowd at the left of a linear axis. */
	int log = isfinite(lo) && hi / lo > 10;
	double x0 = log ? pow(10, floor(log10(lo)) ) : 0;
	if (log)
		snprintf(c->setup, sizeof c->setup,
			 "set logscale x\nset xrange [%.6g:%.6g]\nset format x '%%g'\n", x0, hi);
	else
		snprintf(c->setup, sizeof c->setup, "set xrange [0:%.6g]\n", hi);
	int st = rf_fit_line(c, log ? x0 : 0, hi, log);
	if (!st && ode && ode->n > 0) {
		st = plot_chart_add(c, "", PLOT_DASHDOT, PLOT_BLACK, ode->x, ode->y, ode->n,
				    1, 1, 1);
		plot_chart_key(c, "Zener's ODE (49), solved", PLOT_DASHDOT, PLOT_BLACK, 0);
	}
	if (!st)
		st = rf_lambda_points(c, runs, n, x0, log);
	if (!st)
		st = paper_points_lambda(c, paper, runs, n);
	if (!st && log)
		snprintf(c->footnote, sizeof c->footnote,
			 "markers coloured and labelled by h / r_0; λ^* on a log axis");
	return st;
}

/* ------------------------------------------------------------- accuracy */

/* Output o (0 P_max, 1 t_s, 2 R_f) of a result and its error estimate. */
static double acc_value(const struct anvil_result *r, int o, double *err)
{
	switch (o) {
	case 0:
		*err = r->Pmax.err;
		return r->Pmax.val;
	case 1:
		*err = r->ts.err;
		return r->ts.val;
	default:
		*err = r->Rf.err;
		return r->Rf.val;
	}
}

/* Relative error of output o at level i: against the next finer level
 * that succeeded, else the level's own estimate. */
static double acc_error(const struct plot_run *runs, int i, int o)
{
	double e, x = acc_value(runs[i].r, o, &e);
	for (int j = i + 1; j < ANVIL_ACC_COUNT; j++)
		if (ok_run(&runs[j])) {
			double f = acc_value(runs[j].r, o, &e);
			return fabs(x - f) / fabs(f);
		}
	return fabs(e) / fabs(x);
}

/* The wall times' span, widened for the target lines' labels. */
static void acc_time_span(const struct plot_run *runs, double t[2])
{
	t[0] = INFINITY;
	t[1] = 0;
	for (int i = 0; i < ANVIL_ACC_COUNT; i++)
		if (ok_run(&runs[i]) && runs[i].r->seconds > 0) {
			t[0] = fmin(t[0], runs[i].r->seconds);
			t[1] = fmax(t[1], runs[i].r->seconds);
		}
	if (!(t[1] > 0))
		t[0] = 1e-3, t[1] = 1;
	t[0] /= 2;
	t[1] *= 4;
}

static int acc_targets(struct plot_chart *c, const double t[2])
{
	int st = ANVIL_OK;
	for (int i = 0; i < ANVIL_ACC_COUNT && !st; i++) {
		double y[2], e = anvil_accuracy_target(i);
		char label[PLOT_LABEL_MAX];
		y[0] = y[1] = e;
		st = plot_chart_add(c, "", PLOT_THIN, i, t, y, 2, 1, 1, 1);
		snprintf(label, sizeof label, "%s: target %g", anvil_accuracy_name(i), e);
		plot_chart_key(c, label, PLOT_THIN, i, 0);
	}
	return st;
}

int plot_chart_accuracy(struct plot_chart *c,
			const struct plot_run runs[ANVIL_ACC_COUNT])
{
	static const char *const outputs[] = {"P_{max}", "t_s", "R_f"};
	static const enum plot_point pts[] = {PLOT_PT_DIAMOND, PLOT_PT_CIRCLE, PLOT_PT_SQUARE};
	double t[2];
	int st = ANVIL_OK, any = 0;
	plot_chart_init(c, PLOT_ACCURACY);
	snprintf(c->title, sizeof c->title, "Error of each output against cold wall time");
	acc_time_span(runs, t);
	st = acc_targets(c, t);
	for (int o = 0; o < 3 && !st; o++)
		for (int i = 0; i < ANVIL_ACC_COUNT && !st; i++) {
			if (!ok_run(&runs[i]))
				continue;
			/* A log axis has no place for a zero or undefined error. */
			double e = acc_error(runs, i, o), s = runs[i].r->seconds;
			if (!(isfinite(e) && e > 0 && isfinite(s) && s > 0))
				continue;
			st = plot_chart_add(c, "", PLOT_POINTS, i, &s, &e, 1, 1, 1, 1);
			if (st)
				break;
			any = 1;
			set_point(c, pts[o]);
			char label[PLOT_LABEL_MAX];
			snprintf(label, sizeof label, "%s", outputs[o]);
			plot_chart_key(c, label, PLOT_POINTS, PLOT_BLACK, pts[o]);
		}
	snprintf(c->footnote, sizeof c->footnote,
		 "error: change to the next finer level; the finest: its own estimate");
	return st ? st : any ? ANVIL_OK : ANVIL_EINVAL;
}

/* ------------------------------------------- R_f against V0 (sweeps) */

/* The V0 axis: the velocities run, end to end (gnuplot would widen a log
 * axis to whole decades), ticked at 1, 2, 5 times the powers of ten. */
static void rf_v_axis(struct plot_chart *c, const struct plot_run *runs, int n)
{
	static const double m[] = {1, 2, 5};
	double lo = INFINITY, hi = 0;
	for (int i = 0; i < n; i++)
		if (ok_run(&runs[i]) && runs[i].V0 > 0 && isfinite(runs[i].V0)) {
			lo = fmin(lo, runs[i].V0);
			hi = fmax(hi, runs[i].V0);
		}
	if (!(hi > lo))
		return; /* one velocity or none: the kind's own axis */
	int k = snprintf(c->setup, sizeof c->setup, "set xrange [%.6g:%.6g]\nset xtics (", lo, hi);
	for (int e = (int)floor(log10(lo)), first = 1; e <= (int)ceil(log10(hi)); e++)
		for (int i = 0; i < 3; i++) {
			double v = m[i] * pow(10, e);
			if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9) && k > 0 && (size_t)k + 32 < sizeof c->setup) {
				k += snprintf(c->setup + k, sizeof c->setup - (size_t)k, "%s%g", first ? "" : ", ", v);
				first = 0;
			}
		}
	if (k > 0 && (size_t)k + 4 < sizeof c->setup)
		snprintf(c->setup + k, sizeof c->setup - (size_t)k, ")\n");
	else
		c->setup[0] = '\0';
}

/* The distinct finite thicknesses of the layer runs, sorted. */
static int rf_v_thicknesses(const struct plot_run *runs, int n, double *h, int max)
{
	int nh = 0;
	for (int i = 0; i < n; i++) {
		if (!ok_run(&runs[i]) || runs[i].model != ANVIL_MODEL_LAYER || !isfinite(runs[i].h_r0))
			continue;
		int j = 0;
		while (j < nh && h[j] < runs[i].h_r0)
			j++;
		if ((j < nh && h[j] == runs[i].h_r0) || nh == max)
			continue;
		memmove(h + j + 1, h + j, (size_t)(nh - j) * sizeof *h);
		h[j] = runs[i].h_r0;
		nh++;
	}
	return nh;
}

/* The (V0, R_f) of model m at thickness h (any h for the half-space),
 * sorted by V0, one point per V0. */
/* (v, rf) into the k points x, y sorted by x (a velocity already there
 * keeps its first value); the new count. */
static size_t v_insert(double *x, double *y, size_t k, double v, double rf)
{
	size_t j = 0;
	while (j < k && x[j] < v)
		j++;
	if (j < k && x[j] == v)
		return k;
	memmove(x + j + 1, x + j, (k - j) * sizeof *x);
	memmove(y + j + 1, y + j, (k - j) * sizeof *y);
	x[j] = v;
	y[j] = rf;
	return k + 1;
}

static size_t rf_v_points(const struct plot_run *runs, int n, enum anvil_model m, double h,
			  double *x, double *y)
{
	size_t k = 0;
	for (int i = 0; i < n; i++) {
		const struct plot_run *r = &runs[i];
		if (!ok_run(r) || r->model != m || (m != ANVIL_MODEL_HALFSPACE && r->h_r0 != h) ||
		    !isfinite(r->r->Rf.val))
			continue;
		k = v_insert(x, y, k, r->V0, r->r->Rf.val);
	}
	return k;
}

int plot_chart_rf_velocity(struct plot_chart *c, const struct plot_run *runs, int n)
{
	double h[PLOT_MAX_KEYS], *x = malloc((size_t)(n + 1) * sizeof *x), *y = malloc((size_t)(n + 1) * sizeof *y);
	int st = ANVIL_OK, any = 0;
	plot_chart_init(c, PLOT_RESTITUTION_VELOCITY);
	snprintf(c->title, sizeof c->title, "Coefficient of restitution R_f against impact velocity V_0");
	rf_v_axis(c, runs, n);
	if (!x || !y) {
		free(x);
		free(y);
		return ANVIL_ENOMEM;
	}
	int nh = rf_v_thicknesses(runs, n, h, PLOT_MAX_KEYS - 3);
	/* the half-space first: a band under the layers that approach it */
	size_t k = rf_v_points(runs, n, ANVIL_MODEL_HALFSPACE, 0, x, y);
	if (k > 0) {
		plot_chart_key(c, "half-space, h = ∞", PLOT_BAND, PLOT_BLACK, 0);
		st = plot_chart_add(c, "", PLOT_BAND, PLOT_BLACK, x, y, k, 1, 1, 1);
		any = 1;
	}
	for (int i = 0; i < nh; i++) {
		char label[PLOT_LABEL_MAX];
		snprintf(label, sizeof label, "h = %.3g r_0", h[i]);
		plot_chart_key(c, label, PLOT_LINE, plot_h_colour(h[i]), 0);
	}
	for (int i = 0; i < nh && !st; i++) {
		int col = plot_h_colour(h[i]);
		if ((k = rf_v_points(runs, n, ANVIL_MODEL_ZENER, h[i], x, y)) > 0)
			st = plot_chart_add(c, "", PLOT_DASH, col, x, y, k, 1, 1, 1);
		if (!st && (k = rf_v_points(runs, n, ANVIL_MODEL_LAYER, h[i], x, y)) > 0) {
			st = plot_chart_add(c, "", PLOT_LINE, col, x, y, k, 1, 1, 1);
			if (!st)
				st = plot_chart_add(c, "", PLOT_POINTS, col, x, y, k, 1, 1, 1);
			any = 1;
		}
	}
	plot_chart_key(c, "layer (transform), anvil's points", PLOT_LINESPOINTS, PLOT_BLACK, 0);
	plot_chart_key(c, "Zener's plate", PLOT_DASH, PLOT_BLACK, 0);
	free(x);
	free(y);
	return st ? st : any ? ANVIL_OK : ANVIL_EINVAL;
}

/* The (V0, R_f) of model m in group g, sorted by V0, one point per V0. */
static size_t rf_g_points(const struct plot_run *runs, const int *group, int n, enum anvil_model m,
			  int g, double *x, double *y)
{
	size_t k = 0;
	for (int i = 0; i < n; i++) {
		const struct plot_run *r = &runs[i];
		if (!ok_run(r) || r->model != m || group[i] != g || !isfinite(r->r->Rf.val))
			continue;
		k = v_insert(x, y, k, r->V0, r->r->Rf.val);
	}
	return k;
}

int plot_chart_rf_velocity_groups(struct plot_chart *c, const struct plot_run *runs, int n,
				  const int *group, const char *const *label, int ngroups)
{
	double *x = malloc((size_t)(n + 1) * sizeof *x), *y = malloc((size_t)(n + 1) * sizeof *y);
	int st = ANVIL_OK, any = 0, hs = 0, zener = 0;
	plot_chart_init(c, PLOT_RESTITUTION_VELOCITY);
	snprintf(c->title, sizeof c->title, "Coefficient of restitution R_f against impact velocity V_0");
	rf_v_axis(c, runs, n);
	if (!x || !y || ngroups > PLOT_MAX_GROUPS) {
		free(x);
		free(y);
		return ngroups > PLOT_MAX_GROUPS ? ANVIL_EINVAL : ANVIL_ENOMEM;
	}
	/* the half-spaces first: bands under the layers that approach them */
	for (int g = 0; g < ngroups && !st; g++) {
		size_t k = rf_g_points(runs, group, n, ANVIL_MODEL_HALFSPACE, g, x, y);
		if (k > 0)
			st = plot_chart_add(c, "", PLOT_BAND, g, x, y, k, 1, 1, 1);
		hs |= k > 0;
	}
	for (int g = 0; g < ngroups; g++)
		plot_chart_key(c, label[g], PLOT_LINE, g, 0);
	for (int g = 0; g < ngroups && !st; g++) {
		size_t k = rf_g_points(runs, group, n, ANVIL_MODEL_ZENER, g, x, y);
		if (k > 0)
			st = plot_chart_add(c, "", PLOT_DASH, g, x, y, k, 1, 1, 1);
		zener |= k > 0;
		if (!st && (k = rf_g_points(runs, group, n, ANVIL_MODEL_LAYER, g, x, y)) > 0) {
			st = plot_chart_add(c, "", PLOT_LINE, g, x, y, k, 1, 1, 1);
			if (!st)
				st = plot_chart_add(c, "", PLOT_POINTS, g, x, y, k, 1, 1, 1);
			any = 1;
		}
	}
	/* the models' styles once, in black (the band in the grey of a band) */
	plot_chart_key(c, "layer (transform), anvil's points", PLOT_LINESPOINTS, PLOT_BLACK, 0);
	if (zener)
		plot_chart_key(c, "Zener's plate", PLOT_DASH, PLOT_BLACK, 0);
	if (hs)
		plot_chart_key(c, "half-space (band, the pair's tint)", PLOT_BAND, PLOT_BLACK, 0);
	free(x);
	free(y);
	return st ? st : any || hs ? ANVIL_OK : ANVIL_EINVAL;
}
