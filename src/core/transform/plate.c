/* plate.c: the layer correction's long-time response from the plate.  See
 * plate.h. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_multifit.h>

#include "material.h"
#include "plate.h"
#include "plate_ks.h"
#include "status.h"

/* T1 = 32 below hh = 1, max(64, 16 hh) from there, whatever the window
 * (the tail is closed form; plate.h says why and what it was measured
 * against).  The tail takes over from a window of TAIL_FROM_THIN T1 below
 * hh = 1, TAIL_FROM T1 from there. */
#define T1_THIN 32.0
#define T1_THICK_MIN 64.0
#define T1_PER_H 16.0
#define TAIL_FROM_THIN 4.0
#define TAIL_FROM 2.0

double anvil_plate_t1(double hh, double tau_end)
{
	int thin = hh < 1.0;
	double t1 = thin ? T1_THIN : fmax(T1_THICK_MIN, T1_PER_H * hh);
	return tau_end >= (thin ? TAIL_FROM_THIN : TAIL_FROM) * t1 ? t1 : 0.0;
}

/* ---- the table of K(t)/t^2 in log t ----
 *
 * Nodes u_i = u0 + i h, h = ln 2 / 32, u0 = log(T1/17): the grid depends on
 * T1 only, so a longer window's table is this one extended.  The cubic
 * B-spline quasi-interpolant s(u) = sum_i b_i B((u - u_i)/h) is C2; its
 * coefficients are the interpolating spline's, b = (1 + delta^2/6)^-1 k,
 * to the delta^4 term, b_i = (k_{i-2} - 10 k_{i-1} + 54 k_i - 10 k_{i+1}
 * + k_{i+2})/36 (with delta^2 alone its error was 10 times the
 * interpolating spline's on thin plates; with delta^4, measured on h =
 * 0.02-2 r0, the same to two digits: 2.9e-9 relative at h = 0.02 r0 near
 * T1/8, below 3e-10 elsewhere).  Each value uses four coefficients, hence
 * eight nodes.  Hand-written: GSL's splines solve for all nodes at once (a
 * node far off changes the last bits). */
#define K_H (M_LN2 / ANVIL_PLATE_PER_OCTAVE)
#define K_T0_SHARE 17.0

static double node_u0(double t1) { return log(t1 / K_T0_SHARE); }

size_t anvil_plate_nodes(double t1, double tau_end)
{
	return (size_t)ceil((log(tau_end) - node_u0(t1)) / K_H) + 5;
}

/* One table: its plate, load and grid (compared exactly) and its nodes,
 * K/t^2 in k[0..n-1] and S/t in k[cap..cap+n-1] (one block). */
struct memo_table {
	double beta, hh, nu, patch, u0;
	size_t n, cap;
	double *k;
	unsigned long used; /* when last used: the oldest is replaced */
};

/* A table per load: the physical contact's set (a point load and two
 * patches, at one or two bands) asks for three in turn, which one table
 * recomputed each time (6 % of a thin plate's run). */
#define MEMO_TABLES 4

struct anvil_plate_memo {
	struct memo_table t[MEMO_TABLES];
	unsigned long clock;
};

struct anvil_plate_memo *anvil_plate_memo_alloc(void)
{
	return calloc(1, sizeof(struct anvil_plate_memo));
}

void anvil_plate_memo_free(struct anvil_plate_memo *m)
{
	for (int i = 0; m && i < MEMO_TABLES; i++)
		free(m->t[i].k);
	free(m);
}

/* S only where its transition, at t ~ patch^2/beta, reaches into the
 * fit's window [T1/4, T1]: patch^2/beta >= T1/16.  Elsewhere it is over
 * before the fit begins, and the fitted c x log x carries the patch's t
 * log t as it did before S (h = 0.5 r0, patch r0, patch^2/beta = 4.1:
 * cov 0.024 without S, 0.043 with); and S's quadratures, as many and as
 * dear as K's, doubled the table's cost on long windows (h = r0, 100 kg at
 * 10 m/s: 0.80 -> 1.14 s). */
