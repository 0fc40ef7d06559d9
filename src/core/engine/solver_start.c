/* solver_start.c: the layer correction's start for the paper's contact
 * (solver_impl.h, struct response; run_waves' ramp, solver.c).
 *
 * The correction (the layer's response less the half-space's) is made to
 * a band omega (r0/c2 units): at lags under its Nyquist spacing pi/omega
 * it holds nothing, and its ringing there is of the size of its content
 * above omega.  On a thin plate that content is most of the response (the
 * plate's compliance, not the half-space's): at tau = 0.73 r0/c2 on h =
 * 0.2 r0 the twin's (omega = 1) ramp was -0.43 against the half-space's
 * +0.068, so the first weight of the march, g0 = R(dt)/dt, was negative
 * (-1.5e-9 m/N at dt = 0.91 us), Hertz's root B = g0 + dt^2/6m1 < 0, and
 * the implicit march ran away (h = 0.02 r0, 1 kg at 1 km/s: P_2 = -1.0e5
 * N) or lost its contact's end: with the plan's refusal lifted, 19 of
 * the grid's paper rows (h = 0.02-0.2 r0) lost it; 9 with a start at
 * pi/omega alone, 2 with the Nyquist term's end too (impact.c), none
 * with t1 past the ringing (below).
 *
 * What is known there instead: the correction is 0 before the bottom
 * reflection returns, t0 = 2h/c1 (causality); after it, before the
 * bending couples the patch to the plate around it, each element under
 * the patch moves as a free mass under its pressure, u = p(r) t^2 / 2 rho
 * h: a ramp cubic in time (tau^3 / (4 pi hh) at the centre, the scaled
 * units, for unit force on the Hertz patch).  So over [t0, t1] the ramp
 * is c2 x^2 + c3 x^3 in x = tau - t0, which takes the band's value and
 * slope at t1 (the ramp and the step response continuous: no impulse
 * added), with c2 >= 0 (a step response that starts at 0 and does not
 * fall below it; where that bound acts the value alone is matched).  t1
 * is the first of pi/omega 2^(k/2), k < START_TRIES, past the ringing's
 * first lobes: the band's ramp and step response positive there.  On h
 * = 0.02 r0 at omega = 2 the cubic came out 4.83 tau^3 against the free
 * mass's 3.98, the first weight 4.2e-10 m/N.  The twin (half the band)
 * takes its own start, twice as long: the band's error estimate (their
 * difference) counts the start's change.  Kept as the band made it: a
 * layer whose reflection returns after pi/omega (the paper's own case:
 * its Tables 2-3, anvil table, the same),
 * and a ramp whose whole (half-space and correction) stays non-negative
 * over (0, t1], where the ringing makes no compliance a layer cannot
 * have (start_needed).  On the grid's 637 paper scenes, with the
 * Nyquist term's end and the twin's wider band (solver.c), 162 model rows
 * moved, within their estimates but one (h = 0.02 r0, 0.1 g at 10 m/s:
 * P_max by 1.4 times it, to its value at twice the band). */
#include <math.h>

#include "green.h"
#include "halfspace.h"
#include "solver_impl.h"

#define START_TRIES 7
#define START_SAMPLES 64

/* Whether the anvil's whole ramp (half-space and the band's correction)
 * is negative somewhere in (0, t1], on START_SAMPLES points: the ringing
 * has made a compliance no layer has. */
static int start_needed(const struct response *rs, double t1, int *st)
{
	for (int i = 1; i <= START_SAMPLES && !*st; i++) {
		double tau = t1 * i / START_SAMPLES, a = 0, b = 0;
		if (rs->hs)
			*st = anvil_halfspace_ramp(rs->hs, tau, &a, NULL);
		if (!*st)
			*st = anvil_green_ramp(rs->corr, tau, &b);
		if (!*st && a + b < 0)
			return 1;
	}
	return 0;
}

int solver_start_set(struct response *rs, double omega, const struct anvil_params *p)
{
	double t0 = 2.0 * p->h * p->c2 / (p->c1 * p->r0), t1 = M_PI / omega;
	double R = 0, U = 0;
	rs->t0 = rs->t1 = rs->c2 = rs->c3 = 0.0;
	if (!rs->corr || !(t0 < t1))
		return ANVIL_OK;
	for (int k = 0; k < START_TRIES; k++, t1 *= M_SQRT2) {
		if (!(t1 < anvil_green_tau_end(rs->corr)))
			return ANVIL_OK;
		int st = anvil_green_ramp(rs->corr, t1, &R);
		if (!st)
			st = anvil_green_step(rs->corr, t1, &U);
		if (st)
			return st;
		if (R > 0 && U >= 0)
			break;
	}
	if (!(R > 0 && U >= 0))
		return ANVIL_OK; /* no start found: the band's ramp as it is */
	int st = ANVIL_OK;
	if (!start_needed(rs, t1, &st))
		return st;
	double x = t1 - t0;
	rs->t0 = t0, rs->t1 = t1;
	rs->c2 = fmax(0.0, (3.0 * R - U * x) / (x * x));
	rs->c3 = (R - rs->c2 * x * x) / (x * x * x);
	return ANVIL_OK;
}
