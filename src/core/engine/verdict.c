/* verdict.c: the one verdict on the layer (verdict.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include "hertz.h"
#include "plate_bending.h"
#include "verdict.h"

/* The instants around the peak force at which the edge tension is read. */
#define EDGE_NT 5

static void criterion(const struct anvil_problem *pb, struct anvil_verdict *v)
{
	const struct anvil_material *m = &pb->layer;
	memset(v, 0, sizeof *v);
	snprintf(v->material, sizeof v->material, "%s", m->name);
	v->brittle = m->brittle;
	v->limit = m->brittle ? m->tensile : m->yield;
	v->known = v->limit > 0;
}

/* The stress the fate is judged on: the contact's; or, where the plate's
 * bending was checked, the larger of the far face's (there both the
 * tension and the von Mises stress) and the near face's, the contact's
 * field with the bending added (verdict.h). */
static double governing(const struct anvil_verdict *v)
{
	return v->bend_state == 1 ? fmax(v->bend, v->near) : v->stress;
}

static void judge(struct anvil_verdict *v)
{
	v->fate = ANVIL_HERTZ_ELASTIC;
	if (v->known && governing(v) > v->limit)
		v->fate = v->brittle ? ANVIL_HERTZ_CRACKS : ANVIL_HERTZ_YIELDS;
}

/* Quasi-static Hertz under force P at time t: alpha = (P/K)^(2/3),
 * a = sqrt(r0 alpha). */
static int hertz_at(const struct anvil_problem *pb, double P, double t, struct anvil_verdict *v)
{
	const struct anvil_params *p = &pb->p;
	double al = pow(P / p->K, 2.0 / 3.0);
	double a = sqrt(p->r0 * al), p0 = 1.5 * P / (M_PI * a * a);
	struct anvil_hertz_verdict hv;
	int st = anvil_hertz_judge(a, p0, p->nu, NAN, NAN, &hv);
	if (st)
		return st;
	v->a = a;
	v->p0 = p0;
	v->t = t;
	v->r = v->brittle ? a : 0;
	v->z = v->brittle ? 0 : hv.z_vm;
	v->stress = v->brittle ? hv.tension : hv.vm;
	v->err = 1e-10 * v->stress;
	return ANVIL_OK;
}

/* Quasi-static Hertz at its peak: alpha_max = (5/4)^(2/5) T V0, t_s/2. */
static int quasi_static(const struct anvil_problem *pb, struct anvil_verdict *v)
{
	const struct anvil_params *p = &pb->p;
	double al = anvil_hertz_alpha_max() * p->T * p->V0;
	return hertz_at(pb, p->K * pow(al, 1.5), 0.5 * anvil_hertz_tau_s() * p->T, v);
}

/* The impactor under the layer's contact (a, p0): the Hertz field with
 * its own nu, against its own criterion (verdict.h). */
static int impactor(const struct anvil_problem *pb, struct anvil_verdict *v)
{
	const struct anvil_material *m = &pb->impactor;
	struct anvil_verdict_impactor *im = &v->imp;
	struct anvil_hertz_verdict hv;
	memset(im, 0, sizeof *im);
	snprintf(im->material, sizeof im->material, "%s", m->name);
	im->brittle = m->brittle;
	im->limit = m->brittle ? m->tensile : m->yield;
	im->known = im->limit > 0;
	im->fate = ANVIL_HERTZ_ELASTIC;
	if (!(v->a > 0 && v->p0 > 0))
		return ANVIL_OK; /* no contact, no stress */
	int st = anvil_hertz_judge(v->a, v->p0, m->nu, NAN, NAN, &hv);
	if (st)
		return st;
	im->stress = im->brittle ? hv.tension : hv.vm;
	im->z = im->brittle ? 0 : hv.z_vm;
	if (im->known && im->stress > im->limit)
		im->fate = im->brittle ? ANVIL_HERTZ_CRACKS : ANVIL_HERTZ_YIELDS;
	return ANVIL_OK;
}

/* The largest radial stress at the edge r = a(t) of the contact, z = 0,
 * at instants around the peak force. */
