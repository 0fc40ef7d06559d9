/* solver_phys.c: the physical contact's row (issue 10; impact.h,
 * doc/contact-model.md): Hertz's approach plus the layer's dynamic
 * remainder with the true contact radius, its five impacts (the row's and
 * its error estimate's) on threads when their responses are at hand. */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "radiation.h"
#include "solver_impl.h"

/* The cache's key of job j's correction under a Hertz load of radius patch
 * r0 (0: a point load) at bandwidth grid index omega_idx over the window of
 * grid index tau_idx: its band's contour is the one the row's widest patch
 * allows (green.h lift_patch), which all the row's loads share. */
static struct anvil_cache_key phys_key(const struct anvil_problem *pb,
				       const struct anvil_wave_job *j, int omega_idx, int tau_idx,
				       double patch)
{
	return (struct anvil_cache_key){ j->hh, pb->p.nu, pb->accuracy, omega_idx, tau_idx, 0,
					 ANVIL_CACHE_LOAD_PATCH, patch, j->patch };
}

/* The inversion's settings for key's correction (the band's: key's own) */
static void phys_settings(struct anvil_solver *s, const struct anvil_problem *pb,
			  const struct anvil_cache_key *key, struct anvil_green_settings *gs)
{
	anvil_green_settings(pb->accuracy, gs);
	gs->omega_max = anvil_cache_grid(key->omega_idx);
	gs->filter = 1; /* no ringing at the band's edge (green.h) */
	gs->plate = s->plate;
	gs->lift_patch = key->lift_patch;
}

/* The physical contact's layer correction of phys_key's load (the grids
 * of cache.h, as the paper's responses), from the cache or made and kept
 * there: a velocity or mass change, or the scenes of a sweep that share
 * the job's window, bandwidth and patch (plan.h, anvil_plan_share), reuse
 * it.  Held for this run (in held). */
