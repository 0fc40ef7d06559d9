/* test_paper_work.c: the planner's work of the paper's contact rows
 * (plan.h anvil_plan_paper_work, issue 11) against what the solver does.
 *
 * For a seeded random sample of scenes with the paper's contact (h/r0
 * 0.05-1000 and the half-space, V0 1 mm/s - 1 km/s, m 0.1 g - 100 kg, the
 * built-in material pairs, draft and normal), the layer model's row (its
 * method as planned: half-space or layer) is run on a fresh solver with
 * the cache in memory, and the plan's predicted counts are held to the
 * solver's: deterministic counts, not seconds (scripts/bench compares
 * seconds):
 *   windows: the windows the main impact tried, from the contact's end
 *     (the first anvil_wave_window beyond t_s; rows that came to rest are
 *     left out of this one: their t_s is the rest's, not an end);
 *   responses: the layer corrections computed (anvil_solver_stats), one
 *     per (band round, window) with the reflection inside it;
 *   evaluations: their kernel evaluations.
 * Each within a factor of 2 of the solver's (the rounds are the grid's
 * expected shares, plan_paper.c: a row of 1 or 3 rounds is within 2x of
 * 1.5-2), on layers of h >= r0 and the half-space.  On thinner plates the
 * paper's contact may outlast Zener's estimate by several windows (it
 * chatters, or comes to rest only where a later window would be refused):
 * not foreseen (plan_paper.c), their tally is printed, not held (here 3-4
 * of 66 miss 2x; with ANVIL_TEST_N=2000 ANVIL_TEST_PMAX=0.05, 12 of 990
 * rows, all h = 0.06-0.8 r0).  The rounds (on plates below r0 only) are
 * thus not held either.
 * Scenes the plan prices over PRICE_MAX seconds are left out to keep make
 * check short (ANVIL_TEST_N, ANVIL_TEST_PMAX widen it; ANVIL_TEST_DUMP
 * prints every row): 0.02 s since the unit costs' refit (plan.h), which
 * ran 514 rows where 0.03 s ran 527 before it; 592 run now, before and
 * after the paper march's refit (plan_paper.c, pprice30).
 * Every scene planned also holds the planner's shared estimates (plan.c
 * solves Zener's ODE and integrates the quasi-static anvil once a plan) to
 * the standalone ones, bit for bit: the layer row's work and price
 * (anvil_plan_paper_work, which integrates its own) and the bending
 * figure (anvil_plan_bending, which solves its own).
 * Last, the runs the plan prices as ended by a budget (test_budgets,
 * below): on thin plates of every material pair, they end on one. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plan.h"
#include "scene_run.h"
#include "solver.h"
#include "tap.h"

#define NSCENES (getenv("ANVIL_TEST_N") ? atoi(getenv("ANVIL_TEST_N")) : 1500)
#define PRICE_MAX (getenv("ANVIL_TEST_PMAX") ? atof(getenv("ANVIL_TEST_PMAX")) : 0.02)

/* A deterministic generator (a 64-bit LCG, Knuth's MMIX constants). */
static double uniform(unsigned long long *x)
{
	*x = *x * 6364136223846793005ull + 1442695040888963407ull;
	return (double)(*x >> 11) / 9007199254740992.0;
}

static const char *const materials[] = { "steel", "copper", "aluminium", "glass", "titanium",
					 "tungsten-carbide", "pmma" };
static const char *const levels[] = { "draft", "normal" };

static int sample_scene(unsigned long long *seed, struct anvil_scene *sc, char *what, size_t n)
{
	char h[32], v[32], m[32];
	struct anvil_err e;
	double u = uniform(seed);
	double hh = exp(log(0.05) + uniform(seed) * log(2e4));
	double v0 = exp(log(1e-3) + uniform(seed) * log(1e6));
	double m1 = exp(log(1e-4) + uniform(seed) * log(1e6));
	const char *mi = materials[(int)(uniform(seed) * 7)], *ml = materials[(int)(uniform(seed) * 7)];
	const char *lv = levels[(int)(uniform(seed) * 2)];
	if (u < 0.05)
		snprintf(h, sizeof h, "inf");
	else
		snprintf(h, sizeof h, "%.4gr0", hh);
	snprintf(v, sizeof v, "%.4g m/s", v0);
	snprintf(m, sizeof m, "%.4g kg", m1);
	snprintf(what, n, "%s on %s, h %s, V0 %s, m %s, %s", mi, ml, h, v, m, lv);
	anvil_scene_default(sc);
	const char *kv[] = { "layer.thickness", h, "impact.velocity", v, "impactor.mass", m,
			     "impactor.material", mi, "layer.material", ml, "solver.accuracy", lv,
			     "effects.contact", "paper", NULL };
	for (int i = 0; kv[i]; i += 2)
		if (anvil_scene_set(sc, kv[i], kv[i + 1], "test", 0, &e))
			return -1;
	return 0;
}