static int edge_tension(struct anvil_field *f, const struct anvil_field_peak *pk,
			struct anvil_verdict *v, struct anvil_err *err)
{
	double t[EDGE_NT], r[EDGE_NT], z[EDGE_NT] = {0}, tl = anvil_field_t_load(f);
	struct anvil_fval o[EDGE_NT * EDGE_NT];
	for (int i = 0; i < EDGE_NT; i++) {
		t[i] = fmin(tl, fmax(1e-3 * tl, pk->t + (i - EDGE_NT / 2) * tl / 200));
		r[i] = anvil_field_contact_radius(f, anvil_field_load(f, t[i]));
	}
	int st = anvil_field_points(f, EDGE_NT, r, z, EDGE_NT, t, o, err);
	v->stress = -INFINITY;
	for (int i = 0; !st && i < EDGE_NT; i++) {
		const struct anvil_fval *x = &o[i * EDGE_NT + i];
		if (x->v[ANVIL_FQ_SRR] > v->stress) {
			v->stress = x->v[ANVIL_FQ_SRR];
			v->err = x->err[ANVIL_FQ_SRR];
			v->t = t[i];
			v->r = r[i];
		}
	}
	v->z = 0;
	return st;
}

int anvil_verdict_at(const struct anvil_problem *pb, double P, double t, struct anvil_verdict *v)
{
	criterion(pb, v);
	if (!(P > 0) || !isfinite(P))
		return ANVIL_EINVAL;
	int st = hertz_at(pb, P, t, v);
	v->at_row = 1;
	judge(v);
	return st ? st : impactor(pb, v);
}

int anvil_verdict_make(const struct anvil_problem *pb, struct anvil_field *f,
		       struct anvil_verdict *v, struct anvil_err *err)
{
	criterion(pb, v);
	if (!f) {
		int st = quasi_static(pb, v);
		judge(v);
		return st ? st : impactor(pb, v);
	}
	struct anvil_field_peak pk;
	anvil_field_set_contact(f, 1);
	v->dynamic = 1;
	int st = anvil_field_peak(f, 0, &pk, err);
	if (st)
		return st;
	if (v->brittle) {
		st = edge_tension(f, &pk, v, err);
	} else {
		v->stress = pk.vm;
		v->err = pk.vm_err;
		v->r = pk.r;
		v->z = pk.z;
		v->t = pk.t;
	}
	double P = anvil_field_load(f, v->t);
	v->a = anvil_field_contact_radius(f, P);
	v->p0 = v->a > 0 ? 1.5 * P / (M_PI * v->a * v->a) : 0;
	judge(v);
	return st ? st : impactor(pb, v);
}

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
	gsl_min_fminimizer *m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
	if (!m)
		return;
	int gs = gsl_min_fminimizer_set_with_values(m, &F, ts[j], -sv[j], ts[j - 1], -sv[j - 1],
						    ts[j + 1], -sv[j + 1]);
	for (int it = 0; !gs && it < 60; it++) {
		gs = gsl_min_fminimizer_iterate(m);
		double lo = gsl_min_fminimizer_x_lower(m), hi = gsl_min_fminimizer_x_upper(m);
		if (gs || gsl_min_test_interval(lo, hi, 0, 1e-4) == GSL_SUCCESS)
			break;
	}
	if (!gs && !c->status && -gsl_min_fminimizer_f_minimum(m) > sv[j])
		*t = gsl_min_fminimizer_x_minimum(m);
	gsl_min_fminimizer_free(m);
}

