/* test_tail: the layer correction's plate tail (plate.h, green.h
 * anvil_green_t_plate): beyond T1 the response is the plate's closed form,
 * not samples to the window's end.
 *  - the K(t)/t^2 and S(t)/t tables' interpolants against their quadratures
 *    between nodes; S's quadrature against 30-digit values, its
 *    coefficients against the layer's kernel;
 *  - the closed form against a cubic spline through its own samples at the
 *    inversion's step (the response before: the plate's model sampled to the
 *    window's end and interpolated), on h = 0.1, 0.5, 2 r0;
 *  - ramp and step continuous at T1;
 *  - a window 1e6 T1 long: as many samples as a 16 T1 one, the same bits
 *    below 8 T1, its error bound per time, and the plate's memo;
 *  - the cache's round trip to the bit, and a damaged tail refused;
 *  - anvil_green_t_plate's value, and the planner's arithmetic. */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>

#include "cache.h"
#include "green.h"
#include "layer_bc.h"
#include "material.h"
#include "plan.h"
#include "plate.h"
#include "tap.h"

static struct anvil_green *make(double hh, double tau_end, double omega, int no_plate,
				struct anvil_plate_memo *memo)
{
	struct anvil_green_settings gs;
	struct anvil_err e;
	anvil_green_settings(ANVIL_ACC_DRAFT, &gs);
	gs.omega_max = omega;
	gs.no_plate = no_plate;
	gs.plate = memo;
	struct anvil_green *g = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, hh, 0.3, tau_end,
						  &gs, NULL, NULL, &e);
	if (!g)
		diag("h = %g r0, window %g: %s", hh, tau_end, e.msg);
	return g;
}

static double t1_of(double hh) { return hh < 1.0 ? 32.0 : 64.0 * hh; }

/* The tables (32 nodes an octave, cubic B-spline quasi-interpolant)
 * against their quadratures at the midpoints between nodes, where their
 * error is the largest, from T1/8 to the window's end: K/t^2 relative, S/t
 * (which crosses zero at its transition) against its largest value. */
static void test_k_table(const struct anvil_green *g, double hh)
{
	struct anvil_green_samples s;
	struct anvil_plate_tail tl;
	anvil_green_export(g, &s);
	int st = anvil_plate_tail_init(&tl, hh, 0.3, s.patch, s.t1, s.tail_c, s.tail_v, s.tau_end,
				       s.nk, s.k, s.shear);
	double worst = 0, sworst = 0, smax = 0, h = M_LN2 / ANVIL_PLATE_PER_OCTAVE;
	/* S is tabulated where its transition patch^2/beta reaches T1/16
	 * (plate.c, shear_on); elsewhere its table is 0 */
	double beta = hh / sqrt(6.0 * (1.0 - 0.3));
	int on = s.patch > 0 && s.patch * s.patch / beta >= s.t1 / 16.0, zero = 1;
	for (size_t i = 0; i < s.nk; i++)
		zero &= s.shear[i] == 0.0;
	for (double u = log(s.t1 / 8.0) + 0.5 * h; !st && u < log(s.tau_end); u += 7.0 * h) {
		double q, qs, t = exp(u);
		if (anvil_plate_k(hh, 0.3, s.patch, t, &q) || anvil_plate_s(hh, 0.3, s.patch, t, &qs)) {
			st = 1;
			break;
		}
		worst = fmax(worst, fabs(anvil_plate_tail_k(&tl, t) - q) / q);
		sworst = fmax(sworst, fabs(anvil_plate_tail_s(&tl, t) - qs));
		smax = fmax(smax, fabs(qs));
	}
	ok(!st && worst < 1e-9,
	   "h = %g r0: K(t)/t^2 from its table within %.1e of its quadrature between nodes", hh,
	   worst);
	if (on)
		ok(!st && smax > 0 && sworst < 1e-9 * smax,
		   "h = %g r0: S(t)/t from its table within %.1e of its largest value, %.3g", hh,
		   sworst / smax, smax);
	else
		ok(!st && zero, "h = %g r0: S's transition (patch^2/beta = %.3g) is over before T1/16: no S",
		   hh, s.patch * s.patch / beta);
	anvil_plate_tail_free(&tl);
}

