/* yield.c: the yield check as one call: the solver's impact, then the
 * field module's peak von Mises stress (field.h).  In the engine because
 * it runs the solver: the field module depends on no engine. */
#include <math.h>

#include "field.h"
#include "solver.h"

int anvil_solver_yield(struct anvil_solver *s, const struct anvil_plan *pl,
		       struct anvil_field_peak *pk, struct anvil_err *err)
{
	const struct anvil_problem *pb = &pl->pb;
	enum anvil_model m = isinf(pb->p.h) ? ANVIL_MODEL_HALFSPACE : ANVIL_MODEL_LAYER;
	struct anvil_result r;
	struct anvil_err e2 = {0};
	/* the field loads the layer over the paper's patch r0: the paper's
	 * contact's P(t) (plan.h: the plan always holds that row) */
	int st = anvil_solver_run_contact(s, pl, m, ANVIL_CONTACT_PAPER, ANVIL_FIELD_NHIST, &r, err);
	if (st < 0) {
		anvil_result_free(&r);
		return st;
	}
	struct anvil_field *f = anvil_field_from_result(&pb->p, pb->accuracy, &r, &e2);
	int fs = f ? anvil_field_peak(f, pb->layer.yield, pk, &e2) : e2.status;
	anvil_field_free(f);
	anvil_result_free(&r);
	if (fs) {
		if (err)
			*err = e2;
		return fs;
	}
	return st;
}
