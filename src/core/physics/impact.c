#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "impact.h"

/* One time-stepping pass at a fixed dt.  Arrays are per step n = 0..n-1. */
struct pass {
	double dt;
	size_t n, cap;
	double *P, *W, *w, *v; /* one block, owned */
	double *wc;            /* physical contact: the layer correction's deflection */
	double *Q;             /* physical contact: P alpha_H / alpha_ref (true radius) */
	double ts, tmax, Pmax, Vs;
};

struct ctx {
	const struct anvil_params *p;
	anvil_ramp_fn ramp;
	void *rctx;
	double tau_avail;
	double *g;      /* convolution weights g_j, j < ng */
	size_t ng;
	int physical;   /* the physical contact (opts), with beta */
	double beta;
	anvil_ramp_fn ramp2; /* the correction of the patch of radius a_ref (opts) */
	void *rctx2;
	double alpha_ref;
	double *dg;     /* its weights less g's, when ramp2 is given */
};

static void pass_free(struct pass *s)
{
	free(s->P);
	memset(s, 0, sizeof *s);
}

static int pass_alloc(struct pass *s, size_t cap, double dt)
{
	memset(s, 0, sizeof *s);
	s->P = calloc(6 * cap, sizeof *s->P);
	if (!s->P)
		return ANVIL_ENOMEM;
	s->W = s->P + cap;
	s->w = s->P + 2 * cap;
	s->v = s->P + 3 * cap;
	s->wc = s->P + 4 * cap;
	s->Q = s->P + 5 * cap;
	s->cap = cap;
	s->dt = dt;
	return ANVIL_OK;
}

/* Dimensional ramp response Rr(t) (m s/N): the anvil's response to P = t. */
static int ramp_of(const struct ctx *c, anvil_ramp_fn fn, void *ctx, double t, double *val)
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

static int ramp_at(const struct ctx *c, double t, double *val)
{
	return ramp_of(c, c->ramp, c->rctx, t, val);
}

/* Weights of the product integration: the deflection at t_n caused by the
 * hat function of unit height centred at t_m is g_{n-m}, the second
 * difference of the ramp response divided by dt. */
static int weights(struct ctx *c, double dt, size_t cap)
{
	double *R = malloc((cap + 2) * sizeof *R);
	c->g = malloc(cap * sizeof *c->g);
	if (!R || !c->g) {
		free(R);
		return ANVIL_ENOMEM;
	}
	int st = ANVIL_OK;
	for (size_t j = 0; j < cap + 1 && !st; j++)
		st = ramp_at(c, (double)j * dt, &R[j]);
	for (size_t j = 0; j < cap && !st; j++)
		c->g[j] = (R[j + 1] - 2.0 * R[j] + (j ? R[j - 1] : 0.0)) / dt;
	c->ng = cap;
	if (c->ramp2 && !st) { /* dg = g2 - g */
		c->dg = malloc(cap * sizeof *c->dg);
		if (!c->dg)
			st = ANVIL_ENOMEM;
		for (size_t j = 0; j < cap + 1 && !st; j++)
			st = ramp_of(c, c->ramp2, c->rctx2, (double)j * dt, &R[j]);
		for (size_t j = 0; j < cap && !st; j++)
			c->dg[j] = (R[j + 1] - 2.0 * R[j] + (j ? R[j - 1] : 0.0)) / dt - c->g[j];
	}
	free(R);
	return st;
}

/* The one positive root of k0 x^2 + B x^3 = A (x = P^(1/3)), A > 0.
 * Newton from the upper bound sqrt(A/k0) decreases monotonically (the
 * left side is increasing and convex for x > 0), so it cannot overshoot;
 * GSL's cubic solver loses digits here when B x << k0. */
