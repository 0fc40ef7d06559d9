#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "fastconv.h"
#include "impact.h"
#include "impact_impl.h"

static void pass_free(struct pass *s)
{
	free(s->P);
	memset(s, 0, sizeof *s);
}

static int pass_alloc(struct pass *s, size_t cap, double dt)
{
	memset(s, 0, sizeof *s);
	s->P = calloc(8 * cap, sizeof *s->P);
	if (!s->P)
		return ANVIL_ENOMEM;
	s->t = s->P + 6 * cap;
	s->sg = s->P + 7 * cap;
	s->nseg = 1; /* segment 0: node 0, level 0 */
	s->dt0 = dt;
	s->W = s->P + cap;
	s->w = s->P + 2 * cap;
	s->v = s->P + 3 * cap;
	s->wc = s->P + 4 * cap;
	s->Q = s->P + 5 * cap;
	s->cap = cap;
	s->dt = dt;
	return ANVIL_OK;
}

int impact_ramp_of(const struct ctx *c, anvil_ramp_fn fn, void *ctx, double t, double *val)
{
	const struct anvil_params *p = c->p;
	if (t <= 0) {
		*val = 0;
		return ANVIL_OK;
	}
	double v;
	int st = fn(ctx, t * p->c2 / p->r0, &v);
	*val = v / (p->mu * p->c2);
	return st;
}

int impact_ramp_at(const struct ctx *c, double t, double *val)
{
	return impact_ramp_of(c, c->ramp, c->rctx, t, val);
}

/* Weights of the product integration: the deflection at t_n caused by the
 * hat function of unit height centred at t_m is g_{n-m}, the second
 * difference of the ramp response divided by dt; made as the march reaches
 * them (impact_wts.c).  cap: the first segment's (all the window's but in
 * long mode). */
static int weights(struct ctx *c, size_t cap)
{
	c->g = malloc(cap * sizeof *c->g);
	if (c->ramp2)
		c->dg = malloc(cap * sizeof *c->dg);
	c->ng = cap, c->gnf = 0;
	if (!c->g || (c->ramp2 && !c->dg))
		return ANVIL_ENOMEM;
	return impact_g_need(c, 2);
}

/* A push's status (fastconv.h): full is no error here (the march stops
 * at the capacity), out of memory is, and a weight that failed (a ramp
 * call: impact_wts.c). */
static int push_status(int r)
{
	return r == -2 ? ANVIL_ENOMEM : r == -3 ? ANVIL_ENUM : ANVIL_OK;
}

/* The one positive root of k0 x^2 + B x^3 = A (x = P^(1/3)), A > 0.
 * Newton from a point where the left side is at or above A decreases
 * monotonically to the root (the left side is increasing and convex for
 * x > 0), so it cannot overshoot; GSL's cubic solver loses digits here
 * when B x << k0.  The upper bound sqrt(A/k0) is such a point; the last
 * node's root xg is a nearer one when it is above, and when it is below,
 * one Newton step from it (under the convex curve) lands at or past the
 * root: the march's force changes little a step, and Newton from the
 * bound took tens of iterations where B x^3 dominates (h = 0.2 r0, 100 g
 * at 1000 m/s: a twelfth of the run).  The root the same to the stop's
 * 1e-15. */
static double hertz_root(double k0, double B, double A, double xg)
{
	double x = sqrt(A / k0);
	if (xg > 0 && xg < x) {
		double f = k0 * xg * xg + B * xg * xg * xg - A;
		double df = 2.0 * k0 * xg + 3.0 * B * xg * xg;
		if (f >= 0)
			x = xg;
		else if (xg - f / df < x)
			x = xg - f / df;
	}
	for (int i = 0; i < 60; i++) {
		double f = k0 * x * x + B * x * x * x - A;
		double dx = f / (2.0 * k0 * x + 3.0 * B * x * x);
		x -= dx;
		if (fabs(dx) <= 1e-15 * x)
			break;
	}
	return x;
}

/* The march's two-step mode P_n ~ (-1)^n solves its homogeneous equation
 * hc P_n + sum_j g_j P_{n-j} = 0 (hc = dalpha/dP = 2/3 k0 P^(-1/3),
 * Hertz's compliance) at a = -1 when D = hc + sum_j (-1)^j g_j is zero,
 * and grows when D < 0.  Where the grown step is long against the layer's
 * transients its ramp is a dashpot's with a lag, R = t^2 / 2c - b t (the
 * centre of the paper's r0 patch on a thin plate follows the plate's
 * bending late), so g_0 = dt / 2c - b, g_j = dt / c and D = hc - b at any
 * longer step: negative once Hertz's compliance falls below the lag.  The
 * paper's contact on h = 0.05 r0 under 10 kg at 1 mm/s grew its step to
 * 292 us with b = 4e-6 m/N against hc = 1.1e-6: the sawtooth grew 3.6 %
 * a step to the full force (P_max 7.9e-6 kN against the mean's 3.9e-6,
 * its estimate 12 %), and elsewhere it stopped the step's growth (the
 * force "stays rough") until the nodes ran out.  The continuous system is
 * stable (the layer's compliance is positive at the frequencies the long
 * step cannot see); the scheme adds eps (P_n - 2 P_{n-1} + P_{n-2}) to
 * the deflection, a compliance at the step's Nyquist frequency alone
 * (4 eps there, none at zero frequency, eps P'' dt^2 on a smooth force:
 * second order, as the scheme), with eps just enough that D keeps half of
 * hc.  dl: the level's sum_j (-1)^j g_j (to NYQ_J, its tail by Abel's
 * mean). */
