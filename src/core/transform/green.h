/* green.h: the layer's centre response, by Laplace-Hankel transforms.
 *
 * Dimensionless throughout: lengths in r0, time tau = t c2/r0, displacement
 * per newton in 1/(mu r0).  The free layer of thickness h (both faces
 * traction-free) under the Hertz-shaped patch Z(r) (eq 7) is written as
 *
 *     layer = half-space + (layer - half-space),
 *
 * and this module computes the second part, the "layer correction", whose
 * k-integrand decays like exp(-k h) and which is exactly zero until the
 * first reflection returns at tau = 2 h c2/c1 (causality).  The half-space
 * part comes from halfspace.h (an exact route) or, for cross-checks, from
 * this module's mode ANVIL_GREEN_HALFSPACE (the same transform route).
 *
 * Method: Fourier-series inversion of the Laplace transform on the Bromwich
 * line s = c0 + i n pi/T' (Durbin), summed by FFT; the k-integral at each s
 * by globally adaptive Gauss-Kronrod quadrature, which resolves the
 * Lamb-mode poles (at about c0/c_group from the real k axis) wherever they
 * are, to a tolerance derived from the time-domain target.  The
 * frequencies are computed on all cores (OpenMP, when configure finds it);
 * the result has the same bits whatever the number of threads.
 * The ramp response (load P = t) is produced: it is the smoothest of the
 * step/ramp/impulse family and the one the impact solver's product
 * integration needs.  See ../shared/design/solver.md. */
#ifndef ANVIL_GREEN_H
#define ANVIL_GREEN_H

#include <complex.h>
#include <stddef.h>

#include "accuracy.h"
#include "progress.h"
#include "status.h"

enum anvil_green_mode {
	ANVIL_GREEN_LAYER_CORRECTION, /* W_layer - W_halfspace */
	ANVIL_GREEN_HALFSPACE         /* W_halfspace - static, plus the static part */
};

/* Numerical settings of one inversion; anvil_green_settings() gives the ones
 * an accuracy level uses. */
struct anvil_plate_memo; /* plate.h */

struct anvil_green_settings {
	double c0T;     /* c0 times the half period T' */
	double omega_max; /* highest frequency summed (dimensionless) */
	double tol;     /* ramp error target, relative to its half-space size */
	double ktail;   /* integrand cut-off: exp(-2 Re(alpha1) H) below this */
	int no_plate;   /* 1: invert over the whole window, never the plate beyond
			   (plate.h; for tests: the second method) */
	int filter;     /* 1: Vandeven's filter on the band (durbin.h), each
			   inversion (the twin's too) on its own terms: the
			   physical contact's corrections (green.c says why);
			   0: the plain truncated series (the paper's contact) */
	struct anvil_plate_memo *plate; /* the plate's K(t) table kept from one
			   response to the next (plate.h; borrowed, NULL: kept for a
			   response and its twin only) */
	double lift_patch; /* the widest patch (r0 units, in (0, 1]) whose zhat the
			   band's lifted contour must carry (kernel.h anvil_kband_lift:
			   at most 8/lift_patch above the axis); 0: r0's (1).  The
			   physical contact's point and patch loads share the row's
			   widest patch, hence one contour and the kernel's values
			   (anvil_green_alloc_set): a small patch lifts the band
			   higher, in fewer pieces.  A load's patch must not exceed it. */
};

void anvil_green_settings(enum anvil_accuracy acc, struct anvil_green_settings *gs);

struct anvil_green;

/* Compute the ramp response on [0, tau_end] for a layer of thickness hh = h/r0
 * (ignored for ANVIL_GREEN_HALFSPACE) and Poisson ratio nu.  progress may be
 * NULL; a non-zero return from it cancels (NULL returned, err ANVIL_ECANCEL).
 * The caller owns the result; free with anvil_green_free. */
struct anvil_green *anvil_green_alloc(enum anvil_green_mode mode, double hh,
				      double nu, double tau_end,
				      const struct anvil_green_settings *gs,
				      anvil_progress_fn progress, void *ctx,
				      struct anvil_err *err);
/* The same, and in *twin (when twin is not NULL) its coarse twin: the
 * response at half the bandwidth (gs->omega_max / 2) over the same window,
 * from the first terms of the same spectrum (the twin's frequencies are a
 * subset of the main one's), at no extra kernel evaluation.  Its k-integrals
 * meet the main response's (tighter) tolerance; its error estimate is over
 * its own terms.  The caller owns both (*twin NULL on failure). */