static const struct anvil_green *physical_corr(struct anvil_solver *s, const struct anvil_problem *pb,
					       const struct anvil_wave_job *j, double patch,
					       int omega_idx, int tau_idx, struct held *held,
					       struct anvil_err *err)
{
	struct anvil_cache_key key = phys_key(pb, j, omega_idx, tau_idx, patch);
	const struct anvil_green *c = anvil_cache_find(s->cache, &key, NULL);
	if (c)
		return solver_held_add(held, c);
	struct anvil_green_settings gs;
	phys_settings(s, pb, &key, &gs);
	struct anvil_green *g = anvil_green_alloc_patch(ANVIL_GREEN_LAYER_CORRECTION, j->hh, pb->p.nu,
							patch, anvil_cache_grid(tau_idx), &gs,
							s->progress, s->progress_ctx, err);
	if (!g)
		return NULL;
	s->layer_computed++;
	s->layer_evals += anvil_green_evals(g);
	if (!(c = solver_held_add(held, anvil_cache_add(s->cache, &key, g))))
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

/* The half-space's remainder beyond Hertz: -beta dP/dt + g2 d^2(a P)/dt^2
 * (transform/radiation.h; impact.h). */
struct phys_rem {
	double beta, g2;
};

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
		      const struct anvil_wave_job *j, struct phys_rem rem, struct phys_load ld,
		      size_t nhist, struct anvil_ramp_share *share, struct anvil_result *r)
{
	memset(u, 0, sizeof *u);
	u->ld = ld;
	u->r = r;
	u->io = (struct anvil_impact_opts){ .scheme = ANVIL_SCHEME_IMPLICIT, .dt = pb->dt,
					    .dt_auto = j->dt, .max_steps = ANVIL_MAX_STEPS,
					    .nhist = nhist, .physical = 1, .beta = rem.beta, .g2 = rem.g2,
					    .tau_lag = ld.tau_lag };
	solver_merge_opts(&u->io, pb, j);
	u->io.rest_at = ld.rest_at;
	u->io.share = share;
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
	solver_held_release(s->cache, &u->held);
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
	/* the far field of the frozen past (impact.h t_smooth) wherever the
	 * step grows and the plate's tail makes the ramps smooth: in a long
	 * window anvil_wave_t_smooth's, which the refusal rule reads; in one
	 * that fits, the same time, the far field then a saving (impact_far.c,
	 * FAR_MIN_FIT) where the weights out to the window's end had been the
	 * march's largest cost */
	u->io.t_smooth = j->grows && u->corr
				 ? anvil_plate_t1(j->hh, anvil_cache_grid(tau_idx)) * p->r0 / p->c2
				 : 0.0;
	u->io.impulse = solver_response_impulse;
	u->io.impulse_ctx = &u->rs;
	u->io.impulse2 = NULL;
	/* the ramps' names in the row's share: their responses' cache keys
	 * (none, NaN, for the zero ramp of a window without corrections) */
	double nm = u->corr ? ld.omega_idx : NAN;
	memcpy(u->io.ramp_name, (double[3]){ nm, tau_idx, 0.0 }, sizeof u->io.ramp_name);
	memcpy(u->io.ramp2_name, (double[3]){ nm, tau_idx, ld.patch }, sizeof u->io.ramp2_name);
	if (!u->corr)
		return ANVIL_OK;
	u->rs.corr = physical_corr(s, pb, j, 0.0, ld.omega_idx, tau_idx, &u->held, err);
	if (u->rs.corr && ld.patch > 0) {
		u->rs2.corr = physical_corr(s, pb, j, ld.patch, ld.omega_idx, tau_idx, &u->held, err);
		/* a^2 = R alpha with R = r0 */
		u->io.ramp2 = solver_response_ramp;
		u->io.ramp2_ctx = &u->rs2;
		u->io.impulse2 = solver_response_impulse;
		u->io.impulse2_ctx = &u->rs2;
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
	return anvil_impact_run(&pb->p, solver_response_ramp, &u->rs, u->tau_end, &u->io, u->r, err);
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
	/* the ramps' values the runs share (impact.h; NULL: each its own):
	 * four take the point load's as their ramp, two the patch's ramp2 */
	struct anvil_ramp_share *share;
};

/* The loads: the row's, the patch below (the a^4 remainder), the lag's
 * time halved, and point loads at the row's bandwidth and half of it. */
static void phys_set_init(struct phys_set *set, const struct anvil_problem *pb,
			  const struct anvil_wave_job *j, struct phys_rem rem, struct phys_load ld,
			  size_t nhist, struct anvil_result *r)
{
	struct phys_load lds[PHYS_RUNS] = {
		[PHYS_MAIN] = ld,
		[PHYS_BELOW] = { ld.omega_idx, anvil_plan_patch_below(ld.patch), ld.tau_lag, ld.rest_at },
		[PHYS_HALF_LAG] = { ld.omega_idx, ld.patch, 0.5 * ld.tau_lag, ld.rest_at },
		[PHYS_POINT] = { ld.omega_idx, 0.0, ld.tau_lag, ld.rest_at },
		[PHYS_POINT_HALF] = { ld.omega_idx - ANVIL_CACHE_STEPS, 0.0, ld.tau_lag, ld.rest_at },
	};
	set->share = anvil_ramp_share_alloc();
	for (int k = 0; k < PHYS_RUNS; k++) {
		struct anvil_result *rk = k == PHYS_MAIN ? r : &set->q[k];
		if (k != PHYS_MAIN)
			anvil_result_init(rk, r->model);
		phys_init(&set->u[k], pb, j, rem, lds[k], k == PHYS_MAIN ? nhist : 0, set->share, rk);
		set->e[k] = (struct anvil_err){ 0 };
		set->st[k] = ANVIL_ETOL;
		set->done[k] = 0;
	}
	set->warm.n = 0;
}

/* A row at rest (impact.h, rest_at): its error runs are compared at its
 * rest time, so they are set up again to stop there (a warm row not
 * foreseen at rest, phys_rest_likely, ran them beside it before its rest
 * was known: they run twice then). */
static void phys_set_rest(struct anvil_solver *s, struct phys_set *set,
			  const struct anvil_problem *pb, const struct anvil_wave_job *j,
			  struct phys_rem rem, double rest_at)
{
	for (int k = PHYS_MAIN + 1; k < PHYS_RUNS; k++) {
		struct phys_load ld = set->u[k].ld;
		enum anvil_model m = set->q[k].model;
		solver_held_release(s->cache, &set->u[k].held);
		anvil_result_free(&set->q[k]);
		anvil_result_init(&set->q[k], m);
		ld.rest_at = rest_at;
		phys_init(&set->u[k], pb, j, rem, ld, 0, set->share, &set->q[k]);
		set->e[k] = (struct anvil_err){ 0 };
		set->st[k] = ANVIL_ETOL;
		set->done[k] = 0;
	}
}

static void phys_set_free(struct anvil_solver *s, struct phys_set *set)
{
	anvil_ramp_share_free(set->share);
	set->share = NULL;
	solver_held_release(s->cache, &set->warm);
	for (int k = 0; k < PHYS_RUNS; k++) {
		solver_held_release(s->cache, &set->u[k].held);
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
			struct anvil_cache_key key = phys_key(pb, j, ld->omega_idx,
							      anvil_wave_tau_idx(j, tau_end),
							      twice ? ld->patch : 0.0);
			if ((!twice || ld->patch > 0) &&
			    !solver_held_add(&set->warm, anvil_cache_find(s->cache, &key, NULL)))
				return 0;
		}
	return 1;
}

/* Whether the row will likely come to rest (impact.h, rest_tol): Zener's
 * plate rebounds at R_f* = exp(-1.7191 lambda*), and the rest bound is
 * 0.1 of the target (solver_merge_opts); a factor 10 of margin.  Only
 * the order of the runs hangs on it, not their bits. */
static int phys_rest_likely(const struct anvil_plan *pl)
{
	double lambda = pl->fig[ANVIL_FIG_LAMBDA];
	return lambda > 0 && exp(-1.7191 * lambda) < pl->fig[ANVIL_FIG_TARGET];
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
			struct anvil_cache_key ky = phys_key(pb, j, ld->omega_idx, tau_idx,
							     twice ? ld->patch : 0.0);
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
	phys_settings(s, pb, &key[0], &gs); /* omega_max: the loads' own */
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

/* A finished error run carried from one band to the next (solver_run_physical):
 * the point load at the band, which the band twice as wide runs again as
 * its point load at half the band.  An impact's bits are a function of
 * its load and the windows it tries (the responses come from the cache,
 * the same bits whoever made them), so where the loads match exactly the
 * result is that run's: on h = 0.1 r0, 100 kg at 0.1 m/s, refined once,
 * one of the ten impacts (0.04 of 0.67 s CPU). */
struct phys_carry {
	int valid;
	struct phys_load ld;
	struct anvil_result q; /* no history (an error run keeps none) */
};

static int same_load(const struct phys_load *a, const struct phys_load *b)
{
	return a->omega_idx == b->omega_idx && a->patch == b->patch && a->tau_lag == b->tau_lag &&
	       a->rest_at == b->rest_at;
}

/* The half band's point run from the carry when its load is the same and
 * it has not run yet. */
static void phys_reuse(struct phys_set *set, const struct phys_carry *in)
{
	int k = PHYS_POINT_HALF;
	if (!in || !in->valid || set->done[k] || !same_load(&in->ld, &set->u[k].ld))
		return;
	anvil_result_free(&set->q[k]);
	set->q[k] = in->q;
	set->st[k] = ANVIL_OK;
	set->e[k] = (struct anvil_err){ 0 };
	set->done[k] = 1;
}

/* The band's point run into the carry, for the next band (phys_reuse). */
static void phys_keep(const struct phys_set *set, struct phys_carry *out)
{
	int k = PHYS_POINT;
	out->valid = set->done[k] && set->st[k] == ANVIL_OK && !set->q[k].hist.t;
	if (!out->valid)
		return;
	out->ld = set->u[k].ld;
	out->q = set->q[k];
}

/* The errors of the layer correction (run_physical, below): the
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
	/* the super-seismic start (alpha_A not small: plan.c's warning) is
	 * what breaks the remainder's expansion in the wave effect there, not
	 * the step: a 0.1 g carbide ball at 1 km/s on pmma (alpha_A = 0.50)
	 * gave 5.07e4 N against 4.41e4 N, the half-space row's own model
	 * error 17 */
	if (r->Pmax.val > 1.05 * ph && p->alpha_A > ANVIL_PLAN_ALPHA_A_MAX)
		return anvil_err_set(err, ANVIL_EINVAL,
				     "%s: the computed P_max = %.3g N exceeds the rigid anvil's %.3g N, which bounds it (energy): alpha_A = %.2g is not small, the contact spreads faster than the waves at first, and the physical contact's expansion in the wave effect does not hold",
				     anvil_model_name(r->model), r->Pmax.val, ph, p->alpha_A);
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

/* What the physical contact leaves out of the half-space's remainder
 * (impact.h, g2; radiation.h), added to r's estimates and model_err:
 *  - the terms beyond the second order: relative q^2 of the wave effect,
 *    q = pi a / (c2 t_s) (the ratio of the second-order term to the first,
 *    (omega a / c2) at the contact's frequency pi / t_s), or f^2 where the
 *    reduction's own next term is larger; each value moves by at most that
 *    times the radiated fraction f of it (E_a: of m1 V0^2 / 2).  The
 *    first-order model carried f q here, and its measured change to the
 *    second order was 0.14-0.42 of that (tests/test_physical.c, 10-500 m/s);
 *  - the inner region (impact.c): the outer solution starts where
 *    W - w_c = c_u V0^2 and ends where it is c_u V_s^2, a shift the
 *    spreading contact's true start could change by as much again, so t_s
 *    takes (|c_u| + (3/2 beta K)^2) (V0 + |V_s|) (the first order's own
 *    start, a(0) = (3/2 beta K V0)^2, is of that size too) and t_max the
 *    start's part.  P_max, V_s, R_f and E_a do not move with a shift. */
static void physical_model_error(const struct anvil_params *p, struct phys_rem rem, double f,
				 double a, struct anvil_result *r)
{
	double q = M_PI * a / (p->c2 * r->ts.val), d = f * fmax(q, f) * fmax(q, f);
	double gk = 2.0 * rem.g2 * p->K * sqrt(p->r0), bk = rem.beta * p->K;
	double cin = fabs(gk - 1.125 * bk * bk) + 2.25 * bk * bk;
	double t0 = cin * p->V0, t1 = cin * fabs(r->Vs.val);
	r->model_err += d + (t0 + t1) / r->ts.val; /* t_s's share, the largest */
	r->ts.err += d * r->ts.val + t0 + t1;
	r->tmax.err += d * r->tmax.val + t0;
	r->Pmax.err += d * r->Pmax.val;
	r->Vs.err += d * fabs(r->Vs.val);
	r->Rf.err += d * fabs(r->Rf.val);
	r->Ea.err += d * 0.5 * p->m1 * p->V0 * p->V0;
}

/* The band's part (the point load at the band against half of it) of
 * the estimates solver_target_errs weighs, band[3]. */
static void band_part(const struct phys_set *set, const struct anvil_result *r, double band[3])
{
	const struct anvil_result *a = &set->q[PHYS_POINT], *b = &set->q[PHYS_POINT_HALF];
	band[0] = fabs(a->Pmax.val - b->Pmax.val) / r->Pmax.val;
	band[1] = r->rest_bound > 0 ? 0.0 : fabs(a->ts.val - b->ts.val) / r->ts.val;
	band[2] = fabs(a->Rf.val - b->Rf.val) / fmax(fabs(r->Rf.val), 0.1);
}

/* The physical row: Hertz's approach plus the layer's remainder, the
 * correction with the true contact radius a(t) (impact.h: point load plus
 * the a^2 term from the Hertz patch of the largest radius a_max).  Its
 * error estimates add to the time stepping's: physical_errors', and what
 * the remainder's two terms leave (physical_model_error).
 * Where the patch size still matters: thin layers, where a_max is not
 * small against h and the correction is large: there the a^4 remainder
 * is what the error estimate shows (doc/contact-model.md). */
static int physical_band(struct anvil_solver *s, const struct anvil_plan *pl,
			 const struct anvil_plan_row *row, int omega_idx, size_t nhist,
			 struct anvil_result *r, int *corr_out, double band_out[3],
			 const struct phys_carry *carry_in, struct phys_carry *carry_out,
			 struct anvil_err *err)
{
	const struct anvil_params *p = &pl->pb.p;
	struct phys_rem rem = { anvil_radiation_beta(p->nu, p->rho, p->c2),
				anvil_radiation_g2(p->nu, p->rho, p->c2) };
	double a = pl->fig[ANVIL_FIG_A_HERTZ];
	struct phys_load ld = { omega_idx, row->job.patch, a / p->c2, 0.0 };
	struct phys_set set;
	phys_set_init(&set, &pl->pb, &row->job, rem, ld, nhist, r);
	/* warm, the five impacts at once on the cores; cold, the row's first
	 * (thin_check may refuse it before the others' responses are made),
	 * and warm too where the row will likely come to rest: its error runs
	 * stop at its rest time, known only after it (run beside it, they ran
	 * twice: h = 0.05 r0, 10 kg at 0.01 m/s took 1.2 s warm, 0.55 s
	 * cold).  The bits are the same either way. */
	int at_hand = phys_at_hand(s, &pl->pb, &row->job, &set);
	int together = at_hand && !phys_rest_likely(pl);
	if (together)
		phys_reuse(&set, carry_in);
	phys_rounds(s, &pl->pb, &row->job, &set, PHYS_MAIN, together ? PHYS_RUNS : PHYS_MAIN + 1);
	int st = set.st[PHYS_MAIN], corr = set.u[PHYS_MAIN].corr;
	*corr_out = corr;
	if (st && err)
		*err = set.e[PHYS_MAIN];
	if (!st && corr)
		st = thin_check(pl, r, err);
	int rest = !st && r->rest_bound > 0;
	if (rest)
		phys_set_rest(s, &set, &pl->pb, &row->job, rem, r->ts.val);
	if (!st && corr && (!together || rest)) {
		phys_reuse(&set, carry_in);
		phys_rounds(s, &pl->pb, &row->job, &set, PHYS_MAIN + 1, PHYS_RUNS);
	}
	if (!st && corr)
		st = physical_errors(&set, fmin(1.0, a / p->r0), r, err);
	if (!st && corr)
		band_part(&set, r, band_out);
	else
		band_out[0] = band_out[1] = band_out[2] = 0.0;
	if (carry_out)
		phys_keep(&set, carry_out);
	phys_set_free(s, &set);
	if (st)
		return st;
	physical_model_error(p, rem, pl->fig[ANVIL_FIG_RADIATED], a, r);
	if (r->model == ANVIL_MODEL_HALFSPACE || !isfinite(p->h)) {
		r->lambda_star = 0.0;
		r->Rf_star = 1.0;
	}
	if (row->model_err > 0) /* the layer's reflections left out (plan.c) */
		solver_add_model_error(r, p, row->model_err);
	solver_tmax_from_pmax(r, corr ? anvil_cache_grid(ld.omega_idx) * p->c2 / p->r0 : 0.0);
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
			 "physical contact: Hertz + the half-space's remainder to second order, its radiation lag and the reactive term after it (no reflection during the contact)");
	solver_rest_note(r);
	solver_contacts_note(r);
	return solver_check_target(r, pl->pb.accuracy, err);
}

/* Whether a wider band can meet the target r misses: some output over
 * it owes most of its estimate to the band's part band[] (as run_waves'
 * band_dominates).  Not P_max alone: h = 0.1 r0, 10 g at 0.01 m/s met
 * P_max's target, but t_s missed it at 1.2e-3, nearly all of it the
 * band's (8179.36 against 8189.05 us at half the band); twice the band
 * gave 8179.10 against 8179.40. */
static int band_helps(const struct anvil_result *r, const double band[3], double tgt)
{
	double e[3];
	solver_target_errs(r, e);
	for (int i = 0; i < 3; i++)
		if (e[i] > tgt && band[i] > 0.5 * e[i])
			return 1;
	return 0;
}

/* The largest of r's estimates against the target (solver_target_errs). */
static double worst_err(const struct anvil_result *r)
{
	double e[3];
	solver_target_errs(r, e);
	return fmax(e[0], fmax(e[1], e[2]));
}

/* The physical row at the plan's bandwidth, doubled while an output's
 * estimated error misses the target and its band's part (the point load
 * at half the band: the filter's cut) is most of it (band_helps), at most
 * refine_max times, while the refusal rule takes the wider band; a wider
 * band is kept when its worst estimate is smaller.  (Copper on pmma,
 * h = 5.8 r0, missed by 1.1e-3 of which the band was little: four times
 * the band cost 60 times the work for 0.00068 -> 0.00067 kN.)
 * The plan sizes the band by the Hertz pulse (plan.c, wave_job); on a thin
 * plate the force peaks at the impact's first microseconds, long before
 * the pulse's: h = 0.1 r0 (12.2 g, 10 m/s) peaked at 4.0 us with P_max
 * 158.3 +- 10 N at the plan's band, 154.79 +- 3.4 N at twice it, 154.758
 * +- 0.011 N at four times (0.57, 0.66, 0.79 s). */
int solver_run_physical(struct anvil_solver *s, const struct anvil_plan *pl,
			const struct anvil_plan_row *row, size_t nhist, struct anvil_result *r,
			struct anvil_err *err)
{
	const struct anvil_problem *pb = &pl->pb;
	double tgt = anvil_accuracy_target(pb->accuracy);
	int idx = row->job.omega_idx, corr = 0, refined = 0;
	double band[3];
	struct phys_carry carry[2] = { { 0 }, { 0 } }; /* the last band's, the next's */
	int st = physical_band(s, pl, row, idx, nhist, r, &corr, band, NULL, &carry[0], err);
	while (st == ANVIL_WTOL && corr && refined < row->job.refine_max && band_helps(r, band, tgt) &&
	       !anvil_wave_refuse(&pb->p, pb->dt, r->model, &row->job,
				  anvil_wave_window(&row->job, 0),
				  anvil_cache_grid(idx + ANVIL_CACHE_STEPS), NULL)) {
		struct anvil_result prev = *r; /* it owns the history now */
		struct anvil_err pe = err ? *err : (struct anvil_err){ 0 };
		anvil_result_init(r, prev.model);
		int s2 = physical_band(s, pl, row, idx + ANVIL_CACHE_STEPS, nhist, r, &corr, band,
				       &carry[0], &carry[1], err);
		carry[0] = carry[1];
		if (s2 < 0 || !(worst_err(r) < worst_err(&prev))) {
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
			 "; the band %dx the plan's (the band's error)", 1 << refined);
	}
	return solver_graze(r, pb->accuracy, st, err);
}