#define NYQ_J 4
static double nyq_sum(const struct ctx *c)
{
	double d = impact_g_at(c, 0), gj = 0;
	for (size_t j = 1; j <= NYQ_J; j++) {
		gj = impact_g_at(c, j);
		d += (j & 1) ? -gj : gj;
	}
	return d + (NYQ_J & 1 ? 0.5 : -0.5) * gj;
}

static double nyq_eps(const struct ctx *c, double dl, double P)
{
	/* dl >= 0: D keeps all of hc > 0, no eps (the level-0 march's case;
	 * its cube root took a twentieth of the run) */
	if (!(P > 0) || dl >= 0)
		return 0.0;
	double hc = 2.0 / 3.0 * c->p->k0 / cbrt(P);
	return fmax(0.0, -(0.5 * hc + dl) / 4.0);
}

/* The implicit, second-order pass (see impact.h).  With P piecewise linear
 * through the P_m, the impactor's displacement at t_n is exactly
 *   W_n = V0 t_n - (dt/m1) sum_{m<n} P_m (t_n - t_m) - P_n dt^2/(6 m1)
 * and the anvil's w_n = sum_{m<=n} P_m g_{n-m} (the past by the online fast
 * convolution).  Where A_n (alpha_H if P_n were 0) <= 0 there is no
 * contact: P_n = 0, and the march goes on (free flight, the layer's free
 * response) through any new contact until the two have parted for good. */
static int pass_implicit(struct ctx *c, struct pass *s)
{
	const struct anvil_params *p = c->p;
	double dt = s->dt, B = c->g[0] + dt * dt / (6.0 * p->m1);
	double S0 = 0, S1 = 0, impulse = 0; /* sum P_m, sum P_m t_m, int P dt */
	double ioff = 0, a_prev = 0, amax = 0;
	double xr = 0; /* the last root (hertz_root's guess) */
	int in = 1;
	s->v[0] = p->V0;
	s->n = 1;
	s->ncont = 1;
	s->on[0] = 0;
	anvil_fastconv_reset(c->fc);
	anvil_fastconv_push(c->fc, 0.0);
	double dl = nyq_sum(c); /* the level's (nyq_eps) */
	for (size_t n = 1; n < s->cap; n++) {
		int L = impact_grow_due(c, s, n, in), st;
		if (L && (st = impact_grow_switch(c, s, L)))
			return st;
		if (L)
			dt = s->dt, B = c->g[0] + dt * dt / (6.0 * p->m1), S0 = S1 = 0, dl = nyq_sum(c);
		size_t i = n - c->seg0; /* the segment's node; n on the first */
		if (i >= c->segcap)
			break;
		double tn = (double)i * dt, conv = anvil_fastconv_next(c->fc);
		double hw = 0.0, mh = (c->T0 + tn) * c->Ih - c->M1h;
		if (c->nfz && (st = impact_hist(c, i, &hw)))
			return st;
		/* the Nyquist compliance, on the segment's own steps */
		double eps = i >= 2 ? nyq_eps(c, dl, s->P[n - 1]) : 0.0;
		double epast = eps > 0 ? eps * (s->P[n - 2] - 2.0 * s->P[n - 1]) : 0.0;
		double A = p->V0 * (c->T0 + tn) - dt / p->m1 * (tn * S0 - S1) - conv - hw - mh / p->m1 - epast;
		double P = 0;
		/* the Nyquist term's deflection at the node, what the exact end
		 * (impact_end.c, alpha_end: linear between the nodes, as the
		 * physical contact's offset) subtracts: at an end's node P = 0.
		 * Without it the end's approach missed the term the march had
		 * (h = 0.02 r0, 10 kg at 10 m/s: -1.0e-5 m at both ends of the
		 * step after a node in contact, the term 1.8e-5 m): no zero, a
		 * lost end */
		s->sg[n] = epast;
		st = impact_contact_state(c, s, n, A, a_prev, amax, impulse, &in, &ioff);
		/* at rest on the plate before the chatter, or before a contact's
		 * end was lost (impact_rest.c) */
		if ((st == IMPACT_BUDGET || st == IMPACT_END_LOST) && impact_rest_fallback(s))
			break;
		if (st)
			return st;
		if (in) {
			xr = hertz_root(p->k0, B + eps, A, xr);
			P = xr * xr * xr;
		}
		if (!isfinite(P) || !isfinite(A)) { /* ran away: no end to find */
			s->ts = s->t[n - 1];
			return IMPACT_END_LOST;
		}
		a_prev = A - (B + eps) * P;
		amax = fmax(amax, a_prev);
		s->P[n] = P;
		s->sg[n] = epast + eps * P;
		s->W[n] = p->V0 * (c->T0 + tn) - dt / p->m1 * (tn * S0 - S1) - P * dt * dt / (6.0 * p->m1) -
			  mh / p->m1;
		s->w[n] = conv + P * c->g[0] + hw + epast + eps * P;
		s->t[n] = (double)(c->K0 + (i << c->lev)) * s->dt0;
		impulse += 0.5 * dt * (s->P[n - 1] + P);
		s->v[n] = p->V0 - impulse / p->m1;
		S0 += P;
		S1 += P * tn;
		s->n = n + 1;
		if ((st = push_status(anvil_fastconv_push(c->fc, P))))
			return st;
		if (impact_rest_check(c, s, n, in))
			break;
		if (!in && !s->pend_k && impact_parted(c, s, n, impulse, amax)) {
			s->parted = 1;
			break;
		}
	}
	/* at rest on the plate (impact_rest.c): no end; or in contact at the
	 * last window's end after coming to rest, or chattering since */
	if (s->rest || ((in || s->v[s->n - 1] >= 0) && impact_rest_final(c, s, in) && impact_rest_fallback(s))) {
		impact_peak(s);
		return ANVIL_OK;
	}
	int st = impact_sep_resolve(c, s, &ioff); /* a separation at the window's end */
	if (st == IMPACT_END_LOST && impact_rest_fallback(s)) {
		impact_peak(s);
		return ANVIL_OK;
	}
	if (st)
		return st;
	if (in || s->v[s->n - 1] >= 0)
		/* a contact, or a new one, outlasts the window (or the nodes) */
		return impact_long_short(c, s) ? IMPACT_NODES : ANVIL_ETOL;
	if (impact_rest_grazing(c, s, ioff) && impact_rest_fallback(s)) {
		impact_peak(s);
		return ANVIL_OK;
	}
	if (!s->parted)
		s->parted = 2;
	s->Vs = -(p->V0 - ioff / p->m1);
	impact_peak(s);
	return ANVIL_OK;
}

