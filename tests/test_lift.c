/* test_lift.c: the layer correction's band on a lifted k-contour (kernel.h
 * anvil_kband_lift, green_spectrum.c).
 *
 * Lifting the band's path off the real axis is exact (Cauchy) only if no
 * pole or branch point of W(k, s) lies between the two paths.  For each
 * case (thickness, Poisson's ratio, patch, line) the spectrum is computed
 * twice, on the lifted contour and on the real axis (green_spectrum.h
 * no_lift), at every term up to 1.05 times where the whole band's lift stops
 * (kernel.h anvil_lift_cutoff: 0.8 of S1's cutoff, past the A1 cutoff
 * omega = pi/hh; 0.9 of A1's before), and each term must agree within the two error
 * estimates plus ROUND of its size: the estimates of the lowest terms on
 * a thin plate are their rounding floors (green_spectrum.c ROUND_STOP),
 * not bounds, and there the two paths differed by up to 2.0 times their
 * sum, 1e-14 of the value.  The check has teeth: with the lift carried to
 * 3 times the cutoff, terms at omega hh/pi = 1.75-1.81 (nu = 0.3, S1's
 * backward wave, whose pole lies above the axis) were off by 1e5-1e6
 * times their estimates.  Above the cutoff the band is lifted from
 * k hh = ANVIL_LIFT_KS on, to omega hh = ANVIL_LIFT_TOP pi: there the
 * terms are compared to 1.05 times that (from k hh = 0.3 the two paths
 * were 3.5e6 times the allowance apart).  A last test holds the rounding stop: the
 * omega = 0 term of h = 0.02 r0 on a long line, whose tolerance is below
 * its rounding floor, took 343 056 evaluations (8191 pieces) to end where
 * it began. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>

#include "green_spectrum.h"
#include "kernel.h"
#include "material.h"
#include "tap.h"

/* A few hundred ulp of the term: the kernel's own rounding (its stable
 * forms, layer_bc.c) on two different paths. */
#define ROUND 1e-13

struct spectra {
	size_t M, evals[2];
	int st[2];
	double complex *F[2];
	double *e[2];
};

/* Both paths' spectra of the layer correction on the line of half period
 * Tp, c0 = 10/Tp (the normal level's c0T), up to omega_max, with epsF; the
 * lifted one's contour for the widest patch wide (green.h lift_patch). */
static double wide = 0.0;

/* the band's small starting pieces to its end (green_spectrum.h full_band) */
static int full_band[2] = { 0, 0 };

static int spectra_kt(struct spectra *r, double hh, double nu, double patch, double Tp,
		      double omega_max, double epsF, const double ktail[2], const int no_lift[2])
{
	double kap2 = anvil_kappa2(nu), xr;
	struct anvil_durbin dl;
	if (anvil_rayleigh_x(kap2, &xr, NULL) || anvil_durbin_init(&dl, Tp, 10.0 / Tp, omega_max, 0))
		return -1;
	struct green_plate pl = green_plate_term(ANVIL_GREEN_LAYER_CORRECTION, hh, nu);
	r->M = dl.M;
	for (int i = 0; i < 2; i++) {
		r->F[i] = malloc((dl.M + 1) * sizeof *r->F[i]);
		r->e[i] = malloc((dl.M + 1) * sizeof *r->e[i]);
		if (!r->F[i] || !r->e[i])
			return -1;
		struct green_spectrum sp = { .dl = &dl, .cr = sqrt(xr), .ktail = ktail[i],
					     .epsF = epsF, .pl = &pl, .patch = patch,
					     .no_lift = no_lift[i], .lift_patch = wide,
					     .full_band = full_band[i],
					     .spec = r->F[i], .err = r->e[i] };
		r->st[i] = green_sample_spectra(ANVIL_GREEN_LAYER_CORRECTION, kap2, nu, hh, &sp, 1,
						&r->evals[i]);
	}
	return 0;
}

/* Lifted (F[0]) and on the real axis (F[1]), both cut at ktail 1e-10. */
static int spectra(struct spectra *r, double hh, double nu, double patch, double Tp,
		   double omega_max, double epsF)
{
	const double kt[2] = { 1e-10, 1e-10 };
	const int nl[2] = { 0, 1 };
	return spectra_kt(r, hh, nu, patch, Tp, omega_max, epsF, kt, nl);
}