struct anvil_green *anvil_green_alloc_twin(enum anvil_green_mode mode, double hh, double nu,
					   double tau_end, const struct anvil_green_settings *gs,
					   anvil_progress_fn progress, void *ctx,
					   struct anvil_green **twin, struct anvil_err *err);
void anvil_green_free(struct anvil_green *g);
/* 1 if a response over [0, tau_end] at bandwidth omega_max fits this
 * module's limits (ANVIL_DURBIN_M_MAX terms, at most 2^21 + 2 samples over
 * the inversion's window: a long window of a layer correction is inverted
 * over the plate's T1 only, whatever its length, and continued in closed
 * form), by the arithmetic green_compute uses with the default settings;
 * 0 if anvil_green_alloc would refuse it.  The planner asks before any
 * work. */
int anvil_green_fits(enum anvil_green_mode mode, double hh, double tau_end, double omega_max);
/* The same for the Hertz-shaped load of radius patch r0, 0 <= patch <= 1
 * (ANVIL_GREEN_LAYER_CORRECTION only; anvil_green_alloc is patch = 1).
 * patch = 0 is a point load: the correction (layer less half-space) stays
 * finite, its integrand decaying like exp(-k h); that is what the physical
 * contact needs (impact.h), the static indentation being Hertz's.  Against
 * the true contact radius a its error is O((a/h)^2) (doc/contact-model.md).
 * It has no twin.  A long window is continued by the plate as for r0
 * (plate.h), K being this patch's Kirchhoff response. */
struct anvil_green *anvil_green_alloc_patch(enum anvil_green_mode mode, double hh, double nu,
					    double patch, double tau_end,
					    const struct anvil_green_settings *gs,
					    anvil_progress_fn progress, void *ctx,
					    struct anvil_err *err);

/* Several layer corrections over one window, load[i] the Hertz patch
 * (radius patch r0, 0..1; 0 a point load) and bandwidth of out[i]: each
 * the same bits as anvil_green_alloc_patch with gs and that omega_max
 * would give it alone (the physical contact's four: the point load and
 * the patch at the band, the patch below, the point load at half the
 * band), at the cost of little more than one: their spectra share the
 * line, and at each frequency the layer's kernel, which does not depend
 * on the patch, is evaluated once per wavenumber node for all of them.
 * 1 <= n <= 8; gs->omega_max ignored.  anvil_green_evals of each: the
 * kernel evaluations made for it (a node already evaluated for an
 * earlier one of the set costs none).  The caller owns out[0..n-1]; on
 * failure all NULL and the status returned (err set). */
struct anvil_green_load {
	double patch, omega_max;
};
int anvil_green_alloc_set(double hh, double nu, double tau_end,
			  const struct anvil_green_settings *gs,
			  const struct anvil_green_load *load, size_t n,
			  anvil_progress_fn progress, void *ctx, struct anvil_green **out,
			  struct anvil_err *err);

/* Ramp response at tau in [0, tau_end] (0 for tau <= 0): cubic
 * interpolation of the FFT grid up to anvil_green_t_plate, the plate's
 * closed form beyond (plate.h: no samples there, so that a response's
 * memory and time do not grow with its window but for the plate's K
 * table, O(log tau_end)).  ANVIL_EINVAL beyond tau_end. */
int anvil_green_ramp(const struct anvil_green *g, double tau, double *val);
/* Step response (derivative of the ramp: the spline's, or the closed
 * form's analytic one). */
int anvil_green_step(const struct anvil_green *g, double tau, double *val);
/* The tau from which the ramp is the plate's closed form (plate.h: the
 * inversion's window T1: 32 below h = r0, max(64, 16 h/r0) from there): smooth there, without the
 * band limit's ringing (K's table is a C2 interpolant, within 3e-9 of
 * the plate at h = 0.02 r0 and closer on thicker plates); over [T1/2, T1]
 * the samples go from the inversion to it.  INFINITY when the response is
 * the inversion everywhere (a window shorter than 4 T1, 2 T1 from h = r0, the half-space
 * mode, no_plate). */
