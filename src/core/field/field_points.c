/* field_points.c: few places, many times (field.h, anvil_field_points):
 * each point's transformed integrals per frequency, inverted per instant. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>

#include "field_impl.h"
#include "gk21.h"
#include "kernel.h"

/* ---- points: few places, many times --------------------------------------- */

struct ptjob {
	const struct anvil_field *f;
	struct anvil_field_window w;
	struct anvil_field_kgrid g;
	size_t npt;
	double *r, *z;            /* dimensionless */
	size_t *npan;             /* panels used by each point */
	cplx *spK, *spG, *spT;    /* npt x (M+1) x HS: the transformed integrals */
	double *stK, *stG, *stT;  /* npt x HS: their static parts' integrals */
	double *jf;               /* npt x JK */
};

static void ptjob_free(struct ptjob *j)
{
	free(j->w.s);
	free(j->g.a);
	free(j->r);
	free(j->npan);
	free(j->spK);
}

static int ptjob_alloc(struct ptjob *j)
{
	size_t n = j->npt, ns = n * (j->w.M + 1) * HS_COUNT;
	j->r = calloc(2 * n + 3 * n * HS_COUNT + n * JK_COUNT, sizeof *j->r);
	j->npan = malloc(n * sizeof *j->npan);
	j->spK = calloc(3 * ns, sizeof *j->spK);
	if (!j->r || !j->npan || !j->spK)
		return ANVIL_ENOMEM;
	j->z = j->r + n;
	j->stK = j->z + n;
	j->stG = j->stK + n * HS_COUNT;
	j->stT = j->stG + n * HS_COUNT;
	j->jf = j->stT + n * HS_COUNT;
	j->spG = j->spK + ns;
	j->spT = j->spG + ns;
	return ANVIL_OK;
}

/* Term n of every active point at one k. */
static void points_term(struct ptjob *j, const struct anvil_fk_coef *c, size_t n, size_t p,
			double wk, double wgs)
{
	const struct anvil_field *f = j->f;
	int layer = isfinite(f->hh);
	size_t M1 = j->w.M + 1;
	for (size_t i = 0; i < j->npt; i++) {
		double z = j->z[i];
		cplx out[FK_COUNT];
		if (j->npan[i] <= p)
			continue;
		anvil_fk_at(c, f->kap2, cexp(-c->al1 * z), layer ? cexp(-c->al1 * (f->hh - z)) : 0,
			    cexp(-c->al2 * z), layer ? cexp(-c->al2 * (f->hh - z)) : 0, out);
		size_t o = (i * M1 + n) * HS_COUNT;
		for (int h = 0; h < HS_COUNT; h++) {
			cplx v = out[anvil_fk_of_hs[h]] * j->jf[i * JK_COUNT + anvil_field_jkind_of_hs[h]];
			j->spK[o + h] += wk * v;
			j->spG[o + h] += wgs * v;
			if (j->npan[i] == p + 1)
				j->spT[o + h] += wk * v;
		}
	}
}

/* The static kernels' integrals over the same nodes (s-independent). */
static void points_static(struct ptjob *j, double k, size_t p, double wk, double wgs)
{
	for (size_t i = 0; i < j->npt; i++) {
		double st[FK_COUNT];
		if (j->npan[i] <= p)
			continue;
		anvil_fk_static(k, j->z[i], j->f->nu, st);
		for (int h = 0; h < HS_COUNT; h++) {
			double v = st[anvil_fk_of_hs[h]] * j->jf[i * JK_COUNT + anvil_field_jkind_of_hs[h]];
			j->stK[i * HS_COUNT + h] += wk * v;
			j->stG[i * HS_COUNT + h] += wgs * v;
			if (j->npan[i] == p + 1)
				j->stT[i * HS_COUNT + h] += wk * v;
		}
	}
}

static int points_node(struct ptjob *j, double k, double wk, double wgs, size_t p)
{
	double zh = anvil_kernel_zhat(k);
	for (size_t i = 0; i < j->npt; i++)
		if (j->npan[i] > p && anvil_field_bessel_at(k, j->r[i], zh, j->jf + i * JK_COUNT))
			return ANVIL_ENUM;
	for (size_t n = 0; n <= j->w.M; n++) {
		struct anvil_fk_coef c;
		anvil_fk_coef(k, j->w.s[n], j->f->kap2, j->f->hh, &c);
		points_term(j, &c, n, p, wk, wgs);
	}
	points_static(j, k, p, wk, wgs);
	return ANVIL_OK;
}

static int points_panels(struct ptjob *j)
{
	const struct anvil_field *f = j->f;
	size_t pmax = 0;
	for (size_t i = 0; i < j->npt; i++)
		pmax = j->npan[i] > pmax ? j->npan[i] : pmax;
	for (size_t p = 0; p < pmax; p++) {
		for (int n = 0; n < ANVIL_GK21_NODES; n++) {
			double k, wk, wgs;
			anvil_gk21_node(j->g.a[p], j->g.a[p + 1], n, &k, &wk, &wgs);
			if (points_node(j, k, wk, wgs, p))
				return ANVIL_ENUM;
		}
		if (f->progress && f->progress(f->pctx, (double)(p + 1) / (double)pmax, "field"))
			return ANVIL_ECANCEL;
	}
	return ANVIL_OK;
}

