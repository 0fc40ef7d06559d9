/* plan.c: the planner (see plan.h): estimates first, then decisions. */
#include <math.h>
#include <stdio.h>
#include <string.h>


#include "accuracy.h"
#include "green.h"
#include "halfspace.h"
#include "hertz.h"
#include "kernel.h"
#include "material.h"
#include "plan.h"
#include "plate.h"
#include "radiation.h"
#include "zener.h"

/* What each accuracy level spends (cycles, omega_min, nsteps, hs_tol) is in
 * the one table of levels, base/accuracy.c, so that the planner prices
 * exactly what the solver does. */

/* ---- the wave solver's job ---- */

/* Contact time estimate (s): Zener's plate model for a layer, Hertz for a
 * half-space (zs: Zener's solution for the row, NULL when his ODE failed).
 * When Zener's ODE cannot finish (lambda* >> 1, the impactor then slows
 * like exp(-t/(m1 alpha*)) = exp(-t/(lambda* T))), a few of those decay
 * times. */
static double contact_estimate(const struct anvil_params *p, const struct anvil_zener_sol *zs,
			       double lam, double t_hertz, double *t_rise)
{
	*t_rise = 0;
	if (zs && isfinite(zs->tau_s)) {
		if (zs->tau_max > 0 && isfinite(zs->tau_max))
			*t_rise = zs->tau_max * p->T;
		return fmax(zs->tau_s * p->T, t_hertz);
	}
	return fmax(3.0 * lam * p->T, t_hertz);
}

/* The band's floor: the level's omega_min resolves a layer's own early
 * dynamics, which on a thin plate set the force's rise in its first
 * microseconds (a lower floor there made h = 0.2 r0, 10 kg at 1 mm/s
 * widen its band again, at twice the time).  A thick layer's correction
 * starts at 2h/c1 and varies on the reflections' time, ~ h/c: its floor
 * falls as 4/hh beyond h = 4 r0, to an eighth.  On h = 100 r0, 100 kg at
 * 1 mm/s (a 9 ms contact) the floor of 2 asked for 13,100 terms of dense
 * Lamb poles, 28 s; at 0.25, 1.5 s, and t_s, P_max, R_f, t_max moved
 * within their estimates there and on 228 other grid scenes. */
static double omega_floor(const struct anvil_level *lev, double hh)
{
	return lev->omega_min * (isfinite(hh) ? fmax(0.125, fmin(1.0, 4.0 / hh)) : 1.0);
}

/* Zener's solutions the estimates share (each solved once a plan: they
 * were 5 ODE solves, a third of a warm run's planning): at the scene's
 * lambda* and at 0 (Hertz), NULL where the ODE failed. */
struct zener_pair {
	struct anvil_zener_sol lam, hertz;
	const struct anvil_zener_sol *at_lam, *at_0;
};

/* The job of a wave run: layer (1: the layer correction, when h is
 * finite) or not, for a contact of ts seconds (0: the usual Hertz/Zener
 * estimate from z). */
static void wave_job(const struct anvil_problem *pb, const struct zener_pair *z, int layer,
		     double ts, struct anvil_wave_job *j)
{
	const struct anvil_params *p = &pb->p;
	const struct anvil_level *lev = anvil_level(pb->accuracy);
	if (!lev)
		lev = anvil_level(ANVIL_ACC_NORMAL);
	double t_hertz = anvil_hertz_tau_s() * p->T;
	int lay = layer && isfinite(p->h);
	double t_rise = 0;
	if (!(ts > 0))
		ts = contact_estimate(p, lay ? z->at_lam : z->at_0, lay ? p->lambda_star : 0.0,
				      t_hertz, &t_rise);
	double tchar = fmin(ts, t_hertz); /* sets the bandwidth and the step */
	*j = (struct anvil_wave_job){ 0 };
	j->hh = lay ? pb->hh : INFINITY;
	j->ts = ts;
	j->tau_s = ts * p->c2 / p->r0;
	j->t_rise = t_rise;
	j->omega = fmax(omega_floor(lev, j->hh), lev->cycles / (tchar * p->c2 / p->r0));
	j->omega_idx = anvil_cache_grid_up(j->omega);
	j->twin_idx = j->omega_idx - ANVIL_CACHE_STEPS;
	j->dt = pb->dt > 0 ? pb->dt : tchar / lev->nsteps;
	j->hs_tol = lev->hs_tol;
	j->nsteps = lev->nsteps;
	j->refine_max = pb->scheme == ANVIL_SCHEME_PAPER ? 0 : ANVIL_MAX_REFINE;
	j->grows = pb->scheme != ANVIL_SCHEME_PAPER;
	j->attempts = ANVIL_MAX_ATTEMPTS;
}

double anvil_wave_window(const struct anvil_wave_job *j, int attempt)
{
	return 1.4 * j->tau_s * (double)(1 << attempt) + 2.0;
}

int anvil_wave_tau_idx(const struct anvil_wave_job *j, double tau_end)
{
	int idx = anvil_cache_grid_up(tau_end);
	return idx > j->tau_idx_min ? idx : j->tau_idx_min;
}

/* The half-octave grid of patches: 2^(k/2), k <= 0, exactly as exp2 gives
 * it (the cache key compares the bits). */
double anvil_plan_patch(double x)
{
	if (!(x > 0))
		return 0.0;
	if (!(x < 1))
		return 1.0;
	int k = (int)ceil(2.0 * log2(x));
	if (k < -200)
		k = -200; /* 2^-100 r0: far below any contact */
	while (exp2(0.5 * (k - 1)) >= x)
		k--;
	while (exp2(0.5 * k) < x)
		k++;
	return exp2(0.5 * k);
}

double anvil_plan_patch_below(double patch)
{
	if (!(patch > 0))
		return 0.0;
	return exp2(0.5 * (round(2.0 * log2(patch)) - 1));
}

double anvil_wave_t_smooth(const struct anvil_params *p, const struct anvil_wave_job *j,
			   double tau_end)
{
	/* a job whose first window fits the steps keeps the rule: its later
	 * windows follow a contact the estimate did not foresee (chatter on
	 * a plate that carries the momentum off), where the rest state
	 * answers (impact_rest.c) at a fraction of the cost */
	double first = anvil_wave_window(j, 0) * p->r0 / p->c2 / j->dt;
	if (!j->grows || first <= ANVIL_MAX_STEPS || !anvil_wave_needs_corr(p, j, tau_end))
		return 0.0;
	double tq = anvil_cache_grid(anvil_wave_tau_idx(j, tau_end)); /* the response's */
	return anvil_plate_t1(j->hh, tq) * p->r0 / p->c2;
}

