/* plan_work.c: the work the planner predicts for a layer response, in
 * layer-kernel evaluations (plan.h): what the cost model prices and
 * tests/test_work.c holds to green.c's and the solver's counts. */
#include <math.h>

#include "cache.h"
#include "durbin.h"
#include "green.h"
#include "green_spectrum.h"
#include "green_tail.h"
#include "kernel.h"
#include "plan.h"
#include "plate.h"

static double corr_evals(double hh, double nu, double cr, double omega, double tau_end,
			 enum anvil_accuracy acc, double split_f, double wide);

/* The adaptive splitting's work over the starting panels: it bisects
 * towards each Lamb-mode pole until the pieces are as narrow as the poles'
 * distance from the real axis, about c0/c_group with c0 = c0T/(2 tau_end),
 * so about log2 of (starting width w0 = min(1, 2/hh)) / c0 splittings per
 * pole, and a thin layer has fewer poles per starting panel (the factor
 * min(1, hh/2)^(1/4)).  Fitted on 383 responses (tests/test_work.c's
 * generator, another seed, h/r0 0.18-25, draft and normal): the
 * prediction was within 0.73-1.36 of the count; the form before (a
 * function of hh alone) was off by 0.33-2.2.
 * Those bands were 2 and more (the floor then).  Below, on a thick
 * layer whose floor falls as 4/hh (plan.c), the splitting grows less:
 * on the grid's physical rows at h/r0 2-100 (windows 300-12000) the
 * fraction of the fitted growth it showed was 0.97, 0.76, 0.40, 0.17
 * and about 0 at bands 2, 1.6, 0.8, 0.4 and 0.25.  With the factor
 * min(1, omega/2) the 60 rows of h/r0 1-1000 over 3e5 evaluations are
 * priced 0.89-1.10 of their count (1.6-3.7 without). */
static double refine(double hh, double tau_end, double omega)
{
	double w0 = fmin(1.0, 2.0 / hh), l = fmax(0.0, log2(tau_end * w0 / 16.0));
	return 0.5 * pow(l, 1.25) * pow(fmin(1.0, 0.5 * hh), 0.25) * fmin(1.0, 0.5 * omega);
}

/* The tail's 16-wide starting pieces (kernel.h) end up split about 2.5
 * times over, by the patch's zhat (period 2 pi): test_work's three samples
 * were priced 0.69-1.10, 0.93-1.47 and 0.96-1.63 of their evaluations
 * with this, 0.57-1.00, 0.76-1.47, 0.78-1.63 without. */
#define KTAIL_SPLIT 2.5
/* A thin plate's tail longer than GREEN_TAIL_MIN_SPAN takes its kernel
 * from the interpolant's panels (green_tail.h): 17 evaluations each, its
 * pieces none.  test_work's long contacts and thin plates were priced
 * 0.89-2.05 and 1.00-3.40 of their evaluations with the pieces' price,
 * 0.89-1.24 and 0.97-1.16 with this. */

/* A term whose band is lifted off the real axis (kernel.h
 * anvil_kband_lift: below anvil_lift_cutoff, from 0.9 of the first
 * thickness resonance to 0.8 of S1's cutoff) has no
 * poles to chase: its band's starting pieces (2 H wide) split LIFT_SPLIT
 * times over, and the refine() growth does not apply; its tail's pieces
 * LIFT_TAIL of the KTAIL_SPLIT guess.  Fitted on test_work's four samples
 * (predicted/actual 0.65-1.26, 0.81-1.61, 0.92-1.12, 0.89-1.41; pricing
 * the lifted terms as before: 0.75-2.39, 0.83-3.27, 0.93-1.05,
 * 0.98-4.64) and 20 thin scenes (h/r0 0.02-0.5, 1 g and 1 kg at 1 and
 * 10 m/s, the physical row: 0.98-1.35). */
