/* test_grow: the growing time step (impact_grow.c) on an anvil whose long
 * contact is known from an ODE: a dashpot (the thin plate's long-time
 * response, w' = P/c, Zener's 8 sqrt(D rho h)) behind the Hertz contact.
 * The impactor's momentum drains through the dashpot over many Hertz
 * times while the force, after its Hertz rise, falls smoothly: the case
 * the grown step is for.
 *  - the grown step agrees with the ODE within its own error estimates
 *    (t_s, P_max, R_f), and with the fixed step within both's;
 *  - the grown step engaged (its results are not the fixed step's bits)
 *    and its t_s meets the normal level's target;
 *  - the physical pass grows as well: with beta = 0 and no patch it
 *    solves the same equation (agreement within the estimates), and with
 *    a patch correction (ramp2) grown and fixed steps agree;
 *  - convergence: halving dt with the same growth rule moves the results
 *    by less than the coarser run's estimate. */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "hertz.h"
#include "impact.h"
#include "params.h"
#include "paper.h"
#include "tap.h"

/* The dashpot: the ramp response (P = t) is t^2 / (2 c). */
struct dash {
	const struct anvil_params *p;
	double c;
};

static int dash_ramp(void *ctx, double tau, double *val)
{
	const struct dash *d = ctx;
	double t = tau * d->p->r0 / d->p->c2;
	*val = d->p->mu * d->p->c2 * t * t / (2.0 * d->c);
	return ANVIL_OK;
}

/* The same anvil as an ODE: x' = v, v' = -P/m1, w' = P/c, P = K (x - w)^1.5. */
static int rhs(double t, const double y[], double f[], void *ctx)
{
	const struct dash *d = ctx;
	(void)t;
	double a = y[0] - y[2], P = a > 0 ? d->p->K * pow(a, 1.5) : 0.0;
	f[0] = y[1];
	f[1] = -P / d->p->m1;
	f[2] = P / d->c;
	return GSL_SUCCESS;
}

struct ref {
	double ts, Pmax, Rf;
};

/* The ODE to the end of contact (alpha = 0, bisected), rk8pd at the
 * relative tolerance tol. */
static struct ref ode(const struct dash *d, double tol)
{
	const struct anvil_params *p = d->p;
	gsl_odeiv2_system sys = { rhs, NULL, 3, (void *)d };
	gsl_odeiv2_driver *dr = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3 * p->T,
							      1e-3 * tol, tol);
	double y[3] = { 0, p->V0, 0 }, t = 0, h = p->T / 200, Pmax = 0, pp[3] = { 0, 0, 0 };
	struct ref r = { NAN, NAN, NAN };
	for (int i = 0; i < 10000000; i++) {
		double y0[3] = { y[0], y[1], y[2] }, t0 = t;
		gsl_odeiv2_driver_apply(dr, &t, t + h, y);
		if (y[0] - y[2] > 0) {
			/* P_max: the parabola's vertex through the largest sample and
			 * its neighbours (error O(h^3) P''') */
			pp[0] = pp[1], pp[1] = pp[2], pp[2] = p->K * pow(y[0] - y[2], 1.5);
			double den = pp[0] - 2.0 * pp[1] + pp[2];
			if (i >= 2 && pp[1] >= pp[0] && pp[1] > pp[2] && den < 0)
				Pmax = fmax(Pmax, pp[1] - 0.125 * (pp[2] - pp[0]) * (pp[2] - pp[0]) / den);
			continue;
		}
		/* the end within (t0, t]: bisect from the saved state */
		double lo = 0, hi = h;
		for (int k = 0; k < 60; k++) {
			double mid = 0.5 * (lo + hi), z[3] = { y0[0], y0[1], y0[2] }, tz = t0;
			gsl_odeiv2_driver_reset(dr);
			gsl_odeiv2_driver_apply(dr, &tz, t0 + mid, z);
			if (z[0] - z[2] > 0)
				lo = mid;
			else
				hi = mid;
		}
		double z[3] = { y0[0], y0[1], y0[2] }, tz = t0;
		gsl_odeiv2_driver_reset(dr);
		gsl_odeiv2_driver_apply(dr, &tz, t0 + 0.5 * (lo + hi), z);
		r = (struct ref){ t0 + 0.5 * (lo + hi), Pmax, -z[1] / p->V0 };
		break;
	}
	gsl_odeiv2_driver_free(dr);
	return r;
}

