#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include "zener.h"

/* Zener's fit of the restitution coefficient, eq (54). */
#define ZENER_RF_SLOPE 1.7191
/* anvil_zener_run's relative tolerance: 1e-10 costs well under a millisecond. */
#define ZENER_RUN_TOL 1e-10
/* The error estimate compares with a solve at ZENER_COARSE times the tolerance. */
#define ZENER_COARSE 100.0
/* Accepted tolerances: tighter than TOL_MIN rk8pd cannot deliver in double;
 * the coarse solve at TOL_MAX * ZENER_COARSE must still resolve the impact. */
#define ZENER_TOL_MIN 1e-14
#define ZENER_TOL_MAX 1e-4
#define ZENER_H0 1e-3          /* first step, in tau (tau_s is 3.2 at lambda* = 0) */
#define ZENER_NMAX 1000000     /* steps before giving up */
#define ZENER_ROOT_ITER 200    /* Brent iterations before giving up */
/* Contact lasts 3.2 at lambda* = 0, 112 at 10, 8448 at 300; past
 * ZENER_TAU_END (1 + lambda*) it is taken not to end.  For lambda* > ~30 the
 * impactor practically stops (R_f < 1e-8) and alpha creeps to 0 below the
 * absolute tolerance: t_s becomes ill-conditioned, and at ~1000 not found. */
#define ZENER_TAU_END 1000.0
/* The absolute error floor, relative to the tolerance: below every scale
 * the solution reaches up to lambda* = 1e4 (u ~ 1e-20 there). */
#define ZENER_ABS_FLOOR 1e-40
/* lambda* above which the stiff stepper is used (rk8pd below: unchanged
 * results where it is fast; at 30 both take a few thousand steps). */
#define ZENER_STIFF 30.0

/* State: alpha, alpha', v/V0, W/(T V0). */
enum { Y_A, Y_DA, Y_V, Y_W, Y_DIM };

/* Workspace for one solve: allocated once, freed by zener_ws_free. */
struct zener_ws {
	double lambda, tol;
	gsl_odeiv2_system sys;
	gsl_odeiv2_driver *march; /* the accepted steps, through its evolve */
	gsl_odeiv2_driver *probe; /* re-integrates from (t0, y0) inside a step */
	gsl_root_fsolver *root;
	double t0, y0[Y_DIM];     /* start of the step being probed */
	double y[Y_DIM];          /* the probe's result */
	int comp, status;         /* probed component; first probe failure */
	const char *why;          /* what stopped the march, for the message */
};

/* Eq (51) plus the impactor: m1 dv/dt = -P with K T^(5/2) V0^(3/2) / m1 = V0
 * gives (v/V0)' = -alpha^(3/2).  alpha < 0 (past the end of contact, probed
 * by the stepper) means no contact force. */
static int zener_rhs(double t, const double y[], double f[], void *params)
{
	const double lambda = *(const double *)params;
	double s = sqrt(fmax(y[Y_A], 0.0));
	double a32 = s * s * s;
	(void)t;
	f[Y_A] = y[Y_DA];
	f[Y_DA] = -a32 - 1.5 * lambda * s * y[Y_DA];
	f[Y_V] = -a32;
	f[Y_W] = y[Y_V];
	return GSL_SUCCESS;
}

/* The Jacobian, for the stiff stepper.  d sqrt(alpha)/d alpha is infinite
 * at alpha = 0: taken at alpha >= ZENER_JAC_MIN (a Jacobian only steers
 * the Newton iteration of an implicit method, not its accuracy). */
#define ZENER_JAC_MIN 1e-300
static int zener_jac(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
	const double lambda = *(const double *)params;
	double a = fmax(y[Y_A], 0.0), s = sqrt(a), ds = 0.5 / sqrt(fmax(a, ZENER_JAC_MIN));
	(void)t;
	memset(dfdy, 0, Y_DIM * Y_DIM * sizeof *dfdy);
	dfdy[Y_A * Y_DIM + Y_DA] = 1.0;
	dfdy[Y_DA * Y_DIM + Y_A] = a > 0 ? -1.5 * s - 1.5 * lambda * ds * y[Y_DA] : 0.0;
	dfdy[Y_DA * Y_DIM + Y_DA] = -1.5 * lambda * s;
	dfdy[Y_V * Y_DIM + Y_A] = -1.5 * s;
	dfdy[Y_W * Y_DIM + Y_V] = 1.0;
	memset(dfdt, 0, Y_DIM * sizeof *dfdt);
	return GSL_SUCCESS;
}