struct tally {
	const char *name;
	int n, within;
	double lo, hi;
	char worst[300];
};

static void tally_add(struct tally *t, double pred, double got, const char *what)
{
	double q = got > 0 ? pred / got : pred > 0 ? INFINITY : 1.0;
	t->n++;
	t->within += q >= 0.5 && q <= 2.0;
	if (t->n == 1 || q < t->lo || q > t->hi)
		snprintf(t->worst, sizeof t->worst, "%s: predicted %.3g, did %.3g", what, pred, got);
	t->lo = t->n == 1 ? q : fmin(t->lo, q);
	t->hi = t->n == 1 ? q : fmax(t->hi, q);
}

/* The windows the main impact tried: the first whose end is beyond the
 * contact's (its t_s in tau). */
static int windows_tried(const struct anvil_wave_job *j, double tau_s)
{
	int k = 0;
	while (k + 1 < j->attempts && !(anvil_wave_window(j, k) > tau_s))
		k++;
	return k + 1;
}

/* The plan's figures and price from its shared estimates against the
 * standalone functions: the same bits (1), else 0 with a diag. */
static int shared_estimates_hold(const struct anvil_plan *pl, const struct anvil_plan_row *r,
				 const char *what)
{
	double bend = anvil_plan_bending(&pl->pb.p), cost = r->cost;
	int wave = r->method == ANVIL_METHOD_LAYER || r->method == ANVIL_METHOD_HALFSPACE;
	if (wave && !r->status) {
		struct anvil_paper_work w;
		anvil_plan_paper_work(&pl->pb, r, NULL, &w);
		cost = w.seconds;
	}
	int ok_bend = memcmp(&bend, &pl->fig[ANVIL_FIG_BENDING], sizeof bend) == 0;
	int ok_cost = memcmp(&cost, &r->cost, sizeof cost) == 0;
	if (!ok_bend || !ok_cost)
		diag("%s: bending %.17g against %.17g, price %.17g against %.17g", what, bend,
		     pl->fig[ANVIL_FIG_BENDING], cost, r->cost);
	return ok_bend && ok_cost;
}

/* ---- the runs a budget ends (plan_paper.c, budget_tau, nodes_budget) ----
 * Thin plates (h 0.02-0.3 r0, the material pairs, V0 and m as above,
 * normal): the rows the plan prices as ended by a budget are run, and at
 * least BUDGET_HELD of them must end on one (the solver's error says
 * which), each in time: where the plan expects the contacts' budget, that
 * one, within 2x of the plan's time; where it expects the steps' (long
 * mode), either, within the first window (the contacts' budget often
 * comes first there).  Counts and the march's simulated time, not seconds.
 * Rows the plan prices as full runs are not run here: the chattering ones
 * take seconds.  (3000 scenes: 46 and 37 rows so priced, 44 and 37 ended
 * so, the contacts' at 0.90-1.07 times the plan's time; 1200: 21 of 23 and
 * 15 of 15; 400: 7 of 8 and 10 of 10.  Before the refit to the march whose
 * later contacts grow their step once they co-move, 48 of 57 and 48 of 67
 * at 3000: the rows that come to rest on the plate, plan_paper.c.) */
