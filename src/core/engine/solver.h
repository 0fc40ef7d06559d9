/* solver.h: executes a plan (plan.h), row by row.
 *
 * A solver owns what is expensive and reusable: the layer responses
 * ("plans", keyed by h/r0, nu and accuracy, in dimensionless form), kept in
 * a cache (cache.h) in memory and on disk, so a change of velocity, mass
 * or impactor material re-runs in milliseconds.
 * The solver does what the plan's row says (method, job, fallback,
 * refusal) and never plans itself nor sees a scene: a front end turns its
 * scene into a problem (problem.h), the problem into a plan, and runs the
 * plan's rows.  With [effects] waves = auto the plan computes the layer
 * and halfspace rows the cheapest way that meets the accuracy: the
 * result's note then says which, and its error estimates include the
 * estimated model error.
 * One solver is used from one thread at a time; make one per thread. */
#ifndef ANVIL_SOLVER_H
#define ANVIL_SOLVER_H

#include <stddef.h>

#include "cache.h"
#include "options.h"
#include "plan.h"
#include "progress.h"
#include "result.h"
#include "status.h"


struct anvil_solver;

/* A new solver, NULL when out of memory.  Its disk cache is on, in
 * anvil_cache_default_dir() ($XDG_CACHE_HOME/anvil, ~/.cache/anvil; off
 * with ANVIL_NO_CACHE=1); change it with anvil_solver_set_cache_dir. */
struct anvil_solver *anvil_solver_alloc(void);
void anvil_solver_free(struct anvil_solver *s); /* NULL is a no-op */
void anvil_solver_set_progress(struct anvil_solver *s, anvil_progress_fn fn,
			       void *ctx);
/* Where layer responses are kept on disk; NULL or "" for memory only. */
int anvil_solver_set_cache_dir(struct anvil_solver *s, const char *dir,
			       struct anvil_err *err);
/* Warnings that are not errors (a corrupt cache file ignored, a cache
 * directory that cannot be written); without fn they are dropped. */
void anvil_solver_set_warn(struct anvil_solver *s, anvil_warn_fn fn, void *ctx);
/* The solver's cache, to price a plan against it (plan.h). */
const struct anvil_cache *anvil_solver_cache(const struct anvil_solver *s);

/* What a solver has spent: layer responses computed (not found in the
 * cache) and their kernel evaluations, and the cache's counters. */
struct anvil_solver_stats {
	unsigned long layer_computed;
	size_t layer_evals;
	struct anvil_cache_stats cache;
};
void anvil_solver_stats(const struct anvil_solver *s, struct anvil_solver_stats *st);

/* Execute row m of plan pl into r (which this initialises; free it with
 * anvil_result_free).  With nhist > 0 the histories over [0, t_s] are
 * kept, with about nhist samples.  Returns, and records in r->status with
 * the message in r->why (and err):
 *   ANVIL_OK;
 *   ANVIL_WTOL (> 0, a warning): the accuracy target was missed, r holds
 *     the best values with their error estimates;
 *   the row's refusal decided by the planner (ANVIL_ETOL: too many steps
 *     or terms; ANVIL_EINVAL: solver.dt too long), before any work;
 *   ANVIL_ETOL when a grown window is refused by the same rule;
 *   ANVIL_ECANCEL; ANVIL_ENOMEM; ANVIL_ENUM.
 * The responses the run uses are held in the cache while it runs and
 * given back at its end (cache.h). */
int anvil_solver_run(struct anvil_solver *s, const struct anvil_plan *pl, enum anvil_model m,
		     size_t nhist, struct anvil_result *r, struct anvil_err *err);
/* The same for the row of model m with contact model c (PHYSICAL or PAPER:
 * anvil_plan_row_of; AUTO is pl->row[m], as anvil_solver_run).  r->contact
 * says which contact the result has.  ANVIL_EINVAL when the plan has no
 * such row. */
int anvil_solver_run_contact(struct anvil_solver *s, const struct anvil_plan *pl,
			     enum anvil_model m, enum anvil_contact c, size_t nhist,
			     struct anvil_result *r, struct anvil_err *err);

/* The paper's yield check, over the r0 patch (engine/yield.c; the verdict
 * on the layer, over the true contact, is anvil_solver_verdict in
 * verdict.h): run plan pl's layer row
 * (the halfspace row when h = inf) with the histories the field needs,
 * make its field and find where and when the von Mises stress peaks
 * (field.h; pk->yield from the layer's material, the plan's accuracy).
 * Returns the run's status (ANVIL_WTOL: the impact missed its target, pk
 * still filled) or the field's. */
struct anvil_field_peak;
int anvil_solver_yield(struct anvil_solver *s, const struct anvil_plan *pl,
		       struct anvil_field_peak *pk, struct anvil_err *err);

#endif
