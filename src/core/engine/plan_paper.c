/* plan_paper.c: the work and price of the paper's contact rows (plan.h,
 * anvil_plan_paper_work), and the refusal of the thin-plate rows whose
 * paper contact chatters (anvil_plan_paper_refuse).
 *
 * What runs (solver.c run_anvil, run_waves, waves_impact): per band round
 * a main impact and its twin at half the band, each trying the windows
 * anvil_wave_window(j, 0), (j, 1), ... until the contact ends inside one
 * (both from window 0); every window with the bottom reflection inside it
 * needs a layer correction at the round's band, made with its twin from
 * one spectrum (the twin of round r is the main of round r - 1: found in
 * the cache); a round doubles the band while the target is missed and the
 * band's part dominates; then, once, a rerun at a finer step.  The rounds
 * and the rerun depend on the computed error estimates: their expected
 * counts are measured (below), the rest is counted as the solver does it.
 * Fitted on the grid (copper on steel, h = 0.02 r0 - inf, 0.1 g -
 * 100 kg, 1 mm/s - 1 km/s, normal) with the solver instrumented per impact
 * and per response. */
#include <math.h>

#include "cache.h"
#include "hertz.h"
#include "plan.h"

/* The paper's contact lasts at least the quasi-static anvil's time (Hertz
 * plus the patch's static compliance, anvil_plan_static): on thick layers
 * and the half-space at 100 m/s - 1 km/s, 1.45-1.9 times Hertz's, past
 * the first window (1.4 times the estimate), measured 1.43-1.92.  So the
 * windows an impact tries run to the first beyond the larger of the job's
 * estimate and that.  On thin plates (h <= 0.05 r0 under 0.1 g) the
 * contact chatters on to 2-8 times Zener's: not foreseen (10 of the grid's
 * 630 paper rows, 0.1-1.6 s).  The margin: a contact just past the first
 * window (aluminium on pmma at 483 m/s, 1.0004 times its end) is counted
 * two windows, the dearer side (the second window's correction there made
 * 3.8 times the first's evaluations). */
#define PAPER_TS_MARGIN 1.05
static int paper_windows(const struct anvil_params *p, const struct anvil_wave_job *j,
			 double ts_static)
{
	double tau_c = PAPER_TS_MARGIN * fmax(j->ts, ts_static) * p->c2 / p->r0;
	int k = 0;
	while (k + 1 < j->attempts && !(anvil_wave_window(j, k) > tau_c))
		k++;
	return k + 1;
}

/* The band rounds a thin plate's long contact takes (1 + the doublings):
 * the grid's running paper rows at h <= r0 by the first window's steps n
 * (a decade's half each) averaged 1.07, 1.25, 1.47, 1.62, 1.77, 2.1, 1.7,
 * 1.9 at n ~ 10^3 ... 10^6.5 (each row 1, 2 or 3: the error estimate
 * decides), those at h = r0 alone 1.18 (43 of 49 one round); thicker
 * layers 1.0-1.1.  Their trend below r0, at most refine_max + 1. */
static double paper_rounds(const struct anvil_wave_job *j, double n0)
{
	if (!(j->hh < 1.0) || j->refine_max < 1 || !(n0 > 0))
		return 1.0;
	double e = 1.0 + 0.5 * (log10(n0) - 3.25);
	return fmax(1.0, fmin(e, fmin(2.0, (double)j->refine_max + 1)));
}

/* The step's rerun (solver.c step_too_coarse: the force peaked within
 * nsteps/16 steps, P_max missed by the march) cannot be told from the
 * plan's estimates (Zener's t_max does not separate the rows, solver.c):
 * on the grid it ran on 0 of 289 rows with a first window under 10^5.5
 * steps, 0.14, 0.67, 0.88, 0.67 of those at 10^5.5, 10^6, 10^6.5, 10^7,
 * each rerun two impacts (a round at the finer step) of about the first
 * run's.  Its expected share beyond PAPER_RERUN_N, on thin plates, was
 * 0.7; refitted with the march below (pprice30, on CPU, not counted): 0.5
 * (0.35-0.7 give within one row the same counts within 2x). */
#define PAPER_RERUN_N 5.6e5
#define PAPER_RERUN_SHARE 0.5

