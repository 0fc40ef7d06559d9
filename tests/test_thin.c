/* test_thin: thin plates under the physical contact never hang and never
 * print garbage (issue 11).
 *
 * Copper rod r0 = 4 mm on steel unless said, the layer row at draft
 * through the front ends' path (scene -> plan -> solver, cache in
 * memory).  Each scene either is refused with a one-line reason saying
 * why the model does not apply (status < 0, the reason named), or gives
 * a bounded answer: P_max > 0, t_s > 0, R_f in [0, 1], E_a >= 0, a
 * sensible count of contacts (1 up to the budget), and, where normal is
 * cheap, draft and normal within their stated errors.  Each scene's CPU
 * time is shown (not asserted: speed is scripts/bench's); before these
 * checks r4 ran over 10 minutes and h = 0.1 r0 (12.2 g) 3-5 minutes.
 * Where the impactor comes to rest on the plate (impact_rest.c) the row
 * says so: R_f in [0, bound] with the bound within the level's target,
 * E_a in [E0 (1 - bound^2), E0], Zener's R_f* within the bound; t_s is
 * then when the level's bound was met, so normal's is later than
 * draft's.  A scene that ends by itself is followed to its end as
 * before.  The paper's contact on a 1 mm plate is held to the same
 * (it chattered: 334 contacts, 10 s). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_errno.h>

#include "scene_run.h"
#include "result_check.h"
#include "tap.h"

struct thin {
	const char *name, *h, *mass, *velocity, *material;
	const char *refusal; /* a word the refusal must hold; NULL: must run */
	enum anvil_accuracy acc; /* the level run first */
	int normal;          /* 1: normal too, against the first (draft) */
	int rest;            /* 1: comes to rest on the plate (impact_rest.c); 0: must not;
				EITHER: on the edge, both held to their checks */
	int dead;            /* 1: R_f ~ 0, the co-moving phase one contact (up to 4) */
	enum anvil_contact contact;
};

#define DRAFT ANVIL_ACC_DRAFT
#define NORMAL ANVIL_ACC_NORMAL
#define PHYS ANVIL_CONTACT_PHYSICAL
/* Where the late chatter is decided by the layer response's last bits:
 * the plate tail's K table (plate.c) changed its interpolant at the 1e-9
 * level (its own error 3e-9 at h = 0.02 r0) and r4 went from 4 contacts
 * ending at 4860 us (R_f 2.2e-5) to at rest from 1119 us (R_f in [0,
 * 9.8e-4]); the paper's contact on 1 mm from 7 contacts to 62.6 ms (R_f
 * 3e-9) to at rest from 913 us (R_f in [0, 9.9e-4]).  Both answers are
 * bounded and agree within their intervals; neither is the more right. */
#define EITHER 2

