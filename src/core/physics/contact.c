/* contact.c: the physical contact model on a half-space (see contact.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_gamma.h>

#include "contact.h"
#include "hertz.h"

/* The model is not a small correction beyond this eps (f ~ 3.8 eps). */
#define CONTACT_EPS_MAX 0.05
/* No contact of this model lasts past this tau: Hertz's is 3.218 and the
 * loss shortens it (with eps <= 0.05 it stays below 3.3). */
#define CONTACT_TAU_END 20.0
#define CONTACT_NMAX 1000000
#define Y_DIM 5 /* x, u, J2 = int p'^2, JQ = int p' q, JS = int p' sigma */

struct work {
	double eps;
	double cu, cx; /* the second order (contact.h), in these units */
	gsl_odeiv2_system sys, hsys;
	gsl_odeiv2_driver *march, *probe, *henon;
	double y[Y_DIM + 1]; /* scratch for the probe and Henon's step */
};

/* The state's derived quantities: s = a^(1/2), p = a^(3/2), p' = dp/dtau,
 * q = (3/2) a^(1/2) u (the zeroth-order p') and sigma, the second order
 * c_u u^2 - c_x a p (contact.h).  With X = x - c_u u^2,
 *   a - c s - c_x s^5 = X,  c = 1.5 eps u;
 * differentiating (x' = u, u' = -p), s' (2s - c - 5 c_x s^4) = u + 2 c_u
 * u p - 1.5 eps p s, and a' = 2 s s' stays finite as a -> 0 at the end
 * (2s - c = sqrt(c^2 + 4X) > 0 there).  First order (c_x = 0): the
 * quadratic's root; else Newton from it (c_x s^3 = O(f^2)). */
struct state {
	double s, p, dp, q, sig;
};

static struct state derive(const struct work *w, double x, double u)
{
	struct state z = { 0, 0, 0, 0, 0 };
	double eps = w->eps, c = 1.5 * eps * u, X = x - w->cu * u * u, disc = c * c + 4.0 * X;
	if (X < 0 || disc < 0) /* before the start or beyond the end */
		return z;
	double r = sqrt(disc), s = fmax(0.0, 0.5 * (c + r));
	for (int i = 0; i < 50 && w->cx != 0 && s > 0; i++) {
		double s4 = s * s * s * s, ds = (s * s - c * s - w->cx * s4 * s - X) /
						(2.0 * s - c - 5.0 * w->cx * s4);
		s -= ds;
		if (fabs(ds) <= 1e-16 * s)
			break;
	}
	z.s = fmax(0.0, s);
	z.p = z.s * z.s * z.s;
	double den = w->cx != 0 ? 2.0 * z.s - c - 5.0 * w->cx * z.p * z.s : r;
	double ds = den > 0 ? (u + 2.0 * w->cu * u * z.p - 1.5 * eps * z.p * z.s) / den : 0.0;
	z.dp = 3.0 * z.s * z.s * ds;
	z.q = 1.5 * z.s * u;
	z.sig = w->cu * u * u - w->cx * z.s * z.s * z.p;
	return z;
}

static int rhs(double t, const double y[], double f[], void *vw)
{
	const struct work *w = vw;
	struct state z = derive(w, y[0], y[1]);
	(void)t;
	f[0] = y[1];
	f[1] = -z.p;
	f[2] = z.dp * z.dp;
	f[3] = z.dp * z.q;
	f[4] = z.dp * z.sig;
	return GSL_SUCCESS;
}

/* Henon's trick for the end of contact: -X = c_u u^2 - x as the
 * independent variable (increasing to 0; the contact ends at X = 0, where
 * a = 0), y = (tau, u, J2, JQ, JS); u < 0 there, and dX/dtau = u (1 + 2
 * c_u p) < 0. */
static int rhs_henon(double mX, const double y[], double f[], void *vw)
{
	const struct work *w = vw;
	double g[Y_DIM], yy[Y_DIM] = { w->cu * y[1] * y[1] - mX, y[1], y[2], y[3], y[4] };
	rhs(y[0], yy, g, vw);
	double dx = -1.0 / (y[1] * (1.0 + 2.0 * w->cu * (-g[1]))); /* d tau / d(-X) */
	f[0] = dx;
	for (int i = 1; i < Y_DIM; i++)
		f[i] = g[i] * dx;
	return GSL_SUCCESS;
}

static void work_free(struct work *w)
{
	gsl_odeiv2_driver_free(w->march);
	gsl_odeiv2_driver_free(w->probe);
	gsl_odeiv2_driver_free(w->henon);
	memset(w, 0, sizeof *w);
}

