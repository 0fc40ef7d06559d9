/* test_hertz: the closed-form Hertz impact, and Zener's ODE at lambda* = 0
 * reproducing it. */
#include <float.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_gamma.h>

#include "hertz.h"
#include "paper.h"
#include "tap.h"
#include "zener.h"

/* tau_s to 30 digits: 2 (5/4)^(2/5) (2/5) B(2/5, 1/2), mpmath at 30 digits. */
#define TAU_S_REF 3.21806545971904308453593004562
/* The paper's copper impactor on steel, by hand (mpmath, 30 digits):
 * P_max = K^(2/5) (5 m1 V0^2 / 4)^(3/5), t_s = tau_s T. */
#define TS_10_REF 3.95092257338709441630054617054e-5
#define PMAX_10_REF 11360.6241902311538503907965159
#define TS_100_REF 2.49286361515117252556453598871e-5
#define PMAX_100_REF 180053.759412064056582177479965


static void test_constants(void)
{
	double want = 2.0 * pow(1.25, 0.4) * 0.4 * gsl_sf_beta(0.4, 0.5);
	is_abs(anvil_hertz_tau_s(), 3.21807, 1e-5, "tau_s = 3.21807");
	is_rel(anvil_hertz_tau_s(), want, 4 * DBL_EPSILON,
	       "tau_s = 2 (5/4)^(2/5) (2/5) B(2/5,1/2)");
	is_rel(anvil_hertz_tau_s(), TAU_S_REF, 1e-14, "tau_s to 30-digit value");
	is_rel(anvil_hertz_alpha_max(), pow(1.25, 0.4), 4 * DBL_EPSILON,
	       "alpha_max = (5/4)^(2/5)");
}

/* Zener's ODE with lambda* = 0 is Hertz's. */
static void test_ode_is_hertz(void)
{
	struct anvil_zener_sol s;
	struct anvil_err e;
	int st = anvil_zener_solve(0.0, 1e-12, &s, &e);
	ok(st == ANVIL_OK, "ODE at lambda* = 0 solves (%s)", st ? e.msg : "ok");
	is_rel(s.tau_s, anvil_hertz_tau_s(), 1e-9, "ODE tau_s = closed form");
	is_rel(s.tau_max, 0.5 * anvil_hertz_tau_s(), 1e-9, "ODE tau_max = tau_s / 2");
	is_rel(s.alpha_max, anvil_hertz_alpha_max(), 1e-9, "ODE alpha_max = (5/4)^(2/5)");
	is_abs(s.rf, 1.0, 1e-9, "ODE rf = 1");
	ok(s.err > 0 && s.err < 1e-9, "ODE error estimate %.3g in (0, 1e-9)", s.err);
	diag("ODE - closed form: tau_s %.3g, alpha_max %.3g, rf %.3g (err %.3g)",
	     s.tau_s - anvil_hertz_tau_s(), s.alpha_max - anvil_hertz_alpha_max(),
	     s.rf - 1.0, s.err);
}

static void test_closed_form(double V0, double ts_ref, double pmax_ref)
{
	struct anvil_params p;
	struct anvil_result r;
	struct anvil_err e;
	paper_params(&p, 2.0, V0);
	anvil_result_init(&r, ANVIL_MODEL_HERTZ);
	int st = anvil_hertz_run(&p, 0, &r, &e);
	ok(st == ANVIL_OK, "hertz V0 = %g runs", V0);
	is_rel(r.ts.val, ts_ref, 1e-9, "V0 = %g: t_s = %.6g us", V0, 1e6 * ts_ref);
	is_rel(r.tmax.val, 0.5 * ts_ref, 1e-9, "V0 = %g: t_max = t_s / 2", V0);
	is_rel(r.Pmax.val, pmax_ref, 1e-9, "V0 = %g: P_max = %.6g kN", V0, 1e-3 * pmax_ref);
	ok(r.Vs.val == V0 && r.Rf.val == 1.0 && r.Ea.val == 0.0, "V0 = %g: V_s = V0, R_f = 1, E_a = 0", V0);
	ok(r.ts.err > 0 && r.ts.err < 1e-14 * r.ts.val && r.Pmax.err < 1e-14 * r.Pmax.val,
	   "V0 = %g: closed-form error estimates ~1e-15", V0);
	ok(r.lambda_star == p.lambda_star && r.Rf_star == p.Rf_star,
	   "V0 = %g: lambda*, R_f* copied for display", V0);
	ok(strcmp(r.note, "layer taken as rigid (w = 0)") == 0, "note: %s", r.note);
	ok(r.model == ANVIL_MODEL_HERTZ && r.hist.n == 0, "no history without nhist");
	anvil_result_free(&r);

	/* Zener on a half-space is the Hertz row. */
	struct anvil_result z;
	paper_params(&p, INFINITY, V0);
	anvil_result_init(&z, ANVIL_MODEL_ZENER);
	st = anvil_zener_run(&p, 0, &z, &e);
	ok(st == ANVIL_OK, "zener on a half-space runs (%s)", st ? e.msg : "ok");
	is_rel(z.ts.val, ts_ref, 1e-9, "V0 = %g: zener half-space t_s = hertz", V0);
	is_rel(z.tmax.val, 0.5 * ts_ref, 1e-9, "V0 = %g: zener half-space t_max = hertz", V0);
	is_rel(z.Pmax.val, pmax_ref, 1e-9, "V0 = %g: zener half-space P_max = hertz", V0);
	is_abs(z.Rf.val, 1.0, 1e-9, "V0 = %g: zener half-space R_f = 1", V0);
	anvil_result_free(&z);
}

