/* params.h: the physical parameters of one impact, derived once from a scene.
 *
 * All SI.  Formulas: Hertz (39), Zener's plate compliance (8) with the
 * half-thickness h* = h/2, the time scale T and lambda* (53), the
 * super-seismic parameter alpha_A (section 4). */
#ifndef ANVIL_PARAMS_H
#define ANVIL_PARAMS_H

#include "scene.h"
#include "status.h"

struct anvil_params {
	double m1, r0, V0;         /* impactor mass, radius, velocity */
	double E1, nu1, rho1;      /* impactor material */
	double E, nu, rho;         /* layer material */
	double lambda, mu, c1, c2, cR; /* layer: Lame constants, wave speeds */
	double h;                  /* layer thickness, INFINITY for half-space */
	double Estar;              /* 1/E* = (1-nu1^2)/E1 + (1-nu^2)/E */
	double K, k0;              /* P = K alpha^(3/2), K = 4 E* sqrt(r0)/3, k0 = K^(-2/3) */
	double T;                  /* m1^(2/5) V0^(-1/5) K^(-2/5) */
	double alpha_star;         /* eq (8), s/kg; 0 for a half-space */
	double lambda_star;        /* eq (53) */
	double Rf_star;            /* exp(-1.7191 lambda*), eq (54) */
	double alpha_A;            /* (pi rho r0^3/m1)^(1/2) (V0/c1)^(3/2) */
};

/* Fill p from a checked scene.  ANVIL_EINVAL if the scene is not physical. */
int anvil_params_init(struct anvil_params *p, const struct anvil_scene *sc,
		      struct anvil_err *err);

#endif