static void zener_ws_free(struct zener_ws *w)
{
	if (w->march)
		gsl_odeiv2_driver_free(w->march);
	if (w->probe)
		gsl_odeiv2_driver_free(w->probe);
	gsl_root_fsolver_free(w->root);
	w->march = w->probe = NULL;
	w->root = NULL;
}

/* w must stay where it is while in use: the drivers point at w->sys. */
static int zener_ws_init(struct zener_ws *w, double lambda)
{
	memset(w, 0, sizeof *w);
	w->lambda = lambda;
	w->sys = (gsl_odeiv2_system){ zener_rhs, zener_jac, Y_DIM, &w->lambda };
	/* past ZENER_STIFF the approach to the quasi-static balance
	 * alpha^(3/2) = u/lambda* is fast against the contact (rate ~ lambda*
	 * alpha^(1/2) against 1/lambda*): an explicit method would need ~10^8
	 * steps at lambda* = 1e4; GSL's BDF (msbdf) takes it in its stride */
	const gsl_odeiv2_step_type *T = lambda > ZENER_STIFF ? gsl_odeiv2_step_msbdf
							     : gsl_odeiv2_step_rk8pd;
	w->march = gsl_odeiv2_driver_alloc_y_new(&w->sys, T, ZENER_H0, ZENER_TOL_MAX, ZENER_TOL_MAX);
	w->probe = gsl_odeiv2_driver_alloc_y_new(&w->sys, T, ZENER_H0, ZENER_TOL_MAX, ZENER_TOL_MAX);
	w->root = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	if (!w->march || !w->probe || !w->root) {
		zener_ws_free(w);
		return ANVIL_ENOMEM;
	}
	gsl_odeiv2_driver_set_nmax(w->march, ZENER_NMAX);
	gsl_odeiv2_driver_set_nmax(w->probe, ZENER_NMAX);
	return ANVIL_OK;
}

/* Relative tolerance tol on every component, on |y| + h |y'| (GSL's
 * a_y = a_dydt = 1), with an absolute floor tol ZENER_ABS_FLOOR only.  An
 * absolute tolerance tol (all components start O(1)) fails at large
 * lambda*: the impactor then slows like exp(-tau/lambda*) and the contact
 * ends when u and alpha are ~lambda*^-5 and ~lambda*^-4 (1e-20, 1e-16 at
 * lambda* = 1e4: see zener_late), far below it. */
static int zener_ws_set_tol(struct zener_ws *w, double tol)
{
	w->tol = tol;
	int st = gsl_odeiv2_control_init(w->march->c, tol * ZENER_ABS_FLOOR, tol, 1.0, 1.0);
	if (!st)
		st = gsl_odeiv2_control_init(w->probe->c, tol * ZENER_ABS_FLOOR, tol, 1.0, 1.0);
	return st;
}

/* The state at tau >= t0, integrated afresh from (t0, y0) into w->y: as
 * accurate as the accepted steps anywhere inside a step, unlike an
 * interpolant. */
static int zener_probe(struct zener_ws *w, double tau)
{
	double t = w->t0;
	memcpy(w->y, w->y0, sizeof w->y);
	if (!(tau > t))
		return GSL_SUCCESS;
	/* GSL_ERROR_NULL in the driver returns 0 for bad limits: checked above. */
	int st = gsl_odeiv2_driver_reset_hstart(w->probe, tau - t);
	if (!st)
		st = gsl_odeiv2_driver_apply(w->probe, &t, tau, w->y);
	return st;
}

static double zener_probe_f(double tau, void *vp)
{
	struct zener_ws *w = vp;
	int st = zener_probe(w, tau);
	if (st) {
		if (!w->status)
			w->status = st;
		return NAN;
	}
	return w->y[w->comp];
}

