/* problem.c: scene -> problem, the one place the engine's input is read. */
#include <math.h>
#include <string.h>

#include "problem.h"

int anvil_problem_init(struct anvil_problem *pb, const struct anvil_scene *sc,
		       struct anvil_err *err)
{
	memset(pb, 0, sizeof *pb);
	int st = anvil_scene_check(sc, err);
	if (st)
		return st;
	st = anvil_params_init(&pb->p, sc->mass, sc->radius, sc->velocity, anvil_scene_h(sc),
			       &sc->impactor.mat, &sc->layer.mat, err);
	if (st)
		return st;
	pb->hh = sc->thickness_per_r0 ? sc->thickness : pb->p.h / pb->p.r0;
	pb->impactor = sc->impactor.mat;
	pb->layer = sc->layer.mat;
	pb->accuracy = sc->accuracy;
	pb->scheme = sc->scheme;
	pb->dt = sc->dt;
	pb->models = sc->models;
	pb->run = anvil_scene_models(sc);
	pb->effects = sc->effects;
	/* [effects] contact = auto: both models side by side for the paper's own
	 * case, the physical one for any other scene (options.h) */
	if (pb->effects.contact == ANVIL_CONTACT_AUTO)
		pb->effects.contact = anvil_scene_is_paper_case(sc) ? ANVIL_CONTACT_BOTH
								     : ANVIL_CONTACT_PHYSICAL;
	return ANVIL_OK;
}

int anvil_params_from_scene(struct anvil_params *p, const struct anvil_scene *sc,
			    struct anvil_err *err)
{
	struct anvil_problem pb;
	int st = anvil_problem_init(&pb, sc, err);
	*p = pb.p;
	return st;
}