/* One impact of the paper's contact on the layer response over a window
 * of n steps, seconds: the march's cost did not follow the generic model
 * (plan_work.c, anvil_plan_impact_cost: fitted on the physical contact's
 * march).  Refitted (issue 11, pprice30) on the grid's paper rows as they
 * run now (error runs keep their nodes, the contact-end search stops at
 * rounding, a packed FFT for large convolutions: the grid's CPU 132.8 ->
 * 60.1 s), one core, cold, least squares in log(price / CPU) over the 241
 * rows of 0.02 s or more that ran: about PAPER_IMP_S (n / 10^5)^0.35 up
 * to 10^6 steps (the old 0.58 overpriced 10^5 - 10^6 steps 1.5-2.6x), in
 * the level's steps (ANVIL_GROW_AFTER nsteps pulses: the normal level's
 * 400 fitted, others scaled by it: only normal was measured); no dearer
 * than the generic model on windows the step does not grow in (all of it
 * marched).  Beyond 10^6 (long mode, the step grows) a quarter of that
 * law's value at 10^6, then (n / 10^6)^0.3: these rows (0.05-0.53 s at
 * 10^6 - 7 10^7 steps) were priced 1.9-11 times their CPU by the old
 * model, which carried the short law on; now 37 of 39 within 2x.  The
 * median price / CPU per half decade of first-window steps is now
 * 0.82-1.37 from 10^2.5 to 10^8.  The march's cost rises with the chatter
 * measure X (below) whether or not the contact parts: (X /
 * PAPER_CHATTER_X)^0.6 over it, at most PAPER_CHATTER_MAX.  Without it,
 * rows at X = 2-28 ran 2-8 times the law (2-64 contacts; the old onset X
 * = 35 missed them: 0.02 r0, 1 g at 1 mm/s ran 1.37 s, priced 0.29); with
 * it 21 of the 27 that chattered are within 2x (0.20-2.07) and 14 of the
 * 20 with one contact at X >= 3 (0.33-3.8).  Runs the solver ends early
 * (its budget of 64 contacts, or of 10^6 steps in long mode) after
 * 0.03-0.64 s, 9 grid rows priced 3.9-50 times what they ran, are priced
 * as what runs where foreseen (budget_tau, nodes_budget below: 8 of the
 * 9, now 0.71-3.6).  All of it times PAPER_MARCH_SCALE, fitted
 * with the corrections' unit costs of plan.h: 0.45 (0.4 or 0.5 move the
 * counts within 2x by a row). */
/* Refitted (stop 31) after the march's own speed-ups (the contact ends'
 * far past from the convolution, the Hertz root from the last node's, the
 * FFT tables and big blocks kept for the process, the step grown in a
 * co-moving later contact: the paper grid's CPU 60.1 -> 40.5 s): 0.45 ->
 * 0.3, rows >= 0.1 s within 2x of their CPU 68 -> 81 of 98 (0.25: 79,
 * 0.35: 75), >= 0.02 s 165 -> 189 of 218. */
#define PAPER_MARCH_SCALE 0.3
#define PAPER_CHATTER_MAX 8.0
#define PAPER_CHATTER_P 0.6
#define PAPER_IMP_S 0.065
#define PAPER_IMP_P1 0.35
#define PAPER_IMP_P2 0.3
#define PAPER_IMP_LONG 0.25
static double paper_impact(double window_s, const struct anvil_wave_job *j, double chatter)
{
	double n = window_s / j->dt, lvl = j->nsteps / 400.0, m = n / lvl;
	double c = m <= 1e6 ? PAPER_IMP_S * pow(m / 1e5, PAPER_IMP_P1)
			    : PAPER_IMP_LONG * PAPER_IMP_S * pow(10.0, PAPER_IMP_P1) *
				      pow(m / 1e6, PAPER_IMP_P2);
	if (n <= ANVIL_GROW_AFTER * j->nsteps) /* no step grows: all of it marched */
		c = fmin(c, anvil_plan_impact_cost(window_s, j->dt, 1, j->nsteps) / lvl);
	return PAPER_MARCH_SCALE * chatter * lvl * c;
}

