/* contact.h: the physical contact model on a half-space (issue 10).
 *
 * The impactor's displacement W is the Hertz approach of the true contact
 * plus the layer's dynamic remainder only:
 *   W = alpha_H(P) + w_dyn,  alpha_H = (P/K)^(2/3),  w_dyn = -beta dP/dt,
 * beta = xi(nu) / (rho c2^3) (transform/radiation.h).  alpha_H already holds
 * the static indentation of both bodies, so the layer adds only what it
 * does beyond it: for a contact small against the wavelengths it excites,
 * the radiation lag of Miller and Pursey, whose energy is Hunter's (1957)
 * loss beta int (dP/dt)^2 dt.
 *
 * Layering: beta is an argument.  The caller (the engine, the tests) gets
 * it from anvil_radiation_beta() in transform; physics does not include
 * transform.
 *
 * Why not anvil_impact_run with the ramp response -beta H(t): taken as it
 * stands, W = alpha_H(P) - beta dP/dt is an equation for dP/dt,
 *   beta dP/dt = alpha_H(P) - W(t),
 * whose linearisation grows like exp(t/delta), delta = beta dP/dalpha_H
 * (64 ns for the paper's impact, against a 40 us contact): the runaway of
 * the Abraham-Lorentz equation, a spurious solution of a truncated
 * low-frequency expansion used at frequencies (1/delta) where it no longer
 * holds.  The implicit scheme then has a root only for dt > delta and its
 * end-of-contact search fails on the jump (tests/test_contact.c shows
 * both).  The physical (slow) solution is found as Landau and Lifshitz do
 * for radiation reaction: the remainder is O(beta), so within it dP/dt is
 * replaced by its zeroth-order value, dP/dt = (3/2) K alpha^(1/2) dW/dt
 * (the layer's own motion is O(beta) as well).  The error is
 * O(beta^2), i.e. relative O(f) in the wave effect, f the radiated
 * fraction.  In units tau = t/T, x = W/(T V0), u = v/V0, p = P T/(m1 V0):
 *   x'' = -p,  p = a^(3/2),  a - eps (3/2) u a^(1/2) = x,
 *   eps = beta m1 / T^3,
 * a smooth, well-posed ODE (the root a^(1/2) = (c + sqrt(c^2 + 4x))/2,
 * c = 1.5 eps u, is smooth while in contact), solved with GSL odeiv2;
 * contact ends at x = 0 (a = 0) on the rebound, located by integrating in x
 * (Henon's trick).  The model depends on eps alone: eps = 0 is Hertz. */
#ifndef ANVIL_CONTACT_H
#define ANVIL_CONTACT_H

#include <stddef.h>

#include "params.h"
#include "result.h"

struct anvil_contact_opts {
	double tol;   /* relative and absolute tolerance of the ODE, in (0, 1e-3] */
	size_t nhist; /* history samples wanted (0: none) */
	/* The second order (issue 11; 0: first order, the model above): the
	 * remainder's next term + g2 d^2(a P)/dt^2 (g2 = gamma / (mu c2^2),
	 * transform/radiation.h) with the reduction's own next term, as
	 * impact.c's pass_physical has them:
	 *   x = a - (3/2) eps u a^(1/2) + sigma,  sigma = c_u u^2 - c_x a p,
	 *   c_u = eta - (9/8) eps^2,  c_x = eta - (9/4) eps^2,
	 *   eta = 2 g2 K sqrt(R) V0 / T.
	 * The contact then starts and ends at X = x - c_u u^2 = 0 (a = 0 at
	 * the end); before the start the impactor flies free.  The loss
	 * stays equal to Hunter's beta int (dP/dt)^2 to O(f^2) relative (the
	 * first order: O(f)). */
	double g2;
};

/* Energy figures of one run (SI). */
struct anvil_contact_energy {
	double eps;      /* beta m1 / T^3 */
	double lost;     /* kinetic energy lost, m1 (V0^2 - V_s^2) / 2, J */
	double rad_pq;   /* beta int dP/dt Q dt, Q the zeroth-order dP/dt, less
			  * int dP/dt sigma with the second order (g2): what the
			  * model takes, equal to lost up to O(beta^5) */
	double rad_pp;   /* beta int (dP/dt)^2 dt: Hunter's loss, equal to lost up
			  * to O(f^2) relative (the O(f) terms are odd about the
			  * pulse's peak; tests/test_contact.c) */
	double err;      /* estimated absolute error of the three, J */
};

/* eps = beta m1 / T^3, the model's one parameter; NaN for bad input. */
double anvil_contact_eps(const struct anvil_params *p, double beta);

/* Run the model for the scene's parameters p on a half-space with
 * remainder coefficient beta >= 0 (m s/N).  Fills r (anvil_result_init'ed
 * by the caller) with t_s, t_max, P_max, V_s, R_f, E_a and their error
 * estimates (the difference between runs at tol and 100 tol; the values
 * are those of the tol run), histories if asked (w is w_dyn), and en (may
 * be NULL).  Returns ANVIL_OK, ANVIL_EINVAL (bad p, beta or opts),
 * ANVIL_ENOMEM, ANVIL_ENUM (integrator failure, or a loss so large that
 * the impactor does not rebound: eps must be small, <= 0.05). */
int anvil_contact_run(const struct anvil_params *p, double beta,
		      const struct anvil_contact_opts *o, struct anvil_result *r,
		      struct anvil_contact_energy *en, struct anvil_err *err);

/* The radiated fraction for a sphere on a block of its own material,
 * f = C(nu) (V0/c0)^(3/5), c0 = sqrt(E/rho), to first order in eps:
 *   C = 2 xi I_H (4 pi/3)^(-1/5) (2/(3 (1 - nu^2)))^(6/5) (2 (1 + nu))^(3/2),
 * I_H = int (dp/dtau)^2 dtau over the Hertz pulse = 1.8 alpha_m^2 B(4/5, 3/2)
 * (derivation in contact.c).  xi from anvil_radiation_xi(nu).  NaN for nu
 * outside (-1, 0.5). */
double anvil_contact_hunter_coef(double nu, double xi);

#endif
