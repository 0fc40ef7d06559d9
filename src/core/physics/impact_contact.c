/* impact_contact.c: the contact's state through the march: its start, its
 * end (exact for the scheme, impact_end.c, or by a parabola), separations
 * below the scheme's resolution merged or made real (impact.h,
 * merge_sep), parting for good, and the pass's peak.  See impact_impl.h. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "impact.h"
#include "impact_impl.h"

/* Parted for good (see impact.h): the impactor, moving away, is outward of
 * both the surface and the surface's late position by this fraction of the
 * largest Hertz compression of the impact. */
#define IMPACT_PART_MARGIN 0.1

/* Root in (t1, t2) of the parabola through (t0,a0), (t1,a1), (t2,a2),
 * a1 > 0 >= a2: where alpha_H returns to zero. */
static double zero_crossing(double t0, double a0, double t1, double a1, double t2, double a2)
{
	double lo = t1, hi = t2;
	for (int i = 0; i < 100; i++) {
		double t = 0.5 * (lo + hi);
		double q = a0 * (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)) +
			   a1 * (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)) +
			   a2 * (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
		if (q > 0)
			lo = t;
		else
			hi = t;
	}
	return 0.5 * (lo + hi);
}

/* The vertex of the cubic through P at nodes j0..j0+3, by Newton from the
 * parabola's vertex (offset x from node k): *xv its offset from k; 0 when
 * the cubic has no maximum within a step of x. */
static int cubic_vertex(const double *P, size_t j0, size_t k, double x, double *xv)
{
	/* Newton's form in u = node - j0: c1 u + c2 u(u-1) + c3 u(u-1)(u-2) */
	double c1 = P[j0 + 1] - P[j0], c2 = 0.5 * (P[j0 + 2] - 2.0 * P[j0 + 1] + P[j0]);
	double c3 = (P[j0 + 3] - 3.0 * P[j0 + 2] + 3.0 * P[j0 + 1] - P[j0]) / 6.0;
	double u0 = (double)(k - j0) + x, u = u0;
	for (int i = 0; i < 30; i++) {
		double f1 = c1 + c2 * (2.0 * u - 1.0) + c3 * (3.0 * u * u - 6.0 * u + 2.0);
		double f2 = 2.0 * c2 + c3 * (6.0 * u - 6.0);
		if (!(f2 < 0))
			return 0;
		double du = f1 / f2;
		u -= du;
		if (fabs(du) < 1e-12)
			break;
	}
	if (!(fabs(u - u0) <= 1.0))
		return 0;
	*xv = u - (double)(k - j0);
	return 1;
}

/* Peak of the force by a parabola through the largest sample and its
 * neighbours.  The parabola's vertex is off the true one by O(dt^2) times
 * the ratio of the third derivative to the second, with a factor that
 * swings with the peak's phase on the grid, so the dt and dt/2 passes can
 * agree by chance and Richardson then misses it.  Its own error tmax_ie
 * (s) is the shift to the vertex of the cubic through the four nodes
 * nearest the peak (the next term of the same interpolation), or a whole
 * step where the force is not smooth enough for that (a kink at a wave
 * arrival, the peak at an end of the record). */
static void peak_uniform(struct pass *s)
{
	size_t k = 0;
	for (size_t i = 1; i < s->n; i++)
		if (s->P[i] > s->P[k])
			k = i;
	s->tmax = (double)k * s->dt;
	s->Pmax = s->P[k];
	s->tmax_ie = s->dt;
	s->curv = 0;
	if (k == 0 || k + 1 >= s->n)
		return;
	double a = s->P[k - 1], b = s->P[k], c = s->P[k + 1];
	double den = a - 2.0 * b + c;
	if (den < 0) {
		double x = 0.5 * (a - c) / den, xc;
		s->curv = -den / (s->dt * s->dt);
		s->tmax = ((double)k + x) * s->dt;
		s->Pmax = b - 0.25 * (a - c) * x;
		/* the fourth node on the vertex's side, else the other */
		size_t j0 = x < 0 && k >= 2 ? k - 2 : k - 1;
		if (j0 + 3 >= s->n && k >= 2)
			j0 = k - 2;
		if (j0 + 3 < s->n && cubic_vertex(s->P, j0, k, x, &xc))
			s->tmax_ie = fabs(xc - x) * s->dt;
	}
}

/* The peak on the segment that holds the largest P (its last node the
 * next segment's first), in the pass's time. */
