/* test_halfspace.c: the exact half-space centre response (src/core/halfspace).
 *
 * Checks exact facts (initial slope Z(0)/(rho c1), exactly static after the
 * Rayleigh wave from the rim, closed-form Rayleigh speeds), an independent
 * forward check (the Laplace transform of the step response against the
 * transform-domain kernel integrated over k, which uses nothing of the
 * contour derivation), the independent reference curves in
 * $SHARED/reference, the ramp against quadrature of the step, tolerance
 * refinement, and every error status. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "halfspace.h"
#include "tap.h"

#define WS_LIMIT 1000

static gsl_integration_workspace *ws;

/* ---- independent transform-domain check -------------------------------- */

struct lap {
	double nu, k2, p;
	const struct anvil_halfspace *hs;
};

/* F(x) = x^2 a1 / ((2 + x^2)^2 - 4 a1 a2), rationalised so that nothing
 * cancels at small x (the k^8 terms of the Rayleigh function cancel). */
static double kernel_f(double x, double k2)
{
	if (x > 1e8) /* F ~ kappa / x */
		return sqrt(k2) / x;
	double x2 = x * x, a1 = sqrt(1 + k2 * x2), a2 = sqrt(1 + x2);
	double num = a1 * ((2 + x2) * (2 + x2) + 4 * a1 * a2);
	double den = ((x2 + 8) * x2 + (24 - 16 * k2)) * x2 + 16 * (1 - k2);
	return num / den;
}

/* Z^H(k) for r0 = 1, with its series at small k. */
static double load_hankel(double k)
{
	if (k < 1e-2) {
		double k2 = k * k;
		return 3.0 / (2 * M_PI) * (1.0 / 3 - k2 / 30 + k2 * k2 / 840 - k2 * k2 * k2 / 45360);
	}
	return 3 * (sin(k) - k * cos(k)) / (2 * M_PI * k * k * k);
}

static double lap_k_integrand(double k, void *par)
{
	const struct lap *l = par;
	if (k == 0)
		return -(1 - l->nu) * load_hankel(0);
	return (kernel_f(l->p / k, l->k2) - (1 - l->nu)) * load_hankel(k);
}

/* The tail k > K by QAWF: Z^H(k) = 3/(2 pi) (sin k / k^3 - cos k / k^2). */
static double lap_tail_sin(double k, void *par)
{
	const struct lap *l = par;
	return (kernel_f(l->p / k, l->k2) - (1 - l->nu)) * 3 / (2 * M_PI * k * k * k);
}

static double lap_tail_cos(double k, void *par)
{
	const struct lap *l = par;
	return -(kernel_f(l->p / k, l->k2) - (1 - l->nu)) * 3 / (2 * M_PI * k * k);
}

/* (1/p) int_0^inf F(p/k) Z^H(k) dk: the transform of the step response. */
static int lap_forward(double nu, double p, double *val)
{
	const double kcut = 40;
	struct lap l = { nu, (1 - 2 * nu) / (2 * (1 - nu)), p, NULL };
	gsl_function f = { lap_k_integrand, &l };
	gsl_function fs = { lap_tail_sin, &l }, fc = { lap_tail_cos, &l };
	double r1, e1, r2 = 0, e2, r3 = 0, e3;
	int st = gsl_integration_qag(&f, 0, kcut, 1e-14, 1e-12, WS_LIMIT, GSL_INTEG_GAUSS41, ws,
				     &r1, &e1);
	gsl_integration_workspace *cyc = gsl_integration_workspace_alloc(WS_LIMIT);
	gsl_integration_qawo_table *ts = gsl_integration_qawo_table_alloc(1, 1, GSL_INTEG_SINE, 50);
	gsl_integration_qawo_table *tc = gsl_integration_qawo_table_alloc(1, 1, GSL_INTEG_COSINE, 50);
	if (!cyc || !ts || !tc)
		st = GSL_ENOMEM;
	if (!st)
		st = gsl_integration_qawf(&fs, kcut, 1e-15, WS_LIMIT, ws, cyc, ts, &r2, &e2);
	if (!st)
		st = gsl_integration_qawf(&fc, kcut, 1e-15, WS_LIMIT, ws, cyc, tc, &r3, &e3);
	gsl_integration_qawo_table_free(ts);
	gsl_integration_qawo_table_free(tc);
	gsl_integration_workspace_free(cyc);
	if (st)
		return st;
	*val = ((1 - nu) * 0.375 + r1 + r2 + r3) / p;
	return 0;
}

