/* test_layer: the layer and half-space models through the solver.
 *  - Tables 2-3 of the paper (loose: the printed rows carry the paper's own
 *    step error, notes.md), and the direction of the difference;
 *  - every accuracy level meets its target on the paper's ten cases, and
 *    the error estimates cover the actual error;
 *  - h = 1000 r0 is the half-space during the contact;
 *  - hard cases stay finite or are refused with a message, never NaN;
 *  - continuity in the parameters;
 *  - the paper's explicit scheme at its 1 us step gives R_f > 1 for thick
 *    layers (notes.md), the implicit scheme does not. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "solver.h"
#include "scene_run.h"
#include "tap.h"

/* The paper's unstarred rows (tables.tsv, as printed). */
static const struct row {
	double V0, h_r0, ts, tmax, Pmax, Rf;
} paper[] = {
	{ 10, 1, 46.00, 17.00, 6.856, 0.344 },   { 10, 2, 41.00, 19.00, 9.639, 0.768 },
	{ 10, 5, 40.20, 20.00, 10.83, 0.965 },   { 10, 10, 40.20, 20.02, 10.98, 0.998 },
	{ 10, INFINITY, 40.4, 20.02, 11.00, 1.00 }, { 100, 1, 34.3, 10.08, 86.9, 0.177 },
	{ 100, 2, 27.40, 12.16, 134.3, 0.657 },  { 100, 5, 26.72, 13.12, 158.8, 0.935 },
	{ 100, 10, 26.72, 13.28, 161.5, 0.986 }, { 100, INFINITY, 27.0, 13.28, 161.5, 0.991 },
};
#define NROWS (int)(sizeof paper / sizeof paper[0])

static struct anvil_solver *solver;

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

static void paper_scene(struct anvil_scene *sc, const struct row *r, enum anvil_accuracy acc)
{
	anvil_scene_default(sc);
	sc->effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
	sc->accuracy = acc;
	set(sc, "impact.velocity", "%g m/s", r->V0);
	if (isinf(r->h_r0))
		anvil_scene_set(sc, "layer.thickness", "inf", "test", 0, NULL);
	else
		set(sc, "layer.thickness", "%g r0", r->h_r0);
}

static enum anvil_model model_of(const struct row *r)
{
	return isinf(r->h_r0) ? ANVIL_MODEL_HALFSPACE : ANVIL_MODEL_LAYER;
}

static int run(const struct anvil_scene *sc, enum anvil_model m, struct anvil_result *r,
	       struct anvil_err *e)
{
	return scene_run(solver, sc, m, 0, r, e);
}

static void test_tables(void)
{
	int lower = 0, longer = 0;
	for (int i = 0; i < NROWS; i++) {
		const struct row *w = &paper[i];
		struct anvil_scene sc;
		struct anvil_result r;
		struct anvil_err e;
		paper_scene(&sc, w, ANVIL_ACC_NORMAL);
		int st = run(&sc, model_of(w), &r, &e);
		double dP = 1e-3 * r.Pmax.val / w->Pmax - 1, dt = 1e6 * r.ts.val / w->ts - 1;
		double dm = 1e6 * r.tmax.val / w->tmax - 1, dR = r.Rf.val - w->Rf;
		diag("V0 %3g h %4g r0: P_max %+.2f%%  t_s %+.2f%%  t_max %+.2f%%  R_f %+.4f", w->V0,
		     w->h_r0, 100 * dP, 100 * dt, 100 * dm, dR);
		ok(st == ANVIL_OK && fabs(dP) < 0.03 && fabs(dt) < 0.03 && fabs(dm) < 0.03 && fabs(dR) < 0.02,
		   "Table %d, h = %g r0: P_max, t_s, t_max within 3 %%, R_f within 0.02 of the paper",
		   w->V0 < 50 ? 2 : 3, w->h_r0);
		lower += dP < 0;
		longer += dt > 0;
		anvil_result_free(&r);
	}
	/* An independent computation of the paper's model finds P_max lower and
	 * t_s longer than printed in every row (the issue, notes.md); so do we. */
	ok(lower == NROWS && longer == NROWS, "P_max below and t_s above the printed values in all rows (%d, %d of %d)",
	   lower, longer, NROWS);
}

static double rel(double a, double b, double floor)
{
	return fabs(a - b) / fmax(fabs(b), floor);
}

