/* plan_work.c: the work the planner predicts for a layer response, in
 * layer-kernel evaluations (plan.h): what the cost model prices and
 * tests/test_work.c holds to green.c's and the solver's counts. */
#include <math.h>

#include "cache.h"
#include "green.h"
#include "kernel.h"
#include "plan.h"
#include "plate.h"

static double corr_evals(double hh, double nu, double cr, double omega, double tau_end,
			 enum anvil_accuracy acc);

/* The adaptive splitting's work over the starting panels: it bisects
 * towards each Lamb-mode pole until the pieces are as narrow as the poles'
 * distance from the real axis, about c0/c_group with c0 = c0T/(2 tau_end),
 * so about log2 of (starting width w0 = min(1, 2/hh)) / c0 splittings per
 * pole, and a thin layer has fewer poles per starting panel (the factor
 * min(1, hh/2)^(1/4)).  Fitted on 383 responses (tests/test_work.c's
 * generator, another seed, h/r0 0.18-25, draft and normal): the
 * prediction was within 0.73-1.36 of the count; the form before (a
 * function of hh alone) was off by 0.33-2.2. */
static double refine(double hh, double tau_end)
{
	double w0 = fmin(1.0, 2.0 / hh), l = fmax(0.0, log2(tau_end * w0 / 16.0));
	return 1.0 + 0.5 * pow(l, 1.25) * pow(fmin(1.0, 0.5 * hh), 0.25);
}

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
	return corr_evals(hh, nu, sqrt(xr), omega, tau_end, acc);
}

double anvil_plan_inversion_window(double hh, double tau_end)
{
	double tq = anvil_cache_grid(anvil_cache_grid_up(tau_end)); /* as the solver asks */
	double t1 = isfinite(hh) ? anvil_plate_t1(hh, tq) : 0.0;
	return t1 > 0 ? t1 : tau_end;
}

static double corr_evals(double hh, double nu, double cr, double omega, double tau_end,
			 enum anvil_accuracy acc)
{
	struct anvil_green_settings gs;
	double t1 = anvil_plate_t1(hh, tau_end);
	if (t1 > 0) /* the inversion covers [0, T1], the plate the rest (plate.h) */
		tau_end = t1;
	anvil_green_settings(acc, &gs);
	double Tp = 2.0 * tau_end, c0 = gs.c0T / Tp, L = -log(gs.ktail), panels = 0;
	double M = ceil(omega * Tp / M_PI), w0 = fmin(1.0, 2.0 / hh);
	double stride = M + 1 > CORR_SAMPLES ? ceil((M + 1) / CORR_SAMPLES) : 1.0;
	if (!isfinite(M))
		return INFINITY;
	for (double n = 0; n <= M; n += stride) {
		double om = n * M_PI / Tp, wabs = hypot(om, c0);
		double kband = anvil_kband(om, wabs, nu, hh, cr);
		double kend = fmax(kband, sqrt(pow(0.5 * L / hh, 2) + om * om)); /* as green.c */
		panels += stride * (ceil(kband / w0) + ceil((kend - kband) / 4.0));
	}
	return 21.0 * refine(hh, tau_end) * panels;
}


/* The physical contact's layer row (solver.c physical_impact and
 * physical_errors): four corrections (the point load and the Hertz patch at
 * the job's bandwidth, the patch below, the point load at half the band),
 * each a little dearer than the r0 patch's response (the point load's
 * integrand does not decay with k: PHYS_EVAL_F, fitted on 30 scenes, h/r0
 * 0.3-9, 3 g-0.3 kg, 0.3-30 m/s: predicted/actual evaluations 0.8-1.15;
 * the price of the r0 response alone was 3.6-5.2 times short).  Corrections
 * already in the cache cost nothing. */
#define PHYS_EVAL_F 1.3
double anvil_plan_phys_evals(const struct anvil_wave_job *j, double nu, enum anvil_accuracy acc,
			     const struct anvil_cache *cache, enum anvil_cache_where *where)
{
	int tau_idx = anvil_wave_tau_idx(j, anvil_wave_window(j, 0));
	double tq = anvil_cache_grid(tau_idx), evals = 0, xr;
	struct { int omega_idx; double patch; } load[4] = {
		{ j->omega_idx, 0.0 }, { j->omega_idx, j->patch },
		{ j->omega_idx, anvil_plan_patch_below(j->patch) },
		{ j->omega_idx - ANVIL_CACHE_STEPS, 0.0 } };
	*where = ANVIL_CACHE_MEMORY;
	if (anvil_rayleigh_x(anvil_kappa2(nu), &xr, NULL))
		return NAN;
	for (int i = 0; i < 4; i++) {
		struct anvil_cache_key key = { j->hh, nu, acc, load[i].omega_idx, tau_idx, 0,
					       ANVIL_CACHE_LOAD_PATCH, load[i].patch };
		enum anvil_cache_where w = cache ? anvil_cache_probe(cache, &key) : ANVIL_CACHE_NONE;
		if (w == ANVIL_CACHE_NONE)
			evals += PHYS_EVAL_F * corr_evals(j->hh, nu, sqrt(xr),
							  anvil_cache_grid(load[i].omega_idx), tq, acc);
		if (w == ANVIL_CACHE_NONE || (w == ANVIL_CACHE_DISK && *where == ANVIL_CACHE_MEMORY))
			*where = w;
	}
	return evals;
}

