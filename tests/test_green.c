/* test_green: the layer's transformed kernel and its inversion.
 *  - the stable kernel against a direct 4x4 solve of the boundary conditions
 *    (eqs 24-26, both faces free) and against its limits;
 *  - causality: the layer correction is zero until the bottom reflection;
 *  - the layer's step response against the independent reference curves
 *    (../shared/reference), converging as the bandwidth grows;
 *  - two inversion settings far apart agree;
 *  - a thin layer's impulse response tends to the plate's alpha* (eq 8). */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>

#include "green.h"
#include "halfspace.h"
#include "direct_bc.h"
#include "tap.h"

typedef double complex cplx;

/* w(0) of the free layer from the direct solve (eq 24 at z = 0). */
static cplx direct_w(double k, cplx s, double nu, double h)
{
	cplx D[4];
	direct_bc(k, s, nu, h, D);
	return D[1] + k * D[2];
}

static void test_kernel(void)
{
	const double ks[] = { 0.01, 0.4, 1.3, 3.0 }, hs[] = { 0.3, 1.0, 2.0 };
	const cplx ss[] = { 0.3 + 0.1 * I, 0.1 + 2.0 * I, 1.0 + 5.0 * I, 0.05 + 0.9 * I };
	double worst = 0;
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 3; j++)
			for (int l = 0; l < 4; l++) {
				cplx lay, hsp, d = direct_w(ks[i], ss[l], 0.3, hs[j]);
				anvil_green_kernel(ks[i], ss[l], 0.3, hs[j], &lay, &hsp);
				worst = fmax(worst, cabs(lay - d) / cabs(d));
			}
	ok(worst < 1e-9, "layer kernel = direct 4x4 solve of the boundary conditions (worst rel. %.1e)", worst);

	cplx lay, hsp;
	worst = 0;
	for (int l = 0; l < 4; l++) {
		anvil_green_kernel(1.0, ss[l], 0.3, 200.0, &lay, &hsp);
		worst = fmax(worst, cabs(lay - hsp) / cabs(hsp));
	}
	ok(worst < 1e-12, "h = 200 r0: layer kernel = half-space kernel (worst rel. %.1e)", worst);
	anvil_green_kernel(2.0, 1e-6, 0.3, INFINITY, &lay, &hsp);
	is_rel(creal(2.0 * hsp), 1 - 0.3, 1e-9, "static half-space kernel k W(k, 0) = 1 - nu");
	/* large k: the rationalised Rayleigh function keeps its digits */
	anvil_green_kernel(1e4, 0.2 + 1.0 * I, 0.3, INFINITY, &lay, &hsp);
	is_rel(creal(1e4 * hsp), 1 - 0.3, 1e-6, "k = 1e4: k W -> 1 - nu without cancellation");
}

struct setup {
	double hh, nu, tau_end, mu, c2, r0;
};

static struct anvil_green *make(const struct setup *su, double omega, double c0T)
{
	struct anvil_green_settings gs;
	struct anvil_err e;
	anvil_green_settings(ANVIL_ACC_NORMAL, &gs);
	gs.omega_max = omega;
	if (c0T > 0)
		gs.c0T = c0T;
	struct anvil_green *g = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, su->hh, su->nu,
						  su->tau_end, &gs, NULL, NULL, &e);
	if (!g)
		diag("green: %s", e.msg);
	return g;
}

static void test_causality(void)
{
	struct setup su = { .hh = 5, .nu = 0.3, .tau_end = 30 };
	struct anvil_green *g = make(&su, 48, 0);
	struct anvil_halfspace *hs = anvil_halfspace_alloc(0.3, 1e-10, NULL);
	double kappa = sqrt((1 - 2 * 0.3) / (2 * (1 - 0.3))), t_refl = 2 * su.hh * kappa;
	double worst = 0, after = 0, v, ref;
	for (double tau = 0.1; tau < 0.9 * t_refl; tau += 0.1) {
		anvil_green_ramp(g, tau, &v);
		anvil_halfspace_ramp(hs, tau, &ref, NULL);
		worst = fmax(worst, fabs(v) / ref);
	}
	anvil_green_ramp(g, 2 * t_refl, &v);
	anvil_halfspace_ramp(hs, 2 * t_refl, &ref, NULL);
	after = fabs(v) / ref;
	ok(worst < 1e-4, "layer correction is ~0 before the bottom reflection (2h/c1): %.1e of the ramp", worst);
	ok(after > 1e-3, "and not after it (%.1e of the ramp at 4h/c1)", after);
	double s1, s2;
	anvil_halfspace_ramp(hs, 0.05, &s1, NULL);
	anvil_green_ramp(g, 0.05, &s2);
	is_rel(2 * (s1 + s2) / (0.05 * 0.05), 3 * kappa / (2 * M_PI), 2e-3,
	       "early time: step slope = Z(0)/(rho c1), i.e. w_delta(0,0,0+) (eq 34)");
	anvil_green_free(g);
	anvil_halfspace_free(hs);
}

/* Largest |ours - ref| / (peak) of the step response and the largest
 * relative error of the ramp (t > 0.5 us) against a reference file. */
