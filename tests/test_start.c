/* test_start.c: the layer correction's start for the paper's contact
 * (solver_start.c) on a thin plate at the band's floor.
 *
 * On h = 0.2 r0 (the paper's copper on steel) the band-limited
 * correction at omega = 1 (the normal level's floor, halved: a twin) has
 * rung below zero within its first Nyquist spacing: the anvil's whole
 * ramp went negative there, so the march's first weight R(dt)/dt at the
 * plan's step was negative and the implicit march lost its contact's end
 * (h = 0.2 r0, 10 kg at 100 m/s).  With the start the ramp is the cubic
 * from the reflection's return: held here non-negative and non-decreasing
 * over it, continuous at its end (value, and the step response's slope
 * where the band's slope allows it), the first weight positive; a thick
 * layer (h = 2 r0, its reflection after pi/omega) keeps the band's ramp. */
#include <math.h>

#include "green.h"
#include "halfspace.h"
#include "paper.h"
#include "solver_impl.h"
#include "tap.h"

static double ramp(const struct response *rs, double tau)
{
	double v = NAN;
	solver_response_ramp((void *)rs, tau, &v);
	return v;
}

static void thin(const struct anvil_halfspace *hs, double omega)
{
	struct anvil_params p;
	struct anvil_err err;
	struct anvil_green_settings gs;
	paper_params(&p, 0.2, 100.0);
	anvil_green_settings(ANVIL_ACC_NORMAL, &gs);
	gs.omega_max = omega;
	struct anvil_green *g = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, 0.2, p.nu, 40.0, &gs,
						  NULL, NULL, &err);
	ok(g != NULL, "h = 0.2 r0, omega = %g: the correction made", omega);
	if (!g)
		return;
	struct response rs = { .hs = hs, .corr = g };
	double t1 = M_PI / omega, rmin = INFINITY;
	for (int i = 1; i <= 200; i++)
		rmin = fmin(rmin, ramp(&rs, t1 * i / 200.0));
	ok(rmin < 0, "the band's whole ramp rings below 0 within pi/omega: min %.3g", rmin);
	int st = solver_start_set(&rs, omega, &p);
	ok(st == ANVIL_OK && rs.t1 > 0, "a start set: from t0 = %.4g to t1 = %.4g", rs.t0, rs.t1);
	double prev = 0, worst = 0;
	int mono = 1;
	for (int i = 1; i <= 400; i++) {
		double v = ramp(&rs, rs.t1 * i / 400.0);
		mono &= v >= prev;
		prev = v;
		worst = fmin(worst, v);
	}
	ok(mono && worst >= 0, "the ramp non-negative and non-decreasing over the start (min %.3g)", worst);
	double below = ramp(&rs, rs.t1 * (1 - 1e-9)), above = ramp(&rs, rs.t1 * (1 + 1e-9));
	is_abs(below, above, 1e-6 * fabs(above), "the ramp continuous at t1: %.9g, %.9g", below,
	       above);
	double dt = 0.7307; /* the plan's step there (0.912 us), r0/c2 units */
	ok(ramp(&rs, dt) > 0, "the first weight R(dt)/dt positive: %.3g", ramp(&rs, dt) / dt);
	anvil_green_free(g);
}

int main(void)
{
	struct anvil_err err;
	struct anvil_params p;
	plan(8);
	paper_params(&p, 2.0, 10.0);
	struct anvil_halfspace *hs = anvil_halfspace_alloc(p.nu, anvil_level(ANVIL_ACC_NORMAL)->hs_tol, &err);
	if (!hs) {
		diag("half-space: %s", err.msg);
		return 1;
	}
	thin(hs, 1.0);
	/* a thick layer: its correction is 0 before 2h/c1 = 2.2 > pi/2 */
	struct anvil_green_settings gs;
	anvil_green_settings(ANVIL_ACC_NORMAL, &gs);
	gs.omega_max = 2.0;
	struct anvil_green *g = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, 2.0, p.nu, 40.0, &gs,
						  NULL, NULL, &err);
	struct response rs = { .hs = hs, .corr = g };
	ok(g && solver_start_set(&rs, 2.0, &p) == ANVIL_OK && rs.t1 == 0,
	   "h = 2 r0: no start, the band's ramp as it is");
	double a = 0, b = 0;
	anvil_halfspace_ramp(hs, 1.0, &a, NULL);
	if (g)
		anvil_green_ramp(g, 1.0, &b);
	ok(ramp(&rs, 1.0) == a + b, "h = 2 r0: the same bits as the band's ramp at tau = 1");
	anvil_green_free(g);
	anvil_halfspace_free(hs);
	return done_testing();
}
