/* test_work.c: the planner predicts the work of a layer response (issue 11).
 *
 * For a seeded random sample of scenes spanning thickness, velocity, mass,
 * the built-in material pairs and the accuracy levels, the plan's layer
 * job (window of attempt 0, bandwidth) is handed to green.c exactly as the
 * solver does (the response with its twin), and the planner's predicted
 * kernel evaluations (anvil_plan_corr_evals, what the cost model prices)
 * are compared with the count green.c reports: deterministic counts, not
 * seconds (scripts/bench compares seconds).  Each must be within a factor
 * of 2.  Of the 300 scenes drawn (h/r0 0.1-30, V0 0.1-100 m/s, m 1 g-1 kg),
 * those whose response the planner itself predicts to cost more than
 * EVALS_MAX evaluations are left out to keep make check short (about 10 s;
 * ANVIL_TEST_N and ANVIL_TEST_EMAX widen the run, ANVIL_TEST_DUMP prints
 * every pair); the others are run with effects.waves = layer, so every
 * scene with a reflection inside its window counts, and with the paper's
 * contact, whose r0-patch response (and twin) is what the planner prices.
 * A second sample does the same for the physical contact's row (its four
 * corrections, anvil_plan_phys_evals) against the solver's own count, and
 * a third for thick layers at low bands, a fourth for bench section
 * 13's long contacts, with each correction's time samples
 * (anvil_plan_corr_samples) too, and a fifth for thin plates, whose bands
 * are lifted off the real axis. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cache.h"
#include "green.h"
#include "plan.h"
#include "scene_run.h"
#include "tap.h"

#define NSCENES (getenv("ANVIL_TEST_N") ? atoi(getenv("ANVIL_TEST_N")) : 300)
#define EVALS_MAX (getenv("ANVIL_TEST_EMAX") ? atof(getenv("ANVIL_TEST_EMAX")) : 4.0e4)

/* A deterministic generator (a 64-bit LCG, Knuth's MMIX constants): the
 * sample is the same on every machine. */
static double uniform(unsigned long long *x)
{
	*x = *x * 6364136223846793005ull + 1442695040888963407ull;
	return (double)(*x >> 11) / 9007199254740992.0;
}

static const char *const materials[] = { "steel", "copper", "aluminium", "glass", "titanium",
					 "tungsten-carbide",
					 "pmma" };
static const char *const levels[] = { "draft", "normal" };

static int sample_scene(unsigned long long *seed, struct anvil_scene *sc, char *what, size_t n)
{
	char h[32], v[32], m[32];
	struct anvil_err e;
	double hh = exp(log(0.1) + uniform(seed) * log(300.0));
	double v0 = exp(log(0.1) + uniform(seed) * log(1000.0));
	double m1 = exp(log(1e-3) + uniform(seed) * log(1000.0));
	const char *mi = materials[(int)(uniform(seed) * 7)], *ml = materials[(int)(uniform(seed) * 7)];
	const char *lv = levels[(int)(uniform(seed) * 2)];
	snprintf(h, sizeof h, "%.4gr0", hh);
	snprintf(v, sizeof v, "%.4g m/s", v0);
	snprintf(m, sizeof m, "%.4g kg", m1);
	snprintf(what, n, "%s on %s, h %s, V0 %s, m %s, %s", mi, ml, h, v, m, lv);
	anvil_scene_default(sc);
	const char *kv[] = { "layer.thickness", h, "impact.velocity", v, "impactor.mass", m,
			     "impactor.material", mi, "layer.material", ml, "solver.accuracy", lv,
			     "effects.waves", "layer", "effects.contact", "paper", NULL };
	for (int i = 0; kv[i]; i += 2)
		if (anvil_scene_set(sc, kv[i], kv[i + 1], "test", 0, &e))
			return -1;
	return 0;
}

/* The kernel evaluations the layer row of pl makes on a fresh solver with
 * the cache in memory only; 0 (e says why) when it fails. */
