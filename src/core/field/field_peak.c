/* field_peak.c: the peak of von Mises in space and time (field.h,
 * anvil_field_peak), from maps. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "field_impl.h"

/* The exhaustive search: a coarse space-time grid at draft settings (it
 * only has to find the right neighbourhood: von Mises varies on the scale
 * of r0 and of the contact time), r0/8 apart in the top 3 r0 where the
 * contact stresses are (the Hertz maximum is 0.5 r0 deep) and r0/2 below
 * (bending), then a finer grid one coarse cell around the best point at
 * the field's own settings, whose best point is the answer. */
#define PEAK_NR 25
#define PEAK_NT 12
#define PEAK_FINE 7
#define PEAK_NEAR 3.0 /* r0 */

struct peak_cell {
	double dr, dz, dt; /* the coarse spacing around the best point */
};

/* A map over instants t[0..nt) and grid g; its largest von Mises into pk
 * when it beats pk's (cell: the grid's spacing, for the refinement), and,
 * bound not NULL, the largest von Mises plus its error estimate into
 * *bound when larger. */
static int peak_pass(struct anvil_field *f, const flevel_t *lv, size_t nt, const double *t,
		     const struct anvil_field_grid *g, struct anvil_field_peak *pk,
		     struct peak_cell *cell, double *bound, struct anvil_err *err)
{
	size_t n = nt * g->nz * g->nr, b = 0;
	struct anvil_fval *v = malloc(n * sizeof *v);
	if (!v)
		return anvil_err_set(err, ANVIL_ENOMEM, "field: out of memory");
	int st = anvil_field_map_level(f, lv, nt, t, g, 1u << ANVIL_FQ_VM, v, err);
	for (size_t i = 0; !st && i < n; i++) {
		if (v[i].v[ANVIL_FQ_VM] > v[b].v[ANVIL_FQ_VM])
			b = i;
		if (bound && !(v[i].v[ANVIL_FQ_VM] + v[i].err[ANVIL_FQ_VM] <= *bound))
			*bound = v[i].v[ANVIL_FQ_VM] + v[i].err[ANVIL_FQ_VM];
	}
	if (!st && !(v[b].v[ANVIL_FQ_VM] <= pk->vm)) {
		size_t it = b / (g->nz * g->nr), iz = (b / g->nr) % g->nz, ir = b % g->nr;
		double dr = g->nr > 1 ? (g->r_hi - g->r_lo) / (double)(g->nr - 1) : 0;
		double dz = g->nz > 1 ? (g->z_hi - g->z_lo) / (double)(g->nz - 1) : 0;
		pk->vm = v[b].v[ANVIL_FQ_VM];
		pk->vm_err = v[b].err[ANVIL_FQ_VM];
		pk->t = t[it];
		pk->z = g->z_lo + dz * (double)iz;
		pk->r = g->r_lo + dr * (double)ir;
		*cell = (struct peak_cell){dr, dz, nt > 1 ? t[1] - t[0] : 0};
	}
	free(v);
	return st;
}

/* [x - d, x + d] within [lo, hi]. */
static void around(double x, double d, double lo, double hi, double *a, double *b)
{
	*a = fmax(lo, x - d);
	*b = fmin(hi, x + d);
}

/* The coarse pass over the whole layer and load at level lv. */
static int peak_coarse(struct anvil_field *f, const flevel_t *lv, struct anvil_field_peak *pk,
		       struct peak_cell *cell, double *bound, struct anvil_err *err)
{
	double h = anvil_field_h(f), r0 = f->r0, tl = anvil_field_t_load(f), t[PEAK_NT];
	double znear = isfinite(h) ? fmin(h, PEAK_NEAR * r0) : PEAK_NEAR * r0;
	size_t nz = (size_t)ceil(8.0 * znear / r0) + 1;
	struct anvil_field_grid g = {0, PEAK_NEAR * r0, 0, znear, PEAK_NR, nz < 2 ? 2 : nz};
	for (int i = 0; i < PEAK_NT; i++)
		t[i] = tl * (i + 1) / PEAK_NT;
	int st = peak_pass(f, lv, PEAK_NT, t, &g, pk, cell, bound, err);
	if (st || !isfinite(h) || !(h > znear))
		return st;
	g.z_lo = znear;
	g.z_hi = h;
	g.nz = (size_t)fmin(41.0, ceil(2.0 * (h - znear) / r0) + 1);
	return peak_pass(f, lv, PEAK_NT, t, &g, pk, cell, bound, err);
}

/* The true contact's peak lies at 0.48 a (nu = 0.3) below it, a << r0 for
 * a ball: under the coarse grid.  A pass over the top 2 a_max, a_max/8
 * apart, at instants around the peak force a quarter of the coarse step
 * apart (the Hertz field scales with a(t) and p0(t), both flat there). */
