/* impact_end.c: the exact end of a contact (impact.c's march finds that
 * one ends; this finds when, consistently with the scheme). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "impact_impl.h"

/* The end of contact, consistent with the scheme: P falls linearly from
 * P_k (the last node in contact) to 0 at t_k + d, so the last hat is
 * asymmetric (left half-width dt, right d).  alpha_H(t_k + d) = W - w = 0
 * is solved for d by Brent's method (GSL), with W and w evaluated for that
 * P: exactly for the last IMPACT_END_NEAR steps, the older past (a sum
 * smooth in d away from wavefront arrivals) through the cubic in d through
 * d = 0, dt/3, 2dt/3, dt (error O(dt^4) where the response is smooth,
 * O(dt^2) across an arrival: second order either way). */
struct end_ctx {
	const struct ctx *c;
	const struct pass *s;
	size_t k;       /* the last node with P > 0 */
	size_t m0;      /* nodes m < m0 are the far past */
	double S0, S1;  /* sum P_m, sum P_m t_m over m < k */
	double far[4];  /* the far past's deflection at d = i dt/3 */
	double *R;      /* scratch: R(j dt + d), j = 0 .. k - m0 + 1 */
	double memo[4]; /* alpha_end at two d known (d, value, d, value) */
	double last[2]; /* alpha_end's last d and value */
};

void impact_end_tab_free(struct end_tab *t)
{
	for (int r = 0; r < 2; r++)
		for (int i = 0; i < 4; i++)
			free(t->R[r][i]);
	memset(t, 0, sizeof *t);
}

/* R(j dt + d) through ramp r for IMPACT_END_NEAR <= j <= jmax (<= cap)
 * in t's row (r, i); NULL when out of memory.  The far past (m < m0 = k -
 * IMPACT_END_NEAR) reaches lags j >= IMPACT_END_NEAR only: the entries
 * below are never made (nor read). */
static const double *end_tab_get(const struct ctx *c, const struct pass *s, int r, int i,
				 double d, size_t jmax)
{
	struct end_tab *t = c->tab;
	anvil_ramp_fn fn = r ? c->ramp2 : c->ramp;
	void *fctx = r ? c->rctx2 : c->rctx;
	if (!t->R[r][i] && !(t->R[r][i] = malloc((s->cap + 1) * sizeof **t->R)))
		return NULL;
	for (size_t j = t->len[r][i] > IMPACT_END_NEAR ? t->len[r][i] : IMPACT_END_NEAR; j <= jmax;
	     j++)
		impact_ramp_of(c, fn, fctx, (double)j * s->dt + d, &t->R[r][i][j]);
	if (jmax + 1 > t->len[r][i])
		t->len[r][i] = jmax + 1;
	return t->R[r][i];
}

/* sum_{m < m0} F_m times the hat response at t_k + d, off the grid
 * (0 < d < dt), from R(j dt + d) (end_tab): lag k - m rising. */
static double far_of(const struct end_ctx *e, const double *F, const double *R)
{
	const double dt = e->s->dt;
	size_t k = e->k;
	double w = 0;
	for (size_t m = e->m0 - 1; m >= 1; m--) {
		size_t j = k - m;
		w += F[m] * (R[j + 1] - 2.0 * R[j] + R[j - 1]) / dt;
	}
	return w;
}

/* The paper contact's far past at both off-grid offsets, d = dt/3 (R1)
 * and 2 dt/3 (R2), in one sweep, each sum's dt taken out: far_of divided
 * every term by dt, a division a term that bounded the sweep (a chattering
 * thin plate's ends sum up to 5.5e5 nodes each, 374 ends a pass at h =
 * 0.02 r0, 0.1 g at 10 m/s), and read P once for each table.  Two chains
 * a sum (even and odd m) keep the adder busy.  The rounding is another
 * one of the same size (a sum of k terms, relative k eps at worst). */
