/* test_plan: the planner (plan.h) and the response cache (cache.h).
 *  - [effects] and [output] keys: parse, errors, round trip, which rows run;
 *  - the estimates: xi(nu) by an independent route, the radiated energy
 *    against the half-space model and Hunter's form, the quasi-static anvil
 *    against Hertz and the solver;
 *  - decisions and reasons on scenes spanning the regimes (thin, thick,
 *    half-space, slow, fast, soft, coarse); each automatic decision agrees
 *    with the full layer model within the scene's target and, where it
 *    drops the layer, computes no layer response at all and is at least
 *    ten times cheaper;
 *  - warnings: yield, super-seismic, Zener out of range, refusal, a forced
 *    half-space that is not exact;
 *  - the cache: memory hits, a changed velocity reusing the response, the
 *    disk round trip to the bit, corrupt and truncated files ignored with a
 *    warning, another version or format ignored quietly, atomic writes,
 *    the environment (ANVIL_NO_CACHE, XDG_CACHE_HOME). */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>

#include "cache.h"
#include "green.h"
#include "halfspace.h"
#include "hertz_field.h"
#include "plan.h"
#include "radiation.h"
#include "solver.h"
#include "scene_run.h"
#include "tap.h"

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double rel(double a, double b, double floor)
{
	return fabs(a - b) / fmax(fabs(b), floor);
}

/* The worst relative difference of P_max, t_s and R_f (the targets' own
 * measure: R_f relative to max(R_f, 0.1)). */
static double deviation(const struct anvil_result *a, const struct anvil_result *b)
{
	return fmax(rel(a->Pmax.val, b->Pmax.val, 0), fmax(rel(a->ts.val, b->ts.val, 0), rel(a->Rf.val, b->Rf.val, 0.1)));
}

/* A scene from the default and KEY, VALUE pairs (NULL-terminated). */
static struct anvil_scene scene(const char *const kv[])
{
	struct anvil_scene sc;
	struct anvil_err e;
	anvil_scene_default(&sc);
	sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
	for (int i = 0; kv && kv[i]; i += 2)
		if (anvil_scene_set(&sc, kv[i], kv[i + 1], "test", 0, &e))
			diag("%s = %s: %s", kv[i], kv[i + 1], e.msg);
	return sc;
}

static struct anvil_solver *memory_solver(void)
{
	struct anvil_solver *s = anvil_solver_alloc();
	anvil_solver_set_cache_dir(s, NULL, NULL);
	return s;
}

/* ---- scene keys ---- */

static void test_keys(void)
{
	struct anvil_scene sc, back;
	struct anvil_err e;
	anvil_scene_default(&sc);
	sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
	ok(sc.effects.waves == ANVIL_WAVES_AUTO && sc.effects.plate && sc.effects.quasistatic &&
		   sc.effects.field == ANVIL_FIELDMODE_OFF && sc.output.table &&
		   !sc.output.histories[0] && !sc.output.charts[0] && !sc.output.field[0],
	   "defaults: waves auto, plate and quasistatic on, field off; table on, files off");
	int st = anvil_scene_parse(&sc,
				   "[effects]\nwaves = HalfSpace\nplate = off\nquasistatic = OFF\n"
				   "field = map\n[output]\ntable = off\nhistories = out/h.tsv\n"
				   "charts = charts dir\nfield = f.tsv\n",
				   "t.scene", &e);
	ok(st == ANVIL_OK && sc.effects.waves == ANVIL_WAVES_HALFSPACE && !sc.effects.plate &&
		   !sc.effects.quasistatic && sc.effects.field == ANVIL_FIELDMODE_MAP &&
		   !sc.output.table && strcmp(sc.output.histories, "out/h.tsv") == 0 &&
		   strcmp(sc.output.charts, "charts dir") == 0 && strcmp(sc.output.field, "f.tsv") == 0,
	   "[effects] and [output] parse (case-insensitive names, paths with spaces)");
	ok(anvil_scene_models(&sc) == (1u << ANVIL_MODEL_LAYER | 1u << ANVIL_MODEL_HALFSPACE),
	   "plate = off and quasistatic = off take zener and hertz out of the run");
	sc.effects.waves = ANVIL_WAVES_NONE;
	ok(anvil_scene_models(&sc) == 0, "waves = none takes layer and halfspace out");

	/* the writer: every new key back to the bit, "off" files and a file called off */
	anvil_scene_set(&sc, "output.field", "./off", NULL, 0, NULL);
	anvil_scene_set(&sc, "output.charts", "off", NULL, 0, NULL);
	char *text = NULL;
	size_t size = 0;
	FILE *f = open_memstream(&text, &size);
	anvil_scene_write(&sc, f);
	fclose(f);
	anvil_scene_default(&back);
	back.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
	st = anvil_scene_parse(&back, text, "written", &e);
	ok(st == ANVIL_OK && memcmp(&back.effects, &sc.effects, sizeof sc.effects) == 0 &&
		   back.output.table == sc.output.table &&
		   strcmp(back.output.histories, sc.output.histories) == 0 &&
		   strcmp(back.output.charts, sc.output.charts) == 0 &&
		   strcmp(back.output.field, sc.output.field) == 0,
	   "the writer's [effects] and [output] read back the same");
	ok(strstr(text, "[effects]\nwaves = none\nplate = off\nquasistatic = off\nfield = map\n") &&
		   strstr(text, "charts = off\nfield = ./off\n"),
	   "written as documented");
	free(text);

	static const struct {
		const char *key, *value, *want;
	} bad[] = {
		{ "effects.waves", "layr", "expected auto, layer, halfspace or none, got 'layr'; did you mean 'layer'?" },
		{ "effects.plate", "yes", "expected off or on, got 'yes'" },
		{ "effects.field", "grid", "expected off, points or map" },
		{ "output.histories", "", "expected a file name or 'off'" },
		{ "output.charts", "a\tb", "must be one line of text" },
		{ "effects.wave", "auto", "did you mean 'effects.waves'?" },
		{ "output.tabel", "on", "did you mean 'output.table'?" },
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		anvil_scene_default(&sc);
		sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
		st = anvil_scene_set(&sc, bad[i].key, bad[i].value, NULL, 0, &e);
		if (!ok(st == ANVIL_EPARSE && strstr(e.msg, bad[i].want), "%s = '%s': %s", bad[i].key,
			bad[i].value, bad[i].want))
			diag("  got: %s", e.msg);
	}
}

/* ---- estimates ---- */

/* xi(nu) by another route: on the real axis with s = eps + i, where the
 * Rayleigh pole is a peak of width eps, extrapolated linearly to eps = 0. */