/* w must stay where it is while in use: the drivers point at w->sys. */
static int work_init(struct work *w, double eps, double cu, double cx, double tol)
{
	memset(w, 0, sizeof *w);
	w->eps = eps;
	w->cu = cu;
	w->cx = cx;
	w->sys = (gsl_odeiv2_system){ rhs, NULL, Y_DIM, w };
	w->hsys = (gsl_odeiv2_system){ rhs_henon, NULL, Y_DIM, w };
	w->march = gsl_odeiv2_driver_alloc_y_new(&w->sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
	w->probe = gsl_odeiv2_driver_alloc_y_new(&w->sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
	w->henon = gsl_odeiv2_driver_alloc_y_new(&w->hsys, gsl_odeiv2_step_rk8pd, 1e-4, tol, tol);
	if (!w->march || !w->probe || !w->henon) {
		work_free(w);
		return ANVIL_ENOMEM;
	}
	gsl_odeiv2_driver_set_nmax(w->march, CONTACT_NMAX);
	gsl_odeiv2_driver_set_nmax(w->probe, CONTACT_NMAX);
	gsl_odeiv2_driver_set_nmax(w->henon, CONTACT_NMAX);
	return ANVIL_OK;
}

/* The dimensionless solution. */
struct sol {
	double tau_s, tau_m, p_m, u_end, J2, JQ, JS;
	double tau_on, B_on; /* the contact's start and the loss's term from it */
};

/* y at tau, integrated from (t0, y0) by the probe driver into w->y. */
static int probe(struct work *w, double t0, const double *y0, double tau)
{
	memcpy(w->y, y0, Y_DIM * sizeof *y0);
	if (!(tau > t0))
		return ANVIL_OK;
	double t = t0;
	int st = gsl_odeiv2_driver_reset_hstart(w->probe, tau - t0);
	if (!st)
		st = gsl_odeiv2_driver_apply(w->probe, &t, tau, w->y);
	return st ? ANVIL_ENUM : ANVIL_OK;
}

struct peak_ctx {
	struct work *w;
	double t0;
	const double *y0;
	int st;
};

static double dp_at(double tau, void *vc)
{
	struct peak_ctx *c = vc;
	c->st |= probe(c->w, c->t0, c->y0, tau);
	return derive(c->w, c->w->y[0], c->w->y[1]).dp;
}

/* The peak force: p' = 0 in (t0, t1), bracketed by a sign change; Brent. */
static int find_peak(struct work *w, double t0, const double *y0, double t1, double tol,
		     struct sol *s)
{
	struct peak_ctx c = { w, t0, y0, 0 };
	gsl_function f = { dp_at, &c };
	gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	if (!rs)
		return ANVIL_ENOMEM;
	int st = gsl_root_fsolver_set(rs, &f, t0, t1);
	double lo = t0, hi = t1;
	for (int i = 0; !st && i < 200; i++) {
		st = gsl_root_fsolver_iterate(rs);
		lo = gsl_root_fsolver_x_lower(rs);
		hi = gsl_root_fsolver_x_upper(rs);
		if (!st && gsl_root_test_interval(lo, hi, 0.0, tol) == GSL_SUCCESS)
			break;
	}
	s->tau_m = 0.5 * (lo + hi);
	gsl_root_fsolver_free(rs);
	st |= c.st | probe(w, t0, y0, s->tau_m);
	s->p_m = derive(w, w->y[0], w->y[1]).p;
	return st ? ANVIL_ENUM : ANVIL_OK;
}

/* The end of contact: from (t0, y0) with X > 0, u < 0, integrate in -X to 0. */
static int find_end(struct work *w, double t0, const double *y0, struct sol *s)
{
	double X = y0[0] - w->cu * y0[1] * y0[1], mX = -X;
	double yh[Y_DIM] = { t0, y0[1], y0[2], y0[3], y0[4] };
	int st = gsl_odeiv2_driver_reset_hstart(w->henon, fmin(1e-4, 0.5 * X));
	if (!st && mX < 0)
		st = gsl_odeiv2_driver_apply(w->henon, &mX, 0.0, yh);
	s->tau_s = yh[0];
	s->u_end = yh[1];
	s->J2 = yh[2];
	s->JQ = yh[3];
	s->JS = yh[4];
	return st ? ANVIL_ENUM : ANVIL_OK;
}

/* The free flight to the start, exact: x = tau, u = 1, until X = 0 (the
 * outer solution's start, impact.c: the state then a = (c + c_x ..)^2 as
 * at x = 0 to first order); the loss's terms from there (energy). */
static void start(const struct work *w, double *t, double *y, struct sol *s)
{
	*t = fmax(0.0, w->cu);
	y[0] = *t, y[1] = 1.0;
	struct state z = derive(w, y[0], y[1]);
	s->tau_on = *t;
	s->B_on = 2.0 * (-0.4 * z.p * z.s * z.s + w->eps * z.p * z.q - z.p * z.sig);
}

static int solve(struct work *w, double tol, struct sol *s)
{
	gsl_odeiv2_driver *d = w->march;
	double t, h = 1e-3, y[Y_DIM] = { 0, 1, 0, 0, 0 }, t0, y0[Y_DIM];
	int have_peak = 0, st = gsl_odeiv2_driver_reset(d);
	start(w, &t, y, s);
	for (size_t n = 0; !st && n < CONTACT_NMAX && t < CONTACT_TAU_END; n++) {
		t0 = t;
		memcpy(y0, y, sizeof y);
		double dp0 = derive(w, y[0], y[1]).dp;
		st = gsl_odeiv2_evolve_apply(d->e, d->c, d->s, &w->sys, &t, CONTACT_TAU_END, &h, y);
		if (st)
			return ANVIL_ENUM;
		if (!have_peak && dp0 > 0 && derive(w, y[0], y[1]).dp <= 0) {
			st = find_peak(w, t0, y0, t, tol, s);
			have_peak = 1;
		}
		if (y[0] - w->cu * y[1] * y[1] <= 0 && y[1] < 0) /* crossed X = 0 on the rebound */
			return st ? st : (have_peak ? find_end(w, t0, y0, s) : ANVIL_ENUM);
	}
	return ANVIL_ENUM;
}

static int histories(struct work *w, const struct anvil_params *p, const struct sol *s,
		     size_t n, struct anvil_history *hist)
{
	int st = anvil_history_alloc(hist, n);
	double t, y[Y_DIM] = { 0, 1, 0, 0, 0 }, L = p->T * p->V0, F = p->m1 * p->V0 / p->T;
	struct sol s0;
	start(w, &t, y, &s0);
	if (!st)
		st = gsl_odeiv2_driver_reset_hstart(w->probe, 1e-3);
	for (size_t i = 0; !st && i < n; i++) {
		double tau = s->tau_s * (double)i / (double)(n - 1);
		if (i + 1 < n && tau > t)
			st = gsl_odeiv2_driver_apply(w->probe, &t, tau, y);
		/* before the start: the free flight, x = tau */
		double x = tau < s0.tau_on ? tau : y[0], u = tau < s0.tau_on ? 1.0 : y[1];
		struct state z = tau < s0.tau_on ? (struct state){ 0 } : derive(w, x, u);
		hist->t[i] = tau * p->T;
		hist->P[i] = F * z.p;
		hist->v[i] = p->V0 * u;
		hist->W[i] = L * x;
		hist->w[i] = L * (z.sig - w->eps * z.q);
		hist->alpha[i] = L * z.s * z.s;
	}
	if (!st && n) { /* the exact end state: a = 0 at X = 0 */
		hist->P[n - 1] = hist->alpha[n - 1] = 0;
		hist->W[n - 1] = hist->w[n - 1] = L * w->cu * s->u_end * s->u_end;
		hist->v[n - 1] = p->V0 * s->u_end;
	}
	return st ? (st == ANVIL_ENOMEM ? st : ANVIL_ENUM) : ANVIL_OK;
}

double anvil_contact_eps(const struct anvil_params *p, double beta)
{
	if (!p || !(beta >= 0) || !(p->T > 0))
		return NAN;
	return beta * p->m1 / (p->T * p->T * p->T);
}

static void fill(struct anvil_result *r, const struct anvil_params *p, const struct sol *a,
		 const struct sol *b)
{
	double F = p->m1 * p->V0 / p->T;
	r->ts.val = a->tau_s * p->T, r->ts.err = fabs(a->tau_s - b->tau_s) * p->T;
	r->tmax.val = a->tau_m * p->T, r->tmax.err = fabs(a->tau_m - b->tau_m) * p->T;
	r->Pmax.val = a->p_m * F, r->Pmax.err = fabs(a->p_m - b->p_m) * F;
	r->Rf.val = -a->u_end, r->Rf.err = fabs(a->u_end - b->u_end);
	r->Vs.val = r->Rf.val * p->V0, r->Vs.err = r->Rf.err * p->V0;
	r->Ea.val = 0.5 * p->m1 * p->V0 * p->V0 * (1.0 - r->Rf.val * r->Rf.val);
	r->Ea.err = p->m1 * p->V0 * p->V0 * r->Rf.val * r->Rf.err;
	r->lambda_star = p->lambda_star;
	r->Rf_star = p->Rf_star;
	snprintf(r->note, sizeof r->note,
		 "true Hertz contact plus the half-space's radiation lag -beta dP/dt");
}

/* The energies: lost from the rebound speed; the model's own loss,
 * lost = 2 int p x' = 2 (eps int p' q - int p' sigma) + B_on by parts
 * (x = a - eps q + sigma, a = p = 0 at the end), B_on the start's term
 * (start(); 1.2 c0^5, c0 = 1.5 eps, to first order, from a(0) = c0^2);
 * and Hunter's 2 eps int p'^2; all in units m1 V0^2 / 2. */
static void energy(struct anvil_contact_energy *en, const struct anvil_params *p, double eps,
		   const struct sol *a, const struct sol *b)
{
	double E0 = 0.5 * p->m1 * p->V0 * p->V0;
	en->eps = eps;
	en->lost = E0 * (1.0 - a->u_end * a->u_end);
	en->rad_pq = E0 * (2.0 * (eps * a->JQ - a->JS) + a->B_on);
	en->rad_pp = E0 * 2.0 * eps * a->J2;
	en->err = E0 * fmax(fabs(a->u_end * a->u_end - b->u_end * b->u_end),
			    fmax(2.0 * eps * fmax(fabs(a->JQ - b->JQ), fabs(a->J2 - b->J2)),
				 2.0 * fabs(a->JS - b->JS)));
}

int anvil_contact_run(const struct anvil_params *p, double beta,
		      const struct anvil_contact_opts *o, struct anvil_result *r,
		      struct anvil_contact_energy *en, struct anvil_err *err)
{
	if (!p || !o || !r)
		return anvil_err_set(err, ANVIL_EINVAL, "contact: no parameters, options or result");
	double eps = anvil_contact_eps(p, beta);
	if (!(eps >= 0 && eps <= CONTACT_EPS_MAX && isfinite(p->T)))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "contact: radiation parameter eps = %g outside [0, %g]", eps,
				     CONTACT_EPS_MAX);
	if (!(o->tol > 0 && o->tol <= 1e-3) || o->nhist == 1 || !(o->g2 >= 0 && isfinite(o->g2)))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "contact: tolerance %g, %zu samples or g2 = %g", o->tol, o->nhist,
				     o->g2);
	/* the second order (impact.c's c_u, c_x in units T V0 / V0^2 = T / V0) */
	double eta = 2.0 * o->g2 * p->K * sqrt(p->r0) * p->V0 / p->T;
	double cu = o->g2 > 0 ? eta - 1.125 * eps * eps : 0.0;
	double cx = o->g2 > 0 ? eta - 2.25 * eps * eps : 0.0;
	struct work w;
	struct sol a = { 0 }, b = { 0 };
	int st = work_init(&w, eps, cu, cx, o->tol);
	if (!st)
		st = solve(&w, o->tol, &a);
	if (!st && o->nhist)
		st = histories(&w, p, &a, o->nhist, &r->hist);
	work_free(&w);
	if (!st)
		st = work_init(&w, eps, cu, cx, 100.0 * o->tol);
	if (!st)
		st = solve(&w, 100.0 * o->tol, &b);
	work_free(&w);
	if (st)
		return anvil_err_set(err, st, "contact: %s", st == ANVIL_ENOMEM ? "out of memory"
				     : "the ODE integrator failed");
	fill(r, p, &a, &b);
	if (en)
		energy(en, p, eps, &a, &b);
	return ANVIL_OK;
}