/* The one positive root x = P^(1/3) of the physical step equation (see pass_physical)
 *   G(x) = bD x^4 + B x^3 + k0 x^2 - bu x - A,  bD >= 0, B, k0 > 0, A > 0:
 * G is convex on x > 0 with G(0) = -A < 0, so the root is unique, and
 * Newton from a point where G >= 0 decreases to it monotonically.  At
 * x0 = |bu|/k0 + sqrt(A/k0), k0 x0^2 - bu x0 - A >= 0, so G(x0) >= 0.
 * The guess xg (pass_physical's: the line through the last two steps'
 * roots) is nearer: there G >= 0 starts the descent, and G < 0 with G' > 0
 * one Newton step first, whose tangent lies below the convex G, so it
 * lands at or past the root; else x0.  Newton from x0 took 8.6 iterations
 * a root (h = 0.1 r0, 100 kg at 0.1 m/s: 11 % of the run), from the last
 * root 2.2; on the warm row of h = r0 at 9.5 m/s 2.82 from the last root
 * with the stop |dx| <= 1e-15 x alone, 1.99 from the line with the
 * predicted stop below; the root the same to the last place or two. */
static double physical_root(double bD, double B, double k0, double bu, double A, double xg)
{
	double x = fabs(bu) / k0 + sqrt(A / k0), f = 0, df = 0;
	int known = 0; /* f and df at x are the guess's: not formed again
			* (half the first roots of a step start there) */
	if (xg > 0 && xg < x) {
		f = (((bD * xg + B) * xg + k0) * xg - bu) * xg - A;
		df = ((4.0 * bD * xg + 3.0 * B) * xg + 2.0 * k0) * xg - bu;
		if (f >= 0)
			x = xg, known = 1;
		else if (df > 0 && xg - f / df < x)
			x = xg - f / df;
	}
	for (int i = 0; i < 100; i++, known = 0) {
		if (!known) {
			f = (((bD * x + B) * x + k0) * x - bu) * x - A;
			df = ((4.0 * bD * x + 3.0 * B) * x + 2.0 * k0) * x - bu;
		}
		double d2 = (12.0 * bD * x + 6.0 * B) * x + 2.0 * k0, dx = f / df;
		x -= dx;
		/* the next step, G'' dx^2 / (2 G'), below a sixteenth of an ulp:
		 * it would not move x (the old test alone took one more step,
		 * whose dx was the rounding of f, a fifth of the calls) */
		if (fabs(dx) <= 1e-15 * x || fabs(d2) * dx * dx <= 0x1p-56 * x * df)
			break;
	}
	return x;
}

/* The physical contact (issue 10; doc/contact-model.md):
 *   W = alpha_H(P) + w_c - beta Q,
 * w_c the layer correction of a point load (the ramp given here; zero for
 * a half-space), -beta Q the half-space's radiation lag with dP/dt reduced
 * in order to its beta = 0 value Q = (3/2) K alpha^(1/2) (v - dw_c/dt)
 * (Landau and Lifshitz's treatment of radiation reaction: the unreduced
 * -beta dP/dt runs away, see contact.h).  The static indentation is
 * Hertz's alone.  Collocation at t_n as in pass_implicit, dw_c/dt by the
 * second-order backward difference of w_c; with x = P_n^(1/3),
 * (3/2) K alpha^(1/2) = 1.5 x / k0, and v_n, w_c(t_n) linear in P_n:
 *   G(x) = b D x^4 + B x^3 + k0 x^2 - b u0 x - A = 0,  b = 1.5 beta / k0,
 * u0 and D the parts of v_n - dw_c/dt(t_n) free of and linear in P_n.
 * Every piece is second order in dt, so the scheme is (tests/test_physical.c
 * measures it).  With tau_lag > 0 (impact.h) dw_c/dt is that of w_c
 * low-passed, y = (w_c - z)/tau_lag, z' = (w_c - z)/tau_lag by the
 * trapezoidal rule (r = dt/(2 tau_lag)): bounded gain up to Nyquist, so
 * the lag cannot feed a derivative of the delayed load back into P.  The contact ends where A = 0: alpha = 0 takes the lag
 * with it, and finish_exact's alpha_end is W - w_c there (its far past,
 * Q's through ramp2 - ramp included, by far_exact/far_cubic as for the
 * paper's contact).  The march goes on through repeated contacts as in
 * pass_implicit: out of contact P = Q = 0, w = w_c (the layer's free
 * response), until the two have parted for good.  The past's sums come
 * from the online fast convolution: P against g (fc) and, with the true
 * radius, Q against dg = g2 - g (fc a pair).
 *
 * The second order (issue 11; g2 > 0): -beta dP/dt's reduction and the
 * reactive term after it enter as Sigma (impact_lag2.c), which the state
 * and the exact end search see as well. */