static int zener_brent(struct zener_ws *w, double lo, double hi, double *tau)
{
	gsl_function F = { zener_probe_f, w };
	int st = gsl_root_fsolver_set(w->root, &F, lo, hi);
	for (int i = 0; !st && i < ZENER_ROOT_ITER; i++) {
		st = gsl_root_fsolver_iterate(w->root);
		if (st)
			break;
		lo = gsl_root_fsolver_x_lower(w->root);
		hi = gsl_root_fsolver_x_upper(w->root);
		st = gsl_root_test_interval(lo, hi, 0.01 * w->tol, 4 * DBL_EPSILON);
		if (st != GSL_CONTINUE)
			break;
		st = GSL_SUCCESS;
		if (i + 1 == ZENER_ROOT_ITER)
			st = GSL_EMAXITER;
	}
	if (w->status)
		return w->status;
	if (st)
		return st;
	*tau = gsl_root_fsolver_root(w->root);
	return GSL_SUCCESS;
}

/* The root of component comp inside the step (t0, t1], where the march saw
 * it change sign; the state there is left in w->y. */
static int zener_locate(struct zener_ws *w, int comp, double t1, double *tau)
{
	w->comp = comp;
	w->status = GSL_SUCCESS;
	double f0 = w->y0[comp], f1 = zener_probe_f(t1, w);
	if (w->status)
		return w->status;
	if (f0 == 0 || (f0 > 0) == (f1 > 0)) {
		/* The probe and the march disagree in the last digits about
		 * the sign at an end: the root is at that end, to tolerance. */
		*tau = f0 == 0 ? w->t0 : t1;
	} else {
		int st = zener_brent(w, w->t0, t1, tau);
		if (st)
			return st;
	}
	return zener_probe(w, *tau);
}

/* One solve at w->tol: accepted steps until alpha' and then alpha change
 * sign; the peak and the end of contact are located inside their steps. */
static int zener_march(struct zener_ws *w, struct anvil_zener_sol *sol)
{
	gsl_odeiv2_driver *d = w->march;
	double t = 0.0, h = ZENER_H0, y[Y_DIM] = { 0.0, 1.0, 1.0, 0.0 };
	double tend = ZENER_TAU_END * (1.0 + w->lambda);
	int have_max = 0, st = gsl_odeiv2_driver_reset(d);

	for (long n = 0; !st && n < ZENER_NMAX && t < tend; n++) {
		w->t0 = t;
		memcpy(w->y0, y, sizeof y);
		st = gsl_odeiv2_evolve_apply(d->e, d->c, d->s, &w->sys, &t, tend, &h, y);
		if (st == GSL_FAILURE)
			w->why = "the stepper's step fell below tau's rounding";
		if (!st && !have_max && y[Y_DA] <= 0) {
			st = zener_locate(w, Y_DA, t, &sol->tau_max);
			sol->alpha_max = w->y[Y_A];
			have_max = 1;
		}
		if (!st && y[Y_A] <= 0) {
			st = zener_locate(w, Y_A, t, &sol->tau_s);
			sol->rf = -w->y[Y_V];
			if (!st && !have_max)
				w->why = "contact ended before the peak";
			return st ? st : have_max ? GSL_SUCCESS : GSL_FAILURE;
		}
	}
	if (!st)
		w->why = t < tend ? "step limit reached" : "contact did not end";
	return st ? st : GSL_EMAXITER;
}

static double zener_sol_diff(const struct anvil_zener_sol *a,
			     const struct anvil_zener_sol *b)
{
	double d = fabs(a->tau_s - b->tau_s);
	d = fmax(d, fabs(a->tau_max - b->tau_max));
	d = fmax(d, fabs(a->alpha_max - b->alpha_max));
	return fmax(d, fabs(a->rf - b->rf));
}

/* Solve at tol * ZENER_COARSE, then at tol; err is their difference (an
 * estimate of the coarse error, so an upper estimate of the fine one), at
 * least tol.  The workspace is left at tol. */
