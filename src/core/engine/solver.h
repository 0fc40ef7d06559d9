/* solver.h: the one entry point the front ends use to run a model.
 *
 * A solver owns what is expensive and reusable: the layer responses
 * ("plans", keyed by h/r0, nu and accuracy, in dimensionless form), kept in
 * a cache (cache.h) in memory and on disk, so a change of velocity, mass
 * or impactor material re-runs in milliseconds.
 * With [effects] waves = auto (the default) the layer and halfspace models
 * are computed the cheapest way that meets the scene's accuracy (plan.h):
 * the result's note then says which, and its error estimates include the
 * estimated model error.
 * One solver is used from one thread at a time; make one per thread. */
#ifndef ANVIL_SOLVER_H
#define ANVIL_SOLVER_H

#include <stddef.h>

#include "cache.h"
#include "progress.h"
#include "result.h"
#include "scene.h"
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

/* Run model m for scene sc into r (which this initialises; free it with
 * anvil_result_free).  With nhist > 0 the histories over [0, t_s] are kept,
 * with about nhist samples.  Returns ANVIL_OK; ANVIL_EINVAL for a scene the
 * model cannot take; ANVIL_ETOL when the scene's accuracy could not be
 * reached (r then holds the best values with their error estimates);
 * ANVIL_ECANCEL; ANVIL_ENOMEM; ANVIL_ENUM. */
int anvil_solver_run(struct anvil_solver *s, const struct anvil_scene *sc,
		     enum anvil_model m, size_t nhist, struct anvil_result *r,
		     struct anvil_err *err);

#endif