static double hertz_root(double k0, double B, double A)
{
	double x = sqrt(A / k0);
	for (int i = 0; i < 60; i++) {
		double f = k0 * x * x + B * x * x * x - A;
		double dx = f / (2.0 * k0 * x + 3.0 * B * x * x);
		x -= dx;
		if (fabs(dx) <= 1e-15 * x)
			break;
	}
	return x * x * x;
}

/* Root in (t1, t2) of the parabola through (t0,a0), (t1,a1), (t2,a2),
 * a1 > 0 >= a2: where alpha_H returns to zero. */
static double zero_crossing(double t0, double a0, double t1, double a1, double t2, double a2)
{
	double lo = t1, hi = t2;
	for (int i = 0; i < 100; i++) {
		double t = 0.5 * (lo + hi);
		double q = a0 * (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)) +
			   a1 * (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)) +
			   a2 * (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
		if (q > 0)
			lo = t;
		else
			hi = t;
	}
	return 0.5 * (lo + hi);
}

/* Peak of the force by a parabola through the largest sample and its
 * neighbours. */
static void peak(struct pass *s)
{
	size_t k = 0;
	for (size_t i = 1; i < s->n; i++)
		if (s->P[i] > s->P[k])
			k = i;
	s->tmax = (double)k * s->dt;
	s->Pmax = s->P[k];
	if (k == 0 || k + 1 >= s->n)
		return;
	double a = s->P[k - 1], b = s->P[k], c = s->P[k + 1];
	double den = a - 2.0 * b + c;
	if (den < 0) {
		double x = 0.5 * (a - c) / den;
		s->tmax = ((double)k + x) * s->dt;
		s->Pmax = b - 0.25 * (a - c) * x;
	}
}

/* The end of contact between steps n-1 and n, where alpha would be a_n <= 0;
 * V_s from the impulse, the last partial interval with P ~ (t_s - t)^(3/2)
 * since alpha_H falls linearly to zero. */
static void finish(struct pass *s, const struct anvil_params *p, double a_n, double impulse)
{
	size_t n = s->n;
	double dt = s->dt, t1 = (double)(n - 1) * dt;
	double a1 = p->k0 * pow(s->P[n - 1], 2.0 / 3.0);
	double a0 = n >= 2 ? p->k0 * pow(s->P[n - 2], 2.0 / 3.0) : 0.0;
	s->ts = n >= 2 ? zero_crossing(t1 - dt, a0, t1, a1, t1 + dt, a_n)
		       : t1 + dt * a1 / (a1 - a_n);
	impulse += 0.4 * s->P[n - 1] * (s->ts - t1);
	s->Vs = -(p->V0 - impulse / p->m1);
	peak(s);
}

/* The end of contact, consistent with the scheme: P falls linearly from
 * P_{n-1} to 0 at t_s = t_{n-1} + d, so the last hat is asymmetric (left
 * half-width dt, right d).  alpha_H(t_s) = W(t_s) - w(t_s) = 0 is solved for
 * d by Brent's method (GSL), with W and w evaluated exactly for that P. */
struct end_ctx {
	const struct ctx *c;
	const struct pass *s;
	size_t n;  /* steps taken: nodes 0 .. n-1 */
	double *R; /* scratch: R(j dt + d), j = 0 .. n */
};

/* The deflection at t_k + d of the loads F (hats at t_m, the last one
 * ending at t_k + d) through the ramp response R at j dt + d. */
static double end_deflection(const double *F, const double *R, size_t k, double dt, double d)
{
	double w = 0;
	for (size_t m = 1; m < k; m++)
		w += F[m] * (R[k - m + 1] - 2.0 * R[k - m] + R[k - m - 1]) / dt;
	return w + F[k] * (R[1] / dt - R[0] * (1.0 / dt + 1.0 / d));
}

