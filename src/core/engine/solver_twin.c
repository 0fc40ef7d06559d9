/* solver_twin.c: the layer correction's band error from its twin (the
 * same run at half the band; solver.c run_waves): the values' differences,
 * and for P_max and t_s the amplitude of the force's and the approach's
 * difference over a period near the peak and the end, the twin's history
 * taken at the same place in its own contact. */
#include <math.h>
#include <stdint.h>

#include <gsl/gsl_interp.h>

#include "solver_impl.h"

/* y of history h (times rising) at t, linear between its samples; *k:
 * the sample before the last t asked for (SIZE_MAX: none), then this
 * one's (the times asked for rise: a walk on from there). */
static double hist_at(const struct anvil_history *h, const double *y, double t, size_t *k)
{
	size_t j = *k;
	if (j == SIZE_MAX) /* the first: bisection */
		j = gsl_interp_bsearch(h->t, t, 0, h->n - 1);
	while (j + 2 < h->n && h->t[j + 1] <= t)
		j++;
	*k = j;
	double f = fmin(1.0, fmax(0.0, (t - h->t[j]) / (h->t[j + 1] - h->t[j])));
	return (1 - f) * y[j] + f * y[j + 1];
}

/* The errors of the layer correction's band, from its twin (run_waves).
 *
 * Each output's is its change |x - coarse| when the bandwidth is halved
 * (conservative: that is the coarse twin's error), and for P_max and t_s
 * at least the amplitude of that change, not one sample of it.  The main
 * response (band omega) differs from the true one by its content above
 * omega; the twin (omega/2) from the main one by the content in
 * [omega/2, omega].  In the force and the approach both differences
 * oscillate (the layer's thickness resonances, the band's Gibbs ringing):
 * the twin's difference at t_max (or t_s) is one sample of its
 * oscillation, and the main error's own phase there is unrelated to it.
 * On long contacts on pmma (issue 11) the main's true P_max error was up
 * to 4.5 times the twin's change: 1.6e-3 N against 3.6e-4 N on tungsten
 * carbide on 1.94 r0, where the difference's amplitude near the peak is
 * 5.0e-3 N.  The twin measures that amplitude without luck over one
 * period of the difference's slowest part (frequency omega/2, period
 * 4 pi/omega): the main error is taken to be within it (the band
 * converges), as the change alone took it to be within the change.
 *   P_max: max |P_main - P_twin| within 2 pi/omega of t_max (a period
 * centred on the peak); |max P - max Q| <= max |P - Q| there.
 *   t_s: the contact ends where alpha = 0, so an error da in the approach
 * moves t_s by da / |alpha'(t_s)|.  Over the period before t_s the
 * histories are compared at the same fraction of each one's own t_s
 * (the twin's at t t_s' / t_s), so the comparison is aligned at the end
 * (both alpha exactly 0 there) and near it shows da(t) - da(t_s), the
 * oscillation about the end value, which |t_s - coarse t_s| (= da(t_s) /
 * |alpha'|) already counts: the two added bound |da(t)| / |alpha'| over
 * the period.  Near t_max the same alignment moves P by |P'| dt_s, P'
 * small there.
 *   The histories are the runs' own nodes (anvil_impact_opts.hist_nodes),
 * linear between them: the difference of two such functions is itself
 * linear between the union of their nodes, so its largest |value| over
 * a window is at one of them or at the window's ends, and that is what
 * is taken: the supremum, which no sampling of the same functions
 * exceeds.  It was sampled at up to 4e6 points (spacing dt/2, coarser
 * past the first window), whose resampling was half of a long row's time
 * (h = 0.1 r0, 100 kg at 1 m/s, the paper's contact).
 * band: omega in 1/s. */

/* max |A(t) - B(t scale)| at a's nodes in [lo, hi] (B: b at a's time
 * scaled, the alignment at the end), and the same at b's nodes. */
static double nodes_diff(const struct anvil_history *a, const double *x,
			 const struct anvil_history *b, const double *y, double scale, double lo,
			 double hi)
{
	double d = 0;
	size_t kb = SIZE_MAX, ka = SIZE_MAX;
	hist_at(a, x, lo, &ka); /* ka: the node before lo */
	for (size_t i = ka; i < a->n && a->t[i] <= hi; i++)
		if (a->t[i] >= lo)
			d = fmax(d, fabs(x[i] - hist_at(b, y, a->t[i] * scale, &kb)));
	ka = SIZE_MAX;
	kb = SIZE_MAX;
	hist_at(b, y, lo * scale, &kb);
	for (size_t j = kb; j < b->n && b->t[j] / scale <= hi; j++)
		if (b->t[j] / scale >= lo)
			d = fmax(d, fabs(hist_at(a, x, b->t[j] / scale, &ka) - y[j]));
	return d;
}

