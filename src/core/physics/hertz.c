#include <float.h>
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_sf_gamma.h>

#include "hertz.h"
#include "zener.h"

/* alpha_max^(5/2) = 5/4: energy alpha'^2/2 + (2/5) alpha^(5/2) = 1/2. */
#define HERTZ_AMAX_POW 1.25
/* Relative error of the closed forms: a few rounding errors in pow and
 * gsl_sf_beta. */
#define HERTZ_REL_ERR (8 * DBL_EPSILON)

double anvil_hertz_alpha_max(void)
{
	return pow(HERTZ_AMAX_POW, 0.4);
}

/* tau_s = 2 alpha_max int_0^1 dx / sqrt(1 - x^(5/2)) = 2 alpha_max (2/5) B(2/5, 1/2)
 * = 3.21807 (Johnson 1985, sec. 11.4). */
double anvil_hertz_tau_s(void)
{
	return 2.0 * anvil_hertz_alpha_max() * 0.4 * gsl_sf_beta(0.4, 0.5);
}

static void hertz_fill(const struct anvil_params *p, struct anvil_result *r)
{
	r->ts.val = anvil_hertz_tau_s() * p->T;
	r->tmax.val = 0.5 * r->ts.val;
	r->Pmax.val = p->K * pow(anvil_hertz_alpha_max() * p->T * p->V0, 1.5);
	r->Vs.val = p->V0;
	r->Rf.val = 1.0;
	r->Ea.val = 0.0;
	r->ts.err = HERTZ_REL_ERR * r->ts.val;
	r->tmax.err = HERTZ_REL_ERR * r->tmax.val;
	r->Pmax.err = HERTZ_REL_ERR * r->Pmax.val;
	/* Exact in this model. */
	r->Vs.err = r->Rf.err = r->Ea.err = 0.0;
	r->lambda_star = p->lambda_star;
	r->Rf_star = p->Rf_star;
	/* one contact on a rigid layer, with or without the histories (the
	 * column read nan without them, 1 with: qa5) */
	r->ncontacts = 1;
	r->contact_on[0] = 0.0;
	r->contact_off[0] = r->t_free = r->ts.val;
	snprintf(r->note, sizeof r->note, "layer taken as rigid (w = 0)");
}

int anvil_hertz_run(const struct anvil_params *p, size_t nhist,
		    struct anvil_result *r, struct anvil_err *err)
{
	if (!p || !r)
		return anvil_err_set(err, ANVIL_EINVAL, "hertz: no parameters or result");
	if (!(p->T > 0 && isfinite(p->T) && p->K > 0 && isfinite(p->K) && p->V0 > 0))
		return anvil_err_set(err, ANVIL_EINVAL, "hertz: no finite Hertz time scale");
	if (nhist) {
		/* The histories are Zener's with no plate term. */
		struct anvil_params rigid = *p;
		rigid.alpha_star = 0.0;
		rigid.lambda_star = 0.0;
		int st = anvil_zener_run(&rigid, nhist, r, err);
		if (st)
			return st;
		for (size_t i = 0; i < r->hist.n; i++) {
			r->hist.W[i] = r->hist.alpha[i];
			r->hist.w[i] = 0.0;
		}
	}
	hertz_fill(p, r);
	if (!(isfinite(r->ts.val) && isfinite(r->Pmax.val)))
		return anvil_err_set(err, ANVIL_ENUM, "hertz: closed form not finite");
	return ANVIL_OK;
}
