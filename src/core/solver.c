#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "green.h"
#include "halfspace.h"
#include "hertz.h"
#include "impact.h"
#include "params.h"
#include "solver.h"
#include "zener.h"

/* What each accuracy level spends.  Chosen from convergence studies on the
 * paper's ten cases (scripts/bench, tests/test_layer.c): each level's
 * outputs differ from the reference level's by well under its target.
 *   cycles: the layer correction's bandwidth omega_max times the contact
 *           time (dimensionless), so fast impacts get more frequencies;
 *   nsteps: time steps per Hertz contact time (the dt/2 pass doubles them);
 *   hs_tol: tolerance of the exact half-space response. */
static const struct level {
	double cycles, omega_min, hs_tol;
	size_t nsteps; /* per Hertz contact time */
} levels[ANVIL_ACC_COUNT] = {
	{ 60.0, 1.5, 1e-6, 100 },    /* draft */
	{ 120.0, 2.0, 1e-8, 400 },   /* normal */
	{ 240.0, 4.0, 1e-10, 1000 }, /* fine */
	{ 480.0, 8.0, 1e-12, 3000 }, /* reference */
};

#define CACHE_MAX 24
/* Beyond these a run is refused with ANVIL_ETOL and a message, instead of
 * grinding for minutes: very thin layers (lambda* >> 1) have contacts
 * thousands of Hertz times long, where the thin-plate model applies. */
#define MAX_STEPS 40000
#define MAX_TERMS 20000

/* A cached response: the exact half-space (per nu and tolerance) or a layer
 * correction (per h/r0, nu, level), each made once and shared by every
 * impact that needs it ("plan once, execute many times"). */
struct entry {
	int is_corr;
	double hh, nu, tol, omega, tau_end;
	enum anvil_accuracy acc;
	struct anvil_halfspace *hs;
	struct anvil_green *corr;
	unsigned long used;
};

struct anvil_solver {
	anvil_progress_fn progress;
	void *progress_ctx;
	struct entry cache[CACHE_MAX];
	int ncache;
	unsigned long clock;
};

struct anvil_solver *anvil_solver_alloc(void)
{
	return calloc(1, sizeof(struct anvil_solver));
}

static void entry_free(struct entry *e)
{
	anvil_halfspace_free(e->hs);
	anvil_green_free(e->corr);
	memset(e, 0, sizeof *e);
}

void anvil_solver_free(struct anvil_solver *s)
{
	if (!s)
		return;
	for (int i = 0; i < s->ncache; i++)
		entry_free(&s->cache[i]);
	free(s);
}

void anvil_solver_set_progress(struct anvil_solver *s, anvil_progress_fn fn,
			       void *ctx)
{
	s->progress = fn;
	s->progress_ctx = ctx;
}

static double wall_seconds(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A free cache slot (the least recently used one when full). */
static struct entry *slot(struct anvil_solver *s)
{
	if (s->ncache < CACHE_MAX)
		return &s->cache[s->ncache++];
	struct entry *old = &s->cache[0];
	for (int i = 1; i < CACHE_MAX; i++)
		if (s->cache[i].used < old->used)
			old = &s->cache[i];
	entry_free(old);
	return old;
}

static const struct anvil_halfspace *get_halfspace(struct anvil_solver *s, double nu,
						   double tol, struct anvil_err *err)
{
	for (int i = 0; i < s->ncache; i++) {
		struct entry *e = &s->cache[i];
		if (!e->is_corr && e->hs && e->nu == nu && e->tol <= tol) {
			e->used = ++s->clock;
			return e->hs;
		}
	}
	struct anvil_halfspace *hs = anvil_halfspace_alloc(nu, tol, err);
	if (!hs)
		return NULL;
	struct entry *e = slot(s);
	*e = (struct entry){ .nu = nu, .tol = tol, .hs = hs, .used = ++s->clock };
	return hs;
}

/* The layer correction covering [0, tau_end] with bandwidth omega (a cached
 * one with a longer window and at least that bandwidth will do, unless
 * exact: the coarse twin used for the error estimate must be what it says). */
static const struct anvil_green *get_corr(struct anvil_solver *s, double hh, double nu,
					  enum anvil_accuracy acc, double omega,
					  double tau_end, int exact, struct anvil_err *err)
{
	for (int i = 0; i < s->ncache; i++) {
		struct entry *e = &s->cache[i];
		if (e->is_corr && e->hh == hh && e->nu == nu && e->acc == acc &&
		    e->tau_end >= tau_end && (exact ? e->omega == omega : e->omega >= omega)) {
			e->used = ++s->clock;
			return e->corr;
		}
	}
	struct anvil_green_settings gs;
	anvil_green_settings(acc, &gs);
	gs.omega_max = omega;
	struct anvil_green *g = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, hh, nu, tau_end,
						  &gs, s->progress, s->progress_ctx, err);
	if (!g)
		return NULL;
	struct entry *e = slot(s);
	*e = (struct entry){ .is_corr = 1, .hh = hh, .nu = nu, .acc = acc, .omega = omega,
			     .tau_end = tau_end, .corr = g, .used = ++s->clock };
	return g;
}

/* The anvil's ramp response: exact half-space plus the layer correction. */
struct response {
	const struct anvil_halfspace *hs;
	const struct anvil_green *corr;
};

