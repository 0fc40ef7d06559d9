/* halfspace.c: exact centre response of a half-space to the Hertz patch load.
 *
 * Derivation
 * ==========
 * Units: lengths in r0, time tau = c2 t / r0, displacement mu r0 w per newton,
 * kappa = c2/c1, kappa^2 = (1 - 2 nu) / (2 (1 - nu)).
 *
 * 1. Kernel.  With s = c2 k p the half-space kernel alpha1 s^2 /
 *    (c2^2 mu R(k,s)) is F(p) / (mu k),
 *        F(p) = p^2 a1 / ((2 + p^2)^2 - 4 a1 a2),
 *        a1 = sqrt(1 + kappa^2 p^2), a2 = sqrt(1 + p^2)   (principal roots),
 *    F(0) = 1/(2 (1 - kappa^2)) = 1 - nu.  Since s t = p (c2 k t), the step
 *    response is
 *        step(tau) = int_0^inf Z^H(k) g(k tau) dk,   g = L^-1[F(p)/p],
 *    with Z^H(k) = 3 (sin k - k cos k) / (2 pi k^3).
 *
 * 2. g exactly.  F(p)/p is analytic off the imaginary axis; its
 *    singularities are the pole p = 0 (residue 1 - nu), the Rayleigh poles
 *    p = +-i qR (qR = c_R/c2 < 1, the root in (0,1) of (2 - q^2)^2 =
 *    4 sqrt(1 - kappa^2 q^2) sqrt(1 - q^2)), and the cuts p = +-i q, q >= 1
 *    (a2) and q >= 1/kappa (a1).  F/p ~ kappa/p^2 at infinity, so Jordan's
 *    lemma closes the Bromwich contour to the left:
 *        g(tau) = (1 - nu) + A_R cos(qR tau) + int_1^inf m(q) cos(q tau) dq.
 *    Rayleigh residues: with D(p) = (2+p^2)^2 - 4 a1 a2,
 *    D'(p) = 4 p [(2 + p^2) - kappa^2 a2/a1 - a1/a2], the two residues of
 *    e^{p tau} p a1 / D(p) add to A_R cos(qR tau),
 *        A_R = a1 / (2 [(2 - qR^2) - kappa^2 a2/a1 - a1/a2]),
 *    a1 = sqrt(1 - kappa^2 qR^2), a2 = sqrt(1 - qR^2)   (A_R < 0).
 *    Cuts: on p = iq +- 0 (right/left side), F/p = i q a1 / D.  Wrapping the
 *    upper cut (down its right side, up its left) and adding the complex
 *    conjugate lower cut gives the density m(q) = (1/pi) [G_R - G_L](iq),
 *    which is real, so only cosines appear:
 *      1 < q < 1/kappa: a1 = A1 = sqrt(1 - kappa^2 q^2) on both sides,
 *        a2 = +-i B2, B2 = sqrt(q^2 - 1), X = (2 - q^2)^2:
 *        m = -8 q A1^2 B2 / (pi (X^2 + 16 A1^2 B2^2));
 *      q > 1/kappa: a1 = +-i A1', A1' = sqrt(kappa^2 q^2 - 1), same side
 *        sign as a2, so D = X + 4 A1' B2 on both sides:
 *        m = -(2/pi) q A1' / (X + 4 A1' B2).
 *    m ~ -(2 kappa / pi) / q^2 at large q, so everything converges
 *    absolutely.  Checks (done once in mpmath to 20 digits, nu = 0.3):
 *    g(0) = 0 (initial value theorem), i.e. the sum rule
 *        (1 - nu) + A_R + int_1^inf m dq = 0,
 *    which anvil_halfspace_alloc re-checks every time, and the Laplace
 *    transform F(p)/p = (1-nu)/p + A_R p/(p^2+qR^2) + int m p/(p^2+q^2) dq
 *    at p = 0.5 and 2 (the tests check the transform of the final result).
 *
 * 3. The k-integral in closed form.  Z^H(k) = int_0^1 Z(r) J0(k r) r dr and
 *    int_0^inf J0(k r) cos(a k) dk = (r^2 - a^2)^{-1/2} for r > a, else 0,
 *    so the Abel projection is
 *        C(a) = int_0^inf Z^H(k) cos(a k) dk = (3/8) (1 - a^2) for |a| < 1,
 *    and 0 for |a| > 1 (compact support).  Z^H ~ k^-2 and m ~ q^-2, so
 *    Fubini applies and
 *        step(tau) = (3/8) [ (1 - nu) + A_R (1 - qR^2 tau^2)_+
 *                            + int_1^{1/tau} m(q) (1 - q^2 tau^2) dq ].
 *    Hence: step = 3 (1 - nu)/8 exactly for tau >= tau_R = 1/qR, an exact
 *    parabola for 1 <= tau <= tau_R, and a finite integral before.  The
 *    limits mark the waves from the rim: the upper limit 1/tau passes the
 *    branch point 1/kappa at tau = kappa (P wave, t = r0/c1) and 1 at
 *    tau = 1 (S wave, t = r0/c2); the parabola ends at tau_R (Rayleigh).  The
 *    ramp (integral of the step) follows by integrating (1 - q^2 tau'^2)_+:
 *        int_0^tau (1 - q^2 t^2)_+ dt = tau - q^2 tau^3/3 (q tau <= 1),
 *                                       2/(3 q)          (q tau > 1).
 *
 * 4. Numerics.  Two spectral ranges, each mapped to remove the square-root
 *    end points, so the integrands are smooth (analytic) on [0, pi/2]:
 *      range 1, 1 <= q <= 1/kappa: q^2 = 1 + c^2 sin^2 th, c^2 = 1/kappa^2 - 1,
 *        B2 = c sin th, A1 = sqrt(1 - kappa^2) cos th,
 *        m dq = -8 (1-kappa^2) c^3 cos^3 th sin^2 th dth /
 *               (pi [(1 - c^2 sin^2 th)^4 + 16 (1-kappa^2) c^2 sin^2 th cos^2 th]);
 *      range 2, q >= 1/kappa: u = 1/q = kappa sin psi, m dq -> h(u) du,
 *        h(u) = -(2/pi) N / Dn, N = sqrt(kappa^2 - u^2) = kappa cos psi,
 *        Dn = (2u^2 - 1)^2 + 4 u^2 N sqrt(1 - u^2), h(0) = h0 = -2 kappa/pi;
 *        q^2 m dq = h/u^2 du is split as h0/u^2 (done analytically) plus
 *        (h - h0)/u^2 = (2/pi) [1/(N + kappa) + 4 kappa (u^2 - 1 + N S)]/Dn,
 *        S = sqrt(1 - u^2), written so that nothing cancels at small u.
 *    Each range carries three moments (weights 1, 1/q, q^2 in range 1;
 *    h, u h, (h - h0)/u^2 in range 2), tabulated cumulatively on a panel
 *    partition built once by bisection until QUADPACK's 21-point
 *    Gauss-Kronrod rule (gsl_integration_qk21, the rule inside QAG) meets
 *    the tolerance on every panel.  An evaluation adds the tabulated panels
 *    and one qk21 over the part of one panel, with the error estimates
 *    summed.  The table makes the object read-only (no workspace per call),
 *    and qk21 never calls GSL's error handler.
 *    For tau < kappa the step is a sum of O(1) terms cancelling to
 *    O(tau); the sum rule is subtracted exactly there, so that small tau is
 *    computed to relative accuracy:
 *      step = (3/8) [ -A_R qR^2 tau^2 - tau^2 (M2 + Kg) - h0 (tau - tau^2/kappa)
 *                     - (K0(tau) - tau^2 Kg(tau)) ],
 *    K0(tau) = int_0^tau h du, Kg(tau) = int_0^tau (h - h0)/u^2 du, M2 and Kg
 *    without argument the full-range moments; the leading term is
 *    3 kappa tau / (2 pi), that is Z(0)/(rho c1).  The ramp likewise:
 *      ramp = (3/8) [ -A_R qR^2 tau^3/3 - (tau^3/3) (M2 + Kg)
 *                     - (h0/3) (tau^2 - tau^3/kappa)
 *                     - tau K0(tau) + (tau^3/3) Kg(tau) + (2/3) K1(tau) ],
 *    K1(tau) = int_0^tau u h du (= int_{1/tau}^inf m/q dq). */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "halfspace.h"