static const struct thin scenes[] = {
	/* once kicked every T1 = 64 r0/c2 (80 us) by a step in the layer
	 * correction where the plate took over (plate.c, blend), pumped past
	 * the energy bound or lost at a contact's end: now a bounded answer
	 * (draft: P_max 6.6 +- 0.8 N, 4 contacts; Zener's plate, lambda* =
	 * 89: 6.25 N); it ends by itself, so the rest state leaves it be */
	{ "r4: h = 0.02 r0, 0.1 g, 10 m/s", "0.02r0", "0.1g", "10m/s", NULL, NULL, DRAFT, 0, EITHER, 1,
	  PHYS },
	/* the impactor comes to rest on the unbounded plate: gaps of pm over
	 * tens of ms, more contacts than the budget: once refused, now at
	 * rest with R_f bounded (draft follows 47 contacts to the end, 15 s:
	 * normal alone here) */
	{ "r5: h = 0.02 r0, 0.1 g, 0.1 m/s", "0.02r0", "0.1g", "0.1m/s", NULL, NULL, NORMAL, 0, 1, 0, PHYS },
	/* a/h = 2 on Zener's plate: Hertz's half-space law does not hold */
	{ "r6: h = 0.1 r0, 0.1 g, 1000 m/s", "0.1r0", "0.1g", "1000m/s", NULL, "exceeds h", DRAFT, 0, 0, 0,
	  PHYS },
	/* a rebound from a thin plate (R_f 0.0074 at draft): no rest */
	{ "h = 0.5 r0, 12.2 g, 10 m/s", "0.5r0", "12.2g", "10m/s", NULL, NULL, DRAFT, 0, 0, 0, PHYS },
	/* the co-moving phase merged: one contact, R_f ~ 1e-6.  At normal it
	 * was refused (more than 64 contacts): the correction's truncated
	 * series rang at the band's edge, P oscillated at its period (1.94 us)
	 * and grew until the bodies parted every period; filtered (green.h),
	 * one contact, P_max 158 +- 10 N (draft 168 +- 29, Zener 156); it
	 * ends grazing (R_f 1.6e-7, its t_s moved by its steps' rule beyond
	 * its estimate): at rest (impact_rest.c, REST_GRAZE) */
	{ "h = 0.1 r0, 12.2 g, 10 m/s", "0.1r0", "12.2g", "10m/s", NULL, NULL, DRAFT, 1, 1, 1, PHYS },
	/* refused at normal in the same way, by its error run at half the
	 * band (263 us, 0.19 m/s): now at rest on the plate, P_max 0.627 +-
	 * 0.039 N (Zener 0.624) */
	{ "r7: h = 0.02 r0, 0.1 g, 1 m/s", "0.02r0", "0.1g", "1m/s", NULL, NULL, NORMAL, 0, 1, 0, PHYS },
	/* ends grazing (its t_s moved from 93.14 to 93.30 ms with the plate
	 * tail's interpolant, against an estimate of 12 us): at rest */
	{ "500 g steel rod on 1 mm steel, 1 m/s", "1mm", "500g", "1m/s", "steel", NULL, DRAFT, 1, 1, 0,
	  PHYS },
	/* the paper's contact chattered here with no merge and no budget:
	 * 334 contacts at normal, 10 s (174 and 47 s before the speed-ups) */
	{ "paper's contact, default rod on 1 mm steel", "1mm", "12.2g", "10m/s", NULL, NULL, DRAFT, 1, EITHER, 0,
	  ANVIL_CONTACT_PAPER },
};
#define NSCENE (sizeof scenes / sizeof scenes[0])

static int run_model(struct anvil_solver *s, const struct thin *x, enum anvil_accuracy acc,
		     enum anvil_model m, struct anvil_result *r, struct anvil_err *e)
{
	struct anvil_scene sc;
	anvil_scene_default(&sc);
	int st = anvil_scene_set(&sc, "layer.thickness", x->h, NULL, 0, e);
	if (!st)
		st = anvil_scene_set(&sc, "impactor.mass", x->mass, NULL, 0, e);
	if (!st)
		st = anvil_scene_set(&sc, "impact.velocity", x->velocity, NULL, 0, e);
	if (!st && x->material)
		st = anvil_scene_set(&sc, "impactor.material", x->material, NULL, 0, e);
	if (st) {
		anvil_result_init(r, m);
		return st;
	}
	sc.accuracy = acc;
	sc.effects.contact = x->contact;
	return scene_run(s, &sc, m, 0, r, e);
}

static int run_one(struct anvil_solver *s, const struct thin *x, enum anvil_accuracy acc,
		   struct anvil_result *r, struct anvil_err *e)
{
	return run_model(s, x, acc, ANVIL_MODEL_LAYER, r, e);
}

static int sane(const struct anvil_result *r)
{
	return result_sane(r) && isfinite(r->Rf.err);
}

/* A row at rest (impact.h, rest_tol): R_f in [0, bound] with the bound
 * within the level's target (R_f's half of it against check_target's
 * 0.1: 0.2 target), E_a in [E0 (1 - bound^2), E0], Zener's plate (the
 * lumped system the bound is derived for: his ODE's R_f, and his fit
 * R_f*) within the bound, and the note saying so. */
