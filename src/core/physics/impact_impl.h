/* impact_impl.h: what impact.c (the march) and impact_end.c (the exact
 * end of a contact) share.  Internal to the physics module. */
#ifndef ANVIL_IMPACT_IMPL_H
#define ANVIL_IMPACT_IMPL_H

#include <stddef.h>

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

/* One time-stepping pass at a fixed dt.  Arrays are per step n = 0..n-1. */
struct pass {
	double dt;
	size_t n, cap;
	double *P, *W, *w, *v; /* one block, owned */
	double *wc;            /* physical contact: the layer correction's deflection */
	double *Q;             /* physical contact: P alpha_H / alpha_ref (true radius) */
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
	 * V0); rest 1 when the pass ended there (t_s = rest_k dt); Sg the
	 * running sum of the weights g_0..g_n (the layer's step response) */
	int rest;
	size_t rest_k, rest_ncont;
	double rest_bound, Sg;
};

struct ctx {
	const struct anvil_params *p;
	anvil_ramp_fn ramp;
	void *rctx;
	double tau_avail;
	double *g;      /* convolution weights g_j, j < ng */
	size_t ng;
	int physical;   /* the physical contact (opts), with beta */
	double beta;
	anvil_ramp_fn ramp2; /* the correction of the patch of radius a_ref (opts) */
	void *rctx2;
	double alpha_ref;
	double tau_lag; /* the lag's low-pass (opts), s; 0: none */
	double *dg;     /* its weights less g's, when ramp2 is given */
	/* sum_m P_m g_{n-m}, for the pass at hand; with dg, a pair (fastconv.h)
	 * that adds sum_m Q_m dg_{n-m} (physical, ramp2 given) */
	struct anvil_fastconv *fc;
	struct end_tab *tab; /* the contact ends' ramp values, for the pass at hand */
	const struct anvil_fastconv_fft *fft; /* FFT tables of both passes */
	double merge_gap, merge_time; /* merge_sep (opts): relative to alpha_max, s */
	size_t max_contacts;          /* the budget (opts); 0: none */
	double rest_tol;  /* the rest state (opts); 0: off */
	double rest_stop; /* s: the coarse pass came to rest here, the finer stops too; 0: none */
	double rest_long; /* s: a contact longer co-moves (impact_rest_long) */
	int rest_last;    /* the caller's last window (opts): fall back to rest at its end */
};

/* The ramp responses off the grid that the far past needs at every
 * contact end of a pass: R(j dt + d_i), d_i = i dt/3 (i = 1, 2, 3; end_ctx_init),
 * for j < len, through ramp (r = 0) and ramp2 (r = 1).  Filled once per pass
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
 * per node, in order (it keeps s->Sg). */
int impact_rest_check(const struct ctx *c, struct pass *s, size_t n, int in);
/* The pass ends at its first node at rest, if it had one (1; s->rest,
 * n, ncont, ts, Vs set: the contact goes on); else 0, s unchanged. */
int impact_rest_fallback(struct pass *s);
/* The result of two passes either of which came to rest (after fill):
 * R_f and E_a as the intervals the bound allows, t_s the rest's time,
 * r->rest_bound. */
void impact_rest_fill(struct anvil_result *r, const struct anvil_params *p, const struct pass *a,
		      const struct pass *b);

#endif
