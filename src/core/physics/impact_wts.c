/* impact_wts.c: the ramp responses on the grid and the weights from them,
 * each made once, when first needed (issue 11, speed).
 *
 * The product integration's weights are second differences of the ramp
 * response at the lags j 2^L dt0 (impact.c weights(), impact_grow.c).
 * Made in full they cost a ramp evaluation (a log and two B-splines in a
 * plate's tail) per dt0 of the whole window, twice over for the dt/2
 * pass, while a grown march stops far short of the window's end and reads
 * a level's weights only as far as its convolution and its frozen past's
 * targets reach: on h = 0.05 r0, 10 g at 1 m/s the march ended at 27 % of
 * the window at level 7, so most of the table was never read.  So the
 * weights are made as the march asks (impact_g_need, frozen_chunk), each
 * ramp value at most once per impact (the table, rtab, shared by both
 * passes), from the same calls in the same order of operands: the same
 * bits as the whole table gave.
 *
 * Beyond the table (long mode: it covers the first segment's weights),
 * every level's weights are the same lags j 2^L dt0 from j = 0 again for
 * each segment a level makes (impact_grow.c: a full segment freezes and
 * the same step goes on), and the frozen segments' last hats ask for the
 * same lags target after target: on h = 0.05 r0, 10 kg at 1 m/s 3.7e6
 * ramp calls beyond it were at most 7e5 distinct values.  There a value
 * at U = (2 i + 1) 2^z (in the table's dt0) is kept in row z at i: a
 * level's lags fill its rows densely from 0, and the dt pass's 2u lands
 * where the dt/2 pass's u does, one row up. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "impact_impl.h"

int impact_rtab_alloc(struct rtab *t, size_t n, int two)
{
	size_t nw = n / 64 + 1;
	t->n = n;
	for (int r = 0; r < 1 + !!two; r++) {
		/* malloc and calloc: pages never asked for are never touched */
		t->R[r] = malloc((n ? n : 1) * sizeof *t->R[r]);
		t->have[r] = calloc(nw, sizeof *t->have[r]);
		if (!t->R[r] || !t->have[r])
			return ANVIL_ENOMEM;
	}
	return ANVIL_OK;
}

void impact_rtab_free(struct rtab *t)
{
	if (!t)
		return;
	for (int r = 0; r < 2; r++) {
		free(t->R[r]);
		free(t->have[r]);
		t->R[r] = NULL, t->have[r] = NULL;
		for (int z = 0; z < 64; z++) {
			free(t->row[r][z].v);
			free(t->row[r][z].have);
			t->row[r][z] = (struct rtab_row){ 0 };
		}
	}
	t->n = 0;
}

/* A row's entries at most (8 MB of values): beyond, the calls are made
 * every time (a far lag read once or twice: the nodes' own, rest_cloc). */
#define ROW_MAX ((size_t)1 << 20)

/* Row w with room for i; 0, or -1 when out of memory (or past ROW_MAX). */
static int row_room(struct rtab_row *w, size_t i)
{
	if (i < w->cap)
		return 0;
	if (i >= ROW_MAX)
		return -1;
	size_t cap = w->cap ? w->cap : 1024;
	while (cap <= i)
		cap *= 2;
	double *v = realloc(w->v, cap * sizeof *v);
	if (v)
		w->v = v;
	uint64_t *h = v ? realloc(w->have, (cap / 64) * sizeof *h) : NULL;
	if (!h)
		return -1;
	memset(h + w->cap / 64, 0, (cap - w->cap) / 64 * sizeof *h);
	w->have = h, w->cap = cap;
	return 0;
}

/* The ramp at u dt0 beyond the table: row z's, or by the call (kept). */
static double rfar(const struct ctx *c, int r, size_t u)
{
	struct rtab *t = c->rt;
	size_t U = u << c->rsh, i;
	int z = 0;
	double v;
	if (t && U)
		while (!(U >> z & 1))
			z++;
	i = U >> (z + 1);
	struct rtab_row *w = t && U ? &t->row[r][z] : NULL;
	if (w && i < w->cap && (w->have[i >> 6] >> (i & 63) & 1))
		return w->v[i];
	int st = r ? impact_ramp_of(c, c->ramp2, c->rctx2, (double)u * c->dt0, &v)
		   : impact_ramp_at(c, (double)u * c->dt0, &v);
	if (st)
		return NAN;
	if (w && !row_room(w, i)) {
		w->v[i] = v;
		w->have[i >> 6] |= (uint64_t)1 << (i & 63);
	}
	return v;
}

