/* verdict_near.c: the near face, where the contact's field and the plate's
 * bending add at the same instant (verdict_near.h, for verdict.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>


#include "maxscan.h"
#include "plate_bending.h"
#include "verdict_near.h"

/* ---- the near face: the contact and the bending at the same instant ----
 *
 * The contact's quasi-static Hertz field at P(t) and the plate's bending at
 * the same t (its centre's stress s_b(t) from the history, its fall with r
 * from Kirchhoff's equilibrium: plate_bending.c) add at the near face,
 * which the bending compresses in r and theta by about s_b.  Adding an
 * equi-biaxial beta (in r, theta) to any stress,
 *   vm^2 = vm_H^2 + beta (s_rr + s_tt - 2 s_zz) + beta^2,
 * so where the contact's own field squeezes hardest in z (s_zz the most
 * compressive: its whole axis, and the surface inside the contact, where
 * s_rr + s_tt - 2 s_zz = (1 - 2 nu) p) the bending's compression beta =
 * -s_b relieves it: on the axis vm = |vm_H - s_b (1 - 2 z/h)|, below both
 * vm_H and s_b.  At the contact's edge (r = a, z = 0) Hertz's s_rr = -s_tt
 * = t = (1 - 2 nu) p0/3, s_zz = 0, so there the sum is
 *   vm = sqrt(3 t^2 + s_b^2),
 * above both (6.7 % above the larger at most, nu = 0.3, s_b = 0.62 p0),
 * and the edge's tension is t - s_b, the bending relieving it.  Just
 * below the surface outside the edge Hertz's s_rr + s_tt is compressive
 * and s_zz small, so there the term in beta adds: the sum's peak, 0.709
 * p0 at r = 1.046 a, z = 0.079 a for s_b = 0.62 p0, is 14.3 % above the
 * larger (nu = 0.3; 25 % at nu = 0), which neither check alone sees.  So
 * the sum is searched over r <= 3 a, z <= min(3 a, h/2)
 * (anvil_plate_bending_near); the far half, where the bending is tension,
 * is the far face's (its estimate, measured against the transform field
 * there, holds the load's spreading through the thickness: adding the
 * half-space's own field there would count it twice).  Limits: s_b -> 0
 * gives Hertz's own stress; P -> 0 the near face's bending alone, von
 * Mises s_b, the far face's.  The superposition checked against the
 * transform field (`anvil field`, the r0 patch, 100 g at 3 m/s on h = 0.5
 * r0): its near face's s_rr less Hertz's half-space s_rr at the centre
 * was -0.96 to -1.00 times its far face's from 137 us on (-0.89 at
 * 12 us, the bending still forming), and half that at z = h/4, linear.
 *
 * In time: the largest sum over the contact, at NEAR_NSCAN instants
 * log-spaced over it, NEAR_NSCAN more between a quarter of the earlier and
 * twice the later of the two peaks (P's and s_b's), both peaks themselves,
 * then Brent's maximiser (GSL) between the best one's neighbours. */
#define NEAR_NSCAN 32

/* How much less the near face's compression can be than the far face's
 * tension s_b, Pa: the centre moment's excess under Westergaard's patch b
 * (which the far face's estimate takes) over the half-space's own load at
 * depth h (Boussinesq's, P (1 - (1 + rho^2/h^2)^(-3/2)) inside rho), the
 * near face's share once the half-space's field carries the contact: by
 * the fall's rule (M(0) - M(r) = int F/(2 pi rho)) the two centres differ
 * by P/(2 pi) (1/3 + ln(h/b)), so s_b by 3 (1 + nu)/(2 pi) (1/3 +
 * ln(h/b)) P/h^2 (the half-space's own moment over the slab left out: a
 * bound, not the value).  Against the transform field (`anvil field`, the
 * r0 patch c, 3 m/s; its near face's s_rr less Hertz's half-space s_rr,
 * against its far face's) the shortfall was steady in time at 0.627,
 * 0.584, 0.466 and 0.074 P/h^2 for c = 0.1, 0.25, 0.5 and 2 h (this bound
 * 0.89, 0.82, 0.63 and 0, whence the floor NEAR_SHORT_MIN).  The verdict
 * takes the worse of the two ends; before the estimate's range in time
 * (ANVIL_PLATE_BENDING_T_MIN times 2h/c1) the lower end is no compression. */
#define NEAR_SHORT_MIN 0.1
static double near_shortfall(const struct anvil_params *p, double P, double b)
{
	double k = 3 * (1 + p->nu) / (2 * M_PI) * (1.0 / 3 + log(p->h / b));
	return fmax(k, NEAR_SHORT_MIN) * P / (p->h * p->h);
}

struct near_time {
	const struct anvil_problem *pb;
	const struct anvil_history *h;
	struct anvil_plate_bender *bender;
	double tol; /* the bending estimate's stated relative accuracy */
	int brittle, status;
};