static void spectra_free(struct spectra *r)
{
	for (int i = 0; i < 2; i++) {
		free(r->F[i]);
		free(r->e[i]);
	}
}

/* The terms compared: to exp_top pi/hh (0: 1.05 times the cutoff) */
static double exp_top = 0;
static void agree(double hh, double nu, double patch, double Tp)
{
	struct spectra r = { 0 };
	double worst = 0;
	size_t wn = 0, bad = 0;
	double top = exp_top > 0 ? exp_top : 1.05 * anvil_lift_cutoff(nu);
	int st = spectra(&r, hh, nu, patch, Tp, top * M_PI / hh, 1e-9);
	for (size_t n = 0; !st && n <= r.M; n++) {
		double d = cabs(r.F[0][n] - r.F[1][n]);
		double q = d / (r.e[0][n] + r.e[1][n] + ROUND * cabs(r.F[1][n]));
		bad += !(q <= 1.0);
		if (!(q <= worst)) {
			worst = q;
			wn = n;
		}
	}
	ok(!st && (r.st[0] == ANVIL_OK || r.st[0] == ANVIL_ETOL) &&
		   (r.st[1] == ANVIL_OK || r.st[1] == ANVIL_ETOL) && bad == 0,
	   "h = %g r0, nu = %g, patch %g (contour for %g), T' = %g: lifted and real-axis band agree "
	   "on %zu of %zu terms to %.3g pi/hh (worst %.2f of the allowance at omega = %.3g); "
	   "evaluations %zu -> %zu",
	   hh, nu, patch, green_lift_wide(wide), Tp, r.M + 1 - bad, r.M + 1, top, worst,
	   (double)wn * M_PI / Tp, r.evals[1], r.evals[0]);
	spectra_free(&r);
}

/* The tail's cut (green_spectrum.c k_integral: where E1^2 falls below
 * ktail) for the Hertz patches: at ktail = 1e-10 against 1e-14 (every
 * tail 40 % longer), term by term within the two estimates plus ROUND,
 * on a thin plate to the A1 cutoff.  Measured: 0.00-0.16 of the
 * allowance.  Since the cut is chosen by each term's budget (green_cut.h)
 * ktail is only its hard limit; tests/test_kcut.c holds every term
 * against a far cut, point loads and the half-space included. */
static void tail_end(double hh, double patch, double Tp)
{
	struct spectra r = { 0 };
	const double kt[2] = { 1e-10, 1e-14 };
	const int nl[2] = { 0, 0 };
	double worst = 0;
	size_t bad = 0;
	int st = spectra_kt(&r, hh, 0.3, patch, Tp, M_PI / hh, 1e-9, kt, nl);
	for (size_t n = 0; !st && n <= r.M; n++) {
		double q = cabs(r.F[0][n] - r.F[1][n]) /
			   (r.e[0][n] + r.e[1][n] + ROUND * cabs(r.F[1][n]));
		bad += !(q <= 1.0);
		worst = fmax(worst, q);
	}
	ok(!st && bad == 0,
	   "h = %g r0, patch %g: the tail cut at 1e-10 and 1e-14 agree on %zu of %zu terms (worst "
	   "%.2f of the allowance); evaluations %zu, %zu",
	   hh, patch, r.M + 1 - bad, r.M + 1, worst, r.evals[0], r.evals[1]);
	spectra_free(&r);
}

/* A thick layer's band past its poles (kernel.h anvil_kband_poles) in one
 * starting piece (F[0]) against small pieces to the band's end (F[1]), both
 * lifted where the band is: term by term within the two estimates plus
 * ROUND, to omega_max.  The two differ where hh > 1 only.  The bisection
 * carries the rest: with the one piece from 0.7 omega/c_R (below the poles)
 * or from 0 these still agreed (worst 0.02 of the allowance), at more
 * evaluations on h = 10 and 100 r0 (12768 and 263890 where these take 10899
 * and 223696): what they hold is that the estimates stay honest. */