static size_t row_evals(const struct anvil_plan *pl, struct anvil_err *e)
{
	struct anvil_solver *s = anvil_solver_alloc();
	struct anvil_result res;
	struct anvil_solver_stats ss;
	anvil_solver_set_cache_dir(s, NULL, NULL);
	int st = anvil_solver_run(s, pl, ANVIL_MODEL_LAYER, 0, &res, e);
	anvil_solver_stats(s, &ss);
	anvil_result_free(&res);
	anvil_solver_free(s);
	return st < 0 ? 0 : ss.layer_evals;
}

/* The physical contact's row: the planner's four corrections
 * (anvil_plan_phys_evals) against the evaluations the solver makes for the
 * row (its main run and error-estimate runs), each scene on a fresh
 * solver with the cache in memory only.  Of PHYS_N scenes drawn (h/r0
 * 0.3-9, V0 0.3-30 m/s, m 3 g-0.3 kg, the material pairs, draft and
 * normal), those predicted above PHYS_EVALS_MAX are left out (time). */
#define PHYS_N 40
#define PHYS_EVALS_MAX 4.0e5
static void physical_sample(void)
{
	unsigned long long seed = 11;
	int tried = 0, within = 0;
	double lo = 1, hi = 1;
	char worst[300] = "";
	for (int i = 0; i < PHYS_N; i++) {
		struct anvil_scene sc;
		struct anvil_plan pl;
		struct anvil_err e;
		char what[200], h[32], v[32], m[32];
		double hh = exp(log(0.3) + uniform(&seed) * log(30.0));
		double v0 = exp(log(0.3) + uniform(&seed) * log(100.0));
		double m1 = exp(log(3e-3) + uniform(&seed) * log(100.0));
		const char *mi = materials[(int)(uniform(&seed) * 7)];
		const char *ml = materials[(int)(uniform(&seed) * 7)];
		const char *lv = levels[(int)(uniform(&seed) * 2)];
		snprintf(h, sizeof h, "%.4gr0", hh);
		snprintf(v, sizeof v, "%.4g m/s", v0);
		snprintf(m, sizeof m, "%.4g kg", m1);
		snprintf(what, sizeof what, "%s on %s, h %s, V0 %s, m %s, %s", mi, ml, h, v, m, lv);
		anvil_scene_default(&sc);
		const char *kv[] = { "layer.thickness", h, "impact.velocity", v, "impactor.mass", m,
				     "impactor.material", mi, "layer.material", ml, "solver.accuracy", lv,
				     "effects.waves", "layer", "effects.contact", "physical", NULL };
		int bad = 0;
		for (int k = 0; kv[k]; k += 2)
			bad |= anvil_scene_set(&sc, kv[k], kv[k + 1], "test", 0, &e);
		if (bad || scene_plan(&sc, &pl, &e))
			continue;
		const struct anvil_plan_row *r = &pl.row[ANVIL_MODEL_LAYER];
		enum anvil_cache_where where;
		double pred = anvil_plan_phys_evals(&r->job, pl.pb.p.nu, pl.pb.accuracy, NULL, &where);
		if (r->status || r->method != ANVIL_METHOD_LAYER ||
		    !anvil_wave_needs_corr(&pl.pb.p, &r->job, anvil_wave_window(&r->job, 0)) ||
		    !(pred <= PHYS_EVALS_MAX))
			continue;
		size_t evals = row_evals(&pl, &e);
		if (!evals) {
			diag("%s: %s", what, e.msg);
			continue;
		}
		double q = pred / (double)evals;
		tried++;
		within += q >= 0.5 && q <= 2.0;
		if (q < lo || q > hi)
			snprintf(worst, sizeof worst, "%s: predicted %.0f, did %zu", what, pred,
				 evals);
		lo = fmin(lo, q);
		hi = fmax(hi, q);
	}
	diag("physical contact: %d rows computed; predicted/actual evaluations %.2f-%.2f; worst: %s",
	     tried, lo, hi, worst);
	ok(tried >= 15 && within == tried,
	   "the physical row's corrections priced within 2x of the solver's evaluations on %d of %d",
	   within, tried);
}

/* Thick layers below the level's band floor (plan.c: it falls as 4/hh
 * beyond h = 4 r0): there the splitting towards the Lamb poles grows
 * less with the window than at the bands refine() was fitted on
 * (plan_work.c), and these rows were priced 1.6-2.4 times their
 * evaluations before that was known.  Each row's four corrections
 * (anvil_plan_phys_evals) against the solver's count, within 2x. */