static void far_of12(const struct end_ctx *e, const double *F, const double *R1,
		     const double *R2, double *w1, double *w2)
{
	size_t k = e->k, m = 1;
	double a0 = 0, a1 = 0, b0 = 0, b1 = 0;
	for (; m + 1 < e->m0; m += 2) {
		size_t j = k - m; /* m's lag; m + 1's is j - 1 */
		a0 += F[m] * (R1[j + 1] - 2.0 * R1[j] + R1[j - 1]);
		b0 += F[m] * (R2[j + 1] - 2.0 * R2[j] + R2[j - 1]);
		a1 += F[m + 1] * (R1[j] - 2.0 * R1[j - 1] + R1[j - 2]);
		b1 += F[m + 1] * (R2[j] - 2.0 * R2[j - 1] + R2[j - 2]);
	}
	if (m < e->m0) {
		size_t j = k - m;
		a0 += F[m] * (R1[j + 1] - 2.0 * R1[j] + R1[j - 1]);
		b0 += F[m] * (R2[j + 1] - 2.0 * R2[j] + R2[j - 1]);
	}
	*w1 = (a0 + a1) / e->s->dt;
	*w2 = (b0 + b1) / e->s->dt;
}

/* far_of(P, R) + (far_of(Q, R2) - far_of(Q, R)) in one sweep (each sum in
 * far_of's order: the same bits, a third of the memory traffic). */
static double far_of2(const struct end_ctx *e, const double *P, const double *Q,
		      const double *R, const double *R2)
{
	const double dt = e->s->dt;
	size_t k = e->k;
	double wp = 0, wq = 0, wq2 = 0;
	for (size_t m = e->m0 - 1; m >= 1; m--) {
		size_t j = k - m;
		double h = R[j + 1] - 2.0 * R[j] + R[j - 1];
		wp += P[m] * h / dt;
		wq += Q[m] * h / dt;
		wq2 += Q[m] * (R2[j + 1] - 2.0 * R2[j] + R2[j - 1]) / dt;
	}
	return wp + (wq2 - wq);
}

/* The far past's deflection at t_k + d, d = i dt/3 (m < m0), exactly; with
 * the true contact radius (dg), the loads' Q through ramp2 - ramp as well.
 * ANVIL_ENOMEM when the table cannot be had. */
static int far_exact(const struct end_ctx *e, int i, double *val)
{
	const struct ctx *c = e->c;
	const double *P = e->s->P, *Q = e->s->Q, dt = e->s->dt, d = dt * i / 3.0;
	size_t k = e->k;
	if (d == 0.0 || d == dt) { /* on the grid: the weights */
		double w = 0;
		size_t sh = d == 0.0 ? 0 : 1;
		if (!c->physical && !anvil_fastconv_at(c->fc, k + sh, &w)) {
			/* the march's convolution at node k + sh less its near past
			 * (m >= m0): O(IMPACT_END_NEAR), where the sum over the whole
			 * past took O(k) and, on a chattering thin plate, a quarter of
			 * the run (h = 0.02 r0, 0.1 g at 10 m/s: 374 ends of up to
			 * 5.5e5 nodes each).  The convolution's rounding (eps log2 k
			 * of sum |P g|, fastconv.h) stands for the direct sum's. */
			if (impact_g_need(c, k + sh - e->m0 + 1))
				return ANVIL_ENUM;
			for (size_t m = e->m0; m < k + sh; m++)
				w -= P[m] * c->g[k + sh - m];
			*val = w;
			return ANVIL_OK;
		}
		if (impact_g_need(c, k + sh))
			return ANVIL_ENUM;
		for (size_t m = 1; m < e->m0; m++)
			w += P[m] * c->g[k + sh - m] + (c->dg ? Q[m] * c->dg[k + sh - m] : 0.0);
		*val = w;
		return ANVIL_OK;
	}
	const double *R = end_tab_get(c, e->s, 0, i, d, k), *R2 = NULL;
	if (R && c->dg)
		R2 = end_tab_get(c, e->s, 1, i, d, k);
	if (!R || (c->dg && !R2))
		return ANVIL_ENOMEM;
	*val = c->dg ? far_of2(e, P, Q, R, R2) : far_of(e, P, R);
	return ANVIL_OK;
}

static double far_cubic(const struct end_ctx *e, double d)
{
	double x = 3.0 * d / e->s->dt, f = 0;
	for (int i = 0; i < 4; i++) {
		double l = 1;
		for (int j = 0; j < 4; j++)
			if (j != i)
				l *= (x - j) / (double)(i - j);
		f += l * e->far[i];
	}
	return f;
}