static int response_ramp(void *ctx, double tau, double *val)
{
	const struct response *rs = ctx;
	double a, b = 0;
	int st = anvil_halfspace_ramp(rs->hs, tau, &a, NULL);
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
	double hh, kappa, tau_s, omega; /* tau_s: contact time estimate */
	const struct level *lev;
	struct response rs;
	struct anvil_impact_opts io;
};

/* One coupled run with the window grown until the contact fits in it. */
static int waves_impact(struct anvil_solver *s, const struct anvil_scene *sc,
			const struct anvil_params *p, struct waves *wv, double omega,
			int exact, struct anvil_result *r, struct anvil_err *err)
{
	int st = ANVIL_ETOL;
	for (int attempt = 0; attempt < 6 && st == ANVIL_ETOL; attempt++) {
		double tau_end = 1.4 * wv->tau_s * (double)(1 << attempt) + 2.0;
		int need = isfinite(wv->hh) && 2.0 * wv->hh * wv->kappa < tau_end;
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
			wv->rs.corr = get_corr(s, wv->hh, p->nu, sc->accuracy, omega, tau_end, exact, err);
			if (!wv->rs.corr)
				return err ? err->status : ANVIL_ENUM;
		}
		enum anvil_model m = r->model;
		anvil_result_free(r);
		anvil_result_init(r, m);
		st = anvil_impact_run(p, response_ramp, &wv->rs, tau_end, &wv->io, r, err);
		if (st == ANVIL_ETOL && !isnan(r->ts))
			break;
	}
	return st;
}

static void waves_note(struct anvil_result *r, const struct anvil_params *p,
		       const struct waves *wv)
{
	if (r->model == ANVIL_MODEL_HALFSPACE || !isfinite(wv->hh))
		snprintf(r->note, sizeof r->note, "elastic half-space (exact response)");
	else if (!wv->rs.corr)
		snprintf(r->note, sizeof r->note,
			 "bottom reflection returns at 2h/c1 = %.3g us, after the contact (%.3g us): half-space response is exact here",
			 2.0 * p->h / p->c1 * 1e6, r->ts * 1e6);
}

/* Contact time estimate (s): Zener's plate model for a layer, Hertz for a
 * half-space.  When Zener's ODE cannot finish (lambda* >> 1, the impactor
 * then slows like exp(-t/(m1 alpha*)) = exp(-t/(lambda* T))), a few of
 * those decay times. */
static double contact_estimate(const struct anvil_params *p, int layer, double t_hertz)
{
	struct anvil_zener_sol zs;
	double lam = layer ? p->lambda_star : 0.0;
	if (anvil_zener_solve(lam, 1e-8, &zs, NULL) == ANVIL_OK && isfinite(zs.tau_s))
		return fmax(zs.tau_s * p->T, t_hertz);
	return fmax(3.0 * lam * p->T, t_hertz);
}

static int run_waves(struct anvil_solver *s, const struct anvil_scene *sc,
		     const struct anvil_params *p, size_t nhist, struct anvil_result *r,
		     struct anvil_err *err)
{
	struct waves wv = { .lev = &levels[sc->accuracy], .kappa = p->c2 / p->c1 };
	int layer = r->model == ANVIL_MODEL_LAYER && isfinite(p->h);
	double t_hertz = anvil_hertz_tau_s() * p->T;
	double ts = contact_estimate(p, layer, t_hertz);
	double tchar = fmin(ts, t_hertz); /* sets the bandwidth and the step */
	int st;
	wv.hh = layer ? p->h / p->r0 : INFINITY;
	wv.tau_s = ts * p->c2 / p->r0;
	wv.omega = fmax(wv.lev->omega_min, wv.lev->cycles / (tchar * p->c2 / p->r0));
	wv.io = (struct anvil_impact_opts){ .scheme = sc->scheme, .dt = sc->dt,
					    .dt_auto = tchar / (double)wv.lev->nsteps,
					    .max_steps = MAX_STEPS, .nhist = nhist };
	if (sc->dt > 0.25 * ts)
		return anvil_err_set(err, ANVIL_EINVAL,
				     "solver.dt = %.3g us is too long for a contact of about %.3g us (at most a quarter of it)",
				     sc->dt * 1e6, ts * 1e6);
	wv.rs.hs = get_halfspace(s, p->nu, wv.lev->hs_tol, err);
	if (!wv.rs.hs)
		return err ? err->status : ANVIL_ENUM;
	st = waves_impact(s, sc, p, &wv, wv.omega, 0, r, err);
	if (st)
		return st;
	if (wv.rs.corr) {
		struct anvil_result coarse;
		anvil_result_init(&coarse, r->model);
		wv.io.nhist = 0;
		st = waves_impact(s, sc, p, &wv, 0.5 * wv.omega, 1, &coarse, err);
		anvil_result_free(&coarse);
		if (st)
			return st;
		add_green_error(r, &coarse);
	}
	if (!layer) { /* Zener's plate parameter has no meaning for a half-space */
		r->lambda_star = 0.0;
		r->Rf_star = 1.0;
	}
	waves_note(r, p, &wv);
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
		st = run_waves(s, sc, &p, nhist, r, err);
		break;
	default:
		st = anvil_err_set(err, ANVIL_EINVAL, "unknown model %d", (int)m);
	}
	r->seconds = wall_seconds() - t0;
	return st;
}
