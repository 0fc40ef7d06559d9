/* test_coverage: the error estimates cover the true error (issue 11).
 * A seeded random sample of scenes spanning the grid (h/r0 log-uniform in
 * 0.1-100 and the half-space, V0 0.1-100 m/s, impactor mass 1 g-1 kg, the
 * built-in material pairs) is run with the layer model at draft and at
 * normal; an output is covered when |draft - normal| is within the sum of
 * the two estimates (normal is not exact).  Each of t_s, t_max, P_max,
 * R_f and E_a must be covered in at least 95 % of the scenes both levels
 * run (scripts/coverage does the same against reference on more scenes).
 * Scenes the plan prices above COST_MAX at normal are left out (counted).
 * And a row whose true error misses its level's target must not be
 * ANVIL_OK: it carries ANVIL_WTOL or fails.
 *
 * A second sample holds the paper's contact at normal against reference
 * on long contacts, where the estimates failed (issue 11): pmma layers
 * (h/r0 0.7-2.5, reflections returning many times during the contact:
 * t_max moved by more than its own estimate, 1 miss in 13 before the
 * solver's shift from P_max's error, solver.c tmax_from_pmax; P_max in 5
 * of 27 before the band error's amplitude, solver_twin.c solver_add_green_error).
 * NLONG scenes, those the plan prices above LONG_COST_MAX at reference
 * left out; the outputs in LONG_HELD held to 95 %. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>

#include "scene_run.h"
#include "tap.h"

#define NSCENE 40
#define SEED 20261123u
#define NOUT 5
#define COST_MAX 0.3 /* s, the plan's estimate at normal */
#define NLONG 32
#define LONG_COST_MAX 0.8 /* s, the plan's estimate at reference */
/* Held in the long sample: every output.  P_max (81 % before, worst
 * ratio 2.3) and t_s (96 %, 1.5) were only shown until their band error
 * was the amplitude of the twin's difference near the peak and the end,
 * not its value at one instant (solver_twin.c, solver_add_green_error): the thickness
 * resonances make that difference oscillate, and its sample at t_max fell
 * near a zero in 5 of 27 scenes. */
#define LONG_HELD 0x1fu

static const char *const mats[] = { "steel", "copper", "aluminium", "titanium", "glass", "pmma",
				    "tungsten-carbide" };
#define NMAT (int)(sizeof mats / sizeof mats[0])

/* The sample is fixed by SEED on every platform: a 64-bit LCG (Knuth's
 * MMIX constants), not rand(). */
static uint64_t lcg = SEED;
static double uniform(void)
{
	lcg = lcg * 6364136223846793005u + 1442695040888963407u;
	return (double)(lcg >> 11) * 0x1.0p-53;
}

static double loguni(double lo, double hi)
{
	return lo * exp(uniform() * log(hi / lo));
}

struct scene_draw {
	double h_r0, V0, m;
	int a, b;
};

static void draw(struct scene_draw *d)
{
	d->h_r0 = uniform() < 0.125 ? INFINITY : loguni(0.1, 100);
	d->V0 = loguni(0.1, 100);
	d->m = loguni(1e-3, 1);
	d->a = (int)(uniform() * NMAT) % NMAT;
	d->b = (int)(uniform() * NMAT) % NMAT;
}

#define PMMA 5 /* mats[PMMA] */

/* The long-contact sample: any impactor but pmma on a pmma layer. */
static void draw_long(struct scene_draw *d)
{
	d->h_r0 = loguni(0.7, 2.5);
	d->V0 = loguni(1, 30);
	d->m = loguni(1e-3, 3e-2);
	d->a = (int)(uniform() * (NMAT - 1)) % (NMAT - 1);
	d->a += d->a >= PMMA;
	d->b = PMMA;
}

static int set(struct anvil_scene *sc, const char *key, const char *fmt, double v)
{
	char buf[64];
	struct anvil_err e;
	snprintf(buf, sizeof buf, fmt, v);
	int st = anvil_scene_set(sc, key, buf, "test", 0, &e);
	if (st)
		diag("%s = %s: %s", key, buf, e.msg);
	return st;
}