#define LIFT_SPLIT 1.5
#define LIFT_TAIL 0.5

/* Terms summed exactly up to this many; beyond, every stride-th term
 * stands for stride of them (the panel count varies slowly with n), so
 * the planner's work is bounded whatever the scene (a 10 um radius asks
 * for millions of terms, which the solver then refuses). */
#define CORR_SAMPLES 4096.0

double anvil_plan_corr_evals(double hh, double nu, double omega, double tau_end,
			     enum anvil_accuracy acc)
{
	double xr;
	if (anvil_rayleigh_x(anvil_kappa2(nu), &xr, NULL))
		return NAN;
	return corr_evals(hh, nu, sqrt(xr), omega, tau_end, acc, 1.0, 1.0);
}

double anvil_plan_inversion_window(double hh, double tau_end)
{
	double tq = anvil_cache_grid(anvil_cache_grid_up(tau_end)); /* as the solver asks */
	double t1 = isfinite(hh) ? anvil_plate_t1(hh, tq) : 0.0;
	return t1 > 0 ? t1 : tau_end;
}

/* split_f: the splitting's share times this (PHYS_EVAL_F, a point load's);
 * wide: the contour's widest patch (anvil_kband_lift) */
static double corr_evals(double hh, double nu, double cr, double omega, double tau_end,
			 enum anvil_accuracy acc, double split_f, double wide)
{
	struct anvil_green_settings gs;
	double t1 = anvil_plate_t1(hh, tau_end);
	if (t1 > 0) /* the inversion covers [0, T1], the plate the rest (plate.h) */
		tau_end = t1;
	anvil_green_settings(acc, &gs);
	double Tp = 2.0 * tau_end, c0 = gs.c0T / Tp, L = -log(gs.ktail), panels = 0, lifted = 0,
	       fits = 0;
	double M = ceil(omega * Tp / M_PI);
	double stride = M + 1 > CORR_SAMPLES ? ceil((M + 1) / CORR_SAMPLES) : 1.0;
	if (!isfinite(M))
		return INFINITY;
	for (double n = 0; n <= M; n += stride) {
		double om = n * M_PI / Tp, wabs = hypot(om, c0);
		double kband = anvil_kband(om, wabs, nu, hh, cr);
		double kend = fmax(kband, sqrt(pow(0.5 * L / hh, 2) + om * om)); /* as green.c */
		double tail = KTAIL_SPLIT * ceil((kend - kband) / ANVIL_KTAIL_PIECE);
		if (kend - kband > GREEN_TAIL_MIN_SPAN) { /* the interpolant's panels */
			fits += stride * (GREEN_TAIL_DEG + 1) / 21.0 * green_tail_count(hh, kband, kend);
			tail = 0;
		}
		double ks, lift = anvil_kband_lift(om, hh, nu, kband, wide, &ks);
		/* green_spectrum.c: small pieces to kpole, one piece on to kband */
		double kp = fmax(ks, anvil_kband_poles(om, wabs, nu, hh, cr));
		/* that piece and its halves down to the layer's scale 1/hh at kpole */
		double past = kp < kband ? 1.0 + ceil(log2(1.0 + (kband - kp) * hh)) : 0.0;
		if (lift > 0)
			lifted += stride * (LIFT_SPLIT * split_f *
						    (ceil((kp - ks) /
							  anvil_kband_lift_piece(hh, kband - ks, lift)) +
						     past) +
					    LIFT_TAIL * tail) +
				  stride * (1.0 + split_f * refine(hh, tau_end, omega)) *
					  ceil(ks / anvil_kband_piece(hh, kband));
		else
			panels += stride * (ceil(kp / anvil_kband_piece(hh, kband)) + past + tail);
	}
	return 21.0 * ((1.0 + split_f * refine(hh, tau_end, omega)) * panels + lifted + fits);
}


