/* impact_impl.h: what impact.c (the march) and impact_end.c (the exact
 * end of a contact) share.  Internal to the physics module. */
#ifndef ANVIL_IMPACT_IMPL_H
#define ANVIL_IMPACT_IMPL_H

#include <limits.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include <gsl/gsl_fft_halfcomplex.h>
#include <gsl/gsl_fft_real.h>

#include "fastconv.h"
#include "impact.h"

/* The end of a contact is located by Brent on the exact asymmetric last
 * hat; the past older than this many steps enters through a cubic in the
 * end offset d (error O(dt^4) of a smooth sum), so that each Brent
 * iteration costs O(IMPACT_END_NEAR), not O(n). */
#define IMPACT_END_NEAR 256
/* A pass's status when it makes more contacts than the budget
 * (opts.max_contacts): ANVIL_ETOL to the caller, with t_s finite (no
 * longer window tried) and its own message. */
/* A pass's status when a contact's end cannot be bracketed (finish_exact):
 * ANVIL_ENUM to the caller, with a message that says when and what to do. */
#define IMPACT_END_LOST (-101)
/* The contact budget (ANVIL_MAX_CONTACTS) spent: the march stops. */
#define IMPACT_BUDGET (-100)
/* Long mode: the grown march needs more nodes than max_nodes (or its
 * first segment more than its weights): ANVIL_ETOL, t_s infinite. */
#define IMPACT_NODES (-102)

/* The off-grid ramp tables a ctx keeps at hand (impact_rtab_off): ramp
 * and ramp2 at the two offsets of a segment's contact ends, and room. */
#define IMPACT_OFF_TABS 8
/* The most segments (levels of the step) a pass can have (impact_grow.c). */
#define IMPACT_MAX_SEGS 64
/* The largest FFT of the frozen past: 2^(HIST_FFT_MAX - 1). */
#define HIST_FFT_MAX 40

/* One time-stepping pass.  Arrays are per node n = 0..n-1, at times t[n].
 * The step is dt0 2^L on segment k (L = seg_L[k], from node seg_n[k]);
 * dt is the current segment's (the whole pass's when it never grows). */
struct pass {
	double dt, dt0;
	size_t n, cap;
	size_t nseg, seg_n[IMPACT_MAX_SEGS];
	int seg_L[IMPACT_MAX_SEGS];
	double *t;             /* node times (s) */
	double *P, *W, *w, *v; /* one block, owned */
	double *wc;            /* physical contact: the layer correction's deflection */
	double *Q;             /* physical contact: P alpha_H / alpha_ref (true radius) */
	double *sg;            /* physical contact: the second order's offset at
				* alpha = 0, c_u u^2 (impact.c, lag2), m */
	double ts, tmax, Pmax, Vs;
	double tmax_ie;  /* the peak interpolation's own error (peak) */
	double curv;     /* |P''| at the peak (N/s^2, peak), 0 when unknown */
	/* repeated contacts: the count, each one's start and end (s) */
	size_t ncont;
	double on[ANVIL_MAX_CONTACTS], off[ANVIL_MAX_CONTACTS];
	int parted;      /* 1: parted for good by the rule; 2: at the window's end;
			  * 3: moving together at the window's end (co_moving) */
	/* a separation not yet decided (merge_sep): the last node in contact
	 * (0: none), the impulse up to it, A at the next node, the largest gap */
	size_t pend_k;
	double pend_imp, pend_a, sep_gap;
	size_t nmerged;  /* separations merged into their contact */
	double Pmax_run; /* the largest P so far (co_moving) */
	/* the rest state (impact_rest.c): rest_k the first node at rest (0:
	 * none), with the contacts then and the rebound's bound (relative to
	 * V0); rest 1 when the pass ended there (t_s = t[rest_k]); rest_t2 the
	 * first co-moving node's time with the bound within twice rest_tol
	 * (0: none), what t_s's sensitivity is measured against */
	int rest;
	size_t rest_k, rest_ncont;
	double rest_bound, rest_t2;
};

/* A frozen segment of a grown step (impact_grow.c): its nodes 1 .. S-1
 * (x, z: P and Q from its node 0, the pass's arrays) at dt0 2^L from t =
 * K dt0, against its weights g, dg (owned, ng of them); its last node
 * (Pb, Qb at Kb dt0) with its step left and dt0 2^Ln right. */