static double xi_real_axis(double nu, double eps)
{
	double kap2 = (1 - 2 * nu) / (2 * (1 - nu)), sum = 0, h = eps / 40.0;
	double complex s = eps + I, b = s * s;
	for (double q = 0.5 * h; q < 3.0; q += h) {
		double complex a1 = csqrt(q * q + kap2 * b), a2 = csqrt(q * q + b), g = 2 * q * q + b;
		sum += cimag(a1 * b / (g * g - 4 * q * q * a1 * a2) * q) * h;
	}
	return -sum / (2 * M_PI);
}

static void test_estimates(void)
{
	for (double nu = 0.0; nu < 0.45; nu += 0.2) {
		double x1 = xi_real_axis(nu, 0.004), x2 = xi_real_axis(nu, 0.002);
		is_rel(anvil_radiation_xi(nu), 2 * x2 - x1, 2e-3, "xi(%.1f) = %.5f: the contour integral "
		       "matches the real axis extrapolated to s = i", nu, anvil_radiation_xi(nu));
	}
	ok(isnan(anvil_radiation_xi(0.5)) && isnan(anvil_radiation_xi(-1)), "xi: NaN outside (-1, 0.5)");

	/* Hunter's form: a steel ball on steel, f = C (V0/c0)^(3/5) */
	struct anvil_params p;
	double C[2];
	for (int i = 0; i < 2; i++) {
		struct anvil_scene sc = scene((const char *[]){ "impactor.material", "steel",
			"impactor.radius", "5 mm", "impactor.mass", "4.0998 g", "layer.thickness", "inf",
			"impact.velocity", i ? "10 m/s" : "0.1 m/s", NULL });
		anvil_params_from_scene(&p, &sc, NULL);
		C[i] = anvil_plan_radiated(&p) / pow(p.V0 / sqrt(p.E / p.rho), 0.6);
	}
	ok(fabs(C[0] / C[1] - 1) < 1e-9 && fabs(C[0] / 1.04 - 1) < 0.12,
	   "radiated energy of a steel ball on steel: %.3f (V0/c0)^(3/5), Hunter (Johnson 1985) 1.04",
	   C[0]);

	/* against the half-space model: the point-source limit at low speed,
	 * an overestimate (finite patch, longer pulse) at 10 m/s */
	struct anvil_solver *s = memory_solver();
	const char *speeds[] = { "0.01 m/s", "10 m/s" };
	double ratio[2];
	for (int i = 0; i < 2; i++) {
		struct anvil_scene sc = scene((const char *[]){ "layer.thickness", "inf",
			"impact.velocity", speeds[i], "effects.waves", "layer", "solver.accuracy",
			"fine", NULL });
		struct anvil_result r;
		anvil_params_from_scene(&p, &sc, NULL);
		scene_run(s, &sc, ANVIL_MODEL_HALFSPACE, 0, &r, NULL);
		ratio[i] = r.Ea.val / (0.5 * p.m1 * p.V0 * p.V0) / anvil_plan_radiated(&p);
		anvil_result_free(&r);
	}
	ok(fabs(ratio[0] - 1) < 0.1 && ratio[1] > 0.5 && ratio[1] <= 1.0,
	   "radiated fraction vs the half-space model: %.3f of the estimate at 1 cm/s, %.3f at 10 m/s",
	   ratio[0], ratio[1]);

	/* the quasi-static anvil: Hertz without compliance, the solver with it */
	double ts, pm;
	/* E beyond what scene input accepts (1e6 GPa): set on the material */
	struct anvil_scene sc = scene((const char *[]){ "layer.E", "1e6 GPa", NULL });
	sc.layer.mat.E = 1e39;
	anvil_params_from_scene(&p, &sc, NULL);
	anvil_plan_static(&p, &ts, &pm);
	is_rel(ts / p.T, 3.21807, 1e-5, "static anvil of infinite stiffness: t_s = 3.21807 T (Hertz)");
	sc = scene((const char *[]){ "layer.thickness", "inf", "impact.velocity", "0.01 m/s", NULL });
	anvil_params_from_scene(&p, &sc, NULL);
	anvil_plan_static(&p, &ts, &pm);
	struct anvil_result r;
	int st = scene_run(s, &sc, ANVIL_MODEL_HALFSPACE, 0, &r, NULL);
	ok(st == ANVIL_OK && strstr(r.note, "quasi-static") && rel(r.ts.val, ts, 0) < 1e-4 &&
		   rel(r.Pmax.val, pm, 0) < 1e-4,
	   "its energy integral matches the solver's quasi-static run (t_s %.2e, P_max %.2e)",
	   rel(r.ts.val, ts, 0), rel(r.Pmax.val, pm, 0));
	anvil_result_free(&r);
	anvil_solver_free(s);
}

/* ---- decisions on the regimes ---- */

struct regime {
	const char *name;
	const char *kv[12];
	enum anvil_model row;
	enum anvil_method method;
	enum anvil_plan_why why;
	int drops_layer; /* the full model computes a layer response, auto does not */
};

static const struct regime regimes[] = {
	{ "thin (h = r0, the paper)", { NULL }, ANVIL_MODEL_LAYER, ANVIL_METHOD_LAYER,
	  ANVIL_WHY_NEEDS_LAYER, 0 },
	{ "thick (h = 40 r0)", { "layer.thickness", "40 r0", NULL }, ANVIL_MODEL_LAYER,
	  ANVIL_METHOD_HALFSPACE, ANVIL_WHY_LATE_REFLECT, 1 },
	{ "half-space", { "layer.thickness", "inf", NULL }, ANVIL_MODEL_LAYER,
	  ANVIL_METHOD_HALFSPACE, ANVIL_WHY_IS_HALFSPACE, 0 },
	{ "half-space row, 10 m/s", { "layer.thickness", "inf", NULL }, ANVIL_MODEL_HALFSPACE,
	  ANVIL_METHOD_HALFSPACE, ANVIL_WHY_NEEDS_WAVES, 0 },
	{ "slow (1 cm/s, h = 50 r0)", { "layer.thickness", "50 r0", "impact.velocity", "0.01 m/s",
	  NULL }, ANVIL_MODEL_LAYER, ANVIL_METHOD_STATIC, ANVIL_WHY_SMALL_WAVES, 1 },
	{ "slow, half-space row", { "layer.thickness", "inf", "impact.velocity", "0.01 m/s",
	  NULL }, ANVIL_MODEL_HALFSPACE, ANVIL_METHOD_STATIC, ANVIL_WHY_SMALL_WAVES, 0 },
	{ "fast (100 m/s, h = 30 r0)", { "layer.thickness", "30 r0", "impact.velocity", "100 m/s",
	  "solver.accuracy", "draft", NULL }, ANVIL_MODEL_LAYER, ANVIL_METHOD_HALFSPACE,
	  ANVIL_WHY_LATE_REFLECT, 0 },
	{ "fast and thin (100 m/s, h = 2 r0)", { "layer.thickness", "2 r0", "impact.velocity",
	  "100 m/s", "solver.accuracy", "draft", NULL }, ANVIL_MODEL_LAYER, ANVIL_METHOD_LAYER,
	  ANVIL_WHY_NEEDS_LAYER, 0 },
	{ "soft (PMMA on PMMA, h = 30 r0, 10 cm/s, draft)", { "impactor.material", "pmma",
	  "layer.material", "pmma", "layer.thickness", "30 r0", "impact.velocity", "0.1 m/s",
	  "solver.accuracy", "draft", NULL }, ANVIL_MODEL_LAYER, ANVIL_METHOD_HALFSPACE,
	  ANVIL_WHY_SMALL_PLATE, 1 },
	{ "coarse (h = 20 r0, 1 m/s, draft)", { "layer.thickness", "20 r0", "impact.velocity",
	  "1 m/s", "solver.accuracy", "draft", NULL }, ANVIL_MODEL_LAYER, ANVIL_METHOD_HALFSPACE,
	  ANVIL_WHY_SMALL_PLATE, 1 },
	{ "coarse made normal (h = 20 r0, 1 m/s)", { "layer.thickness", "20 r0",
	  "impact.velocity", "1 m/s", NULL }, ANVIL_MODEL_LAYER, ANVIL_METHOD_LAYER,
	  ANVIL_WHY_NEEDS_LAYER, 0 },
};

