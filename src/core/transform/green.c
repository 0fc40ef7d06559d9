#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_interp.h>

#include "accuracy.h"
#include "green.h"
#include "kernel.h"
#include "material.h"

typedef double complex cplx;

struct anvil_green {
	enum anvil_green_mode mode;
	double hh, nu, kap2, tau_end;
	double dtau;          /* output grid step */
	size_t n;             /* samples at tau_j = j dtau, j < n */
	double *tau, *ramp;   /* one block, owned */
	gsl_interp *interp;   /* cubic spline through the ramp samples */
	double abserr;
	size_t evals;
};

/* The level's inversion settings (base/accuracy.h); the bandwidth
 * omega_max is the caller's, scaled to the contact time (engine/plan.c),
 * and is left 0 here. */
void anvil_green_settings(enum anvil_accuracy acc, struct anvil_green_settings *gs)
{
	const struct anvil_level *lv = anvil_level(acc);
	if (!lv)
		lv = anvil_level(ANVIL_ACC_NORMAL);
	*gs = (struct anvil_green_settings){ .c0T = lv->green_c0T, .omega_max = 0.0,
					     .tol = lv->green_tol, .ktail = lv->green_ktail };
}

/* The kernels, units mu = c2 = rho = 1.  With a = k^2, b = s^2:
 *   alpha_j = sqrt(a + kappa_j^2 b), gamma = 2a + b, X = 4 a alpha1 alpha2,
 *   R = gamma^2 - X = b Q / (gamma^2 + X)           (rationalised: the k^8
 *   terms cancel exactly, so Q is expanded by hand and loses no digits;
 *   used where |gamma^2 + X| > |gamma^2 - X|, the plain form elsewhere),
 *   W_hs = alpha1 b / R = alpha1 (gamma^2 + X) / Q.
 * The free layer, split into parts symmetric and antisymmetric about its
 * mid-plane (half-thickness H, zeta from the mid-plane; potentials
 * phi = A cosh(alpha1 zeta), psi = B sinh(alpha2 zeta) for the symmetric
 * part, sinh/cosh for the antisymmetric one; each part's conditions on the
 * loaded face are a 2x2 system), with t_j = tanh(alpha_j H):
 *   W = (alpha1 b / 2) [ t1 t2 / (gamma^2 t2 - X t1) + 1 / (gamma^2 t1 - X t2) ]
 * which agrees with the paper's D1..D4 (eqs 29-30, gamma = 2k^2 + s^2/c2^2)
 * to rounding (checked in tests/test_green.c).  Its difference from W_hs,
 * written with u1 = 1 - t1 and d = t2 - t1 (both O(exp(-2 alpha H)), so the
 * difference is formed without cancellation):
 *   W - W_hs = (W_hs/2) [ (R u1 + X d)/(t1 R - X d) - (t2 R u1 + X d)/(t2 R + X d) ].
 * Every exponential is exp(-2 alpha H) with Re alpha >= 0, and d comes from
 * anvil_kernel_tdiff: nothing overflows. */
struct kern {
	double kap2, H;
	cplx s, b;
};

static cplx w_halfspace(const struct kern *p, double k, cplx *al1_out, cplx *al2_out,
			cplx *R_out, cplx *X_out)
{
	double a = k * k, kap2 = p->kap2;
	cplx b = p->b;
	cplx al1 = csqrt(a + kap2 * b), al2 = csqrt(a + b);
	cplx gam = 2.0 * a + b, X = 4.0 * a * al1 * al2;
	*al1_out = al1;
	*al2_out = al2;
	*X_out = X;
	*R_out = anvil_kernel_rayleigh(a, b, kap2, gam, X);
	return al1 * b / *R_out;
}

