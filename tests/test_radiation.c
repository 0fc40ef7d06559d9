/* test_radiation: the point force's radiation mobility xi(nu) and beta
 *  - against the exact half-space (halfspace.c, an independent method: the
 *    Cagniard-type inversion of the Hertz patch's response): once the
 *    Rayleigh wave from the rim has passed, ramp(tau) - C tau = -xi;
 *  - the Rayleigh wave's share of the power against Miller and Pursey
 *    (1955): 67.4 % for nu = 0.25 (from the pole's residue alone);
 *  - beta's units and bad input. */
#include <math.h>

#include <gsl/gsl_errno.h>

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

int main(void)
{
	gsl_set_error_handler_off();
	plan(6 * 3 + 2 + 4);
	test_ramp_limit();
	test_partition();
	test_beta();
	return done_testing();
}
