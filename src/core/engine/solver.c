#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cache.h"
#include "green.h"
#include "halfspace.h"
#include "hertz.h"
#include "impact.h"
#include "params.h"
#include "plan.h"
#include "solver.h"
#include "zener.h"

/* Beyond these a run is refused with ANVIL_ETOL and a message, instead of
 * grinding for minutes: very thin layers (lambda* >> 1) have contacts
 * thousands of Hertz times long, where the thin-plate model applies.
 * (The accuracy levels' settings are in plan.c, which prices them.) */
#define MAX_STEPS ANVIL_MAX_STEPS
#define MAX_TERMS ANVIL_MAX_TERMS
#define MAX_REFINE 2 /* bandwidth doublings when the target is missed */

struct anvil_solver {
	anvil_progress_fn progress;
	void *progress_ctx;
	/* the responses, each made once and shared by every impact that needs
	 * it ("plan once, execute many times") */
	struct anvil_cache *cache;
	unsigned long layer_computed;
	size_t layer_evals;
};

struct anvil_solver *anvil_solver_alloc(void)
{
	char dir[4096];
	struct anvil_solver *s = calloc(1, sizeof *s);
	if (s && !(s->cache = anvil_cache_alloc())) {
		free(s);
		return NULL;
	}
	/* A directory name too long to use leaves the cache in memory. */
	if (s)
		anvil_cache_set_dir(s->cache, anvil_cache_default_dir(dir, sizeof dir), NULL);
	return s;
}

void anvil_solver_free(struct anvil_solver *s)
{
	if (!s)
		return;
	anvil_cache_free(s->cache);
	free(s);
}

void anvil_solver_set_progress(struct anvil_solver *s, anvil_progress_fn fn,
			       void *ctx)
{
	s->progress = fn;
	s->progress_ctx = ctx;
}

int anvil_solver_set_cache_dir(struct anvil_solver *s, const char *dir, struct anvil_err *err)
{
	return anvil_cache_set_dir(s->cache, dir, err);
}

void anvil_solver_set_warn(struct anvil_solver *s, anvil_warn_fn fn, void *ctx)
{
	anvil_cache_set_warn(s->cache, fn, ctx);
}

const struct anvil_cache *anvil_solver_cache(const struct anvil_solver *s) { return s->cache; }

void anvil_solver_stats(const struct anvil_solver *s, struct anvil_solver_stats *st)
{
	st->layer_computed = s->layer_computed;
	st->layer_evals = s->layer_evals;
	anvil_cache_stats(s->cache, &st->cache);
}

static double wall_seconds(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The layer correction covering [0, tau_end] with bandwidth index
 * omega_idx (a cached one with a longer window and at least that bandwidth
 * will do, unless exact: the coarse twin used for the error estimate must
 * be what it says).  A new one gets its window rounded up to the cache's
 * grid, so that nearby scenes find it. */
static const struct anvil_green *get_corr(struct anvil_solver *s, double hh, double nu,
					  enum anvil_accuracy acc, int omega_idx,
					  double tau_end, int exact, struct anvil_err *err)
{
	struct anvil_cache_key key = { hh, nu, acc, omega_idx };
	const struct anvil_green *g = anvil_cache_find(s->cache, &key, tau_end, exact, NULL);
	if (g)
		return g;
	struct anvil_green_settings gs;
	anvil_green_settings(acc, &gs);
	gs.omega_max = anvil_cache_grid(omega_idx);
	double tau_q = anvil_cache_grid(anvil_cache_grid_up(tau_end));
	struct anvil_green *ng = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, hh, nu, tau_q,
						   &gs, s->progress, s->progress_ctx, err);
	if (!ng)
		return NULL;
	s->layer_computed++;
	s->layer_evals += anvil_green_evals(ng);
	return anvil_cache_add(s->cache, &key, ng);
}

/* The anvil's ramp response: exact half-space plus the layer correction,
 * or (quasi-static anvil, no hs) the static compliance times tau. */
struct response {
	const struct anvil_halfspace *hs;
	const struct anvil_green *corr;
	double stat;
};

static int response_ramp(void *ctx, double tau, double *val)
{
	const struct response *rs = ctx;
	double a, b = 0;
	int st = ANVIL_OK;
	if (rs->hs)
		st = anvil_halfspace_ramp(rs->hs, tau, &a, NULL);
	else
		a = rs->stat * fmax(tau, 0.0);
	if (!st && rs->corr)
		st = anvil_green_ramp(rs->corr, tau, &b);
	*val = a + b;
	return st;
}

