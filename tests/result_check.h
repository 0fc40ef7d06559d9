/* result_check.h: what every sane impact result satisfies, and agreement
 * of two values within their summed error estimates (test_stab, test_thin). */
#ifndef ANVIL_TEST_RESULT_CHECK_H
#define ANVIL_TEST_RESULT_CHECK_H

#include <math.h>

#include "result.h"

/* P_max > 0, t_s > 0 (finite), R_f in [0, 1], E_a >= 0. */
static inline int result_sane(const struct anvil_result *r)
{
	return isfinite(r->Pmax.val) && r->Pmax.val > 0 && isfinite(r->ts.val) && r->ts.val > 0 &&
	       r->Rf.val >= 0 && r->Rf.val <= 1 && r->Ea.val >= 0;
}

/* |a - b| within a's and b's error estimates summed. */
static inline int val_within(const struct anvil_val *a, const struct anvil_val *b)
{
	return fabs(a->val - b->val) <= a->err + b->err;
}

#endif