#define BUDGET_SCENES (getenv("ANVIL_TEST_NB") ? atoi(getenv("ANVIL_TEST_NB")) : 400)
#define BUDGET_HELD 0.85
static int thin_scene(unsigned long long *seed, struct anvil_scene *sc, char *what, size_t n)
{
	char h[32], v[32], m[32];
	struct anvil_err e;
	double hh = exp(log(0.02) + uniform(seed) * log(15.0));
	double v0 = exp(log(1e-3) + uniform(seed) * log(1e6));
	double m1 = exp(log(1e-4) + uniform(seed) * log(1e6));
	const char *mi = materials[(int)(uniform(seed) * 7)], *ml = materials[(int)(uniform(seed) * 7)];
	snprintf(h, sizeof h, "%.4gr0", hh);
	snprintf(v, sizeof v, "%.4g m/s", v0);
	snprintf(m, sizeof m, "%.4g kg", m1);
	snprintf(what, n, "%s on %s, h %s, V0 %s, m %s", mi, ml, h, v, m);
	anvil_scene_default(sc);
	const char *kv[] = { "layer.thickness", h, "impact.velocity", v, "impactor.mass", m,
			     "impactor.material", mi, "layer.material", ml, "effects.contact", "paper",
			     NULL };
	for (int i = 0; kv[i]; i += 2)
		if (anvil_scene_set(sc, kv[i], kv[i + 1], "test", 0, &e))
			return -1;
	return 0;
}

/* The budget the solver's error names (ANVIL_BUDGET_*, 0: none) and the
 * time it names, in r0/c2. */
static int budget_ended(const struct anvil_err *e, const struct anvil_params *p, double *tau)
{
	const char *c = strstr(e->msg, "touch again more than"), *n = strstr(e->msg, "needs more than");
	const char *t = c ? strstr(c, "by t = ") : n ? strstr(n, "near t = ") : NULL;
	double us = NAN;
	if (!t || sscanf(strchr(t, '=') + 1, "%lf", &us) != 1)
		return 0;
	*tau = us * 1e-6 * p->c2 / p->r0;
	return c ? ANVIL_BUDGET_CONTACTS : ANVIL_BUDGET_STEPS;
}

/* Whether a run the plan expected budget w to end ended so in time. */
static int budget_in_time(const struct anvil_paper_work *w, int got, double tau, double *q)
{
	if (w->budget == ANVIL_BUDGET_CONTACTS) {
		*q = w->budget_tau / tau;
		return got == ANVIL_BUDGET_CONTACTS && *q >= 0.5 && *q <= 2.0;
	}
	return got && tau <= w->budget_tau;
}

static void test_budgets(void)
{
	unsigned long long seed = 31;
	int planned = 0, predicted[3] = { 0 }, ended[3] = { 0 }, in_time = 0;
	double lo = INFINITY, hi = 0;
	for (int i = 0; i < BUDGET_SCENES; i++) {
		struct anvil_scene sc;
		struct anvil_plan pl;
		struct anvil_err e = { 0 };
		char what[200];
		if (thin_scene(&seed, &sc, what, sizeof what) || scene_plan(&sc, &pl, &e))
			continue;
		const struct anvil_plan_row *r = &pl.row[ANVIL_MODEL_LAYER];
		planned++;
		if (r->status || !r->run || r->method != ANVIL_METHOD_LAYER)
			continue;
		struct anvil_paper_work w;
		anvil_plan_paper_work(&pl.pb, r, NULL, &w);
		if (!w.budget)
			continue;
		predicted[w.budget]++;
		struct anvil_solver *s = anvil_solver_alloc();
		struct anvil_result res;
		anvil_solver_set_cache_dir(s, NULL, NULL);
		int st = anvil_solver_run(s, &pl, ANVIL_MODEL_LAYER, 0, &res, &e);
		anvil_solver_free(s);
		double tau = NAN, q = NAN;
		int got = st < 0 ? budget_ended(&e, &pl.pb.p, &tau) : 0;
		ended[w.budget] += got != 0;
		int timely = budget_in_time(&w, got, tau, &q);
		in_time += timely;
		if (w.budget == ANVIL_BUDGET_CONTACTS && got == ANVIL_BUDGET_CONTACTS) {
			lo = fmin(lo, q);
			hi = fmax(hi, q);
		}
		if (!timely || getenv("ANVIL_TEST_DUMP"))
			diag("budget %d expected by tau %.4g: %s: %s (%zu contacts)", w.budget,
			     w.budget_tau, what, st < 0 ? e.msg : "ran", res.ncontacts);
		anvil_result_free(&res);
	}
	int n = predicted[1] + predicted[2], got = ended[1] + ended[2];
	diag("budgets: of %d thin-plate scenes, %d and %d rows priced as ended by the contacts' and the steps' budget, %d and %d ended on one; the contacts' time / the plan's %.2f-%.2f",
	     planned, predicted[1], predicted[2], ended[1], ended[2], lo, hi);
	ok(planned >= BUDGET_SCENES / 2 && predicted[1] >= 3 && predicted[2] >= 3 &&
		   got >= BUDGET_HELD * n && in_time == got,
	   "the runs the plan prices as ended by a budget end on one (%d of %d, %d in time; %d scenes planned)",
	   got, n, in_time, planned);
}