static int shear_on(const struct anvil_plate_tail *tl)
{
	return tl->patch > 0 && tl->patch * tl->patch / tl->beta >= tl->t1 / 16.0;
}

/* Late nodes from the quadratures at every F-th node.  Past the patch's
 * transition (beta t ~ patch^2) K/t^2 and S/t are smooth in log t, on a
 * scale that grows with beta t/patch^2 (what is left of the patch goes as
 * patch^2/(beta t) and its log), and the nodes between every F-th are
 * their degree-7 Lagrange interpolant from the FILL_P quadrature nodes
 * about them (m - 3 .. m + 4 in F-th nodes: a fixed stencil, so a node's
 * value depends on neither the window nor the memo).  F = 2 from beta t
 * = patch^2, 4 from 4 patch^2, 8 from 256 patch^2 (fill_c, fill_f).
 * Measured against the quadrature at the filled nodes (hh = 0.02, 0.1,
 * patches 0.5 and 1: the error is a function of beta t/patch^2 alone,
 * and the quadratures' own scatter through the stencil): every node of
 * two tables within 3.8e-13 of K/t^2 and 2.4e-13/hh in S/t
 * (tests/test_tail.c), below the quadratures' own 1e-12; F = 2 from
 * patch^2/2 was 1.4e-12 (at 0.75 patch^2), F = 4 from patch^2 2e-12, F =
 * 8 from 64 patch^2 1.3e-12.  On a thin plate most of the table lies
 * there (h = 0.02 r0, 1 kg at 10 m/s: 824 nodes, 700 of them beyond
 * patch^2/beta): its quadratures had been 9 % of the run. */
#define FILL_P 8
#define FILL_L 3
static const double fill_c[FILL_L] = { 1.0, 4.0, 256.0 };
static const size_t fill_f[FILL_L] = { 2, 4, 8 };

/* Where each level begins (a multiple of its F, with FILL_P/2 - 1 of its
 * nodes below it for the stencil; SIZE_MAX: nowhere, as for a point load,
 * whose nodes are one value). */
struct fill {
	size_t i0[FILL_L];
};

static void fill_levels(const struct anvil_plate_tail *tl, struct fill *fl)
{
	for (int l = 0; l < FILL_L; l++) {
		double F = (double)fill_f[l];
		double x = ceil((log(fill_c[l] * tl->patch * tl->patch / tl->beta) - tl->u0) / (K_H * F));
		double lo = FILL_P / 2 - 1;
		fl->i0[l] = tl->patch == 0.0 || !(x < 1e15) ? SIZE_MAX /* no node there */
							     : (size_t)(x > lo ? x : lo) * fill_f[l];
	}
}

/* Node i's level (-1: below the first) */
static int fill_level(const struct fill *fl, size_t i)
{
	int L = -1;
	while (L + 1 < FILL_L && i >= fl->i0[L + 1])
		L++;
	return L;
}

/* Node i is a quadrature's: a multiple of its level's F, or of a lower
 * level's within that level's stencils' reach (4 of its F past its end). */
static int node_quad(const struct fill *fl, size_t i)
{
	int L = fill_level(fl, i);
	if (L < 0 || i % fill_f[L] == 0)
		return 1;
	for (int l = L - 1; l >= -1; l--) {
		size_t F = l < 0 ? 1 : fill_f[l];
		if (i % F == 0 && i < fl->i0[l + 1] + (FILL_P / 2) * F)
			return 1;
	}
	return 0;
}

/* K/t^2 into *k and (on) S/t into *s at node i by their quadratures. */
static int node_make(const struct anvil_plate_tail *tl, int on, size_t i, struct kwork *kw,
		     double *k, double *s)
{
	double t = exp(tl->u0 + (double)i * K_H);
	int st = plate_k_over_t2(tl->beta, tl->hh, tl->patch, t, kw, k);
	*s = 0.0;
	if (on)
		st = st || plate_s_over_t(tl->beta, tl->hh, tl->nu, tl->patch, t, kw, s);
	return st;
}

/* The stencil's reach beyond n: the quadrature nodes of [n, FILL_EXT) */
#define FILL_EXT (FILL_P / 2 * 8)