static int pass_physical(struct ctx *c, struct pass *s, double beta)
{
	const struct anvil_params *p = c->p;
	const struct impact_lag2 l2 = impact_lag2_of(c);
	double dt = s->dt, b = 1.5 * beta / p->k0;
	double tl = c->tau_lag, rl = 0.5 * dt / tl, zl = 0; /* the lag's filter */
	double udp = 0, z2 = 0; /* dw_c/dt's last node; the second stage */
	double S0 = 0, S1 = 0, impulse = 0;
	double ioff = 0, a_prev = 0, amax = 0;
	/* the last root, and the last two steps' (their line is
	 * physical_root's guess: 2 Newton steps a root where the last root
	 * took 3 to 4) */
	double xr = 0, xr1 = 0, xr2 = 0;
	int in = 1;
	s->v[0] = p->V0;
	s->n = 1;
	s->ncont = 1;
	s->on[0] = 0;
	anvil_fastconv_reset(c->fc);
	anvil_fastconv_push(c->fc, 0.0);
	for (size_t n = 1; n < s->cap; n++) {
		int L = impact_grow_due(c, s, n, in), st;
		if (L && (st = impact_grow_switch(c, s, L)))
			return st;
		if (L)
			dt = s->dt, rl = 0.5 * dt / tl, S0 = S1 = 0, xr2 = 0;
		size_t i = n - c->seg0; /* the segment's node; n on the first */
		if (i >= c->segcap)
			break;
		double tn = (double)i * dt, conv = anvil_fastconv_next(c->fc), g0 = c->g[0];
		double hw = 0.0, mh = (c->T0 + tn) * c->Ih - c->M1h;
		if (c->nfz && (st = impact_hist(c, i, &hw)))
			return st;
		conv += hw; /* the frozen past's w_c */
		if (c->dg) {
			/* the true radius, a^2/a_ref^2 = alpha/alpha_ref, of each past load
			 * (in conv: fc's second kernel, Q against dg); the current one's
			 * (in g0 only, zero before the bottom reflection) extrapolated,
			 * second order; alpha_H = 0 at a node out of contact */
			double q1 = s->P[n - 1] > 0 ? s->Q[n - 1] / s->P[n - 1] : 0.0;
			double q2 = n >= 3 && s->P[n - 2] > 0 ? s->Q[n - 2] / s->P[n - 2] : q1;
			g0 += (2.0 * q1 - q2) * c->dg[0];
		}
		double B = g0 + dt * dt / (6.0 * p->m1);
		double A = p->V0 * (c->T0 + tn) - dt / p->m1 * (tn * S0 - S1) - conv - mh / p->m1;
		double P = 0, Q = 0, sig = 0;
		/* dw_c/dt(t_n) = wd0 + e0 P_n: low-passed at tau_lag (see above),
		 * else BDF2 (Euler at the first step) */
		double wd0, e0;
		if (tl > 0) {
			wd0 = (conv - (1.0 - rl) * zl - rl * s->wc[n - 1]) / ((1.0 + rl) * tl);
			e0 = g0 / ((1.0 + rl) * tl);
		} else if (i >= 2) { /* BDF2 within a segment */
			wd0 = (3.0 * conv - 4.0 * s->wc[n - 1] + s->wc[n - 2]) / (2.0 * dt);
			e0 = 1.5 * g0 / dt;
		} else if (c->seg0) { /* a grown segment's first node: BDF2 on the
				       * steps dt/2 then dt */
			wd0 = (5.0 * conv - 9.0 * s->wc[n - 1] + 4.0 * s->wc[n - 2]) / (3.0 * dt);
			e0 = 5.0 * g0 / (3.0 * dt);
		} else {
			wd0 = (conv - s->wc[n - 1]) / dt;
			e0 = g0 / dt;
		}
		double v0 = p->V0 - (impulse + 0.5 * dt * s->P[n - 1]) / p->m1, u0 = v0 - wd0;
		double sgd = impact_lag2_before(&l2, c, s, n, in, impulse, u0);
		double Ae = A - sgd;
		s->sg[n] = sgd; /* before the state: it may end a contact here */
		/* touching before the outer solution's start (above): no force */
		int pre = in && !(impulse > 0) && !(Ae > 0);
		if (!pre)
			st = impact_contact_state(c, s, n, Ae, a_prev, amax, impulse, &in, &ioff);
		/* at rest on the plate before the chatter, or before a contact's
		 * end was lost (impact_rest.c) */
		if ((st == IMPACT_BUDGET || st == IMPACT_END_LOST) && impact_rest_fallback(s))
			break;
		if (st)
			return st;
		double D = 0.5 * dt / p->m1 + e0;
		if (in && !pre) {
			xr = physical_root(b * D, B, p->k0, b * u0, Ae,
					   xr1 > 0 && xr2 > 0 ? 2.0 * xr1 - xr2 : xr1);
			P = xr * xr * xr;
		}
		if (in && P > 0 && (l2.cu != 0 || l2.cx != 0)) {
			/* one round: Sigma at that P (the filter's trial state),
			 * then the step's root with it */
			double zt = z2, ud = wd0 + e0 * P, u = u0 - D * P;
			double s1 = impact_lag2_after(&l2, p, P, xr, u,
						      impact_lag2_wdd(ud, udp, tl, rl, &zt));
			xr = A - s1 > 0 ? physical_root(b * D, B, p->k0, b * u0, A - s1, xr) : 0.0;
			P = xr * xr * xr;
			s->sg[n] = sgd = s1;
		}
		/* P^(1/3): the root itself (P > 0 only from it), not the cube
		 * root of its cube, which took a twentieth of a warm run */
		double x = P > 0 ? xr : 0.0;
		xr2 = xr1, xr1 = x;
		a_prev = in ? p->k0 * x * x : Ae; /* alpha_H in contact; the gap's A out of it */
		amax = fmax(amax, in ? a_prev : 0.0);
		s->P[n] = P;
		s->Q[n] = c->dg ? P * p->k0 * x * x / c->alpha_ref : 0.0;
		s->wc[n] = conv + P * g0;
		if (tl > 0) /* the filter's state, trapezoidal (Tustin) */
			zl = ((1.0 - rl) * zl + rl * (s->wc[n] + s->wc[n - 1])) / (1.0 + rl);
		impulse += 0.5 * dt * (s->P[n - 1] + P);
		s->v[n] = p->V0 - impulse / p->m1;
		if (in)
			Q = 1.5 * x / p->k0 * (s->v[n] - (wd0 + e0 * P));
		double ud = wd0 + e0 * P;
		if (tl > 0) /* the second stage's state */
			impact_lag2_wdd(ud, udp, tl, rl, &z2);
		sig = P > 0 ? sgd : 0.0;
		udp = ud;
		s->W[n] = p->V0 * (c->T0 + tn) - dt / p->m1 * (tn * S0 - S1) - P * dt * dt / (6.0 * p->m1) -
			  mh / p->m1;
		s->w[n] = s->wc[n] - beta * Q + sig;
		s->t[n] = (double)(c->K0 + (i << c->lev)) * s->dt0;
		S0 += P;
		S1 += P * tn;
		s->n = n + 1;
		if ((st = push_status(anvil_fastconv_push_pair(c->fc, P, s->Q[n]))))
			return st;
		if (impact_rest_check(c, s, n, in))
			break;
		if (!in && !s->pend_k && impact_parted(c, s, n, impulse, amax)) {
			s->parted = 1;
			break;
		}
	}
	/* at rest on the plate (impact_rest.c): no end; or in contact at the
	 * last window's end after coming to rest, or chattering since */
	if (s->rest || ((in || s->v[s->n - 1] >= 0) && impact_rest_final(c, s, in) && impact_rest_fallback(s))) {
		impact_peak(s);
		return ANVIL_OK;
	}
	int st = impact_sep_resolve(c, s, &ioff); /* a separation at the window's end */
	if (st == IMPACT_END_LOST && impact_rest_fallback(s)) {
		impact_peak(s);
		return ANVIL_OK;
	}
	if (st)
		return st;
	if (in || s->v[s->n - 1] >= 0)
		/* a contact, or a new one, outlasts the window (or the nodes) */
		return impact_long_short(c, s) ? IMPACT_NODES : ANVIL_ETOL;
	if (impact_rest_grazing(c, s, ioff) && impact_rest_fallback(s)) {
		impact_peak(s);
		return ANVIL_OK;
	}
	if (!s->parted)
		s->parted = 2;
	s->Vs = -(p->V0 - ioff / p->m1);
	impact_peak(s);
	return ANVIL_OK;
}

