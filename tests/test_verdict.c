/* test_verdict: the one verdict (engine/verdict.h) through the whole path:
 * scene, plan, solver run, field with the true contact, peak search.
 * The case: a 50 g steel ball (R = 11.5 mm) at 3 m/s on a 100 mm
 * steel block, where the r0 patch said 19 MPa and Hertz 3.7 GPa mean
 * pressure.  Johnson (1985, sec. 4.2): the peak von Mises under a Hertz
 * contact is 0.620 p0 at 0.481 a for nu = 0.3 (hertz_field.h). */
#include <math.h>
#include <string.h>

#include "scene_run.h"
#include "tap.h"
#include "verdict.h"

/* The field's peak search ends on a grid a_max/8 / 3 apart in z around
 * the contact (field.c, peak_contact and the fine pass): half of that. */
#define Z_GRID_TOL (2.0 / 16 / 6)
/* The dynamic remainder at the contact is of the order of the radiated
 * fraction (about 1 % here) and the grid's flat-top error below 1e-3. */
#define VM_TOL 0.015

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
	st = anvil_solver_verdict(s, &pl, &d, &e);
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

int main(void)
{
	ball_on_block();
	glass();
	plan(tap_n);
	return done_testing();
}