static void test_levels(void)
{
	for (int i = 0; i < NROWS; i++) {
		const struct row *w = &paper[i];
		struct anvil_result ref, r;
		struct anvil_scene sc;
		struct anvil_err e;
		paper_scene(&sc, w, ANVIL_ACC_REFERENCE);
		int st = run(&sc, model_of(w), &ref, &e);
		double worst[ANVIL_ACC_REFERENCE] = { 0 };
		int cover = 1, fail = st != ANVIL_OK;
		for (int a = 0; a < ANVIL_ACC_REFERENCE; a++) {
			paper_scene(&sc, w, (enum anvil_accuracy)a);
			fail |= run(&sc, model_of(w), &r, &e) != ANVIL_OK;
			worst[a] = fmax(rel(r.Pmax.val, ref.Pmax.val, 0), fmax(rel(r.ts.val, ref.ts.val, 0), rel(r.Rf.val, ref.Rf.val, 0.1)));
			if (a == ANVIL_ACC_NORMAL)
				cover = fabs(r.Pmax.val - ref.Pmax.val) <= r.Pmax.err + ref.Pmax.err &&
					fabs(r.ts.val - ref.ts.val) <= r.ts.err + ref.ts.err &&
					fabs(r.Rf.val - ref.Rf.val) <= r.Rf.err + ref.Rf.err;
			if (a == ANVIL_ACC_NORMAL && !cover)
				diag("  P_max %.2e vs %.2e, t_s %.2e vs %.2e, R_f %.2e vs %.2e (relative)",
				     fabs(r.Pmax.val - ref.Pmax.val) / ref.Pmax.val, (r.Pmax.err + ref.Pmax.err) / ref.Pmax.val,
				     fabs(r.ts.val - ref.ts.val) / ref.ts.val, (r.ts.err + ref.ts.err) / ref.ts.val,
				     fabs(r.Rf.val - ref.Rf.val), r.Rf.err + ref.Rf.err);
			anvil_result_free(&r);
		}
		ok(!fail && worst[0] < anvil_accuracy_target(ANVIL_ACC_DRAFT) &&
		   worst[1] < anvil_accuracy_target(ANVIL_ACC_NORMAL) &&
		   worst[2] < anvil_accuracy_target(ANVIL_ACC_FINE),
		   "V0 %g h %g r0: each level within its target of the reference (draft %.1e, normal %.1e, fine %.1e)",
		   w->V0, w->h_r0, worst[0], worst[1], worst[2]);
		ok(cover, "V0 %g h %g r0: normal's error estimates cover its distance to the reference", w->V0, w->h_r0);
		anvil_result_free(&ref);
	}
}

static void test_thick_is_halfspace(void)
{
	struct anvil_scene sc;
	struct anvil_result a, b;
	struct anvil_err e;
	anvil_scene_default(&sc);
	sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
	set(&sc, "layer.thickness", "%g r0", 1000);
	run(&sc, ANVIL_MODEL_LAYER, &a, &e);
	run(&sc, ANVIL_MODEL_HALFSPACE, &b, &e);
	ok(a.Pmax.val == b.Pmax.val && a.ts.val == b.ts.val && a.Rf.val == b.Rf.val && strstr(a.note, "2h/c1"),
	   "h = 1000 r0: the layer is the half-space during the contact (%s)", a.note);
	anvil_result_free(&a);
	anvil_result_free(&b);
}

/* A hard scene: finite and converging, or refused with a message. */
static void hard(const char *what, const char *key, const char *value)
{
	struct anvil_scene sc;
	struct anvil_result r, d;
	struct anvil_err e = { 0 }, ed = { 0 };
	anvil_scene_default(&sc);
	sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
	if (key && anvil_scene_set(&sc, key, value, "test", 0, &e)) {
		ok(0, "%s: scene: %s", what, e.msg);
		return;
	}
	int st = run(&sc, ANVIL_MODEL_LAYER, &r, &e);
	int finite = isfinite(r.ts.val) && isfinite(r.Pmax.val) && isfinite(r.Rf.val) && isfinite(r.Ea.val) &&
		     r.ts.val > 0 && r.Pmax.val > 0;
	if (st == ANVIL_OK) {
		sc.accuracy = ANVIL_ACC_DRAFT;
		int sd = run(&sc, ANVIL_MODEL_LAYER, &d, &ed);
		/* at rest on the plate (impact_rest.c) t_s is when the level's
		 * bound was met, later at normal: not compared; R_f is the
		 * interval's midpoint */
		int rest = d.rest_bound > 0 || r.rest_bound > 0;
		double dts = rest ? 0.0 : rel(d.ts.val, r.ts.val, 0);
		double dev = fmax(rel(d.Pmax.val, r.Pmax.val, 0), fmax(dts, rel(d.Rf.val, r.Rf.val, 0.1)));
		ok(finite && sd == ANVIL_OK && dev < anvil_accuracy_target(ANVIL_ACC_DRAFT),
		   "%s: finite (P_max %.4g N, t_s %.4g us, R_f %.4f%s), draft within its target of normal (%.1e)",
		   what, r.Pmax.val, 1e6 * r.ts.val, r.Rf.val, rest ? ", at rest" : "", dev);
		anvil_result_free(&d);
	} else {
		ok((st == ANVIL_ETOL || st == ANVIL_EINVAL) && strlen(e.msg) > 20,
		   "%s: refused with a reason: %s", what, e.msg);
	}
	anvil_result_free(&r);
}

