#include <math.h>

#include "params.h"

/* Zener's fit of the restitution coefficient, eq (54). */
#define ZENER_RF_SLOPE 1.7191

int anvil_params_init(struct anvil_params *p, const struct anvil_scene *sc,
		      struct anvil_err *err)
{
	int st = anvil_scene_check(sc, err);
	if (st)
		return st;
	const struct anvil_material *imp = &sc->impactor.mat, *lay = &sc->layer.mat;
	p->m1 = sc->mass;
	p->r0 = sc->radius;
	p->V0 = sc->velocity;
	p->E1 = imp->E;
	p->nu1 = imp->nu;
	p->rho1 = imp->rho;
	p->E = lay->E;
	p->nu = lay->nu;
	p->rho = lay->rho;
	p->lambda = anvil_material_lambda(lay);
	p->mu = anvil_material_mu(lay);
	p->c1 = anvil_material_c1(lay);
	p->c2 = anvil_material_c2(lay);
	p->cR = anvil_material_cr(lay);
	p->h = anvil_scene_h(sc);
	p->Estar = 1.0 / ((1 - p->nu1 * p->nu1) / p->E1 + (1 - p->nu * p->nu) / p->E);
	p->K = 4.0 * p->Estar * sqrt(p->r0) / 3.0;
	p->k0 = pow(p->K, -2.0 / 3.0);
	p->T = pow(p->m1, 0.4) * pow(p->V0, -0.2) * pow(p->K, -0.4);
	if (isinf(p->h)) {
		p->alpha_star = 0.0;
	} else {
		/* Eq (8) with the half-thickness h* = h/2 (notes.md). */
		double hs = 0.5 * p->h;
		p->alpha_star = sqrt(3.0 * p->rho * (1 - p->nu * p->nu) / p->E) /
				(16.0 * p->rho * hs * hs);
	}
	p->lambda_star = p->alpha_star * p->K * sqrt(p->V0) * pow(p->T, 1.5);
	p->Rf_star = exp(-ZENER_RF_SLOPE * p->lambda_star);
	p->alpha_A = sqrt(M_PI * p->rho * pow(p->r0, 3) / p->m1) * pow(p->V0 / p->c1, 1.5);
	if (!(p->K > 0 && p->T > 0 && isfinite(p->T)))
		return anvil_err_set(err, ANVIL_EINVAL, "scene gives no finite Hertz time scale");
	return ANVIL_OK;
}