/* The filled nodes in [from, n) from the quadrature nodes, those at n and
 * beyond in ek, es (from n, FILL_EXT of them). */
static void nodes_fill(const struct anvil_plate_tail *tl, const struct fill *fl, size_t from,
		       size_t n, const double *ek, const double *es)
{
	for (size_t i = from; i < n; i++) {
		if (node_quad(fl, i))
			continue;
		size_t F = fill_f[fill_level(fl, i)], m = i / F;
		double x = (double)(i % F) / (double)F, vk = 0.0, vs = 0.0;
		for (int a = 0; a < FILL_P; a++) {
			double l = 1.0, xa = a - (FILL_P / 2 - 1);
			for (int b = 0; b < FILL_P; b++)
				if (b != a)
					l *= (x - (b - (FILL_P / 2 - 1))) / (xa - (b - (FILL_P / 2 - 1)));
			size_t j = (m + (size_t)a - (FILL_P / 2 - 1)) * F;
			vk += l * (j < n ? tl->k[j] : ek[j - n]);
			vs += l * (j < n ? tl->shear[j] : es[j - n]);
		}
		tl->k[i] = vk;
		tl->shear[i] = vs;
	}
}

/* tl->k[i] and tl->shear[i] for i in [from, n) at the grid u0 of tl's
 * plate and load (those below from made: the stencil reads them). */
static int nodes_make(const struct anvil_plate_tail *tl, size_t from, size_t n)
{
	struct kwork kw;
	int st = plate_kwork_alloc(&kw), on = shear_on(tl);
	size_t nfill = 0;
	struct fill fl;
	double ek[FILL_EXT], es[FILL_EXT];
	fill_levels(tl, &fl);
	for (size_t i = from; !st && i < n; i++) {
		/* a point load's K/t^2 is one integral whatever t (its load
		 * zhat(0) does not see t): the same bits at every node, once */
		if (tl->patch == 0.0 && i > 0) {
			tl->k[i] = tl->k[i - 1];
			tl->shear[i] = 0.0;
			continue;
		}
		if (node_quad(&fl, i))
			st = node_make(tl, on, i, &kw, &tl->k[i], &tl->shear[i]);
		else
			nfill++;
	}
	/* the stencils' quadrature nodes beyond n (the last level's reach) */
	size_t F = nfill ? fill_f[fill_level(&fl, n - 1)] : 0;
	size_t top = nfill ? ((n - 1) / F + FILL_P / 2) * F : 0;
	for (size_t j = n; !st && j <= top; j++)
		if (node_quad(&fl, j))
			st = node_make(tl, on, j, &kw, &ek[j - n], &es[j - n]);
	if (!st && nfill)
		nodes_fill(tl, &fl, from, n, ek, es);
	plate_kwork_free(&kw);
	return st;
}

/* The memo's table for tl's plate, load and grid, or the one to replace
 * (the oldest); *same: it is tl's. */
static struct memo_table *memo_table(struct anvil_plate_memo *m, const struct anvil_plate_tail *tl,
				     int *same)
{
	struct memo_table *old = &m->t[0];
	for (int i = 0; i < MEMO_TABLES; i++) {
		struct memo_table *e = &m->t[i];
		if (e->n && e->beta == tl->beta && e->hh == tl->hh && e->nu == tl->nu &&
		    e->patch == tl->patch && e->u0 == tl->u0) {
			*same = 1;
			return e;
		}
		if (e->used < old->used)
			old = e;
	}
	*same = 0;
	return old;
}

/* The first n nodes into tl->k and tl->shear: the memo's where it has
 * them (the same plate, load and grid), the rest computed (and then the
 * memo's). */