/* The near face's largest stress at t: *n, and the far face's s_b then. */
static int near_at(struct near_time *c, double t, struct anvil_plate_near *n, double *sb)
{
	const struct anvil_params *p = &c->pb->p;
	double P = anvil_history_at(c->h, c->h->P, t), e;
	int st = anvil_plate_bender_at(c->bender, t, sb, &e);
	if (st)
		return st;
	if (!(P > 0)) { /* no contact: the bending's alone, uniform in r near the centre */
		*n = (struct anvil_plate_near){ c->brittle ? 0 : fabs(*sb), 0, 0 };
		return ANVIL_OK;
	}
	double a = sqrt(p->r0 * pow(P / p->K, 2.0 / 3.0)), p0 = 1.5 * P / (M_PI * a * a);
	double b = anvil_plate_bending_patch(p, ANVIL_PLATE_PATCH_TRUE, 0, P);
	/* before the plate estimate's range in time (plate_bending.h: the
	 * plate's dispersion still at the centre) its relief is not trusted:
	 * the compression's range reaches down to none */
	int early = t < ANVIL_PLATE_BENDING_T_MIN * 2 * p->h / p->c1;
	double lo = early ? 0 : fmax(0, *sb - near_shortfall(p, P, b));
	/* a relief is trusted only to the estimate's own accuracy: a fate must
	 * not turn on what the estimate cannot vouch for (the upper end stays
	 * s_b, as the far face's, both stated within bend_tol) */
	lo *= 1 - c->tol;
	struct anvil_plate_near n2;
	/* the sum is convex in the compression: its worse end is the bound */
	st = anvil_plate_bending_near(a, p0, p->nu, p->h, P, b, *sb, c->brittle, n);
	st = st ? st : anvil_plate_bending_near(a, p0, p->nu, p->h, P, b, lo, c->brittle, &n2);
	if (!st && n2.stress > n->stress)
		*n = n2;
	return st;
}

static double minus_near(double t, void *vp)
{
	struct near_time *c = vp;
	struct anvil_plate_near n;
	double sb;
	int st = near_at(c, t, &n, &sb);
	if (st)
		c->status = st;
	return st ? 0 : -n.stress;
}

static int cmp_double(const void *x, const void *y)
{
	double a = *(const double *)x, b = *(const double *)y;
	return (a > b) - (a < b);
}

/* The scan's instants, sorted, in t[] (up to 2 NEAR_NSCAN + 3 of them).
 * The last instant before the relief is trusted (t_early) is one: the sum
 * drops there, and Brent on a step finds either side. */
static size_t near_instants(const struct anvil_history *h, double t_pk, double t_bend,
			    double t_early, double *t)
{
	double te = h->t[h->n - 1], t0 = 1e-3 * te, lo = 0.25 * fmin(t_pk, t_bend),
	       hi = fmin(te, 2 * fmax(t_pk, t_bend));
	size_t n = 0;
	for (int i = 0; i < NEAR_NSCAN; i++) {
		t[n++] = t0 * pow(te / t0, i / (NEAR_NSCAN - 1.0));
		t[n++] = lo + (hi - lo) * i / (NEAR_NSCAN - 1.0);
	}
	t[n++] = t_pk;
	t[n++] = t_bend;
	if (t_early > t0 && t_early < te)
		t[n++] = t_early * (1 - 1e-9);
	qsort(t, n, sizeof *t, cmp_double);
	return n;
}

/* Brent between ts[j - 1] and ts[j + 1] around the scan's best j. */
static void near_refine(struct near_time *c, const double *ts, const double *sv, size_t n,
			size_t j, double *t)
{
	if (j == 0 || j + 1 >= n || !(sv[j] >= sv[j - 1] && sv[j] >= sv[j + 1]) ||
	    !(ts[j - 1] < ts[j] && ts[j] < ts[j + 1]))
		return;
	gsl_function F = { minus_near, c };
	double tm = *t, sm = sv[j];
	anvil_max_refine(&F, ts + j - 1, sv + j - 1, &tm, &sm); /* out of memory: the scan's */
	if (!c->status)
		*t = tm;
}

int verdict_near_face(const struct anvil_problem *pb, const struct anvil_history *h,
		      struct anvil_verdict *v, struct anvil_err *err)
{
	struct near_time c = { pb, h, NULL, v->bend_tol, v->brittle, ANVIL_OK };
	c.bender = anvil_plate_bender_new(&pb->p, h, ANVIL_PLATE_PATCH_TRUE, 0, err);
	if (!c.bender)
		return err->status ? err->status : ANVIL_ENOMEM;
	double ts[2 * NEAR_NSCAN + 3], sv[2 * NEAR_NSCAN + 3], sb, t;
	struct anvil_plate_near n;
	double t_early = ANVIL_PLATE_BENDING_T_MIN * 2 * pb->p.h / pb->p.c1;
	size_t nt = near_instants(h, v->t, v->bend_t, t_early, ts), best = 0;
	int st = ANVIL_OK;
	for (size_t i = 0; i < nt && !st; i++) {
		st = near_at(&c, ts[i], &n, &sb);
		sv[i] = n.stress;
		if (!st && sv[i] > sv[best])
			best = i;
	}
	t = ts[best];
	if (!st)
		near_refine(&c, ts, sv, nt, best, &t);
	st = st ? st : c.status ? c.status : near_at(&c, t, &n, &sb);
	anvil_plate_bender_free(c.bender);
	if (st)
		return anvil_err_set(err, st, "the near face's stress under the contact and the bending failed");
	v->near = n.stress;
	v->near_r = n.r;
	v->near_z = n.z;
	v->near_t = t;
	v->near_sb = sb;
	return ANVIL_OK;
}
