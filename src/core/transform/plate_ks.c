/* plate_ks.c: K(t) and S(t), the Kirchhoff plate's and the layer's
 * first-order term's responses under the patch, by quadrature in u =
 * beta k^2 t (plate.h says what they are; plate.c tabulates them in log t
 * and fits the tail).  Split from plate.c, which had grown to three ideas:
 * these integrals, their table, and the tail's model and fit. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_expint.h>

#include "kernel.h"
#include "plate.h"
#include "plate_ks.h"
#include "status.h"

/* ---- K(t), the Kirchhoff plate under the patch ---- */

/* The load's transform at u = beta t k^2: zhat(k patch), k = sqrt(u/(beta
 * t)).  The tail is the response's own patch's: with the r0 patch's K a
 * point load's tail (the physical contact's) missed the inversion by 4e-4
 * of the ramp at h = 0.02 r0 (10 times its estimate), since K_1 - K_0
 * there is no a + b t + c t log t while patch^2/(beta t) is not small. */
/* K's split between [0, U] and the tail (plate_k_over_t2) */
#define K_SPLIT (64.0 * M_PI)
/* [0, U]'s panels for K's and S's quadratures (panel_qk31) */
#define K_PANELS 8
#define S_PANELS 16

struct umemo;
struct kp {
	double beta, t, patch;
	struct umemo *um; /* the integrand's factor in u alone, kept (NULL: none) */
	struct zmemo *zm; /* zhat at this node's u, kept (NULL: none) */
};

/* zhat(patch sqrt(u/(beta t))) at one node's abscissae, kept by u: it
 * is three fifths of the table's cost (two sines, a division), and a
 * node's three tails (K's sine, S's sine and cosine) read it at the same
 * u, qawf's cycles and their Clenshaw-Curtis points being the same
 * (h = 0.02 r0, 100 kg at 10 m/s: 0.4 % of the run's instructions).
 * Direct-mapped, the entry's u and node compared exactly: a kept value is
 * the call's (the same bits).  A node's key (beta, t, patch) changes the
 * generation.  K's [0, U] on S's 16 panels would share those too (1.9 %
 * more, and no qag fallback) but moves K/t^2 by up to 6e-14, and that
 * moved a flat peak's t_max by half its estimate (h = 0.02 r0, 10 kg at
 * 1 m/s: 312.2 -> 313.4 us +- 0.38 us). */
#define ZMEMO_LG 12
#define ZMEMO_N ((size_t)1 << ZMEMO_LG)
struct zmemo {
	double beta, t, patch;
	unsigned gen;
	unsigned g[ZMEMO_N];
	double u[ZMEMO_N], z[ZMEMO_N];
};

/* The memo for p's node (a new generation when the node changes). */
static struct zmemo *zmemo_at(struct zmemo *m, double beta, double t, double patch)
{
	if (m && !(m->gen && m->beta == beta && m->t == t && m->patch == patch)) {
		if (++m->gen == 0) { /* wrapped: no entry may look current */
			memset(m->g, 0, sizeof m->g);
			m->gen = 1;
		}
		m->beta = beta, m->t = t, m->patch = patch;
	}
	return m;
}

/* The [0, U] integrands are zhat(patch sqrt(u/(beta t))) times a factor
 * of u alone (sinc terms: a sine or two, a division), and every node of a
 * table asks for it at the same abscissae (panel_qk31's fixed panels, in
 * the same order): kept from the first node, replayed at the next (the
 * same bits: a pure function's values; an abscissa that is not the kept
 * one, as in qag's fallback, is computed).  Half of the integrands' cost,
 * 2 % of h = 0.02 r0, 1 kg at 10 m/s. */
#define UMEMO_N (S_PANELS * 31)
struct umemo {
	double u[UMEMO_N], f[UMEMO_N];
	size_t i; /* the next call's place */
};

static double umemo_get(struct umemo *m, double u, double (*fn)(double, const void *),
			const void *arg)
{
	if (!m)
		return fn(u, arg);
	size_t i = m->i++;
	if (i < UMEMO_N && m->u[i] == u)
		return m->f[i];
	double f = fn(u, arg);
	if (i < UMEMO_N) {
		m->u[i] = u;
		m->f[i] = f;
	}
	return f;
}

static double k_load(const struct kp *p, double u)
{
	struct zmemo *m = p->zm;
	if (!m)
		return anvil_kernel_zhat(p->patch * sqrt(u / (p->beta * p->t)));
	uint64_t b;
	memcpy(&b, &u, sizeof b);
	size_t h = (size_t)((b * UINT64_C(0x9E3779B97F4A7C15)) >> (64 - ZMEMO_LG));
	if (m->g[h] == m->gen && m->u[h] == u)
		return m->z[h];
	double z = anvil_kernel_zhat(p->patch * sqrt(u / (p->beta * p->t)));
	m->g[h] = m->gen, m->u[h] = u, m->z[h] = z;
	return z;
}

