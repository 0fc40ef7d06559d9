/* impact_rest.c: the impactor at rest on a thin plate (impact.h,
 * rest_tol; issue 11).
 *
 * After the first contact on a thin plate the impactor and the plate move
 * together: gaps of picometres, contacts that part and touch again below
 * the time step's resolution, for tens of milliseconds.  On an unbounded
 * plate with no gravity the plate carries the impactor's momentum away
 * and the final velocity tends to 0: the impactor comes to rest on the
 * plate (Zener 1941: R_f* = exp(-1.7191 lambda*) at large lambda*).
 * Following that to its end can cost more contacts than the budget or a
 * contact longer than any window; there the pass answers instead from the
 * first moment the rebound the impactor can still reach was bounded
 * within the level's target.
 *
 * The bound.  At low frequency the layer's centre is a Kirchhoff plate's,
 * whose point mobility is real and constant, 1/Z, Z = 8 sqrt(D rho h)
 * (plate.h: its ramp response tends to alpha* t^2/2, alpha* = 1/Z): a
 * dashpot, which radiates what it takes and stores nothing that can come
 * back to the load point.  What the layer holds near the load beyond that
 * dashpot is a local compliance C_loc in series (plate.h: the fitted
 * a + b t + c t log t, the patch's and the thickness's): at lag t the
 * layer's step response is u(t) = t/Z + C_loc, so C_loc = u(t) - t h(t),
 * h the impulse response, here from the weights g (impact.c: g_j =
 * h(t_j) dt, sum_{j<=n} g_j = u(t_{n+1/2})).  The radiation lag of the
 * physical contact (-beta dP/dt) is a dashpot too.  So impactor, Hertz
 * spring, local spring and dashpot: their energy
 *   E = m1 v^2/2 + E_H + E_L,  E_H = (2/5) P alpha_H,  E_L = |C_loc| P^2/2,
 * can only decrease (dE/dt = -Z w_d'^2 with w_d the dashpot's motion), and
 * no later speed of the impactor can exceed sqrt(v^2 + 2 (E_H + E_L)/m1):
 *   R_f <= (|v| + sqrt(2 (E_H + E_L) / m1)) / V0.
 * |C_loc| over C_loc keeps the bound where the correction stiffens the
 * contact (C_loc < 0 stores less than E_H says).  The bound is that of
 * the plate's lumped model; the layer departs from it at frequencies
 * where its waves are short against h, which the co-moving phase (slow:
 * its time m1/Z is many T1 >= 32 r0/c2, plate.h) does not excite.  Zener's
 * plate model is exactly this system with C_loc = 0, so his R_f* (~0 at
 * large lambda*) lies within it.  The scheme's own error on v enters by
 * the two passes' difference (impact_rest_fill).
 *
 * When.  The first node where the bodies co-move (together, in contact or
 * a separation not yet resolved, after they have parted and touched
 * again, merged or not, or in one contact longer than twice Hertz's) with
 * the bound within rest_tol is kept, and the march goes on: a contact
 * that ends with a rebound above rest_tol, however long, is followed to
 * its end as before (the same bits).  Where the march would be refused,
 * more contacts than the budget, a later contact's end lost
 * (finish_exact) or (the caller's last window, rest_last) a contact that
 * outlasts the window, and where the bodies part at a rebound below
 * 1e-6 V0 (in long mode: within rest_tol) (a grazing end,
 * impact_rest_grazing: its time is determined to no stated accuracy), the
 * pass falls back to that node: the impactor
 * came to rest there.  A genuine re-contact keeps its count and times:
 * the bound is not small while the impactor still flies or the spring
 * still holds energy. */
#include <math.h>

#include "hertz.h"
#include "impact_impl.h"

/* A contact longer than this many of Hertz's on a rigid anvil is set by
 * the plate's compliance, not by Hertz's spring: the bodies co-move. */
#define REST_LONG 2.0
/* Below this rebound (relative to V0) an end is grazing in any mode: a
 * relative error of 1e-9 in the deflection (the plate tail's K table is
 * within 3e-9 at h = 0.02 r0) moves it by over 1e-3 of t_s. */
#define REST_GRAZE 1e-6

double impact_rest_long(const struct anvil_params *p)
{
	return REST_LONG * anvil_hertz_tau_s() * p->T;
}

