/* plate.h: the layer correction's long-time response from the plate
 * (issue 11), so that a long window needs no long inversion.  Internal to
 * the core (green.c).
 *
 * Units of green.h (lengths in r0, tau = t c2/r0, displacement per newton
 * in 1/(mu r0)).  Once the waves that matter are long against h, the
 * layer's centre moves like a plate's.  The Kirchhoff plate (D, rho h)
 * under the response's Hertz patch of radius p r0 (p = 0: a point load)
 * has the ramp response, by the Hankel transform and u = beta k^2 t,
 * beta = sqrt(D/(rho h)) = hh/sqrt(6 (1 - nu)):
 *   K(t) = t^2/(2 beta hh) int_0^inf zhat(p sqrt(u/(beta t))) (1 - sin u/u)/u^2 du,
 * which tends to alpha* t^2/2 (alpha* = 1/(8 beta hh), eq 8: the integral
 * tends to pi/(8 pi) = 1/8 as zhat -> 1/(2 pi); for a point load it is
 * that from the start) and carries the patch's t log t correction
 * exactly: on a thin plate p^2/(beta t) is not small at T1 (6 at T1/4,
 * h = 0.02 r0, p = 1), so no fitted term could stand in for it.  The
 * next order in (kh)^2, shear and rotary inertia (plate.c: the layer's own
 * coefficients, not Mindlin's), adds
 *   S(t) = t/hh [A int Z (u - sin u)/u^2 du - B int Z (sin u - u cos u)/u^2 du],
 * A = 3 (1 - nu)/5, B = (17 - 7 nu)/40, Z = zhat(p sqrt(u/(beta t))): the
 * patch's t log(beta t/p^2), with its own transition at t ~ p^2/beta (102
 * at h = 0.02 r0, p = 1), which no fitted term could follow either; for a
 * point load (where it diverges: the layer cuts it off at k ~ 1/h) S = 0
 * and the fitted c t log t carries it, and so it does where the
 * transition is over before the fit's window (p^2/beta < T1/16: thick
 * layers, small patches), where S is 0 too.  The layer correction (layer less
 * half-space, whose late ramp is the static compliance times t) is then
 *   g(t) = K(t) + S(t) - s_hs t + a + b t + c t log t + ...,
 * the last three terms the local (thickness-direction) compliance and what
 * the expansion leaves (for a point load, the t log t).  They are fitted
 * to the inversion over [T1/4, T1] and the sum, in closed form, is the
 * response beyond T1 (the "tail"): no samples there, whatever the window.
 *
 * K(t)/t^2 and S(t)/t are smooth and slowly varying in log t: each is
 * tabulated at ANVIL_PLATE_PER_OCTAVE nodes per octave from T1/17 to the
 * window's end (O(log tau_end) quadratures; beyond beta t = patch^2
 * one node in two, then three in four and seven in eight, are the
 * Lagrange interpolant of those about them, to 4e-13: plate.c
 * nodes_fill) and interpolated by a cubic
 * B-spline quasi-interpolant (C2, local: a value depends on the eight
 * nodes about it only, so that a longer window's table gives the same bits
 * where both are defined).  Its interpolation error, measured against the
 * quadrature at the midpoints between nodes, is that of GSL's
 * interpolating cubic spline on the same nodes: 2.9e-9 of K at h = 0.02 r0
 * (near T1/8, where a thin plate's K/t^2 bends most), 2.3e-10 at 0.1 r0,
 * below 3e-10 on thicker layers and at late times; S's, in the ramp,
 * within 2.4e-10 of K at h = 0.02 r0, p = 1 (2.5e-9 of S/t's largest
 * value, near T1/8 where it turns), 2e-11 of S/t's at 0.1 r0
 * (tests/test_tail.c).
 *
 * Measured (normal settings, nu = 0.3, against one inversion over the
 * whole window, 8 T1): the relative error of g beyond T1 was 2e-6 at
 * hh = 0.5, 5e-6 at hh = 1, 1.5e-5 at hh = 2 (T1 = 100), 5e-5 at hh = 10
 * (T1 = 800; below for T1 = 16 hh), 3e-5 at hh = 0.1 (T1 = 20); a fit on a window 4 times
 * shorter was up to 30 times worse.  At hh = 0.02 (T1 = 64, window 8 T1,
 * normal, band 8) the error over [T1/2, 8 T1] against the estimates'
 * sum ("cov"): 0.003 for a point load, 0.001 for p = 0.71, 0.002 for
 * p = 1 (0.38 and 0.81 without S: 98 and 371 against 0.18 and 0.28 now);
 * over hh = 0.02 .. 0.5, p = 0 .. 1 the largest cov was 0.04.  At T1 =
 * 32 (below hh = 1, with S and the blend over [T1/4, T1]) it is 0.25 at
 * most over the same set (0.017, 0.035, 0.028 at hh = 0.02 for p = 0,
 * 0.5, 1; 0.19 and 0.25 at hh = 0.2 and 0.5, p = 1), where without S it
 * was 2.99 (hh = 0.02, p = 1); 60 thin scenes (h = 0.02-0.2 r0, 0.1 g-
 * 1 kg, 0.1-10 m/s) agree with T1 = 64 within their estimates, at 52.3
 * -> 33.3 s of CPU (h = 0.02 r0: 33.0 -> 17.5 s).  T1 = 16 did not do:
 * at hh = 0.02 a point load's impulse response beyond T1 was off by
 * 0.9 % of alpha* (before S).  tests/test_green.c holds the method to its
 * estimate on a few thicknesses and patches. */