static double k_factor(double u, const void *unused)
{
	(void)unused;
	/* 1 - sin u/u by its series where it cancels */
	double s = u < 1e-3 ? u * u / 6.0 * (1.0 - u * u / 20.0) : 1.0 - sin(u) / u;
	return u < 1e-3 ? (1.0 - u * u / 20.0) / 6.0 : s / (u * u);
}

static double k_integrand(double u, void *v)
{
	const struct kp *p = v;
	return k_load(p, u) * umemo_get(p->um, u, k_factor, NULL);
}

/* The tail's two parts, zhat/u^2 (smooth) and zhat sin(u)/u^3 (against
 * QUADPACK's Fourier-integral rule, qawf).  The first, in k = patch
 * sqrt(u/(beta t)), is 2 k0^2/U int_k0^inf zhat(k)/k^3 dk, U = K_SPLIT, in
 * closed form: (3/(2 pi)) int (sin k - k cos k)/k^6 dk = (3/(2 pi)) [Ci(k)/30
 * - sin k/(30 k) + cos k/(30 k^2) + sin k/(15 k^3) - cos k/(5 k^4) + sin
 * k/(5 k^5)] at k0 (its derivative is minus the integrand); below k = 1,
 * where those terms cancel like 1/k^2, the integrand's series from k0 to 1
 * and the closed form at 1.  qagiu took half of a thin plate's table (10 %
 * of its run at h = 0.02 r0, 1 kg, 10 m/s). */
static double zk3_closed(double k)
{
	double sn = sin(k), cs = cos(k), k2 = k * k;
	return gsl_sf_Ci(k) / 30.0 - sn / (30.0 * k) + cs / (30.0 * k2) + sn / (15.0 * k2 * k) -
	       cs / (5.0 * k2 * k2) + sn / (5.0 * k2 * k2 * k);
}

/* sin k - k cos k = sum_n (-1)^n (2n + 2)/(2n + 3)! k^(2n+3): termwise over
 * [k0, 1], n = 0 and 1 giving the k^-2 and log terms; 12 terms leave
 * 1/(25)! */
static double zk3_series(double k0)
{
	double c = 1.0 / 3.0, sum = 0.5 * c * (1.0 / (k0 * k0) - 1.0), k2 = k0 * k0, kp = 1.0;
	c *= -4.0 / (4.0 * 5.0 * 2.0); /* (2n + 2)/(2n + 3)! at n = 1, signed */
	sum -= c * log(k0);
	for (int n = 2; n < 14; n++) {
		c *= -(2.0 * n + 2.0) / ((2.0 * n) * (2.0 * n + 2.0) * (2.0 * n + 3.0));
		kp *= k2;
		sum += c * (1.0 - kp) / (2.0 * n - 2.0);
	}
	return sum;
}

static double tail_smooth_closed(const struct kp *p)
{
	if (p->patch == 0.0)
		return 1.0 / (2.0 * M_PI * K_SPLIT);
	double k0 = p->patch * sqrt(K_SPLIT / (p->beta * p->t));
	double g = k0 < 1.0 ? zk3_series(k0) + zk3_closed(1.0) : zk3_closed(k0);
	return 2.0 * k0 * k0 / K_SPLIT * 3.0 / (2.0 * M_PI) * g;
}

static double tail_osc(double u, void *v)
{
	return k_load(v, u) / (u * u * u);
}

/* int_0^U F by Gauss-Kronrod 31 on np equal panels, accepted when the
 * panels' summed error estimate meets qag's own test (max(epsabs, epsrel
 * |result|)), else by qag from the whole interval.  qag reaches that
 * partition by bisection from [0, U] (U = 64 pi: 8 panels for K, 13-17
 * for S on a thin plate), spending as many rules again on the levels above
 * it: the table's quadratures were 16 % of a thin plate's run. */
static int panel_qk31(const gsl_function *F, int np, double epsabs, double epsrel,
		      gsl_integration_workspace *w, double *val, double *err)
{
	double sum = 0.0, esum = 0.0, h = K_SPLIT / np;
	for (int i = 0; i < np; i++) {
		double r, e, ra, rasc;
		gsl_integration_qk31(F, i * h, (i + 1 == np) ? K_SPLIT : (i + 1) * h, &r, &e, &ra,
				     &rasc);
		sum += r;
		esum += e;
	}
	if (isfinite(sum) && esum <= fmax(epsabs, epsrel * fabs(sum))) {
		*val = sum;
		*err = esum;
		return GSL_SUCCESS;
	}
	return gsl_integration_qag(F, 0.0, K_SPLIT, epsabs, epsrel, 1000, GSL_INTEG_GAUSS31, w, val,
				   err);
}