#include "material.h"

enum {
	HS_NMOM = 3,        /* moments per spectral range */
	HS_MAXPANEL = 2048, /* per range: beyond it tol is out of reach */
	HS_MAXDEPTH = 40,   /* bisection depth when building panels */
	HS_CALLDEPTH = 12   /* bisection depth inside one evaluation */
};

/* Shares of the tolerance eps = tol (1 - nu) (tol in units of the static
 * bracket): each tabulated moment over a whole range is built to
 * HS_SHARE_MOMENT eps, the three of a range together must stay within
 * HS_SHARE_TOTAL eps (panels accepted at the rounding floor may push them
 * beyond their share), and the one partial panel of an evaluation gets
 * HS_SHARE_PARTIAL eps.  An evaluation draws on both ranges' tables (with
 * weights of modulus <= 1) and one partial panel, so its estimate stays
 * below 0.7 tol times the static value. */
#define HS_SHARE_MOMENT 0.08
#define HS_SHARE_TOTAL 0.3
#define HS_SHARE_PARTIAL 0.1
/* A panel whose qk21 estimate is within this multiple of resabs is resolved
 * to rounding (QUADPACK's own floor is 50 DBL_EPSILON resabs): bisecting it
 * gains nothing. */
#define HS_ROUNDOFF (100.0 * DBL_EPSILON)