/* The layer's local compliance u(t) - t h(t) at node n (t = K dt0: every
 * node of a grown step lies on the dt0 grid), from the ramp table at dt0
 * as the weights are made: sum_{j<=K} g_j = (R_{K+1} - R_K)/dt0 = u, and
 * g_K = h dt0 (impact.c weights()).  The table, not a running sum of the
 * weights, because the weights change as the step grows.  Far out (long
 * mode, beyond the table) g is H's (impact_grow.c), so R_{K-1} is not
 * asked for, and R_{K+1} (an odd lag, which no level's weights read) is
 * the ramp's call itself rather than rtab's row (the same bits): kept
 * there, the lags of every node filled a row of 8 MB that nothing read
 * again (3 % of h = 0.02 r0, 1 kg at 10 m/s). */
static double rest_cloc(const struct ctx *c, const struct pass *s, size_t n)
{
	double dt0 = s->dt0, x = floor(s->t[n] / dt0 + 0.5);
	size_t K = x > 0 ? (size_t)x : 0;
	if (K + 1 >= c->nR)
		return NAN;
	if (c->lng && K >= c->nR0) {
		double R1, R0 = impact_rtab(c, 0, K);
		if (impact_ramp_at(c, (double)(K + 1) * dt0, &R1))
			return NAN;
		double g = dt0 * impact_far_h(c, 0, (double)K * dt0);
		return (R1 - R0) / dt0 - ((double)K + 0.5) * g;
	}
	double R1 = impact_rtab(c, 0, K + 1), R0 = impact_rtab(c, 0, K);
	double u = (R1 - R0) / dt0;
	double g = (R1 - 2.0 * R0 + (K ? impact_rtab(c, 0, K - 1) : 0.0)) / dt0;
	return u - ((double)K + 0.5) * g;
}

/* The rebound's bound at node n, relative to V0 (see above), from the
 * local compliance there (rest_cloc). */
static double rest_bound(const struct ctx *c, const struct pass *s, size_t n, double c_loc)
{
	const struct anvil_params *p = c->p;
	double P = s->P[n];
	double eh = 0.4 * P * p->k0 * cbrt(P * P), el = 0.5 * fabs(c_loc) * P * P;
	return (fabs(s->v[n]) + sqrt(2.0 * (eh + el) / p->m1)) / p->V0;
}

/* rest_cloc is asked for only where the bound is (it is the check's
 * cost: three ramp calls a node, twice), and once. */
int impact_rest_check(const struct ctx *c, struct pass *s, size_t n, int in)
{
	if (!(c->rest_tol > 0))
		return 0;
	double tn = s->t[n];
	/* the finer pass stops where the coarse one came to rest (the same
	 * time in both: rest_stop is a node of each), and so do the error
	 * estimate's runs (rest_at) */
	int stop = c->rest_stop > 0 && tn >= c->rest_stop * (1.0 - 1e-12);
	if (!stop && (s->rest_k || !(in || s->pend_k) ||
		      !(s->ncont >= 2 || s->nmerged >= 1 || tn > c->rest_long)))
		return 0;
	/* the bound is at least |v| / V0: above twice rest_tol it decides
	 * nothing below, and its compliance (three table reads) and Hertz
	 * energy (a cube root) are not asked for; the impactor still moves
	 * for most of a co-moving phase */
	if (!stop && fabs(s->v[n]) / c->p->V0 > 2.0 * c->rest_tol)
		return 0;
	double c_loc = rest_cloc(c, s, n);
	if (isnan(c_loc))
		return 0;
	if (stop) {
		s->rest_k = n;
		s->rest_ncont = s->ncont;
		s->rest_bound = rest_bound(c, s, n, c_loc);
		return impact_rest_fallback(s);
	}
	double b = rest_bound(c, s, n, c_loc);
	if (!(s->rest_t2 > 0) && b <= 2.0 * c->rest_tol)
		s->rest_t2 = tn;
	if (b <= c->rest_tol) { /* the first node at rest: kept for a fallback */
		s->rest_k = n;
		s->rest_ncont = s->ncont;
		s->rest_bound = b;
	}
	return 0;
}

/* A grazing end: the bodies part at a relative speed ~ R_f V0 after
 * co-moving, and the end's time moves by a perturbation of the approach
 * over that speed.  In long mode the far field's own error (up to 1e-7
 * of the deflection at its near edge, impact_grow.c) is such a
 * perturbation, and 1e-9 of a 26 cm plate deflection under 100 kg on
 * h = r0/2 (the impulse response by differences against its closed form)
 * moved t_s from 9.6 s to 5.9 s at R_f 1e-9: what is sure is the bound,
 * and the rest state answers, as where the march would be refused.  In
 * any mode below REST_GRAZE: there the K table's interpolant moved
 * section 13's 500 g rod on 1 mm from 93.14 to 93.30 ms against an
 * estimate of 12 us, and a 16 % change of the step h = 0.1 r0's end by
 * twice its estimate. */