static void poles(double hh, double nu, double patch, double Tp, double omega_max)
{
	struct spectra r = { 0 };
	const double kt[2] = { 1e-10, 1e-10 };
	const int nl[2] = { 0, 0 };
	double worst = 0;
	size_t bad = 0;
	full_band[1] = 1;
	int st = spectra_kt(&r, hh, nu, patch, Tp, omega_max, 1e-9, kt, nl);
	full_band[1] = 0;
	for (size_t n = 0; !st && n <= r.M; n++) {
		double q = cabs(r.F[0][n] - r.F[1][n]) /
			   (r.e[0][n] + r.e[1][n] + ROUND * cabs(r.F[1][n]));
		bad += !(q <= 1.0);
		worst = fmax(worst, q);
	}
	ok(!st && (r.st[0] == ANVIL_OK || r.st[0] == ANVIL_ETOL) &&
		   (r.st[1] == ANVIL_OK || r.st[1] == ANVIL_ETOL) && bad == 0,
	   "h = %g r0, nu = %g, patch %g, T' = %g: the band past its poles in one piece and in "
	   "small ones agree on %zu of %zu terms to omega = %g (worst %.2f of the allowance); "
	   "evaluations %zu -> %zu",
	   hh, nu, patch, Tp, r.M + 1 - bad, r.M + 1, omega_max, worst, r.evals[1], r.evals[0]);
	spectra_free(&r);
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(24);
	agree(0.02, 0.3, 0.0, 16.0);
	/* the physical row's contours for its widest patch (green.h
	 * lift_patch): as high as 0.5/hh for a point load and a small patch,
	 * 8/patch for a larger one */
	wide = 0.0625;
	agree(0.02, 0.3, 0.0, 16.0);
	agree(0.02, 0.3, 0.0625, 16.0);
	wide = 0.5;
	agree(0.02, 0.3, 0.5, 16.0);
	wide = 0.0;
	/* above the cutoff, lifted from k hh = ANVIL_LIFT_KS (kernel.h), to
	 * 1.05 times ANVIL_LIFT_TOP */
	exp_top = 1.05 * ANVIL_LIFT_TOP;
	agree(0.1, 0.3, 0.0, 32.0);
	agree(0.05, 0.0, 0.0, 32.0);
	agree(0.2, 0.45, 1.0, 32.0);
	wide = 0.25;
	agree(0.05, 0.22, 0.25, 32.0);
	wide = 0.0;
	exp_top = 0.0;
	agree(0.05, 0.3, 0.5, 64.0);
	agree(0.05, 0.45, 1.0, 64.0);
	agree(0.1, 0.0, 1.0, 64.0);
	agree(0.2, 0.22, 0.5, 64.0);
	agree(0.5, 0.3, 0.0, 64.0);
	agree(2.0, 0.45, 1.0, 64.0);
	poles(1.5, 0.3, 1.0, 64.0, 6.0);
	poles(2.0, 0.45, 0.0, 64.0, 4.0);
	poles(10.0, 0.3, 1.0, 64.0, 2.0);
	poles(10.0, 0.0, 0.0, 256.0, 1.0);
	poles(100.0, 0.3, 0.0625, 1600.0, 0.5);
	tail_end(0.02, 0.35, 16.0);
	tail_end(0.02, 1.0, 16.0);
	tail_end(0.1, 1.0, 64.0);

	/* The rounding stop: omega = 0 alone (M = 0) on h = 0.02 r0, T' = 64 */
	struct spectra r = { 0 };
	int st = spectra(&r, 0.02, 0.3, 0.0, 64.0, 0.0, 1e-9);
	ok(!st && r.M == 0 && r.st[0] == ANVIL_ETOL && r.st[1] == ANVIL_ETOL && r.evals[0] < 5000 &&
		   r.evals[1] < 5000,
	   "omega = 0 on h = 0.02 r0: its tolerance below rounding, ETOL after %zu and %zu "
	   "evaluations (lifted, real axis)",
	   r.evals[0], r.evals[1]);
	double d = st ? NAN : cabs(r.F[0][0] - r.F[1][0]);
	ok(d <= r.e[0][0] + r.e[1][0] + ROUND * cabs(r.F[1][0]),
	   "and the two agree: |d| = %.3g, estimates %.3g + %.3g, value %.6g", d, r.e[0][0],
	   r.e[1][0], cabs(r.F[1][0]));
	spectra_free(&r);
	return done_testing();
}