/* The time samples green.c writes for one correction (green_finish): the
 * inversion's half period Tp = 2 T_inv (T_inv the plate's T1, plate.h, or
 * the whole window), its FFT length N (durbin.h: a power of two >= 4 (M +
 * 1) and >= green.c's GREEN_N_MIN, 8192), a sample every 2 Tp / N up to
 * T_inv, and with the plate's tail ANVIL_PLATE_PAD more: beyond T1 the
 * response is the plate's closed form, whatever the window (before, a
 * long window's samples, not its evaluations, could be most of the work:
 * 10^6 of them for h = 0.5 r0, 1 kg at 10 m/s). */
double anvil_plan_corr_samples(double hh, double omega, double tau_end)
{
	double t1 = isfinite(hh) ? anvil_plate_t1(hh, tau_end) : 0.0;
	double t_inv = t1 > 0 ? t1 : tau_end, Tp = 2.0 * t_inv;
	struct anvil_durbin dl;
	if (anvil_durbin_init(&dl, Tp, 1.0 / Tp, omega, 0))
		return INFINITY;
	return floor(t_inv / (2.0 * Tp / (double)anvil_durbin_fft_size(&dl, 8192))) + 2.0 +
	       (t1 > 0 ? ANVIL_PLATE_PAD : 0.0);
}

/* The plate's K table (plate.h anvil_plate_nodes: 32 nodes an octave of
 * [T1/17, tau_end]), each a quadrature; none without the plate. */
static double plate_nodes(double hh, double tau_end)
{
	double t1 = isfinite(hh) ? anvil_plate_t1(hh, tau_end) : 0.0;
	return t1 > 0 ? (double)anvil_plate_nodes(t1, tau_end) : 0.0;
}

/* The unit costs of a physical correction (seconds, one core of the
 * development machine): one predicted kernel evaluation (PHYS_EVAL_F
 * included), one time sample, one plate node (plan.h ANVIL_PLAN_COST_*,
 * refitted on the grid: the figures below are the first fit's).  Fitted (CPU time, weighted
 * least squares in the ratio) on 176 corrections of 44 scenes (bench
 * section 13's and a random set: h/r0 0.05-18, 0.1 g-10 kg, 0.1-500 m/s,
 * draft and normal, windows 5-2.6e5): predicted/measured 0.58-1.65 (0.69-
 * 1.20 with the true evaluation count).  The price before, evaluations
 * alone at COST_EVAL, was 0.10-4.8 times the time: an evaluation costs
 * 0.15 us, not 0.35-0.45, and long windows' samples and plate nodes were
 * not priced. */
#define PHYS_COST_EVAL ANVIL_PLAN_COST_EVAL
#define PHYS_COST_SAMPLE ANVIL_PLAN_COST_SAMPLE
#define PHYS_COST_NODE ANVIL_PLAN_COST_NODE

/* The physical contact's layer row (solver_phys.c physical_impact and
 * physical_errors): four corrections (the point load and the Hertz patch at
 * the job's bandwidth, the patch below, the point load at half the band),
 * each a little dearer than the r0 patch's response (the point load's
 * integrand does not decay with k: its pieces split PHYS_EVAL_F times as
 * often, fitted on 30 scenes, h/r0 0.3-9, 3 g-0.3 kg, 0.3-30 m/s:
 * predicted/actual evaluations 0.8-1.15; the price of the r0 response
 * alone was 3.6-5.2 times short; a set that splits nothing, a short
 * window's, makes exactly its starting pieces' evaluations, which the
 * factor on the whole had priced 1.3 times over).  Corrections
 * already in the cache cost nothing.  Those missing are made as one set
 * (solver_phys.c phys_prefetch, green.h anvil_green_alloc_set): the kernel is
 * evaluated once per node for all of them, so the set's evaluations are
 * those of its widest (the others' own nodes were 0.01-0.03 % of them on
 * bench section 13), and each other member's integrand calls cost a
 * memo lookup and its patch's transform, PHYS_COST_HIT each (0.013 us:
 * h = 10 r0, 10 kg, 0.1 m/s, all kernel work, 1.65 s alone, 0.71 s as a
 * set (0.63 s), 3.75 M evaluations and 8.9 M values from the memo;
 * 0.028 us since, scaled with the evaluation's refit, plan.h). */