/* The remainder at instant tau from one point's transformed integrals
 * (times the load's transform, less the static part), to terms nmax. */
static double points_invert(const cplx *a, const cplx *sp, double st, size_t nmax, int h)
{
	double s = 0;
	for (size_t n = 0; n <= nmax; n++)
		s += creal(a[n] * (sp[n * HS_COUNT + h] - st));
	return s;
}

static int points_output(const struct ptjob *j, size_t nt, const double *tau,
			 struct anvil_fval *out)
{
	size_t M1 = j->w.M + 1;
	cplx *a = malloc((M1 + j->w.Mh + 1) * sizeof *a), *b = a + M1;
	if (!a)
		return ANVIL_ENOMEM;
	for (size_t i = 0; i < j->npt; i++) {
		double fst[HS_COUNT], tf = anvil_field_kgrid_tail_factor(&j->g, j->z[i]);
		const cplx *sK = j->spK + i * M1 * HS_COUNT, *sG = j->spG + i * M1 * HS_COUNT,
			   *sT = j->spT + i * M1 * HS_COUNT;
		const double *tK = j->stK + i * HS_COUNT, *tG = j->stG + i * HS_COUNT,
			     *tT = j->stT + i * HS_COUNT;
		anvil_fk_static_field(j->f->nu, j->r[i], j->z[i], fst);
		for (size_t it = 0; it < nt; it++) {
			struct anvil_field_hsv x = {.tailf = tf};
			anvil_field_weights(&j->w, tau[it], j->w.M, a, 1);
			anvil_field_weights(&j->w, tau[it], j->w.Mh, b, 1);
			for (int h = 0; h < HS_COUNT; h++) {
				x.v[h] = points_invert(a, sK, tK[h], j->w.M, h);
				x.dG[h] = x.v[h] - points_invert(a, sG, tG[h], j->w.M, h);
				x.dH[h] = x.v[h] - points_invert(b, sK, tK[h], j->w.Mh, h);
				x.dT[h] = points_invert(a, sT, tT[h], j->w.M, h);
			}
			anvil_field_add_static(j->f, tau[it], fst, &x);
			anvil_field_assemble(j->f, &x, &out[i * nt + it]);
			anvil_field_true_contact(j->f, j->r[i], j->z[i], tau[it], &out[i * nt + it]);
		}
		anvil_field_error_floor(out + i * nt, nt, 1);
	}
	free(a);
	return ANVIL_OK;
}

int anvil_field_points(struct anvil_field *f, size_t npt, const double *r,
		       const double *z, size_t nt, const double *t,
		       struct anvil_fval *out, struct anvil_err *err)
{
	double tau_hi, rmax = 0;
	int st = anvil_field_check_times(f, nt, t, &tau_hi, err);
	for (size_t i = 0; !st && i < npt; i++) {
		st = anvil_field_check_point(f, r[i], z[i], err);
		rmax = fmax(rmax, r[i] / f->r0);
	}
	if (st || npt == 0)
		return st;
	struct ptjob j = {.f = f, .npt = npt};
	double *tau = malloc(nt * sizeof *tau);
	st = tau ? anvil_field_window_init(f, FLEVEL(f->acc), tau_hi, &j.w) : ANVIL_ENOMEM;
	if (st == ANVIL_EINVAL) { /* the load too long for the series: refused as the budget does */
		ptjob_free(&j);
		free(tau);
		return anvil_field_window_fail(f, "field", err);
	}
	if (!st)
		st = anvil_field_kgrid_init(&j.g, f, FLEVEL(f->acc), &j.w, rmax);
	if (!st)
		st = ptjob_alloc(&j);
	for (size_t i = 0; !st && i < npt; i++) {
		j.r[i] = r[i] / f->r0;
		j.z[i] = z[i] / f->r0;
		j.npan[i] = anvil_field_kgrid_panels(&j.g, j.z[i]);
	}
	for (size_t i = 0; tau && i < nt; i++)
		tau[i] = t[i] * f->c2 / f->r0;
	size_t sum = 0;
	for (size_t i = 0; !st && i < npt; i++)
		sum += j.npan[i];
	if (!st && (st = anvil_field_check_work(f, &j.w, &j.g, sum, "field", err))) {
		ptjob_free(&j);
		free(tau);
		return st;
	}
	if (!st)
		st = points_panels(&j);
	if (!st)
		st = points_output(&j, nt, tau, out);
	ptjob_free(&j);
	free(tau);
	return st ? anvil_field_fail(f, st, "field", err) : ANVIL_OK;
}
