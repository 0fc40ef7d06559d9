/* test_verdict: the one verdict (engine/verdict.h) through the whole path:
 * scene, plan, solver run, field with the true contact, peak search.
 * The case: a 50 g steel ball (R = 11.5 mm) at 3 m/s on a 100 mm
 * steel block, where the r0 patch said 19 MPa and Hertz 3.7 GPa mean
 * pressure.  Johnson (1985, sec. 4.2): the peak von Mises under a Hertz
 * contact is 0.620 p0 at 0.481 a for nu = 0.3 (hertz_field.h). */
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "scene_run.h"
#include "tap.h"
#include "verdict.h"

/* The field's peak search ends on a grid a_max/8 / 3 apart in z around
 * the contact (field.c, peak_contact and the fine pass): half of that. */
#define Z_GRID_TOL (2.0 / 16 / 6)
/* The dynamic remainder at the contact is of the order of the radiated
 * fraction (about 1 % here) and the grid's flat-top error below 1e-3. */
#define VM_TOL 0.015

/* The verdict from the searched field of the plan's layer (half-space)
 * row, as anvil_solver_verdict makes it where no quasi-static rule holds
 * (yield.c row_field): the field these tests check. */
static int field_verdict(struct anvil_solver *s, const struct anvil_plan *pl,
			 struct anvil_verdict *d, struct anvil_err *e)
{
	struct anvil_result r;
	enum anvil_model m = anvil_verdict_model(pl);
	int st = anvil_solver_run_contact(s, pl, m, pl->row[m].contact, ANVIL_FIELD_NHIST, &r, e);
	struct anvil_field *f = st >= 0 ? anvil_field_from_result(&pl->pb.p, pl->pb.accuracy, &r, e)
					: NULL;
	st = f ? anvil_verdict_make(&pl->pb, f, d, e) : -1;
	anvil_field_free(f);
	anvil_result_free(&r);
	return st;
}

static void ball_on_block(void)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err e = {0};
	struct anvil_verdict q, d;
	anvil_scene_default(&sc);
	const char *keys[][2] = {{"impactor.material", "steel"}, {"impactor.shape", "ball"},
				 {"impactor.radius", "11.5 mm"}, {"impactor.mass", "50 g"},
				 {"layer.thickness", "100 mm"}, {"impact.velocity", "3 m/s"}};
	for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
		anvil_scene_set(&sc, keys[i][0], keys[i][1], NULL, 0, &e);
	int st = scene_plan(&sc, &pl, &e);
	ok(!st, "the ball-on-block scene plans (%s)", e.msg);
	st = anvil_verdict_make(&pl.pb, NULL, &q, &e);
	ok(!st && q.fate == ANVIL_HERTZ_YIELDS && !q.brittle && q.known && !q.dynamic,
	   "quasi-static (plan): yields, %.4g GPa against Y = %.4g GPa", q.stress * 1e-9,
	   q.limit * 1e-9);
	is_rel(q.stress / q.p0, 0.620041, 1e-5, "  peak von Mises / p0 = 0.620 (Johnson)");
	is_rel(q.z / q.a, 0.480864, 1e-5, "  at 0.481 a");
	struct anvil_solver *s = anvil_solver_alloc();
	st = field_verdict(s, &pl, &d, &e);
	ok(st >= 0 && d.fate == q.fate && d.dynamic, "the run (field): the same verdict, %s",
	   e.msg);
	is_rel(d.stress / d.p0, 0.620041, VM_TOL,
	       "  through the field: peak von Mises %.4g GPa = %.4f p0 (0.620)", d.stress * 1e-9,
	       d.stress / d.p0);
	is_abs(d.z / d.a, 0.480864, Z_GRID_TOL, "  at %.4f a (0.481), r = %.2g mm", d.z / d.a,
	       d.r * 1e3);
	ok(d.r <= 0.1 * d.a, "  on the axis");
	/* and not the r0 patch's 19 MPa: two orders of magnitude apart */
	ok(d.stress > 100 * 19e6 && fabs(d.stress / q.stress - 1) < 0.03,
	   "  the field agrees with quasi-static Hertz within 3 %% (%.4g against %.4g GPa)",
	   d.stress * 1e-9, q.stress * 1e-9);
	anvil_solver_free(s);
}