static void test_hard(void)
{
	hard("h = 0.05 r0", "layer.thickness", "0.05 r0");
	hard("h = 0.5 r0", "layer.thickness", "0.5 r0");
	hard("h = 20 r0", "layer.thickness", "20 r0");
	hard("h = 1000 r0", "layer.thickness", "1000 r0");
	hard("h = inf", "layer.thickness", "inf");
	hard("nu = 0", "layer.nu", "0");
	hard("nu = 0.49", "layer.nu", "0.49");
	hard("V0 = 0.01 m/s", "impact.velocity", "0.01 m/s");
	hard("V0 = 1000 m/s", "impact.velocity", "1000 m/s");
	hard("m1 = 1 g", "impactor.mass", "1 g");
	hard("m1 = 10 kg", "impactor.mass", "10 kg");
	hard("soft impactor (PMMA)", "impactor.material", "pmma");
	hard("very soft impactor (E1 = 1 GPa)", "impactor.E", "1 GPa");
}

static void test_continuity(void)
{
	const char *keys[] = { "layer.thickness", "impact.velocity", "impactor.mass" };
	const char *a[] = { "2 r0", "10 m/s", "12.2 g" }, *b[] = { "2.02 r0", "10.1 m/s", "12.3 g" };
	for (int i = 0; i < 3; i++) {
		struct anvil_scene sc;
		struct anvil_result x, y;
		struct anvil_err e;
		anvil_scene_default(&sc);
		sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
		anvil_scene_set(&sc, "layer.thickness", "2 r0", "test", 0, NULL);
		anvil_scene_set(&sc, keys[i], a[i], "test", 0, NULL);
		run(&sc, ANVIL_MODEL_LAYER, &x, &e);
		anvil_scene_set(&sc, keys[i], b[i], "test", 0, NULL);
		run(&sc, ANVIL_MODEL_LAYER, &y, &e);
		double d = fmax(rel(x.Pmax.val, y.Pmax.val, 0), fmax(rel(x.ts.val, y.ts.val, 0), rel(x.Rf.val, y.Rf.val, 0.1)));
		ok(d < 0.02, "a 1 %% change of %s moves the outputs by %.2g (continuous)", keys[i], d);
		anvil_result_free(&x);
		anvil_result_free(&y);
	}
}

static void test_paper_scheme(void)
{
	const double hs[] = { 5, 10 };
	for (int i = 0; i < 2; i++) {
		struct anvil_scene sc;
		struct anvil_result p, q;
		struct anvil_err e;
		anvil_scene_default(&sc);
		sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
		set(&sc, "layer.thickness", "%g r0", hs[i]);
		run(&sc, ANVIL_MODEL_LAYER, &q, &e);
		anvil_scene_set(&sc, "solver.scheme", "paper", "test", 0, NULL);
		anvil_scene_set(&sc, "solver.dt", "1 us", "test", 0, NULL);
		run(&sc, ANVIL_MODEL_LAYER, &p, &e);
		ok(p.Rf.val > 1.0 && q.Rf.val < 1.0 && p.Pmax.val > q.Pmax.val,
		   "h = %g r0: the paper's scheme at dt = 1 us gives R_f = %.4f > 1 (implicit: %.4f)", hs[i],
		   p.Rf.val, q.Rf.val);
		anvil_result_free(&p);
		anvil_result_free(&q);
	}
}

int main(void)
{
	gsl_set_error_handler_off();
	solver = anvil_solver_alloc();
	test_tables();
	test_levels();
	test_thick_is_halfspace();
	test_hard();
	test_continuity();
	test_paper_scheme();
	anvil_solver_free(solver);
	plan(tap_n);
	return done_testing();
}