static void check_rest(struct anvil_solver *s, const struct thin *x, const struct anvil_result *r,
		       enum anvil_accuracy acc, int st)
{
	double b = r->rest_bound, tgt = anvil_accuracy_target(acc);
	struct anvil_result z;
	struct anvil_err ez = { 0 };
	int sz = run_model(s, x, acc, ANVIL_MODEL_ZENER, &z, &ez);
	double m = 0, v0 = 0, e0;
	sscanf(x->mass, "%lf", &m);
	sscanf(x->velocity, "%lf", &v0);
	e0 = 0.5 * m * 1e-3 * v0 * v0;
	diag("  %s: at rest from %.6g us, R_f < %.3g (%.3g +- %.2g), E_a %.6g +- %.2g J of %.6g; Zener: R_f %.3g +- %.2g (status %d), R_f* %.3g",
	     anvil_accuracy_name(acc), r->ts.val * 1e6, b, r->Rf.val, r->Rf.err, r->Ea.val, r->Ea.err, e0,
	     z.Rf.val, z.Rf.err, sz, r->Rf_star);
	ok(st >= 0 && b > 0 && b <= 0.2 * tgt && r->Rf.val >= 0 && r->Rf.val <= b &&
	   r->Rf.val - r->Rf.err <= 0,
	   "  %s: at rest, R_f in [0, %.2g], the bound within the target", anvil_accuracy_name(acc), b);
	ok(st >= 0 && r->Ea.val >= 0 && r->Ea.val <= e0 * (1 + 1e-9) &&
	   r->Ea.val + r->Ea.err >= e0 * (1 - 1e-9) && r->Rf_star <= b && sz >= 0 &&
	   z.Rf.val - z.Rf.err <= b && strstr(r->note, "came to rest on the plate"),
	   "  E_a in [0, E0] reaching E0, Zener's R_f and R_f* within the bound, the note says so");
	anvil_result_free(&z);
}

/* At rest t_s is when the rebound's bound fell within the target: a
 * slowly falling bound crossing a threshold.  Its estimate is the bound's
 * halving time (impact_rest.c, impact_rest_fill): a quarter of the step
 * moves r5's t_s by 0.16 us, where the estimate said 1e-4 us before. */
static void rest_step(struct anvil_solver *s)
{
	struct anvil_result r[2];
	const char *dt[2] = { "auto", "0.25us" };
	int st[2];
	for (int i = 0; i < 2; i++) {
		struct anvil_scene sc;
		struct anvil_err e = { 0 };
		anvil_scene_default(&sc);
		const char *kv[] = { "layer.thickness", "0.02r0", "impactor.mass", "0.1g",
				     "impact.velocity", "0.1m/s", "solver.dt", dt[i], NULL };
		st[i] = 0;
		for (int k = 0; kv[k]; k += 2)
			st[i] |= anvil_scene_set(&sc, kv[k], kv[k + 1], NULL, 0, &e);
		if (!st[i])
			st[i] = scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, &r[i], &e);
		else
			anvil_result_init(&r[i], ANVIL_MODEL_LAYER);
	}
	double d = fabs(r[0].ts.val - r[1].ts.val);
	ok(st[0] == 0 && st[1] == 0 && r[0].rest_bound > 0 && r[1].rest_bound > 0 && d > 0 &&
		   d <= r[0].ts.err + r[1].ts.err,
	   "r5 at rest, the step a quarter: t_s moves %.3g us within its estimates %.3g + %.3g us", d * 1e6,
	   r[0].ts.err * 1e6, r[1].ts.err * 1e6);
	anvil_result_free(&r[0]);
	anvil_result_free(&r[1]);
}

/* The paper's contact on a thin plate peaks far sooner than the pulse
 * the plan's step is sized by (solver.c, step_too_coarse): h = 0.2 r0
 * under 1 kg at 10 m/s peaked at 4.2 us within two steps of 2.5 us at
 * draft, P_max 999 +- 12 N, the target missed.  Run again at the
 * step that resolves the peak, it meets the target, says so, and agrees
 * with a run at a step the scene sets (no rerun there) within the two
 * estimates. */