static int near_face(const struct anvil_problem *pb, const struct anvil_history *h,
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

void anvil_verdict_bending(const struct anvil_problem *pb, const struct anvil_history *h,
			   struct anvil_verdict *v)
{
	struct anvil_plate_bending b;
	struct anvil_err e = {0};
	v->bend_state = -1;
	int st = anvil_plate_bending_peak(&pb->p, h, ANVIL_PLATE_PATCH_TRUE, 0, 0, &b, &e);
	if (st) {
		snprintf(v->bend_why, sizeof v->bend_why, "%.150s", e.msg);
		return;
	}
	v->bend = b.sigma;
	v->bend_err = b.err;
	v->bend_t = b.t;
	v->bend_tol = b.tol;
	snprintf(v->bend_why, sizeof v->bend_why, "%s", b.why);
	if (b.tol > 0) {
		v->bend_state = 1;
		if (near_face(pb, h, v, &e)) {
			v->bend_state = -1;
			snprintf(v->bend_why, sizeof v->bend_why, "%.150s", e.msg);
		}
	}
	judge(v);
}

int anvil_verdict_fails(const struct anvil_verdict *v)
{
	return v->fate != ANVIL_HERTZ_ELASTIC || v->imp.fate != ANVIL_HERTZ_ELASTIC;
}

/* A stress in MPa below 1 GPa, else GPa, 3 significant digits. */
static void stress_text(double s, char *buf, size_t n)
{
	if (fabs(s) >= 1e9)
		snprintf(buf, n, "%.3g GPa", s * 1e-9);
	else
		snprintf(buf, n, "%.3g MPa", s * 1e-6);
}

/* With the bending checked, the near face's sum (near_face) stands for
 * the contact's own stress: the one shown under the contact. */
static int near_shown(const struct anvil_verdict *v)
{
	return v->bend_state == 1;
}

/* The bending clause (a long contact's, the TUI's on any plate): the
 * plate's bending stress and its accuracy, or why it was not checked. */
static void bending_text(const struct anvil_verdict *v, char *buf, size_t n)
{
	char s[32];
	if (v->bend_state != 1) {
		snprintf(buf, n, "; the plate's bending stress not checked%s%s",
			 v->bend_why[0] ? ": " : "", v->bend_why);
		return;
	}
	stress_text(v->bend, s, sizeof s);
	snprintf(buf, n, "; bending stress at the far face %s at t = %.3g us (Kirchhoff plate, "
		 "within %.0f %%)%s", s, v->bend_t * 1e6, 100 * v->bend_tol,
		 v->known && v->bend > v->near ? ", the larger: judged on it" : "");
}

static const char *fate_word(enum anvil_hertz_fate fate, int known)
{
	return fate == ANVIL_HERTZ_YIELDS   ? "yields"
	       : fate == ANVIL_HERTZ_CRACKS ? "cracks"
	       : !known                     ? "is not judged"
					    : "stays elastic";
}

/* Where the layer's stress under the contact peaks: the contact's own, or
 * with the bending the near face's sum. */
static void layer_where(const struct anvil_verdict *v, char *buf, size_t n)
{
	double a = v->a, r = v->r, z = v->z;
	if (near_shown(v)) {
		/* the sum's contact is a(near_t), not a(t_max): its own a */
		r = v->near_r;
		z = v->near_z;
		if (z <= 0.02 * a && fabs(r - a) <= 0.05 * a) {
			snprintf(buf, n, "at the near face's contact edge r = %.3g mm", r * 1e3);
			return;
		}
		if (z <= 0.02 * a) {
			snprintf(buf, n, "on the near face at r = %.3g mm", r * 1e3);
			return;
		}
		if (fabs(r - a) <= 0.25 * a && z <= 0.25 * a) {
			snprintf(buf, n, "just below the near face's contact edge, r = %.3g mm, "
				 "z = %.3g mm", r * 1e3, z * 1e3);
			return;
		}
	} else if (v->brittle) {
		snprintf(buf, n, "at the contact edge r = a = %.3g mm", a * 1e3);
		return;
	}
	if (r <= 0.5 * a)
		snprintf(buf, n, "at %.2g a = %.3g mm below the contact", a > 0 ? z / a : 0, z * 1e3);
	else
		snprintf(buf, n, "at r = %.3g mm, z = %.3g mm", r * 1e3, z * 1e3);
}

/* The criterion's words for the stress under the contact. */
static const char *layer_what(const struct anvil_verdict *v)
{
	if (!v->brittle)
		return "peak von Mises";
	return near_shown(v) ? "largest tension" : "edge tension (1-2nu) p0/3";
}

/* Which force the quasi-static Hertz field is at ("" when the row's
 * own): after "quasi-static Hertz". */
static void qs_force(const struct anvil_verdict *v, char *buf, size_t n)
{
	if (v->qs_ratio > 0)
		snprintf(buf, n, " at the layer's computed P_max: the contact lasts %.2g times 2h/c1",
			 v->qs_ratio);
	else
		snprintf(buf, n, "%s", v->at_row ? " at the layer's computed P_max" : "");
}

/* With the bending: the contact's own stress, which it no longer is, after
 * the field's name ("" without). */
static void alone_text(const struct anvil_verdict *v, const char *f, char *buf, size_t n)
{
	char s[32];
	if (!near_shown(v)) {
		snprintf(buf, n, "%s", f);
		return;
	}
	stress_text(v->stress, s, sizeof s);
	snprintf(buf, n, "; the contact alone %s, t = %.3g us,%s", s, v->t * 1e6,
		 f[0] ? f : " at its peak");
}

void anvil_verdict_text(const struct anvil_verdict *v, char *buf, size_t n)
{
	char s[32], l[32], where[96], f[96], al[160], qs[320] = "";
	int ns = near_shown(v);
	stress_text(ns ? v->near : v->stress, s, sizeof s);
	stress_text(v->limit, l, sizeof l);
	layer_where(v, where, sizeof where);
	qs_force(v, f, sizeof f);
	alone_text(v, f, al, sizeof al);
	if (!v->dynamic)
		snprintf(qs, sizeof qs, " (quasi-static Hertz%s%s)",
			 ns ? " with the plate's bending at the same instant" : "", al);
	char bend[224] = "";
	if (v->bend_state != 0) /* tried: a long contact's (yield.c) or the TUI's */
		bending_text(v, bend, sizeof bend);
	snprintf(buf, n, "the %s layer %s: %s %s %s at t = %.3g us, %s%s%s%s%s", v->material,
		 fate_word(v->fate, v->known), layer_what(v), s, where,
		 (ns ? v->near_t : v->t) * 1e6, v->brittle ? "tensile strength " : "Y = ",
		 v->known ? l : "unknown", qs,
		 !v->known ? (v->brittle ? ": set layer.tensile" : ": set layer.yield") : "", bend);
}

void anvil_verdict_text_screen(const struct anvil_verdict *v, char *buf, size_t n)
{
	char s[32], l[32], where[96], f[96] = "", al[160] = "";
	int ns = near_shown(v);
	double t = ns ? v->near_t : v->t;
	const char *field = v->dynamic ? "the dynamic field"
			    : ns       ? "Hertz + plate bending"
				       : "quasi-static Hertz";
	stress_text(ns ? v->near : v->stress, s, sizeof s);
	stress_text(v->limit, l, sizeof l);
	layer_where(v, where, sizeof where);
	if (!v->dynamic)
		qs_force(v, f, sizeof f);
	alone_text(v, f, al, sizeof al);
	const char *what = v->brittle ? (ns ? "largest tension" : "edge tension (1-2nu) p0/3")
				      : "von Mises";
	char bend[224] = "";
	if (v->bend_state == 1 && v->known && v->bend > v->near) {
		/* judged on the bending: it leads, as a screen line is cut */
		char b[32];
		stress_text(v->bend, b, sizeof b);
		snprintf(buf, n, "layer %s (plate bending): %s at the far face, %s%s, t = %.3g us "
			 "(Kirchhoff plate, within %.0f %%); under the contact (%s) %s %s %s, t = %.3g us%s%s",
			 fate_word(v->fate, v->known), b, v->brittle ? "tensile strength " : "Y = ", l,
			 v->bend_t * 1e6, 100 * v->bend_tol, field, s, what, where, t * 1e6,
			 al[0] && al[0] != ';' ? ";" : "", al);
		return;
	}
	if (v->bend_state != 0)
		bending_text(v, bend, sizeof bend);
	snprintf(buf, n, "layer %s (%s): %s %s, %s%s%s, %s, t = %.3g us%s%s%s",
		 fate_word(v->fate, v->known), field, s, what,
		 v->brittle ? "tensile strength " : "Y = ", v->known ? l : "unknown",
		 !v->known ? (v->brittle ? " (set layer.tensile)" : " (set layer.yield)") : "",
		 where, t * 1e6, al[0] && al[0] != ';' ? ";" : "", al, bend);
}

void anvil_verdict_impactor_text(const struct anvil_verdict *v, char *buf, size_t n)
{
	const struct anvil_verdict_impactor *im = &v->imp;
	char s[32], l[32], where[96];
	const char *what = fate_word(im->fate, im->known);
	stress_text(im->stress, s, sizeof s);
	stress_text(im->limit, l, sizeof l);
	if (im->brittle)
		snprintf(where, sizeof where, "at the contact edge");
	else
		snprintf(where, sizeof where, "at %.2g a = %.3g mm inside its tip",
			 v->a > 0 ? im->z / v->a : 0, im->z * 1e3);
	snprintf(buf, n, "the %s impactor %s under the same contact: %s %s %s, %s%s%s", im->material,
		 what, im->brittle ? "edge tension (1-2nu) p0/3" : "peak von Mises", s, where,
		 im->brittle ? "tensile strength " : "Y = ", im->known ? l : "unknown",
		 !im->known ? (im->brittle ? ": set impactor.tensile" : ": set impactor.yield") : "");
}

void anvil_verdict_impactor_text_screen(const struct anvil_verdict *v, char *buf, size_t n)
{
	const struct anvil_verdict_impactor *im = &v->imp;
	char s[32], l[32];
	stress_text(im->stress, s, sizeof s);
	stress_text(im->limit, l, sizeof l);
	if (im->brittle)
		snprintf(buf, n, "impactor %s too: %s edge tension (1-2nu) p0/3, tensile strength %s%s, at the contact edge",
			 fate_word(im->fate, im->known), s, im->known ? l : "unknown",
			 im->known ? "" : " (set impactor.tensile)");
	else
		snprintf(buf, n, "impactor %s too: %s von Mises, Y = %s%s, at %.2g a = %.3g mm inside its tip",
			 fate_word(im->fate, im->known), s, im->known ? l : "unknown",
			 im->known ? "" : " (set impactor.yield)", v->a > 0 ? im->z / v->a : 0, im->z * 1e3);
}
