/* problem.h: a scene read once, at the edge, into what the engine needs.
 *
 * The engine (plan.h, solver.h) never sees a scene: a front end turns its
 * scene into a problem here, once, and the planner makes a plan of it.
 * A problem is plain data (copy it freely); it holds the physical
 * parameters, h/r0 exactly as the scene gives it ("2.2 r0" is 2.2 to the
 * bit whatever r0, so that layer responses are shared across radii), the
 * two materials (for the planner's yield check) and the run options. */
#ifndef ANVIL_PROBLEM_H
#define ANVIL_PROBLEM_H

#include "accuracy.h"
#include "material.h"
#include "options.h"
#include "params.h"
#include "scene.h"
#include "status.h"

struct anvil_problem {
	struct anvil_params p;
	double hh;                          /* h/r0; INFINITY for a half-space */
	struct anvil_material impactor, layer; /* with the scene's overrides */
	enum anvil_accuracy accuracy;
	enum anvil_scheme scheme;
	double dt;                          /* s; 0: chosen from the accuracy */
	unsigned models;                    /* solver.models as asked */
	unsigned run;                       /* the rows a run computes (anvil_scene_models) */
	struct anvil_effects effects;
};

/* Check sc and fill pb from it.  ANVIL_EINVAL with the key in err for a
 * scene that fails its checks or gives parameters out of range. */
int anvil_problem_init(struct anvil_problem *pb, const struct anvil_scene *sc,
		       struct anvil_err *err);

/* The physical parameters alone, for code that needs no run options. */
int anvil_params_from_scene(struct anvil_params *p, const struct anvil_scene *sc,
			    struct anvil_err *err);

#endif