static int against_reference(const char *file, double hh, double omega, double *step_dev,
			     double *step_dev_err, double *ramp_dev)
{
	const double E = 209e9, nu = 0.3, rho = 7830, r0 = 4e-3;
	double mu = E / (2 * (1 + nu)), c2 = sqrt(mu / rho);
	struct setup su = { .hh = hh, .nu = nu, .tau_end = 45e-6 * c2 / r0 + 2 };
	const char *shared = getenv("SHARED");
	char path[1024];
	snprintf(path, sizeof path, "%s/reference/%s", shared ? shared : "../shared", file);
	FILE *f = fopen(path, "r");
	if (!f)
		return -1;
	struct anvil_green *g = make(&su, omega, 0);
	struct anvil_halfspace *hs = anvil_halfspace_alloc(nu, 1e-10, NULL);
	char line[512];
	double peak = 0, dmax = 0, dmax_err = 0, rmax = 0, ramp_ref = 0, pt = 0, pw = 0;
	while (fgets(line, sizeof line, f)) {
		double t, w, er;
		if (line[0] == '#' || sscanf(line, "%lf %lf %lf", &t, &w, &er) != 3)
			continue;
		double tau = t * 1e-6 * c2 / r0;
		if (tau > su.tau_end - 1)
			break;
		ramp_ref += 0.5 * (w + pw) * (t - pt) * 1e-6; /* trapezoid */
		pt = t;
		pw = w;
		double a, b, hr, hstep, h = 0.005;
		anvil_green_ramp(g, tau + h, &a);
		anvil_green_ramp(g, tau > h ? tau - h : 0, &b);
		anvil_halfspace_step(hs, tau, &hstep, NULL);
		double step = (hstep + (a - b) / (tau > h ? 2 * h : tau + h)) / (mu * r0);
		anvil_green_ramp(g, tau, &a);
		anvil_halfspace_ramp(hs, tau, &hr, NULL);
		double ramp = (a + hr) / (mu * c2);
		peak = fmax(peak, fabs(w));
		dmax = fmax(dmax, fabs(step - w));
		dmax_err = fmax(dmax_err, fabs(step - w) - 3 * er);
		if (t > 0.5)
			rmax = fmax(rmax, fabs(ramp - ramp_ref) / fabs(ramp_ref));
	}
	fclose(f);
	*step_dev = dmax / peak;
	*step_dev_err = dmax_err / peak;
	*ramp_dev = rmax;
	anvil_green_free(g);
	anvil_halfspace_free(hs);
	return 0;
}

static void test_reference(void)
{
	const char *files[] = { "step-response-steel-h1r0.tsv", "step-response-steel-h5r0.tsv" };
	const double hh[] = { 1, 5 }, omegas[] = { 4, 12, 48 };
	for (int i = 0; i < 2; i++) {
		double dev[3], deverr[3], rdev[3];
		int st = 0;
		for (int j = 0; j < 3 && !st; j++)
			st = against_reference(files[i], hh[i], omegas[j], &dev[j], &deverr[j], &rdev[j]);
		if (st) {
			printf("ok %d # SKIP %s not found (set SHARED)\n", ++tap_n, files[i]);
			continue;
		}
		for (int j = 0; j < 3; j++)
			diag("h = %g r0, bandwidth %g: step |ours-ref| <= %.1e of peak (%.1e beyond 3x the file's err); ramp %.1e",
			     hh[i], omegas[j], dev[j], deverr[j], rdev[j]);
		/* The solver uses the ramp response; it is compared strictly.  The
		 * step response here is its numerical derivative, band-limited, and
		 * rings at every wave arrival (a kink); the reference rings too,
		 * as its err column says. */
		ok(rdev[2] < 5e-4, "h = %g r0: ramp response within 5e-4 of the reference after 0.5 us (%.1e)",
		   hh[i], rdev[2]);
		ok(deverr[2] < 5e-3, "h = %g r0: step response within 3 err + 5e-3 of peak of the reference (%.1e)",
		   hh[i], deverr[2]);
		ok(dev[2] < dev[1] && dev[1] < dev[0], "h = %g r0: the deviation falls as the bandwidth grows", hh[i]);
	}
}

static void test_settings_agree(void)
{
	struct setup su = { .hh = 2, .nu = 0.3, .tau_end = 40 };
	struct anvil_green *a = make(&su, 12, 8.0), *b = make(&su, 12, 13.0);
	struct anvil_halfspace *hs = anvil_halfspace_alloc(0.3, 1e-10, NULL);
	double worst = 0;
	for (double tau = 2; tau <= 38; tau += 2) {
		double va, vb, ref;
		anvil_green_ramp(a, tau, &va);
		anvil_green_ramp(b, tau, &vb);
		anvil_halfspace_ramp(hs, tau, &ref, NULL);
		worst = fmax(worst, fabs(va - vb) / ref);
	}
	ok(worst < 2e-4, "c0 T' = 8 and 13 give the same layer response (%.1e of the ramp)", worst);
	anvil_green_free(a);
	anvil_green_free(b);
	anvil_halfspace_free(hs);
}

/* A thin layer moves like Zener's plate at late times: the impulse response
 * (second derivative of the ramp) tends to alpha* of eq (8), in these units
 * sqrt(3 (1 - nu) / 2) / (4 hh^2). */
static void test_plate_limit(void)
{
	struct setup su = { .hh = 0.5, .nu = 0.3, .tau_end = 400 };
	struct anvil_green *g = make(&su, 2, 0);
	double alpha = sqrt(1.5 * (1 - 0.3)) / (4 * 0.25), r[3];
	for (int i = 0; i < 3; i++)
		anvil_green_ramp(g, 300 + 20 * (i - 1), &r[i]);
	double impulse = (r[0] - 2 * r[1] + r[2]) / 400.0;
	is_rel(impulse, alpha, 0.02, "h = 0.5 r0: late impulse response -> plate alpha* (eq 8)");
	anvil_green_free(g);
}

int main(void)
{
	gsl_set_error_handler_off();
	test_kernel();
	test_causality();
	test_reference();
	test_settings_agree();
	test_plate_limit();
	plan(tap_n);
	return done_testing();
}