/* The far field (long mode, impact_grow.c): its charges at FAR_P
 * Chebyshev points. */
#define FAR_P 8

struct frozen {
	const double *x, *z;
	size_t S, K, Kb, ng, nf; /* nf: its weights made so far (impact_wts.c) */
	int L, Ln;
	double *g, *dg;
	double Pb, Qb;
	/* long mode: the pass's node of its node 0; targets at u dt0 >=
	 * t_far take the far field: the charges Wx (P), Wz (Q) at times tc */
	size_t n0;
	double t_far, tb, ta; /* ta, tb: its first and last charges' times */
	double tc[FAR_P], Wx[FAR_P], Wz[FAR_P];
	/* its far field's last run (impact_far.c): its interpolant's Chebyshev
	 * coefficients over [rt0, rt1] (none while rt1 <= rt0) */
	double rt0, rt1, ra[FAR_P];
	/* its hats' FFT (x's, then z's) at the size 2^xlg of the last chunk
	 * (frozen_chunk): the same for every chunk of that size */
	double *xf;
	int xlg;
};

struct ctx {
	const struct anvil_params *p;
	anvil_ramp_fn ramp;
	void *rctx;
	double tau_avail;
	double *g;      /* convolution weights g_j, j < ng, made below gnf (impact_wts.c) */
	size_t ng, gnf;
	int physical;   /* the physical contact (opts), with beta */
	double beta;
	double g2;      /* the lag's next term (opts); 0: first order */
	anvil_ramp_fn ramp2; /* the correction of the patch of radius a_ref (opts) */
	void *rctx2;
	double alpha_ref;
	double tau_lag; /* the lag's low-pass (opts), s; 0: none */
	double *dg;     /* its weights less g's, when ramp2 is given */
	/* sum_m P_m g_{n-m}, for the pass at hand; with dg, a pair (fastconv.h)
	 * that adds sum_m Q_m dg_{n-m} (physical, ramp2 given) */
	struct anvil_fastconv *fc;
	struct end_tab *tab; /* the contact ends' ramp values, for the pass at hand */
	struct anvil_fastconv_fft *fft; /* FFT tables of both passes */
	double merge_gap, merge_time; /* merge_sep (opts): relative to alpha_max, s */
	size_t max_contacts;          /* the budget (opts); 0: none */
	double rest_tol;  /* the rest state (opts); 0: off */
	double rest_stop; /* s: the coarse pass came to rest here, the finer stops too; 0: none */
	double rest_long; /* s: a contact longer co-moves (impact_rest_long) */
	int rest_last;    /* the caller's last window (opts): fall back to rest at its end */
	/* The growing step (impact_grow.c; impact.h, grow_after). */
	size_t grow_after;   /* nodes before the step may grow; 0: never */
	double grow_eta;     /* the smoothness asked of P (impact.h) */
	const struct pass *sched; /* the schedule to follow (the dt/2 pass), or NULL */
	struct rtab *rt[2];  /* ramp and ramp2 at j dt0 as made (impact_rtab.c): j < nR0 in its table, beyond in its rows */
	struct anvil_ramp_share *share; /* rt's, and the off-grid tables' */
	/* the off-grid tables last used (impact_rtab_off), IMPACT_OFF_TABS of
	 * them, the oldest replaced first */
	struct {
		struct rtab *t;
		int r;
		double d, dt0;
	} off[IMPACT_OFF_TABS];
	unsigned noff;
	int rsh;             /* the pass's j is the table's j << rsh */
	size_t nR;           /* the window's end, in dt0, plus one */
	size_t nR0;          /* the table's reach (nR but in long mode) */
	int lng;             /* long mode (impact.h, t_smooth) */
	double t_smooth;
	size_t max_nodes;    /* long mode: the dt pass's nodes at most */
	anvil_ramp_fn imp[2]; /* the impulse responses (impact.h), or NULL */
	void *ictx[2];
	/* the current segment: from node seg0 at t = T0 = K0 dt0, step dt0 2^lev,
	 * segcap nodes at most; Ih and M1h the frozen past's int P and int t P
	 * (0 on the first segment) */
	double dt0;
	size_t seg0, K0, segcap;
	int lev;
	double T0, Ih, M1h;
	/* the frozen segments, oldest first (impact_grow.c) */
	size_t nfz;
	struct frozen fz[IMPACT_MAX_SEGS];
	/* its deflection at the segment's nodes hlo .. hlo + hn - 1 (a chunk) */
	double *hbuf;
	size_t hlo, hn, hcap;
	/* its FFT tables, by log2 of the size, made when first needed: the
	 * share's (impact_share_fft; its own when there is none), and its
	 * workspaces, kept for both passes (impact_grow_free) */
	const gsl_fft_real_wavetable *rw[HIST_FFT_MAX];
	const gsl_fft_halfcomplex_wavetable *hw[HIST_FFT_MAX];
	gsl_fft_real_workspace *ws[HIST_FFT_MAX];
	/* frozen_chunk's arrays, kept for the next chunk (a fresh calloc of
	 * that size is fresh pages: a fault each 4 kB) */
	double *hwk;
	size_t hwcap;
	/* the far field of the oldest frozen segments 0 .. nmg - 1 as one set
	 * of charges (impact_far_merge; nmg = 0: none), for the targets at
	 * mg.t_far and beyond, where each of them would take its own */
	size_t nmg;
	struct frozen mg;
};