/* S(t)/t's quadrature (plate.c) against the same integrals in 30-digit
 * arithmetic (mpmath: the interval to U = 64 pi by Gauss-Legendre between
 * the multiples of pi, the oscillating tails by quadosc, the smooth one in
 * closed form, checked there against quadosc in k), and S_0 = 0. */
static void test_s_quadrature(void)
{
	const struct {
		double hh, patch, t, want;
	} c[] = { { 0.5, 0.125, 2.0, 0.488419318395233303582 },
		  { 0.02, 1.0, 3.7, -0.0264228723408396551656 },
		  { 0.02, 1.0, 300.0, 4.60176782813155808507 } };
	double worst = 0, v0 = 1;
	int st = anvil_plate_s(0.02, 0.3, 0.0, 100.0, &v0);
	for (size_t i = 0; !st && i < sizeof c / sizeof c[0]; i++) {
		double v;
		st = anvil_plate_s(c[i].hh, 0.3, c[i].patch, c[i].t, &v);
		worst = fmax(worst, fabs(v - c[i].want) * c[i].hh);
	}
	ok(!st && worst < 1e-12 && v0 == 0.0,
	   "S(t)/t's quadrature within %.1e/hh of 30-digit values (on and off its zero); 0 for a "
	   "point load", worst);
}

/* K(t)/t^2's quadrature (plate.c) against the same integral in 30-digit
 * arithmetic (mpmath: [0, U] by Gauss-Legendre on 128 pieces, the
 * smooth tail in closed form, checked against quadosc in k, the
 * oscillating one by quadosc): early and late, thin and thick, small and
 * large patches.  The stated 1e-12: qagiu's smooth tail missed it by
 * 8e-10 at t = 4.9e8 (before its closed form). */
static void test_k_quadrature(void)
{
	const struct {
		double hh, patch, t, want;
	} c[] = { { 0.02, 1.0, 300.0, 270.3235898260156635572 },
		  { 0.02, 0.05, 4.85823e8, 320.2172109234362273783 },
		  { 1.0, 0.3536, 4.85823e8, 0.1280868843693226779233 },
		  { 0.1, 0.5, 2000.0, 12.7733580599271190837 } };
	double worst = 0;
	int st = 0;
	for (size_t i = 0; !st && i < sizeof c / sizeof c[0]; i++) {
		double v;
		st = anvil_plate_k(c[i].hh, 0.3, c[i].patch, c[i].t, &v);
		worst = fmax(worst, fabs(v / c[i].want - 1.0));
	}
	ok(!st && worst < 1e-12, "K(t)/t^2's quadrature within %.1e of 30-digit values", worst);
}

/* The coefficients of S (plate.c) are the layer's: its surface under a
 * surface load, W = Q (1 + h^2 k^2/5)/(D k^4 + rho h s^2 (1 + gamma h^2
 * k^2)) to first order in (kh)^2, gamma = (17 - 7 nu)/(60 (1 - nu)).  From
 * the layer's own kernel at kh = 0.0025 (the next order: 4e-11 of W, 6e-6
 * of the coefficients) for s^2 rho h = 1e-6 and 1 times D k^4: W P - 1 =
 * (kh)^2 (1/5 - gamma r/(1 + r)).  Mindlin's plate would give 0.289 and
 * 0.373 at nu = 0.3. */
static void test_s_coefficients(void)
{
	const double nus[] = { 0.0, 0.3, 0.45 }, hh = 0.0025, k = 1.0;
	double worst = 0;
	for (int i = 0; i < 3; i++) {
		double nu = nus[i], D = hh * hh * hh / (6.0 * (1.0 - nu)), beta = sqrt(D / hh), f[2];
		const double r[2] = { 1e-6, 1.0 };
		for (int j = 0; j < 2; j++) {
			struct anvil_layer_bc bc;
			double s = sqrt(r[j]) * beta * k * k;
			anvil_layer_bc_solve(k, s, anvil_kappa2(nu), hh, &bc);
			double w = creal(anvil_layer_bc_w_halfspace(&bc) +
					 anvil_layer_bc_w_correction(&bc));
			f[j] = (w * (D * k * k * k * k + hh * s * s) - 1.0) / (k * k * hh * hh);
		}
		double gamma = (17.0 - 7.0 * nu) / (60.0 * (1.0 - nu));
		worst = fmax(worst, fmax(fabs(f[0] - 0.2), fabs(2.0 * (f[0] - f[1]) - gamma)));
	}
	ok(worst < 2e-4, "the layer to first order in (kh)^2: its load's 1/5 and its flexural "
	   "branch's (17 - 7 nu)/(60 (1 - nu)), nu = 0 .. 0.45, to %.1e", worst);
}