static void thick_sample(void)
{
	static const char *const scenes[][3] = {
		{ "10r0", "1kg", "0.01m/s" },   { "20r0", "1kg", "0.001m/s" },
		{ "20r0", "10kg", "0.1m/s" },   { "20r0", "100kg", "0.01m/s" },
		{ "100r0", "1kg", "0.01m/s" },  { "100r0", "10kg", "0.01m/s" },
	};
	int tried = 0, within = 0, low = 0;
	double lo = 1, hi = 1;
	for (size_t i = 0; i < sizeof scenes / sizeof *scenes; i++) {
		struct anvil_scene sc;
		struct anvil_plan pl;
		struct anvil_err e;
		const char *kv[] = { "layer.thickness", scenes[i][0], "impactor.mass", scenes[i][1],
				     "impact.velocity", scenes[i][2], "effects.waves", "layer",
				     "effects.contact", "physical", NULL };
		int bad = 0;
		anvil_scene_default(&sc);
		for (int k = 0; kv[k]; k += 2)
			bad |= anvil_scene_set(&sc, kv[k], kv[k + 1], "test", 0, &e);
		if (bad || scene_plan(&sc, &pl, &e)) {
			diag("scene %zu: %s", i, e.msg);
			continue;
		}
		const struct anvil_plan_row *r = &pl.row[ANVIL_MODEL_LAYER];
		enum anvil_cache_where where;
		double pred = anvil_plan_phys_evals(&r->job, pl.pb.p.nu, pl.pb.accuracy, NULL, &where);
		size_t evals = row_evals(&pl, &e);
		if (!evals) {
			diag("h %s, %s, %s: %s", scenes[i][0], scenes[i][1], scenes[i][2], e.msg);
			continue;
		}
		double q = pred / (double)evals;
		tried++;
		low += r->job.omega < 2.0;
		within += q >= 0.5 && q <= 2.0;
		lo = fmin(lo, q);
		hi = fmax(hi, q);
	}
	diag("thick layers: %d rows (%d below the band 2); predicted/actual evaluations %.2f-%.2f",
	     tried, low, lo, hi);
	ok(tried == 6 && low == 6 && within == tried,
	   "thick layers' corrections at low bands priced within 2x on %d of %d", within, tried);
}

/* The four corrections of a scene's physical row (physical, normal; kv
 * the settings, NULL-terminated) made as the solver makes them (one set:
 * solver_phys.c phys_prefetch): *q their predicted evaluations
 * (anvil_plan_phys_evals) over the count, and of the *ncorr corrections
 * *samples_ok those whose time samples equal anvil_plan_corr_samples.
 * 0, or -1 (said why) when there is no correction. */
static int corr_set(const char *const *kv, const char *what, double *q, int *samples_ok,
		    int *ncorr)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err e;
	int bad = 0;
	anvil_scene_default(&sc);
	bad |= anvil_scene_set(&sc, "effects.contact", "physical", "test", 0, &e);
	for (int k = 0; kv[k]; k += 2)
		bad |= anvil_scene_set(&sc, kv[k], kv[k + 1], "test", 0, &e);
	if (bad || scene_plan(&sc, &pl, &e)) {
		diag("%s: %s", what, e.msg);
		return -1;
	}
	const struct anvil_plan_row *r = &pl.row[ANVIL_MODEL_LAYER];
	const struct anvil_wave_job *j = &r->job;
	if (r->status || !anvil_wave_needs_corr(&pl.pb.p, j, anvil_wave_window(j, 0))) {
		diag("%s: no correction (%s)", what, r->refusal);
		return -1;
	}
	enum anvil_cache_where where;
	double pred = anvil_plan_phys_evals(j, pl.pb.p.nu, pl.pb.accuracy, NULL, &where), got = 0;
	int tau_idx = anvil_wave_tau_idx(j, anvil_wave_window(j, 0));
	struct { int oi; double patch; } load[4] = {
		{ j->omega_idx, 0.0 }, { j->omega_idx, j->patch },
		{ j->omega_idx, anvil_plan_patch_below(j->patch) },
		{ j->omega_idx - ANVIL_CACHE_STEPS, 0.0 } };
	struct anvil_green_settings gs;
	struct anvil_green_load set[4];
	struct anvil_green *g[4];
	anvil_green_settings(pl.pb.accuracy, &gs);
	gs.filter = 1;
	gs.lift_patch = j->patch; /* as the solver's (solver_phys.c) */
	for (int k = 0; k < 4; k++)
		set[k] = (struct anvil_green_load){ load[k].patch, anvil_cache_grid(load[k].oi) };
	if (anvil_green_alloc_set(j->hh, pl.pb.p.nu, anvil_cache_grid(tau_idx), &gs, set, 4, NULL,
				  NULL, g, &e)) {
		diag("%s: %s", what, e.msg);
		return -1;
	}
	for (int k = 0; k < 4; k++) {
		struct anvil_green_samples smp;
		anvil_green_export(g[k], &smp);
		++*ncorr;
		*samples_ok += (double)smp.n == anvil_plan_corr_samples(j->hh, set[k].omega_max,
								       anvil_cache_grid(tau_idx));
		got += (double)anvil_green_evals(g[k]);
		anvil_green_free(g[k]);
	}
	*q = pred / got;
	return got > 0 ? 0 : -1;
}