#ifndef ANVIL_PLATE_H
#define ANVIL_PLATE_H

#include <stddef.h>

/* The inversion window T1 before the plate takes over: 32 below hh = 1,
 * max(64, 16 hh) from there (the waves that matter are then long against
 * h and the reverberations between the faces have died down; below hh =
 * 1, with S, 32 is as good as 64 was: cov <= 0.25 over hh = 0.02 .. 0.5,
 * p = 0 .. 1, above, and half the inversion); 0 when the window tau_end
 * is shorter than 4 T1 below hh = 1, 2 T1 from there (a plain inversion is
 * cheap enough there).  T1 does not grow with the window: the closed form
 * covers any length.
 *
 * Thick layers (2026-11, the brief "thick"): T1 was 64 hh, and the tail
 * only from a window of 4 T1, so a 9 ms contact on h = 100 r0 (window
 * 11600 r0/c2) was one inversion of 1844 terms, 8.1e6 kernel evaluations,
 * 1.6 s.  For a point load on hh >> 1 the fit's error is a function of
 * T1/hh alone (the same 4.3e-3 at hh = 5, 10, 30 and T1 = 16 hh against
 * one inversion over 4 T1, normal, filtered): relative error of g beyond
 * T1 1.3e-6, 8e-6, 4.3e-4 at T1 = 32, 16, 8 hh; the true error over the
 * stated bound (anvil_green_abserr_at, the two responses' sum) 0.45-0.49,
 * 0.11-0.21, 1.09-1.26 over hh = 5 .. 100, patches 0 and 0.1.  So 16 hh,
 * with the floor 64: at hh = 1 T1 = 32 missed its bound (1.11, a point
 * load), at hh = 1.3-2 T1 = 32 was 0.11-0.42; with 64 it is 0.01-0.13 over
 * hh = 1.5-4, patches 0 and 1, windows 2 and 4 T1.  With the tail from 2
 * T1 (windows 2 T1, hh = 6-100, bands 0.25-1, draft and normal, patches 0
 * and 0.2) it was 0.07-0.32.  h = 100 r0, 100 kg at 1 mm/s: 255 terms,
 * 9.3e5 evaluations, 0.19 s.
 *
 * Below hh = 1 with a point load (2026-11, the brief "t1thin"): h = 0.3,
 * 0.5, 0.7, 0.85, 0.95 (and 1) r0, patches 0 (filtered, the physical
 * contact's) and 1 (filtered and not), bands 0.5-4, draft and normal,
 * against one inversion over 8 T1, the true error over the bounds' sum
 * (anvil_green_abserr_at) at every tau beyond T1: with the bound then
 * growing by misfit (x - 1) 36 of 144 cases over 1, up to 12.7 (h = 0.85
 * r0, a point load, band 2: 0.95, 12.5, 2.8 at h = 0.7, 0.85, 0.95).  T1
 * was not the cause: forcing T1 = 32, 48, 64, 96, 128 on the same cases
 * gave at most 12.7, 6.0, 12.7, 19.3, 2.6, not monotone (at h = 1, T1 =
 * 64 as this rule has it: 6.0, patch 1, band 1); the bound was (the
 * misfit small by chance; the error grows like x log x: tail_make).  With
 * the bound of tail_make, at most 0.67 over the 144 (at T1 itself, where
 * it is the response's abserr, unchanged; 0.28 with T1 = 64 forced on
 * all), 0.64 over h = 0.02-0.2 r0 and 0.28 over h = 1.5-10 r0 (bands 1-4
 * and 0.25-2), 0.51 over windows of 64 T1 (h = 0.3, 0.7, 0.95); the
 * ratios' geometric mean 0.056 (it was 0.34).  So T1 stays 32. */