struct hs_range {
	size_t n;                  /* panels */
	size_t cap;
	double *x;                 /* n + 1 panel ends, x[0] = 0, x[n] = pi/2 */
	double *cum[HS_NMOM];      /* integral of moment j over [0, x[i]] */
	double *cerr[HS_NMOM];     /* its summed qk21 error estimate */
};

struct anvil_halfspace {
	double nu, tol;
	double k2, kappa;          /* kappa = c2/c1 */
	double cc2, cc;            /* c^2 = 1/kappa^2 - 1 (range 1 map) */
	double qr, tau_r, ar;      /* Rayleigh: c_R/c2, c2/c_R, residue A_R */
	double h0;                 /* h(0) = -2 kappa / pi */
	double eps;                /* absolute tolerance in bracket units */
	struct hs_range r[2];
};

/* ---- integrands -------------------------------------------------------- */

/* Range 1 moments at th: m dq/dth times 1, 1/q, q^2. */
static void hs_mom1(const struct anvil_halfspace *hs, double th, double mom[HS_NMOM])
{
	double s = sin(th), co = cos(th), s2 = s * s;
	double q2 = 1.0 + hs->cc2 * s2;
	double t = 1.0 - hs->cc2 * s2;
	double x2 = t * t * t * t;
	double omk = 1.0 - hs->k2;
	double den = x2 + 16.0 * omk * hs->cc2 * s2 * co * co;
	/* den = 0 only at nu = 0, th = pi/2, where the limit is 0 */
	double base = den > 0 ? -8.0 * omk * hs->cc2 * hs->cc * co * co * co * s2 / (M_PI * den)
			      : 0.0;
	mom[0] = base;
	mom[1] = base / sqrt(q2);
	mom[2] = base * q2;
}

/* Range 2 moments at psi (u = kappa sin psi): h du/dpsi times 1 and u, and
 * (h - h0)/u^2 du/dpsi. */
static void hs_mom2(const struct anvil_halfspace *hs, double psi, double mom[HS_NMOM])
{
	double u = hs->kappa * sin(psi), n = hs->kappa * cos(psi);
	double u2 = u * u, sq = sqrt(1.0 - u2);
	double t = 2.0 * u2 - 1.0;
	double dn = t * t + 4.0 * u2 * n * sq;
	if (!(dn > 0)) { /* nu = 0, psi = pi/2: every moment tends to 0 */
		mom[0] = mom[1] = mom[2] = 0.0;
		return;
	}
	mom[0] = -M_2_PI * n * n / dn;
	mom[1] = u * mom[0];
	mom[2] = M_2_PI * n * (1.0 / (n + hs->kappa) + 4.0 * hs->kappa * (u2 - 1.0 + n * sq)) / dn;
}

