/* yield.c: the yield check as one call: the solver's impact, then the
 * field module's peak von Mises stress (field.h) or the verdict
 * (verdict.h).  In the engine because it runs the solver: the field module
 * depends on no engine. */
#include <math.h>

#include "field.h"
#include "solver.h"
#include "solver_impl.h"
#include "verdict.h"

/* The field of plan pl's layer (or half-space) row, the true contact on
 * or off (the paper's r0 patch). */
static struct anvil_field *row_field(struct anvil_solver *s, const struct anvil_plan *pl,
				     int true_contact, int *run_status, struct anvil_err *err)
{
	const struct anvil_problem *pb = &pl->pb;
	enum anvil_model m = anvil_verdict_model(pl);
	struct anvil_result r;
	/* The paper's patch r0 loads the layer with the paper contact's P(t)
	 * (plan.h: the plan always holds that row).  The true contact loads it
	 * with the force of the row the user is shown (row[m]'s contact): on a
	 * thin plate the paper's P_max is up to 40 % above the physical one's
	 * (a 10 mm steel ball at 1 m/s on 1 mm steel: 113 against 82 N), and a
	 * verdict under a force no printed row has is no answer. */
	enum anvil_contact c = true_contact ? pl->row[m].contact : ANVIL_CONTACT_PAPER;
	int st = anvil_solver_run_contact(s, pl, m, c, ANVIL_FIELD_NHIST, &r, err);
	*run_status = st;
	if (st < 0) {
		anvil_result_free(&r);
		return NULL;
	}
	struct anvil_err e2 = {0};
	struct anvil_field *f = anvil_field_from_result(&pb->p, pb->accuracy, &r, &e2);
	anvil_result_free(&r);
	if (!f) {
		*run_status = e2.status;
		if (err)
			*err = e2;
		return NULL;
	}
	anvil_field_set_contact(f, true_contact);
	/* the search can take seconds: the solver's progress shows it */
	anvil_field_set_progress(f, s->progress, s->progress_ctx);
	return f;
}

int anvil_solver_yield(struct anvil_solver *s, const struct anvil_plan *pl,
		       struct anvil_field_peak *pk, struct anvil_err *err)
{
	int st;
	struct anvil_err e2 = {0};
	/* the paper's patch: what the field's own tests check (test_field.c);
	 * the verdict on the layer is anvil_solver_verdict's */
	struct anvil_field *f = row_field(s, pl, 0, &st, err);
	if (!f)
		return st;
	int fs = anvil_field_peak(f, pl->pb.layer.yield, pk, &e2);
	anvil_field_free(f);
	if (fs) {
		if (err)
			*err = e2;
		return fs;
	}
	return st;
}

enum anvil_model anvil_verdict_model(const struct anvil_plan *pl)
{
	return isfinite(pl->pb.p.h) ? ANVIL_MODEL_LAYER : ANVIL_MODEL_HALFSPACE;
}

enum anvil_verdict_qs anvil_verdict_quasi_static(const struct anvil_plan *pl)
{
	double tr = pl->fig[ANVIL_FIG_T_REFLECT];
	if (isfinite(pl->pb.p.h) && pl->row[ANVIL_MODEL_LAYER].job.ts > ANVIL_VERDICT_QS_RATIO * tr)
		return ANVIL_VERDICT_QS_LONG;
	double rad = pl->fig[ANVIL_FIG_RADIATED], bend = pl->fig[ANVIL_FIG_BENDING];
	if (rad < ANVIL_VERDICT_QS_RADIATED)
		return ANVIL_VERDICT_QS_GENTLE;
	if (rad < ANVIL_VERDICT_QS_RADIATED_BLOCK && (!isfinite(pl->pb.p.h) || bend < ANVIL_VERDICT_QS_BENDING))
		return ANVIL_VERDICT_QS_BLOCK;
	return ANVIL_VERDICT_QS_NO;
}

void anvil_verdict_qs_mark(const struct anvil_plan *pl, enum anvil_verdict_qs why,
			   const struct anvil_result *row, struct anvil_verdict *v)
{
	double tr = pl->fig[ANVIL_FIG_T_REFLECT];
	v->qs_why = why;
	v->qs_radiated = pl->fig[ANVIL_FIG_RADIATED];
	v->qs_bending = isfinite(pl->pb.p.h) ? pl->fig[ANVIL_FIG_BENDING] : 0;
	if (why == ANVIL_VERDICT_QS_LONG)
		/* the row's own contact time, once it is known, not the plan's
		 * estimate (3e9 for 5.5e8 where a 1 kg mass comes to rest on
		 * h = 0.02 r0) */
		v->qs_ratio = row->ts.val > 0 && tr > 0 ? row->ts.val / tr
						       : pl->row[ANVIL_MODEL_LAYER].job.ts / tr;
}

/* A quasi-static verdict (anvil_verdict_quasi_static): Hertz at the row's
 * own P_max (the row as the plan runs it, its responses from the solver's
 * cache), and on a finite layer the plate's bending stress under its
 * history (ANVIL_VERDICT_NHIST samples: the given row's when it has
 * them, else the row run again with them, so the numbers do not depend on
 * what the caller kept). */
static int quasi_static_verdict(struct anvil_solver *s, const struct anvil_plan *pl,
				enum anvil_verdict_qs why, const struct anvil_result *given,
				struct anvil_verdict *v, struct anvil_err *err)
{
	struct anvil_result r;
	enum anvil_model m = anvil_verdict_model(pl);
	if (given && given->model != m)
		given = NULL;
	const struct anvil_result *row = given;
	int own = !given || given->hist.n != ANVIL_VERDICT_NHIST;
	if (given && given->status < 0)
		return anvil_err_set(err, given->status, "%s",
				     given->why[0] ? given->why : anvil_strerror(given->status));
	int st = own ? anvil_solver_run(s, pl, m, ANVIL_VERDICT_NHIST, &r, err) : given->status;
	if (own)
		row = &r;
	if (st >= 0) {
		int vs = anvil_verdict_at(&pl->pb, row->Pmax.val, row->tmax.val, v);
		anvil_verdict_qs_mark(pl, why, row, v);
		if (vs)
			st = anvil_err_set(err, vs, "the %s row's P_max (%g N) gives no Hertz contact",
					   anvil_model_name(m), row->Pmax.val);
		else if (m == ANVIL_MODEL_LAYER)
			anvil_verdict_bending(&pl->pb, &row->hist, v);
	}
	if (own)
		anvil_result_free(&r);
	return st;
}

int anvil_solver_verdict(struct anvil_solver *s, const struct anvil_plan *pl,
			 struct anvil_verdict *v, struct anvil_err *err)
{
	return anvil_solver_verdict_with(s, pl, NULL, v, err);
}

int anvil_solver_verdict_with(struct anvil_solver *s, const struct anvil_plan *pl,
			      const struct anvil_result *layer, struct anvil_verdict *v,
			      struct anvil_err *err)
{
	int st;
	struct anvil_err e2 = {0};
	enum anvil_verdict_qs why = anvil_verdict_quasi_static(pl);
	if (why != ANVIL_VERDICT_QS_NO)
		return quasi_static_verdict(s, pl, why, layer, v, err);
	struct anvil_field *f = row_field(s, pl, 1, &st, err);
	if (!f)
		return st;
	int fs = anvil_verdict_make(&pl->pb, f, v, &e2);
	anvil_field_free(f);
	if (fs) {
		if (err)
			*err = e2;
		return fs;
	}
	return st;
}