/* S's table on the thinnest plate, the paper's patch, where S/t bends most
 * (its transition at patch^2/beta = 102): the quasi-interpolant of the
 * nodes' quadratures against the quadrature between them, from T1/8.
 * What the tail needs of it: its error in the ramp, t dS/t, below K's
 * table's own (1e-9 of K, test_k_table).  Measured: 2.4e-10 of K at
 * most, near T1/8 = 4 where S/t turns (1.6e-8 in S/t, 2.5e-9 of its
 * largest value; at T1 = 64, below 1e-9 of it). */
static void test_s_table_thin(void)
{
	double hh = 0.02, patch = 1.0, tau_end = 512.0, t1 = anvil_plate_t1(hh, tau_end);
	size_t nk = anvil_plate_nodes(t1, tau_end);
	double *k = malloc(2 * nk * sizeof *k), *sh = k + nk, c[3] = { 0, 0, 0 };
	double u0 = log(t1 / 17.0), h = M_LN2 / ANVIL_PLATE_PER_OCTAVE, worst = 0, smax = 0, ofk = 0;
	int st = 0;
	for (size_t i = 0; !st && i < nk; i++) {
		double t = exp(u0 + (double)i * h);
		st = anvil_plate_k(hh, 0.3, patch, t, &k[i]) || anvil_plate_s(hh, 0.3, patch, t, &sh[i]);
	}
	struct anvil_plate_tail tl;
	st = st || anvil_plate_tail_init(&tl, hh, 0.3, patch, t1, c, 0.0, tau_end, nk, k, sh);
	for (double u = log(t1 / 8.0) + 0.5 * h; !st && u < log(tau_end); u += 3.0 * h) {
		double q, qk, t = exp(u);
		st = anvil_plate_s(hh, 0.3, patch, t, &q) || anvil_plate_k(hh, 0.3, patch, t, &qk);
		double e = fabs(anvil_plate_tail_s(&tl, t) - q);
		worst = fmax(worst, e);
		ofk = fmax(ofk, e / (qk * t));
		smax = fmax(smax, fabs(q));
	}
	ok(!st && smax > 0 && ofk < 1e-9,
	   "h = 0.02 r0, patch r0: S(t) from its table within %.1e of K(t) (%.1e of S/t's largest value, %.3g)",
	   ofk, smax > 0 ? worst / smax : 0, smax);
	if (!st)
		anvil_plate_tail_free(&tl);
	free(k);
}

/* The table's late nodes (plate.c, nodes_fill): from beta t = patch^2
 * on, one in two, then three in four and seven in eight are the Lagrange
 * interpolant of the quadratures about them.  Every node against its
 * quadrature: the filled ones within the quadrature's own tolerance,
 * 1e-12 of K/t^2 and 1e-12/hh in S/t (measured: 3.8e-13 and 2.4e-13/hh),
 * the rest, and all in the patch's transition below patch^2/(2 beta),
 * its very bits; and a node depends on neither the window nor the memo
 * (a shorter window's table first, then this one from it: the same
 * bits). */