/* The near past's deflection at t_k + d (loads F, hats at t_m, m0 <= m <= k,
 * the last one ending at t_k + d) through the ramp response R at j dt + d,
 * added to w in the order the paper contact's end has always summed it (same bits). */
static double near_deflection(double w, const double *F, const double *R, size_t k, size_t m0,
			      double dt, double d)
{
	for (size_t m = m0; m < k; m++)
		w += F[m] * (R[k - m + 1] - 2.0 * R[k - m] + R[k - m - 1]) / dt;
	return w + F[k] * (R[1] / dt - R[0] * (1.0 / dt + 1.0 / d));
}

static double alpha_end(double d, void *vp)
{
	struct end_ctx *e = vp;
	const struct ctx *c = e->c;
	const struct anvil_params *p = c->p;
	const double *P = e->s->P, dt = e->s->dt;
	size_t k = e->k, nr = k - e->m0 + 1;
	double t1 = (double)k * dt, tau = t1 + d, w = far_cubic(e, d), *R = e->R;
	double mom = dt * (tau * e->S0 - e->S1);
	for (size_t j = 0; j <= nr; j++)
		impact_ramp_at(c, (double)j * dt + d, &R[j]);
	w = near_deflection(w, P, R, k, e->m0, dt, d);
	if (c->dg) { /* the true contact radius: + Q through (R2 - R) */
		w -= near_deflection(0.0, e->s->Q, R, k, e->m0, dt, d);
		for (size_t j = 0; j <= nr; j++)
			impact_ramp_of(c, c->ramp2, c->rctx2, (double)j * dt + d, &R[j]);
		w += near_deflection(0.0, e->s->Q, R, k, e->m0, dt, d);
	}
	/* the asymmetric last hat: int (tau - t') hat dt' = (tau - t_{k-1}) dt/2 - dt^2/3 + d^2/3 */
	mom += P[k] * ((tau - t1 + dt) * dt / 2.0 - dt * dt / 3.0 + d * d / 3.0);
	/* a grown step: the segment's times from T0, the frozen past's moment */
	mom += (c->T0 + tau) * c->Ih - c->M1h;
	/* the physical contact's second order: its alpha = 0 is at W - w_c =
	 * c_u u^2 (impact.c, sg; 0 otherwise), linear between the nodes */
	double sg = e->s->sg[k] + (e->s->sg[k + 1] - e->s->sg[k]) * d / dt;
	double f = p->V0 * (c->T0 + tau) - mom / p->m1 - w - sg;
	e->last[0] = d, e->last[1] = f;
	return f;
}

/* alpha_end, with the two values already known (memo: d, f, d, f) */
static double alpha_end_memo(double d, void *vp)
{
	struct end_ctx *e = vp;
	if (d == e->memo[0])
		return e->memo[1];
	if (d == e->memo[2])
		return e->memo[3];
	return alpha_end(d, vp);
}

static int end_ctx_init(struct end_ctx *e, const struct ctx *c, const struct pass *s, size_t k)
{
	*e = (struct end_ctx){ .c = c, .s = s, .k = k, .m0 = 1 };
	if (k > IMPACT_END_NEAR + 1)
		e->m0 = k - IMPACT_END_NEAR;
	for (size_t m = 1; m < k; m++) {
		e->S0 += s->P[m];
		e->S1 += s->P[m] * (double)m * s->dt;
	}
	int st = ANVIL_OK;
	for (int i = 0; i < 4 && e->m0 > 1 && !st; i++)
		if (c->physical || i == 0 || i == 3)
			st = far_exact(e, i, &e->far[i]);
	if (!c->physical && e->m0 > 1 && !st) { /* the paper contact's off-grid pair */
		const double *R1 = end_tab_get(c, s, 0, 1, s->dt / 3.0, k),
			     *R2 = R1 ? end_tab_get(c, s, 0, 2, s->dt * 2 / 3.0, k) : NULL;
		if (!R2)
			return ANVIL_ENOMEM;
		far_of12(e, s->P, R1, R2, &e->far[1], &e->far[2]);
	}
	/* a grown step: the frozen past (impact_grow.c), in the same cubic in
	 * d, on the grid from hist, off it by its direct sums */
	for (int i = 0; i < 4 && c->nfz && !st; i++) {
		double h;
		if (i == 0 || (i == 3 && k + 1 < c->segcap))
			h = impact_hist_one(c, k + (i == 3));
		else
			st = impact_hist_at(c, s, k, s->dt * i / 3.0, &h) ? ANVIL_ENUM
												 : ANVIL_OK;
		if (isnan(h))
			st = ANVIL_ENUM;
		e->far[i] += h;
	}
	if (st)
		return st;
	e->R = st ? NULL : malloc((k - e->m0 + 3) * sizeof *e->R);
	return e->R ? ANVIL_OK : ANVIL_ENOMEM;
}