/* The contact's chatter measure X = a r0 / h^2 (a: Hertz's contact radius,
 * the plan's figure; the paper's contact on a plate thinner than the
 * patch): the march's factor above starts at PAPER_CHATTER_X (fitted: 1,
 * 2 or 3 lose 1-3 rows within 2x, no factor 16), on windows within
 * ANVIL_MAX_STEPS (long-mode rows showed no rise with X: 0.05-0.53 s at
 * X = 0.7-70). */
#define PAPER_CHATTER_X 1.5
/* The refusal (anvil_plan_paper_refuse), on long-mode rows (a first
 * window over ANVIL_MAX_STEPS steps): Y = X r0 / h = a r0^2 / h^3 at
 * least PAPER_REFUSE_Y.  The contact there bounces on the plate, each
 * contact resolved: on h = 0.02 r0, 100 g at 1 cm/s every 53 steps (48
 * us) at the plan's step and band, every 107 at half the step and every
 * 53 again at twice the band; on h = 0.05 r0, 1 g at 100 m/s at the same
 * steps (every ~910) with twice the band.  So it is the paper's model
 * (a fixed r0 patch whose plate moves under it as a free mass, then
 * bends), not the march: the budget of contacts, or of steps where they
 * keep the step from growing, ends the run.  Measured on the grid (with
 * the correction's start, solver_start.c, and a failed twin taking the
 * wider band, solver.c): of its long-mode paper rows every one with Y >=
 * 553 failed so (75), and every one at Y <= 442 that runs still runs
 * (one at 442 ran, h = 0.1 r0, 100 kg at 1 m/s; one at 349 ran too, h =
 * 0.2 r0, 100 kg at 100 m/s, 3.5 s, which X >= 55 refused).  Not
 * foreseen: 4 long-mode rows at Y = 279-442 and 5 short-window rows at
 * Y = 561-2.2e4 that fail after 0.03-0.6 s, beside others that run at
 * the same Y.  The threshold sits between 442 and 553 (the grid's Y
 * steps by 1.25): an empirical rule on copper on steel, not derived; a
 * change of the march or the band can move its edge. */
#define PAPER_REFUSE_Y 500.0
static double chatter_x(const struct anvil_params *p)
{
	double a = sqrt(p->r0 * anvil_hertz_alpha_max() * p->T * p->V0);
	return isfinite(p->h) && p->h > 0 ? a * p->r0 / (p->h * p->h) : 0.0;
}

/* Unit costs (one core, cold): a kernel evaluation of the paper's r0
 * response, 0.17-0.3 us on the responses of over 10^5 evaluations (0.35
 * us over all 671, small ones carrying their fixed part), and that fixed
 * part, the time samples and the plate's nodes (plan_work.c,
 * anvil_plan_corr_fixed). */
#define PAPER_COST_EVAL ANVIL_PLAN_COST_EVAL /* plan.h: 2.3e-7 before its refit */
#define PAPER_COST_HALFSPACE 1.0e-4

/* The correction of band index oi over window tau_end: its evaluations
 * when the cache lacks it or its twin, else 0. */