/* Add |x - coarse| to each error estimate: the layer correction's own error,
 * measured by halving its bandwidth (conservative: it is the coarse twin's
 * error). */
static void add_green_error(struct anvil_result *r, const struct anvil_result *c)
{
	r->ts_err += fabs(r->ts - c->ts);
	r->tmax_err += fabs(r->tmax - c->tmax);
	r->Pmax_err += fabs(r->Pmax - c->Pmax);
	r->Vs_err += fabs(r->Vs - c->Vs);
	r->Rf_err += fabs(r->Rf - c->Rf);
	r->Ea_err += fabs(r->Ea - c->Ea);
}

/* Add a model's estimated relative deviation d from the row's full model
 * (the planner's) to each error estimate.  E_a = m1 (V0^2 - V_s^2)/2 moves
 * by m1 V_s^2 d when V_s moves by d V_s. */
static void add_model_error(struct anvil_result *r, const struct anvil_params *p, double d)
{
	r->ts_err += d * r->ts;
	r->tmax_err += d * r->tmax;
	r->Pmax_err += d * r->Pmax;
	r->Vs_err += d * fabs(r->Vs);
	r->Rf_err += d * fabs(r->Rf);
	r->Ea_err += d * p->m1 * fmax(r->Vs * r->Vs, d * p->V0 * p->V0);
}

/* The scene's accuracy target against the error estimates: P_max and t_s
 * relative, R_f relative to max(R_f, 0.1) (a nearly dead rebound has no
 * meaningful relative error). */
static int check_target(const struct anvil_result *r, enum anvil_accuracy acc,
			struct anvil_err *err)
{
	double tgt = anvil_accuracy_target(acc);
	double e_p = r->Pmax_err / r->Pmax, e_t = r->ts_err / r->ts;
	double e_r = r->Rf_err / fmax(fabs(r->Rf), 0.1);
	if (!isfinite(r->ts) || !isfinite(r->Pmax) || !isfinite(r->Rf) || !(r->ts > 0) ||
	    !(r->Pmax > 0) || r->Rf > 1.0 + fmax(10.0 * r->Rf_err, 1e-6))
		return anvil_err_set(err, ANVIL_ENUM,
				     "%s: the solution is unphysical (t_s = %.3g us, P_max = %.3g N, R_f = %.3g): the time stepping is unstable for this scene",
				     anvil_model_name(r->model), r->ts * 1e6, r->Pmax, r->Rf);
	if (e_p > tgt || e_t > tgt || e_r > tgt)
		return anvil_err_set(err, ANVIL_ETOL,
				     "%s: accuracy '%s' (%.0e) not reached: estimated errors P_max %.1e, t_s %.1e, R_f %.1e",
				     anvil_model_name(r->model), anvil_accuracy_name(acc), tgt, e_p, e_t, e_r);
	return ANVIL_OK;
}

struct waves {
	struct anvil_wave_job job;
	double kappa;
	double tau_end; /* the window of the last run */
	struct response rs;
	struct anvil_impact_opts io;
};

/* One coupled run with the window grown until the contact fits in it.
 * omega (for the refusal) and omega_idx (the cache's grid) describe the
 * layer correction's bandwidth. */
static int waves_impact(struct anvil_solver *s, const struct anvil_scene *sc,
			const struct anvil_params *p, struct waves *wv, double omega,
			int omega_idx, int exact, struct anvil_result *r, struct anvil_err *err)
{
	int st = ANVIL_ETOL;
	for (int attempt = 0; attempt < 6 && st == ANVIL_ETOL; attempt++) {
		double tau_end = anvil_wave_window(&wv->job, attempt);
		int need = isfinite(wv->job.hh) && 2.0 * wv->job.hh * wv->kappa < tau_end;
		double terms = omega * 2.0 * tau_end / M_PI;
		double dt = wv->io.dt > 0 ? wv->io.dt : wv->io.dt_auto;
		double steps = tau_end * p->r0 / p->c2 / dt;
		wv->rs.corr = NULL;
		if (steps > MAX_STEPS)
			return anvil_err_set(err, ANVIL_ETOL,
					     "%s: the contact lasts over %.3g us, more than %d steps of %.3g us; %s",
					     anvil_model_name(r->model), tau_end * p->r0 / p->c2 * 1e6,
					     MAX_STEPS, dt * 1e6,
					     p->lambda_star > 3 ? "the thin-plate model 'zener' applies here" :
					     "set a larger solver.dt or a coarser solver.accuracy");
		if (need && terms > MAX_TERMS)
			return anvil_err_set(err, ANVIL_ETOL,
					     "layer: the contact lasts over %.3g us (lambda* = %.3g), too long for the transform solver (%.0f terms); the thin-plate model 'zener' applies here",
					     tau_end * p->r0 / p->c2 * 1e6, p->lambda_star, terms);
		if (need) {
			wv->rs.corr = get_corr(s, wv->job.hh, p->nu, sc->accuracy, omega_idx, tau_end,
					       exact, err);
			if (!wv->rs.corr)
				return err ? err->status : ANVIL_ENUM;
		}
		enum anvil_model m = r->model;
		anvil_result_free(r);
		anvil_result_init(r, m);
		st = anvil_impact_run(p, response_ramp, &wv->rs, tau_end, &wv->io, r, err);
		wv->tau_end = tau_end;
		if (st == ANVIL_ETOL && !isnan(r->ts))
			break;
	}
	return st;
}