#define PHYS_EVAL_F 1.3
#define PHYS_COST_HIT 2.8e-8
/* The four corrections' predicted evaluations and (seconds, may be NULL)
 * the time to make them, those in the cache left out. */
static double phys_work(const struct anvil_wave_job *j, double nu, enum anvil_accuracy acc,
			const struct anvil_cache *cache, enum anvil_cache_where *where,
			double *seconds)
{
	int tau_idx = anvil_wave_tau_idx(j, anvil_wave_window(j, 0));
	double tq = anvil_cache_grid(tau_idx), sum = 0, widest = 0, sec = 0, xr;
	struct { int omega_idx; double patch; } load[4] = {
		{ j->omega_idx, 0.0 }, { j->omega_idx, j->patch },
		{ j->omega_idx, anvil_plan_patch_below(j->patch) },
		{ j->omega_idx - ANVIL_CACHE_STEPS, 0.0 } };
	int plate_paid = 0;
	*where = ANVIL_CACHE_MEMORY;
	if (seconds)
		*seconds = NAN;
	if (anvil_rayleigh_x(anvil_kappa2(nu), &xr, NULL))
		return NAN;
	for (int i = 0; i < 4; i++) {
		struct anvil_cache_key key = { j->hh, nu, acc, load[i].omega_idx, tau_idx, 0,
					       ANVIL_CACHE_LOAD_PATCH, load[i].patch, j->patch };
		enum anvil_cache_where w = cache ? anvil_cache_probe(cache, &key) : ANVIL_CACHE_NONE;
		if (w == ANVIL_CACHE_NONE) {
			double om = anvil_cache_grid(load[i].omega_idx);
			double e = corr_evals(j->hh, nu, sqrt(xr), om, tq, acc, PHYS_EVAL_F,
					      green_lift_wide(j->patch));
			sum += e;
			widest = fmax(widest, e);
			/* the plate's nodes once: the solver keeps its K(t) table
			 * for the next correction (plate.h, anvil_plate_memo) */
			sec += anvil_plan_corr_samples(j->hh, om, tq) * PHYS_COST_SAMPLE +
			       (plate_paid ? 0.0 : plate_nodes(j->hh, tq) * PHYS_COST_NODE);
			plate_paid = 1;
		}
		if (w == ANVIL_CACHE_NONE || (w == ANVIL_CACHE_DISK && *where == ANVIL_CACHE_MEMORY))
			*where = w;
	}
	if (seconds)
		*seconds = sec + widest * PHYS_COST_EVAL + (sum - widest) * PHYS_COST_HIT;
	return widest;
}

double anvil_plan_corr_fixed(double hh, double omega, double tau_end)
{
	return anvil_plan_corr_samples(hh, omega, tau_end) * PHYS_COST_SAMPLE +
	       plate_nodes(hh, tau_end) * PHYS_COST_NODE;
}

double anvil_plan_phys_evals(const struct anvil_wave_job *j, double nu, enum anvil_accuracy acc,
			     const struct anvil_cache *cache, enum anvil_cache_where *where)
{
	return phys_work(j, nu, acc, cache, where, NULL);
}

double anvil_plan_phys_seconds(const struct anvil_wave_job *j, double nu, enum anvil_accuracy acc,
			       const struct anvil_cache *cache, enum anvil_cache_where *where)
{
	double sec;
	phys_work(j, nu, acc, cache, where, &sec);
	return sec;
}