/* The paper's explicit scheme, eqs (42)-(46): the deflection lags one step
 * (w_n from forces up to t_{n-1}) and uses the impulse response w_delta,
 * here the second difference of the ramp response (w_delta(0) from eq 34). */
static int pass_paper(const struct ctx *c, struct pass *s)
{
	const struct anvil_params *p = c->p;
	double dt = s->dt, a_prev = 0, impulse = 0;
	double wd0 = 3.0 / (2.0 * M_PI * p->r0 * p->r0) / (p->rho * p->c1);
	s->v[0] = p->V0;
	s->n = 1;
	anvil_fastconv_reset(c->fc);
	for (size_t n = 1; n < s->cap; n++) {
		double W = n == 1 ? p->V0 * dt : s->W[n - 1] + s->v[n - 1] * dt + 0.5 * a_prev * dt * dt;
		/* w_delta(t_{n-1} - t_m) = g'/dt over m < n - 1 (P_0 = 0), the
		 * pushes so far: the fast convolution, O(N log^2 N) (a direct
		 * sum took minutes on a 2.4e5-step contact, h = 0.3 r0) */
		double w = n >= 2 ? 0.5 * dt * wd0 * s->P[n - 1] + anvil_fastconv_next(c->fc) : 0.0;
		double v = n == 1 ? p->V0 : s->v[n - 1] + a_prev * dt;
		if (W - w <= 0) {
			impact_finish(s, p, W - w, impulse);
			/* the paper's own velocity update, eq (46), to the contact end */
			s->Vs = -(s->v[n - 1] + a_prev * (s->ts - (double)(n - 1) * dt));
			s->ncont = 1, s->on[0] = 0, s->off[0] = s->ts; /* one contact: not followed on */
			return ANVIL_OK;
		}
		s->P[n] = p->K * pow(W - w, 1.5);
		s->W[n] = W;
		s->w[n] = w;
		s->v[n] = v;
		impulse += 0.5 * dt * (s->P[n - 1] + s->P[n]);
		a_prev = -s->P[n] / p->m1;
		s->n = n + 1;
		int st = push_status(anvil_fastconv_push(c->fc, s->P[n - 1]));
		if (st)
			return st;
	}
	return ANVIL_ETOL;
}

