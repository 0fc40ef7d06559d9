#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hertz.h"
#include "solver_impl.h"
#include "zener.h"

/* The solver executes a plan's row (plan.h): every decision (method, job,
 * fallback, refusal) is the planner's; what is left here is the doing,
 * and the checks only a computed result allows (the window long enough,
 * the target met, the contact over before the reflection). */


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



const void *solver_held_add(struct held *h, const void *p)
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

void solver_held_release(struct anvil_cache *c, struct held *h)
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
		return solver_held_add(held, g);
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
		gm = solver_held_add(held, anvil_cache_add(s->cache, &mk, ng));
	if (anvil_cache_probe(s->cache, &tk) == ANVIL_CACHE_MEMORY)
		anvil_green_free(tw);
	else
		gt = solver_held_add(held, anvil_cache_add(s->cache, &tk, tw));
	g = key->twin ? gt : gm;
	if (!g)
		anvil_err_set(err, ANVIL_ENOMEM, "cache: every slot is held");
	return g;
}


int solver_response_ramp(void *ctx, double tau, double *val)
{
	const struct response *rs = ctx;
	double a, b = 0;
	int st = ANVIL_OK;
	if (rs->hs)
		st = anvil_halfspace_ramp(rs->hs, tau, &a, NULL);
	else /* not fmax, a libm call (10^5 a warm run): the same values */
		a = rs->stat * (tau > 0.0 ? tau : 0.0);
	if (!st && rs->corr && tau < rs->t1) {
		double x = tau > rs->t0 ? tau - rs->t0 : 0.0;
		b = x * x * (rs->c2 + rs->c3 * x);
	} else if (!st && rs->corr)
		st = anvil_green_ramp(rs->corr, tau, &b);
	*val = a + b;
	return st;
}

int solver_response_impulse(void *ctx, double tau, double *val)
{
	const struct response *rs = ctx;
	if (rs->hs || !rs->corr) /* the half-space's has no closed form here */
		return ANVIL_EINVAL;
	return anvil_green_impulse(rs->corr, tau, val); /* a static part's is 0 for tau > 0 */
}

/* The caller's nhist samples (none when nhist < 2) from r's node
 * history (anvil_impact_opts.hist_nodes: an error run's, solver_twin.c),
 * as the run would have resampled its pass. */
static int history_from_nodes(struct anvil_result *r, size_t nhist)
{
	struct anvil_history h = { 0 };
	if (nhist < 2 || r->hist.n < 2) {
		anvil_result_free(r);
		return ANVIL_OK;
	}
	if (anvil_impact_history_resample(&r->hist, nhist, &h))
		return ANVIL_ENOMEM;
	anvil_result_free(r);
	r->hist = h;
	return ANVIL_OK;
}

/* Add a model's estimated relative deviation d from the row's full model
 * (the planner's) to each error estimate.  E_a = m1 (V0^2 - V_s^2)/2 moves
 * by m1 V_s^2 d when V_s moves by d V_s. */
void solver_add_model_error(struct anvil_result *r, const struct anvil_params *p, double d)
{
	r->model_err += d;
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
 * term of P_max's is in.
 *
 * The parabola is the march's, through its largest sample: on a plateau
 * (a heavy impactor come to rest on a thin plate) c is that of the plate
 * waves' ripples riding on a broader peak, and a change of 1e-14 in the
 * kernel moved t_max from one ripple's crest to the next, 1.2 us, against
 * an estimate of 0.38 us (0.02 r0, 10 kg at 1 m/s).  Whatever the shape,
 * P + e peaks where P >= P_max - 2 dP: the march's nodes there (the
 * result's plateau, at the next coarser power of 2) bound the shift.
 * Where that set is no wider than the parabola's (twice its cap: the
 * power of 2 widens it by up to sqrt 2), the parabola holds and its rule
 * stands; where it is wider, the peak has crests the parabola does not
 * see, and the set's extent is t_max's estimate. */
