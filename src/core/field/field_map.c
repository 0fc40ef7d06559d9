/* field_map.c: maps, many radii, depths and instants (field.h,
 * anvil_field_map): one k-quadrature per depth and frequency, shared by
 * every radius and instant (field_sum.c has the method). */
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "field_impl.h"
#include "gk21.h"
#include "kernel.h"

/* ---- maps: many radii, depths and instants ------------------------------- */

struct mapjob {
	const struct anvil_field *f;
	struct anvil_field_window w;
	struct anvil_field_kgrid g;
	size_t nr, nz, nt;
	double r_lo, dr, z_lo, dz;   /* dimensionless */
	const double *tau;           /* nt instants */
	cplx *an, *bn;               /* (M+1) x nt and (Mh+1) x nt Durbin weights
				      * with the load: the series and its twin */
	double *Pt, *Pth;            /* nt: the same sums of the load alone */
	double *acc, *acch;          /* nz x nt x FK: one node's time-domain kernels */
	cplx *f1, *f2;               /* nz: e^{-alpha (hh - z)} */
	double *jf;                  /* JK x nr */
	double *sK, *sG, *sH, *sT;   /* nz x nt x HS x nr: the Hankel sums */
	size_t *npan;                /* nz: panels used by each row */
	double *block;               /* owns the doubles above */
	unsigned hs;                 /* the Hankel integrals wanted (bits) */
};

static void mapjob_free(struct mapjob *m)
{
	free(m->w.s);
	free(m->g.a);
	free(m->an);
	free(m->f1);
	free(m->npan);
	free(m->block);
}

static int mapjob_alloc(struct mapjob *m)
{
	size_t nz = m->nz, nt = m->nt, nr = m->nr, M1 = m->w.M + 1;
	size_t nacc = nz * nt * FK_COUNT, nsum = nz * nt * HS_COUNT * nr;
	m->an = malloc((M1 + m->w.Mh + 1) * nt * sizeof *m->an);
	m->f1 = malloc(2 * nz * sizeof *m->f1);
	m->npan = malloc(nz * sizeof *m->npan);
	m->block = calloc(2 * nt + 2 * nacc + JK_COUNT * nr + 4 * nsum, sizeof *m->block);
	if (!m->an || !m->f1 || !m->npan || !m->block)
		return ANVIL_ENOMEM;
	m->f2 = m->f1 + nz;
	m->bn = m->an + M1 * nt;
	m->Pt = m->block;
	m->Pth = m->Pt + nt;
	m->acc = m->Pth + nt;
	m->acch = m->acc + nacc;
	m->jf = m->acch + nacc;
	m->sK = m->jf + JK_COUNT * nr;
	m->sG = m->sK + nsum;
	m->sH = m->sG + nsum;
	m->sT = m->sH + nsum;
	return ANVIL_OK;
}

/* The Durbin weights of every instant, and the load's own Durbin sums (the
 * static kernels are subtracted with these, so that the subtraction is
 * exact for the truncated series too). */
static void mapjob_weights(struct mapjob *m)
{
	size_t nt = m->nt;
	for (size_t it = 0; it < nt; it++) {
		anvil_field_weights(&m->w, m->tau[it], m->w.M, m->an + it, nt);
		anvil_field_weights(&m->w, m->tau[it], m->w.Mh, m->bn + it, nt);
		m->Pt[it] = m->Pth[it] = 0;
		for (size_t n = 0; n <= m->w.M; n++)
			m->Pt[it] += creal(m->an[n * nt + it]);
		for (size_t n = 0; n <= m->w.Mh; n++)
			m->Pth[it] += creal(m->bn[n * nt + it]);
	}
	for (size_t iz = 0; iz < m->nz; iz++)
		m->npan[iz] = anvil_field_kgrid_panels(&m->g, m->z_lo + m->dz * (double)iz);
}

