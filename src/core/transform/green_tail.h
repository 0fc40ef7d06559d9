/* green_tail.h: the layer correction's kernel beyond the band from a few
 * evaluations (green_spectrum.c k_integral; internal to the core).
 *
 * Beyond the band (kernel.h anvil_kband) W_c(k, s) k = B(k) (1 + k hh)^2
 * exp(-2 k hh), B smooth, tending to the static limit 4 (1 - nu)
 * (green_cut.c), its nearest singularities the complex modes' poles at
 * Im k >= 2.25/hh (kernel.h) and the Lamb modes' below kb/1.6 (kb - 3).
 * So on panels from kb, each at most TAIL_PANEL/hh wide and at most
 * TAIL_GROW times its start (green_tail.c), a Chebyshev interpolant of B
 * of degree 16 in k converges geometrically (a pole 2.25/hh off a
 * panel's centre, 1.5/hh from its ends: rho = 3.3; the Lamb modes' 1.9
 * half-widths before it: rho = 5.6; measured, the coefficients fall to
 * 1e-12-1e-15 of the first by the 16th, except at omega near 0), and the
 * quadrature (each load's adaptive Gauss-Kronrod, zhat's oscillation and
 * all) takes W_c from it: on a thin plate 17 kernel evaluations a panel
 * (5-8 panels) for the whole tail of a set's loads at one s, where its
 * 16-wide pieces took 21 each (28 pieces to k = 575 at h = 0.02 r0).
 * Far panels, whose share of the error env makes small, take degree 8
 * from every other point (9 evaluations; 8 more if a load needs 16).
 * The interpolant depends on (s, kb, kend, hh, kappa^2) only, each panel
 * fitted when first asked for: a load's bits do not depend on which
 * others were computed with it. */
#ifndef ANVIL_GREEN_TAIL_H
#define ANVIL_GREEN_TAIL_H

#include <complex.h>
#include <stddef.h>

#define GREEN_TAIL_DEG 16
/* the lower degree, whose points are every other of GREEN_TAIL_DEG's
 * (green_tail.c: a panel where it suffices takes 9 evaluations, not 17) */
#define GREEN_TAIL_DEG0 8
#define GREEN_TAIL_PANELS 32
/* the interpolant serves a tail longer than this (k_integral): 4 pieces
 * of 21 evaluations, 84 against at most 3 panels' 51 */
#define GREEN_TAIL_MIN_SPAN 64.0

struct green_tail_panel {
	int n;        /* 0: not fitted yet; -1: could not be (not finite);
		       * GREEN_TAIL_DEG0: that degree only; GREEN_TAIL_DEG: both */
	int deg;      /* the degree the current load takes (green_tail_bound) */
	double delta; /* the estimate of sup |B - interpolant| on the panel at deg */
	double d0, d1; /* the same at GREEN_TAIL_DEG0 and GREEN_TAIL_DEG */
	/* B's Chebyshev coefficients at the two degrees (c0's zero beyond
	 * GREEN_TAIL_DEG0) and its values at the Chebyshev points */
	double complex c0[GREEN_TAIL_DEG + 1], c[GREEN_TAIL_DEG + 1], f[GREEN_TAIL_DEG + 1];
};

struct green_tail {
	double complex s;
	double kap2, hh, kb, kend; /* the key, with s */
	int np;                    /* panels (0: none yet) */
	int cs_on;                 /* cs holds cos(pi m/GREEN_TAIL_DEG), m < 2 deg */
	double cs[2 * GREEN_TAIL_DEG];
	double a[GREEN_TAIL_PANELS + 1]; /* panel i is [a[i], a[i + 1]] */
	struct green_tail_panel p[GREEN_TAIL_PANELS];
};

/* Make t the interpolant at s from kb (its panels fitted on demand),
 * unless it already is: kend is the furthest k it will be asked for (the
 * hard limit; the last panel reaches it). */
void green_tail_key(struct green_tail *t, double complex s, double kap2, double hh, double kb,
		    double kend);

/* The panels' error bound up to kend: the sum over the panels that
 * [kb, kend] touches of delta times env(panel's start) (env(K) bounding
 * the integral of |W_c k zhat|/|B| over [K, inf), green_cut.h), fitting
 * them (*evals counts the kernel evaluations); INFINITY when one could not
 * be fitted.  env is the caller's (a load's patch).  Each panel at
 * GREEN_TAIL_DEG0 where the sum stays within allow, else (from the first
 * panel on, while the sum exceeds allow) at GREEN_TAIL_DEG where that
 * estimate is the smaller: the degrees the caller's green_tail_w then
 * takes (they depend on allow and env, not on earlier callers). */
double green_tail_bound(struct green_tail *t, double kend, double (*env)(void *, double),
			void *ctx, double allow, size_t *evals);

/* The panels green_tail_key makes for [kb, kend] (the planner's price,
 * plan_work.c). */
int green_tail_count(double hh, double kb, double kend);

/* W_c(k, s) at k in [kb, kend] of an earlier green_tail_bound (its panels
 * fitted). */
double complex green_tail_w(const struct green_tail *t, double k);

/* green_tail_w at k[0..n-1] into out (the same bits, faster); e[i], when
 * not NULL, is exp(-2 hh k[i]) as the caller made it (green_spectrum.c:
 * from a piece's centre and its offsets), else exp is taken here. */
void green_tail_w_n(const struct green_tail *t, const double *k, const double *e, int n,
		    double complex *out);

#endif
