/* test_impact: the coupled impact solver (impact.c) on anvils whose response
 * is known exactly, so that only the time stepping is under test:
 *  - a rigid anvil reproduces the quasi-static Hertz impact in closed form;
 *  - on the exact half-space the implicit scheme is second order (halving dt
 *    cuts the error about four times) and the paper's explicit lagged
 *    scheme (42)-(46) first order (about two times);
 *  - the Richardson error estimate covers the actual error;
 *  - the paper's scheme converges to the implicit result;
 *  - repeated contacts on an anvil that strikes back: a mass on a spring
 *    (its ramp response in closed form), which the impactor sets moving and
 *    which returns to catch it: R_f in [0, 1], P >= 0, the contacts ordered,
 *    and the energy balance m1 (V0^2 - V_s^2)/2 = int P dw;
 *  - the fast convolution against the direct sum (to rounding). */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>

#include "halfspace.h"
#include "hertz.h"
#include "impact.h"
#include "params.h"
#include "paper.h"
#include "tap.h"

static int rigid(void *ctx, double tau, double *val)
{
	(void)ctx;
	(void)tau;
	*val = 0;
	return ANVIL_OK;
}

static int halfspace(void *ctx, double tau, double *val)
{
	return anvil_halfspace_ramp(ctx, tau, val, NULL);
}


static struct anvil_result run(const struct anvil_params *p, anvil_ramp_fn f, void *ctx,
			       enum anvil_scheme scheme, double dt, int single)
{
	struct anvil_impact_opts o = { .scheme = scheme, .dt = dt, .max_steps = 1000000,
				       .single = single };
	struct anvil_result r;
	struct anvil_err e;
	anvil_result_init(&r, ANVIL_MODEL_HALFSPACE);
	double tau_avail = 2.0 * anvil_hertz_tau_s() * p->T * p->c2 / p->r0;
	if (anvil_impact_run(p, f, ctx, tau_avail, &o, &r, &e))
		diag("impact: %s", e.msg);
	return r;
}

static void test_rigid(void)
{
	struct anvil_params p;
	paper_params(&p, INFINITY, 10);
	double ts = anvil_hertz_tau_s() * p.T;
	double Pmax = p.K * pow(anvil_hertz_alpha_max() * p.T * p.V0, 1.5);
	struct anvil_result r = run(&p, rigid, NULL, ANVIL_SCHEME_IMPLICIT, ts / 2000, 0);
	is_rel(r.ts.val, ts, 1e-7, "rigid anvil: t_s = 3.21807 T (quasi-static Hertz)");
	is_rel(r.Pmax.val, Pmax, 1e-7, "rigid anvil: P_max = K ((5/4)^(2/5) T V0)^(3/2)");
	is_rel(r.tmax.val, ts / 2, 1e-6, "rigid anvil: t_max = t_s / 2");
	is_abs(r.Rf.val, 1.0, 1e-7, "rigid anvil: R_f = 1 (no energy leaves)");
	anvil_result_free(&r);
}

/* Observed order from three step sizes: log2 of the ratio of successive
 * differences. */
static double order(double a, double b, double c)
{
	return log2(fabs(a - b) / fabs(b - c));
}