static double plateau_span(const struct anvil_result *r, double dP)
{
	double d = 2.0 * dP / r->Pmax.val;
	int j = d < 1.0 ? -ilogb(d) - 1 : 0;
	j = j < 0 ? 0 : j >= ANVIL_PLATEAU_LEVELS ? ANVIL_PLATEAU_LEVELS - 1 : j;
	return r->Pmax_plat[j];
}

void solver_tmax_from_pmax(struct anvil_result *r, double band)
{
	double c = r->Pmax_curv, dP = r->Pmax.err;
	if (!(c > 0) || !(dP > 0) || !(r->Pmax.val > 0))
		return;
	double rate = fmax(band, sqrt(c / r->Pmax.val)); /* 1/s */
	double cap = 2.0 * sqrt(dP / c), span = plateau_span(r, dP);
	double shift = fmin(dP * rate / c, cap);
	if (span > 2.0 * cap) /* structure the parabola does not see */
		shift = fmax(shift, span);
	r->tmax.err = fmax(r->tmax.err, shift);
}

/* The accuracy target against the error estimates: P_max and t_s
 * relative, R_f relative to max(R_f, 0.1) (a nearly dead rebound has no
 * meaningful relative error).  ANVIL_WTOL (a warning: the values stand)
 * when it is missed, ANVIL_ENUM for an unphysical solution. */
int solver_check_target(const struct anvil_result *r, enum anvil_accuracy acc,
			struct anvil_err *err)
{
	double tgt = anvil_accuracy_target(acc);
	double e[3];
	solver_target_errs(r, e);
	double e_p = e[0], e_t = e[1], e_r = e[2];
	if (!isfinite(r->ts.val) || !isfinite(r->Pmax.val) || !isfinite(r->Rf.val) || !(r->ts.val > 0) ||
	    !(r->Pmax.val > 0) || r->Rf.val > 1.0 + fmax(10.0 * r->Rf.err, 1e-6))
		return anvil_err_set(err, ANVIL_ENUM,
				     "%s: the solution is unphysical (t_s = %.3g us, P_max = %.3g N, R_f = %.3g): the time stepping is unstable for this scene",
				     anvil_model_name(r->model), r->ts.val * 1e6, r->Pmax.val, r->Rf.val);
	if ((e_p > tgt || e_t > tgt || e_r > tgt) && r->model_err > tgt)
		return anvil_err_set(err, ANVIL_WTOL,
				     "%s: accuracy '%s' (%.0e) not reached: estimated errors P_max %.1e, t_s %.1e, R_f %.1e, of which the model's own %.1e (no finer level lowers it)",
				     anvil_model_name(r->model), anvil_accuracy_name(acc), tgt, e_p, e_t, e_r,
				     r->model_err);
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
void solver_grow_opts(struct anvil_impact_opts *io, const struct anvil_problem *pb,
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
	int causal; /* 1: causal_probe may leave the correction out */
};

/* One impact over window tau_end (attempt) with the response as wv holds it. */
static int waves_march(struct waves *wv, int attempt, double tau_end, double omega,
		       struct anvil_result *r, struct anvil_err *err)
{
	const struct anvil_params *p = &wv->pb->p;
	enum anvil_model m = r->model;
	anvil_result_free(r);
	anvil_result_init(r, m);
	/* the last window, or the last the rule lets run: at rest at its
	 * end rather than refused (impact.h, rest_last) */
	wv->io.rest_last = attempt + 1 >= wv->job->attempts ||
			   anvil_wave_refuse(p, wv->pb->dt, r->model, wv->job,
					     anvil_wave_window(wv->job, attempt + 1), omega, NULL);
	wv->io.t_smooth = anvil_wave_t_smooth(p, wv->job, tau_end);
	int st = anvil_impact_run(p, solver_response_ramp, &wv->rs, tau_end, &wv->io, r, err);
	wv->tau_end = tau_end;
	return st;
}

/* Whether the window tau_end is the first with the bottom reflection in
 * it, the last one's contact having outlasted its window: then the
 * contact may yet end before the reflection returns, where the layer is
 * the half-space (causality, as run_anvil's fallback), and its layer
 * correction, made for nothing, is most of the row's time: h = 1000 r0,
 * 100 kg at 100 m/s ended at 1331 us, the reflection back at 1356 us,
 * and the correction over the second window took 2.6 s (1.3e7
 * evaluations) of the row's 2.6.  So that window runs first without it
 * (an impact of a few thousand steps, ms); the correction is made only
 * when the contact reaches the reflection.  Not the paper's scheme (its
 * Tables), nor a long window (the far field's t_smooth asks for the
 * correction's impulse response). */
static int causal_probe(const struct waves *wv, int attempt, double tau_end)
{
	const struct anvil_params *p = &wv->pb->p;
	return wv->causal && attempt > 0 && wv->pb->scheme != ANVIL_SCHEME_PAPER &&
	       anvil_wave_needs_corr(p, wv->job, tau_end) &&
	       !anvil_wave_needs_corr(p, wv->job, anvil_wave_window(wv->job, attempt - 1)) &&
	       !(anvil_wave_t_smooth(p, wv->job, tau_end) > 0);
}

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
		if (causal_probe(wv, attempt, tau_end)) {
			st = waves_march(wv, attempt, tau_end, omega, r, err);
			if (!st && r->ts.val < 2.0 * p->h / p->c1)
				return st;
			anvil_err_clear(err);
		}
		if (anvil_wave_needs_corr(p, wv->job, tau_end)) {
			struct anvil_cache_key key = { wv->job->hh, p->nu, wv->pb->accuracy, omega_idx,
						       anvil_wave_tau_idx(wv->job, tau_end), twin,
						       ANVIL_CACHE_LOAD_R0, 0.0, 0.0 };
			wv->rs.corr = get_corr(s, &key, &wv->held, err);
			if (!wv->rs.corr)
				return err ? err->status : ANVIL_ENUM;
			if ((st = solver_start_set(&wv->rs, omega, p)))
				return anvil_err_set(err, st, "layer correction: its start: %s", anvil_strerror(st));
		}
		st = waves_march(wv, attempt, tau_end, omega, r, err);
		if (st == ANVIL_ETOL && !isnan(r->ts.val))
			break;
	}
	return st;
}