/* The ramp responses off the grid that the far past needs at every
 * contact end of a pass: R(j dt + d_i), d_i = i dt/3 (i = 1, 2, 3; end_ctx_init),
 * for IMPACT_END_NEAR <= j < len (the far past's lags), through ramp (r =
 * 0) and ramp2 (r = 1).  Filled once per pass
 * as far as the latest end needs, so a contact end costs O(n) sums, not
 * O(n) ramp evaluations, and the repeated contacts of a thin plate reuse
 * them; the values are those each end computed for itself (same bits). */
struct end_tab {
	size_t len[2][4];
	double *R[2][4]; /* cap + 1 each, allocated when first needed */
};

/* Dimensional ramp response Rr(t) (m s/N): the anvil's response to P = t
 * through fn (impact_ramp_at: the pass's own ramp). */
int impact_ramp_of(const struct ctx *c, anvil_ramp_fn fn, void *ctx, double t, double *val);
int impact_ramp_at(const struct ctx *c, double t, double *val);

void impact_end_tab_free(struct end_tab *t);
/* The end of the contact whose last node in contact is k = s->n - 1:
 * *toff its time, *ioff the impulse up to it (impulse: up to t_k).
 * ANVIL_OK, ANVIL_ENOMEM, ANVIL_ENUM, or IMPACT_END_LOST (*toff = t_k). */
int impact_finish_exact(const struct ctx *c, const struct pass *s, double impulse, double *toff,
			double *ioff);

/* The time beyond which one contact is a co-moving one (s): twice
 * Hertz's on a rigid anvil. */
double impact_rest_long(const struct anvil_params *p);
/* The rest state (impact.h, rest_tol; impact_rest.c).  At node n of the
 * pass (in: in contact; the pass's arrays filled to n): keeps the first
 * node at rest; 1 when the pass is to stop there (a forced stop,
 * rest_stop: s ended as by impact_rest_fallback), 0 to go on.  Call once
 * per node, after the node's time and values are set. */
int impact_rest_check(const struct ctx *c, struct pass *s, size_t n, int in);
/* Whether a pass at its window's end in contact (in) or moving in falls
 * back to its rest: the caller's last window (rest_last), the contact at
 * rest held to here, or the impactor has chattered on the plate since. */
int impact_rest_final(const struct ctx *c, const struct pass *s, int in);
/* The pass ends at its first node at rest, if it had one (1; s->rest,
 * n, ncont, ts, Vs set: the contact goes on); else 0, s unchanged. */
int impact_rest_fallback(struct pass *s);
/* 1 when pass s, which ended with the impulse ioff, came to rest before
 * (its first node at rest kept) and parts with a rebound below 1e-6 V0
 * (in long mode: within rest_tol): a grazing end, whose time no estimate
 * bounds (impact_rest.c); the rest state then answers. */
int impact_rest_grazing(const struct ctx *c, const struct pass *s, double ioff);
/* The result of two passes either of which came to rest (after fill):
 * R_f and E_a as the intervals the bound allows, t_s the rest's time,
 * r->rest_bound. */
/* The part of t_s's estimate the end's flatness adds (impact_end.c): how
 * long before the finer pass's end the approach stays within its error
 * of 0, beyond the passes' difference of t_s (s). */
