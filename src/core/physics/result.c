#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "result.h"

void anvil_result_init(struct anvil_result *r, enum anvil_model model)
{
	memset(r, 0, sizeof *r);
	r->model = model;
	r->ts.err = r->tmax.err = r->Pmax.err = NAN;
	r->Vs.err = r->Rf.err = r->Ea.err = NAN;
	r->reach_p = r->reach_bend = NAN;
}

void anvil_result_reach(struct anvil_result *r, double h, double E, double nu, double rho, double c1)
{
	double t = r->ts.val;
	r->reach_p = r->reach_bend = NAN;
	if (!(t > 0) || !isfinite(t) || !(h > 0) || !isfinite(h))
		return;
	double beta = h * sqrt(E / (12.0 * rho * (1.0 - nu * nu)));
	r->reach_p = c1 * t;
	r->reach_bend = 2.0 * sqrt(beta * t);
}

int anvil_history_alloc(struct anvil_history *h, size_t n)
{
	/* One block for the six arrays: one owner, one free. */
	double *block = calloc(6 * (n ? n : 1), sizeof *block);
	if (!block)
		return ANVIL_ENOMEM;
	free(h->t);
	h->n = n;
	h->t = block;
	h->P = block + n;
	h->v = block + 2 * n;
	h->W = block + 3 * n;
	h->w = block + 4 * n;
	h->alpha = block + 5 * n;
	return ANVIL_OK;
}

void anvil_result_free(struct anvil_result *r)
{
	if (!r)
		return;
	free(r->hist.t);
	memset(&r->hist, 0, sizeof r->hist);
}
