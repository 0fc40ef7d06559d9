/* hertz.h: quasi-static Hertz impact on a rigid-backed layer (w = 0).
 *
 * Dimensionless form (tau = t/T, alpha = alpha_H/(T V0)):
 *   alpha'' = -alpha^(3/2), alpha(0) = 0, alpha'(0) = 1,
 * whose contact time is tau_s = 2 (5/4)^(2/5) (2/5) B(2/5, 1/2) = 3.21807
 * (Johnson 1985, sec. 11.4) and peak compression alpha_max = (5/4)^(2/5). */
#ifndef ANVIL_HERTZ_H
#define ANVIL_HERTZ_H

#include "params.h"
#include "result.h"

/* tau_s, computed from the beta function (not a rounded constant). */
double anvil_hertz_tau_s(void);
/* (5/4)^(2/5). */
double anvil_hertz_alpha_max(void);

/* The model `hertz`: closed-form t_s, t_max = t_s/2, P_max, V_s = V0, R_f = 1,
 * E_a = 0; with nhist > 0 also the histories (from the ODE with lambda* = 0).
 * r must have been anvil_result_init'ed; returns ANVIL_OK, ANVIL_ENOMEM or
 * ANVIL_ENUM. */
int anvil_hertz_run(const struct anvil_params *p, size_t nhist,
		    struct anvil_result *r, struct anvil_err *err);

#endif
