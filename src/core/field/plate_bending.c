/* plate_bending.c: a thin plate's bending stress at the centre under an
 * impact's force history (plate_bending.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_interp.h>
#include <gsl/gsl_multimin.h>

#include "hertz_field.h"
#include "maxscan.h"
#include "plate_bending.h"

#define QAG_LIMIT 1000
#define QAG_EPSREL 1e-7
/* Gamma (below) from its table below LAM_TAB, from its asymptotic series
 * above (mu = lambda/4 >= 16: the next term, f^(5)(0)/mu^6, is below 1e-7),
 * from its Taylor series below LAM_SERIES (the next term mu^4/1540 is
 * below 1e-14). */
#define LAM_SERIES 1e-3
#define LAM_TAB 64.0
#define NTAB 1200
/* The convolution in ln s starts at s = S_MIN t, or later where lambda
 * (of the patch at t) reaches LAM_CUT: the rest, int Gamma dmu/mu over
 * mu > mu_c = LAM_CUT/4 by Gamma's asymptotic form, is below
 * 0.375/mu_c^2 + 1.33/mu_c^(5/2) = TAIL (times P_max), added to the error
 * estimate; its fast oscillation would only stall QUADPACK. */
#define S_MIN 1e-10
#define LAM_CUT 1e4
#define TAIL 7e-8
/* Instants scanned for the maximum before Brent's refinement. */
#define NSCAN 48

/* Westergaard's equivalent radius (plate_bending.h): for c < 1.724 h. */
static double westergaard(double c, double h)
{
	return c < 1.724 * h ? sqrt(1.6 * c * c + h * h) - 0.675 * h : c;
}

/* The centre moment's impulse response.  Swapping the k- and t-integrals
 * (plate_bending.h), an impulse at tau = 0 on the patch of radius c gives
 *   M_r(0, s) = (1 + nu) / (8 pi s) Gamma(lambda),  lambda = c^2 / (beta s),
 *   Gamma(lambda) = (3/2) int_0^1 sqrt(1 - w) cos(lambda w / 4) dw,
 * from int_0^inf J0(a sqrt(v)) sin v dv = cos(a^2 / 4) (the Laplace pair
 * int J0(a sqrt v) e^(-p v) dv = e^(-a^2/(4p)) / p at p -> -i) and the
 * Hertz patch as 3 int_0^1 sqrt(1 - r^2) J0(k c r) r dr.  Gamma(0) = 1 (a
 * point load: 1/s); Gamma is smooth, so the convolution in t is a plain
 * QUADPACK integral.  Its table: qaws (the weight (1 - w)^(1/2) exact),
 * then a cubic spline in ln lambda (GSL). */
struct gam {
	double x[NTAB], y[NTAB];
	gsl_interp *sp;
	gsl_interp_accel *acc;
};

static double gam_cos(double w, void *vp)
{
	return cos(*(const double *)vp * w);
}

static int gam_init(struct gam *g)
{
	gsl_integration_workspace *ws = gsl_integration_workspace_alloc(QAG_LIMIT);
	gsl_integration_qaws_table *qt = gsl_integration_qaws_table_alloc(0.0, 0.5, 0, 0);
	g->sp = gsl_interp_alloc(gsl_interp_cspline, NTAB);
	g->acc = gsl_interp_accel_alloc();
	int st = ws && qt && g->sp && g->acc ? ANVIL_OK : ANVIL_ENOMEM;
	double l0 = log(LAM_SERIES), l1 = log(LAM_TAB);
	for (int i = 0; i < NTAB && !st; i++) {
		double mu = 0.25 * exp(l0 + (l1 - l0) * i / (NTAB - 1.0)), v, e;
		gsl_function F = { gam_cos, &mu };
		g->x[i] = l0 + (l1 - l0) * i / (NTAB - 1.0);
		int gs = gsl_integration_qaws(&F, 0.0, 1.0, qt, 1e-13, 1e-10, QAG_LIMIT, ws, &v, &e);
		if (gs && gs != GSL_EROUND)
			st = ANVIL_ENUM;
		g->y[i] = 1.5 * v;
	}
	if (!st && gsl_interp_init(g->sp, g->x, g->y, NTAB))
		st = ANVIL_ENUM;
	gsl_integration_qaws_table_free(qt);
	gsl_integration_workspace_free(ws);
	return st;
}

