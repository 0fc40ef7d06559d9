/* impact_wts.c: the weights from the ramps at the grid's times, each
 * made when first needed (issue 11, speed).
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
 * ramp value at most once (the ramps' tables, impact_rtab.c, shared by
 * both passes and by the impacts given the same share), from the same
 * calls in the same order of operands: the same bits as the whole table
 * gave. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "impact_impl.h"

static inline double rraw(const struct ctx *c, int r, size_t u)
{
	return impact_rtab_raw(c, r, u);
}

int impact_wts_span(const struct ctx *c, int L, size_t j0, size_t n, double *g, double *dg)
{
	size_t mn = (size_t)1 << L;
	double dn = ldexp(c->dt0, L);
	int bad = 0;
	/* a window of three sliding along j: each ramp value read once */
	double a[3] = { j0 ? rraw(c, 0, (j0 - 1) * mn) : 0.0, rraw(c, 0, j0 * mn), 0.0 };
	double b[3] = { dg && j0 ? rraw(c, 1, (j0 - 1) * mn) : 0.0, dg ? rraw(c, 1, j0 * mn) : 0.0, 0.0 };
	for (size_t i = 0; i < n; i++) {
		size_t j = j0 + i;
		a[2] = rraw(c, 0, (j + 1) * mn);
		g[i] = (a[2] - 2.0 * a[1] + (j ? a[0] : 0.0)) / dn;
		a[0] = a[1], a[1] = a[2];
		if (dg) {
			b[2] = rraw(c, 1, (j + 1) * mn);
			dg[i] = (b[2] - 2.0 * b[1] + (j ? b[0] : 0.0)) / dn - g[i];
			b[0] = b[1], b[1] = b[2];
		}
		bad |= !isfinite(g[i]) || (dg && !isfinite(dg[i]));
	}
	return bad ? ANVIL_ENUM : ANVIL_OK;
}

int impact_wts_fill(const struct ctx *c, int L, double *g, double *dg, size_t *nf, size_t need)
{
	size_t j0 = *nf;
	if (need <= j0)
		return ANVIL_OK;
	int st = impact_wts_span(c, L, j0, need - j0, g + j0, dg ? dg + j0 : NULL);
	*nf = need;
	return st;
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