static cplx kern_layer_corr(const struct kern *p, double k)
{
	cplx al1, al2, R, X;
	cplx whs = w_halfspace(p, k, &al1, &al2, &R, &X);
	double H = p->H;
	cplx m1 = -anvil_kernel_expm1(-2.0 * H * al1), m2 = -anvil_kernel_expm1(-2.0 * H * al2);
	cplx t1 = m1 / (2.0 - m1), t2 = m2 / (2.0 - m2);
	/* E1 itself, not 1 - m1: that would leave rounding noise (1e-16) where
	 * E1 is 1e-23, later multiplied by a large exp(-2H (alpha2 - alpha1)). */
	cplx E1 = cexp(-2.0 * H * al1), E2 = cexp(-2.0 * H * al2);
	cplx u1 = 2.0 * E1 / (2.0 - m1);
	cplx d = anvil_kernel_tdiff(al1, al2, p->b, p->kap2, 2.0 * H, E1, E2, 2.0 - m1, 2.0 - m2);
	cplx Xd = X * d;
	return 0.5 * whs * ((R * u1 + Xd) / (t1 * R - Xd) - (t2 * R * u1 + Xd) / (t2 * R + Xd));
}


struct quad {
	enum anvil_green_mode mode;
	struct kern kp;
	size_t evals;
	/* GSL's Gauss-Kronrod rules are for real integrands: the real part is
	 * integrated first and the imaginary parts of the same 21 nodes are
	 * kept here for the second call, so each node is evaluated once. */
	double cache_x[21], cache_im[21];
	int ncache, imag_pass;
};

static cplx integrand(struct quad *q, double k)
{
	q->evals++;
	if (q->mode == ANVIL_GREEN_HALFSPACE) {
		cplx al1, al2, R, X;
		cplx whs = w_halfspace(&q->kp, k, &al1, &al2, &R, &X);
		return (k * whs - 0.5 / (1.0 - q->kp.kap2)) * anvil_kernel_zhat(k);
	}
	return kern_layer_corr(&q->kp, k) * anvil_kernel_zhat(k) * k;
}

static double part(double k, void *vq)
{
	struct quad *q = vq;
	if (q->imag_pass) {
		for (int i = 0; i < q->ncache; i++)
			if (q->cache_x[i] == k)
				return q->cache_im[i];
		return cimag(integrand(q, k)); /* not reached with qk21 */
	}
	cplx v = integrand(q, k);
	if (q->ncache < 21) {
		q->cache_x[q->ncache] = k;
		q->cache_im[q->ncache++] = cimag(v);
	}
	return creal(v);
}

/* The 21-point Gauss-Kronrod rule on [a, b] for the complex integrand. */
static void qk21_complex(struct quad *q, double a, double b, cplx *val, double *err)
{
	gsl_function f = { part, q };
	double re, im, ere, eim, r1, r2;
	q->ncache = 0;
	q->imag_pass = 0;
	gsl_integration_qk21(&f, a, b, &re, &ere, &r1, &r2);
	q->imag_pass = 1;
	gsl_integration_qk21(&f, a, b, &im, &eim, &r1, &r2);
	*val = re + I * im;
	*err = hypot(ere, eim);
}

/* Globally adaptive bisection (as QUADPACK's qag, which GSL offers for real
 * integrands only): split the interval with the largest error estimate
 * until the total meets the tolerance.  A binary heap keeps the next
 * interval to split at hand. */
struct seg {
	double a, b, err;
	cplx val;
};

#define SEG_MAX 8192

struct heap {
	struct seg s[SEG_MAX];
	int n;
};

