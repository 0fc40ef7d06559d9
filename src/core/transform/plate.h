/* plate.h: the layer correction's long-time response from the plate
 * (issue 11), so that a long window needs no long inversion.  Internal to
 * the core (green.c).
 *
 * Units of green.h (lengths in r0, tau = t c2/r0, displacement per newton
 * in 1/(mu r0)).  Once the waves that matter are long against h, the
 * layer's centre moves like a plate's.  The Kirchhoff plate (D, rho h)
 * under the Hertz patch has the ramp response, by the Hankel transform
 * and u = beta k^2 t, beta = sqrt(D/(rho h)) = hh/sqrt(6 (1 - nu)):
 *   K(t) = t^2/(2 beta hh) int_0^inf zhat(sqrt(u/(beta t))) (1 - sin u/u)/u^2 du,
 * which tends to alpha* t^2/2 (alpha* = 1/(8 beta hh), eq 8: the integral
 * tends to pi/(8 pi) = 1/8 as zhat -> 1/(2 pi)) and carries the patch's
 * t log t correction exactly.  The layer correction (layer less half-space,
 * whose late ramp is the static compliance times t) is then
 *   g(t) = K(t) - s_hs t + a + b t + c t log t + o(1/t) ...,
 * the last three terms the local (thickness-direction) compliance and the
 * shear and rotary inertia of a thick (Mindlin) plate, whose leading
 * effect on the impulse response decays like 1/t.  They are fitted to the
 * inversion over [T1/4, T1] and the sum is used beyond T1.
 *
 * Measured (normal settings, nu = 0.3, against one inversion over the
 * whole window, 8 T1): the relative error of g beyond T1 was 2e-6 at
 * hh = 0.5, 5e-6 at hh = 1, 1.5e-5 at hh = 2 (T1 = 100), 5e-5 at hh = 10
 * (T1 = 800), 3e-5 at hh = 0.1 (T1 = 20); a fit on a window 4 times
 * shorter was up to 30 times worse.  tests/test_green.c holds the method
 * to its estimate on a few thicknesses. */
#ifndef ANVIL_PLATE_H
#define ANVIL_PLATE_H

#include <stddef.h>

/* The inversion window T1 before the plate takes over: 64 max(1, hh) (the
 * waves that matter are then 8 times longer than h and the reverberations
 * between the faces have died down); 0 when the window tau_end is shorter
 * than 4 T1 (a plain inversion is cheap enough there).  A function of hh
 * and tau_end only, so that the cache's key still says everything. */
double anvil_plate_t1(double hh, double tau_end);

/* Extend the ramp samples ramp[j] at tau_j = j dtau, known (from the
 * inversion) for j < n1, to j < n: the fit of a + b t + c t log t to
 * g - (K - s_hs t) over [T1/4, T1] with T1 = (n1 - 2) dtau, then the sum
 * beyond.  *ext_err gets the estimated absolute error of the extended
 * samples: the same fit made over [T1/16, T1/4] misses the inversion over
 * [T1/4, T1] by v; the error grows with the extrapolation's length, so
 * v (tau_end/T1) is taken (the measured errors above were 3-30 times
 * below it).  ANVIL_ENUM when the quadrature of K fails, ANVIL_ENOMEM. */
int anvil_plate_extend(double hh, double nu, double dtau, size_t n1, size_t n, double *ramp,
		       double *ext_err);

/* The last K(t) table that anvil_plate_extend_memo made (its quadratures,
 * a third of a long window's response), for the next extension of the
 * same plate and span: a layer correction, its twin and the patch's
 * correction of one window share it.  A pure function's memo: the same
 * bits whether it held the table or not.  Owned by one thread at a time
 * (the solver's, beside its cache).  NULL when out of memory. */
struct anvil_plate_memo;
struct anvil_plate_memo *anvil_plate_memo_alloc(void);
void anvil_plate_memo_free(struct anvil_plate_memo *m); /* NULL is a no-op */

/* anvil_plate_extend through memo (NULL: none). */
int anvil_plate_extend_memo(double hh, double nu, double dtau, size_t n1, size_t n, double *ramp,
			    double *ext_err, struct anvil_plate_memo *memo);

#endif
