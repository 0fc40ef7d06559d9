/* verdict.c: the one verdict on the layer (verdict.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hertz.h"
#include "plate_bending.h"
#include "verdict.h"
#include "verdict_near.h"

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
		if (verdict_near_face(pb, h, v, &e)) {
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