/* Relative size of a wrong sign at the contact end's bracket taken for
 * rounding (finish_exact): far above 1e-16, far below any real mismatch. */
#define END_FLAT 1e-9
/* The same in ulps of alpha_end's largest term, V0 (t_k + dt): a grazing
 * contact (P ~ 1e-18 N late in a long thin-plate run, issue 11) has both
 * ends near zero, where END_FLAT against the other end asks for digits
 * that the difference V0 t - mom/m1 - w cannot have. */
#define END_ULPS 64.0
/* The end's offset d is found to within this many steps dt when its
 * residual is at rounding level (finish_exact): far below t_s's estimate
 * (the passes' difference, O(dt^2) of t_s), far above alpha's noise. */
#define END_DTOL 1e-9

/* The end of the contact whose last node in contact is k = s->n - 1:
 * *toff its time, *ioff the impulse up to it (impulse: up to t_k). */
int impact_finish_exact(const struct ctx *c, const struct pass *s, double impulse,
			double *toff, double *ioff)
{
	struct end_ctx e;
	size_t k = s->n - 1;
	int st = end_ctx_init(&e, c, s, k);
	gsl_function f = { alpha_end, &e };
	gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	double lo = 1e-9 * s->dt, hi = s->dt, d = hi;
	if (!rs || st) {
		gsl_root_fsolver_free(rs);
		free(e.R);
		return ANVIL_ENOMEM;
	}
	/* The march saw A_n <= 0, but the exact end's alpha at t_k + dt may
	 * round (or, with the true radius, extrapolate) to a hair above 0 when
	 * A_n is tiny: no sign change, no root to polish.  When the wrong-signed
	 * end is at rounding level against the other (END_FLAT), the end is at
	 * that edge; anything larger is a failure (a runaway: tests/test_contact.c). */
	double flo = alpha_end(lo, &e), fhi = alpha_end(hi, &e);
	double ulp = END_ULPS * DBL_EPSILON * c->p->V0 * (double)(k + 1) * s->dt;
	if (!(flo > 0 && fhi < 0)) {
		gsl_root_fsolver_free(rs);
		free(e.R);
		if (!(fhi >= 0 && fhi <= fmax(END_FLAT * fabs(flo), ulp)) &&
		    !(flo <= 0 && -flo <= fmax(END_FLAT * fabs(fhi), ulp))) {
			*toff = (double)k * s->dt; /* for the message (anvil_impact_run) */
			return IMPACT_END_LOST;
		}
		d = fhi >= 0 ? hi : lo;
		*toff = (double)k * s->dt + d;
		*ioff = impulse + 0.5 * s->P[k] * d;
		return ANVIL_OK;
	}
	/* Brent's set evaluates both ends again: it is handed those known */
	e.memo[0] = lo, e.memo[1] = flo, e.memo[2] = hi, e.memo[3] = fhi;
	f.function = alpha_end_memo;
	st = gsl_root_fsolver_set(rs, &f, lo, hi);
	f.function = alpha_end;
	/* Converged when the root's alpha is within alpha_end's own rounding
	 * (ulp: a difference of terms of size V0 t; the root is then within
	 * ulp / |alpha'| of the true one) and that is below END_DTOL dt at the
	 * bracket's mean slope (not a grazing end, whose flat alpha locates
	 * nothing: those close the bracket as before).  Below that level
	 * alpha's values are noise (they wander by ~1e-11 d), which Brent
	 * chased for six more steps to close the bracket to 1e-13 d.  A
	 * flatter end (ulp / slope above END_DTOL dt, most of a chattering
	 * contact's ends: 351 of 374 at h = 0.02 r0, 0.1 g at 10 m/s) is
	 * located only to within the d where |alpha| <= ulp, about ulp / slope
	 * wide: once the root's alpha is within ulp and the bracket within
	 * four such widths, further steps only wander inside it (there Brent
	 * took 2-28 of them, 16 alpha_end calls an end on average, each 258
	 * of the response's; now 6). */
	double slope = (flo - fhi) / (hi - lo);
	int resid_ok = ulp <= END_DTOL * s->dt * slope;
	double flat_w = 4.0 * ulp / slope;
	for (int i = 0; !st && i < 100; i++) {
		st = gsl_root_fsolver_iterate(rs);
		d = gsl_root_fsolver_root(rs);
		lo = gsl_root_fsolver_x_lower(rs);
		hi = gsl_root_fsolver_x_upper(rs);
		if (st)
			break;
		if (d == e.last[0] && fabs(e.last[1]) <= ulp && (resid_ok || hi - lo <= flat_w))
			break;
		if (gsl_root_test_interval(lo, hi, 1e-14 * s->dt, 1e-13) == GSL_SUCCESS)
			break;
	}
	gsl_root_fsolver_free(rs);
	free(e.R);
	if (st)
		return ANVIL_ENUM;
	*toff = (double)k * s->dt + d;
	*ioff = impulse + 0.5 * s->P[k] * d;
	return ANVIL_OK;
}