static void gam_free(struct gam *g)
{
	gsl_interp_free(g->sp);
	gsl_interp_accel_free(g->acc);
}

static double gam_eval(const struct gam *g, double lam)
{
	double mu = 0.25 * lam;
	if (lam < LAM_SERIES)
		return 1.0 - 4.0 / 35.0 * mu * mu;
	if (lam >= LAM_TAB) /* the ends w = 0 and w = 1 (sqrt(1 - w) exactly there) */
		return 1.5 * (0.5 / (mu * mu) - 0.375 / (mu * mu * mu * mu) +
			      0.5 * sqrt(M_PI) * cos(mu - 0.75 * M_PI) / (mu * sqrt(mu)));
	return gsl_interp_eval(g->sp, g->x, g->y, log(lam), g->acc);
}

struct bend {
	const struct anvil_history *h;
	const struct anvil_params *p;
	const struct gam *g;
	unsigned patch;
	double c;    /* the fixed patch radius, m */
	double t;    /* the instant, s */
	double beta; /* sqrt(D / (rho h)), m^2/s */
};

/* The patch radius under force P. */
static double radius(const struct bend *b, double P)
{
	double r = b->c;
	if (b->patch & ANVIL_PLATE_PATCH_HERTZ)
		r = P > 0 ? sqrt(b->p->r0 * pow(P / b->p->K, 2.0 / 3.0)) : 0;
	return b->patch & ANVIL_PLATE_PATCH_WESTERGAARD ? westergaard(r, b->p->h) : r;
}

/* P(t - s) Gamma(c^2 / (beta s)) at s = e^v: the convolution's integrand
 * in ln s. */
static double integrand(double v, void *vp)
{
	const struct bend *b = vp;
	double s = exp(v), P = anvil_history_at(b->h, b->h->P, b->t - s);
	if (!(P > 0))
		return 0;
	double c = radius(b, P);
	return P * gam_eval(b->g, c * c / (b->beta * s));
}

static int check(const struct anvil_params *p, const struct anvil_history *h, unsigned patch,
		 double c)
{
	if (!isfinite(p->h) || !(p->h > 0) || !h || h->n < 2 || !h->t || !h->P)
		return ANVIL_EINVAL;
	if (!(patch & ANVIL_PLATE_PATCH_HERTZ) && !(c > 0))
		return ANVIL_EINVAL;
	return ANVIL_OK;
}

static double beta_of(const struct anvil_params *p)
{
	double D = p->E * p->h * p->h * p->h / (12.0 * (1.0 - p->nu * p->nu));
	return sqrt(D / (p->rho * p->h));
}

/* sigma at b->t: 6 M_r / h^2 with M_r the convolution of P with the
 * impulse response (struct gam). */
static int sigma_at(struct bend *b, gsl_integration_workspace *ws, double *sigma, double *err)
{
	const struct anvil_params *p = b->p;
	*sigma = 0;
	*err = 0;
	if (!(b->t > b->h->t[0]))
		return ANVIL_OK;
	gsl_function F = { integrand, b };
	double val, e, Pmax = 0, c = radius(b, anvil_history_at(b->h, b->h->P, b->t));
	for (size_t i = 0; i < b->h->n && b->h->t[i] < b->t; i++)
		Pmax = fmax(Pmax, b->h->P[i]);
	double s_lo = fmax(S_MIN * b->t, c * c / (b->beta * LAM_CUT));
	if (!(s_lo < b->t))
		return ANVIL_OK; /* the patch not yet reached by the bending */
	int gs = gsl_integration_qag(&F, log(s_lo), log(b->t), 1e-9 * Pmax, QAG_EPSREL, QAG_LIMIT,
				     GSL_INTEG_GAUSS21, ws, &val, &e);
	if (gs && gs != GSL_EROUND)
		return ANVIL_ENUM;
	if (s_lo > S_MIN * b->t)
		e += TAIL * Pmax;
	double f = 6.0 / (p->h * p->h) * (1.0 + p->nu) / (8.0 * M_PI);
	*sigma = f * val;
	*err = f * e;
	return ANVIL_OK;
}