/* The coupled run for the anvil computed by method (LAYER, HALFSPACE or
 * STATIC), with the layer correction's error estimate when it is used. */
static int run_waves(struct anvil_solver *s, const struct anvil_scene *sc,
		     const struct anvil_params *p, enum anvil_method method, size_t nhist,
		     struct anvil_result *r, int *used_corr, struct anvil_err *err)
{
	struct waves wv = { .kappa = p->c2 / p->c1 };
	double ts_static = 0, pmax;
	if (method == ANVIL_METHOD_STATIC && anvil_plan_static(p, &ts_static, &pmax))
		return anvil_err_set(err, ANVIL_ENUM, "static: the contact time estimate failed");
	anvil_wave_job(p, sc, method == ANVIL_METHOD_LAYER, ts_static, &wv.job);
	wv.io = (struct anvil_impact_opts){ .scheme = sc->scheme, .dt = sc->dt,
					    .dt_auto = wv.job.dt, .max_steps = MAX_STEPS,
					    .nhist = nhist };
	if (sc->dt > 0.25 * wv.job.ts)
		return anvil_err_set(err, ANVIL_EINVAL,
				     "solver.dt = %.3g us is too long for a contact of about %.3g us (at most a quarter of it)",
				     sc->dt * 1e6, wv.job.ts * 1e6);
	if (method == ANVIL_METHOD_STATIC) {
		wv.rs.stat = anvil_halfspace_static(p->nu);
	} else if (!(wv.rs.hs = anvil_cache_halfspace(s->cache, p->nu, wv.job.hs_tol, err))) {
		return err ? err->status : ANVIL_ENUM;
	}
	/* The layer correction's error is measured by halving its bandwidth;
	 * when that estimate misses the target, the bandwidth doubles (twice at
	 * most): convergence in it is fast, the estimate conservative. */
	int st = ANVIL_OK;
	for (int refine = 0; refine <= MAX_REFINE; refine++) {
		double omega = wv.job.omega * (double)(1 << refine);
		int idx = wv.job.omega_idx + refine * ANVIL_CACHE_STEPS;
		wv.io.nhist = nhist;
		st = waves_impact(s, sc, p, &wv, omega, idx, 0, r, err);
		*used_corr = wv.rs.corr != NULL;
		if (st || !wv.rs.corr)
			return st;
		struct anvil_result coarse;
		anvil_result_init(&coarse, r->model);
		wv.io.nhist = 0;
		st = waves_impact(s, sc, p, &wv, 0.5 * omega, idx - ANVIL_CACHE_STEPS, 1, &coarse, err);
		if (!st)
			add_green_error(r, &coarse);
		anvil_result_free(&coarse);
		if (st || sc->scheme == ANVIL_SCHEME_PAPER || check_target(r, sc->accuracy, NULL) == ANVIL_OK)
			break;
		/* a refinement the solver would refuse is not tried: the result
		 * stands, and run_anvil says it missed the target */
		if (4.0 * omega * wv.tau_end / M_PI > MAX_TERMS)
			break;
	}
	return st;
}