struct hs_fparams {
	const struct anvil_halfspace *hs;
	int range;                 /* 0 or 1 */
	int j;                     /* one moment, or -1 for the combination a */
	double a[HS_NMOM];
};

static double hs_f(double x, void *p)
{
	const struct hs_fparams *fp = p;
	double mom[HS_NMOM];
	if (fp->range == 0)
		hs_mom1(fp->hs, x, mom);
	else
		hs_mom2(fp->hs, x, mom);
	if (fp->j >= 0)
		return mom[fp->j];
	return fp->a[0] * mom[0] + fp->a[1] * mom[1] + fp->a[2] * mom[2];
}

/* ---- panel table ------------------------------------------------------- */

static int hs_range_push(struct hs_range *rg, double b, const double res[HS_NMOM],
			 const double err[HS_NMOM])
{
	if (rg->n + 2 > rg->cap) {
		size_t cap = rg->cap ? 2 * rg->cap : 16;
		double *x = realloc(rg->x, cap * sizeof *x);
		if (!x)
			return ANVIL_ENOMEM;
		rg->x = x;
		for (int j = 0; j < HS_NMOM; j++) {
			double *c = realloc(rg->cum[j], cap * sizeof *c);
			if (!c)
				return ANVIL_ENOMEM;
			rg->cum[j] = c;
			c = realloc(rg->cerr[j], cap * sizeof *c);
			if (!c)
				return ANVIL_ENOMEM;
			rg->cerr[j] = c;
		}
		rg->cap = cap;
	}
	if (rg->n == 0) {
		rg->x[0] = 0.0;
		for (int j = 0; j < HS_NMOM; j++)
			rg->cum[j][0] = rg->cerr[j][0] = 0.0;
	}
	rg->x[rg->n + 1] = b;
	for (int j = 0; j < HS_NMOM; j++) {
		rg->cum[j][rg->n + 1] = rg->cum[j][rg->n] + res[j];
		rg->cerr[j][rg->n + 1] = rg->cerr[j][rg->n] + err[j];
	}
	rg->n++;
	return ANVIL_OK;
}

/* Accept [a,b] when qk21 meets eps_per_len (b - a), or is resolved to
 * rounding, for every moment; else bisect.  Depth first, so panels arrive
 * in order. */
static int hs_range_build(struct anvil_halfspace *hs, int range, double a, double b,
			  double eps_per_len, int depth)
{
	struct hs_range *rg = &hs->r[range];
	double res[HS_NMOM], err[HS_NMOM];
	int okay = 1;
	for (int j = 0; j < HS_NMOM; j++) {
		struct hs_fparams fp = { hs, range, j, { 0, 0, 0 } };
		gsl_function f = { hs_f, &fp };
		double resabs, resasc;
		gsl_integration_qk21(&f, a, b, &res[j], &err[j], &resabs, &resasc);
		if (!isfinite(res[j]) || !isfinite(err[j]))
			return ANVIL_ENUM;
		if (err[j] > eps_per_len * (b - a) && err[j] > HS_ROUNDOFF * resabs)
			okay = 0;
	}
	if (okay)
		return hs_range_push(rg, b, res, err);
	if (depth >= HS_MAXDEPTH || rg->n >= HS_MAXPANEL)
		return ANVIL_ETOL;
	double mid = 0.5 * (a + b);
	int st = hs_range_build(hs, range, a, mid, eps_per_len, depth + 1);
	if (st != ANVIL_OK)
		return st;
	return hs_range_build(hs, range, mid, b, eps_per_len, depth + 1);
}

/* qk21 on [a,b] with bisection while the estimate exceeds eps and is not
 * yet at the rounding floor. */
