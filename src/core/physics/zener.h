/* zener.h: Zener's impact on a thin infinite plate, eqs (48)-(54).
 *
 *   alpha'' + alpha^(3/2) + (3/2) lambda* alpha^(1/2) alpha' = 0,
 *   alpha(0) = 0, alpha'(0) = 1   (tau = t/T, alpha = alpha_H/(T V0))
 *
 * solved with GSL odeiv2 (adaptive, error-controlled); the end of contact
 * (alpha back to 0) is located by root finding on the dense output, not by
 * the nearest step. */
#ifndef ANVIL_ZENER_H
#define ANVIL_ZENER_H

#include "params.h"
#include "result.h"

/* Dimensionless solution for one lambda*. */
struct anvil_zener_sol {
	double tau_s;      /* contact time / T */
	double tau_max;    /* time of peak force / T */
	double alpha_max;  /* peak compression / (T V0); P_max = K (T V0 alpha_max)^(3/2) */
	double rf;         /* rebound speed / V0 = -v(tau_s)/V0 */
	double err;        /* estimated absolute error of the values above (the largest) */
	double err_ts, err_tmax, err_amax, err_rf; /* each one's own */
};

/* From this lambda* on, anvil_zener_solve and anvil_zener_run answer with
 * the dashpot limit (anvil_zener_dashpot): the ODE's error estimate there
 * (relative 1e-7 in t_s at tol 1e-10) exceeds the limit's remainder
 * (3e-10), and past about 1e8.5 the stiff stepper's step falls to tau's
 * rounding (a 1 nm plate: lambda* = 1e13). */
#define ANVIL_ZENER_DASHPOT 1e6

/* Solve the ODE to relative tolerance tol (1e-10 is cheap; about 1 ms at
 * lambda* = 1e4, where the contact lasts 4.6e5 T).  lambda* >= 0; tested
 * up to 1e6, and the dashpot limit from ANVIL_ZENER_DASHPOT on (its
 * errors, stated in sol, do not follow tol).  Past lambda* = 30 the stiff
 * BDF stepper is used.  R_f >= 0:
 * at the end of contact the plate's centre is at rest (its velocity is
 * lambda* P, eq (51)), so alpha' = u there and contact ends only with
 * u <= 0; a rounding below 0 is clipped (its error estimate covers it).
 * No repeated contact: after the end the plate stays at rest, the
 * impactor moves away. 
 * ANVIL_EINVAL for a bad argument, ANVIL_ENUM if the integrator fails. */
int anvil_zener_solve(double lambda_star, double tol,
		      struct anvil_zener_sol *sol, struct anvil_err *err);

/* The limit lambda* -> inf (zener_dashpot.c: derivation): the plate is a
 * dashpot Z = 1/alpha* (P_max -> Z V0) and the impactor slows like
 * exp(-tau/lambda*), with eps = lambda*^(-5/3), s_max = (10/9) ln lambda*
 * + 0.764323 (closed form):
 *   tau_max = lambda*^(-2/3) s_max,  alpha_max = lambda*^(-2/3) (1 - (2/3) eps (s_max - 1)),
 *   tau_s = lambda* (5 ln lambda* - 0.359367056 + 3 eps),  rf = 0.679293064 lambda*^-5;
 * each error in sol covers the remainder (relative ~ eps^2, eps s_max^2 in
 * tau_max) and the two constants' uncertainty (3e-8 in tau_s / lambda*).
 * lambda* >= 100, else ANVIL_EINVAL. */
int anvil_zener_dashpot(double lambda_star, struct anvil_zener_sol *sol, struct anvil_err *err);

/* The limit's histories for sol = anvil_zener_dashpot(p->lambda_star) at
 * hist->n times (as anvil_zener_run's): the rise and the slow decay
 * composed, relative O(eps s_max) but in the contact's last few
 * lambda* T, where the force is below lambda*^-5 Z V0 e^3.  ANVIL_ENOMEM,
 * ANVIL_ENUM (the rise's root not found). */
int anvil_zener_dashpot_history(const struct anvil_params *p, const struct anvil_zener_sol *sol,
				struct anvil_history *hist);

/* exp(-1.7191 lambda*), Zener's fit (54). */
double anvil_zener_rf_fit(double lambda_star);

/* The model `zener` for the scene's parameters: t_s, t_max, P_max, V_s, R_f,
 * E_a and, with nhist > 0, the histories (w is the plate deflection w*,
 * eq (8)).  A half-space (alpha* = 0) gives the Hertz values; lambda* >=
 * ANVIL_ZENER_DASHPOT the dashpot limit, which the row's note says. */
int anvil_zener_run(const struct anvil_params *p, size_t nhist,
		    struct anvil_result *r, struct anvil_err *err);

#endif
