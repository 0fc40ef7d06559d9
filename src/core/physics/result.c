#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <gsl/gsl_roots.h>

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

static double warp_eq(double beta, void *q)
{
	return beta / sinh(beta) - *(double *)q;
}

/* beta / sinh(beta) = q: the first interval t_s beta / sinh(beta) / (n - 1)
 * is ANVIL_HISTORY_RISE t_pk / (n - 1).  Brent on [1e-3, 60] (q at 60 is
 * 1e-24: any contact shorter than the age of the universe in ns), which
 * brackets the root for every q < 0.4 (the warp's range): GSL raises no
 * error here, and its global handler is left alone (the physical row's
 * impacts run on threads). */
double anvil_history_warp(double t_pk, double ts)
{
	if (!(t_pk > 0) || !(ts > ANVIL_HISTORY_WARP_AT * t_pk) || !isfinite(ts))
		return 0.0;
	double q = ANVIL_HISTORY_RISE * t_pk / ts, lo = 1e-3, hi = 60.0, beta = hi;
	if (warp_eq(hi, &q) >= 0)
		return hi;
	gsl_function f = { warp_eq, &q };
	gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	if (rs && gsl_root_fsolver_set(rs, &f, lo, hi) == GSL_SUCCESS)
		for (int it = 0; it < 100; it++) {
			if (gsl_root_fsolver_iterate(rs) != GSL_SUCCESS)
				break;
			beta = gsl_root_fsolver_root(rs);
			lo = gsl_root_fsolver_x_lower(rs);
			hi = gsl_root_fsolver_x_upper(rs);
			if (gsl_root_test_interval(lo, hi, 0, 1e-12) == GSL_SUCCESS)
				break;
		}
	gsl_root_fsolver_free(rs);
	return beta;
}

double anvil_history_time(size_t i, size_t n, double ts, double beta)
{
	if (n < 2)
		return 0.0;
	if (i + 1 >= n)
		return ts;
	if (!(beta > 0)) /* as the even histories always were, to the bit */
		return ts * (double)i / (double)(n - 1);
	return ts * sinh(beta * ((double)i / (double)(n - 1))) / sinh(beta);
}

double anvil_history_at(const struct anvil_history *h, const double *y, double t)
{
	size_t n = h->n;
	if (n < 2 || !(t >= h->t[0]) || t > h->t[n - 1])
		return 0.0;
	size_t lo = gsl_interp_bsearch(h->t, t, 0, n - 1);
	if (lo + 1 >= n)
		return y[n - 1];
	double d = h->t[lo + 1] - h->t[lo];
	return d > 0 ? y[lo] + (t - h->t[lo]) / d * (y[lo + 1] - y[lo]) : y[lo];
}