double impact_graze_ts(const struct pass *a, const struct pass *b);
void impact_rest_fill(struct anvil_result *r, const struct anvil_params *p, const struct pass *a,
		      const struct pass *b);
/* The growing step (impact_grow.c). */
/* The level the segment starting at node n - 1 takes (> c->lev), or 0 when
 * the step stays. */
int impact_grow_due(const struct ctx *c, const struct pass *s, size_t n, int in);
/* Freeze the current segment and start a new one at node s->n - 1 with the
 * step dt0 2^L: the frozen past's moments, the new weights and convolution.
 * ANVIL_OK, ANVIL_ENOMEM, or ANVIL_EINVAL (no room left in the window). */
int impact_grow_switch(struct ctx *c, struct pass *s, int L);
/* The frozen past's deflection (w; w_c when physical) at the current
 * segment's node i, in chunks as the march goes (impact_hist), or alone
 * (impact_hist_one: NaN when out of the weights).  ANVIL_OK, ANVIL_ENOMEM. */
int impact_hist(struct ctx *c, size_t i, double *val);
double impact_hist_one(const struct ctx *c, size_t i);
/* Free the frozen segments' weights (a new pass). */
void impact_grow_reset(struct ctx *c);
/* impact_grow_reset and the frozen past's FFT tables (the impact's end). */
void impact_grow_free(struct ctx *c);
/* The frozen past's deflection at the current segment's node k plus d
 * (0 <= d <= its step), by direct sums over its hats (off the grid: the
 * contact end); v the current segment's view. */
int impact_hist_at(const struct ctx *c, const struct pass *v, size_t k, double d, double *val);
/* impact_rtab.c: the ramp responses at the grid's times, made when first
 * asked for and kept for every impact given the same share.
 *
 * A table is one ramp's at U dt0 (dt0: the dt/2 pass's; the dt pass's u
 * is U = 2u, the same double: (2u)(dt/2) and u dt are the one real
 * product rounded, so the same call's same bits), for U < n in R, beyond
 * in its rows.  A bit per entry says it is made (set after the value,
 * with release order: impact_rtab.c). */
struct rtab_key {
	const struct anvil_params *p; /* the ramp's scaling (impact_ramp_of) */
	anvil_ramp_fn fn;
	const void *ctx; /* fn's context: the impact's own share; else NULL */
	double name[3];  /* the caller's name of the ramp (impact.h) */
	double dt0;
	size_t n;
	double off; /* > 0: the values at j dt0 + off, all in the rows (n = 0) */
};
/* A row's block: 2^RTAB_BLK_LG entries; a row has RTAB_ROW_BLKS of them. */
#define RTAB_BLK_LG 12
#define RTAB_BLK ((size_t)1 << RTAB_BLK_LG)
#define RTAB_ROW_BLKS 256
struct rtab_blk {
	_Atomic uint64_t have[RTAB_BLK / 64];
	_Atomic double v[RTAB_BLK];
};
struct rtab {
	struct rtab_key key;
	_Atomic double *R; /* key.n entries */
	_Atomic uint64_t *have;
	/* beyond: U = (2 i + 1) 2^z kept in row z at i, the row's blocks
	 * rows[z RTAB_ROW_BLKS + i / RTAB_BLK] (NULL until made) */
	struct rtab_blk *_Atomic *rows;
	struct rtab *next; /* the share's list */
};
/* A row's entries at most (2^20; 8 MB of values): beyond, the calls are
 * made every time (a far lag read once or twice: the nodes' own,
 * rest_cloc). */
#define RTAB_ROW_MAX ((size_t)RTAB_ROW_BLKS << RTAB_BLK_LG)
/* The count of U's trailing zero bits (U > 0): one instruction where
 * the compiler has it (the loop, bit by bit, was a fifth of the tables'
 * own time on h = 0.02 r0, 1 kg at 0.1 m/s: a grown level's lags are
 * multiples of 2^L). */
static inline int impact_rtab_ctz(size_t U)
{
#if defined(__GNUC__) && SIZE_MAX == ULLONG_MAX
	return __builtin_ctzll(U);
#else
	int z = 0;
	while (!(U >> z & 1))
		z++;
	return z;
#endif
}
/* The share's FFT tables of size 2^lg (lg < HIST_FFT_MAX), made when
 * first asked for, kept until the share is freed: ANVIL_OK or
 * ANVIL_ENOMEM. */