/* auto against the full model (waves = layer) for one regime: the same
 * numbers within the target; where the layer is dropped, no response
 * computed and a much shorter run. */
static void regime_run(const struct regime *g, const struct anvil_scene *sc,
		       const struct anvil_plan_row *row)
{
	struct anvil_scene full = *sc;
	struct anvil_solver *sa = memory_solver(), *sf = memory_solver();
	struct anvil_result ra, rf;
	struct anvil_solver_stats qa, qf;
	struct anvil_err ea = { 0 }, ef = { 0 };
	full.effects.waves = ANVIL_WAVES_LAYER;
	double t0 = now();
	int st = scene_run(sa, sc, g->row, 0, &ra, &ea);
	double t1 = now();
	int st2 = scene_run(sf, &full, g->row, 0, &rf, &ef);
	double t2 = now();
	double d = deviation(&ra, &rf), tgt = anvil_accuracy_target(sc->accuracy);
	anvil_solver_stats(sa, &qa);
	anvil_solver_stats(sf, &qf);
	if (!ok(st == ANVIL_OK && st2 == ANVIL_OK && d <= tgt,
		"  agrees with the full model: %.2e <= target %.0e (estimated %.2e)", d, tgt,
		row->model_err))
		diag("  %s / %s", ea.msg, ef.msg);
	ok(row->exact ? d < 1e-6 : ra.Pmax.err >= row->model_err * ra.Pmax.val,
	   "  %s", row->exact ? "exact: the same to 1e-6" : "error estimates include the model error");
	if (g->drops_layer) {
		ok(qa.layer_computed == 0 && qa.layer_evals == 0 && qf.layer_computed > 0 &&
			   qf.layer_evals >= 10000,
		   "  no layer response computed (full model: %lu, %zu kernel evaluations)",
		   qf.layer_computed, qf.layer_evals);
		/* speed is the benchmark's (scripts/bench); a timed assertion
		 * failed on a loaded machine (2x against 3x): the work saved is
		 * what is asserted above, the time only reported */
		diag("  wall time %.3g s against %.3g s: %.0fx", t1 - t0, t2 - t1, (t2 - t1) / (t1 - t0));
		ok(row->cost_full >= 10.0 * row->cost, "  the plan prices it %.0fx cheaper",
		   row->cost_full / row->cost);
	}
	if (row->method != ANVIL_METHOD_LAYER && row->method != ANVIL_METHOD_HALFSPACE)
		ok(strstr(ra.note, "quasi-static") != NULL, "  the note says so: %s", ra.note);
	else if (g->row == ANVIL_MODEL_LAYER && row->method == ANVIL_METHOD_HALFSPACE)
		ok(strstr(ra.note, "2h/c1") != NULL || strstr(ra.note, "half-space") != NULL,
		   "  the note says so: %s", ra.note);
	anvil_result_free(&ra);
	anvil_result_free(&rf);
	anvil_solver_free(sa);
	anvil_solver_free(sf);
}

static void test_regimes(void)
{
	for (size_t i = 0; i < sizeof regimes / sizeof regimes[0]; i++) {
		const struct regime *g = &regimes[i];
		struct anvil_scene sc = scene(g->kv);
		struct anvil_plan pl;
		struct anvil_err e;
		int st = scene_plan(&sc, &pl, &e);
		const struct anvil_plan_row *row = &pl.row[g->row];
		if (!ok(st == ANVIL_OK && row->method == g->method && row->why == g->why,
			"%s: %s row by %s (%s)", g->name, anvil_model_name(g->row),
			anvil_method_name(row->method), anvil_plan_why_text(row->why)))
			diag("  want %s, %s", anvil_method_name(g->method), anvil_plan_why_text(g->why));
		ok(row->nfig >= 1 && row->cost > 0 && row->cost <= row->cost_full * 1.0001,
		   "  with %d figures and a cost (%.2g s <= full %.2g s)", row->nfig, row->cost,
		   row->cost_full);
		regime_run(g, &sc, row);
	}
}

/* ---- what the scene asks for ---- */