#define CONTACT_NR 17
#define CONTACT_NZ 17
#define CONTACT_NT 5
static int peak_contact(struct anvil_field *f, struct anvil_field_peak *pk,
			struct peak_cell *cell, struct anvil_err *err)
{
	size_t im = 0;
	for (size_t i = 1; i < f->nP; i++)
		if (f->P[i] > f->P[im])
			im = i;
	double tl = anvil_field_t_load(f), dt = tl / PEAK_NT / 4, t[CONTACT_NT];
	double tm = (double)im * f->dtau * f->r0 / f->c2, h = anvil_field_h(f);
	double a = anvil_field_contact_radius(f, f->P[im]);
	if (!(a > 0))
		return ANVIL_OK;
	for (int i = 0; i < CONTACT_NT; i++)
		t[i] = fmin(tl, fmax(0.5 * dt, tm + (i - CONTACT_NT / 2) * dt));
	struct anvil_field_grid g = {0, 2 * a, 0, fmin(2 * a, h), CONTACT_NR, CONTACT_NZ};
	return peak_pass(f, FLEVEL(ANVIL_ACC_DRAFT), CONTACT_NT, t, &g, pk, cell, NULL, err);
}

/* The fine pass, one cell around pk's point at the field's own level:
 * pk's value and place become its best point's. */
static int peak_fine(struct anvil_field *f, const struct peak_cell *cell,
		     struct anvil_field_peak *pk, struct anvil_err *err)
{
	double h = anvil_field_h(f), rmax = PEAK_NEAR * f->r0, zmax = isfinite(h) ? h : rmax;
	double tl = anvil_field_t_load(f), t0, t1, tf[PEAK_FINE];
	struct anvil_field_grid g = {0};
	struct peak_cell fc;
	around(pk->r, cell->dr, 0, rmax, &g.r_lo, &g.r_hi);
	around(pk->z, cell->dz, 0, zmax, &g.z_lo, &g.z_hi);
	around(pk->t, cell->dt, 0.5 * cell->dt, tl, &t0, &t1);
	g.nr = g.nz = PEAK_FINE;
	for (int i = 0; i < PEAK_FINE; i++)
		tf[i] = t0 + (t1 - t0) * i / (PEAK_FINE - 1);
	pk->vm = -1;
	return peak_pass(f, FLEVEL(f->acc), PEAK_FINE, tf, &g, pk, &fc, NULL, err);
}

static void peak_start(struct anvil_field_peak *pk)
{
	memset(pk, 0, sizeof *pk);
	pk->vm = -1;
	pk->elsewhere = NAN;
}

static void peak_yield(double yield, struct anvil_field_peak *pk)
{
	pk->yield = yield > 0 ? yield : 0.0;
	pk->exceeded = pk->yield > 0 && pk->vm > pk->yield;
}

int anvil_field_peak_exhaustive(struct anvil_field *f, double yield,
				struct anvil_field_peak *pk, struct anvil_err *err)
{
	struct peak_cell cell = {0};
	peak_start(pk);
	int st = peak_coarse(f, FLEVEL(ANVIL_ACC_DRAFT), pk, &cell, NULL, err);
	if (!st && f->true_contact)
		st = peak_contact(f, pk, &cell, err);
	if (!st)
		st = peak_fine(f, &cell, pk, err);
	peak_yield(yield, pk);
	return st;
}

/* The global pass's Durbin terms, per level: its cost grows like the
 * square of the load's length (terms, and k panels no wider than the
 * poles' distance c0 ~ 1/t_load), which on thin layers with long or
 * repeated contacts (h = 0.35 r0: 2.9 ms, 1367 terms at draft) made it
 * 95 % of the verdict.  Capped, its bandwidth falls below the load's for
 * long loads, and its error estimates (the twin at 2/3 of the band) grow
 * to say so: the bound below holds them.  Loads of the paper's kind
 * (h >= r0, under 100 us) stay under the cap: their pass is unchanged. */
static const double global_terms[ANVIL_ACC_COUNT] = {64, 128, 256, 512};

/* Draft settings with the bandwidth cut to the cap for a load this long. */
static flevel_t global_level(const struct anvil_field *f)
{
	flevel_t lv = *FLEVEL(ANVIL_ACC_DRAFT);
	double om = global_terms[f->acc] * M_PI / (lv.tw * f->tau_load);
	lv.omega_min = fmin(lv.omega_min, om);
	lv.cycles = fmin(lv.cycles, om * f->tau_load);
	return lv;
}

/* The true contact: the contact's neighbourhood first (cheap: its
 * instants end soon after the peak force), then the global pass bounds
 * the rest; refined only where its bound reaches the contact's peak. */
static int peak_true_contact(struct anvil_field *f, struct anvil_field_peak *pk,
			     struct anvil_err *err)
{
	struct peak_cell cc = {0}, gc = {0};
	struct anvil_field_peak g;
	double bound = -INFINITY;
	flevel_t lv = global_level(f);
	int st = peak_contact(f, pk, &cc, err);
	if (!st)
		st = pk->vm > 0 ? peak_fine(f, &cc, pk, err) : ANVIL_OK;
	peak_start(&g);
	if (!st)
		st = peak_coarse(f, &lv, &g, &gc, &bound, err);
	if (st)
		return st;
	pk->elsewhere = bound;
	if (bound <= pk->vm)
		return ANVIL_OK; /* nothing away from the contact can beat it */
	st = peak_fine(f, &gc, &g, err);
	if (!st && g.vm > pk->vm) {
		g.elsewhere = bound;
		*pk = g;
	}
	return st;
}

int anvil_field_peak(struct anvil_field *f, double yield, struct anvil_field_peak *pk,
		     struct anvil_err *err)
{
	if (!f->true_contact)
		return anvil_field_peak_exhaustive(f, yield, pk, err);
	peak_start(pk);
	int st = peak_true_contact(f, pk, err);
	peak_yield(yield, pk);
	return st;
}