int impact_share_fft(struct anvil_ramp_share *s, int lg, const gsl_fft_real_wavetable **rw,
		     const gsl_fft_halfcomplex_wavetable **hw);
/* The share's table of key k, found or added (NULL when out of memory). */
struct rtab *impact_rtab_get(struct anvil_ramp_share *s, const struct rtab_key *k);
/* ramp (r = 0) or ramp2 (r = 1) at u dt0 by the call, kept in the table
 * (u < nR0) or its rows; NaN when the call fails.  impact_rtab_raw's
 * way when the entry is not yet made. */
double impact_rtab_make(const struct ctx *c, int r, size_t u);
/* ramp (r = 0) or ramp2 (r = 1) at u dt0: the table's, or by the call
 * that makes it (the same bits); NaN when the call fails.  Inline: the
 * weights are made from it (impact_wts.c). */
static inline double impact_rtab_raw(const struct ctx *c, int r, size_t u)
{
	struct rtab *t = c->rt[r];
	size_t U = u << c->rsh;
	if (u < c->nR0 && t && U < t->key.n &&
	    (atomic_load_explicit(&t->have[U >> 6], memory_order_acquire) >> (U & 63) & 1))
		return atomic_load_explicit(&t->R[U], memory_order_relaxed);
	if (u >= c->nR0 && t && U) { /* in its rows, made (impact_rtab.c rfar's way) */
		int z = impact_rtab_ctz(U);
		size_t i = U >> (z + 1), k = i & (RTAB_BLK - 1);
		struct rtab_blk *b =
			i < RTAB_ROW_MAX ? atomic_load_explicit(&t->rows[(size_t)z * RTAB_ROW_BLKS + (i >> RTAB_BLK_LG)],
							       memory_order_acquire)
					 : NULL;
		if (b && (atomic_load_explicit(&b->have[k >> 6], memory_order_acquire) >> (k & 63) & 1))
			return atomic_load_explicit(&b->v[k], memory_order_relaxed);
	}
	return impact_rtab_make(c, r, u);
}
/* Ramp r at j dt0 + d (d > 0; the pass's dt0) into *val, the share's
 * (same bits as the call: the kept value is the call's), or by the call,
 * kept: the frozen past's hats at a contact end (impact_grow.c,
 * impact_hist_at) read the same lags end after end.  The call's status. */
int impact_rtab_off(const struct ctx *c, int r, size_t j, double d, double *val);
/* R_r(u dt0) (r = 1: ramp2 - ramp): the table's, or by call beyond it
 * (the same bits: the table is made by the same call); NaN on failure. */
double impact_rtab(const struct ctx *c, int r, size_t u);
/* impact_wts.c: the weights from the ramps' tables, each made once, when
 * first needed. */
/* Level L's weights g_j (and dg_j) for *nf <= j < need, from the ramps at
 * j 2^L dt0 (as weights() makes level 0's); *nf = need.  ANVIL_ENUM when
 * one is not finite (a ramp call failed), else ANVIL_OK. */
int impact_wts_fill(const struct ctx *c, int L, double *g, double *dg, size_t *nf, size_t need);
/* Level L's weights j0 .. j0 + n - 1 into g[0 .. n-1] (and dg), as
 * impact_wts_fill makes them (the same bits), not kept. */
int impact_wts_span(const struct ctx *c, int L, size_t j0, size_t n, double *g, double *dg);
/* The current segment's weights made to min(need, ng) (c's table is a
 * cache: c itself is never const).  ANVIL_OK or ANVIL_ENUM. */
int impact_g_need(const struct ctx *c, size_t need);
/* The current segment's weight j < ng, made alone when it is not yet (the
 * same bits). */
double impact_g_at(const struct ctx *c, size_t j);
/* The online convolution of the current segment's weights (ng of them),
 * made as it reaches them; NULL when out of memory. */
struct anvil_fastconv *impact_fc_alloc(struct ctx *c, size_t direct_max);
/* The largest segment a long mode's level >= 1 makes before it freezes
 * and goes on at the same level (its weights' count), in the dt pass's
 * nodes (the dt/2 pass: twice). */