static double alpha_end(double d, void *vp)
{
	const struct end_ctx *e = vp;
	const struct anvil_params *p = e->c->p;
	const double *P = e->s->P, dt = e->s->dt;
	size_t k = e->n - 1; /* the last node with P > 0 */
	double t1 = (double)k * dt, tau = t1 + d, mom = 0, w, *R = e->R;
	/* every response needed is R at j dt + d: k + 2 evaluations, not 3k */
	for (size_t j = 0; j <= k + 1; j++)
		ramp_at(e->c, (double)j * dt + d, &R[j]);
	for (size_t m = 1; m < k; m++)
		mom += P[m] * dt * (tau - (double)m * dt);
	/* the asymmetric last hat: int (tau - t') hat dt' = (tau - t_{k-1}) dt/2 - dt^2/3 + d^2/3 */
	mom += P[k] * ((tau - t1 + dt) * dt / 2.0 - dt * dt / 3.0 + d * d / 3.0);
	w = end_deflection(P, R, k, dt, d);
	if (e->c->dg) { /* the true contact radius: + Q through (R2 - R) */
		w -= end_deflection(e->s->Q, R, k, dt, d);
		for (size_t j = 0; j <= k + 1; j++)
			ramp_of(e->c, e->c->ramp2, e->c->rctx2, (double)j * dt + d, &R[j]);
		w += end_deflection(e->s->Q, R, k, dt, d);
	}
	return p->V0 * tau - mom / p->m1 - w;
}

static int finish_exact(const struct ctx *c, struct pass *s, double impulse)
{
	struct end_ctx e = { c, s, s->n, malloc((s->n + 2) * sizeof(double)) };
	gsl_function f = { alpha_end, &e };
	gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	double lo = 1e-9 * s->dt, hi = s->dt, d = hi;
	if (!rs || !e.R) {
		gsl_root_fsolver_free(rs);
		free(e.R);
		return ANVIL_ENOMEM;
	}
	int st = gsl_root_fsolver_set(rs, &f, lo, hi);
	for (int i = 0; !st && i < 100; i++) {
		st = gsl_root_fsolver_iterate(rs);
		d = gsl_root_fsolver_root(rs);
		lo = gsl_root_fsolver_x_lower(rs);
		hi = gsl_root_fsolver_x_upper(rs);
		if (!st && gsl_root_test_interval(lo, hi, 1e-14 * s->dt, 1e-13) == GSL_SUCCESS)
			break;
	}
	gsl_root_fsolver_free(rs);
	free(e.R);
	if (st)
		return ANVIL_ENUM;
	size_t k = s->n - 1;
	s->ts = (double)k * s->dt + d;
	s->Vs = -(c->p->V0 - (impulse + 0.5 * s->P[k] * d) / c->p->m1);
	peak(s);
	return ANVIL_OK;
}

/* The implicit, second-order pass (see impact.h).  With P piecewise linear
 * through the P_m, the impactor's displacement at t_n is exactly
 *   W_n = V0 t_n - (dt/m1) sum_{m<n} P_m (t_n - t_m) - P_n dt^2/(6 m1)
 * and the anvil's w_n = sum_{m<=n} P_m g_{n-m}. */
static int pass_implicit(const struct ctx *c, struct pass *s)
{
	const struct anvil_params *p = c->p;
	double dt = s->dt, B = c->g[0] + dt * dt / (6.0 * p->m1);
	double S0 = 0, S1 = 0, impulse = 0; /* sum P_m, sum P_m t_m, int P dt */
	s->v[0] = p->V0;
	s->n = 1;
	for (size_t n = 1; n < s->cap; n++) {
		double tn = (double)n * dt, conv = 0;
		for (size_t m = 1; m < n; m++)
			conv += s->P[m] * c->g[n - m];
		double A = p->V0 * tn - dt / p->m1 * (tn * S0 - S1) - conv;
		if (A <= 0)
			return n >= 3 ? finish_exact(c, s, impulse) : (finish(s, p, A, impulse), ANVIL_OK);
		double P = hertz_root(p->k0, B, A);
		s->P[n] = P;
		s->W[n] = p->V0 * tn - dt / p->m1 * (tn * S0 - S1) - P * dt * dt / (6.0 * p->m1);
		s->w[n] = conv + P * c->g[0];
		impulse += 0.5 * dt * (s->P[n - 1] + P);
		s->v[n] = p->V0 - impulse / p->m1;
		S0 += P;
		S1 += P * tn;
		s->n = n + 1;
	}
	return ANVIL_ETOL; /* the contact outlasts the response window */
}

