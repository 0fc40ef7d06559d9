/* solver_graze.c: a flat end's part of t_s's estimate (result.h ts_graze,
 * impact_end.c) joins ts.err once the row's refinements are decided.
 *
 * Why last: the refinements (a wider band, solver.c band_dominates and
 * solver_phys.c band_helps; a wider band kept when its worst estimate is
 * the smaller) weigh the estimates they can lower.  The flatness term is
 * the deflection's own error over the approach's slope: no band lowers
 * it, and weighed there it would start refinements that change nothing
 * but the values' bits, or stop those the band's part still asks for.
 * Added here, the values are those without it; the target is checked
 * again, so a row it makes miss says so (ANVIL_WTOL). */
#include "solver_impl.h"

int solver_graze(struct anvil_result *r, enum anvil_accuracy acc, int st, struct anvil_err *err)
{
	if (!(r->ts_graze > 0) || (st != ANVIL_OK && st != ANVIL_WTOL))
		return st;
	r->ts.err += r->ts_graze;
	return solver_check_target(r, acc, err);
}