/* The pass of step dt (fine: the dt/2 one): the window's nodes cap, the
 * nodes the march may make, the first segment's weights nw; cap < 8 is
 * too few. */
static void pass_sizes(const struct ctx *c, double dt, int fine, size_t *cap, size_t *nodes,
		       size_t *nw)
{
	double t_avail = c->tau_avail * c->p->r0 / c->p->c2;
	*cap = *nodes = *nw = (size_t)floor(t_avail / dt) - 1;
	if (c->lng) { /* the nodes the march may make, the first segment's weights */
		size_t mult = fine ? 2 : 1, w0 = 2 * c->grow_after + 64;
		*nodes = *cap < mult * c->max_nodes ? *cap : mult * c->max_nodes;
		w0 = mult * (w0 > IMPACT_LONG_SEG ? w0 : IMPACT_LONG_SEG);
		*nw = *nodes < w0 ? *nodes : w0;
	}
}

static int run_pass(struct ctx *c, enum anvil_scheme scheme, double dt, size_t direct_max,
		    struct pass *s)
{
	size_t cap, nodes, nw;
	pass_sizes(c, dt, c->sched != NULL, &cap, &nodes, &nw);
	if (cap < 8)
		return ANVIL_ETOL;
	int st = pass_alloc(s, nodes, dt);
	free(c->g);
	free(c->dg);
	impact_grow_reset(c);
	c->g = c->dg = NULL;
	c->seg0 = c->K0 = 0, c->lev = 0, c->T0 = c->Ih = c->M1h = 0, c->segcap = nw;
	c->dt0 = dt;
	c->nR = cap + 1;
	c->nR0 = nw + 1;
	c->rsh = c->sched ? 0 : 1; /* the table is in the dt/2 pass's dt0 */
	if (!st)
		st = weights(c, nw);
	anvil_fastconv_free(c->fc);
	c->fc = NULL;
	impact_end_tab_free(c->tab); /* a new dt */
	if (!st && !(c->fc = impact_fc_alloc(c, direct_max)))
		st = ANVIL_ENOMEM;
	if (!st)
		st = scheme == ANVIL_SCHEME_PAPER ? pass_paper(c, s)
		     : c->physical		  ? pass_physical(c, s, c->beta)
						  : pass_implicit(c, s);
	return st;
}

/* Richardson extrapolation for a second-order scheme (fine = dt/2).  The
 * error estimate is the whole difference, not the asymptotic third of it:
 * V_s converges faster than second order and then meets a floor (~1e-8,
 * the end-of-contact interpolation), where the third would be optimistic
 * (tests/test_layer.c checks that the estimates cover the error). */
static double extrap(double coarse, double fine, double *err)
{
	*err = fabs(fine - coarse);
	return fine + (fine - coarse) / 3.0;
}

/* E_a = m1 (V0^2 - V_s^2)/2 moves by at most m1 (|V_s| e + e^2/2) when
 * V_s moves by e: the linear term alone vanishes at V_s = 0 (a dead
 * rebound, R_f near 0), where the quadratic one is the whole error. */
static double ea_err(const struct anvil_params *p, const struct anvil_result *r)
{
	return p->m1 * (fabs(r->Vs.val) + 0.5 * r->Vs.err) * r->Vs.err;
}

/* The contacts of the finer pass; when the passes disagree on how many
 * there are, extrapolation means nothing: the fine values stand, with the
 * whole difference (at least) as their error. */
static void fill_contacts(struct anvil_result *r, const struct anvil_params *p,
			  const struct pass *a, const struct pass *b)
{
	size_t nc = b->ncont < ANVIL_MAX_CONTACTS ? b->ncont : ANVIL_MAX_CONTACTS;
	r->ncontacts = b->ncont;
	memcpy(r->contact_on, b->on, nc * sizeof *b->on);
	memcpy(r->contact_off, b->off, nc * sizeof *b->off);
	if (nc && b->ncont <= ANVIL_MAX_CONTACTS)
		r->contact_off[nc - 1] = r->ts.val;
	r->t_free = b->nseg == 1 ? (double)(b->n - 1) * b->dt : b->t[b->n - 1];
	if (a->ncont == b->ncont)
		return;
	r->ts.val = b->ts, r->ts.err = fmax(r->ts.err, fabs(b->ts - a->ts));
	r->Vs.val = b->Vs, r->Vs.err = fmax(r->Vs.err, fabs(b->Vs - a->Vs));
	r->Rf.val = r->Vs.val / p->V0, r->Rf.err = r->Vs.err / p->V0;
	r->Ea.val = 0.5 * p->m1 * (p->V0 * p->V0 - r->Vs.val * r->Vs.val);
	r->Ea.err = ea_err(p, r);
}

/* The rounding of a pass's rebound velocity: v = V0 - impulse/m1 sums
 * its n trapezoids one by one, and a recursive sum of n terms is off by
 * at most (n - 1) u sum|terms| (Higham, Accuracy and Stability of
 * Numerical Algorithms, 2002, eq. 4.4), u = eps/2; sum|terms| = impulse/m1
 * = V0 - V_s (P >= 0).  It matters only where V_s is a cancellation far
 * below V0: a 500 g rod on 1 mm steel rebounds at 6e-8 V0, and the
 * levels' passes, grown on different schedules, differed by 2.8e-12 V0
 * against a Richardson estimate of 2.5e-12. */