static int make_scene(struct anvil_scene *sc, const struct scene_draw *d, enum anvil_accuracy acc,
		      const char *contact)
{
	struct anvil_err e;
	anvil_scene_default(sc);
	sc->accuracy = acc;
	int st = anvil_scene_set(sc, "effects.contact", contact, "test", 0, &e) || set(sc, "impact.velocity", "%.6g m/s", d->V0) || set(sc, "impactor.mass", "%.6g kg", d->m);
	st = st || anvil_scene_set(sc, "impactor.material", mats[d->a], "test", 0, &e) ||
	     anvil_scene_set(sc, "layer.material", mats[d->b], "test", 0, &e);
	if (isinf(d->h_r0))
		st = st || anvil_scene_set(sc, "layer.thickness", "inf", "test", 0, &e);
	else
		st = st || set(sc, "layer.thickness", "%.6g r0", d->h_r0);
	return st;
}

static const char *const names[NOUT] = { "t_s", "t_max", "P_max", "R_f", "E_a" };

static void vals(const struct anvil_result *r, const struct anvil_val *v[NOUT])
{
	v[0] = &r->ts, v[1] = &r->tmax, v[2] = &r->Pmax, v[3] = &r->Rf, v[4] = &r->Ea;
}

/* A row at rest on the plate (result.h rest_bound) has no contact end:
 * its t_s is when the rebound's bound fell within its level's rest_tol (a
 * tenth of the level's merge gap, solver.c), so draft's and normal's t_s
 * are two thresholds' times, not one quantity (h 0.29 r0 titanium, 0.31 kg
 * at 0.6 m/s: 28.6, 38.0 and 47.2 ms at draft, normal and fine, the bound
 * 1e-3, 1e-4, 1e-5; each within its estimate, the time the bound took to
 * halve).  Its t_s is compared only when neither row is at rest, and the
 * solver holds it to no target (solver_check_target); R_f's [0, bound] is
 * compared as any value. */
static int at_rest(const struct anvil_result *lo, const struct anvil_result *hi)
{
	return lo->rest_bound > 0 || hi->rest_bound > 0;
}

/* The true error of lo against hi past lo's target (the check the solver
 * makes: P_max and t_s relative, R_f against max(R_f, 0.1)). */
static int misses(const struct anvil_result *lo, const struct anvil_result *hi, double tgt)
{
	return fabs(lo->Pmax.val - hi->Pmax.val) > tgt * hi->Pmax.val ||
	       (!at_rest(lo, hi) && fabs(lo->ts.val - hi->ts.val) > tgt * hi->ts.val) ||
	       fabs(lo->Rf.val - hi->Rf.val) > tgt * fmax(fabs(hi->Rf.val), 0.1);
}

/* One sample: n scenes drawn by draw, the layer (or half-space) row with
 * the contact model named, at lo against hi; those the plan prices above
 * cost_max at hi are left out (counted).  Asserts each output's coverage
 * (>= 95 %; a failed lo row is a miss) and that no lo row missing its
 * target is ANVIL_OK. */
struct sample {
	const char *name;
	void (*draw)(struct scene_draw *);
	int n;
	enum anvil_accuracy lo, hi;
	const char *contact;
	double cost_max;
	unsigned held; /* bit k: output k is held to 95 % (else its coverage is only shown) */
};

