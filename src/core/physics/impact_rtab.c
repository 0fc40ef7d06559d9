/* impact_rtab.c: the ramp responses at the grid's times, each made once
 * for every impact that reads them (issue 11, speed).
 *
 * The product integration's weights are second differences of the ramp
 * response at the lags j 2^L dt0 (impact_wts.c).  A value R(U dt/2) is a
 * pure function of the ramp, the step and U: the dt and dt/2 passes of an
 * impact read the same ones (the dt pass's u is U = 2u), and so do the
 * impacts of a physical row, four of whose five take the point load's
 * layer correction as their ramp and two of which the same patch's as
 * their ramp2 (solver_phys.c): on h = 0.02 r0, 0.1 g at 10 m/s the row's
 * impacts made 2.42e6 ramp calls through the tables, 1.43e6 distinct.
 * So the tables live in a share that the caller gives every impact of the
 * row (anvil_ramp_share, impact.h), one table per (ramp, step, window),
 * and the impacts, two of which may run side by side on threads, fill
 * them as they go.  Every entry is made by the same call whoever makes it
 * first, so the order of filling cannot change a bit.
 *
 * Thread safety without a lock on the march's path: an entry's value is
 * stored, then its bit set with release order; a reader that sees the bit
 * (acquire) sees the value.  Two threads may both make an entry: they
 * store the same bits, through atomic stores (no data race).  The rows
 * beyond the table come in blocks made when first needed and published by
 * a compare-and-swap, so a block never moves under a reader (the rows were
 * realloc'd arrays when each impact had its own).  Only finding or adding
 * a table takes the share's lock, once per impact and ramp. */
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "impact_impl.h"

struct anvil_ramp_share {
	pthread_mutex_t lock; /* the list of tables (not their entries), and rw, hw */
	struct rtab *head;
	/* the frozen past's FFT tables by log2 of the size (impact_share_fft) */
	gsl_fft_real_wavetable *rw[HIST_FFT_MAX];
	gsl_fft_halfcomplex_wavetable *hw[HIST_FFT_MAX];
};

/* Made once for every impact of the share: a row's five impacts each made
 * their own, the same trigonometric tables (h = 0.02 r0, 0.1 g at 1 m/s:
 * 3 % of the run); GSL only reads them (const), so threads may share. */
int impact_share_fft(struct anvil_ramp_share *s, int lg, const gsl_fft_real_wavetable **rw,
		     const gsl_fft_halfcomplex_wavetable **hw)
{
	size_t N = (size_t)1 << lg;
	pthread_mutex_lock(&s->lock);
	if (!s->rw[lg] || !s->hw[lg]) {
		if (!s->rw[lg])
			s->rw[lg] = gsl_fft_real_wavetable_alloc(N);
		if (!s->hw[lg])
			s->hw[lg] = gsl_fft_halfcomplex_wavetable_alloc(N);
	}
	*rw = s->rw[lg], *hw = s->hw[lg];
	pthread_mutex_unlock(&s->lock);
	return *rw && *hw ? ANVIL_OK : ANVIL_ENOMEM;
}

struct anvil_ramp_share *anvil_ramp_share_alloc(void)
{
	struct anvil_ramp_share *s = calloc(1, sizeof *s);
	if (s && pthread_mutex_init(&s->lock, NULL)) {
		free(s);
		return NULL;
	}
	return s;
}

static void rtab_free(struct rtab *t)
{
	if (t->rows)
		for (size_t k = 0; k < 64 * RTAB_ROW_BLKS; k++)
			free(atomic_load_explicit(&t->rows[k], memory_order_relaxed));
	free(t->rows);
	free(t->R);
	free(t->have);
	free(t);
}

void anvil_ramp_share_free(struct anvil_ramp_share *s)
{
	if (!s)
		return;
	for (struct rtab *t = s->head, *nx; t; t = nx) {
		nx = t->next;
		rtab_free(t);
	}
	for (int k = 0; k < HIST_FFT_MAX; k++) {
		gsl_fft_real_wavetable_free(s->rw[k]);
		gsl_fft_halfcomplex_wavetable_free(s->hw[k]);
	}
	pthread_mutex_destroy(&s->lock);
	free(s);
}

static int key_eq(const struct rtab_key *a, const struct rtab_key *b)
{
	return a->p == b->p && a->fn == b->fn && a->ctx == b->ctx && a->name[0] == b->name[0] &&
	       a->name[1] == b->name[1] && a->name[2] == b->name[2] && a->dt0 == b->dt0 &&
	       a->n == b->n && a->off == b->off;
}

/* A table of k->n entries and its rows' block pointers; NULL when out of
 * memory.  malloc and calloc: pages never asked for are never touched. */
static struct rtab *rtab_alloc(const struct rtab_key *k)
{
	struct rtab *t = calloc(1, sizeof *t);
	if (!t)
		return NULL;
	t->key = *k;
	t->R = malloc((k->n ? k->n : 1) * sizeof *t->R);
	t->have = calloc(k->n / 64 + 1, sizeof *t->have);
	t->rows = calloc(64 * RTAB_ROW_BLKS, sizeof *t->rows);
	if (!t->R || !t->have || !t->rows) {
		rtab_free(t);
		return NULL;
	}
	return t;
}

struct rtab *impact_rtab_get(struct anvil_ramp_share *s, const struct rtab_key *k)
{
	struct rtab *t;
	pthread_mutex_lock(&s->lock);
	for (t = s->head; t && !key_eq(&t->key, k); t = t->next)
		;
	if (!t && (t = rtab_alloc(k))) {
		t->next = s->head;
		s->head = t;
	}
	pthread_mutex_unlock(&s->lock);
	return t;
}