/* Separations below the resolution of the coarse pass merged (impact.h:
 * gap within the level's target of alpha_max, two coarse steps), and the
 * budget of contacts. */
void solver_merge_opts(struct anvil_impact_opts *io, const struct anvil_problem *pb,
		       const struct anvil_wave_job *j)
{
	io->merge_gap = anvil_accuracy_target(pb->accuracy);
	io->merge_time = fmax(2.0 * (pb->dt > 0 ? pb->dt : j->dt), io->merge_gap * j->ts);
	io->max_contacts = ANVIL_MAX_RUN_CONTACTS;
	/* the rest state (impact.h): its bound at a tenth of the target, so
	 * that R_f's half of it and the passes' difference meet the target
	 * (solver_check_target: R_f's error against 0.1) */
	io->rest_tol = 0.1 * io->merge_gap;
	solver_grow_opts(io, pb, j);
}


void solver_target_errs(const struct anvil_result *r, double e[3])
{
	/* at rest (impact_rest.c) t_s is when the rebound's bound fell within
	 * the target, known to the bound's halving time, not a contact's end */
	e[0] = r->Pmax.err / r->Pmax.val;
	e[1] = r->rest_bound > 0 ? 0.0 : r->ts.err / r->ts.val;
	e[2] = r->Rf.err / fmax(fabs(r->Rf.val), 0.1);
}

