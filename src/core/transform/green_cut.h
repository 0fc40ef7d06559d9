/* green_cut.h: where a k-integral of the layer response may stop, and a
 * bound on what it leaves out (green_spectrum.c k_integral; internal to
 * the core).
 *
 * Beyond the band (kernel.h anvil_kband) the integrands are smooth and
 * decay: the layer correction like its E1^2 = exp(-2 Re(alpha1) hh), the
 * half-space's like k^-4 (its bracket's k^-2 times the patch's zhat).
 * The remainder past K is bounded from the integrand's envelope, pinned by
 * one kernel evaluation; the cut is the first K where that bound falls to
 * the term's share, the bound itself goes into the term's error estimate.
 * green_cut.c derives the envelopes. */
#ifndef ANVIL_GREEN_CUT_H
#define ANVIL_GREEN_CUT_H

#include <complex.h>
#include <stddef.h>

#include <gsl/gsl_roots.h>

#include "green.h"

/* One k-integral's setting: mode, s, kappa^2, nu, hh (INFINITY for the
 * half-space), the load's patch (r0 units, 0 a point; the half-space's
 * integrand has patch 1); root, a Brent solver (the caller's, allocated
 * once: gsl_root_fsolver_alloc(gsl_root_fsolver_brent)); evals counts the
 * kernel evaluations made here. */
struct green_cut {
	enum anvil_green_mode mode;
	double complex s;
	double kap2, nu, hh, patch;
	gsl_root_fsolver *root;
	size_t evals;
};

/* The cut K in [k0, kmax] (k0 at or beyond the band) where the bound on
 * the integral over [K, inf) is at most target, or kmax when the bound
 * there is still above it; *tail that bound at K (the caller adds it to
 * the integral's error estimate: it is honest also at kmax).  With
 * k0 = kmax, the bound at k0.  One or two kernel evaluations. */
double green_cut_find(struct green_cut *c, double k0, double kmax, double target, double *tail);

/* The layer's envelope past K: a bound on the integral of
 * Q(k) |zhat(k patch)| over [K, inf) (green_cut.c; INFINITY where it does
 * not yet fall), without SAFETY: what an error of at most d in A(k)
 * (green_tail.h) can make of the integral is d times this. */
double green_cut_env(const struct green_cut *c, double K);

#endif