/* What one evaluation needs, made once per call. */
struct eval {
	struct gam g;
	gsl_integration_workspace *ws;
	struct bend b;
};

static int eval_init(struct eval *x, const struct anvil_params *p,
		     const struct anvil_history *hist, unsigned patch, double c)
{
	memset(x, 0, sizeof *x);
	x->b = (struct bend){ .h = hist, .p = p, .g = &x->g, .patch = patch, .c = c,
			      .beta = beta_of(p) };
	x->ws = gsl_integration_workspace_alloc(QAG_LIMIT);
	int st = gam_init(&x->g);
	return st ? st : x->ws ? ANVIL_OK : ANVIL_ENOMEM;
}

static void eval_free(struct eval *x)
{
	gam_free(&x->g);
	gsl_integration_workspace_free(x->ws);
}

int anvil_plate_bending_at(const struct anvil_params *p, const struct anvil_history *hist,
			   unsigned patch, double c, double t, double *sigma, double *err)
{
	struct eval x;
	int st = check(p, hist, patch, c);
	if (st)
		return st;
	st = eval_init(&x, p, hist, patch, c);
	x.b.t = t;
	if (!st)
		st = sigma_at(&x.b, x.ws, sigma, err);
	eval_free(&x);
	return st;
}

/* For Brent: minus sigma at t. */
struct peak_ctx {
	struct eval *x;
	int status;
};

static double minus_sigma(double t, void *vp)
{
	struct peak_ctx *c = vp;
	double s, e;
	c->x->b.t = t;
	int st = sigma_at(&c->x->b, c->x->ws, &s, &e);
	if (st)
		c->status = st;
	return -s;
}

/* Brent around scan point j of ts[] (values sv[]), into *t, *s. */
static int refine(struct peak_ctx *x, const double *ts, const double *sv, int j, double *t,
		  double *s)
{
	*t = ts[j];
	*s = sv[j];
	if (j == 0 || j == NSCAN - 1)
		return ANVIL_OK; /* at an end of the range: no bracket */
	gsl_function F = { minus_sigma, x };
	if (anvil_max_refine(&F, ts + j - 1, sv + j - 1, t, s))
		return ANVIL_ENOMEM;
	return x->status;
}

/* The stated range (plate_bending.h). */
static void range(struct anvil_plate_bending *b)
{
	b->tol = ANVIL_PLATE_BENDING_TOL;
	b->why[0] = '\0';
	if (b->a_h < ANVIL_PLATE_BENDING_A_H_MIN || b->a_h > ANVIL_PLATE_BENDING_A_H_MAX)
		snprintf(b->why, sizeof b->why, "the contact radius a = %.2g h, outside the %.2g-%.2g h "
			 "where the plate estimate was measured", b->a_h, ANVIL_PLATE_BENDING_A_H_MIN,
			 ANVIL_PLATE_BENDING_A_H_MAX);
	else if (b->t_h < ANVIL_PLATE_BENDING_T_MIN)
		snprintf(b->why, sizeof b->why, "its peak comes %.2g times 2h/c1 after impact, before "
			 "the %.2g where the plate estimate was measured", b->t_h, ANVIL_PLATE_BENDING_T_MIN);
	if (b->why[0])
		b->tol = 0;
}