static int run_hist(const struct dash *d, double dt, size_t grow_after, int physical,
		    const struct dash *d2, size_t nhist, struct anvil_result *r)
{
	const struct anvil_params *p = d->p;
	struct anvil_impact_opts o = { .scheme = ANVIL_SCHEME_IMPLICIT, .dt = dt,
				       .max_steps = 10000000, .grow_after = grow_after,
				       .grow_eta = (M_PI / 400) * (M_PI / 400),
				       .physical = physical, .beta = 0, .nhist = nhist };
	if (d2) {
		o.ramp2 = dash_ramp;
		o.ramp2_ctx = (void *)d2;
		o.alpha_ref = 2e-6;
	}
	struct anvil_err e;
	anvil_result_init(r, ANVIL_MODEL_LAYER);
	double tau_avail = 300 * p->T * p->c2 / p->r0;
	int st = anvil_impact_run(p, dash_ramp, (void *)d, tau_avail, &o, r, &e);
	if (st)
		diag("impact: %s", e.msg);
	return st;
}

/* A smooth kernel that is not a polynomial (the far field's Chebyshev
 * interpolant is then not exact): the dashpot plus b t log(1 + t/t1), a
 * compliance b relaxing over t1 (the plate's t log t term, softened). */
struct dlog {
	struct dash d;
	double b, t1;
};

static int dlog_ramp(void *ctx, double tau, double *val)
{
	const struct dlog *q = ctx;
	const struct anvil_params *p = q->d.p;
	double t = tau * p->r0 / p->c2;
	int st = dash_ramp((void *)&q->d, tau, val);
	*val += p->mu * p->c2 * q->b * t * log1p(t / q->t1);
	return st;
}

/* dlog_ramp, its calls counted. */
struct counted {
	struct dlog q;
	size_t calls;
};

static int counted_ramp(void *ctx, double tau, double *val)
{
	struct counted *k = ctx;
	k->calls++;
	return dlog_ramp(&k->q, tau, val);
}

/* A run in long mode (impact.h t_smooth; max_steps bounds the nodes) or
 * not (max_steps 0: as run()), on ramp over a window of win T. */
static int run_long(const struct dash *d, anvil_ramp_fn ramp, void *ctx, double dt,
		    size_t grow_after, int physical, size_t max_steps, double win,
		    struct anvil_result *r)
{
	const struct anvil_params *p = d->p;
	struct anvil_impact_opts o = { .scheme = ANVIL_SCHEME_IMPLICIT, .dt = dt,
				       .max_steps = max_steps ? max_steps : 100000000,
				       .grow_after = grow_after,
				       .grow_eta = (M_PI / 400) * (M_PI / 400),
				       .physical = physical, .beta = 0,
				       .t_smooth = max_steps ? 0.5 * p->T : 0.0 };
	if (physical) { /* with the loads' Q: ramp2 a stiffer one */
		o.ramp2 = ramp;
		o.ramp2_ctx = ctx;
		o.alpha_ref = 2e-6;
	}
	struct anvil_err e;
	anvil_result_init(r, ANVIL_MODEL_LAYER);
	int st = anvil_impact_run(p, ramp, ctx, win * p->T * p->c2 / p->r0, &o, r, &e);
	if (st)
		diag("impact: %s", e.msg);
	return st;
}

static int run(const struct dash *d, double dt, size_t grow_after, int physical,
	       const struct dash *d2, struct anvil_result *r)
{
	return run_hist(d, dt, grow_after, physical, d2, 0, r);
}

