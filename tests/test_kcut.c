/* test_kcut.c: the k-integral's cut in each term's error budget
 * (green_spectrum.c k_integral).
 *
 * Each term's k-integral runs to a finite kend; what lies beyond must be
 * in the term's error estimate.  For each case (mode, thickness, patch,
 * line, accuracy level) the spectrum is computed as the solver asks for
 * it (the level's c0T, ktail and per-term budget, as green.c sets it), and
 * again cut far (green_spectrum.h far_cut at ktail 1e-16, so kend runs
 * 1.6 times as far in the layer's exp(-2 k hh) and 3.2 times in the
 * half-space's k^-4) with a budget 100 times tighter; every term must
 * agree within the two estimates plus ROUND of its size (the rounding
 * floors of a thin plate's lowest terms, as test_lift.c).  The check has
 * teeth: with kend where exp(-2 k hh) fell below the level's ktail (the
 * cut before the remainder was counted) h = 0.02 r0 under a point load at
 * T' = 16 was off on 323 of its 801 terms, the worst 5920 times its
 * allowance.
 *
 * Beyond the band the normal and fine runs take the layer correction's
 * kernel from its interpolant (green_tail.h), the far ones evaluate it:
 * the comparison covers the interpolant too.  And the interpolant itself:
 * on each panel, at 64 points, B from it against B from the kernel,
 * within the panel's delta (its estimate, without the factor 2 on it in
 * k_integral), on thin layers (h = 0.02-0.1 r0) from omega = 0 to the A1
 * cutoff pi/hh.  That has teeth: the interpolant truncated to degree 12
 * fails at 40 % of the points, the worst 235 times its estimate. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>

#include "accuracy.h"
#include "green_spectrum.h"
#include "green_tail.h"
#include "kernel.h"
#include "layer_bc.h"
#include "material.h"
#include "tap.h"

#define ROUND 1e-13

struct run {
	size_t M, evals;
	int st;
	double complex *F;
	double *e;
};

/* One spectrum of mode on the line (Tp, the level's c0T, omega_max); its
 * budget per term as green.c spectrum_init's, over tight. */
static int run(struct run *r, enum anvil_green_mode mode, double hh, double patch, double Tp,
	       double omega_max, enum anvil_accuracy acc, int far)
{
	double nu = 0.3, kap2 = anvil_kappa2(nu), xr;
	const struct anvil_level *lv = anvil_level(acc);
	struct anvil_durbin dl;
	if (anvil_rayleigh_x(kap2, &xr, NULL) ||
	    anvil_durbin_init(&dl, Tp, lv->green_c0T / Tp, omega_max, 0))
		return -1;
	struct green_plate pl = green_plate_term(mode, hh, nu);
	double scale = 3.0 / (16.0 * (1.0 - kap2)) * 0.5 * Tp, amp = exp(0.5 * lv->green_c0T) / Tp;
	double epsF = lv->green_tol * scale / (amp * (double)(dl.M + 1)) * (far ? 0.01 : 1.0);
	r->M = dl.M;
	r->F = malloc((dl.M + 1) * sizeof *r->F);
	r->e = malloc((dl.M + 1) * sizeof *r->e);
	if (!r->F || !r->e)
		return -1;
	struct green_spectrum sp = { .dl = &dl, .cr = sqrt(xr),
				     .ktail = far ? 1e-16 : lv->green_ktail, .far_cut = far,
				     .epsF = epsF, .pl = &pl, .patch = patch, .spec = r->F,
				     .err = r->e };
	r->st = green_sample_spectra(mode, kap2, nu, hh, &sp, 1, &r->evals);
	return 0;
}

static void cut(enum anvil_green_mode mode, double hh, double patch, double Tp, double omega_max,
		enum anvil_accuracy acc)
{
	struct run a = { 0 }, b = { 0 };
	double worst = 0, wom = 0;
	size_t bad = 0;
	int st = run(&a, mode, hh, patch, Tp, omega_max, acc, 0) ||
		 run(&b, mode, hh, patch, Tp, omega_max, acc, 1);
	for (size_t n = 0; !st && n <= a.M; n++) {
		double q = cabs(a.F[n] - b.F[n]) / (a.e[n] + b.e[n] + ROUND * cabs(b.F[n]));
		bad += !(q <= 1.0);
		if (!(q <= worst)) {
			worst = q;
			wom = (double)n * M_PI / Tp;
		}
	}
	ok(!st && (a.st == ANVIL_OK || a.st == ANVIL_ETOL) && (b.st == ANVIL_OK || b.st == ANVIL_ETOL) &&
		   bad == 0,
	   "%s h = %g r0, patch %g, T' = %g, %s: the cut within the estimates on %zu of %zu terms "
	   "(worst %.3g of the allowance at omega = %.3g); evaluations %zu (far: %zu)",
	   mode == ANVIL_GREEN_HALFSPACE ? "half-space" : "layer", hh, patch, Tp,
	   anvil_accuracy_name(acc), st ? 0 : a.M + 1 - bad, a.M + 1, worst, wom, a.evals, b.evals);
	free(a.F);
	free(a.e);
	free(b.F);
	free(b.e);
}