void impact_peak(struct pass *s)
{
	if (s->nseg == 1) {
		peak_uniform(s);
		return;
	}
	size_t k = 0, j = 0;
	for (size_t i = 1; i < s->n; i++)
		if (s->P[i] > s->P[k])
			k = i;
	while (j + 1 < s->nseg && s->seg_n[j + 1] <= k)
		j++;
	size_t o = s->seg_n[j], e = j + 1 < s->nseg ? s->seg_n[j + 1] + 1 : s->n;
	struct pass v = *s;
	v.P += o, v.n = (e < s->n ? e : s->n) - o;
	v.dt = ldexp(s->dt0, s->seg_L[j]);
	peak_uniform(&v);
	s->tmax = s->t[o] + v.tmax;
	s->Pmax = v.Pmax, s->tmax_ie = v.tmax_ie, s->curv = v.curv;
}

/* The plateau around the peak (result.h Pmax_plat): one scan of the
 * nodes, each filed by its deficit d = 1 - P/P_max in [2^-(j+1), 2^-j)
 * (ilogb: no log per node), then each level takes in the finer ones.
 * Every node counts, a later contact's too: t_max may jump there. */
void impact_plateau(const struct pass *s, double *plat)
{
	const int L = ANVIL_PLATEAU_LEVELS;
	for (int j = 0; j < L; j++)
		plat[j] = 0.0;
	if (!(s->Pmax > 0))
		return;
	for (size_t i = 0; i < s->n; i++) {
		double d = 1.0 - s->P[i] / s->Pmax;
		if (!(d < 1.0))
			continue;
		int j = d > 0 ? -ilogb(d) - 1 : L - 1;
		j = j < 0 ? 0 : j >= L ? L - 1 : j;
		double t = s->nseg == 1 ? (double)i * s->dt : s->t[i];
		plat[j] = fmax(plat[j], fabs(t - s->tmax));
	}
	for (int j = L - 2; j >= 0; j--)
		plat[j] = fmax(plat[j], plat[j + 1]);
}

/* The end of contact between steps n-1 and n, where alpha would be a_n <= 0;
 * V_s from the impulse, the last partial interval with P ~ (t_s - t)^(3/2)
 * since alpha_H falls linearly to zero. */
void impact_finish(struct pass *s, const struct anvil_params *p, double a_n, double impulse)
{
	size_t n = s->n;
	double dt = s->dt, t1 = (double)(n - 1) * dt;
	double a1 = p->k0 * pow(s->P[n - 1], 2.0 / 3.0);
	double a0 = n >= 2 ? p->k0 * pow(s->P[n - 2], 2.0 / 3.0) : 0.0;
	s->ts = n >= 2 ? zero_crossing(t1 - dt, a0, t1, a1, t1 + dt, a_n)
		       : t1 + dt * a1 / (a1 - a_n);
	impulse += 0.4 * s->P[n - 1] * (s->ts - t1);
	s->Vs = -(p->V0 - impulse / p->m1);
	impact_peak(s);
}

/* The end of the contact whose last node in contact is k (a_n = A_{k+1}
 * <= 0): its time and the impulse up to it, exactly for the scheme when
 * there are nodes enough, else from the parabola through alpha_H (finish).
 * Decided late (merge_sep), it sees the pass as it was at node k + 1: the
 * same bits as at once. */
static int contact_end(const struct ctx *c, struct pass *s, size_t k, double a_n, double impulse,
		       double *ioff)
{
	struct pass v = impact_view(c, s); /* the segment up to node k (arrays shared) */
	double toff = NAN;
	int st = ANVIL_OK;
	if (k < c->seg0 && k >= 1) {
		/* The end is pending across a segment's freeze (long mode freezes
		 * a full segment whatever is pending: impact_grow_due): its nodes
		 * k - 1, k and k + 1 are the pass's, on their own times; the
		 * parabola through alpha_H there (finish's).  Before, k + 1 -
		 * seg0 wrapped round and the exact end read far outside the
		 * arrays (h = 0.05 r0, 100 kg at 0.1 m/s: a crash). */
		const double *P = s->P, *t = s->t;
		double a0 = c->p->k0 * pow(P[k - 1], 2.0 / 3.0), a1 = c->p->k0 * pow(P[k], 2.0 / 3.0);
		toff = zero_crossing(t[k - 1], a0, t[k], a1, t[k + 1], a_n);
		*ioff = impulse + 0.4 * P[k] * (toff - t[k]);
		if (s->ncont <= ANVIL_MAX_CONTACTS)
			s->off[s->ncont - 1] = toff;
		s->ts = toff;
		return ANVIL_OK;
	}
	v.n = k + 1 - c->seg0;
	if (v.n >= 3) {
		st = impact_finish_exact(c, &v, impulse, &toff, ioff);
	} else {
		impact_finish(&v, c->p, a_n, impulse);
		toff = v.ts;
		*ioff = c->p->m1 * (c->p->V0 + v.Vs);
	}
	toff = c->T0 + toff; /* the segment's time to the pass's */
	if (!st && s->ncont <= ANVIL_MAX_CONTACTS)
		s->off[s->ncont - 1] = toff;
	s->ts = toff; /* IMPACT_END_LOST: where it was lost */
	return st;
}