int main(void)
{
	unsigned long long seed = 2024;
	struct tally win = { .name = "windows" }, resp = { .name = "responses" },
		     ev = { .name = "evaluations" }, thin[3] = { { .name = "thin: windows" },
								 { .name = "thin: responses" },
								 { .name = "thin: evaluations" } };
	int dump = getenv("ANVIL_TEST_DUMP") != NULL, ran = 0, corr = 0, planned = 0, same = 0;
	plan(6);
	for (int i = 0; i < NSCENES; i++) {
		struct anvil_scene sc;
		struct anvil_plan pl;
		struct anvil_err e;
		char what[200];
		if (sample_scene(&seed, &sc, what, sizeof what) || scene_plan(&sc, &pl, &e))
			continue;
		const struct anvil_plan_row *r = &pl.row[ANVIL_MODEL_LAYER];
		planned++;
		same += shared_estimates_hold(&pl, r, what);
		if (r->status || !r->run ||
		    (r->method != ANVIL_METHOD_LAYER && r->method != ANVIL_METHOD_HALFSPACE) ||
		    !(r->cost <= PRICE_MAX))
			continue;
		struct anvil_paper_work w;
		anvil_plan_paper_work(&pl.pb, r, NULL, &w);
		struct anvil_solver *s = anvil_solver_alloc();
		struct anvil_result res;
		struct anvil_solver_stats ss;
		anvil_solver_set_cache_dir(s, NULL, NULL);
		int st = anvil_solver_run(s, &pl, ANVIL_MODEL_LAYER, 0, &res, &e);
		anvil_solver_stats(s, &ss);
		anvil_solver_free(s);
		if (st < 0) { /* refused by a check only a computed result allows */
			if (dump)
				diag("%s: %s", what, e.msg);
			anvil_result_free(&res);
			continue;
		}
		ran++;
		double tau_s = res.ts.val * pl.pb.p.c2 / pl.pb.p.r0;
		int plate = pl.pb.p.h < pl.pb.p.r0;
		if (!(res.rest_bound > 0) && r->method == ANVIL_METHOD_LAYER)
			tally_add(plate ? &thin[0] : &win, w.windows, windows_tried(&r->job, tau_s),
				  what);
		tally_add(plate ? &thin[1] : &resp, w.responses, (double)ss.layer_computed, what);
		if (ss.layer_evals > 0 || w.evals > 0) {
			corr += !plate;
			tally_add(plate ? &thin[2] : &ev, w.evals, (double)ss.layer_evals, what);
		}
		if (dump)
			diag("%s: windows %d (t_s %.4g, rest %d), responses %.2f/%lu, evals %.4g/%zu, price %.3g s",
			     what, w.windows, tau_s, res.rest_bound > 0, w.responses,
			     ss.layer_computed, w.evals, ss.layer_evals, w.seconds);
		anvil_result_free(&res);
	}
	const struct tally *t[6] = { &win, &resp, &ev, &thin[0], &thin[1], &thin[2] };
	for (int i = 0; i < 6; i++)
		diag("%s: %d rows, predicted/actual %.2f-%.2f, %d within 2x; worst: %s", t[i]->name,
		     t[i]->n, t[i]->lo, t[i]->hi, t[i]->within, t[i]->worst);
	ok(resp.n >= 300 && corr >= 100,
	   "%d paper rows run (%d on h >= r0, %d of them with a layer correction)", ran, resp.n,
	   corr);
	ok(planned >= 1000 && same == planned,
	   "the plan's shared estimates (bending, the row's price) are the standalone ones' bits on %d of %d scenes",
	   same, planned);
	for (int i = 0; i < 3; i++)
		ok(t[i]->within == t[i]->n, "the plan's %s within 2x of the solver's on %d of %d rows",
		   t[i]->name, t[i]->within, t[i]->n);
	test_budgets();
	return done_testing();
}
