/* solver_impl.h: what solver.c (the paper's contact, the runs of a plan's
 * rows) and solver_phys.c (the physical contact's row) share; internal to
 * the engine. */
#ifndef ANVIL_SOLVER_IMPL_H
#define ANVIL_SOLVER_IMPL_H

#include <stddef.h>

#include "cache.h"
#include "green.h"
#include "halfspace.h"
#include "impact.h"
#include "plan.h"
#include "plate.h"
#include "solver.h"

struct anvil_solver {
	anvil_progress_fn progress;
	void *progress_ctx;
	/* the responses, each made once and shared by every impact that needs
	 * it ("plan once, execute many times") */
	struct anvil_cache *cache;
	/* the plate's K(t) table, kept from one response to the next (plate.h):
	 * a long window's correction, its twin and its patch's share it */
	struct anvil_plate_memo *plate;
	unsigned long layer_computed;
	size_t layer_evals;
};

/* The responses a run holds (cache.h: never evicted until given back):
 * the half-space and, per window tried (ANVIL_MAX_ATTEMPTS) and bandwidth
 * (refine_max + 1), a response and its twin. */
#define HELD_MAX (1 + 2 * ANVIL_MAX_ATTEMPTS * (ANVIL_PAPER_MAX_REFINE + 1))

struct held {
	const void *p[HELD_MAX];
	int n;
};

/* Hold p (a response from the cache) for this run; p back. */
const void *solver_held_add(struct held *h, const void *p);
/* Give back every hold. */
void solver_held_release(struct anvil_cache *c, struct held *h);

/* The anvil's ramp response: exact half-space plus the layer correction,
 * or (quasi-static anvil, no hs) the static compliance times tau. */
struct response {
	const struct anvil_halfspace *hs;
	const struct anvil_green *corr;
	double stat;
	/* the correction's start (solver_start.c): below t1 (0: none) its
	 * ramp is 0 before t0, then c2 x^2 + c3 x^3 in x = tau - t0 */
	double t0, t1, c2, c3;
};

/* The correction's start in rs (solver_start.c) for a band omega
 * (r0/c2 units) on the layer of p: ANVIL_OK or the ramp's error. */
int solver_start_set(struct response *rs, double omega, const struct anvil_params *p);

/* The impact's ramp callback (impact.h) over a struct response. */
int solver_response_ramp(void *ctx, double tau, double *val);
/* Its second derivative where it has a closed form (a layer correction
 * beyond its plate's T1, no half-space: anvil_green_impulse), else
 * ANVIL_EINVAL: the impact's far field (impact.h impulse). */
int solver_response_impulse(void *ctx, double tau, double *val);

/* Whether r meets the level's target: ANVIL_OK, ANVIL_WTOL (values stand,
 * the estimate says why in err), ANVIL_ENUM (unphysical). */
int solver_check_target(const struct anvil_result *r, enum anvil_accuracy acc,
			struct anvil_err *err);
/* A flat end's part of t_s's estimate (result.h ts_graze) added to r,
 * the target checked again when st is ANVIL_OK or ANVIL_WTOL; else st
 * (solver_graze.c). */
int solver_graze(struct anvil_result *r, enum anvil_accuracy acc, int st, struct anvil_err *err);
/* Add to r's estimates the layer correction's band error: r against c,
 * its twin at half the band (band: r's, 1/s) (solver_twin.c). */
void solver_add_green_error(struct anvil_result *r, const struct anvil_result *c, double band);
/* The relative estimates of P_max, t_s and R_f as solver_check_target
 * weighs them against the target, e[3]. */
void solver_target_errs(const struct anvil_result *r, double e[3]);
/* The growing step's options (impact.h) for job j. */
void solver_grow_opts(struct anvil_impact_opts *io, const struct anvil_problem *pb,
		      const struct anvil_wave_job *j);
/* Add the model error d (relative) of a left-out effect to r's estimates. */
void solver_add_model_error(struct anvil_result *r, const struct anvil_params *p, double d);
/* t_max's error from P_max's and the peak's curvature, at least the
 * band's (1/s; 0: none). */
void solver_tmax_from_pmax(struct anvil_result *r, double band);
/* Short separations merged, the budget of contacts, the rest state's
 * tolerance and the growing step (impact.h) for job j. */
void solver_merge_opts(struct anvil_impact_opts *io, const struct anvil_problem *pb,
		       const struct anvil_wave_job *j);
/* The rest state and the repeated contacts in r's note. */
void solver_rest_note(struct anvil_result *r);
void solver_contacts_note(struct anvil_result *r);

/* The physical contact's row (solver_phys.c). */
int solver_run_physical(struct anvil_solver *s, const struct anvil_plan *pl,
			const struct anvil_plan_row *row, size_t nhist, struct anvil_result *r,
			struct anvil_err *err);

#endif