static int nodes_get(struct anvil_plate_memo *m, const struct anvil_plate_tail *tl, size_t n)
{
	int same = 0;
	struct memo_table *e = m ? memo_table(m, tl, &same) : NULL;
	size_t have = same ? (e->n < n ? e->n : n) : 0;
	if (have) {
		memcpy(tl->k, e->k, have * sizeof *tl->k);
		memcpy(tl->shear, e->k + e->cap, have * sizeof *tl->shear);
	}
	int st = nodes_make(tl, have, n);
	if (st || !e)
		return st;
	e->used = ++m->clock;
	if (same && e->n >= n)
		return ANVIL_OK;
	if (e->cap < n) { /* all n are copied below: nothing to keep */
		free(e->k);
		*e = (struct memo_table){ .k = malloc(2 * n * sizeof *e->k), .cap = n,
					  .used = e->used };
		if (!e->k) {
			e->cap = 0;
			return ANVIL_OK; /* the memo lost the table: only a cost */
		}
	}
	memcpy(e->k, tl->k, n * sizeof *e->k);
	memcpy(e->k + e->cap, tl->shear, n * sizeof *e->k);
	e->beta = tl->beta;
	e->hh = tl->hh;
	e->nu = tl->nu;
	e->patch = tl->patch;
	e->u0 = tl->u0;
	e->n = n;
	return ANVIL_OK;
}

/* The B-spline coefficients bc of the n node values k. */
static void qi_coefs(const double *k, size_t n, double *bc)
{
	bc[0] = bc[1] = bc[n - 2] = bc[n - 1] = 0.0; /* not used */
	for (size_t i = 2; i + 2 < n; i++)
		bc[i] = (k[i - 2] - 10.0 * k[i - 1] + 54.0 * k[i] - 10.0 * k[i + 1] + k[i + 2]) / 36.0;
}

/* The tables in interval j (tail_at) as polynomials in f, at imp[SEG_N
 * j ..]: k = K/t^2 and s = S/t (cubics, the B-spline's segments), then
 * the impulse response's part K''(t) = 2 k + 3 k' + k'' (primes in log t)
 * a cubic and t S''(t) = s' + s'' a quadratic.  The far field evaluates
 * the impulse response at every target's charges (1.8e6 times on h =
 * 0.02 r0, 1 kg at 10 m/s), the weights the ramp at every lag: summed from
 * these, not the B-spline's four terms (three times over for the
 * impulse).  Their rounding is the B-spline's (for the impulse the
 * second difference of the coefficients over K_H^2 either way). */
#define SEG_N 15
static void imp_coefs(struct anvil_plate_tail *tl)
{
	const double h = K_H;
	for (size_t j = 3; j + 5 <= tl->nk; j++) {
		const double *b = tl->bc + j - 1, *q = tl->shear_bc + j - 1;
		double *a = tl->imp + SEG_N * j + 8, *p = tl->imp + SEG_N * j;
		/* the cubic B-spline's segment as c0 + c1 f + c2 f^2 + c3 f^3 */
		double c0 = (b[0] + 4.0 * b[1] + b[2]) / 6.0, c1 = (b[2] - b[0]) / 2.0;
		double c2 = (b[0] - 2.0 * b[1] + b[2]) / 2.0;
		double c3 = (-b[0] + 3.0 * (b[1] - b[2]) + b[3]) / 6.0;
		double s0 = (q[0] + 4.0 * q[1] + q[2]) / 6.0, s1 = (q[2] - q[0]) / 2.0;
		double s2 = (q[0] - 2.0 * q[1] + q[2]) / 2.0;
		double s3 = (-q[0] + 3.0 * (q[1] - q[2]) + q[3]) / 6.0;
		p[0] = c0, p[1] = c1, p[2] = c2, p[3] = c3;
		p[4] = s0, p[5] = s1, p[6] = s2, p[7] = s3;
		a[0] = 2.0 * c0 + 3.0 * c1 / h + 2.0 * c2 / (h * h);
		a[1] = 2.0 * c1 + 6.0 * c2 / h + 6.0 * c3 / (h * h);
		a[2] = 2.0 * c2 + 9.0 * c3 / h;
		a[3] = 2.0 * c3;
		a[4] = s1 / h + 2.0 * s2 / (h * h);
		a[5] = 2.0 * s2 / h + 6.0 * s3 / (h * h);
		a[6] = 3.0 * s3 / h;
	}
}