/* Bench section 13's long contacts (physical, normal; the 100 kg scene is
 * refused when planned and left out): the four corrections made as the
 * solver makes them, their evaluations against anvil_plan_phys_evals
 * within 2x, and each one's time samples (what a long window costs beyond
 * its evaluations) equal to anvil_plan_corr_samples: the pieces the
 * planner's seconds are made of (plan_work.c). */
static void long_sample(void)
{
	static const char *const scenes[][9] = {
		{ "layer.thickness", "0.25r0", "impactor.mass", "100g", "impact.velocity", "10m/s" },
		{ "layer.thickness", "0.5r0", "impactor.mass", "1kg", "impact.velocity", "10m/s" },
		{ "layer.thickness", "1r0", "impactor.mass", "1kg", "impact.velocity", "10m/s" },
		{ "layer.thickness", "1mm", "impactor.mass", "500g", "impact.velocity", "1m/s",
		  "impactor.material", "steel" },
		{ "layer.thickness", "0.1r0", "impactor.mass", "1g", "impact.velocity", "10m/s" },
		{ "layer.thickness", "0.05r0", "impactor.mass", "0.1g", "impact.velocity", "1m/s" },
		{ "layer.thickness", "0.25r0", "impactor.mass", "1kg", "impact.velocity", "1m/s" },
		{ "layer.thickness", "2r0", "impactor.mass", "0.1g", "impact.velocity", "500m/s" },
		{ "layer.thickness", "10r0", "impactor.mass", "10kg", "impact.velocity", "0.1m/s" },
	};
	int tried = 0, within = 0, samples_ok = 0, ncorr = 0;
	double lo = 1, hi = 1;
	for (size_t i = 0; i < sizeof scenes / sizeof *scenes; i++) {
		char what[32];
		double q;
		snprintf(what, sizeof what, "scene %zu", i);
		if (corr_set(scenes[i], what, &q, &samples_ok, &ncorr))
			continue;
		tried++;
		within += q >= 0.5 && q <= 2.0;
		lo = fmin(lo, q);
		hi = fmax(hi, q);
	}
	diag("long contacts: %d rows; predicted/actual evaluations %.2f-%.2f", tried, lo, hi);
	ok(tried >= 8 && within == tried,
	   "long contacts' corrections priced within 2x of their evaluations on %d of %d", within,
	   tried);
	ok(ncorr >= 32 && samples_ok == ncorr,
	   "their time samples as predicted on %d of %d corrections", samples_ok, ncorr);
}

/* Thin plates (h = 0.02-0.05 r0), whose bands are integrated on the lifted
 * contour (kernel.h anvil_kband_lift) and priced without the splitting
 * towards the poles (plan_work.c LIFT_SPLIT): the four corrections within
 * 2x of their evaluations (1.1 M at h = 0.02 r0, 1 g at 1 m/s). */