/* Drop what would turn denormal: far below anything summed here. */
static cplx tiny0(cplx x)
{
	return fabs(creal(x)) + fabs(cimag(x)) < 1e-250 ? 0.0 : x;
}

/* e^{-alpha (hh - z)} for the rows below nza, from the deepest up (so the
 * recurrence decays). */
static void rows_bottom(const struct mapjob *m, cplx al, size_t nza, cplx *fv)
{
	cplx step = cexp(-al * m->dz);
	fv[nza - 1] = cexp(-al * (m->f->hh - (m->z_lo + m->dz * (double)(nza - 1))));
	for (size_t iz = nza - 1; iz-- > 0;)
		fv[iz] = tiny0(fv[iz + 1] * step);
}

/* acc[it][q] += Re(a[it] out[q]) for every instant. */
static void accumulate(size_t nt, const cplx *a, const cplx *out, double *acc)
{
	for (size_t it = 0; it < nt; it++, acc += FK_COUNT) {
		double ar = creal(a[it]), ai = cimag(a[it]);
		for (int q = 0; q < FK_COUNT; q++)
			acc[q] += ar * creal(out[q]) - ai * cimag(out[q]);
	}
}

/* Add term n of the Durbin series (and of its twin) at one k to every row
 * and instant. */
static void rows_term(struct mapjob *m, const struct anvil_fk_coef *c, size_t n, size_t nza)
{
	const struct anvil_field *f = m->f;
	size_t nt = m->nt;
	int layer = isfinite(f->hh);
	cplx s1 = cexp(-c->al1 * m->dz), s2 = cexp(-c->al2 * m->dz);
	cplx e1 = cexp(-c->al1 * m->z_lo), e2 = cexp(-c->al2 * m->z_lo);
	const cplx *an = m->an + n * nt, *bn = m->bn + n * nt;
	if (layer) {
		rows_bottom(m, c->al1, nza, m->f1);
		rows_bottom(m, c->al2, nza, m->f2);
	}
	for (size_t iz = 0; iz < nza; iz++) {
		cplx out[FK_COUNT];
		anvil_fk_at(c, f->kap2, e1, layer ? m->f1[iz] : 0, e2, layer ? m->f2[iz] : 0, out);
		accumulate(nt, an, out, m->acc + iz * nt * FK_COUNT);
		if (n <= m->w.Mh)
			accumulate(nt, bn, out, m->acch + iz * nt * FK_COUNT);
		e1 = tiny0(e1 * s1);
		e2 = tiny0(e2 * s2);
	}
}

/* y += a x, four at a time so that -O2's straight-line vectoriser packs it. */
static void axpy(size_t n, double a, const double *restrict x, double *restrict y)
{
	size_t i = 0;
	for (; i + 4 <= n; i += 4) {
		y[i] += a * x[i];
		y[i + 1] += a * x[i + 1];
		y[i + 2] += a * x[i + 2];
		y[i + 3] += a * x[i + 3];
	}
	for (; i < n; i++)
		y[i] += a * x[i];
}

/* One row and instant of a node: the static kernels off, then into the
 * Hankel sums of every radius. */
static void node_row_sums(struct mapjob *m, size_t iz, size_t it, const double *st,
			  double wk, double wgs, int tail)
{
	size_t nr = m->nr, base = ((iz * m->nt + it) * HS_COUNT) * nr;
	const double *a = m->acc + (iz * m->nt + it) * FK_COUNT;
	const double *ah = m->acch + (iz * m->nt + it) * FK_COUNT;
	for (int h = 0; h < HS_COUNT; h++) {
		if (!(m->hs & 1u << h))
			continue;
		int q = anvil_fk_of_hs[h];
		const double *J = m->jf + anvil_field_jkind_of_hs[h] * nr;
		double v = a[q] - st[q] * m->Pt[it], vh = ah[q] - st[q] * m->Pth[it];
		size_t o = base + (size_t)h * nr;
		axpy(nr, wk * v, J, m->sK + o);
		if (wgs != 0)
			axpy(nr, wgs * v, J, m->sG + o);
		axpy(nr, wk * vh, J, m->sH + o);
		if (tail)
			axpy(nr, wk * v, J, m->sT + o);
	}
}