static int hs_qk21_adapt(const gsl_function *f, double a, double b, double eps, int depth,
			 double *res, double *err)
{
	double resabs, resasc;
	gsl_integration_qk21(f, a, b, res, err, &resabs, &resasc);
	if (!isfinite(*res) || !isfinite(*err))
		return ANVIL_ENUM;
	if (*err <= eps || *err <= HS_ROUNDOFF * resabs)
		return ANVIL_OK;
	if (depth >= HS_CALLDEPTH)
		return ANVIL_ETOL;
	double mid = 0.5 * (a + b), r1, e1, r2, e2;
	int st1 = hs_qk21_adapt(f, a, mid, 0.5 * eps, depth + 1, &r1, &e1);
	if (st1 == ANVIL_ENUM)
		return st1;
	int st2 = hs_qk21_adapt(f, mid, b, 0.5 * eps, depth + 1, &r2, &e2);
	if (st2 == ANVIL_ENUM)
		return st2;
	*res = r1 + r2;
	*err = e1 + e2;
	return st1 != ANVIL_OK ? st1 : st2;
}

/* sum_j a[j] int_0^x moment_j over range, with its error estimate. */
static int hs_cum(const struct anvil_halfspace *hs, int range, double x, const double a[HS_NMOM],
		  double *val, double *err)
{
	const struct hs_range *rg = &hs->r[range];
	size_t lo = 0, hi = rg->n; /* x[lo] <= x < x[hi] */
	if (x >= rg->x[rg->n]) {
		lo = rg->n;
	} else {
		while (hi - lo > 1) {
			size_t mid = (lo + hi) / 2;
			if (rg->x[mid] <= x)
				lo = mid;
			else
				hi = mid;
		}
	}
	double v = 0, e = 0;
	for (int j = 0; j < HS_NMOM; j++) {
		v += a[j] * rg->cum[j][lo];
		e += fabs(a[j]) * rg->cerr[j][lo];
	}
	int st = ANVIL_OK;
	if (x > rg->x[lo]) {
		struct hs_fparams fp = { hs, range, -1, { a[0], a[1], a[2] } };
		gsl_function f = { hs_f, &fp };
		double r, re;
		st = hs_qk21_adapt(&f, rg->x[lo], x, HS_SHARE_PARTIAL * hs->eps, 0, &r, &re);
		if (st == ANVIL_ENUM)
			return st;
		v += r;
		e += re;
	}
	*val = v;
	*err = e;
	return st;
}

/* Full-range moment j with its error. */
static double hs_full(const struct anvil_halfspace *hs, int range, int j, double *err)
{
	const struct hs_range *rg = &hs->r[range];
	*err += rg->cerr[j][rg->n];
	return rg->cum[j][rg->n];
}

/* ---- object ------------------------------------------------------------ */

double anvil_halfspace_static(double nu)
{
	if (!(nu > -1.0 && nu < 0.5))
		return NAN;
	return 3.0 * (1.0 - nu) / 8.0;
}

void anvil_halfspace_free(struct anvil_halfspace *hs)
{
	if (!hs)
		return;
	for (int i = 0; i < 2; i++) {
		free(hs->r[i].x);
		for (int j = 0; j < HS_NMOM; j++) {
			free(hs->r[i].cum[j]);
			free(hs->r[i].cerr[j]);
		}
	}
	free(hs);
}

struct anvil_halfspace *anvil_halfspace_alloc(double nu, double tol, struct anvil_err *err)
{
	if (!(nu > -1.0 && nu < 0.5)) {
		anvil_err_set(err, ANVIL_EINVAL,
			      "halfspace: Poisson ratio %g outside (-1, 0.5)", nu);
		return NULL;
	}
	if (!(tol > 0 && tol <= 0.1)) {
		anvil_err_set(err, ANVIL_EINVAL, "halfspace: tolerance %g outside (0, 0.1]", tol);
		return NULL;
	}
	struct anvil_halfspace *hs = calloc(1, sizeof *hs);
	if (!hs) {
		anvil_err_set(err, ANVIL_ENOMEM, "halfspace: out of memory");
		return NULL;
	}
	hs->nu = nu;
	hs->tol = tol;
	hs->k2 = anvil_kappa2(nu);
	hs->kappa = sqrt(hs->k2);
	hs->cc2 = (1.0 - hs->k2) / hs->k2; /* 1/kappa^2 - 1 */
	hs->cc = sqrt(hs->cc2);
	hs->h0 = -M_2_PI * hs->kappa;
	hs->eps = tol * (1.0 - nu);