double anvil_plate_t1(double hh, double tau_end);

/* The samples a response with a tail keeps beyond the inversion's
 * window: its cubic spline (green.c) ends in a natural end condition,
 * whose effect decays by 0.27 a sample; 32 of them (1e-18) keep it off
 * [0, T1], where the spline is used. */
#define ANVIL_PLATE_PAD 32
/* Nodes of the K(t)/t^2 table per octave (quasi-interpolant, above). */
#define ANVIL_PLATE_PER_OCTAVE 32
/* The K table's nodes for a tail from T1 to tau_end: t_i = (T1/17)
 * 2^(i/32), i < n, three below T1/8 and four beyond tau_end at least (the
 * quasi-interpolant's reach). */
size_t anvil_plate_nodes(double t1, double tau_end);

/* The closed form beyond T1: what rebuilds it to the bit (green.c stores
 * it in the cache).  All owned by the tail. */
struct anvil_plate_tail {
	double hh, nu, patch, t1; /* patch: the load's radius, r0 units (0: a point) */
	double c[3];  /* a + b x + c x log x, x = t/T1 */
	double v;     /* the extrapolation's error unit (below; stored) */
	double misfit; /* the validation's misfit over [T1/2, T1] (tail_make; 0
			  from tail_init: the response's abserr, which holds it,
			  is stored beside) */
	size_t nk;    /* K(t)/t^2 at the nodes, k[0..nk-1] */
	double *k;
	double *bc;   /* their B-spline coefficients (from k, the same bits) */
	double *shear, *shear_bc; /* S(t)/t (the (kh)^2 term) at the nodes, and theirs */
	int shear_on;             /* 0: S is 0 here (plate.c, shear_on): not evaluated */
	double *imp;  /* the ramp's and the impulse response's polynomials in
			 each interval (from bc and shear_bc; plate.c, imp_coefs) */
	double beta, shs, u0, lt1; /* lt1 = log t1 */
};

/* The tail of the samples ramp[j] at tau_j = j dtau, known (from the
 * inversion) for j < n1, over the window [0, tau_end]: the fit of
 * a + b t + c t log t to g - (K - s_hs t) over [T1/4, T1] with
 * T1 = (n1 - 2) dtau; then ramp[j] for n1 <= j < n (n - n1 small: the
 * spline's pad) the model's values, and over [T1/4, T1] the blend from
 * the inversion to the model (plate.c says why).  tl->misfit: the same
 * fit made over [T1/8, T1/2] (the validation) misses the inversion over
 * [T1/2, T1] by it: the tail's error at T1.  Beyond, the error is the
 * fit's coefficients' (dc) times the basis, which grows like x log x
 * (x = t/T1; an error in c), so the bound grows by v (x (1 + log x) - 1),
 * v = max(misfit, |dc_a| + |dc_b| + |dc_c|), dc the validation's
 * coefficients less the fit's (anvil_plate_tail_err).  It grew by
 * misfit (x - 1) until 2026-11 (the brief "t1thin"): the misfit can be
 * small by chance (the two fits agreeing over [T1/2, T1] while their c
 * differ), and the true error at 8 T1 reached 12.7 times that bound
 * (h = 0.85 r0, a point load, band 2, filtered, normal: 36 of 144 cases
 * over 1 at h = 0.3-1 r0, T1 = 32), growing like x log x, to 29 times at
 * 64 T1.  No T1 cured it: 12.7, 6.0, 12.7, 19.3, 2.6 at most at T1 = 32,
 * 48, 64, 96, 128 over the same cases, not monotone (figures in
 * anvil_plate_t1's comment).  memo: the K table kept from one
 * tail to the next (NULL: none).  The caller frees tl with
 * anvil_plate_tail_free (also on failure).  ANVIL_ENUM when the
 * quadrature of K fails, ANVIL_ENOMEM. */
