/* verdict_near.h: the near face's stress for the verdict (verdict.c):
 * the contact's quasi-static Hertz field and the plate's bending added at
 * the same instant, the largest over the contact (verdict_near.c says
 * how, and why there).  Private to the verdict. */
#ifndef ANVIL_VERDICT_NEAR_H
#define ANVIL_VERDICT_NEAR_H

#include "result.h"
#include "verdict.h"

/* Fill v->near, near_r, near_z, near_t and near_sb under history h, v's
 * bending (bend, bend_t, bend_tol) already in; ANVIL_OK, or the failure
 * with its message in err. */
int verdict_near_face(const struct anvil_problem *pb, const struct anvil_history *h,
		      struct anvil_verdict *v, struct anvil_err *err);

#endif