static void heap_push(struct heap *h, struct seg x)
{
	int i = h->n++;
	while (i > 0 && h->s[(i - 1) / 2].err < x.err) {
		h->s[i] = h->s[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	h->s[i] = x;
}

static struct seg heap_pop(struct heap *h)
{
	struct seg top = h->s[0], last = h->s[--h->n];
	int i = 0;
	for (;;) {
		int c = 2 * i + 1;
		if (c >= h->n)
			break;
		if (c + 1 < h->n && h->s[c + 1].err > h->s[c].err)
			c++;
		if (h->s[c].err <= last.err)
			break;
		h->s[i] = h->s[c];
		i = c;
	}
	if (h->n)
		h->s[i] = last;
	return top;
}

static void heap_add(struct quad *q, struct heap *h, double a, double b, cplx *sum, double *err)
{
	struct seg x = { .a = a, .b = b };
	qk21_complex(q, a, b, &x.val, &x.err);
	*sum += x.val;
	*err += x.err;
	heap_push(h, x);
}

/* Integrate over [0, kend], starting from pieces of width w0 on [0, kband]
 * (where the Lamb-mode poles are) and w1 beyond; absolute tolerance eps.
 * Returns ANVIL_ETOL (with the best value) when SEG_MAX pieces do not
 * suffice. */
static int adapt(struct quad *q, struct heap *h, double kband, double kend, double w0,
		 double w1, double eps, cplx *val, double *abserr)
{
	cplx sum = 0;
	double err = 0;
	h->n = 0;
	for (double a = 0; a < kend && h->n < SEG_MAX / 2;) {
		double w = a < kband ? w0 : w1;
		double b = fmin(kend, a < kband ? fmin(kband, a + w) : a + w);
		heap_add(q, h, a, b, &sum, &err);
		a = b;
	}
	while (err > eps && h->n < SEG_MAX - 1) {
		struct seg x = heap_pop(h);
		double m = 0.5 * (x.a + x.b);
		sum -= x.val;
		err -= x.err;
		heap_add(q, h, x.a, m, &sum, &err);
		heap_add(q, h, m, x.b, &sum, &err);
	}
	/* re-add from scratch: the running sums drift */
	sum = 0;
	err = 0;
	for (int i = 0; i < h->n; i++) {
		sum += h->s[i].val;
		err += h->s[i].err;
	}
	*val = sum;
	*abserr = err;
	return err <= eps ? ANVIL_OK : ANVIL_ETOL;
}


/* The k-integral at one s = c0 + i omega, to absolute error eps.  The
 * Lamb-mode poles lie within about c0/c_group of the real k axis for k up
 * to about omega/c_A0, where the slowest mode (A0) has phase speed below
 * both c_R and the thin-plate flexural speed: that band starts in small
 * pieces; beyond it the fields are evanescent and the integrand smooth
 * (exp(-2kH) times the period-2pi oscillation of zhat). */
static int k_integral(struct quad *q, struct heap *h, double omega, double hh,
		      double cr, double ktail, double eps, cplx *val, double *abserr)
{
	double nu_ = (1 - 2 * q->kp.kap2) / (2 * (1 - q->kp.kap2));
	double wabs = hypot(omega, creal(q->kp.s));
	int hs = q->mode == ANVIL_GREEN_HALFSPACE;
	double kband = anvil_kband(omega, wabs, nu_, hs ? INFINITY : hh, cr);
	double L = -log(ktail);
	double kend = hs ? fmax(kband, pow(wabs * wabs / ktail, 0.25))
			 : fmax(kband, sqrt(pow(L / hh, 2) + omega * omega));
	/* Starting pieces: about the spacing of the Lamb modes in k (pi/h) in
	 * the band, wider in the smooth tail; the adaptive splitting finds the
	 * poles from there (the results do not move when these are halved). */
	double w0 = hs ? 0.5 : fmin(1.0, 2.0 / hh), w1 = 4.0;
	return adapt(q, h, kband, kend, w0, w1, eps, val, abserr);
}

static size_t pow2_at_least(size_t n)
{
	size_t p = 1;
	while (p < n)
		p <<= 1;
	return p;
}

/* A layer moves like Zener's plate at late times: its impulse response tends
 * to alpha* (eq 8), in these units sqrt(3 (1 - nu)/2) / (4 hh^2), so its ramp
 * response grows like alpha* t^2/2 and would alias in a periodic inversion.
 * That growth is taken out in the s-domain and put back in time, through
 * the impulse response alpha* (1 - exp(-t/tp)), smooth at t = 0:
 *   ramp  alpha* [t^2/2 - tp t + tp^2 (1 - exp(-t/tp))]  <->  alpha* / (s^3 (1 + s tp)). */
struct plate {
	double alpha, tp;
};

static struct plate plate_term(enum anvil_green_mode mode, double hh, double kap2)
{
	struct plate pl = { 0.0, 1.0 };
	if (mode == ANVIL_GREEN_LAYER_CORRECTION) {
		double nu = (1 - 2 * kap2) / (2 * (1 - kap2));
		pl.alpha = sqrt(1.5 * (1 - nu)) / (4.0 * hh * hh);
		pl.tp = fmax(hh, 0.5);
	}
	return pl;
}

static cplx plate_s(const struct plate *pl, cplx s)
{
	return pl->alpha / (s * s * s * (1.0 + s * pl->tp));
}

static double plate_t(const struct plate *pl, double t)
{
	double tp = pl->tp;
	return pl->alpha * (0.5 * t * t - tp * t - tp * tp * expm1(-t / tp));
}

/* Fill spec[0..M] with the transform of the ramp response at
 * s_n = c0 + i n pi/T'.  Each k-integral gets the share eps of the error
 * budget that keeps the time-domain ramp within tol of its size; qerr
 * returns the time-domain bound that the quadrature's estimates give. */
static int sample_spectrum(struct quad *q, struct heap *h, double hh, double c0, double Tp,
			   size_t M, const struct anvil_green_settings *gs, double tau_end,
			   const struct plate *pl, cplx *spec, double *qerr,
			   anvil_progress_fn progress, void *ctx)
{
	double xr, cr;
	if (anvil_rayleigh_x(q->kp.kap2, &xr, NULL))
		return ANVIL_ENUM;
	cr = sqrt(xr); /* c_R/c2 */
	double scale = 3.0 / (16.0 * (1.0 - q->kp.kap2)) * tau_end; /* half-space ramp */
	double amp = exp(c0 * tau_end) / Tp;  /* series -> time at tau_end */
	double epsF = gs->tol * scale / (amp * (double)(M + 1));
	double sum_err = 0;
	int st = ANVIL_OK;
	for (size_t n = 0; n <= M; n++) {
		double omega = (double)n * M_PI / Tp, e;
		cplx In;
		q->kp.s = c0 + I * omega;
		q->kp.b = q->kp.s * q->kp.s;
		double s2 = cabs(q->kp.b);
		int qs = k_integral(q, h, omega, hh, cr, gs->ktail, epsF * s2, &In, &e);
		if (qs && !st)
			st = qs; /* keep going: the result says how far off it is */
		spec[n] = In / q->kp.b - plate_s(pl, q->kp.s);
		sum_err += e / s2;
		if (!isfinite(creal(spec[n])) || !isfinite(cimag(spec[n])))
			return ANVIL_ENUM;
		if (progress && n % 4 == 0 && progress(ctx, (double)n / (double)M, "layer response"))
			return ANVIL_ECANCEL;
	}
	*qerr = amp * sum_err;
	return st;
}

/* Durbin's Fourier series f(t) = (e^{c0 t}/T') [F_0/2 + Re sum F_n e^{i n pi t/T'}]
 * evaluated on t_j = j 2T'/N by one complex FFT (GSL). */
static int invert(const cplx *spec, size_t M, size_t N, double c0, double Tp,
		  double *out, size_t nout)
{
	double *z = calloc(2 * N, sizeof *z);
	if (!z)
		return ANVIL_ENOMEM;
	for (size_t n = 0; n <= M && n < N; n++) {
		double f = n == 0 ? 0.5 : 1.0;
		z[2 * n] = f * creal(spec[n]);
		z[2 * n + 1] = f * cimag(spec[n]);
	}
	int st = gsl_fft_complex_radix2_backward(z, 1, N);
	for (size_t j = 0; !st && j < nout; j++) {
		double t = (double)j * 2.0 * Tp / (double)N;
		out[j] = exp(c0 * t) / Tp * z[2 * j];
	}
	free(z);
	return st ? ANVIL_ENUM : ANVIL_OK;
}

void anvil_green_free(struct anvil_green *g)
{
	if (!g)
		return;
	gsl_interp_free(g->interp);
	free(g->tau);
	free(g);
}

static int green_compute(struct anvil_green *g, const struct anvil_green_settings *gs,
			 anvil_progress_fn progress, void *ctx)
{
	double Tp = 2.0 * g->tau_end, c0 = gs->c0T / Tp;
	size_t M = (size_t)ceil(gs->omega_max * Tp / M_PI);
	size_t N = pow2_at_least(4 * (M + 1));
	if (N < 8192)
		N = 8192;
	g->dtau = 2.0 * Tp / (double)N;
	g->n = (size_t)floor(g->tau_end / g->dtau) + 2;
	g->tau = malloc(2 * g->n * sizeof *g->tau);
	cplx *spec = malloc((M + 1) * sizeof *spec);
	struct heap *heap = malloc(sizeof *heap);
	struct quad q = { .mode = g->mode, .kp = { .kap2 = g->kap2, .H = 0.5 * g->hh } };
	struct plate pl = plate_term(g->mode, g->hh, g->kap2);
	int st = (!g->tau || !spec || !heap) ? ANVIL_ENOMEM : ANVIL_OK;
	double qerr = 0;
	if (!st)
		st = sample_spectrum(&q, heap, g->hh, c0, Tp, M, gs, g->tau_end, &pl, spec, &qerr,
				     progress, ctx);
	/* A k-integral that missed its share of the budget is not fatal: its
	 * error estimate is in qerr, hence in abserr, for the caller to judge. */
	if (st == ANVIL_ETOL)
		st = ANVIL_OK;
	if (!st) {
		g->ramp = g->tau + g->n;
		st = invert(spec, M, N, c0, Tp, g->ramp, g->n);
	}
	if (!st) {
		double tail = cabs(spec[M]) * (double)M * 0.5;
		g->abserr = qerr + exp(c0 * g->tau_end) / Tp * tail;
		for (size_t j = 0; j < g->n; j++) {
			g->tau[j] = (double)j * g->dtau;
			/* the half-space's static part, (1-nu) 3/8 = 3/(16 (1-kappa^2)), as a ramp */
			if (g->mode == ANVIL_GREEN_HALFSPACE)
				g->ramp[j] += 3.0 / (16.0 * (1.0 - g->kap2)) * g->tau[j];
			else
				g->ramp[j] += plate_t(&pl, g->tau[j]);
		}
		g->ramp[0] = 0.0; /* exact: nothing has moved at t = 0 */
		g->interp = gsl_interp_alloc(gsl_interp_cspline, g->n);
		st = g->interp ? ANVIL_OK : ANVIL_ENOMEM;
		if (!st && gsl_interp_init(g->interp, g->tau, g->ramp, g->n))
			st = ANVIL_ENUM;
	}
	g->evals = q.evals;
	free(heap);
	free(spec);
	return st;
}

struct anvil_green *anvil_green_alloc(enum anvil_green_mode mode, double hh,
				      double nu, double tau_end,
				      const struct anvil_green_settings *gs,
				      anvil_progress_fn progress, void *ctx,
				      struct anvil_err *err)
{
	if (!(nu > -1 && nu < 0.5) || !(tau_end > 0) || !isfinite(tau_end) ||
	    (mode == ANVIL_GREEN_LAYER_CORRECTION && !(hh > 0 && isfinite(hh)))) {
		anvil_err_set(err, ANVIL_EINVAL, "layer response: bad parameters (h/r0 = %g, nu = %g, window %g)",
			      hh, nu, tau_end);
		return NULL;
	}
	struct anvil_green *g = calloc(1, sizeof *g);
	if (!g) {
		anvil_err_set(err, ANVIL_ENOMEM, "layer response: out of memory");
		return NULL;
	}
	g->mode = mode;
	g->hh = hh;
	g->nu = nu;
	g->kap2 = anvil_kappa2(nu);
	g->tau_end = tau_end;
	int st = green_compute(g, gs, progress, ctx);
	if (st) {
		anvil_err_set(err, st, st == ANVIL_ECANCEL ? "layer response: cancelled" :
			      "layer response (h/r0 = %g, nu = %g): %s", hh, nu, anvil_strerror(st));
		anvil_green_free(g);
		return NULL;
	}
	return g;
}

int anvil_green_ramp(const struct anvil_green *g, double tau, double *val)
{
	if (tau <= 0) {
		*val = 0;
		return ANVIL_OK;
	}
	if (tau > g->tau_end)
		return ANVIL_EINVAL;
	*val = gsl_interp_eval(g->interp, g->tau, g->ramp, tau, NULL);
	return ANVIL_OK;
}

int anvil_green_step(const struct anvil_green *g, double tau, double *val)
{
	if (tau <= 0) {
		*val = 0;
		return ANVIL_OK;
	}
	if (tau > g->tau_end)
		return ANVIL_EINVAL;
	*val = gsl_interp_eval_deriv(g->interp, g->tau, g->ramp, tau, NULL);
	return ANVIL_OK;
}

void anvil_green_kernel(double k, double complex s, double nu, double hh,
			double complex *layer, double complex *halfspace)
{
	struct kern p = { .kap2 = anvil_kappa2(nu), .H = 0.5 * hh, .s = s, .b = s * s };
	cplx al1, al2, R, X;
	*halfspace = w_halfspace(&p, k, &al1, &al2, &R, &X);
	*layer = *halfspace + kern_layer_corr(&p, k);
}

double anvil_green_tau_end(const struct anvil_green *g) { return g->tau_end; }
double anvil_green_abserr(const struct anvil_green *g) { return g->abserr; }
size_t anvil_green_evals(const struct anvil_green *g) { return g->evals; }

/* ---- export and import (the response cache, cache.c) ---- */

void anvil_green_export(const struct anvil_green *g, struct anvil_green_samples *s)
{
	*s = (struct anvil_green_samples){ .mode = g->mode, .hh = g->hh, .nu = g->nu,
					   .tau_end = g->tau_end, .dtau = g->dtau,
					   .abserr = g->abserr, .n = g->n, .ramp = g->ramp };
}

/* The same checks a freshly computed response passes, so that a damaged
 * file that slipped past its checksum cannot reach the solver. */
static int samples_ok(const struct anvil_green_samples *s)
{
	if (!(s->nu > -1 && s->nu < 0.5) || !(s->tau_end > 0 && isfinite(s->tau_end)) ||
	    !(s->dtau > 0 && isfinite(s->dtau)) || !(s->abserr >= 0 && isfinite(s->abserr)) ||
	    (s->mode != ANVIL_GREEN_LAYER_CORRECTION && s->mode != ANVIL_GREEN_HALFSPACE) ||
	    (s->mode == ANVIL_GREEN_LAYER_CORRECTION && !(s->hh > 0 && isfinite(s->hh))) ||
	    /* the quotient first: (size_t) of one beyond its range is undefined */
	    !s->ramp || s->n < 4 || !(s->tau_end / s->dtau < (double)s->n) ||
	    s->n != (size_t)floor(s->tau_end / s->dtau) + 2 ||
	    s->ramp[0] != 0.0)
		return 0;
	for (size_t j = 0; j < s->n; j++)
		if (!isfinite(s->ramp[j]))
			return 0;
	return 1;
}

struct anvil_green *anvil_green_import(const struct anvil_green_samples *s,
				       struct anvil_err *err)
{
	if (!samples_ok(s)) {
		anvil_err_set(err, ANVIL_EINVAL, "layer response: inconsistent samples");
		return NULL;
	}
	struct anvil_green *g = calloc(1, sizeof *g);
	double *block = malloc(2 * s->n * sizeof *block);
	if (!g || !block) {
		free(g);
		free(block);
		anvil_err_set(err, ANVIL_ENOMEM, "layer response: out of memory");
		return NULL;
	}
	*g = (struct anvil_green){ .mode = s->mode, .hh = s->hh, .nu = s->nu,
				   .kap2 = anvil_kappa2(s->nu), .tau_end = s->tau_end,
				   .dtau = s->dtau, .n = s->n, .tau = block, .ramp = block + s->n,
				   .abserr = s->abserr };
	for (size_t j = 0; j < g->n; j++)
		g->tau[j] = (double)j * g->dtau; /* as green_compute: the same bits */
	memcpy(g->ramp, s->ramp, g->n * sizeof *g->ramp);
	g->interp = gsl_interp_alloc(gsl_interp_cspline, g->n);
	if (!g->interp || gsl_interp_init(g->interp, g->tau, g->ramp, g->n)) {
		anvil_err_set(err, g->interp ? ANVIL_ENUM : ANVIL_ENOMEM,
			      "layer response: cannot rebuild the interpolant");
		anvil_green_free(g);
		return NULL;
	}
	return g;
}