/* Whether a wider band can meet the target r misses: some output over it
 * owes most of its estimate to the band (its part: the estimate less
 * before[], the march's own).  Where the march's step is most of the
 * miss, a wider band changes nothing and costs twice: h = 0.1 r0, 10 kg
 * at 1 m/s (the paper's contact) doubled it twice for P_max's 1.2e-2, of
 * which the band's part was 4e-4. */
static int band_dominates(const struct anvil_result *r, const double before[3], double tgt)
{
	double e[3];
	solver_target_errs(r, e);
	for (int i = 0; i < 3; i++)
		if (e[i] > tgt && e[i] - before[i] > 0.5 * e[i])
			return 1;
	return 0;
}

/* Whether the twin (half the band) failed where the main run did not:
 * its contact chattered or its march found no end (st from waves_impact,
 * impact.c: a budget of contacts or of steps leaves t_s infinite).  Its
 * band's ringing, not the layer: on h = 0.2 r0, 1 kg at 100 m/s the twin
 * (omega = 1, the floor's half) parted and touched again every 23.5
 * steps (8.5 us, about its band's period 2 pi/omega), past 64 contacts,
 * where the main (omega = 2) came to rest in one, and both did at twice
 * the band.  So run_waves takes the next round (the main at twice the
 * band; its twin is this main, which ran) rather than end the row; a
 * main that fails ends it as before. */
static int twin_failed(int st, const struct anvil_result *coarse)
{
	return st == ANVIL_ENUM || (st == ANVIL_ETOL && isinf(coarse->ts.val));
}

/* The step of the plan is the pulse's (its nsteps over the Hertz or
 * Zener contact); the paper's contact on a thin plate peaks far sooner,
 * at 0.22-0.6 of Zener's t_max where it missed normal's target on the
 * grid (copper on steel, h = 0.05-2 r0, 1 g-100 kg): 1.2-21 steps to the
 * peak, P_max's estimate 1.7e-3 to 8.9e-2, nearly all of it the march's.
 * Zener's t_max does not tell those from the rows that peak later than
 * his (h = 0.02 r0 under 0.1-1 g: 1-2.8 times), where a step from it
 * would cost twice for nothing; the run itself does: when P_max misses
 * the target, mostly by the march (march: its part, relative), and its
 * peak came in fewer than nsteps / STEP_RISE steps, the row runs again
 * at the step that gives the peak that many (as the physical contact's
 * rise, plan.c, PHYS_RISE), once, kept when its estimate is the smaller.
 * Not the paper's scheme, nor a scene's own step.  Also when the march's
 * part alone misses the target there: no band makes that up, and
 * run_waves stops its rounds there (WAVES_STOP_COARSE) rather than double the
 * band at a step that is thrown away (h = 0.2 r0, 100 kg at 10 m/s: the
 * march's part 2.3e-2 at the plan's step, 4e-6 at the finer one; its
 * second round at the plan's step, two impacts of 0.4-0.5 s, was). */
#define STEP_RISE 16.0
static int step_rerun(const struct anvil_problem *pb, const struct anvil_wave_job *j,
		      const struct anvil_result *r, double march)
{
	double e = r->Pmax.err / r->Pmax.val, tgt = anvil_accuracy_target(pb->accuracy);
	return pb->scheme != ANVIL_SCHEME_PAPER && !(pb->dt > 0) && r->tmax.val > 0 &&
	       r->tmax.val < j->nsteps / STEP_RISE * j->dt &&
	       (march > tgt || (e > tgt && march > 0.5 * e));
}

