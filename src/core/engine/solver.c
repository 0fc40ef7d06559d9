#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <time.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "cache.h"
#include "green.h"
#include "halfspace.h"
#include "hertz.h"
#include "impact.h"
#include "plate.h"
#include "plan.h"
#include "radiation.h"
#include "solver.h"
#include "zener.h"

/* The solver executes a plan's row (plan.h): every decision (method, job,
 * fallback, refusal) is the planner's; what is left here is the doing,
 * and the checks only a computed result allows (the window long enough,
 * the target met, the contact over before the reflection). */

struct anvil_solver {
	anvil_progress_fn progress;
	void *progress_ctx;
	/* the responses, each made once and shared by every impact that needs
	 * it ("plan once, execute many times") */
	struct anvil_cache *cache;
	/* the plate's K(t) table, kept from one response to the next (plate.h):
	 * a long window's correction, its twin and its patch's share it */
	struct anvil_plate_memo *plate;
	unsigned long layer_computed;
	size_t layer_evals;
};

struct anvil_solver *anvil_solver_alloc(void)
{
	char dir[4096];
	struct anvil_solver *s = calloc(1, sizeof *s);
	if (s && (!(s->cache = anvil_cache_alloc()) || !(s->plate = anvil_plate_memo_alloc()))) {
		anvil_cache_free(s->cache);
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
	anvil_plate_memo_free(s->plate);
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

/* The responses a run holds (cache.h: never evicted until given back):
 * the half-space and, per window tried (ANVIL_MAX_ATTEMPTS) and bandwidth
 * (refine_max + 1), a response and its twin. */
#define HELD_MAX (1 + 2 * ANVIL_MAX_ATTEMPTS * (ANVIL_MAX_REFINE + 1))

struct held {
	const void *p[HELD_MAX];
	int n;
};

static const void *held_add(struct held *h, const void *p)
{
	if (p && h->n < HELD_MAX)
		h->p[h->n++] = p;
	return p;
}

/* Give back one hold on p (a response no longer used), if held. */
static void held_drop(struct anvil_cache *c, struct held *h, const void *p)
{
	for (int i = h->n - 1; p && i >= 0; i--)
		if (h->p[i] == p) {
			anvil_cache_release(c, p);
			h->p[i] = h->p[--h->n];
			return;
		}
}

static void held_release(struct anvil_cache *c, struct held *h)
{
	for (int i = 0; i < h->n; i++)
		anvil_cache_release(c, h->p[i]);
	h->n = 0;
}

/* The layer correction of key, made with exactly the key's window and
 * bandwidth when the cache does not have it, held for this run.  A
 * response is made with its twin (the same spectrum's first terms, half
 * the bandwidth) and both are kept: the twin of key (idx, twin 1) is that
 * of the main response at idx + ANVIL_CACHE_STEPS, made again when it is
 * missing (the main one then kept too, when the cache lacks it). */
static const struct anvil_green *get_corr(struct anvil_solver *s, const struct anvil_cache_key *key,
					  struct held *held, struct anvil_err *err)
{
	const struct anvil_green *g = anvil_cache_find(s->cache, key, NULL);
	if (g)
		return held_add(held, g);
	struct anvil_cache_key mk = *key, tk = *key;
	if (key->twin)
		mk.omega_idx += ANVIL_CACHE_STEPS;
	mk.twin = 0;
	tk.omega_idx = mk.omega_idx - ANVIL_CACHE_STEPS;
	tk.twin = 1;
	struct anvil_green_settings gs;
	anvil_green_settings(key->acc, &gs);
	gs.omega_max = anvil_cache_grid(mk.omega_idx);
	gs.plate = s->plate;
	struct anvil_green *tw = NULL;
	struct anvil_green *ng = anvil_green_alloc_twin(ANVIL_GREEN_LAYER_CORRECTION, key->hh, key->nu,
							anvil_cache_grid(key->tau_idx), &gs, s->progress,
							s->progress_ctx, &tw, err);
	if (!ng)
		return NULL;
	s->layer_computed++;
	s->layer_evals += anvil_green_evals(ng);
	const struct anvil_green *gm = NULL, *gt = NULL;
	if (key->twin && anvil_cache_probe(s->cache, &mk) == ANVIL_CACHE_MEMORY)
		anvil_green_free(ng); /* there already (the same bits) */
	else
		gm = held_add(held, anvil_cache_add(s->cache, &mk, ng));
	if (anvil_cache_probe(s->cache, &tk) == ANVIL_CACHE_MEMORY)
		anvil_green_free(tw);
	else
		gt = held_add(held, anvil_cache_add(s->cache, &tk, tw));
	g = key->twin ? gt : gm;
	if (!g)
		anvil_err_set(err, ANVIL_ENOMEM, "cache: every slot is held");
	return g;
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

/* The errors of the layer correction's band, from its twin (run_waves).
 *
 * Each output's is its change |x - coarse| when the bandwidth is halved
 * (conservative: that is the coarse twin's error), and for P_max and t_s
 * at least the amplitude of that change, not one sample of it.  The main
 * response (band omega) differs from the true one by its content above
 * omega; the twin (omega/2) from the main one by the content in
 * [omega/2, omega].  In the force and the approach both differences
 * oscillate (the layer's thickness resonances, the band's Gibbs ringing):
 * the twin's difference at t_max (or t_s) is one sample of its
 * oscillation, and the main error's own phase there is unrelated to it.
 * On long contacts on pmma (issue 11) the main's true P_max error was up
 * to 4.5 times the twin's change: 1.6e-3 N against 3.6e-4 N on tungsten
 * carbide on 1.94 r0, where the difference's amplitude near the peak is
 * 5.0e-3 N.  The twin measures that amplitude without luck over one
 * period of the difference's slowest part (frequency omega/2, period
 * 4 pi/omega): the main error is taken to be within it (the band
 * converges), as the change alone took it to be within the change.
 *   P_max: max |P_main - P_twin| within 2 pi/omega of t_max (a period
 * centred on the peak); |max P - max Q| <= max |P - Q| there.
 *   t_s: the contact ends where alpha = 0, so an error da in the approach
 * moves t_s by da / |alpha'(t_s)|.  Over the period before t_s the
 * histories are compared sample by sample; each history's sample i is at
 * i t_s / (n - 1) of its own t_s, so the comparison is aligned at the end
 * (both alpha exactly 0 there) and near it shows da(t) - da(t_s), the
 * oscillation about the end value, which |t_s - coarse t_s| (= da(t_s) /
 * |alpha'|) already counts: the two added bound |da(t)| / |alpha'| over
 * the period.  Near t_max the same alignment moves P by |P'| dt_s, P'
 * small there.  Index by index, no interpolation error is added.
 * band: omega in 1/s. */
static double hist_window_diff(const struct anvil_result *a, const struct anvil_result *b, int alpha,
			       double lo, double hi)
{
	size_t n = a->hist.n;
	double d = 0;
	if (n < 2 || b->hist.n != n)
		return 0;
	const double *x = alpha ? a->hist.alpha : a->hist.P, *y = alpha ? b->hist.alpha : b->hist.P;
	for (size_t i = 0; i < n; i++)
		if (a->hist.t[i] >= lo && a->hist.t[i] <= hi)
			d = fmax(d, fabs(x[i] - y[i]));
	return d;
}

static void add_green_error(struct anvil_result *r, const struct anvil_result *c, double band)
{
	double per = 4.0 * M_PI / band, dP = 0, dts = 0;
	size_t n = r->hist.n;
	if (n >= 2 && c->hist.n == n) {
		dP = hist_window_diff(r, c, 0, r->tmax.val - 0.5 * per, r->tmax.val + 0.5 * per);
		/* |alpha'| at the end: the last interval's slope (alpha = 0 at t_s) */
		double slope = fabs(r->hist.alpha[n - 2]) / (r->hist.t[n - 1] - r->hist.t[n - 2]);
		double da = hist_window_diff(r, c, 1, r->ts.val - per, r->ts.val);
		dts = da > 0 ? da / slope : 0; /* a grazing end (slope 0) is no estimate */
	}
	r->ts.err += fabs(r->ts.val - c->ts.val) + dts;
	r->tmax.err += fabs(r->tmax.val - c->tmax.val);
	r->Pmax.err += fmax(fabs(r->Pmax.val - c->Pmax.val), dP);
	r->Vs.err += fabs(r->Vs.val - c->Vs.val);
	r->Rf.err += fabs(r->Rf.val - c->Rf.val);
	r->Ea.err += fabs(r->Ea.val - c->Ea.val);
}

/* The history samples of a run whose error is measured (add_green_error):
 * a spacing of at most half the step dt (the finer pass's, what the history
 * is resampled from) over the first window (anvil_wave_window), coarser
 * only when the contact outlasts it (add_green_error); a multiple of the caller's nhist - 1
 * plus one, so that the caller's samples are every k-th of them
 * (history_decimate). */
static size_t err_nhist(const struct anvil_problem *pb, const struct anvil_wave_job *j,
			size_t nhist)
{
	double t0 = anvil_wave_window(j, 0) * pb->p.r0 / pb->p.c2;
	double dt = pb->dt > 0 ? pb->dt : j->dt;
	size_t want = (size_t)fmin(ceil(2.0 * t0 / dt), 4.0 * ANVIL_MAX_STEPS) + 1;
	if (nhist < 2)
		return want;
	size_t k = (want - 1 + nhist - 2) / (nhist - 1);
	return k * (nhist - 1) + 1;
}

/* Keep every k-th sample of r's history, k = (n - 1) / (nhist - 1): the
 * caller's nhist samples over [0, t_s] (none when nhist < 2).  The times
 * are the ones impact.c's resampling gives, to rounding. */
static int history_decimate(struct anvil_result *r, size_t nhist)
{
	struct anvil_history h = { 0 }, *o = &r->hist;
	if (nhist < 2 || o->n < 2) {
		anvil_result_free(r);
		return ANVIL_OK;
	}
	size_t k = (o->n - 1) / (nhist - 1);
	if (k == 1 && o->n == nhist)
		return ANVIL_OK;
	if (anvil_history_alloc(&h, nhist))
		return ANVIL_ENOMEM;
	for (size_t i = 0; i < nhist; i++) {
		size_t m = i * k;
		h.t[i] = o->t[m];
		h.P[i] = o->P[m];
		h.v[i] = o->v[m];
		h.W[i] = o->W[m];
		h.w[i] = o->w[m];
		h.alpha[i] = o->alpha[m];
	}
	anvil_result_free(r);
	r->hist = h;
	return ANVIL_OK;
}

/* Add a model's estimated relative deviation d from the row's full model
 * (the planner's) to each error estimate.  E_a = m1 (V0^2 - V_s^2)/2 moves
 * by m1 V_s^2 d when V_s moves by d V_s. */
static void add_model_error(struct anvil_result *r, const struct anvil_params *p, double d)
{
	r->ts.err += d * r->ts.val;
	r->tmax.err += d * r->tmax.val;
	r->Pmax.err += d * r->Pmax.val;
	r->Vs.err += d * fabs(r->Vs.val);
	r->Rf.err += d * fabs(r->Rf.val);
	r->Ea.err += d * p->m1 * fmax(r->Vs.val * r->Vs.val, d * p->V0 * p->V0);
}

/* t_max is the arg-max of a flat peak: an error e(t) in the force, small
 * as it is (P_max's estimate dP), moves it by much more than the time
 * step.  Near the peak P = P_max - c (t - t_max)^2 / 2, c = |P''|; P + e
 * peaks where c (t - t_max) = e', so an error of slope e' moves t_max by
 * e'/c.  The slope is dP times the error's frequency: the layer
 * correction's error (a band cut at omega) oscillates at the band's top,
 * omega c2/r0 (band, 1/s; the twin's difference alone, at half of it, was
 * 3-6 times too small on thick layers: issue 11); without the correction
 * (band 0) the error is smooth on the pulse's own time scale T =
 * sqrt(P_max / c) (the half-sine's t_s/pi).  Whatever its shape, an error
 * |e| <= dP cannot move the peak beyond where P has fallen by 2 dP: the
 * cap 2 sqrt(dP / c).  t_max's estimate is at least that shift, once every
 * term of P_max's is in. */
static void tmax_from_pmax(struct anvil_result *r, double band)
{
	double c = r->Pmax_curv, dP = r->Pmax.err;
	if (!(c > 0) || !(dP > 0) || !(r->Pmax.val > 0))
		return;
	double rate = fmax(band, sqrt(c / r->Pmax.val)); /* 1/s */
	double shift = fmin(dP * rate / c, 2.0 * sqrt(dP / c));
	r->tmax.err = fmax(r->tmax.err, shift);
}

/* The accuracy target against the error estimates: P_max and t_s
 * relative, R_f relative to max(R_f, 0.1) (a nearly dead rebound has no
 * meaningful relative error).  ANVIL_WTOL (a warning: the values stand)
 * when it is missed, ANVIL_ENUM for an unphysical solution. */
static int check_target(const struct anvil_result *r, enum anvil_accuracy acc,
			struct anvil_err *err)
{
	double tgt = anvil_accuracy_target(acc);
	double e_p = r->Pmax.err / r->Pmax.val, e_t = r->ts.err / r->ts.val;
	double e_r = r->Rf.err / fmax(fabs(r->Rf.val), 0.1);
	if (!isfinite(r->ts.val) || !isfinite(r->Pmax.val) || !isfinite(r->Rf.val) || !(r->ts.val > 0) ||
	    !(r->Pmax.val > 0) || r->Rf.val > 1.0 + fmax(10.0 * r->Rf.err, 1e-6))
		return anvil_err_set(err, ANVIL_ENUM,
				     "%s: the solution is unphysical (t_s = %.3g us, P_max = %.3g N, R_f = %.3g): the time stepping is unstable for this scene",
				     anvil_model_name(r->model), r->ts.val * 1e6, r->Pmax.val, r->Rf.val);
	if (e_p > tgt || e_t > tgt || e_r > tgt)
		return anvil_err_set(err, ANVIL_WTOL,
				     "%s: accuracy '%s' (%.0e) not reached: estimated errors P_max %.1e, t_s %.1e, R_f %.1e",
				     anvil_model_name(r->model), anvil_accuracy_name(acc), tgt, e_p, e_t, e_r);
	return ANVIL_OK;
}

/* The growing step (impact.h): past ANVIL_GROW_AFTER of the level's Hertz
 * pulses (their nsteps steps each), where the force is as smooth at the
 * doubled step as the Hertz pulse is at the level's: grow_eta = (pi /
 * nsteps)^2, the pulse's |P''| dt^2 / P_max. */
static void grow_opts(struct anvil_impact_opts *io, const struct anvil_problem *pb,
		      const struct anvil_wave_job *j)
{
	/* in time: ANVIL_GROW_AFTER times the level's pulse (nsteps of the
	 * automatic step), in steps of the one taken (solver.dt may set it) */
	io->grow_after = pb->dt > 0 ? (size_t)ceil(ANVIL_GROW_AFTER * j->nsteps * j->dt / pb->dt)
				    : (size_t)(ANVIL_GROW_AFTER * j->nsteps);
	io->grow_eta = (M_PI / j->nsteps) * (M_PI / j->nsteps);
}

/* One wave run in progress: the plan's problem and job, and what it holds. */
struct waves {
	const struct anvil_problem *pb;
	const struct anvil_wave_job *job;
	double tau_end; /* the window of the last run */
	struct response rs;
	struct anvil_impact_opts io;
	struct held held;
};

/* One coupled run with the window grown until the contact fits in it, the
 * layer correction (when the reflection falls in the window) at bandwidth
 * omega (grid index omega_idx).  Every window is checked against the
 * plan's one refusal rule. */
static int waves_impact(struct anvil_solver *s, struct waves *wv, double omega, int omega_idx,
			int twin, struct anvil_result *r, struct anvil_err *err)
{
	const struct anvil_params *p = &wv->pb->p;
	int st = ANVIL_ETOL;
	for (int attempt = 0; attempt < wv->job->attempts && st == ANVIL_ETOL; attempt++) {
		double tau_end = anvil_wave_window(wv->job, attempt);
		/* the shorter window's response is done with: held, the responses
		 * of every window and bandwidth would outnumber the cache's slots */
		held_drop(s->cache, &wv->held, wv->rs.corr);
		wv->rs.corr = NULL;
		st = anvil_wave_refuse(p, wv->pb->dt, r->model, wv->job, tau_end, omega, err);
		if (st)
			return st;
		if (anvil_wave_needs_corr(p, wv->job, tau_end)) {
			struct anvil_cache_key key = { wv->job->hh, p->nu, wv->pb->accuracy, omega_idx,
						       anvil_wave_tau_idx(wv->job, tau_end), twin,
						       ANVIL_CACHE_LOAD_R0, 0.0 };
			wv->rs.corr = get_corr(s, &key, &wv->held, err);
			if (!wv->rs.corr)
				return err ? err->status : ANVIL_ENUM;
		}
		enum anvil_model m = r->model;
		anvil_result_free(r);
		anvil_result_init(r, m);
		/* the last window, or the last the rule lets run: at rest at its
		 * end rather than refused (impact.h, rest_last) */
		wv->io.rest_last = attempt + 1 >= wv->job->attempts ||
				   anvil_wave_refuse(p, wv->pb->dt, r->model, wv->job,
						     anvil_wave_window(wv->job, attempt + 1), omega, NULL);
		st = anvil_impact_run(p, response_ramp, &wv->rs, tau_end, &wv->io, r, err);
		wv->tau_end = tau_end;
		if (st == ANVIL_ETOL && !isnan(r->ts.val))
			break;
	}
	return st;
}

/* The sub-resolution merge, the contact budget and the rest state of the
 * coupled runs (below, with the physical contact's). */
static void merge_opts(struct anvil_impact_opts *io, const struct anvil_problem *pb,
		       const struct anvil_wave_job *j);

/* The coupled run of job j (the anvil's response: static, half-space, or
 * half-space plus layer correction), with the layer correction's error
 * estimate when it is used. */
static int run_waves(struct anvil_solver *s, const struct anvil_problem *pb,
		     const struct anvil_wave_job *j, int method, size_t nhist,
		     struct anvil_result *r, int *used_corr, double *band, struct anvil_err *err)
{
	struct waves wv = { .pb = pb, .job = j };
	wv.io = (struct anvil_impact_opts){ .scheme = pb->scheme, .dt = pb->dt, .dt_auto = j->dt,
					    .max_steps = ANVIL_MAX_STEPS, .nhist = nhist };
	merge_opts(&wv.io, pb, j); /* the paper's contact as the physical (the paper's scheme: none) */
	int st = ANVIL_OK;
	if (method == ANVIL_METHOD_STATIC)
		wv.rs.stat = j->stat;
	else if (!(wv.rs.hs = held_add(&wv.held, anvil_cache_halfspace(s->cache, pb->p.nu,
									 j->hs_tol, err))))
		return err ? err->status : ANVIL_ENUM;
	/* The layer correction's error is measured by halving its bandwidth
	 * (the twin: the same spectrum's first half, made with the response);
	 * when that estimate misses the target, the bandwidth doubles (up to
	 * refine_max times): convergence in it is fast, the estimate
	 * conservative. */
	size_t n_err = method == ANVIL_METHOD_LAYER ? err_nhist(pb, j, nhist) : nhist;
	for (int refine = 0; refine <= j->refine_max; refine++) {
		double omega = j->omega * (double)(1 << refine);
		int idx = j->omega_idx + refine * ANVIL_CACHE_STEPS;
		wv.io.nhist = n_err;
		wv.io.rest_at = 0;
		st = waves_impact(s, &wv, omega, idx, 0, r, err);
		*used_corr = wv.rs.corr != NULL;
		*band = *used_corr ? anvil_cache_grid(idx) * pb->p.c2 / pb->p.r0 : 0.0;
		if (st || !wv.rs.corr)
			break;
		struct anvil_result coarse;
		anvil_result_init(&coarse, r->model);
		wv.io.rest_at = r->rest_bound > 0 ? r->ts.val : 0.0; /* the twin at the rest's time */
		st = waves_impact(s, &wv, 0.5 * omega, idx - ANVIL_CACHE_STEPS, 1, &coarse, err);
		if (!st)
			add_green_error(r, &coarse, *band);
		anvil_result_free(&coarse);
		if (st || refine >= j->refine_max || check_target(r, pb->accuracy, NULL) == ANVIL_OK)
			break;
		/* a refinement the rule would refuse is not tried: the result
		 * stands, and run_anvil says it missed the target */
		if (anvil_wave_refuse(&pb->p, pb->dt, r->model, j, wv.tau_end, 2.0 * omega, NULL))
			break;
	}
	held_release(s->cache, &wv.held);
	if (n_err != nhist && history_decimate(r, nhist) && !st)
		st = anvil_err_set(err, ANVIL_ENOMEM, "history: %s", anvil_strerror(ANVIL_ENOMEM));
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
	else if (method == ANVIL_METHOD_HALFSPACE && r->ts.val > 2.0 * p->h / p->c1)
		snprintf(r->note, sizeof r->note,
			 "half-space response (effects.waves = halfspace): reflections return at 2h/c1 = %.3g us, during the contact: not the layer",
			 t_refl);
	else if (!corr)
		snprintf(r->note, sizeof r->note,
			 "bottom reflection returns at 2h/c1 = %.3g us, after the contact (%.3g us): half-space response is exact here",
			 t_refl, r->ts.val * 1e6);
}

/* The rest state (impact.h, rest_tol) in the note: when, and the bound. */
static void rest_note(struct anvil_result *r)
{
	size_t len = strlen(r->note);
	if (!(r->rest_bound > 0) || len >= sizeof r->note)
		return;
	snprintf(r->note + len, sizeof r->note - len,
		 "%scame to rest on the plate: R_f < %.2g (the rebound still possible from t_s = %.4g us; the contact does not end, the plate carries the momentum off)",
		 len ? "; " : "", r->rest_bound, r->ts.val * 1e6);
}

/* Repeated contacts (impact.h) in the note: how many, and the first few's
 * times. */
static void contacts_note(struct anvil_result *r)
{
	size_t len = strlen(r->note), nc = r->ncontacts;
	if (nc < 2)
		return;
	len += (size_t)snprintf(r->note + len, len < sizeof r->note ? sizeof r->note - len : 0,
			       "%s%zu contacts (us):", len ? "; " : "", nc);
	for (size_t i = 0; i < nc && i < 4 && len < sizeof r->note; i++)
		len += (size_t)snprintf(r->note + len, sizeof r->note - len, " %.4g-%.4g",
				       r->contact_on[i] * 1e6, r->contact_off[i] * 1e6);
	if (nc > 4 && len < sizeof r->note)
		snprintf(r->note + len, sizeof r->note - len, " ... -%.4g", r->ts.val * 1e6);
}

/* --- contactB: the physical contact (issue 10; impact.h, doc/contact-model.md) --- */

/* The physical contact's layer correction of a Hertz load of radius patch
 * r0 (0: a point load) at bandwidth grid index omega_idx over the window of
 * grid index tau_idx (the grids of cache.h, as the paper's responses), from
 * the cache or made and kept there: a velocity or mass change, or the scenes
 * of a sweep that share the job's window, bandwidth and patch (plan.h,
 * anvil_plan_share), reuse it.  Held for this run (in held). */
static const struct anvil_green *physical_corr(struct anvil_solver *s, const struct anvil_problem *pb,
					       double hh, double patch, int omega_idx, int tau_idx,
					       struct held *held, struct anvil_err *err)
{
	struct anvil_cache_key key = { hh, pb->p.nu, pb->accuracy, omega_idx, tau_idx, 0,
				       ANVIL_CACHE_LOAD_PATCH, patch };
	const struct anvil_green *c = anvil_cache_find(s->cache, &key, NULL);
	if (c)
		return held_add(held, c);
	struct anvil_green_settings gs;
	anvil_green_settings(pb->accuracy, &gs);
	gs.omega_max = anvil_cache_grid(omega_idx);
	gs.filter = 1; /* no ringing at the band's edge (green.h) */
	gs.plate = s->plate;
	struct anvil_green *g = anvil_green_alloc_patch(ANVIL_GREEN_LAYER_CORRECTION, hh, pb->p.nu,
							patch, anvil_cache_grid(tau_idx), &gs,
							s->progress, s->progress_ctx, err);
	if (!g)
		return NULL;
	s->layer_computed++;
	s->layer_evals += anvil_green_evals(g);
	if (!(c = held_add(held, anvil_cache_add(s->cache, &key, g))))
		anvil_err_set(err, ANVIL_ENOMEM, "cache: every slot is held");
	return c;
}

/* What one physical run takes: the bandwidth's grid index, the patch
 * (radius patch r0) whose correction gives the true contact radius (0: a
 * point load throughout), and the radiation lag's low-pass time (impact.h,
 * tau_lag; a_max / c2). */
struct phys_load {
	int omega_idx;
	double patch;
	double tau_lag;
	double rest_at; /* s: a row at rest (impact.h, rest_at): its runs stop there; 0: none */
};

/* Separations below the resolution of the coarse pass merged (impact.h:
 * gap within the level's target of alpha_max, two coarse steps), and the
 * budget of contacts. */
static void merge_opts(struct anvil_impact_opts *io, const struct anvil_problem *pb,
		       const struct anvil_wave_job *j)
{
	io->merge_gap = anvil_accuracy_target(pb->accuracy);
	io->merge_time = fmax(2.0 * (pb->dt > 0 ? pb->dt : j->dt), io->merge_gap * j->ts);
	io->max_contacts = ANVIL_MAX_RUN_CONTACTS;
	/* the rest state (impact.h): its bound at a tenth of the target, so
	 * that R_f's half of it and the passes' difference meet the target
	 * (check_target: R_f's error against 0.1) */
	io->rest_tol = 0.1 * io->merge_gap;
	grow_opts(io, pb, j);
}

/* One physical impact of job j in progress: its load, the responses it
 * holds for the window being tried (a ramp and, with the true radius, a
 * second), and its result.  Split in two (phys_window, phys_execute) so
 * that what touches the cache and the progress callback, which are
 * single-threaded, runs apart from the impact itself, which only reads
 * the responses and may run beside another (physical_errors). */
struct phys_run {
	struct phys_load ld;
	struct response rs, rs2; /* no half-space, no static part: Hertz's */
	struct anvil_impact_opts io;
	struct held held;
	double tau_end;
	int corr; /* the corrections taken (the bottom reflection returns) */
	struct anvil_result *r;
};

static void phys_init(struct phys_run *u, const struct anvil_problem *pb,
		      const struct anvil_wave_job *j, double beta, struct phys_load ld,
		      size_t nhist, struct anvil_result *r)
{
	memset(u, 0, sizeof *u);
	u->ld = ld;
	u->r = r;
	u->io = (struct anvil_impact_opts){ .scheme = ANVIL_SCHEME_IMPLICIT, .dt = pb->dt,
					    .dt_auto = j->dt, .max_steps = ANVIL_MAX_STEPS,
					    .nhist = nhist, .physical = 1, .beta = beta,
					    .tau_lag = ld.tau_lag };
	merge_opts(&u->io, pb, j);
	u->io.rest_at = ld.rest_at;
}

/* Window `attempt` of run u: the plan's refusal rule, then the corrections
 * it needs (when the bottom reflection returns within it) from the cache,
 * made there when missing.  The shorter window's are given back first. */
static int phys_window(struct anvil_solver *s, const struct anvil_problem *pb,
		       const struct anvil_wave_job *j, int attempt, struct phys_run *u,
		       struct anvil_err *err)
{
	const struct anvil_params *p = &pb->p;
	struct phys_load ld = u->ld;
	u->tau_end = anvil_wave_window(j, attempt);
	int tau_idx = anvil_wave_tau_idx(j, u->tau_end);
	held_release(s->cache, &u->held);
	u->rs.corr = u->rs2.corr = NULL;
	int st = anvil_wave_refuse(p, pb->dt, u->r->model, j, u->tau_end,
				   anvil_cache_grid(ld.omega_idx), err);
	if (st)
		return st;
	u->io.rest_last = attempt + 1 >= j->attempts || /* as in waves_impact */
			  anvil_wave_refuse(p, pb->dt, u->r->model, j, anvil_wave_window(j, attempt + 1),
					    anvil_cache_grid(ld.omega_idx), NULL);
	u->corr = isfinite(j->hh) && anvil_wave_needs_corr(p, j, u->tau_end);
	u->io.alpha_ref = 0;
	if (!u->corr)
		return ANVIL_OK;
	u->rs.corr = physical_corr(s, pb, j->hh, 0.0, ld.omega_idx, tau_idx, &u->held, err);
	if (u->rs.corr && ld.patch > 0) {
		u->rs2.corr = physical_corr(s, pb, j->hh, ld.patch, ld.omega_idx, tau_idx, &u->held,
					    err);
		/* a^2 = R alpha with R = r0 */
		u->io.ramp2 = response_ramp;
		u->io.ramp2_ctx = &u->rs2;
		u->io.alpha_ref = ld.patch * ld.patch * p->r0;
	}
	if (!u->rs.corr || (ld.patch > 0 && !u->rs2.corr))
		return err ? err->status : ANVIL_ENUM;
	return ANVIL_OK;
}

/* The impact in the window phys_window loaded: no cache, no callback. */
static int phys_execute(const struct anvil_problem *pb, struct phys_run *u,
			struct anvil_err *err)
{
	enum anvil_model m = u->r->model;
	anvil_result_free(u->r);
	anvil_result_init(u->r, m);
	return anvil_impact_run(&pb->p, response_ramp, &u->rs, u->tau_end, &u->io, u->r, err);
}

/* A longer window is wanted: the contact outlasted this one (ANVIL_ETOL
 * with t_s NaN; a finite t_s is a refusal no window helps). */
static int phys_retry(int st, const struct anvil_result *r)
{
	return st == ANVIL_ETOL && isnan(r->ts.val);
}

/* Add f |a - b| of each value to r's error estimates. */
static void add_diff_error(struct anvil_result *r, const struct anvil_result *a,
			   const struct anvil_result *b, double f)
{
	r->ts.err += f * fabs(a->ts.val - b->ts.val);
	r->tmax.err += f * fabs(a->tmax.val - b->tmax.val);
	r->Pmax.err += f * fabs(a->Pmax.val - b->Pmax.val);
	r->Vs.err += f * fabs(a->Vs.val - b->Vs.val);
	r->Rf.err += f * fabs(a->Rf.val - b->Rf.val);
	r->Ea.err += f * fabs(a->Ea.val - b->Ea.val);
}

/* The physical row's impacts (run_physical): the row's own (MAIN) and
 * its error estimate's (physical_errors), each with its load, status and
 * message. */
enum { PHYS_MAIN, PHYS_BELOW, PHYS_HALF_LAG, PHYS_POINT, PHYS_POINT_HALF, PHYS_RUNS };

struct phys_set {
	struct phys_run u[PHYS_RUNS];
	struct anvil_result q[PHYS_RUNS]; /* the error runs' results (MAIN's is the row's) */
	struct anvil_err e[PHYS_RUNS];
	int st[PHYS_RUNS], done[PHYS_RUNS];
	struct held warm; /* the responses phys_at_hand found */
};

/* The loads: the row's, the patch below (the a^4 remainder), the lag's
 * time halved, and point loads at the row's bandwidth and half of it. */
static void phys_set_init(struct phys_set *set, const struct anvil_problem *pb,
			  const struct anvil_wave_job *j, double beta, struct phys_load ld,
			  size_t nhist, struct anvil_result *r)
{
	struct phys_load lds[PHYS_RUNS] = {
		[PHYS_MAIN] = ld,
		[PHYS_BELOW] = { ld.omega_idx, anvil_plan_patch_below(ld.patch), ld.tau_lag, ld.rest_at },
		[PHYS_HALF_LAG] = { ld.omega_idx, ld.patch, 0.5 * ld.tau_lag, ld.rest_at },
		[PHYS_POINT] = { ld.omega_idx, 0.0, ld.tau_lag, ld.rest_at },
		[PHYS_POINT_HALF] = { ld.omega_idx - ANVIL_CACHE_STEPS, 0.0, ld.tau_lag, ld.rest_at },
	};
	for (int k = 0; k < PHYS_RUNS; k++) {
		struct anvil_result *rk = k == PHYS_MAIN ? r : &set->q[k];
		if (k != PHYS_MAIN)
			anvil_result_init(rk, r->model);
		phys_init(&set->u[k], pb, j, beta, lds[k], k == PHYS_MAIN ? nhist : 0, rk);
		set->e[k] = (struct anvil_err){ 0 };
		set->st[k] = ANVIL_ETOL;
		set->done[k] = 0;
	}
	set->warm.n = 0;
}

/* A row at rest (impact.h, rest_at): its error runs are compared at its
 * rest time, so they are set up again to stop there (a warm row ran them
 * beside it before its rest was known; rare: only a run otherwise refused
 * comes to rest). */
static void phys_set_rest(struct anvil_solver *s, struct phys_set *set,
			  const struct anvil_problem *pb, const struct anvil_wave_job *j,
			  double beta, double rest_at)
{
	for (int k = PHYS_MAIN + 1; k < PHYS_RUNS; k++) {
		struct phys_load ld = set->u[k].ld;
		enum anvil_model m = set->q[k].model;
		held_release(s->cache, &set->u[k].held);
		anvil_result_free(&set->q[k]);
		anvil_result_init(&set->q[k], m);
		ld.rest_at = rest_at;
		phys_init(&set->u[k], pb, j, beta, ld, 0, &set->q[k]);
		set->e[k] = (struct anvil_err){ 0 };
		set->st[k] = ANVIL_ETOL;
		set->done[k] = 0;
	}
}

static void phys_set_free(struct anvil_solver *s, struct phys_set *set)
{
	held_release(s->cache, &set->warm);
	for (int k = 0; k < PHYS_RUNS; k++) {
		held_release(s->cache, &set->u[k].held);
		if (k != PHYS_MAIN)
			anvil_result_free(&set->q[k]);
	}
}

/* Whether the first window takes corrections (the error runs are then
 * wanted) and every run's are in the cache (memory, or disk: loaded, and
 * held in set->warm till the runs fetch them): a warm run, whose error
 * runs may go beside the row's own before thin_check has seen it (their
 * results are only used when it passes).  A cold one makes no response a
 * refusal would waste. */
static int phys_at_hand(struct anvil_solver *s, const struct anvil_problem *pb,
			const struct anvil_wave_job *j, struct phys_set *set)
{
	double tau_end = anvil_wave_window(j, 0);
	if (!isfinite(j->hh) || !anvil_wave_needs_corr(&pb->p, j, tau_end))
		return 0;
	for (int k = 0; k < PHYS_RUNS; k++)
		for (int twice = 0; twice < 2; twice++) { /* the point load, then the patch */
			const struct phys_load *ld = &set->u[k].ld;
			struct anvil_cache_key key = { j->hh, pb->p.nu, pb->accuracy, ld->omega_idx,
						       anvil_wave_tau_idx(j, tau_end), 0,
						       ANVIL_CACHE_LOAD_PATCH, twice ? ld->patch : 0.0 };
			if ((!twice || ld->patch > 0) &&
			    !held_add(&set->warm, anvil_cache_find(s->cache, &key, NULL)))
				return 0;
		}
	return 1;
}

/* The impacts of a round (phys_rounds), shared out to threads: each
 * takes the next run not yet taken until none is left. */
struct phys_crew {
	const struct anvil_problem *pb;
	struct phys_set *set;
	const int *go;
	int n;
	atomic_int next;
};

static void *phys_crew_work(void *arg)
{
	struct phys_crew *w = arg;
	for (int i; (i = atomic_fetch_add(&w->next, 1)) < w->n;) {
		int k = w->go[i];
		w->set->st[k] = phys_execute(w->pb, &w->set->u[k], &w->set->e[k]);
	}
	return NULL;
}

/* The threads for a round's n impacts: one per core (OpenMP's count, so
 * OMP_NUM_THREADS rules here too), at most PHYS_RUNS. */
static int phys_threads(int n)
{
	int t = 1;
#ifdef _OPENMP
	t = omp_get_max_threads();
#endif
	return t < n ? t : n;
}

/* The corrections that the runs of set not yet done need in window
 * `attempt` (those the window does not refuse) and the cache lacks, made
 * together when there are two or more (green.h, anvil_green_alloc_set:
 * each the bits it has alone, the four at about 1.2 times the kernel
 * evaluations of one) and left in the cache, where phys_window finds
 * them.  A cold row's first window takes its error runs' corrections
 * with its own: made later, apart, they would cost twice as much; wasted
 * only when thin_check refuses the row.  A failure here is left to
 * phys_window, which makes the correction alone and reports it. */
#define PHYS_SET_MAX (2 * PHYS_RUNS)

static void phys_prefetch(struct anvil_solver *s, const struct anvil_problem *pb,
			  const struct anvil_wave_job *j, int attempt, const struct phys_set *set,
			  int k0, int k1)
{
	double tau_end = anvil_wave_window(j, attempt);
	int tau_idx = anvil_wave_tau_idx(j, tau_end);
	struct anvil_cache_key key[PHYS_SET_MAX];
	struct anvil_green_load load[PHYS_SET_MAX];
	struct anvil_green *g[PHYS_SET_MAX];
	size_t n = 0;
	if (!isfinite(j->hh) || !anvil_wave_needs_corr(&pb->p, j, tau_end))
		return;
	/* the first window: this round's runs and those after it (a cold row's
	 * error runs); a longer one: the runs of this round that go on */
	for (int k = k0; k < (attempt ? k1 : PHYS_RUNS); k++) {
		const struct phys_load *ld = &set->u[k].ld;
		if (set->done[k] || anvil_wave_refuse(&pb->p, pb->dt, set->u[k].r->model, j, tau_end,
						      anvil_cache_grid(ld->omega_idx), NULL))
			continue;
		for (int twice = 0; twice < 2; twice++) { /* the point load, then the patch */
			struct anvil_cache_key ky = { j->hh, pb->p.nu, pb->accuracy, ld->omega_idx,
						      tau_idx, 0, ANVIL_CACHE_LOAD_PATCH,
						      twice ? ld->patch : 0.0 };
			size_t i = 0;
			while (i < n && !(key[i].omega_idx == ky.omega_idx && key[i].patch == ky.patch))
				i++;
			if ((twice && !(ld->patch > 0)) || i < n ||
			    anvil_cache_probe(s->cache, &ky) != ANVIL_CACHE_NONE)
				continue;
			key[n] = ky;
			load[n++] = (struct anvil_green_load){ ky.patch,
							       anvil_cache_grid(ky.omega_idx) };
		}
	}
	if (n < 2)
		return;
	struct anvil_green_settings gs;
	anvil_green_settings(pb->accuracy, &gs);
	gs.filter = 1; /* as physical_corr */
	gs.plate = s->plate;
	if (anvil_green_alloc_set(j->hh, pb->p.nu, anvil_cache_grid(tau_idx), &gs, load, n,
				  s->progress, s->progress_ctx, g, NULL))
		return;
	for (size_t i = 0; i < n; i++) {
		s->layer_computed++;
		s->layer_evals += anvil_green_evals(g[i]);
		anvil_cache_release(s->cache, anvil_cache_add(s->cache, &key[i], g[i]));
	}
}

/* The runs k0 <= k < k1 of set, each with its window grown until its
 * contact fits (as waves_impact does), all together: per window the
 * responses first, one run after another (the cache and the progress
 * callback are single-threaded), then the impacts side by side on the
 * cores, each reading its own responses and writing its own result and
 * status: the bits do not depend on the threads or on which runs went
 * together.  Plain threads that block when done, not OpenMP's team, whose
 * waiting threads spin: on a machine whose cores are busy with other
 * work the spinning took the time the impacts needed (3 times slower). */
static void phys_rounds(struct anvil_solver *s, const struct anvil_problem *pb,
			const struct anvil_wave_job *j, struct phys_set *set, int k0, int k1)
{
	for (int attempt = 0; attempt < j->attempts; attempt++) {
		int go[PHYS_RUNS], n = 0;
		phys_prefetch(s, pb, j, attempt, set, k0, k1);
		for (int k = k0; k < k1; k++) {
			if (set->done[k])
				continue;
			set->st[k] = phys_window(s, pb, j, attempt, &set->u[k], &set->e[k]);
			if (set->st[k])
				set->done[k] = 1; /* refused, or no response */
			else
				go[n++] = k;
		}
		if (!n)
			return;
		struct phys_crew w = { .pb = pb, .set = set, .go = go, .n = n };
		pthread_t th[PHYS_RUNS];
		int nt = 0;
		atomic_init(&w.next, 0);
		/* a thread that cannot be had leaves its share to the others */
		while (nt + 1 < phys_threads(n) && !pthread_create(&th[nt], NULL, phys_crew_work, &w))
			nt++;
		phys_crew_work(&w);
		for (int t = 0; t < nt; t++)
			pthread_join(th[t], NULL);
		for (int i = 0; i < n; i++)
			set->done[go[i]] = !phys_retry(set->st[go[i]], set->u[go[i]].r);
	}
}

/* The errors of the layer correction (solver.c's run_physical): the
 * O(a^4) remainder of the true radius, and the correction's own, by
 * halving the bandwidth (point loads, as run_waves does).
 * The remainder: with w(a) = w0 + a^2 w2 + a^4 w4 and the a^2 term fitted
 * on the patch P >= a_max (the job's: plan.h), the run's w0 + a^2 (w(P) -
 * w0) / P^2 is off by a^2 (P^2 - a^2) w4, at most a_max^2 P^2 w4 (and
 * P^4 w4 / 4 when a_max^2 >= P^2 / 2); the fit on P' = P/sqrt(2) differs
 * from it by a^2 P^2 w4 / 2, at most a_max^2 P^2 w4 / 2.  So that
 * difference bounds the remainder when P <= sqrt(2) a_max (the patch on
 * its half-octave grid, a run alone: 1 to 2 times over), and 2 (1 -
 * a_max^2 / P^2) times it does for a sweep's wider patch. */
static int physical_errors(const struct phys_set *set, double a_max_r0,
			   struct anvil_result *r, struct anvil_err *err)
{
	/* the first failure in the order of the sums, which is that of the
	 * runs one after another (and so are the bits) */
	static const int order[] = { PHYS_BELOW, PHYS_POINT, PHYS_POINT_HALF, PHYS_HALF_LAG };
	for (size_t i = 0; i < sizeof order / sizeof *order; i++)
		if (set->st[order[i]]) {
			if (err)
				*err = set->e[order[i]];
			return set->st[order[i]];
		}
	double patch = set->u[PHYS_MAIN].ld.patch, x = a_max_r0 / patch;
	double f = fmax(1.0, 2.0 * (1.0 - x * x));
	add_diff_error(r, r, &set->q[PHYS_BELOW], f);
	add_diff_error(r, &set->q[PHYS_POINT], &set->q[PHYS_POINT_HALF], 1.0);
	add_diff_error(r, r, &set->q[PHYS_HALF_LAG], 1.0);
	return ANVIL_OK;
}

/* The computed contact against the layer's thickness (plan.c's
 * thin_refuse decides first on Zener's plate): the largest Hertz
 * compression alpha = k0 P_max^(2/3) gives a = sqrt(r0 alpha); beyond h
 * the layer is no half-space at the contact's scale and the row is
 * refused (before its error estimate's runs). */
static int thin_check(const struct anvil_plan *pl, const struct anvil_result *r,
		      struct anvil_err *err)
{
	const struct anvil_params *p = &pl->pb.p;
	double a = sqrt(p->r0 * p->k0 * pow(r->Pmax.val, 2.0 / 3.0));
	/* the Hertz spring's energy at the peak is at most the impact's: P_max
	 * is at most the rigid anvil's (the plan's figure; 5 % for the lag's
	 * approximation) */
	double ph = pl->fig[ANVIL_FIG_P_MAX];
	if (r->Pmax.val > 1.05 * ph)
		return anvil_err_set(err, ANVIL_ENUM,
				     "%s: the computed P_max = %.3g N exceeds the rigid anvil's %.3g N, which bounds it (energy): the time stepping is unstable for this scene",
				     anvil_model_name(r->model), r->Pmax.val, ph);
	if (!(a > p->h))
		return ANVIL_OK;
	return anvil_err_set(err, ANVIL_EINVAL,
			     "%s: the contact radius a = %.3g mm (from the computed P_max = %.3g N) exceeds h = %.3g mm (a/h = %.2g): Hertz's law for a half-space does not hold",
			     anvil_model_name(r->model), a * 1e3, r->Pmax.val, p->h * 1e3, a / p->h);
}

/* The physical row: Hertz's approach plus the layer's remainder, the
 * correction with the true contact radius a(t) (impact.h: point load plus
 * the a^2 term from the Hertz patch of the largest radius a_max).  Its
 * error estimates add to the time stepping's: physical_errors', and the
 * half-space remainder's next term, relative O(omega a / c2) of the wave
 * effect (radiation.h), taken as pi a_max / (c2 t_s) times the radiated
 * fraction of each value.
 * Where the patch size still matters: thin layers, where a_max is not
 * small against h and the correction is large: there the a^4 remainder
 * is what the error estimate shows (doc/contact-model.md). */
static int physical_band(struct anvil_solver *s, const struct anvil_plan *pl,
			 const struct anvil_plan_row *row, int omega_idx, size_t nhist,
			 struct anvil_result *r, int *corr_out, double *band_out,
			 struct anvil_err *err)
{
	const struct anvil_params *p = &pl->pb.p;
	double beta = anvil_radiation_beta(p->nu, p->rho, p->c2);
	double a = pl->fig[ANVIL_FIG_A_HERTZ];
	struct phys_load ld = { omega_idx, row->job.patch, a / p->c2, 0.0 };
	struct phys_set set;
	phys_set_init(&set, &pl->pb, &row->job, beta, ld, nhist, r);
	/* warm, the five impacts at once on the cores; cold, the row's first
	 * (thin_check may refuse it before the others' responses are made) */
	int at_hand = phys_at_hand(s, &pl->pb, &row->job, &set);
	phys_rounds(s, &pl->pb, &row->job, &set, PHYS_MAIN, at_hand ? PHYS_RUNS : PHYS_MAIN + 1);
	int st = set.st[PHYS_MAIN], corr = set.u[PHYS_MAIN].corr;
	*corr_out = corr;
	if (st && err)
		*err = set.e[PHYS_MAIN];
	if (!st && corr)
		st = thin_check(pl, r, err);
	int rest = !st && r->rest_bound > 0;
	if (rest)
		phys_set_rest(s, &set, &pl->pb, &row->job, beta, r->ts.val);
	if (!st && corr && (!at_hand || rest))
		phys_rounds(s, &pl->pb, &row->job, &set, PHYS_MAIN + 1, PHYS_RUNS);
	if (!st && corr)
		st = physical_errors(&set, fmin(1.0, a / p->r0), r, err);
	/* the band's part of P_max's estimate (physical_errors) */
	*band_out = !st && corr ? fabs(set.q[PHYS_POINT].Pmax.val - set.q[PHYS_POINT_HALF].Pmax.val)
				: 0.0;
	phys_set_free(s, &set);
	if (st)
		return st;
	/* the radiation lag's next term: relative pi a / (c2 t_s) of the wave
	 * effect, which moves P_max, t_s and R_f by at most the radiated
	 * fraction f of their values (plan.c's estimate; 0.4 % of P_max against
	 * f = 1.3 % on the paper's half-space) and E_a by f m1 V0^2 / 2 */
	double d = M_PI * a / (p->c2 * r->ts.val) * pl->fig[ANVIL_FIG_RADIATED];
	r->ts.err += d * r->ts.val;
	r->tmax.err += d * r->tmax.val;
	r->Pmax.err += d * r->Pmax.val;
	r->Vs.err += d * fabs(r->Vs.val);
	r->Rf.err += d * fabs(r->Rf.val);
	r->Ea.err += d * 0.5 * p->m1 * p->V0 * p->V0;
	if (r->model == ANVIL_MODEL_HALFSPACE || !isfinite(p->h)) {
		r->lambda_star = 0.0;
		r->Rf_star = 1.0;
	}
	if (row->model_err > 0) /* the layer's reflections left out (plan.c) */
		add_model_error(r, p, row->model_err);
	tmax_from_pmax(r, corr ? anvil_cache_grid(ld.omega_idx) * p->c2 / p->r0 : 0.0);
	/* a_max at the computed peak force (on a thin plate far below the
	 * rigid anvil's, which sized the patch) */
	if (corr)
		snprintf(r->note, sizeof r->note,
			 "physical contact: Hertz + the layer's remainder with the true contact radius (a_max = %.3g mm; its a^2 term fitted on a %.3g mm patch), reflections from 2h/c1 = %.3g us",
			 sqrt(p->r0 * p->k0 * pow(r->Pmax.val, 2.0 / 3.0)) * 1e3, ld.patch * p->r0 * 1e3,
			 2e6 * p->h / p->c1);
	else if (row->model_err > 0)
		snprintf(r->note, sizeof r->note,
			 "physical contact on the half-space: the reflections from 2h/c1 = %.3g us change the results by about %.2g (estimated), below the target: left out",
			 2e6 * p->h / p->c1, row->model_err);
	else
		snprintf(r->note, sizeof r->note,
			 "physical contact: Hertz + the half-space's radiation lag (no reflection during the contact)");
	rest_note(r);
	contacts_note(r);
	return check_target(r, pl->pb.accuracy, err);
}

/* The physical row at the plan's bandwidth, doubled while the peak force's
 * estimated error misses the target and its band's part (the point load
 * at half the band: the filter's cut) is most of it, at most refine_max
 * times, while the refusal rule takes the wider band; a wider band is kept
 * when it is better.  (Copper on pmma, h = 5.8 r0, missed by 1.1e-3 of
 * which the band was little: four times the band cost 60 times the work
 * for 0.00068 -> 0.00067 kN.)
 * The plan sizes the band by the Hertz pulse (plan.c, wave_job); on a thin
 * plate the force peaks at the impact's first microseconds, long before
 * the pulse's: h = 0.1 r0 (12.2 g, 10 m/s) peaked at 4.0 us with P_max
 * 158.3 +- 10 N at the plan's band, 154.79 +- 3.4 N at twice it, 154.758
 * +- 0.011 N at four times (0.57, 0.66, 0.79 s). */
static int run_physical(struct anvil_solver *s, const struct anvil_plan *pl,
			const struct anvil_plan_row *row, size_t nhist, struct anvil_result *r,
			struct anvil_err *err)
{
	const struct anvil_problem *pb = &pl->pb;
	double tgt = anvil_accuracy_target(pb->accuracy);
	int idx = row->job.omega_idx, corr = 0, refined = 0;
	double band = 0;
	int st = physical_band(s, pl, row, idx, nhist, r, &corr, &band, err);
	while (st == ANVIL_WTOL && corr && refined < row->job.refine_max &&
	       r->Pmax.err > tgt * r->Pmax.val && band > 0.5 * r->Pmax.err &&
	       !anvil_wave_refuse(&pb->p, pb->dt, r->model, &row->job,
				  anvil_wave_window(&row->job, 0),
				  anvil_cache_grid(idx + ANVIL_CACHE_STEPS), NULL)) {
		struct anvil_result prev = *r; /* it owns the history now */
		struct anvil_err pe = err ? *err : (struct anvil_err){ 0 };
		anvil_result_init(r, prev.model);
		int s2 = physical_band(s, pl, row, idx + ANVIL_CACHE_STEPS, nhist, r, &corr, &band,
				       err);
		if (s2 < 0 || !(r->Pmax.err < prev.Pmax.err)) {
			anvil_result_free(r);
			*r = prev;
			if (err)
				*err = pe;
			break;
		}
		anvil_result_free(&prev);
		st = s2;
		idx += ANVIL_CACHE_STEPS;
		refined++;
	}
	if (refined) {
		size_t len = strlen(r->note);
		snprintf(r->note + len, sizeof r->note - len,
			 "; the band %dx the plan's (the peak force's band error)", 1 << refined);
	}
	return st;
}
/* --- end contactB --- */

/* A wave row (STATIC, HALFSPACE or LAYER) as the plan says, with its
 * fallback when the computed contact outlasts the reflection. */
static int run_anvil(struct anvil_solver *s, const struct anvil_plan *pl,
		     const struct anvil_plan_row *planned, size_t nhist, struct anvil_result *r,
		     struct anvil_err *err)
{
	const struct anvil_params *p = &pl->pb.p;
	struct anvil_plan_row row = *planned;
	int corr = 0;
	if (row.contact == ANVIL_CONTACT_PHYSICAL)
		return run_physical(s, pl, planned, nhist, r, err);
	double band = 0;
	int st = run_waves(s, &pl->pb, &row.job, row.method, nhist, r, &corr, &band, err);
	/* Causality made the half-space exact only if the contact really ended
	 * before the reflection came back: else the layer after all. */
	if (!st && row.fallback && !(r->ts.val < 2.0 * p->h / p->c1)) {
		row.method = ANVIL_METHOD_LAYER;
		row.why = ANVIL_WHY_NOT_ASKED;
		row.exact = 1;
		row.model_err = 0;
		row.job = row.fallback_job;
		st = run_waves(s, &pl->pb, &row.job, row.method, nhist, r, &corr, &band, err);
	}
	if (st)
		return st;
	if (!row.exact && row.why != ANVIL_WHY_FORCED)
		add_model_error(r, p, row.model_err);
	tmax_from_pmax(r, band);
	if (r->model == ANVIL_MODEL_HALFSPACE || !isfinite(p->h)) {
		/* Zener's plate parameter has no meaning for a half-space */
		r->lambda_star = 0.0;
		r->Rf_star = 1.0;
	}
	waves_note(r, p, &row, row.method, corr);
	rest_note(r);
	contacts_note(r);
	return pl->pb.scheme == ANVIL_SCHEME_PAPER ? ANVIL_OK : check_target(r, pl->pb.accuracy, err);
}

static int run_row(struct anvil_solver *s, const struct anvil_plan *pl, enum anvil_model m,
		   enum anvil_contact c, size_t nhist, struct anvil_result *r,
		   struct anvil_err *err)
{
	if ((unsigned)m >= ANVIL_MODEL_COUNT)
		return anvil_err_set(err, ANVIL_EINVAL, "unknown model %d", (int)m);
	const struct anvil_plan_row *row = anvil_plan_row_of(pl, m, c);
	if (!row)
		return anvil_err_set(err, ANVIL_EINVAL, "%s: the plan has no row with the %s contact",
				     anvil_model_name(m), anvil_contact_name(c));
	if (row->status) /* refused when planned: no work */
		return anvil_err_set(err, row->status, "%s", row->refusal);
	switch (row->method) {
	case ANVIL_METHOD_HERTZ:
		return anvil_hertz_run(&pl->pb.p, nhist, r, err);
	case ANVIL_METHOD_ZENER:
		return anvil_zener_run(&pl->pb.p, nhist, r, err);
	case ANVIL_METHOD_STATIC:
	case ANVIL_METHOD_HALFSPACE:
	case ANVIL_METHOD_LAYER:
		return run_anvil(s, pl, row, nhist, r, err);
	default:
		return anvil_err_set(err, ANVIL_EINVAL, "%s: no method planned",
				     anvil_model_name(m));
	}
}

int anvil_solver_run(struct anvil_solver *s, const struct anvil_plan *pl, enum anvil_model m,
		     size_t nhist, struct anvil_result *r, struct anvil_err *err)
{
	return anvil_solver_run_contact(s, pl, m, ANVIL_CONTACT_AUTO, nhist, r, err);
}

int anvil_solver_run_contact(struct anvil_solver *s, const struct anvil_plan *pl,
			     enum anvil_model m, enum anvil_contact c, size_t nhist,
			     struct anvil_result *r, struct anvil_err *err)
{
	struct anvil_err e = { 0 };
	double t0 = wall_seconds();
	anvil_result_init(r, m);
	int st = run_row(s, pl, m, c, nhist, r, &e);
	const struct anvil_plan_row *row = anvil_plan_row_of(pl, m, c);
	r->contact = row ? row->contact : ANVIL_CONTACT_AUTO; /* runs re-init r: set last */
	const struct anvil_params *p = &pl->pb.p;
	if (st >= 0 && (m == ANVIL_MODEL_LAYER || m == ANVIL_MODEL_ZENER))
		anvil_result_reach(r, p->h, p->E, p->nu, p->rho, p->c1);
	r->seconds = wall_seconds() - t0;
	if (!st)
		anvil_err_clear(&e); /* no stale message from a retried window */
	r->status = st;
	snprintf(r->why, sizeof r->why, "%s", st ? e.msg : "");
	if (err)
		*err = e;
	return st;
}
