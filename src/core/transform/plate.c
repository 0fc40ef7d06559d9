/* plate.c: the layer correction's long-time response from the plate.  See
 * plate.h. */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_spline.h>

#include "kernel.h"
#include "material.h"
#include "plate.h"
#include "status.h"

/* T1 = 64 max(1, hh), and at least tau_end/512 so that the extended
 * response keeps at most 2^21 samples (green.c: 2048 samples per T1). */
#define T1_PER_H 64.0
#define T1_MIN_SHARE 512.0

double anvil_plate_t1(double hh, double tau_end)
{
	double t1 = fmax(T1_PER_H * fmax(1.0, hh), tau_end / T1_MIN_SHARE);
	return tau_end >= 4.0 * t1 ? t1 : 0.0;
}

/* ---- K(t), the Kirchhoff plate under the patch ---- */

struct kp {
	double beta, t;
};

static double k_integrand(double u, void *v)
{
	const struct kp *p = v;
	/* 1 - sin u/u by its series where it cancels */
	double s = u < 1e-3 ? u * u / 6.0 * (1.0 - u * u / 20.0) : 1.0 - sin(u) / u;
	double r = u < 1e-3 ? (1.0 - u * u / 20.0) / 6.0 : s / (u * u);
	return anvil_kernel_zhat(sqrt(u / (p->beta * p->t))) * r;
}

/* The tail's two parts, zhat/u^2 (smooth) and zhat sin(u)/u^3 (against
 * QUADPACK's Fourier-integral rule, qawf). */
static double tail_smooth(double u, void *v)
{
	const struct kp *p = v;
	return anvil_kernel_zhat(sqrt(u / (p->beta * p->t))) / (u * u);
}

static double tail_osc(double u, void *v)
{
	const struct kp *p = v;
	return anvil_kernel_zhat(sqrt(u / (p->beta * p->t))) / (u * u * u);
}

/* K(t)/t^2 = (1/(2 beta hh)) int_0^inf ...: to 1e-12 relative on [0, U]
 * (U = 64 pi: the sinc's oscillation, and zhat's where beta t is small),
 * the tail (below 1/U = 5e-3 of a total near 1/8) as its smooth part by
 * qagiu and its oscillating part by qawf, each to 1e-12 absolute. */
#define K_SPLIT (64.0 * M_PI)

struct kwork {
	gsl_integration_workspace *w, *wc;
	gsl_integration_qawo_table *tab;
};

static int k_over_t2(double beta, double hh, double t, struct kwork *kw, double *val)
{
	struct kp p = { beta, t };
	gsl_function F = { k_integrand, &p }, S = { tail_smooth, &p }, O = { tail_osc, &p };
	double a, b, c, ea, eb, ec;
	int st = gsl_integration_qag(&F, 0.0, K_SPLIT, 0.0, 1e-12, 1000, GSL_INTEG_GAUSS31, kw->w,
				     &a, &ea);
	st = st || gsl_integration_qagiu(&S, K_SPLIT, 1e-12, 0.0, 1000, kw->w, &b, &eb);
	st = st || gsl_integration_qawf(&O, K_SPLIT, 1e-12, 1000, kw->w, kw->wc, kw->tab, &c, &ec);
	*val = (a + b - c) / (2.0 * beta * hh);
	return st || !isfinite(*val) ? ANVIL_ENUM : ANVIL_OK;
}

/* K(t)/t^2 as a cubic spline in log t, 32 nodes per octave from t0 to t1:
 * smooth and slowly varying there (it tends to alpha* / 2). */
#define K_PER_OCTAVE 32

struct kspline {
	gsl_interp_accel *acc;
	gsl_spline *sp;
};

static void kspline_free(struct kspline *ks)
{
	gsl_spline_free(ks->sp);
	gsl_interp_accel_free(ks->acc);
}