/* Whether the twin of this round (half the band, rest_at: the main's rest
 * time or 0) would run as the previous round's main did: that main was
 * at the same band (the twin's), with the same window rule, the same
 * step and rest_at 0; so the twin is it when rest_at is 0 (no rest to
 * align to; the previous main came to rest by itself or not, as the twin
 * would) or when the previous main came to rest at the same node as this
 * one (rest_at then stops the twin where it came to rest by itself).
 * The twin's response is the first half of this round's spectrum, the
 * previous main's its own spectrum: the same terms, their k-integrals
 * to the previous band's tolerance, not this one's.  On the grid's rows
 * (copper on steel, h = 0.05-0.5 r0) the two runs' P_max agreed to 1e-11
 * - 5e-10 of it, t_max to 1e-9, R_f to 4e-7 of its value (at rest, 2e-11
 * absolute against the target's 1e-4): far inside the estimates they
 * make, at the cost of one impact (0.3-1 s on those rows). */
static int twin_is_prev(const struct anvil_result *prev, double rest_at)
{
	return rest_at == 0.0 || (prev->rest_bound > 0 && prev->ts.val == rest_at);
}

/* What run_waves reports besides the result. */
struct waves_out {
	int used_corr; /* 1: the layer correction was used */
	double band;   /* its band, 1/s (0: none) */
	double march;  /* the march's own part of P_max's estimate (relative), without the band's */
	double band_part; /* the band's part of it, relative (0: not measured) */
	double tau_end; /* the window the result came from (r0/c2 units) */
	int round;     /* in: the band's round to start from (0: the plan's band); out: the result's */
};

/* The coupled run of job j (the anvil's response: static, half-space, or
 * half-space plus layer correction), with the layer correction's error
 * estimate when it is used.  flags: WAVES_STOP_COARSE, the rounds end as
 * soon as the step is seen too coarse (step_rerun: the caller reruns at a
 * finer step, and a wider band here is thrown away with it);
 * WAVES_CAUSAL, causal_probe. */