int anvil_plate_bending_peak(const struct anvil_params *p, const struct anvil_history *hist,
			     unsigned patch, double c, double t_end, struct anvil_plate_bending *b,
			     struct anvil_err *err)
{
	memset(b, 0, sizeof *b);
	int st = check(p, hist, patch, c);
	if (st)
		return anvil_err_set(err, st, "plate bending: needs a finite plate and a force history");
	double tl = hist->t[hist->n - 1], tp = 0, Pm = 0;
	if (!(t_end > 0) || t_end > tl)
		t_end = tl;
	for (size_t i = 0; i < hist->n; i++)
		if (hist->P[i] > Pm && hist->t[i] <= t_end) {
			Pm = hist->P[i];
			tp = hist->t[i];
		}
	if (!(Pm > 0))
		return anvil_err_set(err, ANVIL_EINVAL, "plate bending: the force never exceeds 0");
	struct eval x;
	double ts[NSCAN], sv[NSCAN], se[NSCAN];
	st = eval_init(&x, p, hist, patch, c);
	if (st) {
		anvil_err_set(err, st, "plate bending: %s", anvil_strerror(st));
		goto done;
	}
	struct bend *bd = &x.b;
	/* the bending peaks after the force (it keeps growing while the force
	 * holds): instants log-spaced from t_pk / 4 to t_end */
	double t0 = fmax(0.25 * tp, 1e-3 * t_end);
	int best = 0;
	for (int j = 0; j < NSCAN && !st; j++) {
		ts[j] = t0 * pow(t_end / t0, j / (NSCAN - 1.0));
		bd->t = ts[j];
		st = sigma_at(bd, x.ws, &sv[j], &se[j]);
		if (sv[j] > sv[best])
			best = j;
	}
	if (st) {
		anvil_err_set(err, st, "plate bending: the convolution's quadrature failed");
		goto done;
	}
	struct peak_ctx pc = { &x, ANVIL_OK };
	st = refine(&pc, ts, sv, best, &b->t, &b->sigma);
	if (!st) {
		bd->t = b->t;
		st = sigma_at(bd, x.ws, &b->sigma, &b->err);
	}
	if (st) {
		anvil_err_set(err, st, "plate bending: the convolution's quadrature failed");
		goto done;
	}
	b->P = anvil_history_at(hist, hist->P, b->t);
	b->a = b->P > 0 ? sqrt(p->r0 * pow(b->P / p->K, 2.0 / 3.0)) : 0;
	b->a_h = b->a / p->h;
	b->t_h = b->t / (2.0 * p->h / p->c1);
	range(b);
done:
	eval_free(&x);
	return st;
}

struct anvil_plate_bender {
	struct eval x;
};

struct anvil_plate_bender *anvil_plate_bender_new(const struct anvil_params *p,
						  const struct anvil_history *hist, unsigned patch,
						  double c, struct anvil_err *err)
{
	int st = check(p, hist, patch, c);
	if (st) {
		anvil_err_set(err, st, "plate bending: needs a finite plate and a force history");
		return NULL;
	}
	struct anvil_plate_bender *pb = malloc(sizeof *pb);
	if (!pb) {
		anvil_err_set(err, ANVIL_ENOMEM, "plate bending: %s", anvil_strerror(ANVIL_ENOMEM));
		return NULL;
	}
	st = eval_init(&pb->x, p, hist, patch, c);
	if (st) {
		anvil_err_set(err, st, "plate bending: %s", anvil_strerror(st));
		anvil_plate_bender_free(pb);
		return NULL;
	}
	return pb;
}

int anvil_plate_bender_at(struct anvil_plate_bender *pb, double t, double *sigma, double *err)
{
	pb->x.b.t = t;
	return sigma_at(&pb->x.b, pb->x.ws, sigma, err);
}

void anvil_plate_bender_free(struct anvil_plate_bender *pb)
{
	if (!pb)
		return;
	eval_free(&pb->x);
	free(pb);
}