/* The coefficients; S's evaluation is skipped where its table is 0: a
 * tail is evaluated at every step of a long contact's far field, and
 * the second interpolant cost h = r0, 100 kg at 10 m/s 0.3 s of 1.1 */
static void tail_coefs(struct anvil_plate_tail *tl)
{
	qi_coefs(tl->k, tl->nk, tl->bc);
	qi_coefs(tl->shear, tl->nk, tl->shear_bc);
	tl->shear_on = 0;
	for (size_t i = 0; i < tl->nk; i++)
		tl->shear_on |= tl->shear[i] != 0.0;
	imp_coefs(tl);
}

/* The interval j (its coefficients j-1 .. j+2 exist: 3 <= j <= nk - 5) and
 * the place f in it of u = log t. */
static size_t tail_at_log(const struct anvil_plate_tail *tl, double lt, double *f)
{
	double x = (lt - tl->u0) / K_H, j = floor(x);
	double jmax = (double)(tl->nk - 5);
	j = j < 3.0 ? 3.0 : j > jmax ? jmax : j;
	*f = x - j;
	return (size_t)j;
}

static size_t tail_at(const struct anvil_plate_tail *tl, double t, double *f)
{
	return tail_at_log(tl, log(t), f);
}

/* The table of coefficients bc (K/t^2's or S/t's) in interval j at
 * fraction f (tail_at), and (d) its derivative in log t.  K's and S's
 * share j and f: one logarithm for both (a long contact's far field
 * evaluates the tail at every step). */
static inline double qi_val(const double *bc, size_t j, double f, double *d)
{
	double g = 1.0 - f;
	const double *b = bc + j - 1;
	double f2 = f * f, f3 = f2 * f;
	if (d)
		*d = (-0.5 * g * g * b[0] + (1.5 * f2 - 2.0 * f) * b[1] +
		      (-1.5 * f2 + f + 0.5) * b[2] + 0.5 * f2 * b[3]) / K_H;
	return (g * g * g * b[0] + (3.0 * f3 - 6.0 * f2 + 4.0) * b[1] +
		(-3.0 * f3 + 3.0 * f2 + 3.0 * f + 1.0) * b[2] + f3 * b[3]) / 6.0;
}

static double qi_interp(const struct anvil_plate_tail *tl, const double *bc, double t, double *d)
{
	double f;
	size_t j = tail_at(tl, t, &f);
	return qi_val(bc, j, f, d);
}

/* ---- the model and its fit ---- */

/* K + S - s_hs t at t: g less the part fitted */
/* K + S - s_hs t at t, lt = log t (the segments' polynomials) */
static double plate_part_log(const struct anvil_plate_tail *tl, double t, double lt)
{
	double f;
	const double *p = tl->imp + SEG_N * tail_at_log(tl, lt, &f);
	double k = ((p[3] * f + p[2]) * f + p[1]) * f + p[0];
	double s = tl->shear_on ? ((p[7] * f + p[6]) * f + p[5]) * f + p[4] : 0.0;
	return t * t * k + t * s - tl->shs * t;
}

static double plate_part(const struct anvil_plate_tail *tl, double t)
{
	return plate_part_log(tl, t, log(t));
}

static void basis(const struct anvil_plate_tail *tl, double t, double *b)
{
	double x = t / tl->t1; /* scaled: the normal matrix stays well conditioned */
	b[0] = 1.0;
	b[1] = x;
	b[2] = x * log(x);
}

/* The model at t: one logarithm for the table's place and x log x */
static double model_at(const struct anvil_plate_tail *tl, const double c[3], double t)
{
	double lt = log(t), x = t / tl->t1;
	return plate_part_log(tl, t, lt) + c[0] + c[1] * x + c[2] * (x * (lt - tl->lt1));
}

double anvil_plate_tail_ramp(const struct anvil_plate_tail *tl, double t)
{
	return model_at(tl, tl->c, t);
}