/* The flatness of a contact's end (issue 11: each output's estimate
 * covers its true error).
 *
 * The end is where the approach alpha(t) = W - w (alpha_H in contact, the
 * gap out of it) reaches 0.  Let the computed alpha be off the true one
 * by at most delta near the end.  Then the true end can lie anywhere in
 * the interval before t_s where |alpha| <= delta (every time there is a
 * zero of some alpha within delta of ours), and no earlier: its length
 * L(delta) bounds the move of t_s.  Where alpha is not flat,
 * L = delta / |alpha'(t_s)|, the linear estimate; after a co-moving
 * phase the bodies part at a relative speed far below V0 (h = r0, 1 kg
 * at 1000 m/s: |alpha'| = 5.4e-4 m/s against V0 = 1000, R_f 3e-6) and a
 * nanometre moves the end by microseconds; where alpha creeps through 0
 * L exceeds the linear estimate, and gaps within delta (a chatter whose
 * separations were never deep) are part of the interval too.
 *
 * delta has two parts:
 *  - the scheme's: the passes' difference of alpha at the coarse pass's
 *    nodes over the interval (the finer pass's alpha interpolated there).  At
 *    a sloped end that difference is |alpha'| |t_s(dt) - t_s(dt/2)|, so
 *    its L is the passes' difference of t_s, which t_s's estimate has
 *    already: only its excess over that is added;
 *  - the deflection's own error, a floor GRAZE_DEFL of max |w|: what the
 *    two passes share and cannot show (the response's tables and
 *    transform, the far field's interpolation).  Its size is stated, not
 *    measured on each run: the plate tail's K table is within 3e-9 of
 *    the deflection at h = 0.02 r0 (impact_rest.c, REST_GRAZE), and a
 *    change of the far field of about 1e-8 of it moved ends (issue 11).
 *    Scaling the layer's response by 1 +- 1e-8 moved the end above by
 *    +2.7/-2.9 us, by 1 +- 1e-7 by +23/-34 us; the floor's L is 12 us.
 *    (The move to 5848 us under a far-field change of ~1e-8, issue 11,
 *    was no move of the end: 5847.6 us is both passes' first node at
 *    rest, impact_rest.c, the answer a pass falls back to, in long mode
 *    for any end below rest_tol.)  The floor bounds an error spread like
 *    the deflection; one concentrated late is larger near the end than
 *    that: on a dashpot (tests/test_graze.c) a response change of 1e-8
 *    switched on over the last 20 T changed alpha there by 14 times the
 *    floor and moved the end by 15 times its L; on the layer above, 1e-8
 *    of the response switched on beyond 7 ms changed w near the end by
 *    4-10 times the floor, alpha by up to 6 times, and moved the end by
 *    -61/+41 us against t_s's estimate of 18 us: L(delta) follows the
 *    true delta, and the floor is a stated size, not a measured one.
 * L is concave in delta wherever alpha ~ (t_s - t)^k, k >= 1, so L(d1) +
 * L(d2) >= L(d1 + d2): the two parts' intervals are added.
 *
 * t_max is unaffected (the peak is far from the end); V_s moves by the
 * impulse of the interval, at most L K delta^1.5 / m1 (P <= K delta^1.5
 * there), 5e-8 V0 in the example above: far below R_f's target (against
 * max(R_f, 0.1)), not added. */
