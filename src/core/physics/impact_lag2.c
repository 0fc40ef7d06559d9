/* impact_lag2.c: the physical contact's second order (issue 11; impact.h,
 * g2; transform/radiation.h; doc/contact-model.md), for impact.c's
 * pass_physical.
 *
 * The remainder is -beta dP/dt + g2 d^2(a P)/dt^2, reduced in order as the
 * first:
 *   W - w_c = alpha - beta P'(alpha) u + Sigma,  u = v - dw_c/dt,
 *   Sigma = g2 (a P)''_0 - beta^2 P'(alpha) P''_0
 *         = c_u u^2 - c_x alpha (P/m1 + d^2w_c/dt^2),
 * the subscript 0 the zeroth-order values (alpha' = u, alpha'' = -P/m1 -
 * w_c''; a P = K sqrt(R) alpha^2 and P' P'' = (9/8) K^2 are finite as
 * alpha -> 0):
 *   c_u = 2 g2 K sqrt(R) - (9/8) beta^2 K^2,  c_x = 2 g2 K sqrt(R) - (9/4) beta^2 K^2.
 * The beta^2 part is the first-order reduction's own next term, of the
 * same order as g2's (doc/contact-model.md).  Sigma is O(f^2) of alpha
 * and tends to c_u u^2 as alpha -> 0: the outer solution starts and ends
 * where W - w_c = c_u u^2, not 0 (the inner region, while the contact
 * spreads faster than the waves, alpha up to about R V0^2/c2^2, is not modelled:
 * solver_phys.c puts that shift into t_s's error).  So the state sees
 * A - Sigma, with Sigma before the step (impact_lag2_before): in contact the
 * last two nodes' extrapolated, out of contact c_u u0^2 (P_n = 0 there).
 * Not Sigma at P_n = 0 in contact: on a layer dw_c/dt has a gain e0 on
 * P_n, and the velocity had P_n been 0 is far from the contact's (1 km/s
 * on h = r0 then "ended" at the peak).  P_n solves the root with A less
 * that Sigma, then once more with Sigma at that P_n (one fixed-point
 * round; dSigma/dP is O(f^2) of the Hertz stiffness).  sg keeps the
 * Sigma each node's step used, so W - w_c - sg is alpha - beta Q > 0 at a
 * node in contact and the state's A - sg at the next: the exact end
 * search interpolates it (impact_end.c).  w_c'' passes the lag's low-pass
 * twice (impact.h, tau_lag: gain at most 1/tau_lag^2 up to Nyquist,
 * where the expansion no longer holds anyway); the BDF2 of the filtered
 * dw_c/dt has gain 1/(tau_lag dt), and the paper's case lost its end in
 * the run at half tau_lag (so the second order needs tau_lag > 0:
 * anvil_impact_run; with the BDF2 of an unfiltered dw_c/dt, gain 1/dt^2,
 * a test's layer at h = r0 took 34 times the energy lost).  Before the outer
 * solution's start the bodies touch without force (on[0] = 0 stays the
 * touch). */
#include <math.h>

#include "impact_impl.h"

struct impact_lag2 impact_lag2_of(const struct ctx *c)
{
	const struct anvil_params *p = c->p;
	if (!(c->g2 > 0))
		return (struct impact_lag2){ 0.0, 0.0 };
	double gk = 2.0 * c->g2 * p->K * sqrt(p->r0), bk = c->beta * p->K;
	return (struct impact_lag2){ gk - 1.125 * bk * bk, gk - 2.25 * bk * bk };
}

/* Sigma at node n before its step, what decides the state: in contact
 * (after a force) the last two nodes' Sigma (sg: what their steps used)
 * extrapolated, else c_u u0^2 (P_n = 0). */
double impact_lag2_before(const struct impact_lag2 *l, const struct ctx *c,
			  const struct pass *s, size_t n, int in, double impulse, double u0)
{
	if (!in || !(impulse > 0) || n < 2)
		return l->cu * u0 * u0;
	double r = n - c->seg0 >= 2 || !c->seg0 ? 1.0 : 2.0; /* the steps' ratio */
	return s->sg[n - 1] + r * (s->sg[n - 1] - s->sg[n - 2]);
}

/* d^2w_c/dt^2 at node n (see above) from dw_c/dt there, ud, low-passed:
 * the second stage's state *z2 and ud's last value udp, trapezoidal as
 * the first (r = dt / (2 tl)). */
double impact_lag2_wdd(double ud, double udp, double tl, double rl, double *z2)
{
	*z2 = ((1.0 - rl) * *z2 + rl * (ud + udp)) / (1.0 + rl);
	return (ud - *z2) / tl;
}

/* Sigma at node n for load P = x^3 (x the step's root: no cube root of
 * its cube), relative velocity u, w_c'' wdd. */
double impact_lag2_after(const struct impact_lag2 *l, const struct anvil_params *p, double P,
			 double x, double u, double wdd)
{
	return l->cu * u * u - l->cx * p->k0 * x * x * (P / p->m1 + wdd);
}
