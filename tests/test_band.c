/* test_band: the physical contact's band on thin plates (issue 11).
 *
 * The plan sizes the corrections' band by the Hertz pulse and, for the
 * physical row, by the force's rise too (plan.c, phys_band: Zener's
 * t_max); the solver doubles it while P_max's estimate misses the target
 * mostly through the band (solver_phys.c, run_physical).  On h = 0.1 r0
 * (copper rod, 12.2 g, 10 m/s) the force peaks at 6 us of a 13 ms
 * contact: at the pulse's band P_max was 158.3 +- 10 N (exit 1), the
 * converged value 154.758 N. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "cache.h"
#include "scene_run.h"
#include "tap.h"

static int plan_of(const char *h, enum anvil_contact c, struct anvil_plan *pl)
{
	struct anvil_scene sc;
	struct anvil_err e;
	anvil_scene_default(&sc);
	if (anvil_scene_set(&sc, "layer.thickness", h, NULL, 0, &e))
		return -1;
	sc.accuracy = ANVIL_ACC_NORMAL;
	sc.effects.contact = c;
	sc.effects.waves = ANVIL_WAVES_LAYER;
	return scene_plan(&sc, pl, &e);
}

static int run(struct anvil_plan *pl, struct anvil_result *r)
{
	struct anvil_solver *s = anvil_solver_alloc();
	struct anvil_err e = { 0 };
	anvil_solver_set_cache_dir(s, NULL, NULL);
	int st = anvil_solver_run(s, pl, ANVIL_MODEL_LAYER, 0, r, &e);
	if (st)
		diag("  %s", e.msg);
	anvil_solver_free(s);
	return st;
}

/* lambda* >= 1e4 (h = 0.05 r0, 100 kg at 1 m/s: 3.6e4): the plan starts at
 * twice its band (plan.c, PHYS_WIDE_LAMBDA), where the solver went after
 * throwing a round away; planned at the narrower band, the solver doubles
 * it and lands on the same bits. */