#define IMPACT_LONG_SEG 2048
/* The far field (impact_far.c).  R_r''(t) (r = 0 ramp, 1 ramp2): the
 * impulse response where the ramps are smooth (far out), the caller's
 * closed form (impact.h impulse) or a wide difference; NaN on failure. */
double impact_far_h(const struct ctx *c, int r, double t);
/* Frozen segment f's charges at its Chebyshev points and t_far, tb, from
 * its node times tn (f's node 0 first), its step dp and the next dn. */
void impact_far_charges(const struct ctx *c, struct frozen *f, const double *tn, double dp,
			double dn);
/* f's far field at the target time t (t >= f->t_far). */
double impact_far_sum(const struct ctx *c, const struct frozen *f, double t);
/* f's far field at the targets (u0 + k 2^lev) dt0, k0 <= k < C, added to
 * out[k] (interpolated over the targets where they are far enough). */
void impact_far_chunk(const struct ctx *c, struct frozen *f, size_t u0, size_t k0, size_t C,
		      double *out);
/* The merged far field (c->mg) extended to the most oldest segments whose
 * far fields all hold from t0 on, if that is more than it holds. */
void impact_far_merge(struct ctx *c, double t0);
/* Long mode: 1 when the march at node s->n - 1 stopped short of the
 * window's end (its nodes ran out, not the window). */
int impact_long_short(const struct ctx *c, const struct pass *s);
/* The pass's arrays from the current segment's node 0 on, as a pass of
 * uniform step (n, cap local). */
struct pass impact_view(const struct ctx *c, const struct pass *s);

/* impact_contact.c: the contact's state through the march. */
/* The pass's peak force and its time (a vertex through the largest nodes). */
void impact_peak(struct pass *s);
/* The peak's plateau of pass s into plat[ANVIL_PLATEAU_LEVELS] (result.h). */
void impact_plateau(const struct pass *s, double *plat);
/* The pass's history (impact_history.c): nhist samples over [0, t_s]
 * spaced as result.h says, or the pass's own nodes before t_s and its
 * end state (impact.h hist_nodes).  ANVIL_OK, ANVIL_ENOMEM, or ANVIL_ENUM
 * (node history: no node before t_s). */
int impact_resample(const struct pass *s, size_t nhist, struct anvil_history *h);
int impact_node_history(const struct pass *s, struct anvil_history *h);
/* The end between nodes n - 1 and n (alpha would be a_n <= 0) by the
 * parabola through alpha_H; s->ts, s->Vs (impulse: up to t_{n-1}). */
void impact_finish(struct pass *s, const struct anvil_params *p, double a_n, double impulse);
/* A pending separation made real (its end found); ANVIL_OK when none. */
int impact_sep_resolve(const struct ctx *c, struct pass *s, double *ioff);
/* In contact or not at node n, A (alpha_H if P_n were 0): *in and *ioff
 * updated, a contact started, a separation opened, merged or resolved;
 * IMPACT_BUDGET when the contacts run out, IMPACT_END_LOST, ANVIL_ENOMEM. */
int impact_contact_state(const struct ctx *c, struct pass *s, size_t n, double A, double a_prev,
			 double amax, double impulse, int *in, double *ioff);
/* Parted for good at node n (impact.h). */
int impact_parted(const struct ctx *c, const struct pass *s, size_t n, double impulse,
		  double amax);

/* impact_lag2.c: the physical contact's second order, Sigma = c_u u^2 -
 * c_x alpha (P/m1 + w_c''); c_u = c_x = 0 without it (g2 = 0). */
struct impact_lag2 {
	double cu, cx;
};
struct impact_lag2 impact_lag2_of(const struct ctx *c);
/* Sigma at node n before its step (the state's): in contact after a force
 * the last two nodes' sg extrapolated, else c_u u0^2. */
double impact_lag2_before(const struct impact_lag2 *l, const struct ctx *c,
			  const struct pass *s, size_t n, int in, double impulse, double u0);
/* w_c'' from dw_c/dt ud through the second low-pass stage (*z2; udp: ud's
 * last value; rl = dt / (2 tl)). */
double impact_lag2_wdd(double ud, double udp, double tl, double rl, double *z2);
/* Sigma for load P = x^3, relative velocity u and w_c'' wdd. */
double impact_lag2_after(const struct impact_lag2 *l, const struct anvil_params *p, double P,
			 double x, double u, double wdd);

#endif