static void glass(void)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err e = {0};
	struct anvil_verdict q, d;
	anvil_scene_default(&sc);
	anvil_scene_parse(&sc, "[impactor]\nmaterial = steel\nshape = ball\ndiameter = 10 mm\n"
			       "[layer]\nmaterial = glass\nthickness = 6 mm\n"
			       "[impact]\nvelocity = 1 m/s\n", "glass", &e);
	int st = scene_plan(&sc, &pl, &e);
	st = st ? st : anvil_verdict_make(&pl.pb, NULL, &q, &e);
	ok(!st && q.brittle && q.fate == ANVIL_HERTZ_CRACKS && q.limit == 45e6,
	   "glass (plan): the tensile criterion, cracks: %.4g MPa against 45 MPa", q.stress * 1e-6);
	is_rel(q.stress, (1 - 2 * 0.22) / 3 * q.p0, 1e-12, "  the edge tension is (1-2nu) p0/3");
	struct anvil_solver *s = anvil_solver_alloc();
	st = anvil_solver_verdict(s, &pl, &d, &e);
	ok(st >= 0 && d.brittle && d.fate == ANVIL_HERTZ_CRACKS,
	   "glass (run): cracks, edge tension %.4g MPa (+- %.2g) at r = %.3g mm", d.stress * 1e-6,
	   d.err * 1e-6, d.r * 1e3);
	char line[320];
	anvil_verdict_text(&d, line, sizeof line);
	ok(strstr(line, "the glass layer cracks: edge tension") && strstr(line, "tensile strength"),
	   "  the line names the criterion: %s", line);
	anvil_solver_free(s);
}

/* The stress a verdict is judged on (verdict.c, governing). */
static double judged(const struct anvil_verdict *v)
{
	return v->bend_state == 1 ? fmax(v->bend, v->near) : v->stress;
}

static const char *const qs_name[] = {"searched", "long", "gentle", "block"};

/* verdict.h's quasi-static rules: where one holds, anvil_solver_verdict
 * is quasi-static Hertz at the row's P_max (and the bending), says why in
 * its line, and agrees with the field it no longer searches within the
 * rule's measured bound (GENTLE 0.9 %, BLOCK 1.3 % at worst on the grid:
 * tol); the field is searched here as yield.c does where no rule holds. */
static void quasi_static(const char *h, const char *m, const char *v, enum anvil_verdict_qs why,
			 const char *says, double tol)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err e = {0};
	struct anvil_verdict q, d;
	anvil_scene_default(&sc);
	anvil_scene_set(&sc, "layer.thickness", h, NULL, 0, &e);
	anvil_scene_set(&sc, "impactor.mass", m, NULL, 0, &e);
	anvil_scene_set(&sc, "impact.velocity", v, NULL, 0, &e);
	int st = scene_plan(&sc, &pl, &e);
	enum anvil_verdict_qs got = st ? ANVIL_VERDICT_QS_NO : anvil_verdict_quasi_static(&pl);
	ok(!st && got == why, "%s, %s at %s: %s (radiated %.2g %%, bending %.2g %%)", h, m, v,
	   qs_name[got], 100 * pl.fig[ANVIL_FIG_RADIATED], 100 * pl.fig[ANVIL_FIG_BENDING]);
	if (why == ANVIL_VERDICT_QS_NO)
		return; /* the field's own tests are ball_on_block's and test_field's */
	struct anvil_solver *s = anvil_solver_alloc();
	st = anvil_solver_verdict(s, &pl, &q, &e);
	char line[ANVIL_VERDICT_TEXT_MAX];
	anvil_verdict_text(&q, line, sizeof line);
	ok(st >= 0 && !q.dynamic && q.qs_why == (int)why && strstr(line, says),
	   "  the verdict is quasi-static and says why: %s", line);
	st = field_verdict(s, &pl, &d, &e);
	ok(!st && d.dynamic && d.fate == q.fate, "  the searched field: the same fate (%s)", e.msg);
	is_rel(judged(&q), judged(&d), tol, "  and within %g %%: %.4g against the field's %.4g MPa",
	       100 * tol, judged(&q) * 1e-6, judged(&d) * 1e-6);
	anvil_solver_free(s);
}

int main(void)
{
	gsl_set_error_handler_off(); /* as the front ends (ui/common.c): statuses, not aborts */
	ball_on_block();
	glass();
	/* a block, the contact 2.7 times 2h/c1; a plate, 35 times */
	quasi_static("10 r0", "0.1 g", "1 mm/s", ANVIL_VERDICT_QS_GENTLE, "the waves would carry off", 0.01);
	quasi_static("2 r0", "10 g", "0.1 m/s", ANVIL_VERDICT_QS_GENTLE, "the waves would carry off", 0.01);
	/* a thick layer at 10 m/s; the half-space at 100 m/s (14 % radiated) */
	quasi_static("10 r0", "1 g", "10 m/s", ANVIL_VERDICT_QS_BLOCK, "the plate's bending changes", 0.015);
	quasi_static("inf", "0.1 g", "100 m/s", ANVIL_VERDICT_QS_BLOCK, "it does not bend", 0.015);
	/* a plate whose bending relieves the stress under the contact by 10 %
	 * (the field against Hertz); and 1 km/s (35 % radiated): searched */
	quasi_static("1 r0", "100 g", "10 m/s", ANVIL_VERDICT_QS_NO, NULL, 0);
	quasi_static("10 r0", "1 g", "1000 m/s", ANVIL_VERDICT_QS_NO, NULL, 0);
	plan(tap_n);
	return done_testing();
}
