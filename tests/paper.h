/* paper.h: the paper's impact (copper rod on steel, the embedded default
 * scene) at thickness h_r0 (INFINITY: half-space) and velocity V0, through
 * the same scene -> params path as anvil itself. */
#ifndef ANVIL_TEST_PAPER_H
#define ANVIL_TEST_PAPER_H

#include <math.h>
#include <stdio.h>

#include "params.h"
#include "problem.h"
#include "scene.h"

static inline void paper_params(struct anvil_params *p, double h_r0, double V0)
{
	struct anvil_scene sc;
	struct anvil_err e;
	anvil_scene_default(&sc);
	sc.velocity = V0;
	sc.thickness = h_r0;
	sc.thickness_per_r0 = !isinf(h_r0);
	if (anvil_params_from_scene(p, &sc, &e))
		printf("# paper_params: %s\n", e.msg);
}

#endif