double anvil_plate_bending_patch(const struct anvil_params *p, unsigned patch, double c,
				 double P)
{
	struct bend b = { .p = p, .patch = patch, .c = c };
	return radius(&b, P);
}

/* ---- the near face: the contact's field and the bending's together ----
 *
 * The bending's fall from the centre.  Kirchhoff's axisymmetric plate: with
 * M = (M_r + M_t)/(1 + nu) = -D lap w, D lap^2 w = q gives lap M = -q, so
 * r M' = -F(r)/(2 pi), F(r) the net load inside r; then
 *   M(0) - M(r) = int_0^r F(rho)/(2 pi rho) drho = Delta(r),
 *   M_r - M_t = -(1 - nu) (Mbar(r) - M(r)) = -(1 - nu) E(r),
 * Mbar the mean of M over the disc r (from w_r/r - w_rr = (M - Mbar)/D), so
 *   M_r(r) = M_r(0) - [(1 + nu) Delta + (1 - nu) E] / 2,
 *   M_t(r) = M_r(0) - [(1 + nu) Delta - (1 - nu) E] / 2:
 * the fall is the load's inside r alone, whatever the plate does further
 * out (its size, its dynamics).  F is the patch's (Hertz-shaped, radius b,
 * Westergaard's as the centre's moment takes it), the plate's inertia
 * inside r neglected: over r <= 3 a it is rho h w_tt pi r^2, against P a
 * fraction (r / the bending's spread)^2, below 1e-4 on the plates where
 * the centre's estimate holds.  With u = r^2/b^2 and F/P = 1 - (1 - u)^(3/2)
 * (u < 1), 1 beyond:
 *   Delta = P/(4 pi) I(u),  I(u) = int_0^u F/(P x) dx
 *         = 8/3 - 2 ln 2 - (2 s^3/3 + 2 s - 2 ln(1 + s)), s = sqrt(1 - u),
 *         = I(1) + ln u beyond;
 *   E = P/(4 pi) (I(u) - J(u)/u), J = int_0^u I, so
 *   I - J/u = 1 - (2/5) (1 - s^5)/u  (u <= 1),
 *   J(u) = J(1) + I(1)(u - 1) + u ln u - u + 1 beyond, J(1) = I(1) - 3/5.
 * Near the centre the fall is (3 + nu) q0 r^2/16 in M_r and (1 + 3 nu)
 * q0 r^2/16 in M_t, q0 = 3P/(2 pi b^2) (a uniform load's with its central
 * intensity, Timoshenko sec. 16).  The far face's stress s_b = 6 M_r(0)/h^2
 * sets M_r(0); through the thickness the bending's stress is linear,
 * -6 M/h^2 (1 - 2 z/h). */
static double fall_I(double u)
{
	if (u < 1e-3) /* the closed form cancels: its series, next term u^4/128 */
		return u * (1.5 - u * (3.0 / 16 + u / 48));
	if (u > 1)
		return 8.0 / 3 - 2 * M_LN2 + log(u);
	double s = sqrt(1 - u);
	return 8.0 / 3 - 2 * M_LN2 - (2 * s * s * s / 3 + 2 * s - 2 * log1p(s));
}

static double fall_E(double u)
{
	if (u < 1e-3)
		return u * (0.75 - u / 8);
	if (u > 1) {
		double I1 = fall_I(1), J = I1 - 0.6 + I1 * (u - 1) + u * log(u) - u + 1;
		return fall_I(u) - J / u;
	}
	return 1 - 0.4 * (1 - pow(1 - u, 2.5)) / u;
}

void anvil_plate_bending_near_stress(double sb, double P, double b, double nu, double h,
				     double r, double z, double *srr, double *stt)
{
	double u = b > 0 ? r * r / (b * b) : 0, k = 6 / (h * h) * P / (4 * M_PI);
	double D = (1 + nu) * fall_I(u), E = (1 - nu) * fall_E(u), f = 1 - 2 * z / h;
	*srr = -f * (sb - 0.5 * k * (D + E));
	*stt = -f * (sb - 0.5 * k * (D - E));
}