static void test_history(void)
{
	struct anvil_params p;
	struct anvil_result r;
	struct anvil_err e;
	const size_t n = 201;
	paper_params(&p, 1.0, 10.0);
	anvil_result_init(&r, ANVIL_MODEL_HERTZ);
	int st = anvil_hertz_run(&p, n, &r, &e);
	ok(st == ANVIL_OK && r.hist.n == n, "hertz history of %zu samples", n);
	if (st != ANVIL_OK || r.hist.n != n)
		return;
	const struct anvil_history *h = &r.hist;
	is_abs(h->t[0], 0.0, 0.0, "history starts at t = 0");
	is_rel(h->t[n - 1], r.ts.val, 1e-9, "history ends at t_s");
	is_rel(h->v[0], p.V0, 1e-15, "v(0) = V0");
	is_rel(h->v[n - 1], -p.V0, 1e-9, "v(t_s) = -V0");
	is_rel(h->P[(n - 1) / 2], r.Pmax.val, 1e-9, "P(t_s/2) = P_max");
	ok(h->alpha[n - 1] < 1e-9 * h->alpha[(n - 1) / 2], "alpha(t_s) = 0");
	double ework = 0, wmax = 0, dW = 0;
	for (size_t i = 0; i < n; i++) {
		/* Kinetic plus Hertz energy (2/5) K alpha^(5/2) is conserved. */
		double a = fmax(h->alpha[i], 0.0);
		double en = 0.5 * p.m1 * h->v[i] * h->v[i] + 0.4 * p.K * pow(a, 2.5);
		ework = fmax(ework, fabs(en / (0.5 * p.m1 * p.V0 * p.V0) - 1.0));
		wmax = fmax(wmax, fabs(h->w[i]));
		dW = fmax(dW, fabs(h->W[i] - h->alpha[i]));
	}
	ok(ework < 1e-9, "energy conserved along the history (max rel. dev. %.3g)", ework);
	ok(wmax == 0.0 && dW == 0.0, "w = 0 and W = alpha_H (rigid layer)");
	anvil_result_free(&r);
}

static void test_errors(void)
{
	struct anvil_params p;
	struct anvil_result r;
	struct anvil_err e;
	paper_params(&p, 1.0, 10.0);
	anvil_result_init(&r, ANVIL_MODEL_HERTZ);
	ok(anvil_hertz_run(NULL, 0, &r, &e) == ANVIL_EINVAL, "NULL params: EINVAL");
	ok(anvil_hertz_run(&p, 0, NULL, NULL) == ANVIL_EINVAL, "NULL result: EINVAL");
	p.T = NAN;
	ok(anvil_hertz_run(&p, 0, &r, &e) == ANVIL_EINVAL && e.msg[0],
	   "T = NaN: EINVAL (%s)", e.msg);
}

int main(void)
{
	gsl_set_error_handler_off();
	test_constants();
	test_ode_is_hertz();
	test_closed_form(10.0, TS_10_REF, PMAX_10_REF);
	test_closed_form(100.0, TS_100_REF, PMAX_100_REF);
	test_history();
	test_errors();
	plan(tap_n);
	return done_testing();
}