/* What the result says about how it was computed. */
static void waves_note(struct anvil_result *r, const struct anvil_params *p,
		       const struct anvil_plan_row *row, enum anvil_method method, int corr)
{
	double t_refl = 2.0 * p->h / p->c1 * 1e6;
	if (method == ANVIL_METHOD_STATIC)
		snprintf(r->note, sizeof r->note,
			 "quasi-static anvil (Hertz + static patch compliance): waves would change the results by ~%.2g%%, within the target; errors include it",
			 100 * row->model_err);
	else if (r->model == ANVIL_MODEL_HALFSPACE || !isfinite(p->h))
		snprintf(r->note, sizeof r->note, "elastic half-space (exact response)");
	else if (method == ANVIL_METHOD_HALFSPACE && row->why == ANVIL_WHY_SMALL_PLATE)
		snprintf(r->note, sizeof r->note,
			 "half-space response: reflections return at 2h/c1 = %.3g us, during the contact, but change the results by ~%.2g%%, within the target; errors include it",
			 t_refl, 100 * row->model_err);
	else if (method == ANVIL_METHOD_HALFSPACE && r->ts > 2.0 * p->h / p->c1)
		snprintf(r->note, sizeof r->note,
			 "half-space response (effects.waves = halfspace): reflections return at 2h/c1 = %.3g us, during the contact: not the layer",
			 t_refl);
	else if (!corr)
		snprintf(r->note, sizeof r->note,
			 "bottom reflection returns at 2h/c1 = %.3g us, after the contact (%.3g us): half-space response is exact here",
			 t_refl, r->ts * 1e6);
}

/* How the scene wants row m (LAYER or HALFSPACE) computed: the planner's
 * choice with waves = auto or a forced half-space, else the row's own
 * model.  An explicit request for a row [effects] switches off is run as
 * the row's own model. */
static int choose(const struct anvil_scene *sc, enum anvil_model m, const struct anvil_params *p,
		  struct anvil_plan_row *row, struct anvil_err *err)
{
	int layer = m == ANVIL_MODEL_LAYER && isfinite(p->h);
	*row = (struct anvil_plan_row){ .exact = 1, .why = ANVIL_WHY_OWN_MODEL,
					.method = layer ? ANVIL_METHOD_LAYER : ANVIL_METHOD_HALFSPACE };
	int planned = (sc->effects.waves == ANVIL_WAVES_AUTO && sc->scheme != ANVIL_SCHEME_PAPER) ||
		      (sc->effects.waves == ANVIL_WAVES_HALFSPACE && layer);
	if (!planned)
		return ANVIL_OK;
	struct anvil_plan pl;
	int st = anvil_plan_make(sc, NULL, &pl, err);
	if (!st)
		*row = pl.row[m];
	return st;
}

static int run_anvil(struct anvil_solver *s, const struct anvil_scene *sc,
		     const struct anvil_params *p, size_t nhist, struct anvil_result *r,
		     struct anvil_err *err)
{
	struct anvil_plan_row row;
	int st = choose(sc, r->model, p, &row, err);
	if (st)
		return st;
	enum anvil_method method = row.method;
	int corr = 0;
	st = run_waves(s, sc, p, method, nhist, r, &corr, err);
	/* Causality made the half-space exact only if the contact really ended
	 * before the reflection came back: else the layer after all. */
	if (!st && row.why == ANVIL_WHY_LATE_REFLECT && !(r->ts < 2.0 * p->h / p->c1)) {
		row = (struct anvil_plan_row){ .exact = 1, .method = ANVIL_METHOD_LAYER };
		method = ANVIL_METHOD_LAYER;
		st = run_waves(s, sc, p, method, nhist, r, &corr, err);
	}
	if (st)
		return st;
	if (!row.exact && row.why != ANVIL_WHY_FORCED)
		add_model_error(r, p, row.model_err);
	if (r->model == ANVIL_MODEL_HALFSPACE || !isfinite(p->h)) {
		/* Zener's plate parameter has no meaning for a half-space */
		r->lambda_star = 0.0;
		r->Rf_star = 1.0;
	}
	waves_note(r, p, &row, method, corr);
	return sc->scheme == ANVIL_SCHEME_PAPER ? ANVIL_OK : check_target(r, sc->accuracy, err);
}

int anvil_solver_run(struct anvil_solver *s, const struct anvil_scene *sc,
		     enum anvil_model m, size_t nhist, struct anvil_result *r,
		     struct anvil_err *err)
{
	struct anvil_params p;
	double t0 = wall_seconds();
	anvil_result_init(r, m);
	int st = anvil_params_init(&p, sc, err);
	if (st)
		return st;
	switch (m) {
	case ANVIL_MODEL_HERTZ:
		st = anvil_hertz_run(&p, nhist, r, err);
		break;
	case ANVIL_MODEL_ZENER:
		st = anvil_zener_run(&p, nhist, r, err);
		break;
	case ANVIL_MODEL_LAYER:
	case ANVIL_MODEL_HALFSPACE:
		st = run_anvil(s, sc, &p, nhist, r, err);
		break;
	default:
		st = anvil_err_set(err, ANVIL_EINVAL, "unknown model %d", (int)m);
	}
	r->seconds = wall_seconds() - t0;
	return st;
}
