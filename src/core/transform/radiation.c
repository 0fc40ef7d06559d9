/* radiation.c: the radiation mobility of a point force on a half-space
 * (see radiation.h for the derivation of beta and its sign). */
#include <complex.h>
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "halfspace.h"
#include "material.h"
#include "radiation.h"

/* Height of the lifted contour; any value in (0, 1) keeps it clear of the
 * branch points (kappa, 1) and the Rayleigh pole, which lie on the real
 * axis, and of the poles of the analytic continuation. */
#define XI_LIFT 0.3
/* End of the lifted part: past the Rayleigh pole q_R = c2/c_R, which is
 * below 1.15 for every nu in (-1, 0.5); beyond it the integrand is real. */
#define XI_X 3.0
#define XI_LIMIT 200

struct xi_ctx {
	double kap2;
};

/* Im of W_hs(q, s = i) q dq on the contour q = x + i XI_LIFT sin(pi x/X),
 * in units mu = c2 = rho = 1; W_hs = alpha1 s^2 / ((2q^2 + s^2)^2 -
 * 4 q^2 alpha1 alpha2) (green.c), the surface displacement per unit normal
 * traction in the Hankel domain.  Lifting the path above the real axis
 * passes above the pole and the branch points as s = i + 0 requires. */
static double xi_integrand(double x, void *vc)
{
	const struct xi_ctx *c = vc;
	double y = XI_LIFT * sin(M_PI * x / XI_X);
	double dy = XI_LIFT * M_PI / XI_X * cos(M_PI * x / XI_X);
	double complex q = x + I * y, b = -1.0; /* s^2 with s = i */
	double complex a1 = csqrt(q * q + c->kap2 * b), a2 = csqrt(q * q + b);
	double complex g = 2.0 * q * q + b;
	double complex w = a1 * b / (g * g - 4.0 * q * q * a1 * a2);
	return cimag(w * q * (1.0 + I * dy));
}

double anvil_radiation_xi(double nu)
{
	if (!(nu > -1 && nu < 0.5))
		return NAN;
	struct xi_ctx c = { anvil_kappa2(nu) };
	gsl_function f = { xi_integrand, &c };
	double im, abserr;
	gsl_integration_workspace *w = gsl_integration_workspace_alloc(XI_LIMIT);
	if (!w)
		return NAN;
	int st = gsl_integration_qag(&f, 0.0, XI_X, 0.0, 0.1 * ANVIL_RADIATION_XI_TOL, XI_LIMIT,
				     GSL_INTEG_GAUSS31, w, &im, &abserr);
	gsl_integration_workspace_free(w);
	/* Re Y = -omega Im U and U = (omega / 2 pi) int W_hs q dq for the point
	 * load (omega = 1 here) */
	double xi = -im / (2.0 * M_PI);
	if (st || !(abserr <= ANVIL_RADIATION_XI_TOL * fabs(im)))
		return NAN;
	return xi;
}

double anvil_radiation_beta(double nu, double rho, double c2)
{
	if (!(rho > 0 && c2 > 0 && isfinite(rho) && isfinite(c2)))
		return NAN;
	return anvil_radiation_xi(nu) / (rho * c2 * c2 * c2);
}

/* The Rayleigh pole q_R = c2/c_R is a simple zero of D(q) = (2q^2 - 1)^2 -
 * 4 q^2 a1 a2 (a1 = sqrt(q^2 - kappa^2), a2 = sqrt(q^2 - 1), both real
 * there).  A contour above a simple pole picks up -i pi Res, so the pole's
 * part of Re Y = -Im U is (1/2) Res(W q) = (1/2) a1 q_R s^2 / D'(q_R). */
double anvil_radiation_rayleigh_share(double nu)
{
	double k2 = anvil_kappa2(nu), x;
	if (!(nu > -1 && nu < 0.5) || anvil_rayleigh_x(k2, &x, NULL))
		return NAN;
	double q = 1.0 / sqrt(x), q2 = q * q;
	double a1 = sqrt(q2 - k2), a2 = sqrt(q2 - 1.0);
	double dD = 8.0 * q * (2.0 * q2 - 1.0) - 8.0 * q * a1 * a2 -
		    4.0 * q2 * (q * a2 / a1 + q * a1 / a2);
	double xi_r = -0.5 * a1 * q / dD; /* (1/2) a1 q s^2 / D', s^2 = -1 */
	return xi_r / anvil_radiation_xi(nu);
}

/* The centre's next term: the exact ramp response of the Hertz patch
 * (halfspace.c) less its asymptote C tau - xi, integrated over [0, tau_R]
 * (beyond tau_R the two are equal, radiation.h): that area is the
 * coefficient of (i omega)^2 a / (mu c2^2) in w / P at the centre. */
struct gamma_ctx {
	const struct anvil_halfspace *hs;
	double C, xi;
	int st;
};

static double gamma_integrand(double tau, void *vc)
{
	struct gamma_ctx *c = vc;
	double r;
	c->st |= anvil_halfspace_ramp(c->hs, tau, &r, NULL);
	return r - c->C * tau + c->xi;
}

double anvil_radiation_gamma(double nu)
{
	if (!(nu > -1 && nu < 0.5))
		return NAN;
	struct anvil_halfspace *hs = anvil_halfspace_alloc(nu, 1e-12, NULL);
	gsl_integration_workspace *w = gsl_integration_workspace_alloc(XI_LIMIT);
	struct gamma_ctx c = { hs, anvil_halfspace_static(nu), anvil_radiation_xi(nu), 0 };
	double g = NAN, abserr = 0;
	if (hs && w && isfinite(c.xi)) {
		/* the integrand's kinks: the P and S arrivals from the rim at the
		 * centre (kappa, 1) and the Rayleigh wave's (tau_R) */
		double pts[] = { 0.0, sqrt(anvil_kappa2(nu)), 1.0, anvil_halfspace_tau_r(hs) };
		gsl_function f = { gamma_integrand, &c };
		int st = gsl_integration_qagp(&f, pts, 4, 1e-14, 0.1 * ANVIL_RADIATION_XI_TOL,
					      XI_LIMIT, w, &g, &abserr);
		if (st || c.st || !(abserr <= ANVIL_RADIATION_XI_TOL * fabs(g)))
			g = NAN;
	}
	gsl_integration_workspace_free(w);
	anvil_halfspace_free(hs);
	return ANVIL_RADIATION_PUNCH_MEAN * g;
}

double anvil_radiation_g2(double nu, double rho, double c2)
{
	if (!(rho > 0 && c2 > 0 && isfinite(rho) && isfinite(c2)))
		return NAN;
	return anvil_radiation_gamma(nu) / (rho * c2 * c2 * c2 * c2);
}