static void paper_step(struct anvil_solver *s)
{
	struct anvil_result r[2];
	const char *dt[2] = { "auto", "0.3us" };
	int st[2];
	for (int i = 0; i < 2; i++) {
		struct anvil_scene sc;
		struct anvil_err e = { 0 };
		anvil_scene_default(&sc);
		const char *kv[] = { "layer.thickness", "0.2r0", "impactor.mass", "1kg", "impact.velocity",
				     "10m/s", "solver.dt", dt[i], "effects.contact", "paper", NULL };
		st[i] = 0;
		for (int k = 0; kv[k]; k += 2)
			st[i] |= anvil_scene_set(&sc, kv[k], kv[k + 1], NULL, 0, &e);
		sc.accuracy = ANVIL_ACC_DRAFT;
		if (!st[i])
			st[i] = scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, &r[i], &e);
		else
			anvil_result_init(&r[i], ANVIL_MODEL_LAYER);
		diag("paper's contact, h = 0.2 r0, 1 kg, 10 m/s, draft, step %s: status %d, P_max %.6g +- %.2g N at %.4g us%s%s",
		     dt[i], st[i], r[i].Pmax.val, r[i].Pmax.err, r[i].tmax.val * 1e6, st[i] ? ": " : "",
		     st[i] ? e.msg : "");
	}
	ok(st[0] == 0 && r[0].Pmax.err <= 1e-2 * r[0].Pmax.val && strstr(r[0].note, "the step"),
	   "paper's contact, early peak: the step refined, draft's target met, the note says so");
	ok(st[0] == 0 && st[1] >= 0 && !strstr(r[1].note, "the step") &&
		   fabs(r[0].Pmax.val - r[1].Pmax.val) <= r[0].Pmax.err + r[1].Pmax.err,
	   "  P_max within the estimates of a run at the scene's own finer step (%.3g N apart)",
	   fabs(r[0].Pmax.val - r[1].Pmax.val));
	anvil_result_free(&r[0]);
	anvil_result_free(&r[1]);
}

/* The paper's contact on h = 0.05 r0 under 10 kg at 1 mm/s: where the
 * step had grown long the layer's lag exceeded Hertz's compliance and the
 * march's two-step mode grew (impact.c, nyq_eps) to the full force: P_max
 * 7.9e-6 +- 9.6e-7 kN at 42.5 ms against the true early peak's 6.78e-6 at
 * 14.8 us.  Now the force is smooth after its peak (no sample stands out
 * of its neighbours' mean by 1 % of P_max) and P_max is the early peak's. */
static void paper_nyquist(struct anvil_solver *s)
{
	struct anvil_scene sc;
	struct anvil_err e = { 0 };
	struct anvil_result r;
	anvil_scene_default(&sc);
	const char *kv[] = { "layer.thickness", "0.05r0", "impactor.mass", "10kg", "impact.velocity",
			     "1mm/s", "effects.contact", "paper", NULL };
	int st = 0;
	for (int k = 0; kv[k]; k += 2)
		st |= anvil_scene_set(&sc, kv[k], kv[k + 1], NULL, 0, &e);
	if (!st)
		st = scene_run(s, &sc, ANVIL_MODEL_LAYER, 400, &r, &e);
	else
		anvil_result_init(&r, ANVIL_MODEL_LAYER);
	double jump = 0;
	for (size_t i = 1; i + 1 < r.hist.n; i++)
		if (r.hist.t[i] > 1e-3)
			jump = fmax(jump, fabs(r.hist.P[i] - 0.5 * (r.hist.P[i - 1] + r.hist.P[i + 1])));
	diag("paper's contact, h = 0.05 r0, 10 kg, 1 mm/s: status %d, P_max %.6g +- %.2g N at %.4g us, the largest jump after 1 ms %.3g N%s%s",
	     st, r.Pmax.val, r.Pmax.err, r.tmax.val * 1e6, jump, st ? ": " : "", st ? e.msg : "");
	ok(st == 0 && r.tmax.val < 100e-6 && r.Pmax.err <= 1e-3 * r.Pmax.val && r.hist.n > 100 &&
		   jump <= 0.01 * r.Pmax.val,
	   "paper's contact, a long step on a thin plate: no sawtooth, P_max the early peak's, the target met");
	anvil_result_free(&r);
}