#define GRAZE_DEFL 1e-8

/* alpha at node k of pass s: W - w (alpha_H in contact, minus the gap) */
static double graze_alpha(const struct pass *s, size_t k)
{
	return s->W[k] - s->w[k];
}

/* The last node of s at or before t (node times rise). */
static size_t graze_node(const struct pass *s, double t)
{
	size_t lo = 0, hi = s->n - 1;
	while (lo < hi) {
		size_t mid = lo + (hi - lo + 1) / 2;
		if (s->t[mid] <= t)
			lo = mid;
		else
			hi = mid - 1;
	}
	return lo;
}

/* alpha of s at t, linear between its nodes. */
static double graze_alpha_at(const struct pass *s, double t)
{
	size_t k = graze_node(s, t);
	if (k + 1 >= s->n || s->t[k] == t)
		return graze_alpha(s, k);
	double f = (t - s->t[k]) / (s->t[k + 1] - s->t[k]);
	return (1.0 - f) * graze_alpha(s, k) + f * graze_alpha(s, k + 1);
}

/* L(delta): how long before its end s->ts the approach stays within
 * delta of 0 (alpha linear between the nodes, 0 at s->ts). */
static double graze_len(const struct pass *s, double delta)
{
	if (!(delta > 0))
		return 0.0;
	double t1 = s->ts, a1 = 0.0;
	for (size_t j = graze_node(s, s->ts) + 1; j-- > 0;) {
		double aj = graze_alpha(s, j);
		if (s->t[j] >= s->ts)
			continue;
		if (fabs(aj) > delta) {
			double lim = aj > 0 ? delta : -delta;
			return s->ts - (s->t[j] + (t1 - s->t[j]) * (lim - aj) / (a1 - aj));
		}
		t1 = s->t[j], a1 = aj;
	}
	return s->ts;
}

/* The passes' largest difference of alpha at a's nodes in [t0, t1]. */
static double graze_diff(const struct pass *a, const struct pass *b, double t0, double t1)
{
	double d = 0.0;
	for (size_t k = graze_node(a, t1) + 1; k-- > 0 && a->t[k] >= t0;)
		if (a->t[k] <= t1)
			d = fmax(d, fabs(graze_alpha(a, k) - graze_alpha_at(b, a->t[k])));
	return d;
}

double impact_graze_ts(const struct pass *a, const struct pass *b)
{
	if (b->n < 2 || a->n < 2 || !isfinite(a->ts) || !isfinite(b->ts))
		return 0.0;
	double wmax = 0.0, tc = fmin(a->ts, b->ts);
	for (size_t k = 0; k < b->n && b->t[k] <= b->ts; k++)
		wmax = fmax(wmax, fabs(b->w[k]));
	double lf = graze_len(b, GRAZE_DEFL * wmax);
	/* the scheme's delta over the interval it spans, which grows with
	 * it: from the last common node before the end, a few rounds */
	double dp = graze_diff(a, b, a->t[graze_node(a, tc)], tc), lp = graze_len(b, dp);
	for (int i = 0; i < 4; i++) {
		double d = graze_diff(a, b, b->ts - lp - lf, tc);
		if (!(d > dp))
			break;
		dp = d, lp = graze_len(b, dp);
	}
	return fmax(0.0, lp - fabs(a->ts - b->ts)) + lf;
}