/* |a - b| within tol (the estimates), for t_s, P_max, R_f. */
static int within(const struct anvil_result *a, double ts, double Pmax, double Rf, double kt,
		  double kp, double kr)
{
	return fabs(a->ts.val - ts) <= kt && fabs(a->Pmax.val - Pmax) <= kp &&
	       fabs(a->Rf.val - Rf) <= kr;
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(14);
	struct anvil_params p;
	paper_params(&p, INFINITY, 10);
	/* the dashpot drains the impactor's momentum over about 10 T */
	struct dash d = { &p, p.m1 / (10 * p.T) };
	/* the reference and its own error (the tolerance's hundredfold one) */
	struct ref x = ode(&d, 1e-14), xl = ode(&d, 1e-12);
	struct ref xe = { fabs(x.ts - xl.ts), fabs(x.Pmax - xl.Pmax), fabs(x.Rf - xl.Rf) };
	diag("ODE: t_s = %.10g T (%.1g), P_max = %.10g N (%.1g), R_f = %.10g (%.1g)", x.ts / p.T,
	     xe.ts / p.T, x.Pmax, xe.Pmax, x.Rf, xe.Rf);
	double dt = p.T / 400; /* normal's step for a Hertz time of about 3.2 T */
	size_t ga = 8 * 400;
	struct anvil_result f, g, g2, ph, pf, pg;
	int st = run(&d, dt, 0, 0, NULL, &f) || run(&d, dt, ga, 0, NULL, &g) ||
		 run(&d, 0.5 * dt, 2 * ga, 0, NULL, &g2);
	if (!ok(!st, "the dashpot anvil runs, fixed and grown steps"))
		return done_testing();
	diag("fixed: t_s = %.8g T (%.2g), P_max = %.8g (%.2g), R_f = %.8g (%.2g)", f.ts.val / p.T,
	     f.ts.err / p.T, f.Pmax.val, f.Pmax.err, f.Rf.val, f.Rf.err);
	diag("grown: t_s = %.8g T (%.2g), P_max = %.8g (%.2g), R_f = %.8g (%.2g)", g.ts.val / p.T,
	     g.ts.err / p.T, g.Pmax.val, g.Pmax.err, g.Rf.val, g.Rf.err);
	ok(x.ts > 20 * p.T && x.Rf < 0.5, "a long contact: t_s = %.1f T, R_f = %.3f", x.ts / p.T, x.Rf);
	/* the fixed step's own estimates are not under test here (its t_s
	 * estimate, 5e-10 relative, is at the end interpolation's floor) */
	diag("fixed step against the ODE: t_s %.1e, P_max %.1e, R_f %.1e of its estimates",
	     fabs(f.ts.val - x.ts) / f.ts.err, fabs(f.Pmax.val - x.Pmax) / f.Pmax.err,
	     fabs(f.Rf.val - x.Rf) / f.Rf.err);
	ok(within(&g, x.ts, x.Pmax, x.Rf, g.ts.err + xe.ts, g.Pmax.err + xe.Pmax, g.Rf.err + xe.Rf),
	   "grown step: within its estimates of the ODE (t_s %.1e, R_f %.1e off)",
	   fabs(g.ts.val - x.ts) / x.ts, fabs(g.Rf.val - x.Rf));
	ok(g.ts.val != f.ts.val && g.ts.err <= 1e-3 * g.ts.val &&
	   within(&g, f.ts.val, f.Pmax.val, f.Rf.val, g.ts.err + f.ts.err, g.Pmax.err + f.Pmax.err,
		  g.Rf.err + f.Rf.err),
	   "grown and fixed steps agree within their estimates; t_s to %.1e (target 1e-3)",
	   g.ts.err / g.ts.val);
	ok(within(&g2, g.ts.val, g.Pmax.val, g.Rf.val, g.ts.err, g.Pmax.err, g.Rf.err),
	   "dt/2 with the same rule: within the dt run's estimates (t_s moves %.1e)",
	   fabs(g2.ts.val - g.ts.val) / g.ts.val);
	/* the physical pass: beta = 0, no patch: the same equation */
	st = run(&d, dt, ga, 1, NULL, &ph);
	ok(!st && within(&ph, g.ts.val, g.Pmax.val, g.Rf.val, ph.ts.err + g.ts.err,
			 ph.Pmax.err + g.Pmax.err, ph.Rf.err + g.Rf.err),
	   "physical pass (beta = 0), grown: the implicit one's answer within the estimates");
	/* with a patch correction: the loads' Q through ramp2 - ramp */
	struct dash d2 = { &p, 0.9 * d.c };
	st = run(&d, dt, 0, 1, &d2, &pf) || run(&d, dt, ga, 1, &d2, &pg);
	ok(!st && pg.ts.val != pf.ts.val &&
	   within(&pg, pf.ts.val, pf.Pmax.val, pf.Rf.val, pg.ts.err + pf.ts.err,
		  pg.Pmax.err + pf.Pmax.err, pg.Rf.err + pf.Rf.err),
	   "physical pass with a patch correction: grown and fixed agree within the estimates");
	diag("patch: fixed t_s = %.8g T (%.2g), grown %.8g T (%.2g); R_f %.8g / %.8g", pf.ts.val / p.T,
	     pf.ts.err / p.T, pg.ts.val / p.T, pg.ts.err / p.T, pf.Rf.val, pg.Rf.val);
	ok(pg.ts.err <= 1e-3 * pg.ts.val, "... t_s to %.1e", pg.ts.err / pg.ts.val);
	/* the history of a grown run: on the nodes of every level */
	struct anvil_result gh;
	st = run_hist(&d, dt, ga, 0, NULL, 4001, &gh);
	const struct anvil_history *h = &gh.hist;
	int rising = 1;
	double pmin = 0, pmax = 0, imp = 0;
	for (size_t i = 0; !st && i < h->n; i++) {
		rising &= i == 0 || h->t[i] > h->t[i - 1];
		pmin = fmin(pmin, h->P[i]);
		pmax = fmax(pmax, h->P[i]);
		if (i)
			imp += 0.5 * (h->P[i] + h->P[i - 1]) * (h->t[i] - h->t[i - 1]);
	}
	/* the trapezoid on 4000 intervals of a force smooth on the scale T:
	 * (t_s/4000/T)^2/12, about 1e-4 of the impulse m1 (V0 + V_s) */
	double want = p.m1 * (p.V0 + gh.Vs.val);
	ok(!st && h->n == 4001 && rising && pmin >= 0 && pmax <= gh.Pmax.val + gh.Pmax.err &&
	   pmax >= 0.99 * gh.Pmax.val && h->P[h->n - 1] == 0 && fabs(imp / want - 1) < 1e-4,
	   "grown run's history: times rising, 0 <= P <= P_max, P = 0 at t_s, its impulse m1 (V0 + V_s) to %.1e",
	   fabs(imp / want - 1));
	anvil_result_free(&gh);
	/* long mode (impact.h t_smooth): the far field against the exact
	 * weights, on a kernel it interpolates (not a polynomial); 300 T at
	 * T/400 is 120000 steps, the long run may make 20000 nodes */
	struct dlog q = { { &p, d.c }, 0.2 * p.T / d.c, 2.0 * p.T };
	struct anvil_result le, ll, lp, lq, lo;
	st = run_long(&d, dlog_ramp, &q, dt, ga, 0, 0, 300, &le) ||
	     run_long(&d, dlog_ramp, &q, dt, ga, 0, 20000, 300, &ll);
	double dl = fabs(ll.ts.val - le.ts.val) / le.ts.val, dp = fabs(ll.Pmax.val / le.Pmax.val - 1);
	ok(!st && ll.ts.val != le.ts.val && dl < 0.1 * le.ts.err / le.ts.val && dp < 1e-6 &&
	   fabs(ll.Rf.val - le.Rf.val) < 0.1 * le.Rf.err,
	   "long mode (20000 nodes for a 120000-step window): the far field moves t_s by %.1e, P_max by %.1e (under a tenth of the exact weights' estimates)",
	   dl, dp);
	diag("long: t_s = %.10g T, exact %.10g T (%.2g); R_f %.10g / %.10g", ll.ts.val / p.T,
	     le.ts.val / p.T, le.ts.err / p.T, ll.Rf.val, le.Rf.val);
	/* the weights made as the march reaches them, each ramp value once
	 * for both passes (impact_wts.c): the whole tables of the two passes
	 * were 120001 + 240001 calls; the contact ends at 112 T of the 300,
	 * so the dt/2 pass's table alone, made in full, was more than all
	 * the calls now (the contact end's off-grid ones included) */
	struct counted kq = { q, 0 };
	struct anvil_result lk;
	st = run_long(&d, counted_ramp, &kq, dt, ga, 0, 0, 300, &lk);
	ok(!st && lk.ts.val == le.ts.val && lk.Pmax.val == le.Pmax.val && lk.Rf.val == le.Rf.val &&
	   kq.calls < 240001,
	   "the ramp's table made only as far as the march reaches: %zu calls, the dt/2 table alone was 240001 (the same bits)",
	   kq.calls);
	anvil_result_free(&lk);
	st = run_long(&d, dlog_ramp, &q, dt, ga, 1, 0, 300, &lp) ||
	     run_long(&d, dlog_ramp, &q, dt, ga, 1, 20000, 300, &lq);
	ok(!st && fabs(lq.ts.val - lp.ts.val) < 0.1 * lp.ts.err &&
	   fabs(lq.Rf.val - lp.Rf.val) < 0.1 * lp.Rf.err,
	   "long mode, physical pass with the loads' Q: t_s moves %.1e", fabs(lq.ts.val / lp.ts.val - 1));
	/* a window no fixed-step table holds: 1e5 T at T/400 (4e7 steps; the
	 * two passes' tables 1.2e8 samples) on 50000 nodes, a dashpot three
	 * times softer with the log term, against the exact weights over a
	 * window of 1000 T that holds the contact */
	struct dlog q3 = { { &p, d.c / 3.0 }, 0.2 * p.T / d.c, 2.0 * p.T };
	struct anvil_result lx;
	st = run_long(&q3.d, dlog_ramp, &q3, dt, ga, 0, 0, 1000, &lx) ||
	     run_long(&q3.d, dlog_ramp, &q3, dt, ga, 0, 50000, 1e5, &lo);
	/* the windows' ends differ, so do the steps' schedules near the
	 * contact's end (impact_grow_due): the two agree within their
	 * estimates, and the long one meets normal's target */
	ok(!st && within(&lo, lx.ts.val, lx.Pmax.val, lx.Rf.val, lo.ts.err + lx.ts.err,
			 lo.Pmax.err + lx.Pmax.err, lo.Rf.err + lx.Rf.err) &&
	   lo.ts.err <= 1e-3 * lo.ts.val,
	   "a window of 4e7 steps in long mode: the %.0f T contact as the exact weights have it over 1000 T (t_s %.1e, R_f %.1e off)",
	   lx.ts.val / p.T, fabs(lo.ts.val / lx.ts.val - 1), fabs(lo.Rf.val - lx.Rf.val));
	diag("long window: t_s = %.10g T (%.2g), R_f = %.10g (%.2g); exact %.10g T (%.2g), %.10g (%.2g)",
	     lo.ts.val / p.T, lo.ts.err / p.T, lo.Rf.val, lo.Rf.err, lx.ts.val / p.T, lx.ts.err / p.T,
	     lx.Rf.val, lx.Rf.err);
	anvil_result_free(&lx);
	struct dash ds = { &p, d.c / 30.0 };
	/* a node budget it cannot meet (the dashpot 30 times softer): refused with a reason, t_s infinite */
	struct anvil_result lr;
	st = run_long(&ds, dash_ramp, &ds, dt, ga, 0, 3000, 1e5, &lr);
	ok(st == ANVIL_ETOL && isinf(lr.ts.val), "long mode out of nodes: refused, t_s infinite");
	anvil_result_free(&lr);
	anvil_result_free(&le);
	anvil_result_free(&ll);
	anvil_result_free(&lp);
	anvil_result_free(&lq);
	anvil_result_free(&lo);
	anvil_result_free(&f);
	anvil_result_free(&g);
	anvil_result_free(&g2);
	anvil_result_free(&ph);
	anvil_result_free(&pf);
	anvil_result_free(&pg);
	return done_testing();
}