	double xi = 0;
	if (anvil_rayleigh_x(hs->k2, &xi, err) != ANVIL_OK)
		goto fail;
	hs->qr = sqrt(xi);
	hs->tau_r = 1.0 / hs->qr;
	{
		double a1 = sqrt(1.0 - hs->k2 * xi), a2 = sqrt(1.0 - xi);
		hs->ar = a1 / (2.0 * ((2.0 - xi) - hs->k2 * a2 / a1 - a1 / a2));
	}

	for (int range = 0; range < 2; range++) {
		int st = hs_range_build(hs, range, 0.0, M_PI_2,
					HS_SHARE_MOMENT * hs->eps / M_PI_2, 0);
		if (st != ANVIL_OK) {
			anvil_err_set(err, st,
				      st == ANVIL_ETOL
					      ? "halfspace: tolerance %g out of reach (nu = %g)"
					      : "halfspace: quadrature failed (tolerance %g, nu = %g)",
				      tol, nu);
			goto fail;
		}
	}

	/* panels accepted at the rounding floor may add up beyond the share */
	for (int range = 0; range < 2; range++) {
		double tot = 0;
		for (int j = 0; j < HS_NMOM; j++)
			tot += hs->r[range].cerr[j][hs->r[range].n];
		if (!(tot <= HS_SHARE_TOTAL * hs->eps)) {
			anvil_err_set(err, ANVIL_ETOL,
				      "halfspace: tolerance %g out of reach (nu = %g, rounding %.1e)",
				      tol, nu, tot / (1.0 - nu));
			goto fail;
		}
	}

	/* Sum rule g(0) = 0: (1 - nu) + A_R + int_1^inf m dq = 0.  It ties the
	 * residue, both cut densities and the branch choices together. */
	{
		double e = 0;
		double sum = (1.0 - nu) + hs->ar + hs_full(hs, 0, 0, &e) + hs_full(hs, 1, 0, &e);
		if (!(fabs(sum) <= e + 1e-13)) {
			anvil_err_set(err, ANVIL_ENUM,
				      "halfspace: sum rule violated by %g (estimate %g, nu = %g)",
				      sum, e, nu);
			goto fail;
		}
	}
	anvil_err_clear(err);
	return hs;
fail:
	anvil_halfspace_free(hs);
	return NULL;
}

double anvil_halfspace_tau_r(const struct anvil_halfspace *hs) { return hs->tau_r; }

/* Range 1 angle for tau in [kappa, 1]: q = 1/tau = sqrt(1 + c^2 sin^2 th). */
static double hs_theta(const struct anvil_halfspace *hs, double tau)
{
	double s2 = (1.0 - tau * tau) / (tau * tau * hs->cc2);
	return s2 >= 1.0 ? M_PI_2 : asin(sqrt(s2));
}

/* Range 2 angle for tau in [0, kappa]: u = tau = kappa sin psi. */
static double hs_psi(const struct anvil_halfspace *hs, double tau)
{
	double s = tau / hs->kappa;
	return s >= 1.0 ? M_PI_2 : asin(s);
}

/* Rounding of a bracket built from terms of size mag, in step units. */
#define HS_ROUND(mag) (16.0 * DBL_EPSILON * (mag))

/* What step and ramp return: 3/8 of the bracket b (the patch's Abel
 * projection at a = 0), its error from the quadrature (e) and from rounding
 * in sums of magnitude mag; NaN for a failed status. */
static int hs_result(int st, double b, double e, double mag, double *val, double *abserr)
{
	int failed = st == ANVIL_ENUM || st == ANVIL_EINVAL;
	*val = failed ? NAN : 0.375 * b;
	if (abserr)
		*abserr = failed ? NAN : 0.375 * (e + HS_ROUND(mag));
	return st;
}

