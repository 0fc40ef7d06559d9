/* scene_run.h: a scene's row through the path the front ends take (scene
 * -> problem -> plan -> solver), for tests that start from a scene. */
#ifndef ANVIL_TEST_SCENE_RUN_H
#define ANVIL_TEST_SCENE_RUN_H

#include "plan.h"
#include "problem.h"
#include "scene.h"
#include "solver.h"

/* The plan of sc (cache NULL: decisions never depend on it). */
static inline int scene_plan(const struct anvil_scene *sc, struct anvil_plan *pl,
			     struct anvil_err *err)
{
	struct anvil_problem pb;
	int st = anvil_problem_init(&pb, sc, err);
	return st ? st : anvil_plan_make(&pb, NULL, pl, err);
}

/* Row m of sc run by solver s; r is initialised either way. */
static inline int scene_run(struct anvil_solver *s, const struct anvil_scene *sc,
			    enum anvil_model m, size_t nhist, struct anvil_result *r,
			    struct anvil_err *err)
{
	struct anvil_plan pl;
	int st = scene_plan(sc, &pl, err);
	if (!st)
		return anvil_solver_run(s, &pl, m, nhist, r, err);
	anvil_result_init(r, m);
	r->status = st;
	return st;
}

#endif