static int kspline_make(double beta, double hh, double t0, double t1, struct kspline *ks)
{
	size_t n = (size_t)ceil(K_PER_OCTAVE * log2(t1 / t0)) + 4;
	double *x = malloc(2 * n * sizeof *x);
	struct kwork kw = { gsl_integration_workspace_alloc(1000),
			    gsl_integration_workspace_alloc(1000),
			    gsl_integration_qawo_table_alloc(1.0, 1.0, GSL_INTEG_SINE, 25) };
	ks->acc = gsl_interp_accel_alloc();
	ks->sp = gsl_spline_alloc(gsl_interp_cspline, n);
	int st = (!x || !kw.w || !kw.wc || !kw.tab || !ks->acc || !ks->sp) ? ANVIL_ENOMEM : ANVIL_OK;
	for (size_t i = 0; !st && i < n; i++) {
		x[i] = log(t0) + (double)i * (log(t1) - log(t0)) / (double)(n - 1);
		st = k_over_t2(beta, hh, exp(x[i]), &kw, &x[n + i]);
	}
	if (!st && gsl_spline_init(ks->sp, x, x + n, n))
		st = ANVIL_ENUM;
	gsl_integration_qawo_table_free(kw.tab);
	gsl_integration_workspace_free(kw.wc);
	gsl_integration_workspace_free(kw.w);
	free(x);
	if (st)
		kspline_free(ks);
	return st;
}

struct anvil_plate_memo {
	int ok;
	double beta, hh, t0, t1; /* kspline_make's arguments, compared exactly */
	struct kspline ks;
};

struct anvil_plate_memo *anvil_plate_memo_alloc(void)
{
	return calloc(1, sizeof(struct anvil_plate_memo));
}

void anvil_plate_memo_free(struct anvil_plate_memo *m)
{
	if (m && m->ok)
		kspline_free(&m->ks);
	free(m);
}

/* The table into *ks: the memo's (when it is this one), or made (and then
 * the memo's, or own: *own set, the caller frees it). */
static int kspline_get(struct anvil_plate_memo *m, double beta, double hh, double t0, double t1,
		       struct kspline *ks, int *own)
{
	*own = 0;
	if (m && m->ok && m->beta == beta && m->hh == hh && m->t0 == t0 && m->t1 == t1) {
		*ks = m->ks;
		return ANVIL_OK;
	}
	int st = kspline_make(beta, hh, t0, t1, ks);
	if (st || !m) {
		*own = !st;
		return st;
	}
	if (m->ok)
		kspline_free(&m->ks);
	*m = (struct anvil_plate_memo){ .ok = 1, .beta = beta, .hh = hh, .t0 = t0, .t1 = t1,
					.ks = *ks };
	return ANVIL_OK;
}

/* ---- the fit ---- */

struct model {
	double beta, hh, shs, t1;
	struct kspline ks;
};

/* g - (K - s_hs t) at t, the part fitted */
static double plate_part(const struct model *m, double t)
{
	return t * t * gsl_spline_eval(m->ks.sp, log(t), m->ks.acc) - m->shs * t;
}

static void basis(const struct model *m, double t, double *b)
{
	double x = t / m->t1; /* scaled: the normal matrix stays well conditioned */
	b[0] = 1.0;
	b[1] = x;
	b[2] = x * log(x);
}

/* Least squares (GSL's SVD-based multifit) of ramp - plate_part over the
 * samples with t in [ta, tb], at most 1024 of them. */
static int fit(const struct model *m, const double *ramp, double dtau, double ta, double tb,
	       double c[3])
{
	size_t j0 = (size_t)ceil(ta / dtau), j1 = (size_t)floor(tb / dtau);
	size_t stride = (j1 - j0) / 1024 + 1, n = (j1 - j0) / stride + 1;
	gsl_matrix *X = gsl_matrix_alloc(n, 3);
	gsl_vector *y = gsl_vector_alloc(n), *cv = gsl_vector_alloc(3);
	gsl_matrix *cov = gsl_matrix_alloc(3, 3);
	gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc(n, 3);
	int st = (!X || !y || !cv || !cov || !w) ? ANVIL_ENOMEM : ANVIL_OK;
	for (size_t i = 0; !st && i < n; i++) {
		size_t j = j0 + i * stride;
		double t = (double)j * dtau, b[3];
		basis(m, t, b);
		for (int k = 0; k < 3; k++)
			gsl_matrix_set(X, i, (size_t)k, b[k]);
		gsl_vector_set(y, i, ramp[j] - plate_part(m, t));
	}
	double chi2;
	if (!st && gsl_multifit_linear(X, y, cv, cov, &chi2, w))
		st = ANVIL_ENUM;
	for (int k = 0; !st && k < 3; k++)
		c[k] = gsl_vector_get(cv, (size_t)k);
	gsl_multifit_linear_free(w);
	gsl_matrix_free(cov);
	gsl_vector_free(cv);
	gsl_vector_free(y);
	gsl_matrix_free(X);
	return st;
}

