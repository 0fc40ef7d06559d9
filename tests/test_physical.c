/* test_physical: the physical contact model integrated in the impact
 * solver (anvil_impact_run with opts.physical; issue 10):
 *  - rigid layer (E -> inf): quasi-static Hertz to 1e-6;
 *  - the half-space row against contact.c's ODE (two independent
 *    methods of the same model) within their error estimates;
 *  - the scheme is second order (single passes at dt, dt/2, dt/4);
 *  - Hunter's loss for a sphere of the block's material (nu = 0.3):
 *    the exponent 3/5 over V0 = 0.1..30 m/s and the coefficient C(nu);
 *  - energy balance: kinetic energy lost = work of P on the remainder. */
#include <math.h>
#include <stdio.h>

#include "contact.h"
#include "hertz.h"
#include "impact.h"
#include "paper.h"
#include "radiation.h"
#include "tap.h"

static int zero_ramp(void *ctx, double tau, double *val)
{
	(void)ctx;
	(void)tau;
	*val = 0;
	return ANVIL_OK;
}

static double beta_of(const struct anvil_params *p)
{
	return anvil_radiation_beta(p->nu, p->rho, p->c2);
}

/* The physical half-space row: n steps per Hertz contact time. */
static int run_hs(const struct anvil_params *p, double n, int single, size_t nhist,
		  struct anvil_result *r)
{
	double ts = anvil_hertz_tau_s() * p->T;
	struct anvil_impact_opts o = { .scheme = ANVIL_SCHEME_IMPLICIT, .dt = ts / n,
				       .max_steps = 10000000, .single = single, .nhist = nhist,
				       .physical = 1, .beta = beta_of(p) };
	struct anvil_err e = { 0 };
	double tau_avail = 2.0 * ts * p->c2 / p->r0;
	anvil_result_init(r, ANVIL_MODEL_HALFSPACE);
	int st = anvil_impact_run(p, zero_ramp, NULL, tau_avail, &o, r, &e);
	if (st)
		diag("impact: %s", e.msg);
	return st;
}

static void test_rigid(void)
{
	struct anvil_scene sc;
	struct anvil_params p;
	struct anvil_result r, h;
	anvil_scene_default(&sc);
	sc.velocity = 10;
	sc.thickness = INFINITY;
	sc.thickness_per_r0 = 0;
	sc.layer.mat.E *= 1e6; /* beta ~ E^(-3/2) -> 0; E* -> the impactor's */
	anvil_params_from_scene(&p, &sc, NULL);
	anvil_result_init(&h, ANVIL_MODEL_HERTZ);
	anvil_hertz_run(&p, 0, &h, NULL);
	ok(run_hs(&p, 1000, 0, 0, &r) == ANVIL_OK, "rigid layer: runs");
	is_rel(r.ts.val, h.ts.val, 1e-6, "rigid layer (E x 1e6): t_s = Hertz's to 1e-6 (%.3g)",
	       fabs(r.ts.val / h.ts.val - 1));
	is_rel(r.Pmax.val, h.Pmax.val, 1e-6, "rigid layer: P_max = Hertz's to 1e-6 (%.3g)",
	       fabs(r.Pmax.val / h.Pmax.val - 1));
	is_abs(r.Rf.val, 1.0, 1e-6, "rigid layer: R_f = 1 to 1e-6 (%.3g)", fabs(r.Rf.val - 1));
}

static void test_against_ode(void)
{
	struct anvil_params p;
	struct anvil_result a, c;
	struct anvil_contact_opts co = { 1e-11, 0 };
	paper_params(&p, INFINITY, 10);
	anvil_result_init(&c, ANVIL_MODEL_HALFSPACE);
	anvil_contact_run(&p, beta_of(&p), &co, &c, NULL, NULL);
	ok(run_hs(&p, 700, 0, 0, &a) == ANVIL_OK, "paper's scene, half-space: runs");
	diag("integrated: P_max %.8g +- %.2g N, t_s %.8g +- %.2g us, R_f %.8g +- %.2g", a.Pmax.val,
	     a.Pmax.err, a.ts.val * 1e6, a.ts.err * 1e6, a.Rf.val, a.Rf.err);
	diag("ODE:        P_max %.8g +- %.2g N, t_s %.8g +- %.2g us, R_f %.8g +- %.2g", c.Pmax.val,
	     c.Pmax.err, c.ts.val * 1e6, c.ts.err * 1e6, c.Rf.val, c.Rf.err);
	ok(fabs(a.Pmax.val - c.Pmax.val) <= a.Pmax.err + c.Pmax.err,
	   "P_max: integrated and ODE agree within their estimates (%.2g <= %.2g)",
	   fabs(a.Pmax.val - c.Pmax.val), a.Pmax.err + c.Pmax.err);
	ok(fabs(a.ts.val - c.ts.val) <= a.ts.err + c.ts.err,
	   "t_s: agree within the estimates (%.2g <= %.2g)", fabs(a.ts.val - c.ts.val),
	   a.ts.err + c.ts.err);
	ok(fabs(a.tmax.val - c.tmax.val) <= a.tmax.err + c.tmax.err,
	   "t_max: agree within the estimates (%.2g <= %.2g)", fabs(a.tmax.val - c.tmax.val),
	   a.tmax.err + c.tmax.err);
	ok(fabs(a.Rf.val - c.Rf.val) <= a.Rf.err + c.Rf.err,
	   "R_f: agree within the estimates (%.2g <= %.2g)", fabs(a.Rf.val - c.Rf.val),
	   a.Rf.err + c.Rf.err);
	ok(a.Pmax.err < 1e-5 * a.Pmax.val && a.Rf.err < 1e-5,
	   "700 steps: P_max to %.1g, R_f to %.1g", a.Pmax.err / a.Pmax.val, a.Rf.err);
}