static void test_fill(double hh, double patch)
{
	double dtau = 0.25, tau_end = 1e5;
	size_t n1 = 130, n = n1 + ANVIL_PLATE_PAD; /* T1 = (n1 - 2) dtau = 32 */
	double *ramp = calloc(n, sizeof *ramp);
	struct anvil_plate_tail tl, ts, tm;
	struct anvil_plate_memo *m = anvil_plate_memo_alloc();
	int st = !ramp || !m ||
		 anvil_plate_tail_make(hh, 0.3, patch, dtau, n1, n, ramp, tau_end, NULL, &tl) ||
		 anvil_plate_tail_make(hh, 0.3, patch, dtau, n1, n, ramp, 4e3, m, &ts) ||
		 anvil_plate_tail_make(hh, 0.3, patch, dtau, n1, n, ramp, tau_end, m, &tm);
	double u0 = log(32.0 / 17.0), h = M_LN2 / ANVIL_PLATE_PER_OCTAVE, wk = 0, ws = 0;
	size_t nq = 0, nf = 0, same = 0, memo_same = 1;
	for (size_t i = 0; !st && i < tl.nk; i++) {
		double q, qs, t = exp(u0 + (double)i * h);
		st = anvil_plate_k(hh, 0.3, patch, t, &q) || anvil_plate_s(hh, 0.3, patch, t, &qs);
		if (tl.k[i] == q && tl.shear[i] == qs)
			same++;
		else if (t >= 0.5 * patch * patch / tl.beta)
			nf++;
		else
			nq++; /* a transition's node not its quadrature's */
		wk = fmax(wk, fabs(tl.k[i] - q) / q);
		ws = fmax(ws, fabs(tl.shear[i] - qs) * hh);
		memo_same &= tm.k[i] == tl.k[i] && tm.shear[i] == tl.shear[i];
	}
	ok(!st && same + nf == tl.nk && !nq && nf > tl.nk / 2 && wk < 1e-12 && ws < 1e-12,
	   "h = %g r0, patch %g: %zu of %zu nodes filled, within %.1e of K/t^2 and %.1e/hh of S/t; "
	   "the rest their quadratures' bits", hh, patch, nf, tl.nk, wk, ws);
	ok(!st && memo_same && tm.nk == tl.nk,
	   "  the same bits through the memo, from a shorter window's table (%zu nodes)", ts.nk);
	anvil_plate_tail_free(&tl);
	anvil_plate_tail_free(&ts);
	anvil_plate_tail_free(&tm);
	anvil_plate_memo_free(m);
	free(ramp);
}

/* The impulse response (plate.c imp_coefs: the B-spline's segments as
 * polynomials) against the step's derivative by a fourth-order central
 * difference (delta = 1e-4 t, within a node interval mostly: its error
 * is the rounding's, 1e-12 of the step over delta), on the thinnest
 * plate with the paper's patch, where S is largest, and past its filled
 * nodes: within 3e-8 of the impulse response's scale, 2 alpha* (measured
 * 6e-9 and 1e-9; an S cubic coefficient off by a third: 1.1e-7); a wrong
 * coefficient would be O(1) of a term. */
static void test_impulse(double hh, double patch)
{
	double dtau = 0.25, tau_end = 1e4, worst = 0, scale = 2.0 / (8.0 * (hh / sqrt(4.2)) * hh);
	size_t n1 = 130, n = n1 + ANVIL_PLATE_PAD;
	double *ramp = calloc(n, sizeof *ramp);
	struct anvil_plate_tail tl;
	int st = !ramp || anvil_plate_tail_make(hh, 0.3, patch, dtau, n1, n, ramp, tau_end, NULL, &tl);
	for (double u = log(4.0); !st && u < log(0.9 * tau_end); u += 0.0137) {
		double t = exp(u), d = 1e-4 * t;
		double ds = (8.0 * (anvil_plate_tail_step(&tl, t + d) - anvil_plate_tail_step(&tl, t - d)) -
			     (anvil_plate_tail_step(&tl, t + 2 * d) - anvil_plate_tail_step(&tl, t - 2 * d))) /
			    (12.0 * d);
		worst = fmax(worst, fabs(anvil_plate_tail_impulse(&tl, t) - ds) / scale);
	}
	ok(!st && tl.shear_on && worst < 3e-8,
	   "h = %g r0, patch %g: the tail's impulse response is its step's derivative to %.1e of 2 alpha*",
	   hh, patch, worst);
	anvil_plate_tail_free(&tl);
	free(ramp);
}

/* The closed form beyond T1 against the response before this change: the
 * same model sampled at the inversion's step dtau to the window's end and
 * interpolated by a natural cubic spline.  They differ by that spline's
 * interpolation error, (5/384) dtau^4 max |g''''| with g'''' ~ c/t^3 (the
 * t log t term) and K's: below 1e-12 of the response beyond T1 + 64 dtau
 * (nearer T1 the old samples held the blend, which the spline's pad still
 * holds).  Checked at points off the sample grid, to 7 T1 (the natural
 * end at 8 T1 is the old spline's own). */