/* ---- the coupled run's cost (plan.c's rows; the unit costs measured as
 * plan.c's COST_* are) ----
 * IMPACT_LIN_HS, IMPACT_SQ_HS: a run on the half-space or the static
 * anvil, linear and quadratic in its steps; IMPACT_LIN_LAYER,
 * IMPACT_FFT_LAYER: on the layer response, per node and per node's
 * log^2 (the online fast convolution). */
#define IMPACT_LIN_HS 5.0e-7
#define IMPACT_SQ_HS 1.1e-9
#define IMPACT_LIN_LAYER 2.7e-6
#define IMPACT_FFT_LAYER 3.2e-9
/* The growing step (impact.h, impact_grow.c): past ANVIL_GROW_AFTER Hertz
 * pulses of nsteps steps the step doubles where the force is smooth, and a
 * long contact then marches about IMPACT_GROWN more pulses' worth of
 * nodes, whatever its length (the bench's long contacts, normal: 4-19,
 * their predicted/marched nodes 0.75-1.6); each such node pays the frozen
 * past (IMPACT_HIST, s: 8 us before its chunks were held to a few spans
 * of the frozen segments, impact_grow.c hist_cmax, and the plate's K(t)
 * was made once per window, plan_work.c), and the ramp's table costs per
 * step of the window at dt (IMPACT_TAB, s; measured 0.7-1.2 us per
 * window step in PHYS_RUNS' units before the plate's tail left the
 * samples beyond T1 out, 0.44-0.47 us after: 19 grid rows of 3.4e5 and
 * 6e5 window steps, priced 1.9-2.3 times their CPU at 1 us).  Since the
 * table is made only as far as the march reaches (impact_wts.c), 0.27-0.38
 * of the window on the grown contacts measured (all of it where the
 * contact fills its window, short ones), it is priced at 0.16 us: on
 * scripts/bench section 13 and the six thin-plate scenes of the march's
 * speed-up (cold, one thread, best of 3) the physical row's whole
 * prediction is then 0.69-1.96 times the process' CPU time (before:
 * 0.65-1.9): 0.69-0.74 on the two long-mode rows at h = 0.05-0.1 r0,
 * whose band the solver doubles (lambda* = 9000: plan.c,
 * PHYS_WIDE_LAMBDA), 1.84-1.96 on h = 0.5 r0, 100 kg at 1 m/s and
 * h = 0.02 r0, 100 kg at 1 mm/s (1.78-1.90 before), 0.70-1.36 elsewhere
 * but 1.63 on h = r0, 1 kg at 10 m/s. */
/* Long mode: the weights a level makes (impact_impl.h IMPACT_LONG_SEG,
 * both passes), and the far field's cost per grown node and frozen level
 * (its FAR_P sums, a chunk's share of them; impact_grow.c).  IMPACT_FAR
 * was 1.0e-6 until a chunk's far targets went in interpolated runs
 * (impact_far.c far_run) and the end's search took 5 evaluations
 * (impact_end.c): then 13 of the grid's 195 rows of 0.1 s or more were
 * priced 2.03-2.46 times their CPU, long-mode rows at 0.14-0.29 s; at
 * 0.4e-6 all 195 are within 0.56-1.95 (median 1.12; the low end the
 * band's doubling at lambda* ~ 9000, above). */
#define IMPACT_LONG_W 4096.0
#define IMPACT_FAR 0.4e-6
#define IMPACT_GROWN 12.0
#define IMPACT_HIST 3.5e-6
#define IMPACT_TAB 1.6e-7
double anvil_plan_marched(double window_s, double dt, double nsteps, int grows)
{
	double n = window_s / dt, g = ANVIL_GROW_AFTER * nsteps;
	return grows && n > g ? fmin(n, g + IMPACT_GROWN * nsteps) : n;
}