static double one(void *ctx, double K)
{
	(void)ctx;
	(void)K;
	return 1.0;
}

/* B = W_c k exp(2 k hh)/(1 + k hh)^2 (green_tail.h) from the kernel */
static double complex b_kernel(double k, double complex s, double kap2, double hh)
{
	struct anvil_layer_bc bc;
	anvil_layer_bc_solve(k, s, kap2, hh, &bc);
	double q = 1.0 + k * hh;
	return anvil_layer_bc_w_correction(&bc) * k * exp(2.0 * hh * k) / (q * q);
}

/* allow 0: every panel at the larger degree (where its estimate is the
 * smaller); INFINITY: at the lower */
static void interpolant(double hh, double allow)
{
	double nu = 0.3, kap2 = anvil_kappa2(nu), xr, worst = 0, c0 = 2.5 / 16.0;
	size_t n = 0, bad = 0, evals = 0, panels = 0;
	int refused = 0;
	anvil_rayleigh_x(kap2, &xr, NULL);
	for (int m = 0; m <= 40; m++) {
		double om = m * M_PI / hh / 40.0, wabs = hypot(om, c0);
		double complex s = anvil_kernel_cmplx(c0, om);
		double kb = anvil_kband(om, wabs, nu, hh, sqrt(xr));
		double kend = sqrt(pow(0.5 * -log(1e-10) / hh, 2) + om * om);
		if (!(kend - kb > 64.0))
			continue;
		struct green_tail t = { 0 };
		green_tail_key(&t, s, kap2, hh, kb, kend);
		refused += !isfinite(green_tail_bound(&t, kend, one, NULL, allow, &evals));
		for (int i = 0; i < t.np; i++, panels++)
			for (int j = 0; j < 64 && t.p[i].n > 0; j++, n++) {
				double k = t.a[i] + (j + 0.5) / 64.0 * (t.a[i + 1] - t.a[i]), q = 1.0 + k * hh;
				double complex bi = green_tail_w(&t, k) * k * exp(2.0 * hh * k) / (q * q);
				double r = cabs(bi - b_kernel(k, s, kap2, hh)) / t.p[i].delta;
				bad += !(r <= 1.0);
				worst = fmax(worst, r);
			}
	}
	ok(n > 0 && bad == 0 && !refused,
	   "the tail's interpolant on h = %g r0 (%s degree): B within the panel's estimate at %zu "
	   "of %zu points (worst %.3g of it; %zu panels, %zu evaluations)",
	   hh, allow > 0 ? "lower" : "higher", n - bad, n, worst, panels, evals);
}

int main(void)
{
	gsl_set_error_handler_off();
	const enum anvil_accuracy lv[2] = { ANVIL_ACC_NORMAL, ANVIL_ACC_FINE };
	plan(24);
	for (int i = 0; i < 2; i++) {
		interpolant(0.02, i ? INFINITY : 0.0);
		interpolant(0.05, i ? INFINITY : 0.0);
		interpolant(0.1, i ? INFINITY : 0.0);
	}
	for (int i = 0; i < 2; i++) {
		cut(ANVIL_GREEN_LAYER_CORRECTION, 0.02, 0.0, 16.0, M_PI / 0.02, lv[i]);
		cut(ANVIL_GREEN_LAYER_CORRECTION, 0.02, 1.0, 16.0, M_PI / 0.02, lv[i]);
		cut(ANVIL_GREEN_LAYER_CORRECTION, 0.1, 0.0, 32.0, M_PI / 0.1, lv[i]);
		cut(ANVIL_GREEN_LAYER_CORRECTION, 0.1, 0.35, 32.0, M_PI / 0.1, lv[i]);
		cut(ANVIL_GREEN_LAYER_CORRECTION, 1.0, 0.0, 32.0, 30.0, lv[i]);
		cut(ANVIL_GREEN_LAYER_CORRECTION, 1.0, 1.0, 32.0, 30.0, lv[i]);
		cut(ANVIL_GREEN_LAYER_CORRECTION, 10.0, 0.0, 32.0, 30.0, lv[i]);
		cut(ANVIL_GREEN_LAYER_CORRECTION, 10.0, 1.0, 32.0, 30.0, lv[i]);
		cut(ANVIL_GREEN_HALFSPACE, INFINITY, 1.0, 16.0, 30.0, lv[i]);
	}
	return done_testing();
}