static void test_against_samples(double hh)
{
	double t1 = t1_of(hh), tau_end = 8.0 * t1;
	struct anvil_green *g = make(hh, tau_end, 2.0, 0, NULL);
	if (!g) {
		ok(0, "h = %g r0: response made", hh);
		return;
	}
	struct anvil_green_samples s;
	anvil_green_export(g, &s);
	size_t n = (size_t)floor(tau_end / s.dtau) + 2;
	double *x = malloc(2 * n * sizeof *x), *y = x + n, worst = 0;
	for (size_t j = 0; j < n; j++) {
		x[j] = (double)j * s.dtau;
		if (j < s.n)
			y[j] = s.ramp[j];
		else
			anvil_green_ramp(g, fmin(x[j], tau_end), &y[j]);
	}
	gsl_interp *sp = gsl_interp_alloc(gsl_interp_cspline, n);
	gsl_interp_accel *acc = gsl_interp_accel_alloc();
	gsl_interp_init(sp, x, y, n);
	for (double t = t1 + 64.0 * s.dtau + 0.37 * s.dtau; t < 7.0 * t1; t += 13.1 * s.dtau) {
		double a, b = gsl_interp_eval(sp, x, y, t, acc);
		anvil_green_ramp(g, t, &a);
		worst = fmax(worst, fabs(a - b) / fabs(b));
	}
	ok(worst < 1e-12, "h = %g r0: the closed form beyond T1 = %g is the old sampled tail to "
	   "%.1e (its spline's interpolation error at dtau = %.3g)", hh, t1, worst, s.dtau);
	gsl_interp_accel_free(acc);
	gsl_interp_free(sp);
	free(x);
	test_k_table(g, hh);
	anvil_green_free(g);
}

/* At T1 the ramp goes from the samples' spline to the closed form: the
 * samples there are the model's, so ramp and step join to the spline's
 * interpolation error (the step: its derivative's, O(dtau^3)). */
static void test_join(double hh)
{
	double t1 = t1_of(hh);
	struct anvil_green *g = make(hh, 16.0 * t1, 2.0, 0, NULL);
	if (!g) {
		ok(0, "h = %g r0: response made", hh);
		return;
	}
	double tp = anvil_green_t_plate(g), above = nextafter(tp, INFINITY), r0, r1, s0, s1;
	anvil_green_ramp(g, tp, &r0);
	anvil_green_ramp(g, above, &r1);
	anvil_green_step(g, tp, &s0);
	anvil_green_step(g, above, &s1);
	double dr = fabs(r1 - r0) / fabs(r0), ds = fabs(s1 - s0) / fabs(s0);
	ok(dr < 1e-13 && ds < 1e-8, "h = %g r0: at T1 the ramp joins to %.1e, the step to %.1e",
	   hh, dr, ds);
	/* the closed form's step is its ramp's derivative (analytic, not a
	 * difference: checked against one) */
	double t = 3.3 * t1, d = 1e-3 * t1, rp, rm, st;
	anvil_green_ramp(g, t + d, &rp);
	anvil_green_ramp(g, t - d, &rm);
	anvil_green_step(g, t, &st);
	double fd = (rp - rm) / (2.0 * d);
	ok(fabs(fd - st) < 1e-8 * fabs(st), "h = %g r0: the tail's step = d ramp/dt (%.1e)", hh,
	   fabs(fd - st) / fabs(st));
	anvil_green_free(g);
}

static int same_at(const struct anvil_green *a, const struct anvil_green *b, double lo,
		   double hi)
{
	for (double t = lo; t < hi; t += 0.01731 * (hi - lo)) {
		double x, y, u, v;
		anvil_green_ramp(a, t, &x);
		anvil_green_ramp(b, t, &y);
		anvil_green_step(a, t, &u);
		anvil_green_step(b, t, &v);
		if (memcmp(&x, &y, sizeof x) || memcmp(&u, &v, sizeof u))
			return 0;
	}
	return 1;
}

/* A window 1e6 T1 long: the inversion and the samples are T1's, the K
 * table O(log tau_end); below 8 T1 the same bits as a 16 T1 window's (the
 * fit is over [T1/4, T1], T1 does not depend on the window, and the K
 * table's interpolant is local), also when a memo held the longer table
 * first. */