static int zener_solve_ws(struct zener_ws *w, double tol, struct anvil_zener_sol *sol,
			  struct anvil_err *err)
{
	struct anvil_zener_sol coarse;
	int st = zener_ws_set_tol(w, tol * ZENER_COARSE);
	if (!st)
		st = zener_march(w, &coarse);
	if (!st)
		st = zener_ws_set_tol(w, tol);
	if (!st)
		st = zener_march(w, sol);
	if (st)
		return anvil_err_set(err, ANVIL_ENUM,
				     "zener: ODE solve failed at lambda* = %g, tol %g: %s",
				     w->lambda, w->tol, w->why ? w->why : gsl_strerror(st));
	sol->err = fmax(zener_sol_diff(sol, &coarse), tol);
	sol->err_ts = fmax(fabs(sol->tau_s - coarse.tau_s), tol * sol->tau_s);
	sol->err_tmax = fmax(fabs(sol->tau_max - coarse.tau_max), tol * sol->tau_max);
	sol->err_amax = fmax(fabs(sol->alpha_max - coarse.alpha_max), tol * sol->alpha_max);
	sol->err_rf = fmax(fabs(sol->rf - coarse.rf), tol);
	/* physics: R_f >= 0 (zener.h); the clip is within err_rf */
	sol->err_rf = fmax(sol->err_rf, -sol->rf);
	sol->rf = fmax(sol->rf, 0.0);
	return ANVIL_OK;
}

static int zener_check(double lambda_star, double tol, struct anvil_err *err)
{
	if (!(lambda_star >= 0 && isfinite(lambda_star)))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "zener: lambda* = %g, expected a finite number >= 0",
				     lambda_star);
	if (!(tol >= ZENER_TOL_MIN && tol <= ZENER_TOL_MAX))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "zener: tolerance %g, expected %g to %g", tol,
				     ZENER_TOL_MIN, ZENER_TOL_MAX);
	return ANVIL_OK;
}

int anvil_zener_solve(double lambda_star, double tol, struct anvil_zener_sol *sol,
		      struct anvil_err *err)
{
	struct zener_ws w;
	int st = zener_check(lambda_star, tol, err);
	if (st)
		return st;
	if (!sol)
		return anvil_err_set(err, ANVIL_EINVAL, "zener: no solution given");
	if (lambda_star >= ANVIL_ZENER_DASHPOT)
		return anvil_zener_dashpot(lambda_star, sol, err);
	st = zener_ws_init(&w, lambda_star);
	if (st)
		return anvil_err_set(err, st, "zener: out of memory");
	st = zener_solve_ws(&w, tol, sol, err);
	zener_ws_free(&w);
	return st;
}

double anvil_zener_rf_fit(double lambda_star)
{
	return exp(-ZENER_RF_SLOPE * lambda_star);
}

/* Histories at n tau in [0, tau_s] (evenly spaced unless the contact
 * outlasts its peak at tau_max many times: result.h), integrating from
 * one sample to the next at the workspace's tolerance. */
static int zener_history(struct zener_ws *w, const struct anvil_params *p,
			 double tau_s, double tau_max, struct anvil_history *hist)
{
	double beta = anvil_history_warp(tau_max, tau_s);
	double L = p->T * p->V0, t = 0.0, y[Y_DIM] = { 0.0, 1.0, 1.0, 0.0 };
	size_t n = hist->n;
	int st = gsl_odeiv2_driver_reset_hstart(w->probe, ZENER_H0);

	for (size_t i = 0; !st && i < n; i++) {
		double ti = anvil_history_time(i, n, tau_s, beta);
		if (ti > t)
			st = gsl_odeiv2_driver_apply(w->probe, &t, ti, y);
		double a = fmax(y[Y_A], 0.0);
		hist->t[i] = p->T * ti;
		hist->alpha[i] = L * y[Y_A];
		hist->P[i] = p->K * pow(L * a, 1.5);
		hist->v[i] = p->V0 * y[Y_V];
		hist->W[i] = L * y[Y_W];
		hist->w[i] = L * (y[Y_W] - y[Y_A]);
	}
	return st;
}