static int node_hankel(struct mapjob *m, double k, double wk, double wgs, size_t p,
		       size_t nza)
{
	double zh = anvil_kernel_zhat(k), b[JK_COUNT];
	for (size_t ir = 0; ir < m->nr; ir++) {
		if (anvil_field_bessel_at(k, m->r_lo + m->dr * (double)ir, zh, b))
			return ANVIL_ENUM;
		for (int j = 0; j < JK_COUNT; j++)
			m->jf[j * m->nr + ir] = b[j];
	}
	for (size_t iz = 0; iz < nza; iz++) {
		double st[FK_COUNT];
		anvil_fk_static(k, m->z_lo + m->dz * (double)iz, m->f->nu, st);
		for (size_t it = 0; it < m->nt; it++)
			node_row_sums(m, iz, it, st, wk, wgs, m->npan[iz] == p + 1);
	}
	return ANVIL_OK;
}

static int map_node(struct mapjob *m, double k, double wk, double wgs, size_t p, size_t nza)
{
	const struct anvil_field *f = m->f;
	size_t nacc = nza * m->nt * FK_COUNT;
	memset(m->acc, 0, nacc * sizeof *m->acc);
	memset(m->acch, 0, nacc * sizeof *m->acch);
	for (size_t n = 0; n <= m->w.M; n++) {
		struct anvil_fk_coef c;
		anvil_fk_coef(k, m->w.s[n], f->kap2, f->hh, &c);
		rows_term(m, &c, n, nza);
	}
	for (size_t i = 0; i < nacc; i++)
		if (!isfinite(m->acc[i]))
			return ANVIL_ENUM;
	return node_hankel(m, k, wk, wgs, p, nza);
}

static int map_panels(struct mapjob *m)
{
	const struct anvil_field *f = m->f;
	for (size_t p = 0; p < m->g.np; p++) {
		size_t nza = 0;
		while (nza < m->nz && m->npan[nza] > p)
			nza++;
		if (nza == 0)
			break; /* rows are sorted by depth: deeper ones end sooner */
		for (int j = 0; j < ANVIL_GK21_NODES; j++) {
			double k, wk, wgs;
			anvil_gk21_node(m->g.a[p], m->g.a[p + 1], j, &k, &wk, &wgs);
			int st = map_node(m, k, wk, wgs, p, nza);
			if (st)
				return st;
		}
		if (f->progress && f->progress(f->pctx, (double)(p + 1) / (double)m->g.np, "field"))
			return ANVIL_ECANCEL;
	}
	return ANVIL_OK;
}

/* Unwanted quantities (not computed) as NaN. */
static void drop_unwanted(unsigned want, struct anvil_fval *o)
{
	for (int q = 0; q < ANVIL_FQ_COUNT; q++)
		if (!(want & 1u << q))
			o->v[q] = o->err[q] = NAN;
}

static void map_values(const struct mapjob *m, struct anvil_fval *out)
{
	size_t nr = m->nr, nz = m->nz;
	double fst[HS_COUNT];
	for (size_t iz = 0; iz < nz; iz++) {
		double z = m->z_lo + m->dz * (double)iz, tf = anvil_field_kgrid_tail_factor(&m->g, z);
		for (size_t ir = 0; ir < nr; ir++) {
			anvil_fk_static_field(m->f->nu, m->r_lo + m->dr * (double)ir, z, fst);
			for (size_t it = 0; it < m->nt; it++) {
				struct anvil_field_hsv x = {.tailf = tf};
				size_t base = ((iz * m->nt + it) * HS_COUNT) * nr + ir;
				for (int h = 0; h < HS_COUNT; h++) {
					size_t o = base + (size_t)h * nr;
					x.v[h] = m->sK[o];
					x.dG[h] = m->sK[o] - m->sG[o];
					x.dH[h] = m->sK[o] - m->sH[o];
					x.dT[h] = m->sT[o];
				}
				anvil_field_add_static(m->f, m->tau[it], fst, &x);
				anvil_field_assemble(m->f, &x, &out[(it * nz + iz) * nr + ir]);
				anvil_field_true_contact(m->f, m->r_lo + m->dr * (double)ir, z, m->tau[it],
					     &out[(it * nz + iz) * nr + ir]);
			}
		}
	}
}