static void test_long_window(void)
{
	double hh = 0.5, t1 = t1_of(hh);
	struct anvil_plate_memo *m = anvil_plate_memo_alloc();
	struct anvil_green *l = make(hh, 1e6 * t1, 2.0, 0, m);
	struct anvil_green *sm = make(hh, 16.0 * t1, 2.0, 0, m);
	struct anvil_green *s0 = make(hh, 16.0 * t1, 2.0, 0, NULL);
	if (!l || !sm || !s0) {
		ok(0, "windows 1e6 T1 and 16 T1 made");
		goto out;
	}
	struct anvil_green_samples a, b;
	anvil_green_export(l, &a);
	anvil_green_export(sm, &b);
	ok(a.n == b.n && anvil_green_evals(l) == anvil_green_evals(s0),
	   "window 1e6 T1: %zu samples and %zu evaluations, as a 16 T1 window (K table: %zu "
	   "nodes against %zu)", a.n, anvil_green_evals(l), a.nk, b.nk);
	ok(same_at(l, s0, 1e-3, 8.0 * t1) && same_at(sm, s0, 1e-3, 16.0 * t1),
	   "  its ramp and step below 8 T1 have the 16 T1 window's bits (also from the memo)");
	double v = a.tail_v, e1 = anvil_green_abserr_at(l, 1e5 * t1);
	ok(anvil_green_abserr(l) == anvil_green_abserr(s0) && v > 0 &&
		   fabs(e1 - (anvil_green_abserr(l) + v * (1e5 * (1.0 + log(1e5)) - 1.0))) <= 1e-12 * e1,
	   "  its error bound: %.3g to T1, by v (x (1 + log x) - 1) beyond, not by the window "
	   "(v = %.3g, %.3g at 1e5 T1)",
	   anvil_green_abserr(l), v, e1);
	double r, want = 1.0 / (8.0 * (hh / sqrt(6.0 * 0.7)) * hh) * 0.5;
	anvil_green_ramp(l, 1e6 * t1, &r);
	double tt = 1e6 * t1;
	ok(fabs(r / (tt * tt) - want) < 1e-4 * want,
	   "  at 1e6 T1 the ramp is the plate's alpha* t^2/2 to %.1e", fabs(r / (tt * tt) - want) / want);
out:
	anvil_green_free(l);
	anvil_green_free(sm);
	anvil_green_free(s0);
	anvil_plate_memo_free(m);
}

/* The cache's file (format 11): a tailed response written and read back
 * gives the same bits, beyond T1 too; a damaged tail (a coefficient, a
 * node) is refused by the importer. */