/* Separations below the scheme's resolution (impact.h, merge_sep).  A
 * contact that ends at node k + 1 leaves a pending separation; it becomes
 * a real one (its end found by contact_end) once its gap exceeds
 * merge_gap alpha_max or it lasts longer than merge_time, and a re-contact
 * before either merges it into the contact: no end, no new contact. */
static void sep_open(struct pass *s, size_t n, double a_n, double impulse)
{
	s->pend_k = n - 1;
	s->pend_imp = impulse;
	s->pend_a = a_n;
	s->sep_gap = -a_n;
}

int impact_sep_resolve(const struct ctx *c, struct pass *s, double *ioff)
{
	size_t k = s->pend_k;
	if (!k)
		return ANVIL_OK;
	s->pend_k = 0;
	return contact_end(c, s, k, s->pend_a, s->pend_imp, ioff);
}

/* Out of contact at node n (A = a_n <= 0): the pending separation decided
 * when it is resolved by the scheme. */
/* merge_time (impact.h: at least two of the dt pass's steps); on a grown
 * step (impact_grow.c) at least two of the dt pass's steps at the level,
 * the same time in both passes. */
static double merge_time(const struct ctx *c)
{
	if (!c->lev)
		return c->merge_time;
	return fmax(c->merge_time, ldexp((c->sched ? 4.0 : 2.0) * c->dt0, c->lev));
}

static int sep_step(const struct ctx *c, struct pass *s, size_t n, double a_n, double amax,
		    double *ioff)
{
	if (!s->pend_k)
		return ANVIL_OK;
	/* The gap W - w is the difference of two displacements each known to
	 * merge_gap of its size: its error is merge_gap times the larger of
	 * alpha_max and the impactor's displacement at the separation */
	double res = c->merge_gap * fmax(amax, fabs(s->W[s->pend_k]));
	s->sep_gap = fmax(s->sep_gap, -a_n);
	if (s->sep_gap > res ||
	    (double)(n - s->pend_k) * s->dt > merge_time(c))
		return impact_sep_resolve(c, s, ioff);
	return ANVIL_OK;
}

/* A new contact between nodes n-1 and n: A rose through 0 (linear). */
static void contact_start(const struct ctx *c, struct pass *s, size_t n, double a_prev,
			  double a_n)
{
	s->ncont++;
	if (s->ncont <= ANVIL_MAX_CONTACTS)
		s->on[s->ncont - 1] = c->T0 + s->dt * ((double)(n - c->seg0) - a_n / (a_n - a_prev));
}

/* The contact's state at node n from A = A_n (alpha_H if P_n were 0):
 * a contact ends (a pending separation, merge_sep), a separation is
 * decided or merged, a new contact starts; *in the state after. */
int impact_contact_state(const struct ctx *c, struct pass *s, size_t n, double A, double a_prev,
			 double amax, double impulse, int *in, double *ioff)
{
	int st = ANVIL_OK;
	if (A <= 0 && *in)
		sep_open(s, n, A, impulse);
	if (A <= 0) {
		st = sep_step(c, s, n, A, amax, ioff);
	} else if (!*in && s->pend_k) { /* back within the resolution: one contact */
		s->pend_k = 0;
		s->nmerged++;
	} else if (!*in) {
		contact_start(c, s, n, a_prev, A);
	}
	*in = A > 0;
	if (!st && c->max_contacts && s->ncont > c->max_contacts)
		st = IMPACT_BUDGET;
	return st;
}

/* Parted for good (impact.h) at node n, out of contact: the impactor moves
 * away, the gap opens, and the impactor is outward of both the surface and
 * the surface's late position (impulse times the displacement impulse
 * response at the window's end, g_{cap-1}/dt: alpha* I for a plate, 0 for
 * a half-space) by IMPACT_PART_MARGIN of the largest compression. */
int impact_parted(const struct ctx *c, const struct pass *s, size_t n, double impulse,
		  double amax)
{
	double dt = s->dt, late = impulse * impact_g_at(c, c->ng - 1) / dt;
	double u = (s->w[n] - s->w[n - 1]) / dt;
	return s->v[n] < 0 && u > s->v[n] &&
	       s->W[n] < fmin(s->w[n], late) - IMPACT_PART_MARGIN * amax;
}