/* The one positive root of the physical step equation (see pass_physical)
 *   G(x) = bD x^4 + B x^3 + k0 x^2 - bu x - A,  bD >= 0, B, k0 > 0, A > 0:
 * G is convex on x > 0 with G(0) = -A < 0, so the root is unique, and
 * Newton from a point where G >= 0 decreases to it monotonically.  At
 * x0 = |bu|/k0 + sqrt(A/k0), k0 x0^2 - bu x0 - A >= 0, so G(x0) >= 0. */
static double physical_root(double bD, double B, double k0, double bu, double A)
{
	double x = fabs(bu) / k0 + sqrt(A / k0);
	for (int i = 0; i < 100; i++) {
		double f = (((bD * x + B) * x + k0) * x - bu) * x - A;
		double df = ((4.0 * bD * x + 3.0 * B) * x + 2.0 * k0) * x - bu;
		double dx = f / df;
		x -= dx;
		if (fabs(dx) <= 1e-15 * x)
			break;
	}
	return x * x * x;
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
 * measures it).  The contact ends where A = 0: alpha = 0 takes the lag
 * with it, and finish_exact's alpha_end is W - w_c there. */
static int pass_physical(const struct ctx *c, struct pass *s, double beta)
{
	const struct anvil_params *p = c->p;
	double dt = s->dt, B = c->g[0] + dt * dt / (6.0 * p->m1), b = 1.5 * beta / p->k0;
	double S0 = 0, S1 = 0, impulse = 0;
	s->v[0] = p->V0;
	s->n = 1;
	for (size_t n = 1; n < s->cap; n++) {
		double tn = (double)n * dt, conv = 0, g0 = c->g[0];
		for (size_t m = 1; m < n; m++)
			conv += s->P[m] * c->g[n - m];
		if (c->dg) {
			/* the true radius, a^2/a_ref^2 = alpha/alpha_ref, of each past load;
			 * the current one's (in g0 only, zero before the bottom reflection)
			 * extrapolated, second order */
			for (size_t m = 1; m < n; m++)
				conv += s->Q[m] * c->dg[n - m];
			double q1 = n >= 2 ? s->Q[n - 1] / s->P[n - 1] : 0.0;
			double q2 = n >= 3 ? s->Q[n - 2] / s->P[n - 2] : q1;
			g0 += (2.0 * q1 - q2) * c->dg[0];
			B = g0 + dt * dt / (6.0 * p->m1);
		}
		double A = p->V0 * tn - dt / p->m1 * (tn * S0 - S1) - conv;
		if (A <= 0)
			return n >= 3 ? finish_exact(c, s, impulse) : (finish(s, p, A, impulse), ANVIL_OK);
		/* dw_c/dt(t_n) = wd0 + e0 P_n (BDF2; Euler at the first step) */
		double wd0, e0;
		if (n >= 2) {
			wd0 = (3.0 * conv - 4.0 * s->wc[n - 1] + s->wc[n - 2]) / (2.0 * dt);
			e0 = 1.5 * g0 / dt;
		} else {
			wd0 = (conv - s->wc[0]) / dt;
			e0 = g0 / dt;
		}
		double v0 = p->V0 - (impulse + 0.5 * dt * s->P[n - 1]) / p->m1;
		double D = 0.5 * dt / p->m1 + e0;
		double P = physical_root(b * D, B, p->k0, b * (v0 - wd0), A);
		double x = cbrt(P);
		s->P[n] = P;
		s->Q[n] = c->dg ? P * p->k0 * x * x / c->alpha_ref : 0.0;
		s->wc[n] = conv + P * g0;
		impulse += 0.5 * dt * (s->P[n - 1] + P);
		s->v[n] = p->V0 - impulse / p->m1;
		double Q = 1.5 * x / p->k0 * (s->v[n] - (wd0 + e0 * P));
		s->W[n] = p->V0 * tn - dt / p->m1 * (tn * S0 - S1) - P * dt * dt / (6.0 * p->m1);
		s->w[n] = s->wc[n] - beta * Q;
		S0 += P;
		S1 += P * tn;
		s->n = n + 1;
	}
	return ANVIL_ETOL;
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
	for (size_t n = 1; n < s->cap; n++) {
		double W = n == 1 ? p->V0 * dt : s->W[n - 1] + s->v[n - 1] * dt + 0.5 * a_prev * dt * dt;
		double w = n >= 2 ? 0.5 * dt * wd0 * s->P[n - 1] : 0.0;
		for (size_t m = 1; m + 2 <= n; m++) /* w_delta(t_{n-1} - t_m) = g'/dt */
			w += dt * s->P[m] * c->g[n - 1 - m] / dt;
		double v = n == 1 ? p->V0 : s->v[n - 1] + a_prev * dt;
		if (W - w <= 0) {
			finish(s, p, W - w, impulse);
			/* the paper's own velocity update, eq (46), to the contact end */
			s->Vs = -(s->v[n - 1] + a_prev * (s->ts - (double)(n - 1) * dt));
			return ANVIL_OK;
		}
		s->P[n] = p->K * pow(W - w, 1.5);
		s->W[n] = W;
		s->w[n] = w;
		s->v[n] = v;
		impulse += 0.5 * dt * (s->P[n - 1] + s->P[n]);
		a_prev = -s->P[n] / p->m1;
		s->n = n + 1;
	}
	return ANVIL_ETOL;
}