static int hs_status;

static double step_fn(double tau, void *par)
{
	const struct lap *l = par;
	double v, e;
	int st = anvil_halfspace_step(l->hs, tau, &v, &e);
	if (st)
		hs_status = st;
	return l->p > 0 ? exp(-l->p * tau) * v : v;
}

/* int_0^inf e^{-p tau} step(tau) dtau, using step = static beyond tau_R. */
static int lap_ours(const struct anvil_halfspace *hs, double nu, double p, double *val)
{
	struct lap l = { nu, 0, p, hs };
	gsl_function f = { step_fn, &l };
	double kap = sqrt((1 - 2 * nu) / (2 * (1 - nu))), tr = anvil_halfspace_tau_r(hs);
	double pts[4] = { 0, kap, 1, tr }, r, e;
	int st = gsl_integration_qagp(&f, pts, 4, 1e-14, 1e-12, WS_LIMIT, ws, &r, &e);
	if (st)
		return st;
	*val = r + anvil_halfspace_static(nu) * exp(-p * tr) / p;
	return hs_status;
}

/* int_0^tau step, by QAGP with the kinks (kappa, 1, tau_R) as break points. */
static int ramp_by_quadrature(const struct anvil_halfspace *hs, double nu, double tau, double *val)
{
	struct lap l = { nu, 0, 0, hs };
	gsl_function f = { step_fn, &l };
	double kap = sqrt((1 - 2 * nu) / (2 * (1 - nu))), tr = anvil_halfspace_tau_r(hs);
	double cand[3] = { kap, 1, tr }, pts[5];
	size_t n = 0;
	pts[n++] = 0;
	for (int i = 0; i < 3; i++)
		if (cand[i] < tau)
			pts[n++] = cand[i];
	pts[n++] = tau;
	double e;
	int st = gsl_integration_qagp(&f, pts, n, 1e-14, 1e-12, WS_LIMIT, ws, val, &e);
	return st ? st : hs_status;
}

/* ---- reference curves ---------------------------------------------------- */

/* Steel of the reference files: E = 209 GPa, nu = 0.3, rho = 7830, r0 = 4 mm. */
#define STEEL_E 209e9
#define STEEL_NU 0.3
#define STEEL_RHO 7830.0
#define STEEL_R0 4e-3

/* The reference files come from a Fourier-series inversion: their error is
 * about 1e-5 of the value, but grows into Gibbs ringing before the bottom
 * reflection arrives at 2h/c1 and the waves from the rim at r0/c2, r0/c_R
 * (the err column says so, and the h = r0 and h = 5 r0 files, both the
 * half-space before 1.33 us, differ by up to 9e-4 of the peak at 1.28 us).
 * So the strict 1e-4-of-peak bound is applied where the file claims 1e-5 of
 * peak, and at every point the bound is 1e-4 of peak plus twice the file's
 * own error estimate.  Both maxima are reported. */
/* Read the file's rows with t < tmax_us; -1 if it cannot be opened. */
static int read_reference(const char *name, double tmax_us, double *t, double *w, double *e,
			  int nmax, char *path, size_t pathlen)
{
	const char *shared = getenv("SHARED");
	snprintf(path, pathlen, "%s/reference/%s", shared && *shared ? shared : "../shared", name);
	FILE *fp = fopen(path, "r");
	if (!fp)
		return -1;
	char line[512];
	int n = 0;
	while (n < nmax && fgets(line, sizeof line, fp)) {
		if (line[0] == '#' || sscanf(line, "%lf %lf %lf", &t[n], &w[n], &e[n]) != 3)
			continue;
		if (t[n] < tmax_us)
			n++;
	}
	fclose(fp);
	return n;
}

enum { NREF = 20000 };
static double tt[NREF], ours[NREF], ref[NREF], rerr[NREF];
static double tt2[NREF], ref2[NREF], rerr2[NREF];