static void thin_sample(void)
{
	static const char *const scenes[][7] = {
		{ "layer.thickness", "0.02r0", "impactor.mass", "1g", "impact.velocity", "1m/s" },
		{ "layer.thickness", "0.05r0", "impactor.mass", "1kg", "impact.velocity", "1m/s" },
		{ "layer.thickness", "0.05r0", "impactor.mass", "10g", "impact.velocity", "0.1m/s" },
	};
	int tried = 0, within = 0, samples_ok = 0, ncorr = 0;
	double lo = 1, hi = 1;
	for (size_t i = 0; i < sizeof scenes / sizeof *scenes; i++) {
		double q;
		if (corr_set(scenes[i], scenes[i][1], &q, &samples_ok, &ncorr))
			continue;
		tried++;
		within += q >= 0.5 && q <= 2.0;
		lo = fmin(lo, q);
		hi = fmax(hi, q);
	}
	diag("thin plates: %d rows; predicted/actual evaluations %.2f-%.2f", tried, lo, hi);
	ok(tried == 3 && within == tried,
	   "thin plates' lifted corrections priced within 2x of their evaluations on %d of %d",
	   within, tried);
}

int main(void)
{
	plan(7);
	unsigned long long seed = 7; /* not the fit's (plan.c: refine) */
	int tried = 0, within = 0, skipped = 0;
	double worst_lo = 1, worst_hi = 1, hmin = INFINITY, hmax = 0;
	char what[200], worst[300] = "";
	for (int i = 0; i < NSCENES; i++) {
		struct anvil_scene sc;
		struct anvil_plan pl;
		struct anvil_err e;
		if (sample_scene(&seed, &sc, what, sizeof what) || scene_plan(&sc, &pl, &e))
			continue;
		const struct anvil_plan_row *r = &pl.row[ANVIL_MODEL_LAYER];
		const struct anvil_wave_job *j = &r->job;
		double tau_end = anvil_wave_window(j, 0);
		if (r->status || r->method != ANVIL_METHOD_LAYER ||
		    !anvil_wave_needs_corr(&pl.pb.p, j, tau_end))
			continue;
		double om = anvil_cache_grid(j->omega_idx);
		double tq = anvil_cache_grid(anvil_cache_grid_up(tau_end));
		double pred = anvil_plan_corr_evals(j->hh, pl.pb.p.nu, om, tq, pl.pb.accuracy);
		if (!(pred <= EVALS_MAX)) {
			skipped++;
			continue;
		}
		struct anvil_green_settings gs;
		struct anvil_green *tw = NULL;
		anvil_green_settings(pl.pb.accuracy, &gs);
		gs.omega_max = om;
		struct anvil_green *g = anvil_green_alloc_twin(ANVIL_GREEN_LAYER_CORRECTION, j->hh,
							       pl.pb.p.nu, tq, &gs, NULL, NULL, &tw, &e);
		if (!g) {
			diag("%s: %s", what, e.msg);
			continue;
		}
		double got = (double)anvil_green_evals(g), q = pred / got;
		if (getenv("ANVIL_TEST_DUMP"))
			diag("ROW %g %d %g %g %g %g %g", j->hh, (int)pl.pb.accuracy, pl.pb.p.nu, om, tq,
			     pred, got);
		tried++;
		within += q >= 0.5 && q <= 2.0;
		hmin = fmin(hmin, j->hh);
		hmax = fmax(hmax, j->hh);
		if (q < worst_lo || q > worst_hi) {
			snprintf(worst, sizeof worst, "%s: predicted %.0f, did %.0f", what, pred, got);
			if (getenv("ANVIL_TEST_VERBOSE"))
				diag("%s", worst);
		}
		worst_lo = fmin(worst_lo, q);
		worst_hi = fmax(worst_hi, q);
		anvil_green_free(g);
		anvil_green_free(tw);
	}
	diag("%d scenes computed (h/r0 %.3g-%.3g), %d left out as too costly for make check",
	     tried, hmin, hmax, skipped);
	diag("predicted/actual kernel evaluations from %.2f to %.2f; worst: %s", worst_lo, worst_hi,
	     worst);
	ok(tried >= 80, "at least 80 layer responses in the sample (%d)", tried);
	ok(within == tried, "the planner's kernel evaluations within 2x of green.c's on %d of %d",
	   within, tried);
	physical_sample();
	thick_sample();
	long_sample();
	thin_sample();
	return done_testing();
}