/* ramp (r = 0) or ramp2 (r = 1) at u dt0 by the call, kept in the table
 * when it is there (tab); NaN when the call fails.  Apart from rraw's
 * lookup, so that the lookup inlines where the weights are made. */
static double rmake(const struct ctx *c, int r, size_t u, int tab)
{
	double v;
	int st = r ? impact_ramp_of(c, c->ramp2, c->rctx2, (double)u * c->dt0, &v)
		   : impact_ramp_at(c, (double)u * c->dt0, &v);
	if (st)
		return NAN;
	if (tab) {
		struct rtab *t = c->rt;
		size_t U = u << c->rsh;
		t->R[r][U] = v;
		t->have[r][U >> 6] |= (uint64_t)1 << (U & 63);
	}
	return v;
}

/* ramp (r = 0) or ramp2 (r = 1) at u dt0: the table's, or by the call
 * that makes it (the same bits); NaN when the call fails. */
static inline double rraw(const struct ctx *c, int r, size_t u)
{
	const struct rtab *t = c->rt;
	size_t U = u << c->rsh;
	int tab = u < c->nR0 && t && U < t->n && t->R[r];
	if (tab && (t->have[r][U >> 6] >> (U & 63) & 1))
		return t->R[r][U];
	return tab || u < c->nR0 ? rmake(c, r, u, tab) : rfar(c, r, u);
}

double impact_rtab(const struct ctx *c, int r, size_t u)
{
	return r ? rraw(c, 1, u) - rraw(c, 0, u) : rraw(c, 0, u);
}

int impact_wts_fill(const struct ctx *c, int L, double *g, double *dg, size_t *nf, size_t need)
{
	size_t j0 = *nf, mn = (size_t)1 << L;
	double dn = ldexp(c->dt0, L);
	if (need <= j0)
		return ANVIL_OK;
	int bad = 0;
	/* a window of three sliding along j: each ramp value read once */
	double a[3] = { j0 ? rraw(c, 0, (j0 - 1) * mn) : 0.0, rraw(c, 0, j0 * mn), 0.0 };
	double b[3] = { dg && j0 ? rraw(c, 1, (j0 - 1) * mn) : 0.0, dg ? rraw(c, 1, j0 * mn) : 0.0, 0.0 };
	for (size_t j = j0; j < need; j++) {
		a[2] = rraw(c, 0, (j + 1) * mn);
		g[j] = (a[2] - 2.0 * a[1] + (j ? a[0] : 0.0)) / dn;
		a[0] = a[1], a[1] = a[2];
		if (dg) {
			b[2] = rraw(c, 1, (j + 1) * mn);
			dg[j] = (b[2] - 2.0 * b[1] + (j ? b[0] : 0.0)) / dn - g[j];
			b[0] = b[1], b[1] = b[2];
		}
		bad |= !isfinite(g[j]) || (dg && !isfinite(dg[j]));
	}
	*nf = need;
	return bad ? ANVIL_ENUM : ANVIL_OK;
}

int impact_g_need(const struct ctx *c, size_t need)
{
	struct ctx *m = (struct ctx *)c; /* a cache: never a const object */
	return impact_wts_fill(c, c->lev, m->g, m->dg, &m->gnf, need < c->ng ? need : c->ng);
}

double impact_g_at(const struct ctx *c, size_t j)
{
	if (j < c->gnf)
		return c->g[j];
	size_t mn = (size_t)1 << c->lev; /* impact_wts_fill's expression */
	double a2 = rraw(c, 0, (j + 1) * mn), a1 = rraw(c, 0, j * mn);
	return (a2 - 2.0 * a1 + (j ? rraw(c, 0, (j - 1) * mn) : 0.0)) / ldexp(c->dt0, c->lev);
}

static int fc_fill(void *ctx, size_t need)
{
	return impact_g_need(ctx, need);
}

struct anvil_fastconv *impact_fc_alloc(struct ctx *c, size_t direct_max)
{
	return anvil_fastconv_alloc_lazy(c->g, c->dg, c->ng, direct_max, c->fft, fc_fill, c);
}