static void zener_fill(const struct anvil_params *p, const struct anvil_zener_sol *s,
		       struct anvil_result *r)
{
	double L = p->T * p->V0;
	r->ts.val = p->T * s->tau_s;
	r->tmax.val = p->T * s->tau_max;
	r->Pmax.val = p->K * pow(L * s->alpha_max, 1.5);
	r->Rf.val = s->rf;
	r->Vs.val = p->V0 * s->rf;
	r->Ea.val = 0.5 * p->m1 * (p->V0 * p->V0 - r->Vs.val * r->Vs.val);
	r->ts.err = p->T * s->err_ts;
	r->tmax.err = p->T * s->err_tmax;
	r->Pmax.err = 1.5 * r->Pmax.val * s->err_amax / s->alpha_max;
	r->Rf.err = s->err_rf;
	r->Vs.err = p->V0 * s->err_rf;
	r->ncontacts = 1;
	r->contact_off[0] = r->t_free = r->ts.val;
	r->Ea.err = p->m1 * (fabs(r->Vs.val) + r->Vs.err) * r->Vs.err;
	r->lambda_star = p->lambda_star;
	r->Rf_star = p->Rf_star;
}

static void zener_note(const struct anvil_params *p, struct anvil_result *r)
{
	if (p->lambda_star >= ANVIL_ZENER_DASHPOT)
		snprintf(r->note, sizeof r->note,
			 "dashpot limit (lambda* = %.3g): the plate is a dashpot 1/alpha* to the impactor, P_max -> 1/alpha* V0, the impactor stops like exp(-t/(lambda* T)); the limit's remainder (below 1e-9 relative from lambda* = 1e6) is in the +-",
			 p->lambda_star);
	else if (isinf(p->h) || p->alpha_star == 0)
		snprintf(r->note, sizeof r->note,
			 "half-space: no plate term, the Hertz solution");
	else if (p->h > p->r0)
		snprintf(r->note, sizeof r->note,
			 "thin-plate theory; h/r0 = %.4g is thick for it", p->h / p->r0);
	else
		r->note[0] = '\0';
}

/* anvil_zener_run past ANVIL_ZENER_DASHPOT: the limit, no ODE. */
static int zener_run_dashpot(const struct anvil_params *p, size_t nhist,
			     struct anvil_result *r, struct anvil_err *err)
{
	struct anvil_zener_sol sol;
	int st = anvil_zener_dashpot(p->lambda_star, &sol, err);
	if (st)
		return st;
	zener_fill(p, &sol, r);
	zener_note(p, r);
	if (!nhist)
		return ANVIL_OK;
	st = anvil_history_alloc(&r->hist, nhist);
	if (st)
		return anvil_err_set(err, st, "zener: out of memory for %zu samples", nhist);
	st = anvil_zener_dashpot_history(p, &sol, &r->hist);
	if (st)
		return anvil_err_set(err, st, "zener: the dashpot limit's history failed: %s",
				     anvil_strerror(st));
	return ANVIL_OK;
}

int anvil_zener_run(const struct anvil_params *p, size_t nhist,
		    struct anvil_result *r, struct anvil_err *err)
{
	struct zener_ws w;
	struct anvil_zener_sol sol;
	if (!p || !r)
		return anvil_err_set(err, ANVIL_EINVAL, "zener: no parameters or result");
	int st = zener_check(p->lambda_star, ZENER_RUN_TOL, err);
	if (st)
		return st;
	if (!(p->T > 0 && isfinite(p->T) && p->K > 0 && p->V0 > 0 && p->m1 > 0))
		return anvil_err_set(err, ANVIL_EINVAL, "zener: no finite Hertz time scale");
	if (p->lambda_star >= ANVIL_ZENER_DASHPOT)
		return zener_run_dashpot(p, nhist, r, err);
	st = zener_ws_init(&w, p->lambda_star);
	if (st)
		return anvil_err_set(err, st, "zener: out of memory");
	st = zener_solve_ws(&w, ZENER_RUN_TOL, &sol, err);
	if (st)
		goto out;
	zener_fill(p, &sol, r);
	zener_note(p, r);
	if (nhist) {
		st = anvil_history_alloc(&r->hist, nhist);
		if (st) {
			st = anvil_err_set(err, st, "zener: out of memory for %zu samples", nhist);
			goto out;
		}
		st = zener_history(&w, p, sol.tau_s, sol.tau_max, &r->hist);
		if (st)
			st = anvil_err_set(err, ANVIL_ENUM, "zener: history failed: %s",
					   gsl_strerror(st));
	}
out:
	zener_ws_free(&w);
	return st;
}