static int run_pass(struct ctx *c, enum anvil_scheme scheme, double dt, struct pass *s)
{
	double t_avail = c->tau_avail * c->p->r0 / c->p->c2;
	size_t cap = (size_t)floor(t_avail / dt) - 1;
	if (cap < 8)
		return ANVIL_ETOL;
	int st = pass_alloc(s, cap, dt);
	free(c->g);
	free(c->dg);
	c->g = c->dg = NULL;
	if (!st)
		st = weights(c, dt, cap);
	if (!st)
		st = scheme == ANVIL_SCHEME_PAPER ? pass_paper(c, s)
		     : c->physical		  ? pass_physical(c, s, c->beta)
						  : pass_implicit(c, s);
	return st;
}

/* Linear resampling of a pass onto nhist points over [0, t_s]. */
static int resample(const struct pass *s, const struct anvil_params *p, size_t nhist,
		    struct anvil_history *h)
{
	int st = anvil_history_alloc(h, nhist);
	for (size_t i = 0; !st && i < nhist; i++) {
		double t = s->ts * (double)i / (double)(nhist - 1);
		double x = t / s->dt;
		size_t k = (size_t)floor(x);
		if (k + 1 >= s->n)
			k = s->n - 2;
		double f = x - (double)k;
		h->t[i] = t;
		h->P[i] = fmax(0.0, (1 - f) * s->P[k] + f * s->P[k + 1]);
		h->W[i] = (1 - f) * s->W[k] + f * s->W[k + 1];
		h->w[i] = (1 - f) * s->w[k] + f * s->w[k + 1];
		h->v[i] = (1 - f) * s->v[k] + f * s->v[k + 1];
		h->alpha[i] = h->W[i] - h->w[i];
	}
	if (!st && nhist) { /* the exact end state */
		h->P[nhist - 1] = 0;
		h->v[nhist - 1] = -s->Vs;
		h->alpha[nhist - 1] = 0;
		h->W[nhist - 1] = h->w[nhist - 1];
	}
	(void)p;
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

static void fill(struct anvil_result *r, const struct anvil_params *p,
		 const struct pass *a, const struct pass *b, enum anvil_scheme scheme)
{
	if (scheme == ANVIL_SCHEME_PAPER) { /* first order: report the step asked for */
		r->ts.val = a->ts, r->ts.err = fabs(b->ts - a->ts);
		r->tmax.val = a->tmax, r->tmax.err = fabs(b->tmax - a->tmax);
		r->Pmax.val = a->Pmax, r->Pmax.err = fabs(b->Pmax - a->Pmax);
		r->Vs.val = a->Vs, r->Vs.err = fabs(b->Vs - a->Vs);
	} else {
		r->ts.val = extrap(a->ts, b->ts, &r->ts.err);
		r->tmax.val = extrap(a->tmax, b->tmax, &r->tmax.err);
		r->Pmax.val = extrap(a->Pmax, b->Pmax, &r->Pmax.err);
		r->Vs.val = extrap(a->Vs, b->Vs, &r->Vs.err);
	}
	r->Rf.val = r->Vs.val / p->V0;
	r->Rf.err = r->Vs.err / p->V0;
	r->Ea.val = 0.5 * p->m1 * (p->V0 * p->V0 - r->Vs.val * r->Vs.val);
	r->Ea.err = p->m1 * fabs(r->Vs.val) * r->Vs.err;
	r->lambda_star = p->lambda_star;
	r->Rf_star = p->Rf_star;
}

int anvil_impact_run(const struct anvil_params *p, anvil_ramp_fn ramp, void *rctx,
		     double tau_avail, const struct anvil_impact_opts *o,
		     struct anvil_result *r, struct anvil_err *err)
{
	double dt = o->dt > 0 ? o->dt : o->dt_auto;
	if (!(dt > 0))
		return anvil_err_set(err, ANVIL_EINVAL, "impact: no time step");
	if (tau_avail * p->r0 / p->c2 / dt > (double)o->max_steps)
		return anvil_err_set(err, ANVIL_ETOL,
				     "the contact (over %.3g us) needs more than %zu steps of %.3g us",
				     tau_avail * p->r0 / p->c2 * 1e6, o->max_steps, dt * 1e6);
	int st;
	struct ctx c = { .p = p, .ramp = ramp, .rctx = rctx, .tau_avail = tau_avail,
			 .physical = o->physical, .beta = o->beta,
			 .ramp2 = o->physical && o->alpha_ref > 0 ? o->ramp2 : NULL,
			 .rctx2 = o->ramp2_ctx, .alpha_ref = o->alpha_ref };
	if (o->physical && (!(o->beta >= 0) || !isfinite(o->beta) || o->scheme == ANVIL_SCHEME_PAPER))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "impact: the physical contact needs beta >= 0 and the implicit scheme");
	struct pass a = {0}, b = {0};
	st = run_pass(&c, o->scheme, dt, &a);
	if (!st)
		st = run_pass(&c, o->scheme, 0.5 * dt, &b);
	if (!st && o->single) { /* the dt pass alone; its error vs dt/2 */
		fill(r, p, &a, &b, ANVIL_SCHEME_PAPER);
		if (o->nhist > 1)
			st = resample(&a, p, o->nhist, &r->hist);
	} else if (!st) {
		fill(r, p, &a, &b, o->scheme);
		if (o->nhist > 1)
			st = resample(o->scheme == ANVIL_SCHEME_PAPER ? &a : &b, p, o->nhist, &r->hist);
	}
	if (st == ANVIL_ETOL) {
		r->ts.val = NAN;
		anvil_err_set(err, st, "the contact outlasts the computed response (%.3g us)",
			      tau_avail * p->r0 / p->c2 * 1e6);
	} else if (st) {
		anvil_err_set(err, st, "impact: %s", anvil_strerror(st));
	}
	free(c.g);
	free(c.dg);
	pass_free(&a);
	pass_free(&b);
	return st;
}