static void test_order(struct anvil_halfspace *hs)
{
	struct anvil_params p;
	paper_params(&p, INFINITY, 10);
	double dt = anvil_hertz_tau_s() * p.T / 200;
	struct anvil_result r[3], q[3];
	for (int i = 0; i < 3; i++) {
		r[i] = run(&p, halfspace, hs, ANVIL_SCHEME_IMPLICIT, dt / (1 << i), 1);
		q[i] = run(&p, halfspace, hs, ANVIL_SCHEME_PAPER, dt / (1 << i), 1);
	}
	double oP = order(r[0].Pmax.val, r[1].Pmax.val, r[2].Pmax.val), oV = order(r[0].Vs.val, r[1].Vs.val, r[2].Vs.val);
	double oT = order(r[0].ts.val, r[1].ts.val, r[2].ts.val);
	double qP = order(q[0].Pmax.val, q[1].Pmax.val, q[2].Pmax.val), qV = order(q[0].Vs.val, q[1].Vs.val, q[2].Vs.val);
	diag("observed orders: implicit P_max %.2f, t_s %.2f, V_s %.2f; paper P_max %.2f, V_s %.2f",
	     oP, oT, oV, qP, qV);
	ok(oP > 1.7 && oP < 2.5 && oT > 1.7 && oT < 2.5,
	   "implicit scheme is second order (P_max %.2f, t_s %.2f)", oP, oT);
	/* V_s, an integral of P, converges faster (about dt^2.7 here) */
	ok(oV > 1.7, "and V_s converges at least as fast (%.2f)", oV);
	ok(qP > 0.7 && qP < 1.4 && qV > 0.7 && qV < 1.4,
	   "paper's explicit scheme (42)-(46) is first order (P_max %.2f, V_s %.2f)", qP, qV);

	/* Richardson: the extrapolated value and its estimate against a run
	 * with a 16 times smaller step. */
	struct anvil_result x = run(&p, halfspace, hs, ANVIL_SCHEME_IMPLICIT, dt, 0);
	struct anvil_result f = run(&p, halfspace, hs, ANVIL_SCHEME_IMPLICIT, dt / 16, 0);
	ok(fabs(x.Pmax.val - f.Pmax.val) <= x.Pmax.err + 1e-9 * f.Pmax.val && fabs(x.ts.val - f.ts.val) <= x.ts.err + 1e-9 * f.ts.val &&
	   fabs(x.Rf.val - f.Rf.val) <= x.Rf.err + 1e-9,
	   "error estimates cover the error (P_max %.1e <= %.1e, t_s %.1e <= %.1e, R_f %.1e <= %.1e)",
	   fabs(x.Pmax.val - f.Pmax.val) / f.Pmax.val, x.Pmax.err / f.Pmax.val, fabs(x.ts.val - f.ts.val) / f.ts.val,
	   x.ts.err / f.ts.val, fabs(x.Rf.val - f.Rf.val), x.Rf.err);
	double d0 = fabs(q[0].Pmax.val - f.Pmax.val), d2 = fabs(q[2].Pmax.val - f.Pmax.val);
	ok(d2 < 0.3 * d0, "paper's scheme converges to the implicit result (%.2e -> %.2e)",
	   d0 / f.Pmax.val, d2 / f.Pmax.val);
	ok(q[0].Pmax.val > f.Pmax.val && q[0].Rf.val > f.Rf.val,
	   "at a coarse step the paper's scheme overestimates P_max and R_f (notes.md)");
	for (int i = 0; i < 3; i++) {
		anvil_result_free(&r[i]);
		anvil_result_free(&q[i]);
	}
	anvil_result_free(&x);
	anvil_result_free(&f);
}

/* A surface that is a mass M on a spring k (the anvil as one oscillator):
 * M w'' + k w = P, so the ramp response is (t - sin(om t)/om)/k, om^2 = k/M;
 * dimensionless as anvil_ramp_fn wants: mu c2 times it at t = tau r0/c2. */
struct sdof {
	const struct anvil_params *p;
	double k, om;
};

static int sdof_ramp(void *ctx, double tau, double *val)
{
	const struct sdof *o = ctx;
	double t = tau * o->p->r0 / o->p->c2;
	*val = o->p->mu * o->p->c2 * (t - sin(o->om * t) / o->om) / o->k;
	return ANVIL_OK;
}

