#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "hertz.h"
#include "params.h"
#include "solver.h"
#include "zener.h"

struct anvil_solver {
	anvil_progress_fn progress;
	void *progress_ctx;
};

struct anvil_solver *anvil_solver_alloc(void)
{
	return calloc(1, sizeof(struct anvil_solver));
}

void anvil_solver_free(struct anvil_solver *s)
{
	free(s);
}

void anvil_solver_set_progress(struct anvil_solver *s, anvil_progress_fn fn,
			       void *ctx)
{
	s->progress = fn;
	s->progress_ctx = ctx;
}

static double wall_seconds(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int anvil_solver_run(struct anvil_solver *s, const struct anvil_scene *sc,
		     enum anvil_model m, size_t nhist, struct anvil_result *r,
		     struct anvil_err *err)
{
	struct anvil_params p;
	double t0 = wall_seconds();
	int st;
	anvil_result_init(r, m);
	(void)s;
	st = anvil_params_init(&p, sc, err);
	if (st)
		return st;
	switch (m) {
	case ANVIL_MODEL_HERTZ:
		st = anvil_hertz_run(&p, nhist, r, err);
		break;
	case ANVIL_MODEL_ZENER:
		st = anvil_zener_run(&p, nhist, r, err);
		break;
	default:
		st = anvil_err_set(err, ANVIL_EINVAL, "model '%s' is not available",
				   anvil_model_name(m));
	}
	r->seconds = wall_seconds() - t0;
	return st;
}