#define WAVES_STOP_COARSE 1
#define WAVES_CAUSAL 2
static int run_waves(struct anvil_solver *s, const struct anvil_problem *pb,
		     const struct anvil_wave_job *j, int method, size_t nhist,
		     struct anvil_result *r, struct waves_out *o, int flags,
		     struct anvil_err *err)
{
	struct waves wv = { .pb = pb, .job = j, .causal = flags & WAVES_CAUSAL };
	wv.io = (struct anvil_impact_opts){ .scheme = pb->scheme, .dt = pb->dt, .dt_auto = j->dt,
					    .max_steps = ANVIL_MAX_STEPS, .nhist = nhist };
	solver_merge_opts(&wv.io, pb, j); /* the paper's contact as the physical (the paper's scheme: none) */
	int st = ANVIL_OK;
	if (method == ANVIL_METHOD_STATIC)
		wv.rs.stat = j->stat;
	else if (!(wv.rs.hs = solver_held_add(&wv.held, anvil_cache_halfspace(s->cache, pb->p.nu,
									 j->hs_tol, err))))
		return err ? err->status : ANVIL_ENUM;
	/* The layer correction's error is measured by halving its bandwidth
	 * (the twin: the same spectrum's first half, made with the response);
	 * when that estimate misses the target, the bandwidth doubles (up to
	 * refine_max times): convergence in it is fast, the estimate
	 * conservative. */
	/* the layer's runs keep their passes' nodes for the twin's
	 * comparisons (solver_twin.c), the caller's samples made at the end */
	wv.io.hist_nodes = method == ANVIL_METHOD_LAYER;
	double tgt = anvil_accuracy_target(pb->accuracy);
	struct anvil_result prev; /* the previous round's main (twin_is_prev) */
	double prev_tau = 0;
	int first = o->round;
	anvil_result_init(&prev, r->model);
	o->band_part = 0;
	for (int refine = first; refine <= j->refine_max; refine++) {
		o->round = refine;
		double omega = j->omega * (double)(1 << refine);
		int idx = j->omega_idx + refine * ANVIL_CACHE_STEPS;
		wv.io.rest_at = 0;
		if (refine > first) { /* r: the previous round's main, kept for this one's twin */
			anvil_result_free(&prev);
			prev = *r;
			prev_tau = wv.tau_end;
			anvil_result_init(r, prev.model);
		}
		st = waves_impact(s, &wv, omega, idx, 0, r, err);
		o->used_corr = wv.rs.corr != NULL;
		o->band = o->used_corr ? anvil_cache_grid(idx) * pb->p.c2 / pb->p.r0 : 0.0;
		double before[3];
		solver_target_errs(r, before);
		o->march = before[0];
		o->band_part = 0;
		if (st || !wv.rs.corr)
			break;
		struct anvil_result coarse;
		anvil_result_init(&coarse, r->model);
		wv.io.rest_at = r->rest_bound > 0 ? r->ts.val : 0.0; /* the twin at the rest's time */
		const struct anvil_result *tw = &coarse;
		if (refine > first && twin_is_prev(&prev, wv.io.rest_at)) {
			tw = &prev;
			wv.tau_end = prev_tau;
		} else {
			st = waves_impact(s, &wv, 0.5 * omega, idx - ANVIL_CACHE_STEPS, 1, &coarse, err);
		}
		if (!st) {
			solver_add_green_error(r, tw, o->band);
			o->band_part = r->Pmax.err / r->Pmax.val - o->march;
		}
		int twin_lost = twin_failed(st, &coarse);
		anvil_result_free(&coarse);
		if (twin_lost && refine < j->refine_max &&
		    !anvil_wave_refuse(&pb->p, pb->dt, r->model, j, wv.tau_end, 2.0 * omega, NULL)) {
			anvil_err_clear(err);
			st = ANVIL_OK;
			continue;
		}
		if (st || refine >= j->refine_max || solver_check_target(r, pb->accuracy, NULL) == ANVIL_OK ||
		    !band_dominates(r, before, tgt) || ((flags & WAVES_STOP_COARSE) && step_rerun(pb, j, r, o->march)))
			break;
		/* a refinement the rule would refuse is not tried: the result
		 * stands, and run_anvil says it missed the target */
		if (anvil_wave_refuse(&pb->p, pb->dt, r->model, j, wv.tau_end, 2.0 * omega, NULL))
			break;
	}
	o->tau_end = wv.tau_end;
	anvil_result_free(&prev);
	solver_held_release(s->cache, &wv.held);
	if (wv.io.hist_nodes && r->hist.n && history_from_nodes(r, nhist) && !st)
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
	else if (!corr) {
		/* digits enough to tell the two apart: h = 1000 r0, 100 kg at
		 * 100 m/s ends at 1330.7 us, the reflection back at 1334.7 */
		int d = 3;
		char a[32], b[32];
		do {
			snprintf(a, sizeof a, "%.*g", d, t_refl);
			snprintf(b, sizeof b, "%.*g", d, r->ts.val * 1e6);
		} while (!strcmp(a, b) && ++d < 8);
		snprintf(r->note, sizeof r->note,
			 "bottom reflection returns at 2h/c1 = %s us, after the contact (%s us): half-space response is exact here",
			 a, b);
	}
}

/* The rest state (impact.h, rest_tol) in the note: when, and the bound. */
void solver_rest_note(struct anvil_result *r)
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
void solver_contacts_note(struct anvil_result *r)
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


/* The band's round the rerun at the finer step starts from: the one the
 * first run reached, or the next where the band's part of P_max's
 * estimate there was over the target by itself.  A finer step resolves
 * the band's content at least as well as the coarse one: the band's part
 * there was no smaller on the grid (h = 0.05-0.5 r0, 10 mm/s-100 m/s,
 * 1-100 kg: at the coarse step 1.6e-2, 2.1e-2, 1.2e-3, 4.8e-3 against
 * 1.9e-2, 3.0e-2, 2.0e-3, 1.9e-2 at the fine one), so the rerun would
 * take that round only to double its band, two impacts thrown away.  Not
 * a round the rule refuses (at the coarse run's window). */