int main(void)
{
	gsl_set_error_handler_off();
	struct anvil_solver *s = anvil_solver_alloc();
	anvil_solver_set_cache_dir(s, NULL, NULL); /* in memory: nothing on disk */
	for (size_t i = 0; i < NSCENE; i++) {
		const struct thin *x = &scenes[i];
		const char *lv = anvil_accuracy_name(x->acc);
		struct anvil_result d, n;
		struct anvil_err e = { 0 }, en = { 0 };
		clock_t c0 = clock();
		int sd = run_one(s, x, x->acc, &d, &e);
		diag("%s: %s status %d, %.2f s CPU, P_max %.6g +- %.2g N, t_s %.6g +- %.2g us, R_f %.4g +- %.2g, %zu contacts%s%s",
		     x->name, lv, sd, (double)(clock() - c0) / CLOCKS_PER_SEC, d.Pmax.val, d.Pmax.err,
		     d.ts.val * 1e6, d.ts.err * 1e6, d.Rf.val, d.Rf.err, d.ncontacts, sd ? ": " : "",
		     sd ? e.msg : "");
		if (x->refusal) {
			ok(sd < 0, "%s: refused", x->name);
			ok(sd < 0 && strstr(e.msg, x->refusal) && !strchr(e.msg, '\n') && strlen(e.msg) > 20,
			   "  with a one-line reason (%s)", *x->refusal ? x->refusal : "any");
			ok(d.status < 0 && d.status == sd, "  the row's status says so (no values to print)");
			anvil_result_free(&d);
			continue;
		}
		ok(sd >= 0, "%s: a bounded answer", x->name);
		ok(sd >= 0 && sane(&d) && d.ncontacts >= 1 && d.ncontacts <= ANVIL_MAX_RUN_CONTACTS,
		   "  P_max > 0, t_s > 0, R_f in [0, 1], E_a >= 0, 1 to %d contacts",
		   ANVIL_MAX_RUN_CONTACTS);
		if (x->rest == 1 || (x->rest == EITHER && d.rest_bound > 0))
			check_rest(s, x, &d, x->acc, sd);
		else
			ok(d.rest_bound == 0, "  not at rest: followed to its end");
		/* lambda* = 63 and 89: Zener's R_f = exp(-1.72 lambda*) ~ 1e-47 */
		if (x->dead)
			ok(sd >= 0 && d.Rf.val - d.Rf.err <= 1e-3 && d.ncontacts <= 4,
			   "  R_f ~ 0 (the plate carries the energy off), the co-moving phase one contact");
		if (!x->normal) {
			anvil_result_free(&d);
			continue;
		}
		c0 = clock();
		int sn = run_one(s, x, ANVIL_ACC_NORMAL, &n, &en);
		diag("%s: normal status %d, %.2f s CPU, P_max %.6g +- %.2g N, t_s %.6g +- %.2g us, R_f %.4g +- %.2g, %zu contacts%s%s",
		     x->name, sn, (double)(clock() - c0) / CLOCKS_PER_SEC, n.Pmax.val, n.Pmax.err,
		     n.ts.val * 1e6, n.ts.err * 1e6, n.Rf.val, n.Rf.err, n.ncontacts, sn ? ": " : "",
		     sn ? en.msg : "");
		/* at rest, t_s is when the level's bound was met: later at normal */
		int both = d.rest_bound > 0 && n.rest_bound > 0, one = (d.rest_bound > 0) != (n.rest_bound > 0);
		int ts_ok = both  ? n.ts.val >= d.ts.val && n.rest_bound <= d.rest_bound
			    : one ? 1
				  : val_within(&d.ts, &n.ts);
		ok(sd >= 0 && sn >= 0 && sane(&n) && val_within(&d.Pmax, &n.Pmax) && ts_ok &&
		   val_within(&d.Rf, &n.Rf) && val_within(&d.Ea, &n.Ea),
		   "  draft and normal agree within their stated errors%s",
		   both || one ? " (at rest: t_s is when the bound was met)" : "");
		if (x->rest == 1 || (x->rest == EITHER && n.rest_bound > 0))
			check_rest(s, x, &n, ANVIL_ACC_NORMAL, sn);
		anvil_result_free(&d);
		anvil_result_free(&n);
	}
	rest_step(s);
	paper_step(s);
	paper_nyquist(s);
	anvil_solver_free(s);
	plan(tap_n); /* at the end (TAP allows it): EITHER's checks depend on the outcome */
	return done_testing();
}