struct anvil_plate_memo;
int anvil_plate_tail_make(double hh, double nu, double patch, double dtau, size_t n1, size_t n,
			  double *ramp, double tau_end, struct anvil_plate_memo *memo,
			  struct anvil_plate_tail *tl);
/* A tail from what tail_make stored (t1, c, v, nk nodes k and shear
 * copied): the same bits.  ANVIL_EINVAL for a table that does not fit the
 * window (nk != anvil_plate_nodes(t1, tau_end)) or implausible values (not
 * finite; K/t^2 outside (0, alpha*], where the plate's moves no faster
 * than its limit alpha* t^2/2 and always forward; S not 0 for a point
 * load), ANVIL_ENOMEM. */
int anvil_plate_tail_init(struct anvil_plate_tail *tl, double hh, double nu, double patch,
			  double t1, const double c[3], double v, double tau_end, size_t nk,
			  const double *k, const double *shear);
void anvil_plate_tail_free(struct anvil_plate_tail *tl); /* frees the arrays; zeroed */

/* The ramp and step (its analytic derivative: the quasi-interpolant's in
 * log t) at t >= T1/8, within the table. */
double anvil_plate_tail_ramp(const struct anvil_plate_tail *tl, double t);
double anvil_plate_tail_step(const struct anvil_plate_tail *tl, double t);
/* The impulse response (the ramp's second derivative, analytic: the
 * quasi-interpolant's, continuous, its slope jumping at the nodes by
 * about its own error) at t >= T1/8, within the table. */
double anvil_plate_tail_impulse(const struct anvil_plate_tail *tl, double t);
/* K(t)/t^2 and S(t)/t from the tables (the quasi-interpolant), for tests. */
double anvil_plate_tail_k(const struct anvil_plate_tail *tl, double t);
double anvil_plate_tail_s(const struct anvil_plate_tail *tl, double t);
/* What the error bound grows by beyond T1 (anvil_green_abserr_at adds it
 * to the response's abserr, which holds the misfit): v (x (1 + log x) -
 * 1), x = t/T1 (0 at t <= T1). */
double anvil_plate_tail_err(const struct anvil_plate_tail *tl, double t);

/* K(t)/t^2 by its quadrature (to 1e-12), for tests of the table. */
int anvil_plate_k(double hh, double nu, double patch, double t, double *val);
/* S(t)/t, the layer's first-order term (plate.c), by its quadrature (to
 * 1e-12 relative), for tests of the table; 0 for a point load. */
int anvil_plate_s(double hh, double nu, double patch, double t, double *val);

/* The K(t) tables that anvil_plate_tail_make made last (their
 * quadratures), one for each of the last four loads, for the next tail of
 * the same plate and load: a layer correction and its twin share one, so
 * do the physical contact's corrections of one load at two bands; a longer
 * window extends it.  A pure function's memo: the same bits whether it
 * held the table or not.  Owned by one thread at a time (the solver's,
 * beside its cache).  NULL when out of memory. */
struct anvil_plate_memo *anvil_plate_memo_alloc(void);
void anvil_plate_memo_free(struct anvil_plate_memo *m); /* NULL is a no-op */

#endif