static int rerun_round(const struct anvil_problem *pb, const struct anvil_wave_job *fine,
		       enum anvil_model m, const struct waves_out *o)
{
	double omega = fine->omega * (double)(1 << o->round);
	if (o->used_corr && o->band_part > anvil_accuracy_target(pb->accuracy) &&
	    o->round < fine->refine_max &&
	    !anvil_wave_refuse(&pb->p, pb->dt, m, fine, o->tau_end, 2.0 * omega, NULL))
		return o->round + 1;
	return o->round;
}

/* A wave row (STATIC, HALFSPACE or LAYER) as the plan says, with its
 * fallback when the computed contact outlasts the reflection. */
static int run_anvil(struct anvil_solver *s, const struct anvil_plan *pl,
		     const struct anvil_plan_row *planned, size_t nhist, struct anvil_result *r,
		     struct anvil_err *err)
{
	const struct anvil_params *p = &pl->pb.p;
	struct anvil_plan_row row = *planned;
	if (row.contact == ANVIL_CONTACT_PHYSICAL)
		return solver_run_physical(s, pl, planned, nhist, r, err);
	double step = 1;
	struct waves_out o = { 0 };
	int st = run_waves(s, &pl->pb, &row.job, row.method, nhist, r, &o,
			   WAVES_STOP_COARSE | (row.fallback ? 0 : WAVES_CAUSAL), err);
	/* Causality made the half-space exact only if the contact really ended
	 * before the reflection came back: else the layer after all. */
	if (!st && row.fallback && !(r->ts.val < 2.0 * p->h / p->c1)) {
		row.method = ANVIL_METHOD_LAYER;
		row.why = ANVIL_WHY_NOT_ASKED;
		row.exact = 1;
		row.model_err = 0;
		row.job = row.fallback_job;
		o = (struct waves_out){ 0 };
		st = run_waves(s, &pl->pb, &row.job, row.method, nhist, r, &o, WAVES_STOP_COARSE, err);
	}
	if (st)
		return st;
	if (step_rerun(&pl->pb, &row.job, r, o.march)) {
		struct anvil_plan_row fine = row;
		struct anvil_result prev = *r; /* it owns the history now */
		struct anvil_err pe = err ? *err : (struct anvil_err){ 0 };
		fine.job.dt = STEP_RISE * r->tmax.val / row.job.nsteps;
		struct waves_out o2 = { .round = rerun_round(&pl->pb, &fine.job, r->model, &o) };
		anvil_result_init(r, prev.model);
		int s2 = run_waves(s, &pl->pb, &fine.job, fine.method, nhist, r, &o2, WAVES_CAUSAL, err);
		if (s2 || !(r->Pmax.err < prev.Pmax.err)) {
			anvil_result_free(r);
			*r = prev;
			if (err)
				*err = pe;
		} else {
			anvil_result_free(&prev);
			step = fine.job.dt / row.job.dt;
			row = fine;
			o = o2;
		}
	}
	if (!row.exact && row.why != ANVIL_WHY_FORCED)
		solver_add_model_error(r, p, row.model_err);
	solver_tmax_from_pmax(r, o.band);
	if (r->model == ANVIL_MODEL_HALFSPACE || !isfinite(p->h)) {
		/* Zener's plate parameter has no meaning for a half-space */
		r->lambda_star = 0.0;
		r->Rf_star = 1.0;
	}
	waves_note(r, p, &row, row.method, o.used_corr);
	if (step < 1) {
		size_t len = strlen(r->note);
		snprintf(r->note + len, sizeof r->note - len,
			 "%sthe step %.2g of the plan's (the force peaked within a few of its steps)",
			 len ? "; " : "", step);
	}
	solver_rest_note(r);
	solver_contacts_note(r);
	return pl->pb.scheme == ANVIL_SCHEME_PAPER ? ANVIL_OK : solver_graze(r, pl->pb.accuracy, solver_check_target(r, pl->pb.accuracy, err), err);
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