/* The physical row's impacts (layer = 2) since their ramp tables are
 * shared (impact_rtab.c), the rest check made once a node and the far
 * field summed by Clenshaw (impact_rest.c, impact_far.c): per node, frozen
 * node and far sum IMPACT_PHYS_SCALE_* of the units above.  Fitted (a grid
 * of scale factors, the largest |log(price/CPU)| made smallest) on the
 * issue's grid, 219 physical rows of 0.05 s or more: price/CPU 0.73-2.59
 * with the units above (44 rows over 2, long thin-plate contacts priced
 * 0.2 s of march for 0.03-0.1 s), 0.56-1.78 then (median 1.02).  The
 * paper's contact keeps the units above: its march did not change.
 * Refitted (issue 11, plan29) on the grid of 637 scenes as it runs now,
 * with the corrections' unit costs of plan.h: the march's nodes, frozen
 * nodes and far sums 1.45 times the scales before (one factor for the
 * three), the ramp's table (IMPACT_PHYS_SCALE_TAB) 0.55 times IMPACT_TAB.
 * The table had priced the rows whose first window holds 3-6e5 steps at
 * 1.4-1.9 times their whole CPU (the contact ends at 0.27-0.45 of the
 * window there, Zener's estimate of a thin plate's contact being 2-3.7
 * times long: the table stops where the march does).  Rows of 0.02 s or
 * more within 2x of their CPU: 308 of 405 before, 403 after (0.1 s or
 * more: 185 of 207, 205).  The far field's (IMPACT_PHYS_SCALE_FAR, plan31)
 * then 0.5, not 1: the long-mode rows (first window over 10^6 steps)
 * were priced at a median 1.3-2.1 times their CPU per half decade of
 * steps against 0.8-0.9 at 10^4.5-10^5.5, up to 2.64 on h = 0.02 r0,
 * 100 kg (lambda* 5.6e4, 5e8 steps: the far sums' levels grow with the
 * window's log, the Clenshaw sums did not as fast); with 0.5 the grid's
 * rows within 2x: 174 -> 177 of 181 (0.1 s or more), 327 -> 330 of 334
 * (0.02 s), the highest 2.64 -> 2.15 (the rows at 6e5 steps, whose
 * table the contact's early end stops: above); 0.25 gained a row more
 * but took two long-mode rows to 0.56-0.60. */
#define IMPACT_PHYS_SCALE_NODE 0.73
#define IMPACT_PHYS_SCALE_HIST 0.51
#define IMPACT_PHYS_SCALE_FAR 0.5
#define IMPACT_PHYS_SCALE_TAB 0.55
double anvil_plan_impact_cost(double window_s, double dt, int layer, double nsteps)
{
	double n = window_s / dt, g = ANVIL_GROW_AFTER * nsteps;
	if (!layer)
		return IMPACT_LIN_HS * n + IMPACT_SQ_HS * n * n;
	int phys = layer == 2;
	double m = anvil_plan_marched(window_s, dt, nsteps, 1);
	double l2 = log2(fmax(m, 2.0)), tab = n, far = 0.0;
	if (n > ANVIL_MAX_STEPS) { /* long mode (impact.h t_smooth): no table to the window's
				    * end; each level's weights, and the far field per node */
		double levels = log2(n / fmax(g, 1.0));
		tab = fmax(2.0 * g + 64.0, IMPACT_LONG_W) + levels * IMPACT_LONG_W;
		far = (m - g) * levels * IMPACT_FAR * (phys ? IMPACT_PHYS_SCALE_FAR : 1.0);
	}
	double node = (IMPACT_LIN_LAYER + IMPACT_FFT_LAYER * l2 * l2) *
		      (phys ? IMPACT_PHYS_SCALE_NODE : 1.0);
	double hist = IMPACT_HIST * (phys ? IMPACT_PHYS_SCALE_HIST : 1.0);
	tab *= IMPACT_TAB * (phys ? IMPACT_PHYS_SCALE_TAB : 1.0);
	return m * node + (m > g ? (m - g) * hist + tab + far : 0.0);
}
