/* test_tmax: t_max's estimate on a rippled plateau (solver.c
 * solver_tmax_from_pmax, impact_contact.c impact_plateau; issue 11).
 *
 * A heavy impactor at rest on a thin plate presses with a force flat to
 * 1e-9 over a long stretch, with the plate's waves rippling on it: the
 * march's parabola through the largest sample is the ripple's, and an
 * error far below P_max's estimate moves t_max from one ripple's crest to
 * another (0.02 r0, 10 kg at 1 m/s: 1.2 us against an estimate of
 * 0.38 us).  Here a synthetic pass, a broad parabola 1 - q (t - t0)^2 with
 * ripples of amplitude A on it, is perturbed by errors e(t) = dP sin(W t +
 * phi) (|e| <= dP, P_max's estimate) of several frequencies and phases:
 * the perturbed force's peak must stay within t_max's estimate of the
 * unperturbed one.  The local parabola's shift alone (the rule before the
 * plateau) must fall short at least once, or the case proves nothing; a
 * clean parabola keeps that smaller estimate.  The errors oscillate at
 * up to the band the solver names (solver_tmax_from_pmax's assumption). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "impact_impl.h"
#include "solver_impl.h"
#include "tap.h"

#define N 20001
#define DT 1e-8	 /* s: the pass spans 200 us */
#define T0 1e-4	 /* s: the broad peak's centre */
#define DP 1e-8	 /* P_max's estimate (P in units of its peak) */

static double force(double t, double q, double A)
{
	double x = t - T0;
	return 1.0 - q * x * x + A * cos(2.0 * M_PI * x / 2e-6);
}

/* The pass of the force with the error e added; its peak by impact_peak. */
static void make_pass(struct pass *s, double *P, double q, double A, double W, double phi, double amp)
{
	memset(s, 0, sizeof *s);
	for (size_t i = 0; i < N; i++) {
		double t = (double)i * DT;
		P[i] = force(t, q, A) + amp * sin(W * t + phi);
	}
	s->P = P, s->n = N, s->nseg = 1, s->dt = s->dt0 = DT;
	impact_peak(s);
}

/* The largest move of the peak under the errors, and t_max's estimate;
 * old: the local parabola's shift alone. */
static void run(double q, double A, double *move, double *est, double *old)
{
	const double band = 2.0 * M_PI / 5e-6; /* the errors' top frequency */
	static double P[N];
	struct pass s;
	make_pass(&s, P, q, A, 0, 0, 0);
	struct anvil_result r;
	memset(&r, 0, sizeof r);
	r.Pmax.val = s.Pmax, r.Pmax.err = DP;
	r.tmax.val = s.tmax, r.tmax.err = 0;
	r.Pmax_curv = s.curv;
	impact_plateau(&s, r.Pmax_plat);
	solver_tmax_from_pmax(&r, band);
	double c = s.curv, rate = fmax(band, sqrt(c / s.Pmax));
	*old = fmin(DP * rate / c, 2.0 * sqrt(DP / c));
	*est = r.tmax.err;
	*move = 0;
	double t0 = s.tmax;
	for (int w = 0; w < 6; w++)
		for (int k = 0; k < 8; k++) {
			double W = 2.0 * M_PI / (5e-6 * (double)(1 << w)); /* periods 5-160 us */
			make_pass(&s, P, q, A, W, 2.0 * M_PI * k / 8.0, DP);
			*move = fmax(*move, fabs(s.tmax - t0));
		}
}

int main(void)
{
	plan(4);
	double move, est, old;
	/* P drops 1e-6 at 100 us from the centre; ripples of 1e-8 every 2 us */
	run(1e-6 / 1e-8, 1e-8, &move, &est, &old);
	diag("rippled plateau: the peak moves up to %.3g us; estimate %.3g us (local parabola's %.3g)",
	     move * 1e6, est * 1e6, old * 1e6);
	ok(move <= est, "rippled plateau: t_max's estimate covers the peak's moves");
	ok(move > old, "rippled plateau: the local parabola alone would not (the case has teeth)");
	run(1e-6 / 1e-8, 0.0, &move, &est, &old);
	diag("clean parabola: moves %.3g us; estimate %.3g us (local parabola's %.3g)", move * 1e6,
	     est * 1e6, old * 1e6);
	ok(move <= est, "clean parabola: t_max's estimate covers the peak's moves");
	ok(est <= 3.0 * old + 2.0 * DT,
	   "clean parabola: the plateau adds little (within 3x of the parabola's, plus the node spacing)");
	return done_testing();
}