static double model_at(const struct model *m, const double c[3], double t)
{
	double b[3];
	basis(m, t, b);
	return plate_part(m, t) + c[0] * b[0] + c[1] * b[1] + c[2] * b[2];
}

/* The join.  The least-squares model does not pass through the
 * inversion's last samples: they differ by the inversion's error there
 * (largest at T1, its e^{c0 t} amplification), e.g. 50 in 1.3e6 at h =
 * 0.02 r0, draft.  Switched at one sample, that offset is a step in the
 * ramp, a dipole in the impulse response (its second difference, the
 * impact's weights) that echoes every T1 through the contact force: the
 * periodic kicks of issue 11.  So over [T1/2, T1] the samples go from the
 * inversion to the model with the C2 weight x^3 (10 - 15 x + 6 x^2): the
 * ramp stays C2, the offset d spreads over T1/2 (at most 5.8 d (2/T1)^2 in
 * the impulse response), and each blended sample, a convex combination
 * of two estimates of the same function, is within the larger of their
 * errors (both already in abserr). */
static void blend(const struct model *m, const double c[3], double dtau, size_t n1, double *ramp)
{
	double ta = 0.5 * m->t1, w = m->t1 - ta;
	for (size_t j = (size_t)ceil(ta / dtau); j < n1; j++) {
		double t = (double)j * dtau, x = fmin(1.0, (t - ta) / w);
		double s = x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
		ramp[j] += s * (model_at(m, c, t) - ramp[j]);
	}
}

int anvil_plate_extend(double hh, double nu, double dtau, size_t n1, size_t n, double *ramp,
		       double *ext_err)
{
	return anvil_plate_extend_memo(hh, nu, dtau, n1, n, ramp, ext_err, NULL);
}

int anvil_plate_extend_memo(double hh, double nu, double dtau, size_t n1, size_t n, double *ramp,
			    double *ext_err, struct anvil_plate_memo *memo)
{
	struct model m = { .beta = hh / sqrt(6.0 * (1.0 - nu)), .hh = hh,
			   .shs = 3.0 / (16.0 * (1.0 - anvil_kappa2(nu))),
			   .t1 = (double)(n1 - 2) * dtau };
	double tend = (double)(n - 1) * dtau, c[3], cv[3], v = 0;
	/* nodes a little beyond both ends: log t at the last sample must not
	 * round past the last node */
	int own;
	int st = kspline_get(memo, m.beta, hh, m.t1 / 17.0, 1.01 * tend, &m.ks, &own);
	if (st)
		return st;
	/* the validation: fitted on [T1/8, T1/2], checked on [T1/2, T1] */
	st = fit(&m, ramp, dtau, m.t1 / 8.0, m.t1 / 2.0, cv);
	for (size_t j = (size_t)ceil(0.5 * m.t1 / dtau); !st && (double)j * dtau <= m.t1; j++)
		v = fmax(v, fabs(model_at(&m, cv, (double)j * dtau) - ramp[j]));
	if (!st)
		st = fit(&m, ramp, dtau, m.t1 / 4.0, m.t1, c);
	for (size_t j = n1; !st && j < n; j++)
		ramp[j] = model_at(&m, c, (double)j * dtau);
	if (!st)
		blend(&m, c, dtau, n1, ramp);
	*ext_err = v * tend / m.t1;
	if (own)
		kspline_free(&m.ks);
	return st;
}
