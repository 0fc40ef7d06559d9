/* gk21.h: the 21-point Gauss-Kronrod rule (QUADPACK's qk21) for complex and
 * vector-valued integrands.  Internal to the core (transform/, field/).
 *
 * GSL's gsl_integration_qk21 takes one real function: a complex integrand
 * would be evaluated twice (real and imaginary parts), and the field's
 * vector of integrals over many depths and frequencies must share nodes it
 * walks itself.  So this is the one hand-written rule, with the nodes in one
 * place (gk21.c); real integrands use GSL's own (halfspace.c). */
#ifndef ANVIL_GK21_H
#define ANVIL_GK21_H

#include <complex.h>

#define ANVIL_GK21_NODES 21

/* Node j (0..20) of the panel [a, b]: abscissa x, Kronrod weight wk and the
 * weight wg of the embedded 10-point Gauss rule (0 at the Kronrod-only
 * nodes).  sum wk f(x) is the rule, sum (wk - wg) f(x) its error estimate's
 * raw difference. */
void anvil_gk21_node(double a, double b, int j, double *x, double *wk, double *wg);

/* The node (anvil_gk21_node's j) that anvil_gk21_complex_floor evaluates
 * at its call n (0..20): always the same order, so that a caller can
 * prepare per-node factors of a panel before the rule asks for them
 * (green_spectrum.c).  Inline: its callers ask at every node of a piece
 * (a call a node was 1 % of a thin plate's instructions). */
static inline int anvil_gk21_called(int n)
{
	if (n == 0)
		return 10;
	int pair = (n - 1) / 2, i = pair < 5 ? 2 * pair + 1 : 2 * (pair - 5);
	return (n - 1) % 2 == 0 ? i : 20 - i;
}

/* The 21 abscissae of [a, b] in that order, x[n] = anvil_gk21_node's x
 * for j = anvil_gk21_called(n) (the same bits, without a call a node). */
void anvil_gk21_called_nodes(double a, double b, double *x);

typedef double complex (*anvil_gk21_fn)(double x, void *ctx);

/* The rule on [a, b] for a complex integrand, each node evaluated once:
 * *val, and *err the QUADPACK error estimate (the Gauss-Kronrod difference
 * rescaled as qk21 does, gsl_integration_qk21's abserr) of the real and
 * imaginary parts, combined by hypot. */
void anvil_gk21_complex(anvil_gk21_fn f, void *ctx, double a, double b, double complex *val,
			double *err);

/* The same, and *floor (when not NULL) the part of that estimate rounding
 * alone sets, 50 DBL_EPSILON times the integral of |Re f| and |Im f|
 * combined by hypot: no bisection takes the estimate below it. */
void anvil_gk21_complex_floor(anvil_gk21_fn f, void *ctx, double a, double b,
			      double complex *val, double *err, double *floor);

#endif