static void map_output(const struct mapjob *m, unsigned want, struct anvil_fval *out)
{
	size_t nr = m->nr, nz = m->nz;
	map_values(m, out);
	for (size_t it = 0; it < m->nt; it++)
		anvil_field_error_floor(out + it * nz * nr, nz * nr, 1);
	for (size_t i = 0; i < m->nt * nz * nr; i++)
		drop_unwanted(want, &out[i]);
}

/* A map at the settings of level lv (the peak search locates at draft). */
int anvil_field_map_level(struct anvil_field *f, const flevel_t *lv, size_t nt, const double *t,
		     const struct anvil_field_grid *g, unsigned quantities,
		     struct anvil_fval *out, struct anvil_err *err)
{
	double tau_hi, s = f->c2 / f->r0;
	int st = anvil_field_check_times(f, nt, t, &tau_hi, err);
	if (!st)
		st = anvil_field_check_grid(f, g, err);
	if (st)
		return st;
	unsigned want = quantities ? quantities : (1u << ANVIL_FQ_COUNT) - 1;
	struct mapjob m = {.f = f, .nr = g->nr, .nz = g->nz, .nt = nt, .hs = anvil_field_hs_needed(want)};
	double *tau = malloc(nt * sizeof *tau);
	m.r_lo = g->r_lo / f->r0;
	m.dr = g->nr > 1 ? (g->r_hi - g->r_lo) / f->r0 / (double)(g->nr - 1) : 0;
	m.z_lo = g->z_lo / f->r0;
	m.dz = g->nz > 1 ? (g->z_hi - g->z_lo) / f->r0 / (double)(g->nz - 1) : 0;
	m.tau = tau;
	st = tau ? anvil_field_window_init(f, lv, tau_hi, &m.w) : ANVIL_ENOMEM;
	if (st == ANVIL_EINVAL) { /* the load too long for the series: refused as the budget does */
		mapjob_free(&m);
		free(tau);
		return anvil_field_window_fail(f, "field map", err);
	}
	for (size_t i = 0; tau && i < nt; i++)
		tau[i] = t[i] * s;
	if (!st)
		st = anvil_field_kgrid_init(&m.g, f, lv, &m.w, g->r_hi / f->r0);
	size_t sum = 0;
	for (size_t iz = 0; !st && iz < g->nz; iz++)
		sum += anvil_field_kgrid_panels(&m.g, m.z_lo + m.dz * (double)iz);
	if (!st && (st = anvil_field_check_work(f, &m.w, &m.g, sum, "field map", err))) {
		mapjob_free(&m);
		free(tau);
		return st;
	}
	if (!st)
		st = mapjob_alloc(&m);
	if (!st) {
		mapjob_weights(&m);
		st = map_panels(&m);
	}
	if (!st)
		map_output(&m, want, out);
	mapjob_free(&m);
	free(tau);
	return st ? anvil_field_fail(f, st, "field map", err) : ANVIL_OK;
}

int anvil_field_map(struct anvil_field *f, size_t nt, const double *t,
		    const struct anvil_field_grid *g, unsigned quantities,
		    struct anvil_fval *out, struct anvil_err *err)
{
	return anvil_field_map_level(f, FLEVEL(f->acc), nt, t, g, quantities, out, err);
}