/* Single passes (no extrapolation) at n, 2n, 4n steps against the ODE:
 * the error falls 4x per halving. */
static void test_order(void)
{
	struct anvil_params p;
	struct anvil_result r, c;
	struct anvil_contact_opts co = { 1e-12, 0 };
	double eP[3], eR[3], eT[3];
	paper_params(&p, INFINITY, 10);
	anvil_result_init(&c, ANVIL_MODEL_HALFSPACE);
	anvil_contact_run(&p, beta_of(&p), &co, &c, NULL, NULL);
	for (int i = 0; i < 3; i++) {
		run_hs(&p, 100.0 * (1 << i), 1, 0, &r);
		eP[i] = fabs(r.Pmax.val - c.Pmax.val);
		eR[i] = fabs(r.Rf.val - c.Rf.val);
		eT[i] = fabs(r.tmax.val - c.tmax.val);
	}
	double oP = log2(eP[1] / eP[2]), oT = log2(eT[0] / eT[2]) / 2;
	diag("single passes 100, 200, 400 steps: P_max errors %.3g %.3g %.3g, R_f %.3g %.3g %.3g",
	     eP[0], eP[1], eP[2], eR[0], eR[1], eR[2]);
	ok(oP > 1.8 && oP < 2.3, "P_max: order %.3f (second order)", oP);
	ok(oT > 1.8 && oT < 2.3, "t_max: order %.3f over 100..400 steps (second order)", oT);
	/* R_f meets the end-of-contact floor (impact.c's extrap) at once */
	ok(eR[0] < 1e-6 && eR[2] < eR[0], "R_f: %.2g at 100 steps, smaller at 400", eR[0]);
}

static void sphere(struct anvil_params *p, double V0)
{
	struct anvil_scene sc;
	anvil_scene_default(&sc);
	sc.impactor.mat = sc.layer.mat;
	sc.radius = 5e-3;
	sc.mass = 4.0 / 3.0 * M_PI * pow(sc.radius, 3) * sc.layer.mat.rho;
	sc.velocity = V0;
	sc.thickness = INFINITY;
	sc.thickness_per_r0 = 0;
	anvil_params_from_scene(p, &sc, NULL);
}

static void test_hunter(void)
{
	enum { N = 8 };
	double lv[N], lf[N], fbig = 0, worst = 0, ferr = 0, c0 = 0;
	double C = anvil_contact_hunter_coef(0.3, anvil_radiation_xi(0.3));
	int good = 1;
	for (int i = 0; i < N; i++) {
		double V0 = 0.1 * pow(300.0, (double)i / (N - 1));
		struct anvil_params p;
		struct anvil_result r;
		sphere(&p, V0);
		good &= run_hs(&p, 1000, 0, 0, &r) == ANVIL_OK;
		c0 = sqrt(p.E / p.rho);
		double f = 1 - r.Rf.val * r.Rf.val; /* fraction of the kinetic energy lost */
		ferr = fmax(ferr, 2 * r.Rf.err / f);
		lv[i] = log(V0);
		lf[i] = log(f);
		fbig = fmax(fbig, f);
		worst = fmax(worst, fabs(f / (C * pow(V0 / c0, 0.6)) - 1) / f);
		if (i == 0 || i == N - 1)
			diag("V0 = %g m/s: f = %.6g = %.5f (V0/c0)^(3/5) (+- %.1g relative); C(0.3) = %.5f",
			     V0, f, f / pow(V0 / c0, 0.6), 2 * r.Rf.err / f, C);
	}
	ok(good, "sphere on its own material, integrated row: 8 runs, 0.1 to 30 m/s");
	ok(ferr < 1e-3, "the radiated fraction is resolved: relative error <= %.2g", ferr);
	double mx = 0, my = 0, sxy = 0, sxx = 0;
	for (int i = 0; i < N; i++)
		mx += lv[i] / N, my += lf[i] / N;
	for (int i = 0; i < N; i++)
		sxy += (lv[i] - mx) * (lf[i] - my), sxx += (lv[i] - mx) * (lv[i] - mx);
	is_abs(sxy / sxx, 0.6, fbig, "fitted exponent %.5f = 3/5 within f_max = %.4f", sxy / sxx,
	       fbig);
	ok(worst < 1.0, "f = C (V0/c0)^(3/5) (1 + O(f)): |f/(C ...) - 1| <= %.3f f", worst);
}

/* Kinetic energy lost = the work of P on the remainder, int P dw, w the
 * history's remainder (-beta Q on a half-space): trapezoid on a fine
 * history, against its own halving. */
static void test_energy(void)
{
	struct anvil_params p;
	struct anvil_result r;
	paper_params(&p, INFINITY, 10);
	run_hs(&p, 2000, 0, 20001, &r);
	double work = 0;
	for (size_t i = 1; i < r.hist.n; i++)
		work += 0.5 * (r.hist.P[i] + r.hist.P[i - 1]) * (r.hist.w[i] - r.hist.w[i - 1]);
	double lost = r.Ea.val;
	diag("lost %.8g J, work on the remainder %.8g J (%.2g relative)", lost, work,
	     fabs(work / lost - 1));
	is_rel(work, lost, 2e-3, "energy balance: kinetic energy lost = energy into the layer");
	anvil_result_free(&r);
}

int main(void)
{
	plan(18);
	test_rigid();
	test_against_ode();
	test_order();
	test_hunter();
	test_energy();
	return done_testing();
}