int impact_rest_grazing(const struct ctx *c, const struct pass *s, double ioff)
{
	const struct anvil_params *p = c->p;
	double v = fabs(p->V0 - ioff / p->m1) / p->V0;
	return c->rest_tol > 0 && s->rest_k && s->rest_k < s->n && v <= c->rest_tol &&
	       (c->lng || v <= REST_GRAZE);
}

/* At the window's end, in contact or moving in, after the rest: a
 * longer window tells no more when the contact at rest has held to here
 * (any end of it is below the bound: grazing, where the rest answers
 * too) or the impactor has chattered on the plate since (each contact
 * bounded alike).  h = 0.02 r0, 0.1 g at 10 m/s, the paper's contact: at
 * rest at 3996 us in its 63rd contact, which held to the first window's
 * end at 4930 us; the doubled window fell back to the same node, a
 * third of the row's time.  One separation after the rest is not that:
 * the bodies may yet part for good and tell the contact's true end
 * (h = 0.35 r0, the paper's contact at draft: at rest at 431 us in the
 * first contact, parted at 593 us, the second contact ends at 2864 us
 * with R_f 2.5e-6). */
#define REST_CHATTER 4

int impact_rest_final(const struct ctx *c, const struct pass *s, int in)
{
	int held = in && !s->pend_k && s->ncont == s->rest_ncont;
	return c->rest_last || (s->rest_k && (held || s->ncont >= s->rest_ncont + REST_CHATTER));
}

int impact_rest_fallback(struct pass *s)
{
	size_t k = s->rest_k;
	if (!k)
		return 0;
	s->rest = 1;
	s->n = k + 1;
	s->ncont = s->rest_ncont;
	s->ts = s->t[k];
	s->Vs = -s->v[k];
	return 1;
}

/* The velocity of pass s at time t: its nearest node at or after t (the
 * node times grow with a grown step), within its run. */
static double v_at(const struct pass *s, double t)
{
	size_t lo = 0, hi = s->n - 1;
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		if (s->t[mid] < t * (1.0 - 1e-12))
			lo = mid + 1;
		else
			hi = mid;
	}
	return s->v[lo];
}

void impact_rest_fill(struct anvil_result *r, const struct anvil_params *p, const struct pass *a,
		      const struct pass *b)
{
	/* each pass's bound (or, for one that parted, its rebound), and the
	 * scheme's error on v where both ran: the whole difference, as
	 * extrap takes it */
	double ta = a->t[a->n - 1], tb = b->t[b->n - 1], tc = fmin(ta, tb);
	double dv = fabs(v_at(a, tc) - v_at(b, tc)) / p->V0;
	double ba = a->rest ? a->rest_bound : fabs(a->Vs) / p->V0;
	double bb = b->rest ? b->rest_bound : fabs(b->Vs) / p->V0;
	double bnd = fmin(1.0, fmax(ba, bb) + dv), e0 = 0.5 * p->m1 * p->V0 * p->V0;
	r->rest_bound = bnd;
	r->Rf.val = r->Rf.err = 0.5 * bnd;
	r->Vs.val = r->Vs.err = 0.5 * bnd * p->V0;
	/* V_s in [0, bnd V0]: E_a = E0 - m1 V_s^2/2 in [E0 (1 - bnd^2), E0] */
	r->Ea.val = e0 * (1.0 - 0.5 * bnd * bnd);
	r->Ea.err = 0.5 * e0 * bnd * bnd;
	/* t_s: when the rest was recognised (the contact goes on), a threshold
	 * crossed by a slowly falling bound: the finer pass stops where the
	 * coarse one did, so the passes agree to the bit, while an error of
	 * the bound itself (of the size R_f's estimate allows) moves the
	 * crossing by up to the time the bound took to halve.  Measured: T1 =
	 * 32 instead of 64 (r0/c2) moved h = 0.2 r0, 1 kg at 0.1 m/s's t_s
	 * from 148184 to 148092 us against an estimate of 1e-4 us; the halving
	 * time there is 11 ms.  That is its estimate (the target does not
	 * apply to it: solver.c, solver_check_target). */
	const struct pass *s = a->rest ? a : b;
	r->ts.val = s->ts;
	r->ts.err = a->rest && b->rest ? fabs(a->ts - b->ts) : fabs(ta - tb);
	if (s->rest && s->rest_t2 > 0)
		r->ts.err = fmax(r->ts.err, s->ts - s->rest_t2);
	r->t_free = r->ts.val;
	if (b->ncont >= 1 && b->ncont <= ANVIL_MAX_CONTACTS)
		r->contact_off[b->ncont - 1] = r->ts.val;
}