/* The supremum of the two histories' difference over [lo, hi] (alpha: the
 * approach's, else the force's).  It can fall below the samples'
 * maximum, by up to 4.6e-5 of it on the grid (h = 0.5 r0, 100 g at
 * 10 m/s): that one had interpolated the twin's samples again where its
 * warp was not the main's, cutting the corners of its curve at the peak. */
static double hist_window_diff(const struct anvil_result *a, const struct anvil_result *b, int alpha,
			       double lo, double hi)
{
	const struct anvil_history *ha = &a->hist, *hb = &b->hist;
	if (ha->n < 2 || hb->n < 2)
		return 0;
	const double *x = alpha ? ha->alpha : ha->P, *y = alpha ? hb->alpha : hb->P;
	double scale = hb->t[hb->n - 1] / ha->t[ha->n - 1];
	lo = fmax(lo, 0.0);
	hi = fmin(hi, ha->t[ha->n - 1]);
	if (!(lo <= hi))
		return 0;
	size_t ka = SIZE_MAX, kb = SIZE_MAX, la = SIZE_MAX, lb = SIZE_MAX;
	double d = fabs(hist_at(ha, x, lo, &ka) - hist_at(hb, y, lo * scale, &kb));
	d = fmax(d, fabs(hist_at(ha, x, hi, &la) - hist_at(hb, y, hi * scale, &lb)));
	return fmax(d, nodes_diff(ha, x, hb, y, scale, lo, hi));
}

/* The smaller of |alpha'(t_s)| from the parabola through the last two
 * nodes and the end (alpha = 0 there) and the secant of the interval
 * before the last, at least half the last interval's secant sec.  That
 * secant is the slope at its interval's middle, off the end's by the
 * approach's curvature times the spacing, either way: the samples' last
 * interval (dt/2 or finer, between the pass's nodes, the chord to the
 * node past the end) had made t_s's part up to 0.55 % larger on thick
 * plates (h = 20 r0, 10 kg at 100 m/s), an artefact of the spacing but
 * one that a slope from the nodes alone must not undercut.  A parabola
 * flatter than half the secant is an end turning into a graze, which
 * ts_graze counts (impact_end.c); the slope is not taken below that. */
static double end_slope_low(const struct anvil_history *h, double sec)
{
	size_t n = h->n;
	double x0 = h->t[n - 3], x1 = h->t[n - 2], x2 = h->t[n - 1];
	double d01 = (h->alpha[n - 2] - h->alpha[n - 3]) / (x1 - x0);
	double d12 = (h->alpha[n - 1] - h->alpha[n - 2]) / (x2 - x1);
	double q = d12 + (d12 - d01) / (x2 - x0) * (x2 - x1);
	double low = fmin(d12 * q > 0 ? fabs(q) : 0.0, d01 * d12 > 0 ? fabs(d01) : 0.0);
	return fmax(low, 0.5 * sec);
}

/* |alpha'| at the end: the last interval's slope (alpha = 0 at t_s).  At
 * rest (impact_rest.c) alpha stays near its value, the end no zero of it
 * and the last interval's secant only a measure of the spacing (the
 * nodes' 0.3 of the samples' made a rest row's t_s part 3 times smaller,
 * h = 0.05 r0, 10 g at 0.1 m/s): the secant over the period compared
 * (per), whatever the spacing, is taken there. */
static double end_slope(const struct anvil_history *h, int rest, double per)
{
	size_t n = h->n, k = SIZE_MAX;
	double te = h->t[n - 1], t0 = rest ? fmax(te - per, 0.0) : h->t[n - 2];
	if (rest && t0 < h->t[n - 2])
		return fabs(hist_at(h, h->alpha, t0, &k)) / (te - t0);
	double sec = fabs(h->alpha[n - 2]) / (te - h->t[n - 2]);
	return n < 3 ? sec : fmin(sec, end_slope_low(h, sec));
}

void solver_add_green_error(struct anvil_result *r, const struct anvil_result *c, double band)
{
	double per = 4.0 * M_PI / band, dP = 0, dts = 0;
	size_t n = r->hist.n;
	if (n >= 2 && c->hist.n >= 2) {
		dP = hist_window_diff(r, c, 0, r->tmax.val - 0.5 * per, r->tmax.val + 0.5 * per);
		double slope = end_slope(&r->hist, r->rest_bound > 0, per);
		double da = hist_window_diff(r, c, 1, r->ts.val - per, r->ts.val);
		dts = da > 0 ? da / slope : 0; /* a grazing end (slope 0) is no estimate */
	}
	r->ts.err += fabs(r->ts.val - c->ts.val) + dts;
	r->tmax.err += fabs(r->tmax.val - c->tmax.val);
	r->Pmax.err += fmax(fabs(r->Pmax.val - c->Pmax.val), dP);
	r->Vs.err += fabs(r->Vs.val - c->Vs.val);
	r->Rf.err += fabs(r->Rf.val - c->Rf.val);
	r->Ea.err += fabs(r->Ea.val - c->Ea.val);
}