static void compare_reference(const struct anvil_halfspace *hs, const char *name, double tmax_us,
			      double tstat)
{
	char path[1024];
	int n = read_reference(name, tmax_us, tt, ref, rerr, NREF, path, sizeof path);
	if (n < 0) {
		ok(1, "%s # SKIP not found at %s", name, path);
		ok(1, "%s # SKIP not found", name);
		return;
	}
	double mu = STEEL_E / (2 * (1 + STEEL_NU)), c2 = sqrt(mu / STEEL_RHO);
	double peak = 0, ownerr = 0;
	int status = 0;
	for (int i = 0; i < n; i++) {
		double v, e;
		int st = anvil_halfspace_step(hs, c2 * tt[i] * 1e-6 / STEEL_R0, &v, &e);
		if (st)
			status = st;
		ours[i] = v / (mu * STEEL_R0);
		if (e / (mu * STEEL_R0) > ownerr)
			ownerr = e / (mu * STEEL_R0);
		if (fabs(ref[i]) > peak)
			peak = fabs(ref[i]);
	}
	double dall = 0, tall = 0, eall = 0, dgood = 0, tgood = 0, worst = 0, tworst = 0;
	double sumst = 0;
	int ngood = 0, nbeyond = 0, nstat = 0;
	for (int i = 0; i < n; i++) {
		double d = fabs(ours[i] - ref[i]);
		if (d > dall) {
			dall = d;
			tall = tt[i];
			eall = rerr[i];
		}
		if (rerr[i] <= 1e-5 * peak) {
			ngood++;
			if (d > dgood) {
				dgood = d;
				tgood = tt[i];
			}
		}
		if (d > rerr[i])
			nbeyond++;
		double r = d / (1e-4 * peak + 2 * rerr[i]);
		if (r > worst) {
			worst = r;
			tworst = tt[i];
		}
		if (tt[i] > tstat) {
			sumst += ref[i] - ours[i];
			nstat++;
		}
	}
	diag("%s, t < %g us: %d points, peak %.6e m/N, our error estimate <= %.1e m/N", name,
	     tmax_us, n, peak, ownerr);
	diag("  all points:  max |ours - ref| = %.2e of peak at t = %.4f us (file err there"
	     " %.2e of peak)", dall / peak, tall, eall / peak);
	diag("  %d points with file err <= 1e-5 of peak: max |ours - ref| = %.2e of peak at"
	     " t = %.4f us", ngood, dgood / peak, tgood);
	diag("  |ours - ref| > file err at %d of %d points; max |ours - ref| / (1e-4 peak +"
	     " 2 err) = %.2f at t = %.4f us", nbeyond, n, worst, tworst);
	if (nstat)
		diag("  t > r0/c_R (ours exactly static): mean(ref - ours) = %.1e of peak over %d"
		     " points", sumst / nstat / peak, nstat);
	ok(status == 0 && ngood >= 5 && dgood <= 1e-4 * peak,
	   "%s: max |ours - ref| = %.1e of peak <= 1e-4 where the file's err <= 1e-5", name,
	   dgood / peak);
	ok(status == 0 && n > 0 && worst <= 1,
	   "%s: |ours - ref| <= 1e-4 peak + 2 err at all %d points, t < %g us", name, n,
	   tmax_us);
}

/* ---- main ---------------------------------------------------------------- */