static void test_effects(void)
{
	struct anvil_plan pl;
	struct anvil_scene sc = scene((const char *[]){ "effects.plate", "off", "effects.quasistatic",
		"off", "solver.models", "hertz, zener, layer", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(!pl.row[0].run && pl.row[0].off == ANVIL_WHY_EFFECT_OFF && !pl.row[1].run &&
		   pl.row[2].run && !pl.row[3].run && pl.row[3].off == ANVIL_WHY_NOT_ASKED,
	   "rows off by [effects] and by solver.models, each with its reason");
	ok(fabs(pl.cost - pl.row[2].cost) < 1e-12, "the total prices only the rows run");
	sc = scene((const char *[]){ "layer.thickness", "40 r0", "effects.waves", "layer", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(pl.row[2].method == ANVIL_METHOD_LAYER && pl.row[2].why == ANVIL_WHY_FORCED,
	   "waves = layer forces the layer model on a thick block");
	sc = scene((const char *[]){ "layer.thickness", "40 r0", "solver.scheme", "paper",
		"solver.dt", "0.5 us", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(pl.row[2].method == ANVIL_METHOD_LAYER && pl.row[2].why == ANVIL_WHY_FORCED,
	   "the paper's scheme is never replaced (it is there to reproduce the paper)");
	sc = scene((const char *[]){ "effects.waves", "none", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(!pl.row[2].run && !pl.row[3].run && pl.row[2].off == ANVIL_WHY_EFFECT_OFF,
	   "waves = none: no wave rows");

	/* asked for all the same (the TUI, anvil table): its own model */
	struct anvil_solver *s = memory_solver();
	struct anvil_result r;
	sc = scene((const char *[]){ "layer.thickness", "inf", "effects.waves", "none", NULL });
	ok(scene_run(s, &sc, ANVIL_MODEL_HALFSPACE, 0, &r, NULL) == ANVIL_OK &&
		   strstr(r.note, "exact"), "a row switched off runs as its own model when asked");
	anvil_result_free(&r);
	anvil_solver_free(s);
}

static int has_warning(const struct anvil_plan *pl, enum anvil_plan_warn k)
{
	for (int i = 0; i < pl->nwarn; i++)
		if (pl->warn[i].kind == k)
			return 1;
	return 0;
}

static void test_warnings(void)
{
	struct anvil_plan pl;
	struct anvil_scene sc = scene(NULL);
	scene_plan(&sc, &pl, NULL);
	/* the one verdict (verdict.h): the layer, and the impactor under the
	 * same contact judged on its own nu and Y (the old 1.1 Y of the softer
	 * body is gone: it judged the copper and said it was the layer's) */
	const struct anvil_verdict *vd = &pl.verdict;
	double vm_cu = NAN, z_cu = NAN;
	ok(vd->fate == ANVIL_HERTZ_YIELDS && strcmp(vd->material, "steel") == 0 && vd->known &&
		   vd->stress > vd->limit,
	   "the paper's steel layer yields: von Mises %.0f MPa against Y = %.0f MPa",
	   vd->stress / 1e6, vd->limit / 1e6);
	ok(vd->imp.fate == ANVIL_HERTZ_YIELDS && strcmp(vd->imp.material, "copper") == 0 &&
		   vd->imp.stress > 100 * vd->imp.limit,
	   "  and, on its own line, the copper impactor: %.0f MPa against Y = %.1f MPa",
	   vd->imp.stress / 1e6, vd->imp.limit / 1e6);
	int st_cu = anvil_hertz_vm_peak(vd->a, vd->p0, pl.pb.impactor.nu, &vm_cu, &z_cu);
	ok(!st_cu && fabs(vd->imp.stress - vm_cu) <= 1e-12 * vm_cu && pl.pb.impactor.nu != pl.pb.layer.nu &&
		   fabs(vd->imp.stress - vd->stress) > 1e-3 * vd->stress,
	   "  the impactor's peak is Hertz's with copper's nu = %.2f (%.4g p0), not the layer's",
	   pl.pb.impactor.nu, vm_cu / vd->p0);
	ok(anvil_verdict_fails(vd), "  the plan's verdict fails");
	is_rel(pl.fig[ANVIL_FIG_P_MEAN], 2.0 / 3.0 * 3.0 * pl.fig[ANVIL_FIG_P_MAX] /
	       (2 * M_PI * pow(pl.fig[ANVIL_FIG_A_HERTZ], 2)), 1e-12, "  p_m = 2/3 p0, p0 = 3P/(2 pi a^2)");
	ok(!has_warning(&pl, ANVIL_WARN_SUPERSEISMIC) && !has_warning(&pl, ANVIL_WARN_PLATE_RANGE) &&
		   !has_warning(&pl, ANVIL_WARN_REFUSE),
	   "  and nothing else at h = r0, 10 m/s");
	sc = scene((const char *[]){ "impactor.yield", "100 GPa", "layer.yield", "100 GPa", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(pl.verdict.fate == ANVIL_HERTZ_ELASTIC && pl.verdict.known &&
		   pl.verdict.imp.fate == ANVIL_HERTZ_ELASTIC && pl.verdict.imp.known &&
		   !anvil_verdict_fails(&pl.verdict),
	   "strong bodies: both elastic, both judged");
	sc = scene((const char *[]){ "impactor.yield", "0 GPa", "layer.yield", "0 GPa", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(!pl.verdict.known && !pl.verdict.imp.known && !anvil_verdict_fails(&pl.verdict),
	   "no yield stress known: neither body judged");
	sc = scene((const char *[]){ "impactor.material", "glass", "layer.material", "glass", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(pl.verdict.brittle && pl.verdict.imp.brittle && pl.verdict.imp.known &&
		   fabs(pl.verdict.imp.stress - anvil_hertz_tension(pl.verdict.p0, pl.pb.impactor.nu)) <=
			   1e-12 * pl.verdict.imp.stress,
	   "glass on glass: both judged by the edge tension (1-2nu) p0/3 (%s)",
	   pl.verdict.imp.fate == ANVIL_HERTZ_CRACKS ? "cracks" : "elastic");
	sc = scene((const char *[]){ "impact.velocity", "3000 m/s", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(has_warning(&pl, ANVIL_WARN_SUPERSEISMIC) && pl.fig[ANVIL_FIG_ALPHA_A] > 0.1,
	   "3 km/s: alpha_A = %.3f, super-seismic", pl.fig[ANVIL_FIG_ALPHA_A]);
	sc = scene((const char *[]){ "layer.thickness", "2 r0", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(has_warning(&pl, ANVIL_WARN_PLATE_RANGE), "Zener at h = 2 r0: out of its range");
	sc = scene((const char *[]){ "layer.thickness", "2 r0", "effects.plate", "off", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(!has_warning(&pl, ANVIL_WARN_PLATE_RANGE), "  not when the plate is off");
	/* the paper's explicit scheme: no growing step, no long mode */
	sc = scene((const char *[]){ "layer.thickness", "0.05 r0", "solver.scheme", "paper", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(has_warning(&pl, ANVIL_WARN_REFUSE), "h = 0.05 r0, the paper's scheme: the layer solver will refuse");
	/* the warning is of the rows that run: the paper's contact refuses
	 * this scene, the physical one (the default) answers it */
	const char *wc[] = { "layer.thickness", "0.1 r0", "impactor.mass", "100 kg", "impact.velocity",
			     "100 m/s", "impactor.material", "tungsten-carbide", "effects.contact",
			     "physical", NULL };
	sc = scene(wc);
	scene_plan(&sc, &pl, NULL);
	ok(!has_warning(&pl, ANVIL_WARN_REFUSE) && pl.row[ANVIL_MODEL_LAYER].status == ANVIL_OK,
	   "carbide, 100 kg at 100 m/s on 0.1 r0, physical contact: runs, no refusal warning");
	wc[9] = "paper";
	sc = scene(wc);
	scene_plan(&sc, &pl, NULL);
	ok(has_warning(&pl, ANVIL_WARN_REFUSE), "  the paper's contact: refused, said so");
	sc = scene((const char *[]){ "effects.waves", "halfspace", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(has_warning(&pl, ANVIL_WARN_NOT_EXACT) && !pl.row[2].exact,
	   "waves = halfspace on a thin layer: not exact, said so");
	sc = scene((const char *[]){ "effects.field", "points", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(has_warning(&pl, ANVIL_WARN_FIELD), "a field asked for: pointed to anvil field");
}

/* ---- the cache ---- */

static char tmpdir[64];

static void warn_count(void *ctx, const char *msg)
{
	int *n = ctx;
	++*n;
	diag("  (warning: %s)", msg);
}

static int same_results(const struct anvil_result *a, const struct anvil_result *b)
{
	return memcmp(&a->ts.val, &b->ts.val, sizeof a->ts.val) == 0 &&
	       memcmp(&a->Pmax.val, &b->Pmax.val, sizeof a->Pmax.val) == 0 &&
	       memcmp(&a->Rf.val, &b->Rf.val, sizeof a->Rf.val) == 0 &&
	       memcmp(&a->Pmax.err, &b->Pmax.err, sizeof a->Pmax.err) == 0;
}

static void test_memory(void)
{
	struct anvil_solver *s = memory_solver();
	struct anvil_solver_stats st;
	struct anvil_result a, b, c;
	struct anvil_scene sc = scene(NULL);
	scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, &a, NULL);
	anvil_solver_stats(s, &st);
	unsigned long made = st.layer_computed;
	double t0 = now();
	scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, &b, NULL);
	double t1 = now();
	anvil_solver_stats(s, &st);
	/* one computation makes the response and its twin (one spectrum) */
	ok(made == 1 && st.layer_computed == 1 && st.cache.mem_hits >= 2 && same_results(&a, &b),
	   "the same scene again: from memory, the same bits (%.3g s against %.3g s)", t1 - t0,
	   a.seconds);
	/* 9.5 m/s lands on the same window and bandwidth grid points (10.5 m/s
	 * does not: lookups are exact, so that no result depends on the cache) */
	sc = scene((const char *[]){ "impact.velocity", "9.5 m/s", NULL });
	scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, &c, NULL);
	anvil_solver_stats(s, &st);
	ok(st.layer_computed == 1 && c.ts.val > a.ts.val,
	   "9.5 m/s: the response is reused (%.3g s); t_s %.3f us", c.seconds, c.ts.val * 1e6);
	ok(anvil_cache_held(anvil_solver_cache(s)) == 0, "no response held between runs");
	anvil_result_free(&a);
	anvil_result_free(&b);
	anvil_result_free(&c);
	anvil_solver_free(s);
	ok(anvil_cache_grid_up(anvil_cache_grid(7)) == 7 &&
		   anvil_cache_grid_up(nextafter(anvil_cache_grid(7), 1e9)) == 8 &&
		   anvil_cache_grid(-4) == 0.5, "the grid: exact at its points");
}

/* The same scene gives the same bits cold and warm, whatever the cache
 * held: here a run at 10.5 m/s that cached a longer window first. */
static void test_bits(void)
{
	struct anvil_solver *cold = memory_solver(), *warm = memory_solver();
	struct anvil_result a, b, x;
	struct anvil_scene sc = scene(NULL);
	struct anvil_scene fast = scene((const char *[]){ "impact.velocity", "10.5 m/s", NULL });
	scene_run(warm, &sc, ANVIL_MODEL_LAYER, 0, &x, NULL); /* caches the 10 m/s window */
	anvil_result_free(&x);
	scene_run(cold, &fast, ANVIL_MODEL_LAYER, 0, &a, NULL);
	scene_run(warm, &fast, ANVIL_MODEL_LAYER, 0, &b, NULL);
	ok(same_results(&a, &b) && memcmp(&a.Ea.val, &b.Ea.val, sizeof a.Ea.val) == 0 &&
		   memcmp(&a.tmax.err, &b.tmax.err, sizeof a.tmax.err) == 0,
	   "cold and warm (after a longer window was cached): the same bits (P_max %.17g)", a.Pmax.val);
	anvil_result_free(&a);
	anvil_result_free(&b);
	anvil_solver_free(cold);
	anvil_solver_free(warm);
}

/* A held response survives more than ANVIL_CACHE_SLOTS insertions; once
 * every slot is held, an insertion fails instead of evicting one. */
static void test_hold(void)
{
	struct anvil_cache *c = anvil_cache_alloc();
	struct anvil_err e;
	const struct anvil_halfspace *hs = anvil_cache_halfspace(c, 0.3, 1e-6, &e);
	struct anvil_green_settings gs;
	anvil_green_settings(ANVIL_ACC_DRAFT, &gs);
	gs.omega_max = 2.0;
	int added = 0, evicted_ok = 1;
	for (int i = 0; i < ANVIL_CACHE_SLOTS + 6; i++) {
		struct anvil_cache_key key = { 3.0, 0.3, ANVIL_ACC_DRAFT, 4, i, 0, ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
		struct anvil_green *g = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, 3.0, 0.3,
							  4.0, &gs, NULL, NULL, &e);
		const struct anvil_green *k = anvil_cache_add(c, &key, g);
		added += k != NULL;
		anvil_cache_release(c, k);
		double v;
		evicted_ok &= anvil_halfspace_ramp(hs, 1.0, &v, NULL) == ANVIL_OK && v > 0;
	}
	struct anvil_cache_key first = { 3.0, 0.3, ANVIL_ACC_DRAFT, 4, 0, 0, ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
	ok(added == ANVIL_CACHE_SLOTS + 6 && evicted_ok && anvil_cache_held(c) == 1 &&
		   !anvil_cache_probe(c, &first) &&
		   anvil_cache_halfspace(c, 0.3, 1e-6, &e) == hs,
	   "a held half-space outlives %d insertions; unheld ones are evicted",
	   ANVIL_CACHE_SLOTS + 6);
	anvil_cache_release(c, hs);
	anvil_cache_release(c, hs);
	/* hold every slot: the next insertion is refused, nothing evicted */
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++) {
		struct anvil_cache_key key = { 2.0, 0.3, ANVIL_ACC_DRAFT, 4, i, 0, ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
		anvil_cache_add(c, &key, anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, 2.0, 0.3,
							   4.0, &gs, NULL, NULL, &e));
	}
	struct anvil_cache_key more = { 2.0, 0.3, ANVIL_ACC_DRAFT, 4, 99, 0, ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
	ok(anvil_cache_held(c) == ANVIL_CACHE_SLOTS &&
		   !anvil_cache_add(c, &more, anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, 2.0,
								0.3, 4.0, &gs, NULL, NULL, &e)),
	   "every slot held: an insertion is refused (NULL), none evicted");
	anvil_cache_free(c);
}

/* Statuses: a refusal decided by the planner comes back before any work,
 * a failure (< 0); a missed target is a warning (> 0) with values. */
static void test_status(void)
{
	struct anvil_solver *s = memory_solver();
	struct anvil_scene sc = scene((const char *[]){ "layer.thickness", "0.05 r0", "solver.scheme",
						       "paper", NULL });
	struct anvil_plan pl;
	struct anvil_result r;
	struct anvil_err e;
	int st = scene_plan(&sc, &pl, &e);
	const struct anvil_plan_row *row = &pl.row[ANVIL_MODEL_LAYER];
	ok(st == ANVIL_OK && row->status == ANVIL_ETOL && row->refusal[0],
	   "a very thin layer, the paper's scheme: the plan refuses the layer row (%s)", row->refusal);
	anvil_solver_stats(s, &(struct anvil_solver_stats){ 0 });
	st = anvil_solver_run(s, &pl, ANVIL_MODEL_LAYER, 0, &r, &e);
	struct anvil_solver_stats ss;
	anvil_solver_stats(s, &ss);
	ok(st == ANVIL_ETOL && r.status == st && strcmp(r.why, row->refusal) == 0 &&
		   ss.layer_computed == 0 && ss.cache.misses == 0,
	   "the solver returns the planned refusal without work");
	anvil_result_free(&r);
	/* Values the scene input refuses (its ranges); set on the materials
	 * directly, so that params' own guard is what is tested. */
	struct anvil_scene dense = scene((const char *[]){ NULL }), stiff = dense;
	dense.layer.mat.rho = 1e308;
	stiff.layer.mat.E = 1.7e308;
	st = scene_plan(&dense, &pl, &e);
	ok(st == ANVIL_EINVAL && strstr(e.msg, "layer.rho"), "rho = 1e308: %s", e.msg);
	st = scene_plan(&stiff, &pl, &e);
	ok(st == ANVIL_EINVAL && strstr(e.msg, "layer.E"), "E = 1.7e308: %s", e.msg);
	ok(ANVIL_WTOL > 0 && strcmp(anvil_strerror(ANVIL_WTOL), "unknown status") != 0 &&
		   ANVIL_ETOL < 0,
	   "warnings are positive, failures negative: %s / %s", anvil_strerror(ANVIL_WTOL),
	   anvil_strerror(ANVIL_ETOL));
	anvil_solver_free(s);
}

/* The files of the cache directory, counted; temporaries too. */
static int count_files(const char *dir, const char *part)
{
	char cmd[300];
	snprintf(cmd, sizeof cmd, "ls -A '%s' 2>/dev/null | grep -c -- '%s'", dir, part);
	FILE *p = popen(cmd, "r");
	int n = -1;
	if (p && fscanf(p, "%d", &n) != 1)
		n = -1;
	if (p)
		pclose(p);
	return n;
}

static int first_file(const char *dir, char *path, size_t n)
{
	char cmd[300];
	snprintf(cmd, sizeof cmd, "ls '%s'/corr-*.bin | head -n 1", dir);
	FILE *p = popen(cmd, "r");
	int got = p && fgets(path, (int)n, p);
	if (p)
		pclose(p);
	path[strcspn(path, "\n")] = 0;
	return got;
}

/* Change the bytes at off of file path. */
static void poke(const char *path, long off, const void *bytes, size_t n)
{
	FILE *f = fopen(path, "r+b");
	if (!f)
		return;
	fseek(f, off, SEEK_SET);
	fwrite(bytes, 1, n, f);
	fclose(f);
}

/* A run with a fresh solver on dir: its result, counters and warnings. */
static int fresh_run(const char *dir, struct anvil_result *r, struct anvil_solver_stats *st,
		     int *warnings)
{
	struct anvil_solver *s = anvil_solver_alloc();
	struct anvil_scene sc = scene(NULL);
	*warnings = 0;
	anvil_solver_set_cache_dir(s, dir, NULL);
	anvil_solver_set_warn(s, warn_count, warnings);
	int rc = scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, r, NULL);
	anvil_solver_stats(s, st);
	anvil_solver_free(s);
	return rc;
}

static void test_disk(void)
{
	char dir[128], path[400];
	struct anvil_result a, b;
	struct anvil_solver_stats st;
	int w;
	snprintf(dir, sizeof dir, "%s/cache/anvil", tmpdir);
	fresh_run(dir, &a, &st, &w);
	ok(st.layer_computed == 1 && st.cache.disk_writes == 2 && count_files(dir, "^corr-") == 2 &&
		   count_files(dir, "XXXX\\|\\.bin\\.") == 0,
	   "a cold run writes its two responses, no temporary file left");
	double t0 = now();
	fresh_run(dir, &b, &st, &w);
	double t1 = now();
	ok(st.layer_computed == 0 && st.cache.disk_hits == 2 && same_results(&a, &b) && w == 0,
	   "a new solver reads them back: the same bits, nothing computed (%.3g s against %.3g s)",
	   t1 - t0, a.seconds);
	anvil_result_free(&b);

	/* the format directly: write, read, compare the samples */
	struct anvil_green_settings gs;
	struct anvil_green_samples x, y;
	struct anvil_err e;
	struct anvil_cache_key key = { 3.0, 0.3, ANVIL_ACC_DRAFT, 4, 3, 0, ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
	anvil_green_settings(ANVIL_ACC_DRAFT, &gs);
	gs.omega_max = anvil_cache_grid(key.omega_idx);
	struct anvil_green *g = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, 3.0, 0.3, 20.0, &gs,
						  NULL, NULL, &e);
	anvil_cache_path(dir, &key, path, sizeof path);
	int rc = anvil_cache_write(path, &key, g, &e);
	struct anvil_green *h = anvil_cache_read(path, &key, &e);
	anvil_green_export(g, &x);
	if (h)
		anvil_green_export(h, &y);
	ok(rc == ANVIL_OK && h && x.n == y.n && x.dtau == y.dtau && x.tau_end == y.tau_end &&
		   memcmp(x.ramp, y.ramp, x.n * sizeof *x.ramp) == 0 && anvil_green_evals(h) == 0,
	   "write and read: %zu samples to the bit", x.n);
	double v1, v2;
	anvil_green_ramp(g, 7.77, &v1);
	if (h)
		anvil_green_ramp(h, 7.77, &v2);
	ok(h && memcmp(&v1, &v2, sizeof v1) == 0, "  and the rebuilt interpolant gives the same bits");
	anvil_green_free(h);
	struct anvil_cache_key other = key;
	other.hh = 3.5;
	ok(!anvil_cache_read(path, &other, &e) && e.status == ANVIL_EPARSE,
	   "another key in the file: ignored quietly");
	ok(!anvil_cache_read("/nonexistent/x.bin", &key, &e) && e.status == ANVIL_ENOTFOUND,
	   "no file: ANVIL_ENOTFOUND");

	/* atomic: a reader holding the old file keeps reading the old bytes */
	FILE *old = fopen(path, "rb");
	struct stat s1, s2;
	stat(path, &s1);
	anvil_cache_write(path, &key, g, &e);
	stat(path, &s2);
	char head[8] = "";
	ok(old && s1.st_ino != s2.st_ino && fread(head, 1, 8, old) == 8 && memcmp(head, "ANVILRSP", 8) == 0,
	   "a rewrite puts a new file in place by rename; an open reader is undisturbed");
	if (old)
		fclose(old);
	ok(anvil_cache_write("/nonexistent/dir/x.bin", &key, g, &e) == ANVIL_EIO &&
		   strstr(e.msg, "cannot create"), "an unwritable place: ANVIL_EIO (%s)", e.msg);
	anvil_green_free(g);
	unlink(path);

	/* damage: a flipped sample, a short file, another version, another format */
	first_file(dir, path, sizeof path);
	unsigned char junk = 0x5a;
	poke(path, 112 + 8 * 100 + 3, &junk, 1);
	fresh_run(dir, &b, &st, &w);
	ok(w == 1 && st.cache.disk_corrupt == 1 && st.layer_computed == 1 && same_results(&a, &b),
	   "corrupt: ignored with a warning, recomputed, the same result");
	anvil_result_free(&b);
	fresh_run(dir, &b, &st, &w);
	ok(w == 0 && st.layer_computed == 0, "  and the file was replaced by a good one");
	anvil_result_free(&b);
	if (truncate(path, 112 + 800) == 0) {
		fresh_run(dir, &b, &st, &w);
		ok(w == 1 && st.cache.disk_corrupt == 1 && same_results(&a, &b),
		   "a truncated file: ignored with a warning");
		anvil_result_free(&b);
	}
	poke(path, 16, "9.9.9", 6);
	fresh_run(dir, &b, &st, &w);
	ok(w == 0 && st.cache.disk_stale + st.cache.disk_corrupt >= 1 && st.layer_computed == 1 &&
		   same_results(&a, &b),
	   "another anvil version (checksum broken by the patch too): ignored, recomputed");
	anvil_result_free(&b);
	unsigned int fmt = 99;
	poke(path, 8, &fmt, sizeof fmt);
	fresh_run(dir, &b, &st, &w);
	ok(w == 0 && st.cache.disk_stale == 1 && same_results(&a, &b),
	   "another format version: ignored quietly, recomputed");
	anvil_result_free(&b);
	anvil_result_free(&a);
}

/* A version mismatch with an intact checksum: rewrite the header the way
 * another anvil would have. */
static void test_version(void)
{
	char dir[128], path[400];
	struct anvil_result a, b;
	struct anvil_solver_stats st;
	int w;
	snprintf(dir, sizeof dir, "%s/v/anvil", tmpdir);
	fresh_run(dir, &a, &st, &w);
	first_file(dir, path, sizeof path);
	/* re-sign: recompute FNV-1a (on 64-bit words, cache.c) over the
	 * patched header, its checksum zero, and the samples */
	FILE *f = fopen(path, "r+b");
	struct anvil_cache_header hd;
	long n = 0;
	if (f && fread(&hd, sizeof hd, 1, f) == 1) {
		memcpy(hd.version, "0.0.1\0\0\0", 8);
		hd.checksum = 0;
		unsigned long long hsh = 14695981039346656037ull, w;
		const unsigned char *b = (const unsigned char *)&hd;
		for (size_t i = 0; i < sizeof hd; i += 8) {
			memcpy(&w, b + i, 8);
			hsh = (hsh ^ w) * 1099511628211ull;
		}
		while (fread(&w, 8, 1, f) == 1) {
			hsh = (hsh ^ w) * 1099511628211ull;
			n++;
		}
		hd.checksum = hsh;
		fseek(f, 0, SEEK_SET);
		fwrite(&hd, sizeof hd, 1, f);
	}
	if (f)
		fclose(f);
	fresh_run(dir, &b, &st, &w);
	ok(n > 0 && w == 0 && st.cache.disk_stale == 1 && st.cache.disk_corrupt == 0 &&
		   st.layer_computed == 1 && same_results(&a, &b),
	   "a file from anvil 0.0.1 with a valid checksum: ignored quietly (stale), recomputed");
	anvil_result_free(&a);
	anvil_result_free(&b);
}

static void test_environment(void)
{
	char buf[512];
	setenv("HOME", "/home/u", 1);
	setenv("XDG_CACHE_HOME", "/x/cache", 1);
	unsetenv("ANVIL_NO_CACHE");
	ok(strcmp(anvil_cache_default_dir(buf, sizeof buf), "/x/cache/anvil") == 0,
	   "XDG_CACHE_HOME/anvil");
	setenv("XDG_CACHE_HOME", "relative", 1);
	ok(strcmp(anvil_cache_default_dir(buf, sizeof buf), "/home/u/.cache/anvil") == 0,
	   "a relative XDG_CACHE_HOME is ignored (XDG spec): ~/.cache/anvil");
	setenv("ANVIL_NO_CACHE", "1", 1);
	ok(anvil_cache_default_dir(buf, sizeof buf)[0] == 0, "ANVIL_NO_CACHE=1: no disk cache");
	setenv("ANVIL_NO_CACHE", "0", 1);
	ok(anvil_cache_default_dir(buf, sizeof buf)[0] == '/', "ANVIL_NO_CACHE=0: on");
	setenv("ANVIL_NO_CACHE", "1", 1);
	struct anvil_solver *s = anvil_solver_alloc();
	ok(anvil_cache_dir(anvil_solver_cache(s)) == NULL, "a solver made under ANVIL_NO_CACHE=1 keeps to memory");
	anvil_solver_free(s);
}

/* ---- the physical contact's corrections in the cache, sharing (plan.h) ---- */

static struct anvil_scene phys_scene(const char *v)
{
	struct anvil_scene sc = scene((const char *[]){ "impact.velocity", v, "solver.accuracy",
							"draft", NULL });
	sc.effects.contact = ANVIL_CONTACT_PHYSICAL;
	return sc;
}

static unsigned long computed(const struct anvil_solver *s)
{
	struct anvil_solver_stats st;
	anvil_solver_stats(s, &st);
	return st.layer_computed;
}

static void test_physical_cache(void)
{
	struct anvil_solver *s = memory_solver(), *d1 = anvil_solver_alloc(),
			    *d2 = anvil_solver_alloc();
	struct anvil_result a, b, c, x, y;
	struct anvil_scene sc = phys_scene("10 m/s"), near = phys_scene("9.5 m/s");
	char dir[128];
	snprintf(dir, sizeof dir, "%s/phys", tmpdir);
	scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, &a, NULL);
	unsigned long made = computed(s);
	scene_run(s, &sc, ANVIL_MODEL_LAYER, 0, &b, NULL);
	/* point load and patch at the bandwidth, the patch below, the point
	 * load at half the bandwidth */
	ok(a.contact == ANVIL_CONTACT_PHYSICAL && made == 4 && computed(s) == 4 &&
		   same_results(&a, &b),
	   "physical contact: 4 corrections made once, the same scene again from memory, the same bits");
	scene_run(s, &near, ANVIL_MODEL_LAYER, 0, &c, NULL);
	ok(computed(s) == 4 && c.ts.val > a.ts.val,
	   "9.5 m/s: the same window, bandwidth and patch grid points: corrections reused");
	anvil_solver_set_cache_dir(d1, dir, NULL);
	anvil_solver_set_cache_dir(d2, dir, NULL);
	scene_run(d1, &sc, ANVIL_MODEL_LAYER, 0, &x, NULL);
	scene_run(d2, &sc, ANVIL_MODEL_LAYER, 0, &y, NULL);
	ok(computed(d2) == 0 && same_results(&x, &y) && same_results(&a, &x) &&
		   count_files(dir, "^phys-draft-") == 4,
	   "on disk (4 phys- files): a fresh solver reads them, the same bits as cold");
	anvil_result_free(&a);
	anvil_result_free(&b);
	anvil_result_free(&c);
	anvil_result_free(&x);
	anvil_result_free(&y);
	anvil_solver_free(s);
	anvil_solver_free(d1);
	anvil_solver_free(d2);
	int grid = 1;
	for (double v = 0.013; v < 1.2; v *= 1.37) {
		double p = anvil_plan_patch(v), q = anvil_plan_patch_below(p);
		grid &= v < 1 ? p >= v && q < v && p == anvil_plan_patch(p) && q == anvil_plan_patch(q)
			      : p == 1.0;
	}
	ok(grid && anvil_plan_patch(0) == 0 && anvil_plan_patch(0.5) == 0.5,
	   "the patch grid: the half-octave point at or above a_max/r0, the one below under it");
}

/* Plans of three velocities on one envelope, run on one solver: the
 * responses counted, each row against its scene alone. */
static void share_sweep(enum anvil_contact contact, unsigned long want)
{
	const char *v[3] = { "0.5 m/s", "2 m/s", "8 m/s" };
	struct anvil_plan pl[3], alone;
	struct anvil_plan_share sh = { 0 };
	struct anvil_solver *s = memory_solver(), *cold = memory_solver();
	struct anvil_result r[3], a, w;
	const char *name = contact == ANVIL_CONTACT_PHYSICAL ? "physical" : "paper";
	int within = 1;
	for (int i = 0; i < 3; i++) {
		struct anvil_scene sc = phys_scene(v[i]);
		sc.effects.contact = contact;
		scene_plan(&sc, &pl[i], NULL);
		anvil_plan_share_add(&sh, &pl[i]);
	}
	for (int i = 0; i < 3; i++) {
		struct anvil_scene sc = phys_scene(v[i]);
		sc.effects.contact = contact;
		scene_plan(&sc, &alone, NULL);
		anvil_plan_share_apply(&pl[i], &sh);
		anvil_solver_run(s, &pl[i], ANVIL_MODEL_LAYER, 0, &r[i], NULL);
		anvil_solver_run(cold, &alone, ANVIL_MODEL_LAYER, 0, &a, NULL);
		/* both within their error of the truth: within the sum of each other */
		within &= fabs(r[i].ts.val - a.ts.val) <= r[i].ts.err + a.ts.err &&
			  fabs(r[i].Pmax.val - a.Pmax.val) <= r[i].Pmax.err + a.Pmax.err &&
			  fabs(r[i].Rf.val - a.Rf.val) <= r[i].Rf.err + a.Rf.err;
		diag("  %s %s: t_s %.9g (shared) %.9g (alone) +- %.2g us", name, v[i],
		     r[i].ts.val * 1e6, a.ts.val * 1e6, r[i].ts.err * 1e6);
		anvil_result_free(&a);
	}
	ok(computed(s) == want && pl[0].row[ANVIL_MODEL_LAYER].job.omega_idx ==
					  pl[2].row[ANVIL_MODEL_LAYER].job.omega_idx,
	   "%s contact: three velocities on one envelope make %lu responses (alone: %lu)", name,
	   computed(s), computed(cold));
	ok(within, "  each row is its scene's alone within the sum of their error estimates");
	anvil_solver_free(cold);
	cold = memory_solver();
	anvil_solver_run(cold, &pl[1], ANVIL_MODEL_LAYER, 0, &w, NULL);
	ok(same_results(&w, &r[1]), "  a shared row cold (a fresh solver) and warm: the same bits");
	anvil_result_free(&w);
	for (int i = 0; i < 3; i++)
		anvil_result_free(&r[i]);
	anvil_solver_free(s);
	anvil_solver_free(cold);
}

static void test_share(void)
{
	share_sweep(ANVIL_CONTACT_PAPER, 1);
	share_sweep(ANVIL_CONTACT_PHYSICAL, 4);
	struct anvil_plan_share sh = { 0 }, before;
	struct anvil_plan pl;
	struct anvil_scene sc = phys_scene("1 m/s");
	scene_plan(&sc, &pl, NULL);
	anvil_plan_share_add(&sh, &pl);
	before = sh;
	sc = scene((const char *[]){ "layer.thickness", "2r0", NULL });
	scene_plan(&sc, &pl, NULL);
	ok(anvil_plan_share_add(&sh, &pl) == ANVIL_EINVAL && !memcmp(&sh, &before, sizeof sh),
	   "a plan of another thickness is not of the group: refused, the envelope unchanged");
}

int main(void)
{
	gsl_set_error_handler_off();
	/* Never the user's cache: every solver here is told where to keep
	 * responses, and the environment points nowhere real. */
	setenv("ANVIL_NO_CACHE", "1", 1);
	snprintf(tmpdir, sizeof tmpdir, "/tmp/anvil-test-plan-XXXXXX");
	if (!mkdtemp(tmpdir)) {
		plan(1);
		ok(0, "mkdtemp");
		return 1;
	}
	test_keys();
	test_estimates();
	test_regimes();
	test_effects();
	test_warnings();
	test_memory();
	test_bits();
	test_hold();
	test_status();
	test_disk();
	test_version();
	test_environment();
	test_physical_cache();
	test_share();
	char cmd[200];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
	if (system(cmd) != 0)
		diag("could not remove %s", tmpdir);
	plan(tap_n);
	return done_testing();
}