/* f = 2 eps I_H to first order (x'' = -p with the Hertz pulse; lost =
 * 2 eps int p'^2 in units m1 V0^2/2).  With eps = beta m / T^3,
 * T^3 = m^(6/5) V0^(-3/5) K^(-6/5), and for a sphere of radius R of the
 * block's material m = (4/3) pi R^3 rho, K = (4/3) E* sqrt(R),
 * E* = E / (2 (1 - nu^2)), c2^3 = (E / (2 (1 + nu) rho))^(3/2):
 *   f = 2 xi I_H ((4/3) pi)^(-1/5) (2/(3(1-nu^2)))^(6/5) (2(1+nu))^(3/2)
 *       (rho/E)^(3/10) V0^(3/5),
 * R cancels, and (rho/E)^(3/10) V0^(3/5) = (V0/c0)^(3/5). */
double anvil_contact_hunter_coef(double nu, double xi)
{
	if (!(nu > -1 && nu < 0.5) || !(xi > 0))
		return NAN;
	double am = anvil_hertz_alpha_max();
	double IH = 1.8 * am * am * gsl_sf_beta(0.8, 1.5);
	return 2.0 * xi * IH * pow(4.0 * M_PI / 3.0, -0.2) *
	       pow(2.0 / (3.0 * (1.0 - nu * nu)), 1.2) * pow(2.0 * (1.0 + nu), 1.5);
}