double anvil_plate_tail_step(const struct anvil_plate_tail *tl, double t)
{
	/* K = t^2 k(log t): K' = t (2 k + k'); S = t s(log t): S' = s + s' */
	double f, d, ds = 0.0;
	size_t j = tail_at(tl, t, &f);
	double k = qi_val(tl->bc, j, f, &d);
	double s = tl->shear_on ? qi_val(tl->shear_bc, j, f, &ds) : 0.0, x = t / tl->t1;
	return t * (2.0 * k + d) + s + ds - tl->shs +
	       (tl->c[1] + tl->c[2] * (log(x) + 1.0)) / tl->t1;
}

double anvil_plate_tail_impulse(const struct anvil_plate_tail *tl, double t)
{
	/* K'' = 2 k + 3 k' + k'', S'' = (s' + s'')/t (imp_coefs); the fit's
	 * a + b x + c x log x (x = t/T1) and -s_hs t leave c/(T1 t) */
	double f;
	size_t j = tail_at(tl, t, &f);
	const double *a = tl->imp + SEG_N * j + 8;
	double kpp = ((a[3] * f + a[2]) * f + a[1]) * f + a[0];
	double spp = tl->shear_on ? ((a[6] * f + a[5]) * f + a[4]) / t : 0.0;
	return kpp + tl->c[2] / (tl->t1 * t) + spp;
}

double anvil_plate_tail_k(const struct anvil_plate_tail *tl, double t)
{
	return qi_interp(tl, tl->bc, t, NULL);
}

double anvil_plate_tail_s(const struct anvil_plate_tail *tl, double t)
{
	return tl->shear_on ? qi_interp(tl, tl->shear_bc, t, NULL) : 0.0;
}

double anvil_plate_tail_err(const struct anvil_plate_tail *tl, double t)
{
	double x = fmax(1.0, t / tl->t1);
	return tl->v * (x * (1.0 + log(x)) - 1.0);
}

/* Least squares (GSL's SVD-based multifit) of ramp - plate_part over the
 * samples with t in [ta, tb], at most 1024 of them. */
static int fit(const struct anvil_plate_tail *tl, const double *ramp, double dtau, double ta,
	       double tb, double c[3])
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
		basis(tl, t, b);
		for (int k = 0; k < 3; k++)
			gsl_matrix_set(X, i, (size_t)k, b[k]);
		gsl_vector_set(y, i, ramp[j] - plate_part(tl, t));
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

/* The join.  The least-squares model does not pass through the
 * inversion's last samples: they differ by the inversion's error there
 * (largest at T1, its e^{c0 t} amplification), e.g. 50 in 1.3e6 at h =
 * 0.02 r0, draft.  Switched at one sample, that offset is a step in the
 * ramp, a dipole in the impulse response (its second difference, the
 * impact's weights) that echoes every T1 through the contact force: the
 * periodic kicks of issue 11.  So over [T1/4, T1], the fit's own window,
 * the samples go from the inversion to the model with the C2 weight x^3
 * (10 - 15 x + 6 x^2): the ramp stays C2, the offset d spreads over
 * 3 T1/4 (at most 5.8 d (4/(3 T1))^2 in the impulse response), and each
 * blended sample, a convex combination of two estimates of the same
 * function, is within the larger of their errors (both already in
 * abserr, which holds the tail's v over [0, T1]).  Beyond T1 the samples
 * (the spline's pad) are the model's.  Over [T1/2, T1] at T1 = 32 the
 * join's dipole at h = 0.02 r0 (draft, a point load) was 20.7 against the
 * inversion's scatter of 14-20 (tests/test_green.c, plate_join); over
 * [T1/4, T1], 8.5. */
static void blend(const struct anvil_plate_tail *tl, double dtau, size_t n1, size_t n,
		  double *ramp)
{
	double ta = 0.25 * tl->t1, w = tl->t1 - ta;
	for (size_t j = (size_t)ceil(ta / dtau); j < n1; j++) {
		double t = (double)j * dtau, x = fmin(1.0, (t - ta) / w);
		double s = x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
		ramp[j] += s * (model_at(tl, tl->c, t) - ramp[j]);
	}
	for (size_t j = n1; j < n; j++)
		ramp[j] = model_at(tl, tl->c, (double)j * dtau);
}