/* K(t)/t^2 = (1/(2 beta hh)) int_0^inf ...: to 1e-12 relative on [0, U]
 * (U = 64 pi: the sinc's oscillation, and zhat's where beta t is small),
 * the tail (below 1/U = 5e-3 of a total near 1/8) as its smooth part in
 * closed form (tail_smooth_closed) and its oscillating part by qawf to
 * 1e-12 absolute.  qagiu's smooth part had been off by up to 1.4e-9 of
 * K/t^2 (h = 0.02 r0, patch r0, t = 1.4; 8e-10 at late times), against
 * 30-digit quadratures (mpmath); the closed form's is 5e-15 there. */
int plate_k_over_t2(double beta, double hh, double patch, double t, struct kwork *kw,
		    double *val)
{
	struct kp p = { beta, t, patch, kw->uk, zmemo_at(kw->zm, beta, t, patch) };
	gsl_function F = { k_integrand, &p }, O = { tail_osc, &p };
	kw->uk->i = 0;
	double a, b = tail_smooth_closed(&p), c, ea, ec;
	int st = panel_qk31(&F, K_PANELS, 0.0, 1e-12, kw->w, &a, &ea);
	st = st || gsl_integration_qawf(&O, K_SPLIT, 1e-12, 1000, kw->w, kw->wc, kw->tab, &c, &ec);
	*val = (a + b - c) / (2.0 * beta * hh);
	return st || !isfinite(*val) ? ANVIL_ENUM : ANVIL_OK;
}


int plate_kwork_alloc(struct kwork *kw)
{
	*kw = (struct kwork){ gsl_integration_workspace_alloc(1000),
			      gsl_integration_workspace_alloc(1000),
			      gsl_integration_qawo_table_alloc(1.0, 1.0, GSL_INTEG_SINE, 25),
			      gsl_integration_qawo_table_alloc(1.0, 1.0, GSL_INTEG_COSINE, 25),
			      malloc(sizeof(struct umemo)), malloc(sizeof(struct umemo)),
			      calloc(1, sizeof(struct zmemo)) };
	for (size_t i = 0; kw->uk && kw->us && i < UMEMO_N; i++) /* NaN: no abscissa kept */
		kw->uk->u[i] = kw->us->u[i] = NAN;
	return kw->w && kw->wc && kw->tab && kw->tabc && kw->uk && kw->us && kw->zm ? ANVIL_OK
										    : ANVIL_ENOMEM;
}

void plate_kwork_free(struct kwork *kw)
{
	free(kw->zm);
	free(kw->us);
	free(kw->uk);
	gsl_integration_qawo_table_free(kw->tabc);
	gsl_integration_qawo_table_free(kw->tab);
	gsl_integration_workspace_free(kw->wc);
	gsl_integration_workspace_free(kw->w);
}

double plate_beta(double hh, double nu) { return hh / sqrt(6.0 * (1.0 - nu)); }

int anvil_plate_k(double hh, double nu, double patch, double t, double *val)
{
	struct kwork kw;
	int st = plate_kwork_alloc(&kw);
	if (!st)
		st = plate_k_over_t2(plate_beta(hh, nu), hh, patch, t, &kw, val);
	plate_kwork_free(&kw);
	return st;
}

/* ---- S(t), the layer's first-order term (shear, rotary inertia) ----
 *
 * To first order in (kh)^2 the layer's surface under a surface load Q
 * moves as
 *   W = Q (1 + h^2 k^2/5) / (D k^4 + rho h s^2 (1 + gamma h^2 k^2)),
 *   gamma = (17 - 7 nu)/(60 (1 - nu)),
 * gamma the known first correction of the flexural (A0) branch of
 * Rayleigh-Lamb, 1/5 the load's (shear and the thickness's compression
 * under it): both measured against the layer's own kernel
 * (anvil_layer_bc, hh = 0.0025, nu = 0 .. 0.45) to 4 digits.  Mindlin's
 * plate has eps = 1/(6 kappa (1 - nu)) = 0.29 and r2 + eps = 0.37 in their
 * places (nu = 0.3, kappa = pi^2/12): with them the fitted c x log x had
 * to take back 31 % of the patch's t log t, and could not (worst error 4
 * times this term's at T1 = 32, h = 0.02 r0, patch 1).  Where the plate
 * holds, s ~ beta k^2 and the s^4 and s^2 terms of the next order are
 * (kh)^4, with the rest of that order a near-constant the fit's a carries.
 * To first order W - Q/P = Q k^2 h^2 [1/(5 P) - rho h s^2 gamma/P^2], P =
 * D k^4 + rho h s^2; for the ramp Q = zhat/s^2, inverted with u = beta k^2
 * t as K is (h^2/beta^2 = 6 (1 - nu)):
 *   S(t)/t = (A I1 - B I2)/hh,  A = 3 (1 - nu)/5,  B = (17 - 7 nu)/40,
 *   I1 = int_0^inf Z (u - sin u)/u^2 du,  I2 = int_0^inf Z (sin u - u cos u)/u^2 du,
 * Z = zhat(patch sqrt(u/(beta t))).  I1 grows like log(beta t/patch^2)/(2 pi):
 * S is the patch's own t log t, and its transition at t ~ patch^2/beta
 * (100 at h = 0.02 r0, patch 1) is what the fitted a + b x + c x log x
 * could not follow.  A point load's I1 diverges (the (kh)^2 expansion's log
 * under a point, which the layer cuts off at k ~ 1/h): S_0 = 0, and the
 * fit's c x log x carries its t log t. */