static void run_sample(struct anvil_solver *s, const struct sample *sp)
{
	int covered[NOUT] = { 0 }, ncmp[NOUT] = { 0 }, n = 0, silent = 0, slow = 0, rest = 0;
	double worst[NOUT] = { 0 };
	const char *lo_name = anvil_accuracy_name(sp->lo), *hi_name = anvil_accuracy_name(sp->hi);
	for (int i = 0; i < sp->n; i++) {
		struct scene_draw d;
		struct anvil_scene sc;
		struct anvil_result lo, hi;
		struct anvil_err e;
		struct anvil_plan pl;
		sp->draw(&d);
		enum anvil_model m = isinf(d.h_r0) ? ANVIL_MODEL_HALFSPACE : ANVIL_MODEL_LAYER;
		if (make_scene(&sc, &d, sp->hi, sp->contact))
			continue;
		/* long contacts (thin, slow, heavy) cost minutes today (issue 11,
		 * reach): the plan's predicted cost keeps the test short, and the
		 * scenes it leaves out are counted */
		if (!scene_plan(&sc, &pl, &e) && pl.row[m].cost > sp->cost_max) {
			slow++;
			continue;
		}
		int sh = scene_run(s, &sc, m, 0, &hi, &e);
		make_scene(&sc, &d, sp->lo, sp->contact);
		int sl = scene_run(s, &sc, m, 0, &lo, &e);
		if (sh < 0) { /* the truth refused or failed: nothing to check against */
			anvil_result_free(&lo);
			anvil_result_free(&hi);
			continue;
		}
		n++;
		const struct anvil_val *a[NOUT], *b[NOUT];
		vals(&lo, a);
		vals(&hi, b);
		rest += at_rest(&lo, &hi);
		for (int k = 0; k < NOUT; k++) {
			if (k == 0 && at_rest(&lo, &hi))
				continue; /* two rest thresholds' times (at_rest) */
			ncmp[k]++;
			double err = fabs(a[k]->val - b[k]->val), est = a[k]->err + b[k]->err;
			double ratio = est > 0 ? err / est : (err > 0 ? INFINITY : 0);
			if (sl < 0)
				ratio = INFINITY;
			covered[k] += ratio <= 1;
			if (!(ratio <= 1))
				diag("%s: h %.4g r0, V0 %.4g m/s, m %.4g kg, %s on %s: %s error %.3e, estimate %.3e",
				     sp->name, d.h_r0, d.V0, d.m, mats[d.a], mats[d.b], names[k], err, est);
			worst[k] = fmax(worst[k], ratio);
		}
		if (sl == ANVIL_OK && misses(&lo, &hi, anvil_accuracy_target(sp->lo))) {
			silent++;
			diag("%s: h %.4g r0, V0 %.4g m/s: %s missed its target with ANVIL_OK", sp->name,
			     d.h_r0, d.V0, lo_name);
		}
		anvil_result_free(&lo);
		anvil_result_free(&hi);
	}
	diag("%s: %d scenes left out by their planned cost; %d at rest on the plate (t_s not compared)",
	     sp->name, slow, rest);
	ok(n >= sp->n / 2, "%s: %d of %d scenes run at both levels", sp->name, n, sp->n);
	for (int k = 0; k < NOUT; k++)
		if (!(sp->held >> k & 1u))
			diag("%s: %s's coverage of %s not held yet: %.1f %% of %d scenes (worst ratio %.2f)",
			     sp->name, lo_name, names[k], ncmp[k] ? 100.0 * covered[k] / ncmp[k] : 0.0,
			     ncmp[k], worst[k]);
		else
			ok(ncmp[k] >= n / 2 && ncmp[k] > 0 && covered[k] >= 0.95 * ncmp[k],
			   "%s: %s's estimate (plus %s's) covers |%s - %s| of %s in %.1f %% of %d scenes (worst ratio %.2f)",
			   sp->name, lo_name, hi_name, lo_name, hi_name, names[k],
			   ncmp[k] ? 100.0 * covered[k] / ncmp[k] : 0.0, ncmp[k], worst[k]);
	ok(silent == 0, "%s: no %s row that misses its target is ANVIL_OK (%d did)", sp->name,
	   lo_name, silent);
}

int main(void)
{
	gsl_set_error_handler_off();
	struct anvil_solver *s = anvil_solver_alloc();
	anvil_solver_set_cache_dir(s, NULL, NULL); /* in memory: nothing on disk */
	const struct sample grid = { "grid", draw, NSCENE, ANVIL_ACC_DRAFT, ANVIL_ACC_NORMAL,
				     "auto", COST_MAX, 0x1f };
	const struct sample longc = { "long contacts, paper's contact", draw_long, NLONG,
				      ANVIL_ACC_NORMAL, ANVIL_ACC_REFERENCE, "paper", LONG_COST_MAX,
				      LONG_HELD };
	run_sample(s, &grid);
	run_sample(s, &longc);
	anvil_solver_free(s);
	plan(tap_n);
	return done_testing();
}
