/* test_radiation: the point force's radiation mobility xi(nu) and beta
 *  - against the exact half-space (halfspace.c, an independent method: the
 *    Cagniard-type inversion of the Hertz patch's response): once the
 *    Rayleigh wave from the rim has passed, ramp(tau) - C tau = -xi;
 *  - the Rayleigh wave's share of the power against Miller and Pursey
 *    (1955): 67.4 % for nu = 0.25 (from the pole's residue alone);
 *  - beta's units and bad input;
 *  - the next term gamma (issue 11): the centre's area from the exact
 *    half-space at nu = 0 and 1/4, where it is rational (21/256, 27/512,
 *    times 8/5), and the factor 8/5 itself, the flat punch's mean of
 *    |x - x'| over the Hertz pressure against the centre's, by quadrature
 *    over the disc. */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_ellint.h>

#include "halfspace.h"
#include "material.h"
#include "radiation.h"
#include "tap.h"

/* Tolerance of the half-space objects (relative to the static value) */
#define HS_TOL 1e-11

static void test_ramp_limit(void)
{
	const double nus[] = { 0.0, 0.15, 0.25, 0.3, 0.45, -0.3 };
	for (size_t i = 0; i < sizeof nus / sizeof nus[0]; i++) {
		double nu = nus[i], xi = anvil_radiation_xi(nu), C = anvil_halfspace_static(nu);
		struct anvil_halfspace *hs = anvil_halfspace_alloc(nu, HS_TOL, NULL);
		double tr = anvil_halfspace_tau_r(hs), r1, r2, e1, e2;
		int st = anvil_halfspace_ramp(hs, tr + 0.5, &r1, &e1) |
			 anvil_halfspace_ramp(hs, 3.0 * tr + 7.0, &r2, &e2);
		/* 1e-8: the ramp's own error estimate (checked below) is about
		 * 1e-10 of the static value; xi's is 1e-10 */
		ok(st == ANVIL_OK && e1 < 1e-9 && e2 < 1e-9, "nu = %.2f: half-space ramp computed",
		   nu);
		is_rel(r1 - C * (tr + 0.5), -xi, 1e-8,
		       "nu = %.2f: ramp - C tau = -xi = %.10f just after the Rayleigh wave", nu, -xi);
		is_rel(r2 - C * (3.0 * tr + 7.0), -xi, 1e-8,
		       "nu = %.2f: and stays there (the remainder is a pure -beta dP/dt)", nu);
		anvil_halfspace_free(hs);
	}
}

static void test_partition(void)
{
	/* Miller and Pursey (1955), Proc. R. Soc. A 233, 55: for nu = 1/4,
	 * 67.4 % of the power goes into the Rayleigh wave (25.8 % shear,
	 * 6.9 % compressional).  The share here is the pole's residue over
	 * the whole contour integral: two different computations. */
	double share = anvil_radiation_rayleigh_share(0.25);
	is_abs(share, 0.674, 0.001, "Rayleigh share of the radiated power at nu = 0.25: %.4f "
	       "(Miller & Pursey 1955: 0.674)", share);
	int mono = 1;
	for (double nu = 0.0; nu < 0.45; nu += 0.05)
		mono &= anvil_radiation_rayleigh_share(nu + 0.05) < anvil_radiation_rayleigh_share(nu);
	ok(mono, "the Rayleigh share falls as nu grows (more goes into body waves)");
}

static void test_beta(void)
{
	struct anvil_material st = *anvil_material_find("steel");
	double c2 = anvil_material_c2(&st), xi = anvil_radiation_xi(st.nu);
	double beta = anvil_radiation_beta(st.nu, st.rho, c2);
	is_rel(beta * anvil_material_mu(&st) * c2, xi, 1e-14,
	       "beta mu c2 = xi: the ramp of w_dyn is -xi in halfspace.h's units");
	diag("steel: xi = %.8f, beta = %.6g m s/N", xi, beta);
	ok(isnan(anvil_radiation_xi(0.5)) && isnan(anvil_radiation_xi(-1)) &&
	   isnan(anvil_radiation_xi(NAN)), "xi: NaN outside (-1, 0.5)");
	ok(isnan(anvil_radiation_beta(0.3, 0, c2)) && isnan(anvil_radiation_beta(0.3, st.rho, -1)) &&
	   isnan(anvil_radiation_beta(0.3, INFINITY, c2)), "beta: NaN for bad rho or c2");
	ok(isnan(anvil_radiation_rayleigh_share(0.5)), "Rayleigh share: NaN outside (-1, 0.5)");
}