static void test_repeated(void)
{
	struct anvil_params p;
	paper_params(&p, INFINITY, 10);
	/* a light mass (m1/5) on a soft spring (period 20 T): the
	 * impactor sets it moving away faster than itself; it comes back */
	double M = p.m1 / 5, om = M_PI / (10 * p.T);
	struct sdof o = { &p, M * om * om, om };
	struct anvil_impact_opts io = { .scheme = ANVIL_SCHEME_IMPLICIT, .dt = p.T / 400,
					.max_steps = 10000000, .nhist = 40001 };
	struct anvil_result r;
	struct anvil_err e;
	anvil_result_init(&r, ANVIL_MODEL_LAYER);
	double tau_avail = 200 * p.T * p.c2 / p.r0;
	int st = anvil_impact_run(&p, sdof_ramp, &o, tau_avail, &io, &r, &e);
	if (!ok(st == ANVIL_OK, "spring-mounted mass: runs (%s)", st ? e.msg : "ok"))
		return;
	int order = 1;
	size_t nc = r.ncontacts < ANVIL_MAX_CONTACTS ? r.ncontacts : ANVIL_MAX_CONTACTS;
	for (size_t i = 0; i < nc; i++)
		order &= r.contact_on[i] < r.contact_off[i] &&
			 (i + 1 == nc || r.contact_off[i] < r.contact_on[i + 1]);
	ok(r.ncontacts >= 2 && order && r.contact_on[0] == 0 && r.contact_off[nc - 1] == r.ts.val,
	   "%zu contacts, ordered, the last ending at t_s = %.4g T (first %.4g-%.4g T, second %.4g-%.4g T)",
	   r.ncontacts, r.ts.val / p.T, r.contact_on[0] / p.T, r.contact_off[0] / p.T,
	   r.contact_on[1] / p.T, r.contact_off[1] / p.T);
	ok(r.Rf.val >= 0 && r.Rf.val <= 1 && r.Ea.val >= 0, "R_f = %.6f in [0, 1], E_a = %.4g J >= 0",
	   r.Rf.val, r.Ea.val);
	const struct anvil_history *h = &r.hist;
	double pmin = 0, work = 0;
	int zero_between = 0;
	for (size_t i = 0; i < h->n; i++) {
		pmin = fmin(pmin, h->P[i]);
		if (i + 1 < h->n)
			work += 0.5 * (h->P[i] + h->P[i + 1]) * (h->w[i + 1] - h->w[i]);
		if (nc >= 2 && h->t[i] > r.contact_off[0] + 0.01 * p.T &&
		    h->t[i] < r.contact_on[1] - 0.01 * p.T)
			zero_between |= h->P[i] != 0;
	}
	ok(pmin >= 0 && !zero_between, "P >= 0 everywhere, P = 0 between the contacts");
	/* second order at dt = T/400 plus the trapezoid on 40001 samples: 1e-4 */
	double lost = 0.5 * p.m1 * (p.V0 * p.V0 - r.Vs.val * r.Vs.val), ke = 0.5 * p.m1 * p.V0 * p.V0;
	ok(fabs(lost - work) < 1e-4 * ke,
	   "energy balance: kinetic energy lost %.6g J = int P dw %.6g J (to %.1e of m1 V0^2/2)",
	   lost, work, fabs(lost - work) / ke);
	/* the rest state on (impact.h, rest_tol, as the solver sets it at
	 * normal): a genuine re-contact, the impactor flying between the
	 * contacts and rebounding, is no rest: the same contacts, the same
	 * bits */
	struct anvil_result q;
	anvil_result_init(&q, ANVIL_MODEL_LAYER);
	io.rest_tol = 1e-4;
	io.nhist = 0;
	st = anvil_impact_run(&p, sdof_ramp, &o, tau_avail, &io, &q, &e);
	ok(st == ANVIL_OK && q.rest_bound == 0 && q.ncontacts == r.ncontacts && q.ts.val == r.ts.val &&
	   q.Rf.val == r.Rf.val && q.contact_on[1] == r.contact_on[1],
	   "with the rest state on: not at rest, %zu contacts, the same t_s and R_f", q.ncontacts);
	anvil_result_free(&q);
	anvil_result_free(&r);
}

/* The fast convolution changes the implicit scheme's sums only by
 * rounding: the same run with the squares summed directly. */
static void test_fast_vs_direct(struct anvil_halfspace *hs)
{
	struct anvil_params p;
	paper_params(&p, INFINITY, 10);
	double dt = anvil_hertz_tau_s() * p.T / 3000, tau_avail = 2.0 * anvil_hertz_tau_s() * p.T * p.c2 / p.r0;
	struct anvil_impact_opts o = { .scheme = ANVIL_SCHEME_IMPLICIT, .dt = dt, .max_steps = 1000000 };
	struct anvil_result a, b;
	anvil_result_init(&a, ANVIL_MODEL_HALFSPACE);
	anvil_result_init(&b, ANVIL_MODEL_HALFSPACE);
	int st = anvil_impact_run(&p, halfspace, hs, tau_avail, &o, &a, NULL);
	o.direct_max = (size_t)-1;
	st = st ? st : anvil_impact_run(&p, halfspace, hs, tau_avail, &o, &b, NULL);
	double d = fmax(fabs(a.Pmax.val / b.Pmax.val - 1), fmax(fabs(a.ts.val / b.ts.val - 1), fabs(a.Rf.val - b.Rf.val)));
	ok(!st && d < 1e-11, "fast and direct convolution agree to %.1e (P_max, t_s relative; R_f)", d);
	anvil_result_free(&a);
	anvil_result_free(&b);
}

int main(void)
{
	gsl_set_error_handler_off();
	struct anvil_halfspace *hs = anvil_halfspace_alloc(0.3, 1e-12, NULL);
	test_rigid();
	test_order(hs);
	test_repeated();
	test_fast_vs_direct(hs);
	anvil_halfspace_free(hs);
	plan(tap_n);
	return done_testing();
}