int anvil_wave_needs_corr(const struct anvil_params *p, const struct anvil_wave_job *j,
			  double tau_end)
{
	return isfinite(j->hh) && 2.0 * j->hh * (p->c2 / p->c1) < tau_end;
}

int anvil_wave_refuse(const struct anvil_params *p, double scene_dt, enum anvil_model m,
		      const struct anvil_wave_job *j, double tau_end, double omega,
		      struct anvil_err *err)
{
	double steps = tau_end * p->r0 / p->c2 / j->dt;
	double tq = anvil_cache_grid(anvil_wave_tau_idx(j, tau_end)); /* the response's */
	double terms = omega * 2.0 * anvil_plan_inversion_window(j->hh, tq) / M_PI;
	if (scene_dt > 0.25 * j->ts)
		return anvil_err_set(err, ANVIL_EINVAL,
				     "solver.dt = %.3g us is too long for a contact of about %.3g us (at most a quarter of it)",
				     scene_dt * 1e6, j->ts * 1e6);
	if (steps > ANVIL_MAX_STEPS && !(anvil_wave_t_smooth(p, j, tau_end) > 0))
		return anvil_err_set(err, ANVIL_ETOL,
				     "%s: the contact lasts over %.3g us, more than %d steps of %.3g us; %s",
				     anvil_model_name(m), tau_end * p->r0 / p->c2 * 1e6,
				     ANVIL_MAX_STEPS, j->dt * 1e6,
				     p->lambda_star > 3 ? "the thin-plate model 'zener' applies here" :
				     "set a larger solver.dt or a coarser solver.accuracy");
	/* the bandwidth as the solver rounds it (cache grid; a sweep's shared
	 * one may be wider) */
	double oq = fmax(anvil_cache_grid(anvil_cache_grid_up(omega)),
			 anvil_cache_grid(j->omega_idx));
	if (anvil_wave_needs_corr(p, j, tau_end) && terms <= ANVIL_MAX_TERMS &&
	    !anvil_green_fits(ANVIL_GREEN_LAYER_CORRECTION, j->hh, tq, oq))
		return anvil_err_set(err, ANVIL_ETOL,
				     "layer: the contact lasts over %.3g us (lambda* = %.3g), more samples than a layer response holds at this bandwidth; %s",
				     tau_end * p->r0 / p->c2 * 1e6, p->lambda_star,
				     p->lambda_star > 3 ? "the thin-plate model 'zener' applies here" :
				     "set a coarser solver.accuracy");
	if (anvil_wave_needs_corr(p, j, tau_end) && terms > ANVIL_MAX_TERMS)
		return anvil_err_set(err, ANVIL_ETOL,
				     "layer: the contact lasts over %.3g us (lambda* = %.3g), too long for the transform solver (%.0f terms); the thin-plate model 'zener' applies here",
				     tau_end * p->r0 / p->c2 * 1e6, p->lambda_star, terms);
	return ANVIL_OK;
}

/* ---- cost model ----
 *
 * Seconds = work x unit cost, the unit costs measured on the development
 * machine (a loaded 2-core x86-64; scripts/bench prints the real figures
 * for yours):
 *   COST_EVAL      one layer-kernel evaluation (green.c's integrand with
 *                  its share of the quadrature's bookkeeping): plan.h's
 *                  ANVIL_PLAN_COST_EVAL, the contacts' rows' own (0.35 us
 *                  here before, a full model's price beside a static row);
 *   IMPACT_*       (plan_work.c) one coupled run (passes at dt and dt/2) over a window of
 *                  n steps: linear (weights, the exact contact end) plus,
 *                  on a layer, the online convolution's n log2(n)^2
 *                  (fastconv.h; it was quadratic before, and the planner
 *                  priced a 10^5-step contact 15-40 times too dear).  Fitted
 *                  again after the convolution's mixed-radix FFT, its pair
 *                  of kernels and the contact ends' tabled ramps (issue 11,
 *                  speed) on 13 warm physical-contact runs (responses from
 *                  the cache: the impacts alone), h/r0 0.25-2, 12 g-10 kg,
 *                  1-10 m/s, 8e3-3.5e5 steps, up to 87 contacts: predicted/
 *                  measured 0.62-1.35 (the constants before: 1.1-2.6 times
 *                  dear).  The n log2(n)^2 term is now a quarter of the
 *                  cost at 10^5 steps; beyond the fitted range it grows;
 *                  a run on the layer response costs more per step than one
 *                  on the half-space or the static anvil (interpolation in
 *                  the sampled ramp);
 *   COST_HALFSPACE the exact half-space response (0.03-0.1 ms).
 * The count of kernel evaluations (plan_work.c) mirrors green.c's k_integral: the
 * starting panels (of width min(1, 2/hh) over the band that holds the
 * Lamb-mode poles, 4 beyond), 21 nodes each (real and imaginary parts
 * share them), times the adaptive splitting's extra work (refine()).
 * One evaluation costs 0.28-0.33 us since the kernel was made leaner
 * (transform/layer_bc.c); the twin comes from the main spectrum for free. */
#define COST_EVAL ANVIL_PLAN_COST_EVAL
#define COST_HERTZ 2.0e-6
#define COST_ZENER 2.0e-4
#define COST_HALFSPACE 1.0e-4
struct est {
	struct anvil_params p;
	const struct anvil_problem *pb;
	struct anvil_wave_job lay, hs, st; /* the jobs of a layer, half-space, static run */
	struct zener_pair z;
	double t_static, p_static;
	double radiated, bending, target;
	double window_lay;             /* first window of the layer row, s */
	double steps, terms;
};