int main(void)
{
	gsl_set_error_handler_off();
	ws = gsl_integration_workspace_alloc(WS_LIMIT);
	if (!ws) {
		printf("1..0 # SKIP no memory\n");
		return 1;
	}
	struct anvil_err err;
	const double nu = 0.3, tol = 1e-8;
	const double kap = sqrt((1 - 2 * nu) / (2 * (1 - nu)));
	const double stat = anvil_halfspace_static(nu);

	/* errors */
	anvil_err_clear(&err);
	ok(!anvil_halfspace_alloc(0.5, tol, &err) && err.status == ANVIL_EINVAL && err.msg[0],
	   "nu = 0.5 refused: %s", err.msg);
	ok(!anvil_halfspace_alloc(-1.0, tol, &err) && err.status == ANVIL_EINVAL,
	   "nu = -1 refused");
	ok(!anvil_halfspace_alloc(NAN, tol, &err) && err.status == ANVIL_EINVAL, "nu = NaN refused");
	ok(!anvil_halfspace_alloc(nu, 0.0, &err) && err.status == ANVIL_EINVAL, "tol = 0 refused");
	ok(!anvil_halfspace_alloc(nu, NAN, &err) && err.status == ANVIL_EINVAL, "tol = NaN refused");
	ok(!anvil_halfspace_alloc(nu, 1e-16, &err) && err.status == ANVIL_ETOL && err.msg[0],
	   "tol = 1e-16 gives ANVIL_ETOL: %s", err.msg);
	ok(!anvil_halfspace_alloc(0.7, tol, NULL), "NULL err is allowed");
	anvil_halfspace_free(NULL);
	ok(isnan(anvil_halfspace_static(0.5)) && isnan(anvil_halfspace_static(-1.5)),
	   "static(nu) is NaN outside (-1, 0.5)");
	is_rel(stat, 0.2625, 1e-15, "static(0.3) = 3 (1 - nu) / 8");

	struct anvil_halfspace *hs = anvil_halfspace_alloc(nu, tol, &err);
	if (!ok(hs != NULL, "alloc nu = 0.3, tol = 1e-8")) {
		diag("%s", err.msg);
		plan(tap_n);
		return 1;
	}
	{
		double v, e = 0;
		int st1 = anvil_halfspace_step(hs, -1e-300, &v, &e);
		ok(st1 == ANVIL_EINVAL && isnan(v), "step(tau < 0) is ANVIL_EINVAL, NaN");
		st1 = anvil_halfspace_step(hs, NAN, &v, NULL);
		int st2 = anvil_halfspace_ramp(hs, INFINITY, &v, NULL);
		int st3 = anvil_halfspace_ramp(hs, -1, &v, NULL);
		ok(st1 == ANVIL_EINVAL && st2 == ANVIL_EINVAL && st3 == ANVIL_EINVAL,
		   "NaN, infinite and negative tau refused by step and ramp");
		ok(anvil_halfspace_step(hs, 0, &v, &e) == 0 && v == 0 &&
			   anvil_halfspace_ramp(hs, 0, &v, &e) == 0 && v == 0,
		   "step(0) = ramp(0) = 0");
	}

	/* Rayleigh speed against closed forms: nu = 1/4, xi = 2 - 2/sqrt(3)
	 * (Rayleigh 1885); nu = 0, xi = 3 - sqrt(5) (root of (xi - 2)(xi^2 - 6 xi + 4)). */
	{
		struct anvil_halfspace *a = anvil_halfspace_alloc(0.25, tol, NULL);
		struct anvil_halfspace *b = anvil_halfspace_alloc(0.0, tol, NULL);
		ok(a && b, "alloc nu = 0.25 and nu = 0");
		if (a && b) {
			is_rel(anvil_halfspace_tau_r(a), 1 / sqrt(2 - 2 / sqrt(3)), 1e-14,
			       "tau_R(nu = 1/4) = 1/sqrt(2 - 2/sqrt 3)");
			is_rel(anvil_halfspace_tau_r(b), 1 / sqrt(3 - sqrt(5)), 1e-14,
			       "tau_R(nu = 0) = 1/sqrt(3 - sqrt 5)");
		}
		anvil_halfspace_free(a);
		anvil_halfspace_free(b);
	}

	/* initial slope Z(0)/(rho c1): in these units 3 kappa / (2 pi) */
	{
		double want = 3 * kap / (2 * M_PI), v, e;
		int st = anvil_halfspace_step(hs, 1e-6, &v, &e);
		is_rel(v / 1e-6, want, 1e-4, "step(tau)/tau -> 3 kappa/(2 pi) = %.10f (tau = 1e-6)",
		       want);
		diag("  step(1e-6)/1e-6 = %.12f, rel. dev. %.1e (status %d)", v / 1e-6,
		     fabs(v / 1e-6 - want) / want, st);
		anvil_halfspace_step(hs, 1e-3, &v, &e);
		diag("  step(1e-3)/1e-3 = %.12f", v / 1e-3);
	}

	/* exactly static after tau_R, continuous there and at the kinks kappa, 1 */
	{
		double tr = anvil_halfspace_tau_r(hs), v, e, worst = 0;
		double taus[] = { tr, tr * (1 + 1e-12), 1.2, 2.0, 10.0, 1e6 };
		for (size_t i = 0; i < sizeof taus / sizeof *taus; i++) {
			anvil_halfspace_step(hs, taus[i], &v, &e);
			if (fabs(v - stat) > worst)
				worst = fabs(v - stat);
		}
		is_abs(worst, 0, 0, "step = 3 (1 - nu)/8 exactly for tau >= tau_R = %.12f", tr);
		anvil_halfspace_step(hs, tr * (1 - 1e-9), &v, &e);
		is_abs(v, stat, tol * stat, "continuous at tau_R (from below)");
		double kinks[] = { kap, 1.0 };
		for (int i = 0; i < 2; i++) {
			double lo, hi, elo, ehi;
			anvil_halfspace_step(hs, kinks[i] * (1 - 1e-12), &lo, &elo);
			anvil_halfspace_step(hs, kinks[i] * (1 + 1e-12), &hi, &ehi);
			is_abs(lo, hi, tol * stat, "step continuous at tau = %.6f", kinks[i]);
			anvil_halfspace_ramp(hs, kinks[i] * (1 - 1e-12), &lo, &elo);
			anvil_halfspace_ramp(hs, kinks[i] * (1 + 1e-12), &hi, &ehi);
			is_abs(lo, hi, tol * stat, "ramp continuous at tau = %.6f", kinks[i]);
		}
		/* between 1 and tau_R the step is a parabola: second differences constant */
		double p[3];
		for (int i = 0; i < 3; i++)
			anvil_halfspace_step(hs, 1.0 + 0.02 * i, &p[i], &e);
		double d2a = p[2] - 2 * p[1] + p[0];
		for (int i = 0; i < 3; i++)
			anvil_halfspace_step(hs, 1.03 + 0.02 * i, &p[i], &e);
		is_abs(p[2] - 2 * p[1] + p[0], d2a, 1e-14, "parabola on [1, tau_R]");
	}

	/* independent forward check: the Laplace transform */
	{
		double ps[] = { 0.3, 1.0, 3.0, 10.0 };
		for (int i = 0; i < 4; i++) {
			double a = NAN, b = NAN;
			int st1 = lap_ours(hs, nu, ps[i], &a);
			int st2 = lap_forward(nu, ps[i], &b);
			ok(st1 == 0 && st2 == 0, "Laplace transforms at p = %g computed", ps[i]);
			is_rel(a, b, 1e-9, "L[step](p = %g) = (1/p) int F(p/k) Z^H(k) dk", ps[i]);
			diag("  %.15f vs %.15f: rel. dev. %.1e", a, b, fabs(a - b) / fabs(b));
		}
	}

	/* reference curves: layer = half-space until 2h/c1 */
	{
		double c1 = sqrt(STEEL_E * (1 - STEEL_NU) /
				 (STEEL_RHO * (1 + STEEL_NU) * (1 - 2 * STEEL_NU)));
		diag("2h/c1: h = 5 r0 %.4f us, h = r0 %.4f us", 2 * 5 * STEEL_R0 / c1 * 1e6,
		     2 * STEEL_R0 / c1 * 1e6);
		double c2 = sqrt(STEEL_E / (2 * (1 + STEEL_NU) * STEEL_RHO));
		double tstat = STEEL_R0 / c2 * anvil_halfspace_tau_r(hs) * 1e6;
		diag("r0/c_R = %.4f us", tstat);
		compare_reference(hs, "step-response-steel-h5r0.tsv", 6.5, tstat);
		compare_reference(hs, "step-response-steel-h1r0.tsv", 1.33, tstat);
		/* both files are the half-space before 1.33 us: how well do they agree? */
		char path[1024];
		int n1 = read_reference("step-response-steel-h1r0.tsv", 1.33, tt, ref, rerr, NREF,
					path, sizeof path);
		int n5 = read_reference("step-response-steel-h5r0.tsv", 1.33, tt2, ref2, rerr2,
					NREF, path, sizeof path);
		double dmax = 0, tmax = 0;
		for (int i = 0; i < n1 && i < n5; i++)
			if (tt[i] == tt2[i] && fabs(ref[i] - ref2[i]) > dmax) {
				dmax = fabs(ref[i] - ref2[i]);
				tmax = tt[i];
			}
		double stat_si = stat / (STEEL_E / (2 * (1 + STEEL_NU)) * STEEL_R0);
		if (n1 > 0 && n5 > 0)
			diag("h1r0 vs h5r0 file for t < 1.33 us (both the half-space): max difference"
			     " %.2e of static at t = %.4f us", dmax / stat_si, tmax);
	}

	/* the ramp is the integral of the step */
	{
		double taus[] = { 0.05, 0.3, 0.6, 0.95, 1.04, 1.5, 3.0 };
		for (size_t i = 0; i < sizeof taus / sizeof *taus; i++) {
			double r, e, q = NAN;
			int st1 = anvil_halfspace_ramp(hs, taus[i], &r, &e);
			int st2 = ramp_by_quadrature(hs, nu, taus[i], &q);
			ok(st1 == 0 && st2 == 0 && fabs(r - q) <= 1e-11 + e,
			   "ramp(%g) = %.12f = QAGP of step %.12f (diff %.1e, est %.1e)", taus[i], r,
			   q, fabs(r - q), e);
		}
		double r4, r5, e;
		anvil_halfspace_ramp(hs, 4.0, &r4, &e);
		anvil_halfspace_ramp(hs, 5.0, &r5, &e);
		is_abs(r5 - r4, stat, 1e-14, "ramp linear with slope static beyond tau_R");
	}

	/* the reported error estimates honour tol (1e-8 here) */
	{
		int honest = 1;
		double worst = 0;
		for (int i = 0; i <= 300; i++) {
			double tau = 0.004 * i, v, e, r, re;
			honest &= anvil_halfspace_step(hs, tau, &v, &e) == 0 && e <= tol * stat &&
				  anvil_halfspace_ramp(hs, tau, &r, &re) == 0 && re <= tol * stat;
			if (e > worst)
				worst = e;
		}
		ok(honest, "abserr <= tol * static for step and ramp on [0, 1.2] (max step"
			   " abserr %.1e)", worst);
	}

	/* tightening tol changes the answer by less than the reported abserr */
	{
		struct anvil_halfspace *lo = anvil_halfspace_alloc(nu, 1e-4, NULL);
		struct anvil_halfspace *hi = anvil_halfspace_alloc(nu, 1e-12, NULL);
		int good = lo && hi, honest = 1;
		double worst = 0;
		for (int i = 0; good && i <= 60; i++) {
			double tau = 0.02 * i, a, ea, b, eb;
			good &= anvil_halfspace_step(lo, tau, &a, &ea) == 0 &&
				anvil_halfspace_step(hi, tau, &b, &eb) == 0 && fabs(a - b) <= ea + eb;
			honest &= ea <= 1e-4 * stat;
			if (fabs(a - b) > worst)
				worst = fabs(a - b);
			good &= anvil_halfspace_ramp(lo, tau, &a, &ea) == 0 &&
				anvil_halfspace_ramp(hi, tau, &b, &eb) == 0 && fabs(a - b) <= ea + eb;
		}
		ok(good, "tol 1e-4 vs 1e-12: differences within the reported abserr (max %.1e)",
		   worst);
		ok(honest, "the reported abserr honours tol = 1e-4");
		anvil_halfspace_free(lo);
		anvil_halfspace_free(hi);
	}

	/* other Poisson ratios */
	{
		double nus[] = { 0.0, 0.25, 0.49, -0.5, -0.99, 0.4999 };
		for (size_t i = 0; i < sizeof nus / sizeof *nus; i++) {
			double n = nus[i], s = anvil_halfspace_static(n);
			double kn = sqrt((1 - 2 * n) / (2 * (1 - n)));
			struct anvil_halfspace *h = anvil_halfspace_alloc(n, tol, &err);
			if (!ok(h != NULL, "alloc nu = %g", n)) {
				diag("%s", err.msg);
				continue;
			}
			double tr = anvil_halfspace_tau_r(h), v, e;
			int finite = 1, stc = 1;
			for (int j = 0; j <= 200; j++) {
				double tau = tr * j / 200.0;
				finite &= anvil_halfspace_step(h, tau, &v, &e) == 0 && isfinite(v) &&
					  isfinite(e);
				finite &= anvil_halfspace_ramp(h, tau, &v, &e) == 0 && isfinite(v);
			}
			for (int j = 0; j < 5; j++) {
				anvil_halfspace_step(h, tr * (1 + 0.5 * j), &v, &e);
				stc &= v == s;
			}
			ok(finite && stc, "nu = %g: finite on [0, tau_R = %.6f], static after", n, tr);
			anvil_halfspace_step(h, 1e-7, &v, &e);
			is_rel(v / 1e-7, 3 * kn / (2 * M_PI), 1e-4, "nu = %g: initial slope", n);
			double a = NAN, b = NAN;
			hs_status = 0;
			lap_ours(h, n, 1.0, &a);
			lap_forward(n, 1.0, &b);
			is_rel(a, b, 1e-9, "nu = %g: Laplace transform at p = 1 (rel. dev. %.1e)", n,
			       fabs(a - b) / fabs(b));
			anvil_halfspace_free(h);
		}
	}

	anvil_halfspace_free(hs);
	gsl_integration_workspace_free(ws);
	plan(tap_n);
	return done_testing();
}
