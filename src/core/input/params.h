/* params.h: the physical parameters of one impact, derived once.
 *
 * All SI.  Formulas: Hertz (39), Zener's plate compliance (8) with the
 * half-thickness h* = h/2, the time scale T and lambda* (53), the
 * super-seismic parameter alpha_A (section 4).  A scene becomes params in
 * problem.h (anvil_problem_init); this header knows no scene. */
#ifndef ANVIL_PARAMS_H
#define ANVIL_PARAMS_H

#include "material.h"
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

/* Fill p for an impactor of mass m1, radius r0 and material imp striking
 * at V0 a layer of thickness h (INFINITY: a half-space) of material lay,
 * both materials checked (anvil_material_check).  ANVIL_EINVAL, naming
 * the input key ("layer.rho"), when an input is not positive or a derived
 * value (wave speeds, T, lambda*, alpha_A, ...) is not finite: inputs near
 * the limits of a double overflow here, long before any solver runs. */
int anvil_params_init(struct anvil_params *p, double m1, double r0, double V0, double h,
		      const struct anvil_material *imp, const struct anvil_material *lay,
		      struct anvil_err *err);

#endif