static double layer_cost(const struct est *e, const struct anvil_cache *cache,
			 enum anvil_accuracy acc, enum anvil_cache_where *where)
{
	const struct anvil_params *p = &e->p;
	double tau_end = anvil_wave_window(&e->lay, 0);
	int tau_idx = anvil_wave_tau_idx(&e->lay, tau_end);
	double om = anvil_cache_grid(e->lay.omega_idx), tau_q = anvil_cache_grid(tau_idx);
	/* the response and its coarse twin (half the bandwidth, solver.c), made
	 * together from one spectrum: the main one's evaluations pay for both */
	struct anvil_cache_key key = { e->lay.hh, p->nu, acc, e->lay.omega_idx, tau_idx, 0,
				       ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
	struct anvil_cache_key twin = { e->lay.hh, p->nu, acc, e->lay.twin_idx, tau_idx, 1,
					ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
	enum anvil_cache_where wm = ANVIL_CACHE_NONE, wt = ANVIL_CACHE_NONE;
	if (cache) {
		wm = anvil_cache_probe(cache, &key);
		wt = anvil_cache_probe(cache, &twin);
	}
	double evals = 0;
	if (wm == ANVIL_CACHE_NONE || wt == ANVIL_CACHE_NONE)
		evals += anvil_plan_corr_evals(e->lay.hh, p->nu, om, tau_q, acc);
	/* found only when both are: else something is computed */
	*where = wm == ANVIL_CACHE_NONE || wt == ANVIL_CACHE_NONE ? ANVIL_CACHE_NONE
		 : wm == ANVIL_CACHE_DISK || wt == ANVIL_CACHE_DISK ? ANVIL_CACHE_DISK
								     : ANVIL_CACHE_MEMORY;
	return COST_HALFSPACE + evals * COST_EVAL + 2.0 * anvil_plan_impact_cost(e->window_lay, e->lay.dt, 1, e->lay.nsteps);
}

/* ---- figures ---- */

static const struct anvil_fig_info fig_info[ANVIL_FIG_COUNT] = {
	[ANVIL_FIG_TARGET] = { "target", "accuracy target", ANVIL_UNIT_FRACTION },
	[ANVIL_FIG_H_R0] = { "h/r0", "layer thickness / r0", ANVIL_UNIT_NONE },
	[ANVIL_FIG_T_HERTZ] = { "t_s(hertz)", "Hertz contact time", ANVIL_UNIT_TIME },
	[ANVIL_FIG_T_STATIC] = { "t_s(static)", "contact time, quasi-static anvil",
				 ANVIL_UNIT_TIME },
	[ANVIL_FIG_T_ZENER] = { "t_s(zener)", "contact time, Zener's plate", ANVIL_UNIT_TIME },
	[ANVIL_FIG_T_REFLECT] = { "2h/c1", "bottom reflection returns", ANVIL_UNIT_TIME },
	[ANVIL_FIG_RADIATED] = { "radiated", "impact energy radiated as waves (half-space)",
				 ANVIL_UNIT_FRACTION },
	[ANVIL_FIG_BENDING] = { "bending", "change of P_max, t_s, R_f by the layer's bending",
				ANVIL_UNIT_FRACTION },
	[ANVIL_FIG_LAMBDA] = { "lambda*", "Zener's plate parameter", ANVIL_UNIT_NONE },
	[ANVIL_FIG_ALPHA_A] = { "alpha_A", "super-seismic parameter", ANVIL_UNIT_NONE },
	[ANVIL_FIG_P_MAX] = { "P_max", "Hertz peak force", ANVIL_UNIT_FORCE },
	[ANVIL_FIG_A_HERTZ] = { "a", "Hertz contact radius sqrt(r0 alpha_max)",
				ANVIL_UNIT_LENGTH },
	[ANVIL_FIG_P_MEAN] = { "p_m", "mean contact pressure", ANVIL_UNIT_PRESSURE },
	[ANVIL_FIG_STEPS] = { "steps", "time steps of a wave run", ANVIL_UNIT_NONE },
	[ANVIL_FIG_MARCHED] = { "marched", "of them marched (the step grows where P is smooth)",
				ANVIL_UNIT_NONE },
	[ANVIL_FIG_TERMS] = { "terms", "Fourier terms of the layer response", ANVIL_UNIT_NONE },
};

const struct anvil_fig_info *anvil_plan_fig_info(enum anvil_fig f)
{
	return (unsigned)f < ANVIL_FIG_COUNT ? &fig_info[f] : NULL;
}

static const char *const method_names[ANVIL_METHOD_COUNT] = {
	"skip", "hertz", "zener", "static", "halfspace", "layer" };

const char *anvil_method_name(enum anvil_method m)
{
	return (unsigned)m < ANVIL_METHOD_COUNT ? method_names[m] : "unknown";
}

static const char *const why_text[ANVIL_WHY_COUNT] = {
	[ANVIL_WHY_NOT_ASKED] = "not in solver.models",
	[ANVIL_WHY_EFFECT_OFF] = "switched off in [effects]",
	[ANVIL_WHY_OWN_MODEL] = "its own closed form or ODE",
	[ANVIL_WHY_FORCED] = "as [effects] waves says (or solver.scheme = paper)",
	[ANVIL_WHY_IS_HALFSPACE] = "the layer is a half-space (h = inf)",
	[ANVIL_WHY_LATE_REFLECT] = "the bottom reflection returns after the contact: "
				   "the half-space is exact here (causality)",
	[ANVIL_WHY_SMALL_PLATE] = "reflections return during the contact, but the layer's "
				  "bending changes the results by less than the target allows",
	[ANVIL_WHY_SMALL_WAVES] = "the energy radiated as waves is below what the target "
				  "allows: the quasi-static anvil suffices",
	[ANVIL_WHY_NEEDS_LAYER] = "reflections return during the contact and change the "
				  "results by more than the target allows",
	[ANVIL_WHY_NEEDS_WAVES] = "the energy radiated as waves matters at this accuracy",
	[ANVIL_WHY_PHYSICAL] = "the physical contact: Hertz's approach plus the layer's "
			       "dynamic remainder with the true contact radius (the bottom "
			       "reflections when they return during the contact)",
};

const char *anvil_plan_why_text(enum anvil_plan_why w)
{
	return (unsigned)w < ANVIL_WHY_COUNT ? why_text[w] : "unknown";
}

static const char *const warn_text[ANVIL_WARN_COUNT] = {
	[ANVIL_WARN_SUPERSEISMIC] = "alpha_A is not small: the super-seismic phase right after "
				    "first contact matters, which anvil does not model",
	[ANVIL_WARN_PLATE_RANGE] = "thin-plate theory (zener) is out of its range: h/r0 > 1",
	[ANVIL_WARN_REFUSE] = "the layer solver will refuse this scene (too many steps or "
			      "terms): the thin-plate model 'zener' applies here",
	[ANVIL_WARN_NOT_EXACT] = "waves = halfspace, but the bottom reflection returns during "
				 "the contact: the layer row is not the layer",
	[ANVIL_WARN_FIELD] = "a field inside the layer is asked for ([effects] field): "
			     "'anvil field' and 'anvil map' compute it; not priced here",
};

const char *anvil_plan_warn_text(enum anvil_plan_warn w)
{
	return (unsigned)w < ANVIL_WARN_COUNT ? warn_text[w] : "unknown";
}

/* ---- estimates ---- */

static int estimate(const struct anvil_problem *pb, struct est *e, struct anvil_err *err)
{
	const struct anvil_params *p = &e->p;
	e->p = pb->p;
	e->pb = pb;
	e->z.at_0 = anvil_plan_zener_hertz();
	/* (a half-space has no plate: no estimate reads it) */
	e->z.at_lam = !isfinite(p->h) ||
			      anvil_zener_solve(p->lambda_star, ANVIL_PLAN_ZENER_TOL, &e->z.lam, NULL)
			      ? NULL
			      : &e->z.lam;
	wave_job(pb, &e->z, 1, 0, &e->lay);
	wave_job(pb, &e->z, 0, 0, &e->hs);
	if (anvil_plan_static(p, &e->t_static, &e->p_static))
		return anvil_err_set(err, ANVIL_ENUM, "plan: the quasi-static estimate failed");
	wave_job(pb, &e->z, 0, e->t_static, &e->st);
	e->st.stat = anvil_halfspace_static(p->nu);
	e->radiated = anvil_plan_radiated(p);
	e->bending = anvil_plan_bending_of(p, e->z.at_lam, e->z.at_0);
	e->target = anvil_accuracy_target(pb->accuracy);
	double tau_end = anvil_wave_window(&e->lay, 0);
	e->window_lay = tau_end * p->r0 / p->c2;
	e->steps = ceil(e->window_lay / e->lay.dt);
	e->terms = ceil(e->lay.omega * 2.0 * anvil_plan_inversion_window(e->lay.hh, tau_end) / M_PI);
	return ANVIL_OK;
}

static void figures(const struct est *e, struct anvil_plan *pl)
{
	const struct anvil_params *p = &e->p;
	double am = anvil_hertz_alpha_max() * p->T * p->V0, P = p->K * pow(am, 1.5);
	double a2 = p->r0 * am; /* Hertz: a^2 = R alpha for a sphere of radius R = r0 */
	double *f = pl->fig;
	f[ANVIL_FIG_TARGET] = e->target;
	f[ANVIL_FIG_H_R0] = p->h / p->r0;
	f[ANVIL_FIG_T_HERTZ] = anvil_hertz_tau_s() * p->T;
	f[ANVIL_FIG_T_STATIC] = e->t_static;
	f[ANVIL_FIG_T_ZENER] = e->lay.ts;
	f[ANVIL_FIG_T_REFLECT] = 2.0 * p->h / p->c1;
	f[ANVIL_FIG_RADIATED] = e->radiated;
	f[ANVIL_FIG_BENDING] = e->bending;
	f[ANVIL_FIG_LAMBDA] = p->lambda_star;
	f[ANVIL_FIG_ALPHA_A] = p->alpha_A;
	f[ANVIL_FIG_P_MAX] = P;
	f[ANVIL_FIG_A_HERTZ] = sqrt(a2);
	f[ANVIL_FIG_P_MEAN] = P / (M_PI * a2);
	f[ANVIL_FIG_STEPS] = e->steps;
	f[ANVIL_FIG_MARCHED] = ceil(anvil_plan_marched(e->window_lay, e->lay.dt, e->lay.nsteps,
						       e->lay.grows));
	f[ANVIL_FIG_TERMS] = e->terms;
}

/* ---- rows ---- */

static void row_set(struct anvil_plan_row *r, enum anvil_method m, enum anvil_plan_why why,
		    double model_err, double cost)
{
	r->method = m;
	r->why = why;
	r->model_err = model_err;
	r->exact = model_err == 0;
	r->cost = cost;
}

static void row_fig(struct anvil_plan_row *r, enum anvil_fig f)
{
	if (r->nfig < ANVIL_PLAN_NFIG)
		r->fig[r->nfig++] = f;
}

/* Whether the bottom reflection returns after the contact, with a margin
 * over the larger of the two contact estimates (the solver checks the
 * computed t_s against 2h/c1 afterwards). */
static int late_reflection(const struct est *e)
{
	double t_contact = fmax(e->t_static, e->lay.ts);
	return !isfinite(e->p.h) || 2.0 * e->p.h / e->p.c1 >= 1.1 * t_contact;
}

static double static_cost(const struct est *e)
{
	return anvil_plan_impact_cost(1.4 * e->t_static + 2.0 * e->p.r0 / e->p.c2, e->hs.dt, 0, 0.0);
}

static double halfspace_cost(const struct est *e, const struct anvil_wave_job *j)
{
	double window = anvil_wave_window(j, 0) * e->p.r0 / e->p.c2;
	return COST_HALFSPACE + anvil_plan_impact_cost(window, j->dt, 0, 0.0);
}

/* The physical contact's layer row: its four corrections
 * (anvil_plan_phys_seconds, plan_work.c) and three runs' worth of impact
 * steps (measured against warm runs, impacts alone). */
#define PHYS_RUNS 3.0
/* The whole physical price times PHYS_SPEED: stop 31's kernel, cache and
 * march speed-ups (one exponential fewer a kernel evaluation, the spline's
 * coefficients read from the cache, the Newton root's stop, the
 * convolution's blocks kept) made every row faster alike: the grid's CPU
 * 44.1 -> 35.7 s (0.81), the median price/CPU of each h/r0 group rose from
 * 1.05-1.32 to 1.25-1.61.  With 0.82 the rows >= 0.1 s within 2x: 134 ->
 * 144 of 144 (0.78: 142; 0.86: 144, its top 1.98), >= 0.02 s 279 -> 299 of
 * 300. */
#define PHYS_SPEED 0.82
static double physical_cost(const struct est *e, const struct anvil_wave_job *job,
			    const struct anvil_cache *cache, double patch,
			    enum anvil_cache_where *where)
{
	struct anvil_wave_job j = *job;
	j.patch = patch;
	double corr = anvil_plan_phys_seconds(&j, e->p.nu, e->pb->accuracy, cache, where);
	return PHYS_SPEED * (COST_HALFSPACE + corr +
			     PHYS_RUNS * anvil_plan_impact_cost(e->window_lay, j.dt, 2, j.nsteps));
}

/* The physical row's band: the Hertz pulse's, as the paper's contact has
 * it (wave_job), or the force's rise where that is shorter: on a thin
 * plate P peaks in the impact's first microseconds, which Zener's t_max
 * follows (4.15 us against the layer's 6.24 at h = 0.1 r0, 12.2 g,
 * 10 m/s; Hertz's 19.8), and the pulse's band missed that peak by 2 % at
 * normal, its estimate 6 % (solver_phys.c, run_physical, which widens the band
 * further when the estimate still misses).  And its step: the level's
 * nsteps over the pulse resolve a rise of a Hertz pulse's eighth (cf.
 * Zener's 4.15 us of 19.8 above), but a heavy impactor on a thin plate
 * rises far sooner, 7.2 us of a 1.1 ms pulse under 10 kg on h = 0.05 r0
 * at 1 m/s: 2.6 steps, P_max 3.44 +- 1.5 N against Zener's 3.92; so the
 * step is at most PHYS_RISE t_rise / nsteps (the scene's own dt is kept):
 * 25 steps of the rise at normal, and no change where the pulse's step
 * already resolves it (8 here moved h = 0.1 r0, 12.2 g's step by 16 %). */
#define PHYS_RISE 16.0
/* Beyond lambda* = PHYS_WIDE_LAMBDA the plate carries nearly all of the
 * approach: P_max is a small difference (Hertz's compression at the peak
 * is about 1e-3 of the deflection for 1 kg at 10 m/s on h = 0.02 r0,
 * lambda* = 2.2e4), the correction's band error is amplified by it, and
 * the solver doubled the band on every such scene of the grid (17 of 17,
 * copper on steel, h = 0.02-0.1 r0, 0.1 g-100 kg, 1 mm/s-100 m/s; 6 of 19
 * between 3500 and 1e4, 2 of 140 below).  The plan starts there: the
 * solver's doubled round, without the round it threw away (the same
 * bits), and the plan prices what runs. */
#define PHYS_WIDE_LAMBDA 1e4
static void phys_band(const struct est *e, int widen, struct anvil_wave_job *j)
{
	const struct anvil_level *lev = anvil_level(e->pb->accuracy);
	if (!lev || !(j->t_rise > 0))
		return;
	if (!(e->pb->dt > 0) && PHYS_RISE * j->t_rise / j->nsteps < j->dt)
		j->dt = PHYS_RISE * j->t_rise / j->nsteps;
	double om = lev->cycles / (2.0 * j->t_rise * e->p.c2 / e->p.r0);
	double want = fmax(om, j->omega);
	int wide = widen && e->p.lambda_star >= PHYS_WIDE_LAMBDA;
	if (want > j->omega || wide) {
		j->omega = wide ? 2.0 * want : want;
		j->omega_idx = anvil_cache_grid_up(want) + (wide ? ANVIL_CACHE_STEPS : 0);
		j->twin_idx = j->omega_idx - ANVIL_CACHE_STEPS;
	}
}

/* The layer row: what the full model costs, and whether it needs the
 * layer correction at all (the solver skips it when the reflection
 * returns after the first window: exact, as before the planner). */
static double layer_full_cost(const struct est *e, const struct anvil_cache *cache,
			      enum anvil_accuracy acc, enum anvil_cache_where *where)
{
	*where = ANVIL_CACHE_NONE;
	if (!isfinite(e->p.h) || 2.0 * e->p.h / e->p.c1 >= e->window_lay)
		return halfspace_cost(e, &e->lay);
	return layer_cost(e, cache, acc, where);
}

static void layer_auto(const struct est *e, struct anvil_plan_row *r)
{
	double d_hs = late_reflection(e) ? 0.0 : e->bending;
	double d_static = d_hs + e->radiated;
	if (ANVIL_PLAN_SAFETY * d_static <= e->target) {
		row_set(r, ANVIL_METHOD_STATIC, ANVIL_WHY_SMALL_WAVES, d_static, static_cost(e));
		row_fig(r, ANVIL_FIG_RADIATED);
		row_fig(r, d_hs > 0 ? ANVIL_FIG_BENDING : ANVIL_FIG_T_REFLECT);
	} else if (d_hs == 0) {
		row_set(r, ANVIL_METHOD_HALFSPACE,
			isfinite(e->p.h) ? ANVIL_WHY_LATE_REFLECT : ANVIL_WHY_IS_HALFSPACE, 0.0,
			halfspace_cost(e, &e->lay));
		row_fig(r, ANVIL_FIG_T_REFLECT);
		row_fig(r, ANVIL_FIG_T_STATIC);
		row_fig(r, ANVIL_FIG_T_ZENER);
		return;
	} else if (ANVIL_PLAN_SAFETY * d_hs <= e->target) {
		row_set(r, ANVIL_METHOD_HALFSPACE, ANVIL_WHY_SMALL_PLATE, d_hs,
			halfspace_cost(e, &e->lay));
		row_fig(r, ANVIL_FIG_T_REFLECT);
		row_fig(r, ANVIL_FIG_BENDING);
	} else {
		row_set(r, ANVIL_METHOD_LAYER, ANVIL_WHY_NEEDS_LAYER, 0.0, r->cost_full);
		row_fig(r, ANVIL_FIG_T_REFLECT);
		row_fig(r, ANVIL_FIG_BENDING);
	}
	row_fig(r, ANVIL_FIG_TARGET);
}

static void layer_row(const struct anvil_problem *pb, const struct est *e,
		      const struct anvil_cache *cache, struct anvil_plan_row *r)
{
	enum anvil_cache_where where;
	/* the layer's own model: a half-space when h = inf */
	enum anvil_method own = isfinite(e->p.h) ? ANVIL_METHOD_LAYER : ANVIL_METHOD_HALFSPACE;
	r->cost_full = layer_full_cost(e, cache, pb->accuracy, &where);
	if (pb->effects.waves == ANVIL_WAVES_NONE) { /* asked for all the same: its own model */
		row_set(r, own, ANVIL_WHY_EFFECT_OFF, 0.0, r->cost_full);
	} else if (pb->effects.waves == ANVIL_WAVES_HALFSPACE) {
		row_set(r, ANVIL_METHOD_HALFSPACE, ANVIL_WHY_FORCED,
			late_reflection(e) ? 0.0 : e->bending, halfspace_cost(e, &e->lay));
		row_fig(r, ANVIL_FIG_T_REFLECT);
		row_fig(r, ANVIL_FIG_T_ZENER);
	} else if (pb->effects.waves == ANVIL_WAVES_LAYER || pb->scheme == ANVIL_SCHEME_PAPER) {
		row_set(r, own, ANVIL_WHY_FORCED, 0.0, r->cost_full);
		r->cached = where;
		row_fig(r, ANVIL_FIG_T_REFLECT);
		row_fig(r, ANVIL_FIG_T_ZENER);
	} else {
		layer_auto(e, r);
		r->cached = r->method == ANVIL_METHOD_LAYER ? where : ANVIL_CACHE_NONE;
	}
}

static void halfspace_row(const struct anvil_problem *pb, const struct est *e,
			  struct anvil_plan_row *r)
{
	r->cost_full = halfspace_cost(e, &e->hs);
	int may = pb->effects.waves == ANVIL_WAVES_AUTO && pb->scheme != ANVIL_SCHEME_PAPER;
	if (may && ANVIL_PLAN_SAFETY * e->radiated <= e->target) {
		row_set(r, ANVIL_METHOD_STATIC, ANVIL_WHY_SMALL_WAVES, e->radiated, static_cost(e));
		row_fig(r, ANVIL_FIG_RADIATED);
		row_fig(r, ANVIL_FIG_TARGET);
	} else {
		row_set(r, ANVIL_METHOD_HALFSPACE, may ? ANVIL_WHY_NEEDS_WAVES : ANVIL_WHY_OWN_MODEL,
			0.0, r->cost_full);
		if (may) {
			row_fig(r, ANVIL_FIG_RADIATED);
			row_fig(r, ANVIL_FIG_TARGET);
		}
	}
}

/* The paper's contact's price of a wave row (HALFSPACE or LAYER: what
 * the solver runs, plan_paper.c) and of the layer model's full job. */
static void paper_price(const struct est *e, const struct anvil_cache *cache, enum anvil_model m,
			struct anvil_plan_row *r)
{
	struct anvil_paper_work w;
	if (r->method != ANVIL_METHOD_HALFSPACE && r->method != ANVIL_METHOD_LAYER)
		return;
	anvil_plan_paper_work_ts(e->pb, r, cache, e->t_static, &w);
	r->cost = r->status ? 0.0 : w.seconds; /* refused: nothing runs */
	if (m != ANVIL_MODEL_LAYER || r->method == ANVIL_METHOD_LAYER || !isfinite(e->p.h)) {
		r->cost_full = w.seconds;
		return;
	}
	struct anvil_plan_row full = { .method = ANVIL_METHOD_LAYER, .job = e->lay };
	anvil_plan_paper_work_ts(e->pb, &full, cache, e->t_static, &w);
	r->cost_full = w.seconds;
}

/* What the solver runs for a wave row: the job of its method, the
 * fallback of a half-space taken on causality, the refusal, and the
 * paper's contact's price (every wave row here is the paper's: the
 * physical rows replace them after, contact_rows). */
static void row_job(const struct est *e, const struct anvil_cache *cache, enum anvil_model m,
		    struct anvil_plan_row *r)
{
	struct anvil_err err;
	if (r->method == ANVIL_METHOD_HERTZ || r->method == ANVIL_METHOD_ZENER)
		return;
	r->job = r->method == ANVIL_METHOD_LAYER  ? e->lay
		 : r->method == ANVIL_METHOD_STATIC ? e->st
						     : e->hs;
	r->fallback = r->why == ANVIL_WHY_LATE_REFLECT;
	if (r->fallback)
		r->fallback_job = e->lay;
	if (r->job.refine_max == ANVIL_MAX_REFINE) /* not the paper's scheme (none) */
		r->job.refine_max = ANVIL_PAPER_MAX_REFINE;
	if (r->fallback && r->fallback_job.refine_max == ANVIL_MAX_REFINE)
		r->fallback_job.refine_max = ANVIL_PAPER_MAX_REFINE;
	r->status = anvil_wave_refuse(&e->p, e->pb->dt, m, &r->job, anvil_wave_window(&r->job, 0),
				      r->job.omega, &err);
	if (!r->status && r->method == ANVIL_METHOD_LAYER)
		r->status = anvil_plan_paper_refuse(&e->p, m, &r->job, &err);
	if (r->status)
		snprintf(r->refusal, sizeof r->refusal, "%s", err.msg);
	paper_price(e, cache, m, r);
}

/* --- contactB: the physical contact's rows (issue 10) --- */

/* Hertz's law takes the layer for a half-space at the contact's scale:
 * a contact radius beyond h is outside the physical contact's model.
 * Decided here on Zener's plate (its peak compression, the plate's
 * bending included), not the rigid anvil's Hertz radius, which is an
 * upper bound (the Hertz spring's energy at the peak is at most the
 * impact's) and would refuse scenes the layer computes: h = 0.1 r0 under
 * the paper's impactor has a_Hertz/h = 1.8 and a/h = 0.6 computed.  The
 * plate is softer at the contact than the layer (no local compression
 * beyond Hertz's), so its radius is the smaller: the refusal is
 * conservative (measured: a_Zener/a 0.72-1.0 on h = 0.02-0.25 r0); the
 * solver checks the computed force as well (solver_phys.c, thin_check).  When
 * Zener's ODE does not finish, the solver alone decides. */
#define THIN_DASHPOT_LAMBDA 1e4
static int thin_refuse(const struct anvil_params *p, const struct anvil_zener_sol *zs,
		       enum anvil_model m, struct anvil_err *err)
{
	double a;
	if (!isfinite(p->h))
		return ANVIL_OK;
	if (zs && isfinite(zs->alpha_max)) {
		a = sqrt(p->r0 * zs->alpha_max * p->T * p->V0);
	} else if (p->lambda_star >= THIN_DASHPOT_LAMBDA && p->alpha_star > 0) {
		/* Zener's ODE gave up (h = 1 nm: lambda* = 1e13; the layer's
		 * response then ran 14-29 s into "numerical failure"): the plate
		 * is his dashpot Z = 1/alpha*, and P = Z dw/dt <= Z v <= Z V0,
		 * its peak tending to Z V0 as lambda* grows (the impactor hardly
		 * slows before it); a from 0.9 of that keeps the refusal on the
		 * safe side */
		a = sqrt(p->r0 * p->k0 * pow(0.9 * p->V0 / p->alpha_star, 2.0 / 3.0));
	} else {
		return ANVIL_OK;
	}
	if (!(a > p->h))
		return ANVIL_OK;
	return anvil_err_set(err, ANVIL_EINVAL,
			     "%s: the contact radius a = %.3g mm (Zener's plate, the smallest estimate) exceeds h = %.3g mm (a/h = %.2g): Hertz's law for a half-space does not hold",
			     anvil_model_name(m), a * 1e3, p->h * 1e3, a / p->h);
}

/* The physical row of a wave model m (solver_phys.c's run_physical): no
 * approximation to choose, its own model is cheap.  A finite layer gets the
 * layer job (the solver adds the point load's correction when the bottom
 * reflection returns inside the window: causality) with the corrections
 * physical_cost prices (cached like the paper's responses); a half-space
 * needs no response at all (the radiation lag is beta dP/dt). */
static void physical_row(const struct est *e, const struct anvil_cache *cache, enum anvil_model m,
			 struct anvil_plan_row *r)
{
	struct anvil_err err;
	/* effects.waves = halfspace: no reflections, as for the paper's rows */
	int layer = m == ANVIL_MODEL_LAYER && isfinite(e->p.h) &&
		    e->pb->effects.waves != ANVIL_WAVES_HALFSPACE;
	/* Only the effects the scene calls for (as layer_auto does for the
	 * paper's contact): under effects.waves = auto, a layer whose
	 * reflections change P_max, t_s and R_f by less than the target allows
	 * (plan's bending estimate, 0 when they return after the contact) is
	 * the physical half-space, that estimate its model error. */
	double d_hs = layer && !late_reflection(e) ? e->bending : 0.0;
	/* (a late reflection stays with the layer job: the solver leaves its
	 * correction out by causality, exactly, and sees a longer contact) */
	int small = layer && d_hs > 0 && e->pb->effects.waves == ANVIL_WAVES_AUTO &&
		    ANVIL_PLAN_SAFETY * d_hs <= e->target;
	layer = layer && !small;
	double hs_cost = anvil_plan_impact_cost(anvil_wave_window(&e->hs, 0) * e->p.r0 / e->p.c2, e->hs.dt, 0, 0.0);
	enum anvil_cache_where where = ANVIL_CACHE_NONE;
	/* the Hertz radius as figures() has it, on the patch grid */
	double a = sqrt(e->p.r0 * anvil_hertz_alpha_max() * e->p.T * e->p.V0);
	double patch = anvil_plan_patch(fmin(1.0, a / e->p.r0));
	struct anvil_wave_job pj = e->lay;
	if (layer) {
		phys_band(e, 1, &pj);
		/* the wide band only where it is not refused: the solver would
		 * not have widened it there either (solver_phys.c) */
		if (anvil_wave_refuse(&e->p, e->pb->dt, m, &pj, anvil_wave_window(&pj, 0), pj.omega,
				      NULL)) {
			pj = e->lay;
			phys_band(e, 0, &pj);
		}
	}
	double cost = layer ? physical_cost(e, &pj, cache, patch, &where) : hs_cost;
	int run = r->run;
	enum anvil_plan_why off = r->off;
	memset(r, 0, sizeof *r);
	r->run = run;
	r->off = off;
	r->contact = ANVIL_CONTACT_PHYSICAL;
	row_set(r, layer ? ANVIL_METHOD_LAYER : ANVIL_METHOD_HALFSPACE,
		small ? ANVIL_WHY_SMALL_PLATE : ANVIL_WHY_PHYSICAL,
		small ? d_hs : 0.0, cost);
	r->cost_full = cost;
	r->job = layer ? pj : e->hs;
	r->job.patch = patch;
	r->cached = layer ? where : ANVIL_CACHE_NONE;
	row_fig(r, ANVIL_FIG_RADIATED);
	row_fig(r, ANVIL_FIG_A_HERTZ);
	if (layer)
		row_fig(r, ANVIL_FIG_T_REFLECT);
	/* a contact wider than the layer first: then no cost matters */
	r->status = layer ? thin_refuse(&e->p, e->z.at_lam, m, &err) : ANVIL_OK;
	if (!r->status)
		r->status = anvil_wave_refuse(&e->p, e->pb->dt, m, &r->job,
					      anvil_wave_window(&r->job, 0), r->job.omega, &err);
	if (r->status)
		snprintf(r->refusal, sizeof r->refusal, "%s", err.msg);
}

/* row[] holds the paper's contact as planned; with the physical one asked
 * for, it moves to paper[] (run only for BOTH) and row[] gets the physical
 * rows.  solver.scheme = paper is the paper's model: its contact alone. */
static void contact_rows(const struct anvil_problem *pb, const struct est *e,
			 const struct anvil_cache *cache, struct anvil_plan *pl)
{
	enum anvil_contact c = pb->effects.contact;
	if (c == ANVIL_CONTACT_AUTO || (unsigned)c >= ANVIL_CONTACT_COUNT)
		c = ANVIL_CONTACT_PHYSICAL; /* a problem not made by anvil_problem_init */
	if (pb->scheme == ANVIL_SCHEME_PAPER)
		c = ANVIL_CONTACT_PAPER;
	pl->contact = c;
	for (int m = ANVIL_MODEL_LAYER; m <= ANVIL_MODEL_HALFSPACE; m++) {
		pl->row[m].contact = ANVIL_CONTACT_PAPER;
		if (c == ANVIL_CONTACT_PAPER)
			continue;
		pl->paper[m] = pl->row[m];
		pl->paper[m].run = pl->row[m].run && c == ANVIL_CONTACT_BOTH;
		if (pl->row[m].run)
			pl->cost -= pl->row[m].cost;
		physical_row(e, cache, (enum anvil_model)m, &pl->row[m]);
		if (pl->row[m].run)
			pl->cost += pl->row[m].cost;
		if (pl->paper[m].run)
			pl->cost += pl->paper[m].cost;
	}
}

const struct anvil_plan_row *anvil_plan_row_of(const struct anvil_plan *pl, enum anvil_model m,
					       enum anvil_contact c)
{
	if ((unsigned)m >= ANVIL_MODEL_COUNT)
		return NULL;
	if (c == ANVIL_CONTACT_AUTO || pl->row[m].contact == c ||
	    m < ANVIL_MODEL_LAYER) /* hertz, zener: one row whatever the contact */
		return &pl->row[m];
	return pl->paper[m].contact == c ? &pl->paper[m] : NULL;
}
/* --- end contactB --- */

static void rows(const struct anvil_problem *pb, const struct est *e,
		 const struct anvil_cache *cache, struct anvil_plan *pl)
{
	for (int m = 0; m < ANVIL_MODEL_COUNT; m++) {
		struct anvil_plan_row *r = &pl->row[m];
		r->run = (pb->run >> m) & 1u;
		r->off = pb->models & (1u << m) ? ANVIL_WHY_EFFECT_OFF : ANVIL_WHY_NOT_ASKED;
		if (m == ANVIL_MODEL_HERTZ)
			row_set(r, ANVIL_METHOD_HERTZ, ANVIL_WHY_OWN_MODEL, 0.0, COST_HERTZ);
		else if (m == ANVIL_MODEL_ZENER)
			row_set(r, ANVIL_METHOD_ZENER, ANVIL_WHY_OWN_MODEL, 0.0, COST_ZENER);
		else if (m == ANVIL_MODEL_LAYER)
			layer_row(pb, e, cache, r);
		else
			halfspace_row(pb, e, r);
		row_job(e, cache, (enum anvil_model)m, r);
		if (m <= ANVIL_MODEL_ZENER)
			r->cost_full = r->cost;
		if (r->run)
			pl->cost += r->cost;
	}
}

/* ---- warnings ---- */

static void warn_add(struct anvil_plan *pl, enum anvil_plan_warn k, enum anvil_fig f0,
		     enum anvil_fig f1, enum anvil_fig f2)
{
	struct anvil_plan_warning *w = &pl->warn[pl->nwarn++];
	enum anvil_fig f[3] = { f0, f1, f2 };
	*w = (struct anvil_plan_warning){ .kind = k };
	for (int i = 0; i < 3; i++)
		if (f[i] != ANVIL_FIG_COUNT)
			w->fig[w->nfig++] = f[i];
}

static void warnings(const struct anvil_problem *pb, const struct est *e, struct anvil_plan *pl)
{
	const struct anvil_plan_row *lay = &pl->row[ANVIL_MODEL_LAYER];
	const enum anvil_fig none = ANVIL_FIG_COUNT;
	if (e->p.alpha_A > ANVIL_PLAN_ALPHA_A_MAX)
		warn_add(pl, ANVIL_WARN_SUPERSEISMIC, ANVIL_FIG_ALPHA_A, none, none);
	if (pl->row[ANVIL_MODEL_ZENER].run && !(e->p.h <= e->p.r0))
		warn_add(pl, ANVIL_WARN_PLATE_RANGE, ANVIL_FIG_H_R0, ANVIL_FIG_LAMBDA, none);
	if (lay->run && lay->method == ANVIL_METHOD_HALFSPACE && lay->why == ANVIL_WHY_FORCED &&
	    !lay->exact)
		warn_add(pl, ANVIL_WARN_NOT_EXACT, ANVIL_FIG_T_REFLECT, ANVIL_FIG_T_ZENER, none);
	if (pb->effects.field != ANVIL_FIELDMODE_OFF)
		warn_add(pl, ANVIL_WARN_FIELD, none, none, none);
}

/* The refusal warning, of the layer rows that run (after contact_rows):
 * the paper's row refused while the physical one runs said "will refuse"
 * of a row that answered (tungsten carbide, 100 kg at 100 m/s on
 * h = 0.1 r0 of steel: the paper's 2.6e8 steps). */
static void refuse_warning(struct anvil_plan *pl)
{
	const struct anvil_plan_row *r[2] = { &pl->row[ANVIL_MODEL_LAYER],
					       &pl->paper[ANVIL_MODEL_LAYER] };
	for (int i = 0; i < 2; i++)
		if (r[i]->run && r[i]->method == ANVIL_METHOD_LAYER && r[i]->status == ANVIL_ETOL) {
			warn_add(pl, ANVIL_WARN_REFUSE, ANVIL_FIG_STEPS, ANVIL_FIG_TERMS,
				 ANVIL_FIG_LAMBDA);
			return;
		}
}

int anvil_plan_make(const struct anvil_problem *pb, const struct anvil_cache *cache,
		    struct anvil_plan *pl, struct anvil_err *err)
{
	struct est e;
	memset(pl, 0, sizeof *pl);
	pl->pb = *pb;
	pl->waves = pb->effects.waves;
	pl->field = pb->effects.field;
	int st = estimate(&pl->pb, &e, err);
	if (st)
		return st;
	figures(&e, pl);
	rows(&pl->pb, &e, cache, pl);
	warnings(&pl->pb, &e, pl); /* of the layer model's choices: the paper's rows */
	contact_rows(&pl->pb, &e, cache, pl);
	refuse_warning(pl);
	/* the one verdict (verdict.h), quasi-static: a plan runs nothing */
	return anvil_verdict_make(&pl->pb, NULL, &pl->verdict, err);
}

/* ---- the key of a result ---- */

void anvil_plan_key(const struct anvil_problem *pb, enum anvil_model m, size_t nhist,
		    struct anvil_plan_key *k)
{
	memset(k, 0, sizeof *k); /* padding too: keys are compared with memcmp */
	k->p = pb->p;
	k->hh = pb->hh;
	k->dt = pb->dt;
	k->accuracy = (int)pb->accuracy;
	k->scheme = (int)pb->scheme;
	k->model = (int)m;
	k->effects.waves = pb->effects.waves;
	k->effects.plate = pb->effects.plate;
	k->effects.quasistatic = pb->effects.quasistatic;
	k->effects.field = pb->effects.field;
	k->effects.contact = pb->effects.contact;
	k->nhist = nhist;
	/* the row's contact, as contact_rows gives row[m] */
	k->contact = m < ANVIL_MODEL_LAYER ? ANVIL_CONTACT_AUTO
		     : pb->effects.contact == ANVIL_CONTACT_PAPER || pb->scheme == ANVIL_SCHEME_PAPER
			     ? ANVIL_CONTACT_PAPER
			     : ANVIL_CONTACT_PHYSICAL;
}

int anvil_plan_key_equal(const struct anvil_plan_key *a, const struct anvil_plan_key *b)
{
	return memcmp(a, b, sizeof *a) == 0;
}