/* The mean of |x - x'| over the angle between x and x' at radii r, s:
 * (2/pi) (r + s) E(k), k = 2 sqrt(r s) / (r + s). */
static double mean_dist(double r, double s)
{
	if (r + s == 0)
		return 0;
	double k = fmin(2.0 * sqrt(r * s) / (r + s), 1.0 - 1e-16);
	return 2.0 / M_PI * (r + s) * gsl_sf_ellint_Ecomp(k, GSL_PREC_DOUBLE);
}

/* Over the unit disc with r = sin u (Hertz: r sqrt(1-r^2) dr = sin u cos^2 u
 * du, weight 1/3) and s = sin v (punch: s ds/sqrt(1-s^2) = sin v dv,
 * weight 1): both smooth in u, v. */
static double punch_inner(double v, void *vu)
{
	return mean_dist(sin(*(double *)vu), sin(v)) * sin(v);
}

static double punch_outer(double u, void *vw)
{
	double r, e;
	gsl_function f = { punch_inner, &u };
	gsl_integration_qags(&f, 0, M_PI / 2, 1e-14, 1e-12, 200, vw, &r, &e);
	return r * sin(u) * cos(u) * cos(u);
}

static double hertz_centre(double u, void *v)
{
	(void)v;
	return sin(u) * sin(u) * cos(u) * cos(u); /* r times the Hertz weight */
}

static void test_gamma(void)
{
	gsl_integration_workspace *w1 = gsl_integration_workspace_alloc(200);
	gsl_integration_workspace *w2 = gsl_integration_workspace_alloc(200);
	double eh, ehf, e;
	gsl_function fc = { hertz_centre, NULL }, fp = { punch_outer, w2 };
	gsl_integration_qags(&fc, 0, M_PI / 2, 1e-14, 1e-12, 200, w1, &eh, &e);
	gsl_integration_qags(&fp, 0, M_PI / 2, 1e-14, 1e-11, 200, w1, &ehf, &e);
	eh *= 3.0, ehf *= 3.0;
	gsl_integration_workspace_free(w1);
	gsl_integration_workspace_free(w2);
	is_rel(eh, 3.0 * M_PI / 16.0, 1e-10, "E_H|x| = 3 pi a / 16 (%.12f)", eh);
	is_rel(ehf / eh, ANVIL_RADIATION_PUNCH_MEAN, 1e-9,
	       "the flat punch's mean of |x - x'| over the Hertz pressure is %.10f times the "
	       "centre's (radiation.h: 8/5)", ehf / eh);
	is_rel(anvil_radiation_gamma(0.0), 1.6 * 21.0 / 256.0, 1e-9,
	       "gamma(0) = (8/5) 21/256 from the exact half-space (%.10f)", anvil_radiation_gamma(0.0));
	is_rel(anvil_radiation_gamma(0.25), 1.6 * 27.0 / 512.0, 1e-9,
	       "gamma(1/4) = (8/5) 27/512 (%.10f)", anvil_radiation_gamma(0.25));
	diag("gamma(0.3) = %.8f, gamma/xi = %.5f", anvil_radiation_gamma(0.3),
	     anvil_radiation_gamma(0.3) / anvil_radiation_xi(0.3));
	struct anvil_material st = *anvil_material_find("steel");
	double c2 = anvil_material_c2(&st);
	ok(isnan(anvil_radiation_gamma(0.5)) && isnan(anvil_radiation_g2(0.3, 0, c2)) &&
	   isnan(anvil_radiation_g2(0.3, st.rho, INFINITY)) &&
	   anvil_radiation_g2(st.nu, st.rho, c2) > 0, "gamma, g2: NaN for bad input, else > 0");
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(6 * 3 + 2 + 4 + 5);
	test_ramp_limit();
	test_partition();
	test_beta();
	test_gamma();
	return done_testing();
}
