#include <math.h>
#include <stddef.h>

#include "params.h"

/* Zener's fit of the restitution coefficient, eq (54). */
#define ZENER_RF_SLOPE 1.7191

struct input {
	const char *key;
	double v;
};

/* The input that sends a derived value out of the doubles: the one
 * farthest from 1 in SI on a log scale.  Every quantity here is a product
 * of powers of the inputs, so an overflow (1e308 kg/m^3) or underflow
 * comes from the extreme one. */
static const char *culprit(const struct input *in, size_t n)
{
	size_t worst = 0;
	for (size_t i = 1; i < n; i++)
		if (fabs(log10(in[i].v)) > fabs(log10(in[worst].v)))
			worst = i;
	return in[worst].key;
}

static void derive(struct anvil_params *p)
{
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
}

int anvil_params_init(struct anvil_params *p, double m1, double r0, double V0, double h,
		      const struct anvil_material *imp, const struct anvil_material *lay,
		      struct anvil_err *err)
{
	const struct input in[] = {
		{ "impactor.mass", m1 }, { "impactor.radius", r0 }, { "impact.velocity", V0 },
		{ "layer.thickness", isinf(h) ? 1.0 : h }, { "impactor.E", imp->E },
		{ "impactor.rho", imp->rho }, { "layer.E", lay->E }, { "layer.rho", lay->rho },
	};
	const size_t n = sizeof in / sizeof in[0];
	for (size_t i = 0; i < n; i++)
		if (!(in[i].v > 0 && isfinite(in[i].v)))
			return anvil_err_set(err, ANVIL_EINVAL, "%s: must be finite and > 0, got %g",
					     in[i].key, in[i].v);
	*p = (struct anvil_params){ .m1 = m1, .r0 = r0, .V0 = V0, .h = h, .E1 = imp->E,
				    .nu1 = imp->nu, .rho1 = imp->rho, .E = lay->E,
				    .nu = lay->nu, .rho = lay->rho };
	p->lambda = anvil_material_lambda(lay);
	p->mu = anvil_material_mu(lay);
	p->c1 = anvil_material_c1(lay);
	p->c2 = anvil_material_c2(lay);
	p->cR = anvil_material_cr(lay);
	derive(p);
	const struct {
		const char *name;
		double v;
	} out[] = {
		{ "c1", p->c1 }, { "c2", p->c2 }, { "c_R", p->cR }, { "E*", p->Estar },
		{ "K", p->K }, { "T", p->T }, { "k0", p->k0 }, { "lambda*", p->lambda_star },
		{ "alpha*", p->alpha_star }, { "alpha_A", p->alpha_A },
	};
	for (size_t i = 0; i < sizeof out / sizeof out[0]; i++)
		if (!isfinite(out[i].v) || (i < 7 && !(out[i].v > 0)))
			return anvil_err_set(err, ANVIL_EINVAL,
					     "%s: out of range: it gives %s = %g, not finite and positive",
					     culprit(in, n), out[i].name, out[i].v);
	return ANVIL_OK;
}