/* Row z's block b, made when missing (NULL when out of memory). */
static struct rtab_blk *row_blk(struct rtab *t, int z, size_t b)
{
	struct rtab_blk *_Atomic *slot = &t->rows[(size_t)z * RTAB_ROW_BLKS + b];
	struct rtab_blk *old = atomic_load_explicit(slot, memory_order_acquire), *nb;
	if (old || !(nb = malloc(sizeof *nb)))
		return old;
	/* the bits cleared, the values left: none is read before its bit */
	for (size_t w = 0; w < RTAB_BLK / 64; w++)
		atomic_init(&nb->have[w], 0);
	if (atomic_compare_exchange_strong_explicit(slot, &old, nb, memory_order_acq_rel,
						    memory_order_acquire))
		return nb;
	free(nb); /* another thread's came first: old is it */
	return old;
}

/* ramp (r = 0) or ramp2 (r = 1) at u dt0 by the call; NaN when it fails. */
static double rcall(const struct ctx *c, int r, size_t u)
{
	double v;
	int st = r ? impact_ramp_of(c, c->ramp2, c->rctx2, (double)u * c->dt0, &v)
		   : impact_ramp_at(c, (double)u * c->dt0, &v);
	return st ? NAN : v;
}

/* Set the entry's value, then its bit (release: the value first). */
static void put(_Atomic double *R, _Atomic uint64_t *have, size_t i, double v)
{
	atomic_store_explicit(&R[i], v, memory_order_relaxed);
	atomic_fetch_or_explicit(&have[i >> 6], (uint64_t)1 << (i & 63), memory_order_release);
}

/* Table t's entry at U in its rows (U = (2 i + 1) 2^z kept in row z at
 * i), its block made when missing; NULL for U = 0, past ROW_MAX, or out
 * of memory (the value then not kept). */
static struct rtab_blk *row_at(struct rtab *t, size_t U, size_t *k)
{
	if (!t || !U)
		return NULL;
	int z = impact_rtab_ctz(U);
	size_t i = U >> (z + 1);
	if (i >= RTAB_ROW_MAX)
		return NULL;
	*k = i & (RTAB_BLK - 1);
	return row_blk(t, z, i >> RTAB_BLK_LG);
}

/* The ramp at u dt0 beyond the table: in its rows, or by the call (kept).
 * A level's lags fill its rows densely from 0, and the dt pass's 2u lands
 * where the dt/2 pass's u does, one row up. */
static double rfar(const struct ctx *c, int r, size_t u)
{
	size_t k = 0;
	struct rtab_blk *b = row_at(c->rt[r], u << c->rsh, &k);
	if (b && (atomic_load_explicit(&b->have[k >> 6], memory_order_acquire) >> (k & 63) & 1))
		return atomic_load_explicit(&b->v[k], memory_order_relaxed);
	double v = rcall(c, r, u);
	if (b && !isnan(v))
		put(b->v, b->have, k, v);
	return v;
}

/* The table of ramp r off the grid by d (at j dt0 + d, the pass's dt0):
 * the ctx's cache's (the same few d's for every contact end of a
 * segment), else the share's; NULL when out of memory. */
static struct rtab *off_tab(const struct ctx *c, int r, double d)
{
	struct ctx *m = (struct ctx *)c; /* a cache: never a const object */
	for (int i = 0; i < IMPACT_OFF_TABS; i++)
		if (c->off[i].t && c->off[i].r == r && c->off[i].d == d && c->off[i].dt0 == c->dt0)
			return c->off[i].t;
	if (!c->share || !c->rt[r])
		return NULL;
	struct rtab_key k = c->rt[r]->key;
	k.dt0 = c->dt0, k.n = 0, k.off = d;
	struct rtab *t = impact_rtab_get(c->share, &k);
	int i = m->noff++ % IMPACT_OFF_TABS;
	m->off[i].t = t, m->off[i].r = r, m->off[i].d = d, m->off[i].dt0 = c->dt0;
	return t;
}

int impact_rtab_off(const struct ctx *c, int r, size_t j, double d, double *val)
{
	size_t k = 0;
	struct rtab_blk *b = row_at(off_tab(c, r, d), j, &k);
	if (b && (atomic_load_explicit(&b->have[k >> 6], memory_order_acquire) >> (k & 63) & 1)) {
		*val = atomic_load_explicit(&b->v[k], memory_order_relaxed);
		return ANVIL_OK;
	}
	int st = impact_ramp_of(c, r ? c->ramp2 : c->ramp, r ? c->rctx2 : c->rctx,
				(double)j * c->dt0 + d, val);
	if (b && !st && !isnan(*val))
		put(b->v, b->have, k, *val);
	return st;
}

double impact_rtab_make(const struct ctx *c, int r, size_t u)
{
	struct rtab *t = c->rt[r];
	size_t U = u << c->rsh;
	if (u >= c->nR0)
		return rfar(c, r, u);
	double v = rcall(c, r, u);
	if (t && U < t->key.n && !isnan(v))
		put(t->R, t->have, U, v);
	return v;
}

double impact_rtab(const struct ctx *c, int r, size_t u)
{
	return r ? impact_rtab_raw(c, 1, u) - impact_rtab_raw(c, 0, u) : impact_rtab_raw(c, 0, u);
}