static void test_cache(void)
{
	double hh = 0.1, t1 = t1_of(hh);
	char dir[] = "/tmp/anvil-test-tail-XXXXXX", path[4096];
	struct anvil_cache_key key = { hh, 0.3, ANVIL_ACC_DRAFT, 4, 40, 0, ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
	struct anvil_err e;
	struct anvil_green *g = make(hh, anvil_cache_grid(key.tau_idx), anvil_cache_grid(key.omega_idx),
				     0, NULL);
	if (!g || !mkdtemp(dir)) {
		ok(0, "a tailed response and a directory");
		anvil_green_free(g);
		return;
	}
	anvil_cache_path(dir, &key, path, sizeof path);
	int rc = anvil_cache_write(path, &key, g, &e);
	struct anvil_green *h = anvil_cache_read(path, &key, &e);
	struct anvil_green_samples x, y;
	anvil_green_export(g, &x);
	if (h)
		anvil_green_export(h, &y);
	double tend = anvil_cache_grid(key.tau_idx);
	ok(!rc && h && x.n == y.n && x.nk == y.nk && x.t1 == y.t1 &&
		   !memcmp(x.ramp, y.ramp, x.n * sizeof *x.ramp) &&
		   !memcmp(x.k, y.k, x.nk * sizeof *x.k) &&
		   !memcmp(x.shear, y.shear, x.nk * sizeof *x.shear) &&
		   !memcmp(x.tail_c, y.tail_c, sizeof x.tail_c) && same_at(g, h, 1e-3, tend),
	   "cache: a tailed response (window %g = %.3g T1, %zu samples, %zu nodes) read back to "
	   "the bit, beyond T1 too", tend, tend / t1, x.n, x.nk);
	anvil_green_free(h);
	struct anvil_green_samples z = x;
	z.tail_c[1] *= 1.0 + 1e-12;
	h = anvil_green_import(&z, &e);
	ok(!h, "  a fitted coefficient off by 1e-12: refused (%s)", h ? "" : e.msg);
	anvil_green_free(h);
	double *k = malloc(x.nk * sizeof *k);
	memcpy(k, x.k, x.nk * sizeof *k);
	k[x.nk / 2] = -k[x.nk / 2];
	z = x;
	z.k = k;
	h = anvil_green_import(&z, &e);
	ok(!h, "  a K node negative: refused");
	anvil_green_free(h);
	double *sh = malloc(x.nk * sizeof *sh);
	memcpy(sh, x.shear, x.nk * sizeof *sh);
	sh[x.nk / 2] = NAN;
	z = x;
	z.shear = sh;
	h = anvil_green_import(&z, &e);
	ok(!h, "  an S node not finite: refused");
	anvil_green_free(h);
	free(sh);
	z = x;
	z.nk--;
	h = anvil_green_import(&z, &e);
	ok(!h, "  a K table short of the window: refused");
	anvil_green_free(h);
	z = x;
	z.t1 = 0;
	h = anvil_green_import(&z, &e);
	ok(!h, "  a long window without its tail: refused");
	anvil_green_free(h);
	free(k);
	unlink(path);
	rmdir(dir);
	anvil_green_free(g);
}

static void test_t_plate(void)
{
	struct anvil_green *a = make(0.5, 16.0 * 32.0, 2.0, 0, NULL);
	struct anvil_green *b = make(2.0, 16.0 * 64.0, 2.0, 0, NULL);
	struct anvil_green *b8 = make(8.0, 2.0 * 128.0, 2.0, 0, NULL);
	struct anvil_green *c = make(0.5, 3.9 * 32.0, 2.0, 0, NULL);
	struct anvil_green *c8 = make(8.0, 1.9 * 128.0, 2.0, 0, NULL);
	struct anvil_green *d = make(0.5, 8.0 * 32.0, 2.0, 1, NULL);
	struct anvil_green_settings gs;
	struct anvil_err e;
	anvil_green_settings(ANVIL_ACC_DRAFT, &gs);
	gs.omega_max = 2.0;
	struct anvil_green *hs = anvil_green_alloc(ANVIL_GREEN_HALFSPACE, 1.0, 0.3, 20.0, &gs, NULL,
						   NULL, &e);
	ok(a && b && b8 && c && c8 && d && hs && anvil_green_t_plate(a) == 32.0 &&
		   anvil_green_t_plate(b) == 64.0 && anvil_green_t_plate(b8) == 128.0 &&
		   isinf(anvil_green_t_plate(c)) && isinf(anvil_green_t_plate(c8)) &&
		   isinf(anvil_green_t_plate(d)) && isinf(anvil_green_t_plate(hs)),
	   "t_plate: 32 below h = r0, max(64, 16 h/r0) from there (32 at h = 0.5, 64 at h = 2, "
	   "128 at h = 8); infinite for a window under 4 T1 (thin) or 2 T1 (from h = r0), "
	   "no_plate and the half-space");
	anvil_green_free(b8);
	anvil_green_free(c8);
	anvil_green_free(a);
	anvil_green_free(b);
	anvil_green_free(c);
	anvil_green_free(d);
	anvil_green_free(hs);
	ok(anvil_green_fits(ANVIL_GREEN_LAYER_CORRECTION, 0.02, 1e12, 8.0) &&
		   !anvil_green_fits(ANVIL_GREEN_HALFSPACE, 0.02, 1e12, 8.0) &&
		   anvil_plan_corr_samples(0.02, 8.0, 1e12) == anvil_plan_corr_samples(0.02, 8.0, 1e3),
	   "planner: a 1e12 window fits with the tail (as many samples as a 1e3 one: %.0f), "
	   "not without", anvil_plan_corr_samples(0.02, 8.0, 1e12));
}

int main(void)
{
	gsl_set_error_handler_off();
	const double hs[] = { 0.1, 0.5, 2.0 };
	for (int i = 0; i < 3; i++) {
		test_against_samples(hs[i]);
		test_join(hs[i]);
	}
	test_s_quadrature();
	test_k_quadrature();
	test_s_coefficients();
	test_s_table_thin();
	test_fill(0.02, 0.5);
	test_fill(0.1, 1.0);
	test_impulse(0.02, 1.0);
	test_impulse(0.1, 0.5);
	test_long_window();
	test_cache();
	test_t_plate();
	plan(tap_n);
	return done_testing();
}
