/* zener_dashpot.c: Zener's impact at large lambda*, where the plate is a
 * dashpot to the impactor (its point impedance 8 sqrt(D rho h) = 1/alpha*
 * far exceeds what the Hertz spring can push against).
 *
 * With u = v/V0 the ODE of zener.h has the first integral
 *   alpha' = u - lambda* alpha^(3/2),   u' = -alpha^(3/2),
 * and (u, alpha, tau) = (L^-5 U, L^-4 B, L sigma), L = lambda*, turns it
 * into the same system with lambda* = 1 started from U = L^5: every large
 * lambda* is one trajectory, entered ever higher on its slow manifold
 * B^(3/2) = U - B'.  Three phases, each in closed form but for two
 * universal constants of the end:
 *  - the rise (s = L^(2/3) tau, alpha = L^(-2/3) A): A' = 1 - A^(3/2),
 *    solved by s(y) below with A = y^2; A -> 1 - k exp(-3s/2),
 *    k = 2 sqrt(3) exp(-pi/(2 sqrt 3)).  u falls by eps (s - A),
 *    eps = L^(-5/3), and the peak (A^(3/2) = u) comes where the rise's
 *    lag k exp(-3s/2) meets the manifold's own fall (4/9) eps:
 *    s_max = (10/9) ln L + (2/3) ln(9k/4).  There P = Z V0 u exactly
 *    (alpha' = 0), so P_max = Z V0 (1 - eps (s_max - 1) + ...): its
 *    relative remainder is O(eps s_max) before the correction kept here;
 *  - the slow decay u ~ exp(-tau/L) (the dashpot draining the impactor);
 *  - the end, when U is O(1): sigma_s = ln U0 + C_END, U_s = -R_INF.  The
 *    start adds 3 eps to sigma_s: eps from the rise's missing impulse
 *    (the integral of 1 - A^(3/2) over the rise is 1) and 2 eps = 2 U0^(-1/3)
 *    from the manifold's -(2/3) U^(2/3) term cut off at U0.
 * Measured against the ODE (tests/test_zener.c, lambda* = 1e2-1e6): the
 * remainders after these terms are about eps^2 in sigma_s, 0.2 eps s_max^2
 * in s_max, below (eps s_max)^2 in alpha_max; the error estimates take
 * twice the first, 0.5 eps s_max^2 and (eps s_max)^2. */
#include <float.h>
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "zener.h"

/* sigma_s - ln U0 and -U_s at the end of the lambda* = 1 trajectory from
 * U0 -> inf: anvil_zener_solve's ODE at tol 1e-13 gives tau_s/L - 5 ln L
 * - 3 eps = -0.3593670559 (L = 1e6), -0.3593670560 (1e7), each +- 2.5e-8
 * (its estimate), and rf L^5 = 0.6792930641 +- 2e-8 (L = 4), 0.6792930653
 * +- 1.4e-7 (6); tests/test_zener.c checks both. */
#define ZENER_C_END (-0.359367056)
#define ZENER_C_END_ERR 3e-8
#define ZENER_R_INF 0.679293064
#define ZENER_R_INF_ERR 2e-7
/* The limit is used from lambda* = 100 (eps = 4.6e-4) up. */
#define ZENER_DASHPOT_MIN 100.0
/* s_max's remainder coefficient (measured 0.19-0.22 at lambda* = 1e2-1e5). */
#define ZENER_TMAX_REM 0.5
/* Past s = 30 the rise's lag 1 - A < k exp(-45) is below double's eps. */
#define ZENER_RISE_END 30.0
#define ZENER_RISE_ITER 100

/* k of the rise's approach A -> 1 - k exp(-3s/2). */
static double rise_k(void)
{
	return 2.0 * sqrt(3.0) * exp(-M_PI / (2.0 * sqrt(3.0)));
}

/* The rise's time s to reach A = y^2, as a function of z = -ln(1 - y):
 * s = int_0^A dA / (1 - A^(3/2)) in closed form (partial fractions of
 * 2y / (1 - y^3)); finite for every z, so a bracket never meets inf. */
static double rise_s(double z, void *vp)
{
	double target = *(const double *)vp;
	double y = -expm1(-z);
	double r3 = sqrt(3.0);
	return 2.0 / 3.0 * z + log1p(y + y * y) / 3.0 -
	       2.0 / r3 * (atan((2.0 * y + 1.0) / r3) - M_PI / 6.0) - target;
}