static int tail_alloc(struct anvil_plate_tail *tl, double hh, double nu, double patch,
		      double t1, size_t nk)
{
	*tl = (struct anvil_plate_tail){ .hh = hh, .nu = nu, .patch = patch, .t1 = t1, .nk = nk,
					 .beta = plate_beta(hh, nu),
					 .shs = 3.0 / (16.0 * (1.0 - anvil_kappa2(nu))),
					 .u0 = node_u0(t1), .lt1 = log(t1) };
	if (nk < 10)
		return ANVIL_EINVAL;
	tl->k = malloc((4 + SEG_N) * nk * sizeof *tl->k);
	if (!tl->k)
		return ANVIL_ENOMEM;
	tl->bc = tl->k + nk;
	tl->shear = tl->k + 2 * nk;
	tl->shear_bc = tl->k + 3 * nk;
	tl->imp = tl->k + 4 * nk;
	return ANVIL_OK;
}

void anvil_plate_tail_free(struct anvil_plate_tail *tl)
{
	free(tl->k);
	*tl = (struct anvil_plate_tail){ 0 };
}

int anvil_plate_tail_make(double hh, double nu, double patch, double dtau, size_t n1, size_t n,
			  double *ramp, double tau_end, struct anvil_plate_memo *memo,
			  struct anvil_plate_tail *tl)
{
	double t1 = (double)(n1 - 2) * dtau, cv[3] = { 0, 0, 0 }, v = 0;
	int st = tail_alloc(tl, hh, nu, patch, t1, anvil_plate_nodes(t1, tau_end));
	if (!st)
		st = nodes_get(memo, tl, tl->nk);
	if (st)
		return st;
	tail_coefs(tl);
	/* the validation: fitted on [T1/8, T1/2], checked on [T1/2, T1] */
	st = fit(tl, ramp, dtau, t1 / 8.0, t1 / 2.0, cv);
	for (size_t j = (size_t)ceil(0.5 * t1 / dtau); !st && (double)j * dtau <= t1; j++)
		v = fmax(v, fabs(model_at(tl, cv, (double)j * dtau) - ramp[j]));
	if (!st)
		st = fit(tl, ramp, dtau, t1 / 4.0, t1, tl->c);
	if (!st)
		blend(tl, dtau, n1, n, ramp);
	/* the extrapolation's unit: the misfit, or the two fits' coefficients
	 * apart where more (plate.h says why: the misfit alone can be small
	 * by chance, and an error in c grows like x log x) */
	double dc = fabs(tl->c[0] - cv[0]) + fabs(tl->c[1] - cv[1]) + fabs(tl->c[2] - cv[2]);
	tl->misfit = v;
	tl->v = st ? v : fmax(v, dc);
	return st;
}

int anvil_plate_tail_init(struct anvil_plate_tail *tl, double hh, double nu, double patch,
			  double t1, const double c[3], double v, double tau_end, size_t nk,
			  const double *k, const double *shear)
{
	if (!(t1 > 0) || !(patch >= 0 && isfinite(patch)) || nk != anvil_plate_nodes(t1, tau_end) ||
	    !(v >= 0 && isfinite(v)) ||
	    !isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2])) {
		*tl = (struct anvil_plate_tail){ 0 };
		return ANVIL_EINVAL;
	}
	int st = tail_alloc(tl, hh, nu, patch, t1, nk);
	double alpha = 1.0 / (8.0 * tl->beta * hh);
	/* S/t: finite, and 0 for a point load (plate.c) */
	for (size_t i = 0; !st && i < nk; i++)
		if (!(k[i] > 0 && k[i] <= alpha) || !isfinite(shear[i]) ||
		    (patch == 0 && shear[i] != 0))
			st = ANVIL_EINVAL;
	if (st)
		return st;
	memcpy(tl->k, k, nk * sizeof *k);
	memcpy(tl->shear, shear, nk * sizeof *shear);
	memcpy(tl->c, c, sizeof tl->c);
	tl->v = v;
	tail_coefs(tl);
	return ANVIL_OK;
}