int anvil_halfspace_step(const struct anvil_halfspace *hs, double tau, double *val,
			 double *abserr)
{
	double b, e = 0, mag;
	int st = ANVIL_OK;
	if (!(tau >= 0) || !isfinite(tau))
		return hs_result(ANVIL_EINVAL, 0, 0, 0, val, abserr);
	double t2 = tau * tau, k = hs->kappa, qr2 = hs->qr * hs->qr;
	if (tau >= hs->tau_r) {
		b = 1.0 - hs->nu;
		mag = b;
	} else if (tau >= 1.0) {
		b = (1.0 - hs->nu) + hs->ar * (1.0 - qr2 * t2);
		mag = (1.0 - hs->nu) + fabs(hs->ar);
	} else if (tau >= k) {
		double a[HS_NMOM] = { 1.0, 0.0, -t2 }, c;
		st = hs_cum(hs, 0, hs_theta(hs, tau), a, &c, &e);
		b = (1.0 - hs->nu) + hs->ar * (1.0 - qr2 * t2) + c;
		mag = (1.0 - hs->nu) + fabs(hs->ar) + fabs(c);
	} else {
		/* the sum rule removed, see the derivation */
		double a[HS_NMOM] = { 1.0, 0.0, -t2 }, c;
		double full = hs_full(hs, 0, 2, &e) + hs_full(hs, 1, 2, &e);
		e *= t2;
		double ec = 0;
		st = hs_cum(hs, 1, hs_psi(hs, tau), a, &c, &ec);
		e += ec;
		b = -hs->ar * qr2 * t2 - t2 * full - hs->h0 * (tau - t2 / k) - c;
		mag = fabs(hs->ar) * qr2 * t2 + t2 * fabs(full) + fabs(hs->h0) * tau + fabs(c);
	}
	return hs_result(st, b, e, mag, val, abserr);
}

int anvil_halfspace_ramp(const struct anvil_halfspace *hs, double tau, double *val,
			 double *abserr)
{
	double b, e = 0, mag;
	int st = ANVIL_OK;
	if (!(tau >= 0) || !isfinite(tau))
		return hs_result(ANVIL_EINVAL, 0, 0, 0, val, abserr);
	double t2 = tau * tau, t3 = t2 * tau, k = hs->kappa, qr2 = hs->qr * hs->qr;
	double omn = 1.0 - hs->nu;
	if (tau >= k) {
		/* the tail: q > 1/tau contributes int m 2/(3q) dq */
		double tail = hs_full(hs, 0, 1, &e) + hs_full(hs, 1, 1, &e);
		e *= 2.0 / 3.0;
		double ray = tau >= hs->tau_r ? 2.0 / (3.0 * hs->qr) : tau - qr2 * t3 / 3.0;
		b = omn * tau + hs->ar * ray + (2.0 / 3.0) * tail;
		mag = omn * tau + fabs(hs->ar * ray) + (2.0 / 3.0) * fabs(tail);
		if (tau < 1.0) {
			/* q in [1, 1/tau]: tau - q^2 tau^3/3 instead of 2/(3q) */
			double a[HS_NMOM] = { tau, -2.0 / 3.0, -t3 / 3.0 }, c, ec = 0;
			st = hs_cum(hs, 0, hs_theta(hs, tau), a, &c, &ec);
			b += c;
			e += ec;
			mag += fabs(c);
		}
	} else {
		double full = hs_full(hs, 0, 2, &e) + hs_full(hs, 1, 2, &e);
		e *= t3 / 3.0;
		double a[HS_NMOM] = { -tau, 2.0 / 3.0, t3 / 3.0 }, c, ec = 0;
		st = hs_cum(hs, 1, hs_psi(hs, tau), a, &c, &ec);
		e += ec;
		b = -hs->ar * qr2 * t3 / 3.0 - (t3 / 3.0) * full - (hs->h0 / 3.0) * (t2 - t3 / k) + c;
		mag = fabs(hs->ar) * qr2 * t3 + t3 * fabs(full) + fabs(hs->h0) * t2 + fabs(c);
	}
	return hs_result(st, b, e, mag, val, abserr);
}