/* 1 - A at rise time s (A = alpha L^(2/3) without the slow fall). */
static int rise_lag(gsl_root_fsolver *root, double s, double *lag)
{
	if (s >= ZENER_RISE_END) {
		*lag = 0.0;
		return GSL_SUCCESS;
	}
	if (!(s > 0)) {
		*lag = 1.0;
		return GSL_SUCCESS;
	}
	/* s(z) >= (2/3) z - 2 pi/(3 sqrt 3) > (2/3) z - 1.21: bracketed */
	gsl_function F = { rise_s, &s };
	double lo = 0.0, hi = 1.5 * (s + 2.0);
	int st = gsl_root_fsolver_set(root, &F, lo, hi);
	for (int i = 0; !st && i < ZENER_RISE_ITER; i++) {
		st = gsl_root_fsolver_iterate(root);
		if (st)
			break;
		lo = gsl_root_fsolver_x_lower(root);
		hi = gsl_root_fsolver_x_upper(root);
		st = gsl_root_test_interval(lo, hi, 0.0, 4 * DBL_EPSILON);
		if (st != GSL_CONTINUE)
			break;
		st = i + 1 == ZENER_RISE_ITER ? GSL_EMAXITER : GSL_SUCCESS;
	}
	if (st)
		return st;
	double e = exp(-gsl_root_fsolver_root(root));
	*lag = e * (2.0 - e); /* 1 - y^2 = (1 - y)(1 + y) */
	return GSL_SUCCESS;
}

int anvil_zener_dashpot(double lambda_star, struct anvil_zener_sol *sol, struct anvil_err *err)
{
	if (!sol)
		return anvil_err_set(err, ANVIL_EINVAL, "zener: no solution given");
	if (!(lambda_star >= ZENER_DASHPOT_MIN && isfinite(lambda_star)))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "zener: the dashpot limit needs lambda* >= %g, got %g",
				     ZENER_DASHPOT_MIN, lambda_star);
	double L = lambda_star, lnL = log(L), eps = pow(L, -5.0 / 3.0);
	double L23 = pow(L, -2.0 / 3.0);
	double s_max = 10.0 / 9.0 * lnL + 2.0 / 3.0 * log(9.0 * rise_k() / 4.0);
	sol->tau_max = L23 * s_max;
	sol->alpha_max = L23 * (1.0 - 2.0 / 3.0 * eps * (s_max - 1.0));
	sol->tau_s = L * (5.0 * lnL + ZENER_C_END + 3.0 * eps);
	sol->rf = ZENER_R_INF * pow(L, -5.0);
	sol->err_tmax = L23 * ZENER_TMAX_REM * eps * s_max * s_max;
	sol->err_amax = L23 * (eps * s_max) * (eps * s_max);
	sol->err_ts = L * (2.0 * eps * eps + ZENER_C_END_ERR);
	sol->err_rf = sol->rf * (ZENER_R_INF_ERR / ZENER_R_INF + eps);
	sol->err = fmax(fmax(sol->err_ts, sol->err_tmax), fmax(sol->err_amax, sol->err_rf));
	return ANVIL_OK;
}

/* The state at tau: the rise and the slow decay composed (their common
 * part 1 + eps - eps s taken out once), u = v/V0, alpha from the manifold
 * times the rise; W = alpha + L (1 - u) (eq (8): w = alpha* m1 (V0 - v)).
 * Relative O(eps s_max) where the force is: the last few L of the
 * contact, where u < L^-5 e^3, are off by as much (u crosses 0 there). */
static int dashpot_state(gsl_root_fsolver *root, double L, double tau, double y[4])
{
	double eps = pow(L, -5.0 / 3.0), s = pow(L, 2.0 / 3.0) * tau, lag;
	int st = rise_lag(root, s, &lag);
	if (st)
		return st;
	double u = (1.0 + eps) * exp(-tau / L) - eps * lag;
	double a = pow(fmax(u, 0.0) / L, 2.0 / 3.0) * (1.0 - lag);
	y[0] = a;
	y[2] = u;
	y[3] = a + L * (1.0 - u);
	y[1] = u - L * pow(a, 1.5);
	return GSL_SUCCESS;
}

int anvil_zener_dashpot_history(const struct anvil_params *p, const struct anvil_zener_sol *sol,
				struct anvil_history *hist)
{
	gsl_root_fsolver *root = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	if (!root)
		return ANVIL_ENOMEM;
	double beta = anvil_history_warp(sol->tau_max, sol->tau_s);
	double Ls = p->T * p->V0, y[4] = { 0 };
	int st = GSL_SUCCESS;
	for (size_t i = 0; !st && i < hist->n; i++) {
		double ti = anvil_history_time(i, hist->n, sol->tau_s, beta);
		if (i + 1 == hist->n) {
			/* the end itself: no compression, the rebound */
			y[0] = y[1] = 0.0;
			y[2] = -sol->rf;
			y[3] = p->lambda_star * (1.0 + sol->rf);
		} else {
			st = dashpot_state(root, p->lambda_star, ti, y);
		}
		hist->t[i] = p->T * ti;
		hist->alpha[i] = Ls * y[0];
		hist->P[i] = p->K * pow(Ls * y[0], 1.5);
		hist->v[i] = p->V0 * y[2];
		hist->W[i] = Ls * y[3];
		hist->w[i] = Ls * (y[3] - y[0]);
	}
	gsl_root_fsolver_free(root);
	return st ? ANVIL_ENUM : ANVIL_OK;
}