struct near_ctx {
	double a, p0, nu, h, P, b, sb, ymax;
	int brittle;
};

/* The largest principal stress of the (r, z) block with the hoop stress. */
static double principal(double rr, double tt, double zz, double rz)
{
	double m = 0.5 * (rr + zz), d = sqrt(0.25 * (rr - zz) * (rr - zz) + rz * rz);
	return fmax(m + d, tt);
}

/* The combined stress at x = r/a, y = z/a (clamped to the region). */
static double near_at(const struct near_ctx *c, double x, double y)
{
	struct anvil_hertz_stress s;
	x = fmin(3.0, fabs(x));
	y = fmin(c->ymax, fabs(y));
	anvil_hertz_stress(c->a, c->p0, c->nu, x * c->a, y * c->a, &s);
	double br, bt;
	anvil_plate_bending_near_stress(c->sb, c->P, c->b, c->nu, c->h, x * c->a, y * c->a, &br,
					&bt);
	s.rr += br;
	s.tt += bt;
	if (c->brittle)
		return principal(s.rr, s.tt, s.zz, s.rz);
	return anvil_hertz_von_mises(&s);
}

static double minus_near(const gsl_vector *v, void *vp)
{
	return -near_at(vp, gsl_vector_get(v, 0), gsl_vector_get(v, 1));
}

/* Nelder-Mead from the grid's best (x, y), step one grid cell. */
static void near_refine(const struct near_ctx *c, double *x, double *y, double *val)
{
	gsl_multimin_function F = { minus_near, 2, (void *)c };
	gsl_multimin_fminimizer *m = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 2);
	gsl_vector *v = gsl_vector_alloc(2), *step = gsl_vector_alloc(2);
	if (m && v && step) {
		gsl_vector_set(v, 0, *x);
		gsl_vector_set(v, 1, *y);
		gsl_vector_set_all(step, 0.05);
		int gs = gsl_multimin_fminimizer_set(m, &F, v, step);
		for (int it = 0; !gs && it < 200; it++) {
			gs = gsl_multimin_fminimizer_iterate(m);
			if (gs || gsl_multimin_test_size(gsl_multimin_fminimizer_size(m), 1e-7) == GSL_SUCCESS)
				break;
		}
		if (-m->fval > *val) {
			*x = fmin(3.0, fabs(gsl_vector_get(m->x, 0)));
			*y = fmin(c->ymax, fabs(gsl_vector_get(m->x, 1)));
			*val = -m->fval;
		}
	}
	gsl_multimin_fminimizer_free(m);
	gsl_vector_free(v);
	gsl_vector_free(step);
}

int anvil_plate_bending_near(double a, double p0, double nu, double h, double P, double b,
			     double sb, int brittle, struct anvil_plate_near *n)
{
	if (!(a > 0 && p0 > 0 && h > 0 && isfinite(a) && isfinite(h) && nu >= 0 && nu < 0.5 &&
	      isfinite(sb) && n))
		return ANVIL_EINVAL;
	struct near_ctx c = { a, p0, nu, h, P, b, sb, fmin(3.0, 0.5 * h / a), brittle };
	double bx = 0, by = 0, best = -INFINITY;
	int ny = (int)ceil(20 * c.ymax);
	for (int i = 0; i <= 60; i++)
		for (int j = 0; j <= ny; j++) {
			double x = i / 20.0, y = fmin(c.ymax, j / 20.0), s = near_at(&c, x, y);
			if (s > best) {
				best = s;
				bx = x;
				by = y;
			}
		}
	/* the grid's best kept if the simplex finds no better (the brittle
	 * peak often sits on the kink at r = a, a grid point) */
	near_refine(&c, &bx, &by, &best);
	n->stress = best;
	n->r = bx * a;
	n->z = by * a;
	return ANVIL_OK;
}