struct sp {
	struct kp p; /* first: k_load's */
	double a, b; /* A and B */
};

static double s_factor(double u, const void *v)
{
	const struct sp *q = v;
	double i1, i2; /* (u - sin u)/u^2, (sin u - u cos u)/u^2: series where they cancel */
	if (u < 1e-2) {
		double u2 = u * u;
		i1 = u * (1.0 / 6.0 - u2 / 120.0 + u2 * u2 / 5040.0);
		i2 = u * (1.0 / 3.0 - u2 / 30.0 + u2 * u2 / 840.0);
	} else {
		double sn = sin(u);
		i1 = (u - sn) / (u * u);
		i2 = (sn - u * cos(u)) / (u * u);
	}
	return q->a * i1 - q->b * i2;
}

static double s_integrand(double u, void *v)
{
	const struct sp *q = v;
	return k_load(&q->p, u) * umemo_get(q->p.um, u, s_factor, q);
}

/* Beyond U: A Z/u, -(A + B) Z sin(u)/u^2 and B Z cos(u)/u (these two by
 * qawf).  The first, in k = patch sqrt(u/(beta t)), is 2 A int_k0^inf
 * zhat(k)/k dk = 2 A [zhat(k0)/3 + (sin k0/k0 - Ci(k0))/(2 pi)] (its
 * derivative is -zhat/k; zhat's own series where sin - k cos cancels):
 * qagiu missed 1e-12 on its oscillation. */
static double s_smooth(double k0)
{
	return anvil_kernel_zhat(k0) / 3.0 + (sin(k0) / k0 - gsl_sf_Ci(k0)) / (2.0 * M_PI);
}

static double s_sin(double u, void *v)
{
	return k_load(v, u) / (u * u);
}

static double s_cos(double u, void *v)
{
	return k_load(v, u) / u;
}

/* S(t)/t to 1e-12 relative or 1e-13/hh absolute (where it crosses zero,
 * near t = patch^2/(8 beta)) on [0, U] and 1e-12/hh absolute beyond (S/t
 * is of order 1/hh); 0 for a point load (above). */
int plate_s_over_t(double beta, double hh, double nu, double patch, double t, struct kwork *kw,
		   double *val)
{
	*val = 0.0;
	if (patch == 0.0)
		return ANVIL_OK;
	struct sp q = { { beta, t, patch, kw->us, zmemo_at(kw->zm, beta, t, patch) }, 0.6 * (1.0 - nu),
			(17.0 - 7.0 * nu) / 40.0 };
	kw->us->i = 0;
	gsl_function F = { s_integrand, &q }, S = { s_sin, &q.p }, C = { s_cos, &q.p };
	double a, b = s_smooth(patch * sqrt(K_SPLIT / (beta * t))), c, d, ea, ec, ed;
	int st = panel_qk31(&F, S_PANELS, 1e-13, 1e-12, kw->w, &a, &ea);
	st = st || gsl_integration_qawf(&S, K_SPLIT, 1e-12, 1000, kw->w, kw->wc, kw->tab, &c, &ec);
	st = st || gsl_integration_qawf(&C, K_SPLIT, 1e-12, 1000, kw->w, kw->wc, kw->tabc, &d, &ed);
	*val = (a + 2.0 * q.a * b - (q.a + q.b) * c + q.b * d) / hh;
	return st || !isfinite(*val) ? ANVIL_ENUM : ANVIL_OK;
}

int anvil_plate_s(double hh, double nu, double patch, double t, double *val)
{
	struct kwork kw;
	int st = plate_kwork_alloc(&kw);
	if (!st)
		st = plate_s_over_t(plate_beta(hh, nu), hh, nu, patch, t, &kw, val);
	plate_kwork_free(&kw);
	return st;
}