double anvil_green_t_plate(const struct anvil_green *g);
/* The impulse response (the ramp's second derivative) in the closed form
 * at tau in (anvil_green_t_plate, tau_end]; ANVIL_EINVAL elsewhere (the
 * caller differences the ramp there). */
int anvil_green_impulse(const struct anvil_green *g, double tau, double *val);

/* The transformed centre displacement per unit Hankel-transformed load at
 * one (k, s), Re s > 0, units mu = c2 = r0 = 1: the free layer of thickness
 * hh (its stable symmetric/antisymmetric form) and the half-space.  For
 * tests and for anyone checking the algebra. */
void anvil_green_kernel(double k, double complex s, double nu, double hh,
			double complex *layer, double complex *halfspace);

double anvil_green_tau_end(const struct anvil_green *g);
/* Estimated absolute error of the ramp response over [0, tau_end]; with
 * the plate's tail, over [0, t_plate] only: beyond, the fit's error grows
 * with the extrapolation's length, and anvil_green_abserr_at gives it. */
double anvil_green_abserr(const struct anvil_green *g);
/* The bound at tau: anvil_green_abserr, and beyond t_plate = T1 that plus
 * v (x (1 + log x) - 1), x = tau/T1, v the plate fit's extrapolation unit
 * (plate.h, anvil_plate_tail_err: the validation's misfit or the two
 * fits' coefficients apart, the larger), which tau_end does not multiply
 * (a window 1e6 T1 long would have carried 1e6 v at every tau). */
double anvil_green_abserr_at(const struct anvil_green *g, double tau);
/* Number of kernel evaluations spent (for benchmarks). */
size_t anvil_green_evals(const struct anvil_green *g);

/* The sampled ramp response, to store it (cache.h) and read it back:
 * ramp[j] at tau = j dtau, j < n, ramp[0] = 0, n = floor(tau_end/dtau) + 2,
 * or with the plate's tail (t1 > 0, anvil_green_t_plate), n =
 * floor(t1/dtau) + 2 + ANVIL_PLATE_PAD and what rebuilds the closed form
 * beyond t1 to the bit (plate.h's struct anvil_plate_tail). */
struct anvil_green_samples {
	enum anvil_green_mode mode;
	int filtered; /* 1: made with gs.filter (its precursor, green.c) */
	double hh, nu, tau_end, dtau, abserr;
	double patch;     /* the load's radius / r0 (0: a point load; 1: the paper's) */
	size_t n;
	const double *ramp;
	double t1;        /* 0: no tail (nk 0, k NULL); its K is the patch's (plate.h) */
	double tail_c[3]; /* the fit's coefficients */
	double tail_v;    /* its validation misfit (anvil_green_abserr_at) */
	size_t nk;        /* the K(t)/t^2 table, k[0..nk-1] */
	const double *k;
	const double *shear; /* the S(t)/t table (Mindlin's term), shear[0..nk-1] */
	/* the natural spline's c_i = y''(tau_i)/2 through the samples, curv[0..n-1]
	 * (GSL's cspline system, green.c spline_cs), as made; NULL: import
	 * solves for them (the disk cache keeps them: a warm run's import then
	 * skips the tridiagonal solve, whose chain of divisions took a tenth
	 * of a warm physical row) */
	const double *curv;
};

/* Fill s from g; s->ramp, s->k and s->shear are borrowed from g (valid
 * while g lives). */
void anvil_green_export(const struct anvil_green *g, struct anvil_green_samples *s);
/* A response from samples (copied; the spline is rebuilt from them and
 * curv, or from them alone when curv is NULL: either way it evaluates to
 * the bit as the exported one did).  Its evals count is 0.
 * NULL with ANVIL_EINVAL for inconsistent sizes or window (checked before
 * any cast or allocation: at most 2^21 + 2 samples) or implausible samples
 * (ramp[0] != 0, non-finite, abserr <= 0, a layer correction that breaks
 * causality: see green.c; curv not finite or not 0 at the ends; a tail
 * whose table is implausible or which does not give the samples beyond t1
 * to the bit), ANVIL_ENOMEM, ANVIL_ENUM. */
struct anvil_green *anvil_green_import(const struct anvil_green_samples *s,
				       struct anvil_err *err);
/* 1 if import would take s's samples as plausible (the checks above, not
 * the sizes): the cache writes only what its reader will take back. */
int anvil_green_samples_plausible(const struct anvil_green_samples *s);

#endif
