/* halfspace.h: the exact centre surface response of an elastic half-space
 * under the Hertz-shaped patch load.
 *
 * Load: sigma_zz(r,0,t) = -Z(r) P(t), Z(r) = 3/(2 pi r0^2) sqrt(1 - r^2/r0^2)
 * for r < r0 (total 1 N), sigma_rz = 0.  The response is the vertical
 * displacement w_H at r = 0, z = 0.
 *
 * Everything here is dimensionless, so that one object per Poisson ratio
 * serves every material and patch radius:
 *   time          tau = t c2 / r0            (c2 the shear speed),
 *   displacement  mu r0 w                    (per newton, mu the shear modulus).
 * For a material (E, nu, rho) and patch radius r0: mu = E / (2 (1 + nu)),
 * c2 = sqrt(mu / rho); the step response in m/N is step(c2 t / r0) / (mu r0);
 * the response to P(t) = t (in N, t in s) is ramp(c2 t / r0) / (mu c2).
 *
 * The method is exact (no inversion on a Bromwich line): the Laplace
 * transform is inverted by closing the contour around the branch cuts and
 * the Rayleigh poles on the imaginary axis, and the wavenumber integral is
 * done in closed form because the cosine transform of the load's Hankel
 * transform has compact support.  What remains are finite integrals of
 * smooth functions, done with QUADPACK's Gauss-Kronrod rules with error
 * estimates.  The derivation is in halfspace.c.
 *
 * Exact facts the response obeys (and the tests check):
 *   step(tau) = 3 kappa tau / (2 pi) + O(tau^2), kappa = c2/c1 (that is,
 *     w(0+) slope Z(0)/(rho c1));
 *   step(tau) = anvil_halfspace_static(nu) = 3 (1 - nu) / 8 exactly for
 *     tau >= tau_R = c2 / c_R (the Rayleigh wave from the rim has passed);
 *   for 1 <= tau <= tau_R the step response is an exact parabola in tau.
 *
 * An object is read-only after anvil_halfspace_alloc: any number of threads
 * may evaluate the same object at once. */
#ifndef ANVIL_HALFSPACE_H
#define ANVIL_HALFSPACE_H

#include "status.h"

struct anvil_halfspace; /* opaque */

/* Make the response for Poisson ratio nu in (-1, 0.5) with tolerance tol
 * (absolute error relative to the static value 3 (1 - nu) / 8, in
 * (0, 0.1]; every tol >= 1e-13 is reachable for every nu, smaller ones give
 * ANVIL_ETOL).  This finds the Rayleigh speed and partitions the two
 * spectral ranges into panels on which every integral is resolved to tol
 * (cost: about 0.03 ms at tol = 1e-8, 0.1 ms at 1e-12).
 * Returns a new object that the caller owns (free it with
 * anvil_halfspace_free), or NULL with err (may be NULL) set to:
 * ANVIL_EINVAL for nu or tol out of range, ANVIL_ENOMEM, ANVIL_ETOL when
 * tol cannot be met in double precision, ANVIL_ENUM when a root or sum rule
 * check fails. */
struct anvil_halfspace *anvil_halfspace_alloc(double nu, double tol,
					      struct anvil_err *err);

/* Free hs; NULL is a no-op. */
void anvil_halfspace_free(struct anvil_halfspace *hs);

/* The step response mu r0 w_H at dimensionless time tau (P(t) = 1 for t > 0)
 * into *val, and an estimate of its absolute error into *abserr (abserr may
 * be NULL).  Equal to anvil_halfspace_static(nu) for tau >= tau_R.
 * Returns ANVIL_OK; ANVIL_EINVAL for tau < 0, NaN or infinite (val is then
 * NaN); ANVIL_ETOL if the tolerance was not met (val then holds the best
 * estimate and abserr says how good it is). */
int anvil_halfspace_step(const struct anvil_halfspace *hs, double tau,
			 double *val, double *abserr);

/* The ramp response: integral from 0 to tau of the step response (the
 * response to P = tau in these units).  Beyond tau_R it continues exactly
 * linearly with slope 3 (1 - nu) / 8.  Arguments and statuses as for
 * anvil_halfspace_step. */
int anvil_halfspace_ramp(const struct anvil_halfspace *hs, double tau,
			 double *val, double *abserr);

/* tau_R = c2 / c_R, the dimensionless time at which the Rayleigh wave from
 * the rim reaches the centre. */
double anvil_halfspace_tau_r(const struct anvil_halfspace *hs);

/* The static centre displacement 3 (1 - nu) / 8 (that is, 3 (1 - nu^2) /
 * (4 E r0) in units of 1 / (mu r0)); NaN for nu outside (-1, 0.5). */
double anvil_halfspace_static(double nu);

#endif
