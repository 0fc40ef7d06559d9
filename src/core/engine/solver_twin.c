/* solver_twin.c: the layer correction's band error from its twin (the
 * same run at half the band; solver.c run_waves): the values' differences,
 * and for P_max and t_s the amplitude of the force's and the approach's
 * difference over a period near the peak and the end, the twin's history
 * taken at the same place in its own contact. */
#include <math.h>
#include <stdint.h>

#include "solver_impl.h"

/* y of history h (times rising) at t, linear between its samples; *k:
 * the sample before the last t asked for (SIZE_MAX: none), then this
 * one's (the times asked for rise: a walk on from there). */
static double hist_at(const struct anvil_history *h, const double *y, double t, size_t *k)
{
	size_t j = *k;
	if (j == SIZE_MAX) { /* the first: bisection */
		size_t lo = 0, hi = h->n - 1;
		while (hi - lo > 1) {
			size_t mid = lo + (hi - lo) / 2;
			if (h->t[mid] <= t)
				lo = mid;
			else
				hi = mid;
		}
		j = lo;
	}
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
 * histories are compared sample by sample; each history's sample i is at
 * i t_s / (n - 1) of its own t_s, so the comparison is aligned at the end
 * (both alpha exactly 0 there) and near it shows da(t) - da(t_s), the
 * oscillation about the end value, which |t_s - coarse t_s| (= da(t_s) /
 * |alpha'|) already counts: the two added bound |da(t)| / |alpha'| over
 * the period.  Near t_max the same alignment moves P by |P'| dt_s, P'
 * small there.  Index by index, no interpolation error is added (but
 * where the samples' spacing differs: hist_window_diff).
 * band: omega in 1/s. */
static double hist_window_diff(const struct anvil_result *a, const struct anvil_result *b, int alpha,
			       double lo, double hi)
{
	size_t n = a->hist.n;
	double d = 0;
	if (n < 2 || b->hist.n != n)
		return 0;
	const double *x = alpha ? a->hist.alpha : a->hist.P, *y = alpha ? b->hist.alpha : b->hist.P;
	/* b at a's sample's place in its own contact (aligned at the end):
	 * sample i itself, but where a long contact's spacing follows each
	 * history's own peak (result.h, anvil_history_warp) and the two
	 * peaked at different nodes, there sample i is elsewhere in each:
	 * at h = 0.5 r0, 100 kg at 100 m/s (t_s 2.36 s, t_max 7.6 us) up to
	 * 1.3 ms apart, and their difference near the peak counted P's own
	 * rise over that shift, 7 times the band's (P_max's part 1.3e-3
	 * against 1.8e-4 at a step 1.2 % finer, where the peaks shared a
	 * node) */
	double scale = b->hist.t[n - 1] / a->hist.t[n - 1], tol = 1e-12 * b->hist.t[n - 1];
	size_t k = SIZE_MAX;
	for (size_t i = 0; i < n; i++) {
		if (!(a->hist.t[i] >= lo && a->hist.t[i] <= hi))
			continue;
		double tb = a->hist.t[i] * scale;
		double yb = fabs(tb - b->hist.t[i]) <= tol ? y[i] : hist_at(&b->hist, y, tb, &k);
		d = fmax(d, fabs(x[i] - yb));
	}
	return d;
}

void solver_add_green_error(struct anvil_result *r, const struct anvil_result *c, double band)
{
	double per = 4.0 * M_PI / band, dP = 0, dts = 0;
	size_t n = r->hist.n;
	if (n >= 2 && c->hist.n == n) {
		dP = hist_window_diff(r, c, 0, r->tmax.val - 0.5 * per, r->tmax.val + 0.5 * per);
		/* |alpha'| at the end: the last interval's slope (alpha = 0 at t_s) */
		double slope = fabs(r->hist.alpha[n - 2]) / (r->hist.t[n - 1] - r->hist.t[n - 2]);
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