static double vs_rounding(const struct anvil_params *p, const struct pass *s)
{
	return (double)s->n * 0.5 * DBL_EPSILON * (p->V0 + fabs(s->Vs));
}

static void fill(struct anvil_result *r, const struct anvil_params *p,
		 const struct pass *a, const struct pass *b, enum anvil_scheme scheme)
{
	if (scheme == ANVIL_SCHEME_PAPER) { /* first order: report the step asked for */
		r->ts.val = a->ts, r->ts.err = fabs(b->ts - a->ts);
		r->tmax.val = a->tmax, r->tmax.err = fabs(b->tmax - a->tmax) + a->tmax_ie;
		r->Pmax.val = a->Pmax, r->Pmax.err = fabs(b->Pmax - a->Pmax);
		r->Vs.val = a->Vs, r->Vs.err = fabs(b->Vs - a->Vs);
	} else {
		r->ts.val = extrap(a->ts, b->ts, &r->ts.err);
		r->tmax.val = extrap(a->tmax, b->tmax, &r->tmax.err);
		/* extrap is 4/3 fine - 1/3 coarse: so are its interpolation errors */
		r->tmax.err += (4.0 * b->tmax_ie + a->tmax_ie) / 3.0;
		r->Pmax.val = extrap(a->Pmax, b->Pmax, &r->Pmax.err);
		r->Vs.val = extrap(a->Vs, b->Vs, &r->Vs.err);
	}
	/* extrap takes 4/3 of the fine pass's and 1/3 of the coarse's rounding */
	r->Vs.err += scheme == ANVIL_SCHEME_PAPER ? vs_rounding(p, a)
		     : (4.0 * vs_rounding(p, b) + vs_rounding(p, a)) / 3.0;
	r->Rf.val = r->Vs.val / p->V0;
	r->Rf.err = r->Vs.err / p->V0;
	r->Ea.val = 0.5 * p->m1 * (p->V0 * p->V0 - r->Vs.val * r->Vs.val);
	r->Ea.err = ea_err(p, r);
	r->lambda_star = p->lambda_star;
	r->Rf_star = p->Rf_star;
	r->Pmax_curv = b->curv > 0 ? b->curv : a->curv;
	impact_plateau(b->curv > 0 ? b : a, r->Pmax_plat);
	fill_contacts(r, p, a, b);
}

/* The ramps' tables of n entries at dt0 (ramp2's when given): from the
 * caller's share by their names, else from own by their contexts.
 * ANVIL_OK, or ANVIL_ENOMEM (own NULL: its allocation failed). */
static int rtabs_get(struct ctx *c, const struct anvil_impact_opts *o,
		     struct anvil_ramp_share *own, double dt0, size_t n)
{
	struct anvil_ramp_share *sh = o->share ? o->share : own;
	c->share = sh;
	for (int r = 0; r < 1 + (c->ramp2 != NULL); r++) {
		struct rtab_key k = { .p = c->p, .fn = r ? c->ramp2 : c->ramp, .dt0 = dt0, .n = n };
		if (o->share)
			memcpy(k.name, r ? o->ramp2_name : o->ramp_name, sizeof k.name);
		else
			k.ctx = r ? c->rctx2 : c->rctx;
		if (!sh || !(c->rt[r] = impact_rtab_get(sh, &k)))
			return ANVIL_ENOMEM;
	}
	return ANVIL_OK;
}