static double corr_needed(const struct anvil_params *p, const struct anvil_problem *pb,
			  const struct anvil_wave_job *j, int oi, double tau_end,
			  const struct anvil_cache *cache, double *fixed)
{
	int ti = anvil_wave_tau_idx(j, tau_end);
	struct anvil_cache_key key = { j->hh, p->nu, pb->accuracy, oi, ti, 0,
				       ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
	struct anvil_cache_key twin = key;
	twin.omega_idx = oi - ANVIL_CACHE_STEPS;
	twin.twin = 1;
	*fixed = 0;
	if (cache && anvil_cache_probe(cache, &key) != ANVIL_CACHE_NONE &&
	    anvil_cache_probe(cache, &twin) != ANVIL_CACHE_NONE)
		return 0.0;
	double om = anvil_cache_grid(oi), tq = anvil_cache_grid(ti);
	*fixed = anvil_plan_corr_fixed(j->hh, om, tq);
	return anvil_plan_corr_evals(j->hh, p->nu, om, tq, pb->accuracy);
}

/* The run the contact's budget ends (solver: more than
 * ANVIL_MAX_RUN_CONTACTS contacts).  Where the paper's contact chatters on
 * a thin plate it comes back about once per PAPER_CHATTER_PERIOD r0/h (in
 * units of r0/c2: the plate's bending time over the patch, r0^2/(h c2)):
 * the grid's five rows that ended so (h = 0.02-0.1 r0, X = 28-440) failed
 * at 0.71-0.88 times 64 such periods (0.63-3.5 ms).  They do so on the
 * main's first round, before a twin, a second round or a later window is
 * tried: what ran was the round's responses up to then and one impact
 * marched to that time, where the plan had priced the whole band's rounds
 * over the window that Zener's time gave (3.9-50 times their CPU).
 * Which rows chatter that long is empirical, by Z = X E* / E (the Hertz
 * contact's stiffness against the plate's: a soft impactor, pmma, makes a
 * copper one's X with far fewer contacts): of the grid's rows (copper on
 * steel, E* / E = 0.41) whose window outlasts the 64 periods, every one at
 * Z >= PAPER_BUDGET_Z (X >= 97) ended on the budget (4 of 4); below it, at
 * X = 28-70, 1 of 7 did (0.05 r0, 10 g at 1 m/s), the others ran on with
 * 3-64 contacts and keep the full price.  On tests/test_paper_work.c's
 * thin plates of every material pair (3000 scenes) 3 of the 36 rows so
 * chosen ran on (45-60 contacts); at Z = 18-40 13 of 15 ended on it, but
 * of the copper-on-steel grid's rows there only 1 of 6 did (so not
 * lower); below Z = 13 none of 23 did (pmma impactors, 1-59 contacts;
 * by X alone, X >= 100, they were chosen and ran on).  At Z >=
 * PAPER_BUDGET_Z the contacts last about the job's contact time (Zener's
 * on these plates) at one per PAPER_CONTACT_EVERY periods: the grid's two
 * rows there that ran made 63 contacts in 56.5 periods and 19 in 17.9
 * (0.90, 0.94); the five that failed had 62-2500 periods.
 * Since a later contact's step may grow once it co-moves (impact_grow.c,
 * later_short), a chatter can instead come to rest within the budget
 * (impact_rest.c): the plate carries the impactor's momentum away over
 * m1/Z_plate = lambda* T (params.c: lambda* = alpha* m1 / T), one bounce
 * of about Hertz's time T at a time, so the contacts to the rest grow
 * with Zener's lambda*.  On the test's thin plates (3000 scenes) the 9
 * rows so chosen that came to rest did so after 0.47-0.91 lambda*
 * contacts (34-64, at lambda* = 42-133): 64 contacts are 0.73 lambda* at
 * PAPER_BUDGET_LAMBDA, where about half of the rows would rest in time.
 * At lambda* >= 100, 40 of 41 ended on the budget (one at 133 rested after
 * 63 contacts); at 88-100, 4 of 5 and the grid's one (h = 0.05 r0, 1 g at
 * 100 m/s, lambda* = 89.6); below 88, 4 of 11.  Out of sample (the
 * test's generator from seed 77, 3000 scenes): 40 of 41 ended so. */
#define PAPER_CHATTER_PERIOD 0.8
#define PAPER_CONTACT_EVERY 0.92
#define PAPER_BUDGET_Z 40.0
#define PAPER_BUDGET_LAMBDA 88.0
static double budget_tau(const struct anvil_params *p, double x, double ts)
{
	if (!(x * p->Estar / p->E >= PAPER_BUDGET_Z) || !isfinite(p->h) ||
	    !(p->lambda_star >= PAPER_BUDGET_LAMBDA))
		return INFINITY;
	double period = p->r0 / p->h, tau_s = ts * p->c2 / p->r0;
	if (!(tau_s > ANVIL_MAX_RUN_CONTACTS * PAPER_CONTACT_EVERY * period))
		return INFINITY;
	return ANVIL_MAX_RUN_CONTACTS * PAPER_CHATTER_PERIOD * period;
}

/* The run the step's budget ends (solver: a long-mode contact whose force
 * stays rough, so the step cannot grow and the nodes run out): on the
 * grid, of the long-mode paper rows the refusal lets through (Y <
 * PAPER_REFUSE_Y), every one at Y >= PAPER_NODES_Y whose Hertz time T is
 * short against the plate's period over the patch, T c2 h / r0^2 <
 * PAPER_NODES_T (2.5-6.3 there: 4 of 4), ended so after 0.03 s, priced
 * 5.3-6.9 times that as a full run; the four there at 25-63 ran (0.29-0.40
 * s), as did all 26 long-mode rows at Y = 100-223.  The first round's main
 * then fails in its first window: budget_work over that window.
 * Since a later contact's step may grow once it co-moves (impact_grow.c,
 * later_short), a slow heavy impactor that settles on the plate in a few
 * long contacts answers (at rest, impact_rest.c) instead.  It settles
 * where the plate follows the contact: the Hertz contact soft against the
 * plate (Z = X E* / E) and slow against the plate's time over the patch
 * (T against r0^2 / (c2 h)); it keeps bouncing, its force rough, where
 * both are the other way.  Hence W = Z r0^2 / (c2 h T), the contact's
 * stiffness against the plate's times the plate's time against Hertz's:
 * on the test's thin plates (3000 scenes) the 19 rows the rule above
 * chose that ran (1-4 contacts, at rest) had W = 0.30-4.13; at W >=
 * PAPER_NODES_W all 37 ended on a budget (the steps' or the contacts'),
 * below it 11 of 30 did; out of sample (seed 77, 3000 scenes) 42 of 42. */
#define PAPER_NODES_Y 250.0
#define PAPER_NODES_T 12.0
#define PAPER_NODES_W 4.5
static int nodes_budget(const struct anvil_params *p, const struct anvil_wave_job *j,
			double n0, double x)
{
	double th = p->T * p->c2 * p->h / (p->r0 * p->r0);
	return j->grows && n0 > ANVIL_MAX_STEPS && isfinite(p->h) &&
	       x * p->r0 / p->h >= PAPER_NODES_Y && th < PAPER_NODES_T &&
	       x * p->Estar / p->E >= PAPER_NODES_W * th;
}

/* The work of a run the contact's budget ends at tau_b (budget_tau, in
 * r0/c2) added to w: the first round's main over the windows it reaches
 * (all of them marched but the last, marched to tau_b) and the responses
 * those windows need. */
static void budget_work(const struct anvil_params *p, const struct anvil_problem *pb,
			const struct anvil_wave_job *j, int layer_resp,
			const struct anvil_cache *cache, double chat, double tau_b,
			struct anvil_paper_work *w)
{
	double sec = 0;
	int k = 0;
	for (;; k++) {
		double tau_end = anvil_wave_window(j, k), fixed;
		int last = k + 1 >= j->attempts || tau_end >= tau_b;
		sec += paper_impact(fmin(tau_end, tau_b) * p->r0 / p->c2, j, chat);
		if (layer_resp && anvil_wave_needs_corr(p, j, tau_end)) {
			double ev = corr_needed(p, pb, j, j->omega_idx, tau_end, cache, &fixed);
			if (ev > 0 || fixed > 0)
				w->responses += 1;
			w->evals += ev;
			sec += ev * PAPER_COST_EVAL + fixed;
		}
		if (last)
			break;
	}
	w->windows = k + 1;
	w->rounds = 1;
	w->impacts += 1;
	w->seconds += sec + PAPER_COST_HALFSPACE;
}

/* The work of job j (a wave run of the paper's contact) added to w. */
static void job_work(const struct anvil_problem *pb, const struct anvil_wave_job *j,
		     int layer_resp, const struct anvil_cache *cache, double ts_static,
		     struct anvil_paper_work *w)
{
	const struct anvil_params *p = &pb->p;
	int nw = paper_windows(p, j, ts_static);
	double n0 = anvil_wave_window(j, 0) * p->r0 / p->c2 / j->dt;
	double x = chatter_x(p);
	double chat = x > PAPER_CHATTER_X && n0 <= ANVIL_MAX_STEPS
			      ? fmin(PAPER_CHATTER_MAX, pow(x / PAPER_CHATTER_X, PAPER_CHATTER_P))
			      : 1.0;
	double tau_b = n0 <= ANVIL_MAX_STEPS ? budget_tau(p, x, fmax(j->ts, ts_static)) : INFINITY;
	int budget = ANVIL_BUDGET_CONTACTS;
	if (nodes_budget(p, j, n0, x)) {
		tau_b = anvil_wave_window(j, 0);
		budget = ANVIL_BUDGET_STEPS;
	}
	if (anvil_wave_window(j, nw - 1) >= tau_b) {
		budget_work(p, pb, j, layer_resp, cache, chat, tau_b, w);
		w->budget = budget;
		w->budget_tau = tau_b;
		return;
	}
	int corr = 0;
	for (int k = 0; k < nw; k++)
		corr |= layer_resp && anvil_wave_needs_corr(p, j, anvil_wave_window(j, k));
	double rounds = corr ? paper_rounds(j, n0) : 1.0;
	double sec = 0, imp = 0;
	w->windows = nw;
	w->rounds = rounds;
	/* each round's main and (with a correction) twin try every window up
	 * to the one that holds the contact, marching each to its end but the
	 * last */
	for (int k = 0; k < nw; k++) {
		double win = anvil_wave_window(j, k) * p->r0 / p->c2;
		imp += paper_impact(win, j, chat);
	}
	double per_round = corr ? 2.0 : 1.0;
	double rerun = corr && j->hh < 1.0 && n0 > PAPER_RERUN_N ? PAPER_RERUN_SHARE : 0.0;
	w->impacts += nw * per_round * (rounds + rerun);
	sec += imp * per_round * (rounds + rerun);
	/* round r's responses (a share of the last, rounds not whole) */
	for (int r = 0; corr && r <= j->refine_max; r++) {
		double share = fmin(1.0, rounds - r);
		if (!(share > 0))
			break;
		for (int k = 0; k < nw; k++) {
			double tau_end = anvil_wave_window(j, k), fixed;
			if (!anvil_wave_needs_corr(p, j, tau_end))
				continue;
			double ev = corr_needed(p, pb, j, j->omega_idx + r * ANVIL_CACHE_STEPS,
						tau_end, cache, &fixed);
			if (ev > 0 || fixed > 0)
				w->responses += share;
			w->evals += share * ev;
			sec += share * (ev * PAPER_COST_EVAL + fixed);
		}
	}
	w->seconds += sec + PAPER_COST_HALFSPACE;
}

void anvil_plan_paper_work(const struct anvil_problem *pb, const struct anvil_plan_row *r,
			   const struct anvil_cache *cache, struct anvil_paper_work *w)
{
	double ts_static = 0, pmax;
	if (anvil_plan_static(&pb->p, &ts_static, &pmax))
		ts_static = 0;
	anvil_plan_paper_work_ts(pb, r, cache, ts_static, w);
}

void anvil_plan_paper_work_ts(const struct anvil_problem *pb, const struct anvil_plan_row *r,
			      const struct anvil_cache *cache, double ts_static,
			      struct anvil_paper_work *w)
{
	*w = (struct anvil_paper_work){ 0 };
	job_work(pb, &r->job, r->method == ANVIL_METHOD_LAYER, cache, ts_static, w);
	/* the fallback (a late reflection: the half-space's contact outlasting
	 * 2h/c1) when the contact the windows were chosen for reaches it */
	if (r->fallback && !w->budget && fmax(r->job.ts, ts_static) >= 2.0 * pb->p.h / pb->p.c1) {
		struct anvil_paper_work f;
		anvil_plan_paper_work_ts(pb, &(struct anvil_plan_row){ .method = ANVIL_METHOD_LAYER,
								      .job = r->fallback_job },
					 cache, ts_static, &f);
		w->impacts += f.impacts;
		w->responses += f.responses;
		w->evals += f.evals;
		w->seconds += f.seconds;
	}
}

int anvil_plan_paper_refuse(const struct anvil_params *p, enum anvil_model m,
			    const struct anvil_wave_job *j, struct anvil_err *err)
{
	double n0 = anvil_wave_window(j, 0) * p->r0 / p->c2 / j->dt, x = chatter_x(p);
	if (!j->grows || !(n0 > ANVIL_MAX_STEPS) || !(x * p->r0 / p->h >= PAPER_REFUSE_Y))
		return ANVIL_OK;
	return anvil_err_set(err, ANVIL_ETOL,
			     "%s: the paper's contact chatters on this plate (Hertz's contact radius a = %.3g mm, a r0^2 / h^3 = %.3g): the impactor bounces on the plate under its fixed patch over more than %d steps; the thin-plate model 'zener' or the physical contact applies here",
			     anvil_model_name(m), sqrt(p->r0 * anvil_hertz_alpha_max() * p->T * p->V0) * 1e3,
			     x * p->r0 / p->h, ANVIL_MAX_STEPS);
}
