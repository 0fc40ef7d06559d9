/* test_stab: the physical contact on thin layers stays stable (issue 11).
 *
 * The radiation lag -beta Q holds the layer correction's dw_c/dt; before
 * it was low-passed (impact.h, tau_lag), the scheme fed a delayed dP/dt
 * back into the contact and P alternated and blew up at the Nyquist
 * frequency ("impact: numerical failure") on ordinary thin scenes.  Each
 * reproducer runs at draft and normal through the front ends' path
 * (scene -> plan -> solver, cache in memory) and must give finite values
 * with R_f in [0, 1], E_a >= 0, P_max > 0, and draft and normal within
 * the sum of their stated errors (P_max, t_s, R_f, E_a).  A row that
 * misses its level's target is a warning (status > 0), not a failure. */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>

#include "scene_run.h"
#include "result_check.h"
#include "tap.h"

struct repro {
	const char *name;
	double hh, mass, velocity; /* h/r0, kg, m/s */
};

/* copper rod, r0 = 4 mm, on steel (the default scene otherwise) */
static const struct repro repros[] = {
	{ "h = 0.35 r0, 12.2 g, 10 m/s", 0.35, 12.2e-3, 10.0 },
	{ "h = 0.1 r0, 0.1 g, 10 m/s", 0.1, 0.1e-3, 10.0 },
	{ "h = 0.25 r0, 12.2 g, 10 m/s", 0.25, 12.2e-3, 10.0 },
};
#define NREPRO (sizeof repros / sizeof repros[0])

static int run_one(struct anvil_solver *s, const struct repro *x, enum anvil_accuracy acc,
		   struct anvil_result *r)
{
	struct anvil_scene sc;
	struct anvil_err e = { 0 };
	anvil_scene_default(&sc);
	sc.thickness = x->hh; /* h/r0 */
	sc.mass = x->mass;
	sc.velocity = x->velocity;
	sc.accuracy = acc;
	sc.effects.contact = ANVIL_CONTACT_PHYSICAL;
	int st = scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, r, &e);
	if (st < 0)
		diag("%s (%s): %s", x->name, anvil_accuracy_name(acc), e.msg);
	return st;
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(3 * (int)NREPRO);
	struct anvil_solver *s = anvil_solver_alloc();
	anvil_solver_set_cache_dir(s, NULL, NULL); /* in memory: nothing on disk */
	for (size_t i = 0; i < NREPRO; i++) {
		struct anvil_result d, n;
		int sd = run_one(s, &repros[i], ANVIL_ACC_DRAFT, &d);
		int sn = run_one(s, &repros[i], ANVIL_ACC_NORMAL, &n);
		diag("%s: draft P_max %.6g +- %.2g N, t_s %.6g +- %.2g us, R_f %.6g +- %.2g, %zu contacts",
		     repros[i].name, d.Pmax.val, d.Pmax.err, d.ts.val * 1e6, d.ts.err * 1e6, d.Rf.val,
		     d.Rf.err, d.ncontacts);
		diag("%s: normal P_max %.6g +- %.2g N, t_s %.6g +- %.2g us, R_f %.6g +- %.2g, %zu contacts",
		     repros[i].name, n.Pmax.val, n.Pmax.err, n.ts.val * 1e6, n.ts.err * 1e6, n.Rf.val,
		     n.Rf.err, n.ncontacts);
		ok(sd >= 0 && sn >= 0, "%s: draft and normal run (no numerical failure)",
		   repros[i].name);
		ok(sd >= 0 && sn >= 0 && result_sane(&d) && result_sane(&n),
		   "  P_max > 0, t_s > 0, R_f in [0, 1], E_a >= 0");
		ok(sd >= 0 && sn >= 0 && val_within(&d.Pmax, &n.Pmax) && val_within(&d.ts, &n.ts) &&
		   val_within(&d.Rf, &n.Rf) && val_within(&d.Ea, &n.Ea),
		   "  draft and normal agree within their stated errors");
		anvil_result_free(&d);
		anvil_result_free(&n);
	}
	anvil_solver_free(s);
	return done_testing();
}