int anvil_impact_run(const struct anvil_params *p, anvil_ramp_fn ramp, void *rctx,
		     double tau_avail, const struct anvil_impact_opts *o,
		     struct anvil_result *r, struct anvil_err *err)
{
	double dt = o->dt > 0 ? o->dt : o->dt_auto;
	if (!(dt > 0))
		return anvil_err_set(err, ANVIL_EINVAL, "impact: no time step");
	int lng = tau_avail * p->r0 / p->c2 / dt > (double)o->max_steps;
	if (lng && !(o->t_smooth > 0 && o->grow_after && o->scheme != ANVIL_SCHEME_PAPER))
		return anvil_err_set(err, ANVIL_ETOL,
				     "the contact (over %.3g us) needs more than %zu steps of %.3g us",
				     tau_avail * p->r0 / p->c2 * 1e6, o->max_steps, dt * 1e6);
	int st;
	struct ctx c = { .p = p, .ramp = ramp, .rctx = rctx, .tau_avail = tau_avail,
			 .physical = o->physical, .beta = o->beta,
			 .g2 = o->physical && o->g2 > 0 ? o->g2 : 0.0,
			 .ramp2 = o->physical && o->alpha_ref > 0 ? o->ramp2 : NULL,
			 .rctx2 = o->ramp2_ctx, .alpha_ref = o->alpha_ref,
			 .tau_lag = o->physical && o->tau_lag > 0 ? o->tau_lag : 0.0,
			 .merge_gap = o->merge_gap > 0 ? o->merge_gap : 0.0,
			 .merge_time = o->merge_time > 0 ? o->merge_time : 0.0,
			 .max_contacts = o->max_contacts,
			 .rest_tol = o->rest_tol > 0 && o->scheme != ANVIL_SCHEME_PAPER ? o->rest_tol : 0.0,
			 .grow_after = o->scheme == ANVIL_SCHEME_PAPER ? 0 : o->grow_after,
			 .grow_eta = o->grow_eta, .lng = lng, .t_smooth = o->t_smooth,
			 .max_nodes = o->max_steps, .imp = { o->impulse, o->impulse2 },
			 .ictx = { o->impulse_ctx, o->impulse2_ctx } };
	c.rest_stop = c.rest_tol > 0 && o->rest_at > 0 ? o->rest_at : 0.0;
	c.rest_long = impact_rest_long(p);
	c.rest_last = o->rest_last;
	if (o->physical && (!(o->beta >= 0) || !isfinite(o->beta) || !(o->g2 >= 0) ||
			    !isfinite(o->g2) || (o->g2 > 0 && !(o->tau_lag > 0)) ||
			    o->scheme == ANVIL_SCHEME_PAPER))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "impact: the physical contact needs beta >= 0, g2 >= 0 (with g2 > 0, tau_lag > 0) and the implicit scheme");
	struct pass a = {0}, b = {0};
	struct end_tab tab = {0};
	c.tab = &tab;
	/* the FFT tables of the finer pass's capacity (run_pass) serve both */
	double fcap = fmax(tau_avail * p->r0 / p->c2 / (0.5 * dt), 1.0);
	struct anvil_fastconv_fft *fft =
		anvil_fastconv_fft_alloc((size_t)(lng ? fmin(fcap, 2.0 * (double)o->max_steps) : fcap),
					 o->direct_max);
	/* the ramps' tables, the dt/2 pass's first segment's reach (the dt
	 * pass's lies within: its u is 2u there): the caller's share's, or
	 * this impact's own */
	struct anvil_ramp_share *own = o->share ? NULL : anvil_ramp_share_alloc();
	size_t fcp, fnodes, fnw;
	pass_sizes(&c, 0.5 * dt, 1, &fcp, &fnodes, &fnw);
	if (!(c.fft = fft) || (fcp >= 8 && rtabs_get(&c, o, own, 0.5 * dt, fnw + 1))) {
		anvil_fastconv_fft_free(fft);
		anvil_ramp_share_free(own);
		return anvil_err_set(err, ANVIL_ENOMEM, "impact: %s", anvil_strerror(ANVIL_ENOMEM));
	}
	st = run_pass(&c, o->scheme, dt, o->direct_max, &a);
	struct pass *last = &a; /* the pass that ran last, for the messages */
	c.rest_stop = a.rest ? a.ts : c.rest_stop; /* the finer pass stops there too */
	c.sched = &a; /* the dt/2 pass: the dt pass's steps, halved */
	if (!st)
		st = run_pass(&c, o->scheme, 0.5 * dt, o->direct_max, last = &b);
	if (!st && o->single) { /* the dt pass alone; its error vs dt/2 */
		fill(r, p, &a, &b, ANVIL_SCHEME_PAPER);
		if (a.rest || b.rest)
			impact_rest_fill(r, p, &a, &b);
		if (o->hist_nodes || o->nhist > 1)
			st = o->hist_nodes ? impact_node_history(&a, &r->hist) : impact_resample(&a, o->nhist, &r->hist);
	} else if (!st) {
		fill(r, p, &a, &b, o->scheme);
		if (a.rest || b.rest)
			impact_rest_fill(r, p, &a, &b);
		else if (o->scheme != ANVIL_SCHEME_PAPER)
			r->ts_graze = impact_graze_ts(&a, &b);
		const struct pass *hp = o->scheme == ANVIL_SCHEME_PAPER ? &a : &b;
		if (o->hist_nodes || o->nhist > 1)
			st = o->hist_nodes ? impact_node_history(hp, &r->hist) : impact_resample(hp, o->nhist, &r->hist);
	}
	if (st == IMPACT_BUDGET) { /* finite t_s: the caller tries no longer window */
		st = ANVIL_ETOL;
		r->ts.val = INFINITY;
		anvil_err_set(err, st,
			      "the impactor and the layer part and touch again more than %zu times (a contact chatters below the time step's resolution; by t = %.4g us the impactor still moves at %.3g m/s, not at rest on the plate); the thin-plate model 'zener' applies here",
			      o->max_contacts, (double)(last->n - 1) * last->dt * 1e6,
			      last->n ? last->v[last->n - 1] : p->V0);
	} else if (st == IMPACT_NODES) { /* no longer window helps */
		st = ANVIL_ETOL;
		r->ts.val = INFINITY;
		anvil_err_set(err, st,
			      "the contact needs more than %zu steps even with the growing step (the force stays rough near t = %.4g us); the thin-plate model 'zener' applies here",
			      o->max_steps, last->n ? last->t[last->n - 1] * 1e6 : 0.0);
	} else if (st == ANVIL_ETOL) {
		r->ts.val = NAN;
		anvil_err_set(err, st, "the contact outlasts the computed response (%.3g us)",
			      tau_avail * p->r0 / p->c2 * 1e6);
	} else if (st == IMPACT_END_LOST) {
		st = ANVIL_ENUM;
		anvil_err_set(err, st,
			      "impact: the contact's end near t = %.4g us is lost (the approach has no zero within the step of %.3g us): the time stepping ran away there; a higher solver.accuracy or a smaller solver.dt may settle it",
			      last->ts * 1e6, last->dt * 1e6);
	} else if (st) {
		anvil_err_set(err, st, "impact: %s", anvil_strerror(st));
	}
	free(c.g);
	anvil_fastconv_free(c.fc);
	free(c.dg);
	anvil_ramp_share_free(own);
	impact_grow_free(&c);
	impact_end_tab_free(&tab);
	anvil_fastconv_fft_free(fft);
	pass_free(&a);
	pass_free(&b);
	return st;
}