static void wide_band(void)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err e;
	anvil_scene_default(&sc);
	const char *kv[] = { "layer.thickness", "0.05r0", "impactor.mass", "100kg",
			     "impact.velocity", "1m/s", "effects.waves", "layer", NULL };
	int bad = 0;
	for (int i = 0; kv[i]; i += 2)
		bad |= anvil_scene_set(&sc, kv[i], kv[i + 1], NULL, 0, &e);
	bad = bad || scene_plan(&sc, &pl, &e);
	if (!ok(!bad && pl.pb.p.lambda_star > 1e4, "h = 0.05 r0, 100 kg, 1 m/s planned (lambda* %.3g)",
		bad ? 0.0 : pl.pb.p.lambda_star))
		return;
	struct anvil_result a, b;
	double tgt = anvil_accuracy_target(ANVIL_ACC_NORMAL);
	int sa = run(&pl, &a);
	ok(sa == ANVIL_OK && a.Pmax.err <= tgt * a.Pmax.val && !strstr(a.note, "the band"),
	   "  at its planned band: P_max %.6g +- %.2g N meets normal, no doubling", a.Pmax.val,
	   a.Pmax.err);
	struct anvil_wave_job *j = &pl.row[ANVIL_MODEL_LAYER].job;
	j->omega_idx -= ANVIL_CACHE_STEPS;
	j->omega = anvil_cache_grid(j->omega_idx);
	j->twin_idx = j->omega_idx - ANVIL_CACHE_STEPS;
	int sb = run(&pl, &b);
	ok(sb == ANVIL_OK && strstr(b.note, "the band 2x the plan's") && a.Pmax.val == b.Pmax.val &&
		   a.ts.val == b.ts.val && a.tmax.val == b.tmax.val && a.Rf.val == b.Rf.val,
	   "  at half of it the solver doubles it (%s) to the same bits",
	   strstr(b.note, "the band") ? strstr(b.note, "the band") : "no doubling");
	anvil_result_free(&a);
	anvil_result_free(&b);

	/* 1 kg at 1 km/s on h = 0.02 r0 (lambda* 5.6e4): the contact is wider
	 * than the layer, which is why the row is refused, whatever the wide
	 * band's terms would cost (24298, over the limit: the refusal said so
	 * first) */
	anvil_scene_set(&sc, "layer.thickness", "0.02r0", NULL, 0, &e);
	anvil_scene_set(&sc, "impactor.mass", "1kg", NULL, 0, &e);
	anvil_scene_set(&sc, "impact.velocity", "1000m/s", NULL, 0, &e);
	bad = scene_plan(&sc, &pl, &e);
	const struct anvil_plan_row *r = &pl.row[ANVIL_MODEL_LAYER];
	ok(!bad && r->status && strstr(r->refusal, "exceeds h"), "1 kg at 1 km/s: refused for a/h (%s)",
	   bad ? e.msg : r->refusal);

	/* h = 1 nm, the default rod: lambda* = 1e13, where Zener's ODE gives
	 * up; the plate is his dashpot there, and the row is refused when
	 * planned (it ran 14-29 s into "numerical failure") */
	anvil_scene_default(&sc);
	anvil_scene_set(&sc, "layer.thickness", "1e-9m", NULL, 0, &e);
	bad = scene_plan(&sc, &pl, &e);
	r = &pl.row[ANVIL_MODEL_LAYER];
	ok(!bad && pl.pb.p.lambda_star > 1e12 && r->status && strstr(r->refusal, "exceeds h"),
	   "h = 1 nm: refused for a/h when planned (%s)", bad ? e.msg : r->refusal);
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(11);
	struct anvil_plan thin, paper, thick, thick_paper;
	int st = plan_of("0.1r0", ANVIL_CONTACT_PHYSICAL, &thin) |
		 plan_of("0.1r0", ANVIL_CONTACT_PAPER, &paper) |
		 plan_of("1r0", ANVIL_CONTACT_PHYSICAL, &thick) |
		 plan_of("1r0", ANVIL_CONTACT_PAPER, &thick_paper);
	if (!ok(!st, "plans made"))
		return done_testing();
	struct anvil_wave_job *jt = &thin.row[ANVIL_MODEL_LAYER].job;
	int pulse = paper.row[ANVIL_MODEL_LAYER].job.omega_idx;
	int d_thin = jt->omega_idx - pulse;
	int d_thick = thick.row[ANVIL_MODEL_LAYER].job.omega_idx -
		      thick_paper.row[ANVIL_MODEL_LAYER].job.omega_idx;
	ok(d_thin >= 2 * ANVIL_CACHE_STEPS && d_thick <= 1,
	   "h = 0.1 r0: the band %.2g times the pulse's (Zener's rise); h = r0: %.2g times",
	   exp2((double)d_thin / ANVIL_CACHE_STEPS), exp2((double)d_thick / ANVIL_CACHE_STEPS));

	struct anvil_result a, b;
	int sa = run(&thin, &a);
	double tgt = anvil_accuracy_target(ANVIL_ACC_NORMAL);
	ok(sa == ANVIL_OK && a.Pmax.err <= tgt * a.Pmax.val && !strstr(a.note, "the band"),
	   "  at its planned band: P_max %.6g +- %.2g N meets normal, no doubling", a.Pmax.val, a.Pmax.err);

	/* the plan as it was (the pulse's band): the solver widens it */
	jt->omega_idx = pulse;
	jt->omega = anvil_cache_grid(pulse);
	jt->twin_idx = pulse - ANVIL_CACHE_STEPS;
	int sb = run(&thin, &b);
	ok(sb == ANVIL_OK && strstr(b.note, "the band 4x the plan's"),
	   "  planned at the pulse's band: doubled twice (status %d; %s)", sb,
	   strstr(b.note, "the band") ? strstr(b.note, "the band") : "no doubling");
	ok(b.Pmax.err <= tgt * b.Pmax.val && fabs(a.Pmax.val - b.Pmax.val) <= a.Pmax.err + b.Pmax.err,
	   "  then within normal: %.6g +- %.2g N, the planned band's within their errors", b.Pmax.val,
	   b.Pmax.err);
	anvil_result_free(&b);

	/* a doubling that does not pay is not kept going: the pmma row missed by
	 * 1.1e-3 mostly through the patch terms; the default rod on the paper's
	 * case meets the target without any */
	struct anvil_result c;
	int sc = run(&thick, &c);
	ok(sc == ANVIL_OK && !strstr(c.note, "the band"), "h = r0: no doubling (P_max %.6g +- %.2g N)",
	   c.Pmax.val, c.Pmax.err);
	anvil_result_free(&a);
	anvil_result_free(&c);
	wide_band();
	return done_testing();
}
