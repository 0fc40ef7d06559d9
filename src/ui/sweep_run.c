/* sweep_run.c: a sweep's scenes on several threads, one solver each
 * (a solver is used from one thread at a time: solver.h).
 *
 * Scenes that share a layer response (the same h/r0, layer nu and
 * accuracy: cache.h's key less the window) form one unit of work, run by
 * one thread in scene order, so that a velocity sweep makes its responses
 * once and reuses them from that solver's memory; units go to threads as
 * they come free, and a thread left without a unit takes scenes from the
 * back of the longest one left (a thin layer's unit can be most of a
 * sweep's work).  Before any runs, every scene of the sweep (not only the
 * shard's) is planned, and each group of scenes sharing a response runs on
 * the group's envelope (plan.h, anvil_plan_share): one window, bandwidth
 * and patch for all, so a velocity sweep makes its responses once, and
 * every shard, thread count and resumed run makes the same choice.  Results are handed back in scene order whatever thread
 * made them, and each is the same bits whichever solver ran it (exact
 * cache lookups), so the output does not depend on the thread count. */
#include <errno.h>
#include <stdint.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "common.h"
#include "solver.h"
#include "sweep.h"

int sweep_cores(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);
	return n < 1 ? 1 : n > 256 ? 256 : (int)n;
}

struct unit_key {
	double hr0, nu;
	int acc;
	size_t s;
};

static int key_cmp(const void *a, const void *b)
{
	const struct unit_key *x = a, *y = b;
	if (x->acc != y->acc)
		return x->acc < y->acc ? -1 : 1;
	if (x->nu != y->nu)
		return x->nu < y->nu ? -1 : 1;
	if (x->hr0 != y->hr0)
		return x->hr0 < y->hr0 ? -1 : 1;
	return x->s < y->s ? -1 : x->s > y->s;
}

/* A scene's group (what a layer response depends on, the plan's own h/r0
 * bits) and its envelope, for sorting. */
struct share_key {
	struct anvil_plan_share sh;
	size_t s;
};

struct pool {
	const struct sweep *sw;
	struct anvil_plan_share *share; /* by scene - s0: its group's envelope */
	size_t s0, s1;
	const unsigned char *skip;
	struct unit_key *order; /* scenes by unit */
	size_t *front, *end;    /* each unit is order[front, end): its front
				 * advances as its thread runs it, its end
				 * comes back when others help (pool_take) */
	size_t nunit, next;     /* next unit to hand out */
	struct sweep_done **slot;
	size_t done;
	int live;     /* workers running */
	volatile sig_atomic_t halt; /* stop handing out work (emit failed) */
	volatile sig_atomic_t *stop;
	pthread_mutex_t mu;
	pthread_cond_t cv;
	struct sweep_stats stats;
};

static int halted(struct pool *p)
{
	return p->halt || (p->stop && *p->stop);
}

/* The solver's progress callback: cancels the run under way on a signal. */
static int pool_cancel(void *ctx, double fraction, const char *what)
{
	(void)fraction;
	(void)what;
	return halted(ctx);
}

static void pool_warn(void *ctx, const char *msg)
{
	(void)ctx;
	cli_error("warning: %s", msg);
}

/* R_f outside [0, 1] beyond its error: the impactor still moves in at the
 * end of contact and will strike again (as anvil run says). */
static void note_unphysical(struct anvil_result *r)
{
	double tol = (isfinite(r->Rf.err) ? fabs(r->Rf.err) : 0) + 1e-9;
	if (r->status == ANVIL_OK && isfinite(r->Rf.val) && (r->Rf.val < -tol || r->Rf.val > 1 + tol))
		snprintf(r->why, sizeof r->why, "R_f outside 0..1: the contact ends with the impactor "
			 "still moving in: re-contact not modelled");
}

/* Scene idx (sc, st and err from sweep_scene; err takes the plan's) into d. */
static void run_scene(struct anvil_solver *s, const struct anvil_scene *sc, int st,
		      struct anvil_err *err, const struct anvil_plan_share *share, size_t idx,
		      struct sweep_done *d)
{
	struct anvil_plan pl;
	d->scene = idx;
	d->st = st;
	if (!d->st)
		d->st = cli_plan(sc, anvil_solver_cache(s), &pl, err);
	if (!d->st && share)
		anvil_plan_share_apply(&pl, share);
	if (!d->st && !anvil_scene_models(sc))
		d->st = anvil_err_set(err, ANVIL_EINVAL, "no model to run");
	if (d->st) {
		snprintf(d->why, sizeof d->why, "%s", err->msg[0] ? err->msg : anvil_strerror(d->st));
		return;
	}
	struct sweep_rowkey k[SWEEP_MAXROWS];
	int nk = sweep_scene_rows(sc, k);
	for (int i = 0; i < nk && k[i].model < ANVIL_MODEL_COUNT; i++) {
		anvil_solver_run_contact(s, &pl, k[i].model, k[i].contact, 0, &d->r[d->n], NULL);
		note_unphysical(&d->r[d->n]);
		d->n++;
	}
}

/* The next scene for a thread working on unit *u (under the lock): the
 * front of its own unit, else the next unit not started, else the back of
 * the unit with the most scenes left (a thread that runs out of units
 * helps with the longest one instead of idling: balance at the end costs
 * only the responses the two threads then make twice).  1 if any. */
static int pool_take(struct pool *p, size_t *u, size_t *idx)
{
	if (*u < p->nunit && p->front[*u] < p->end[*u]) {
		*idx = p->order[p->front[*u]++].s;
		return 1;
	}
	if (p->next < p->nunit) {
		*u = p->next++;
		*idx = p->order[p->front[*u]++].s;
		return 1;
	}
	size_t best = p->nunit, left = 0;
	for (size_t v = 0; v < p->nunit; v++)
		if (p->end[v] - p->front[v] > left)
			left = p->end[v] - p->front[v], best = v;
	if (!left)
		return 0;
	*idx = p->order[--p->end[best]].s;
	return 1;
}

/* A scene with any run cut short by a signal (the models after it may
 * still finish: the half-space after a cancelled layer row) is no result:
 * kept, --resume would take its cancelled row for a failed one. */
static int cut_short(const struct sweep_done *d)
{
	if (d->st == ANVIL_ECANCEL)
		return 1;
	for (int i = 0; i < d->n; i++)
		if (d->r[i].status == ANVIL_ECANCEL)
			return 1;
	return 0;
}

static void *worker(void *arg)
{
	struct pool *p = arg;
	struct anvil_solver *s = anvil_solver_alloc();
	size_t u = SIZE_MAX, idx;
	if (s) {
		anvil_solver_set_progress(s, pool_cancel, p);
		anvil_solver_set_warn(s, pool_warn, NULL);
	}
	pthread_mutex_lock(&p->mu);
	while (s && !halted(p) && pool_take(p, &u, &idx)) {
		if (p->skip && p->skip[idx - p->s0])
			continue;
		/* the scene made under the lock: once halted, no worker reads
		 * the sweep again (a signal leaves runs under way to end with
		 * the process, and the caller frees the sweep: sweep_run) */
		struct anvil_scene sc;
		struct anvil_err err = {0};
		int sst = sweep_scene(p->sw, idx, &sc, &err);
		pthread_mutex_unlock(&p->mu);
		struct sweep_done *d = calloc(1, sizeof *d);
		if (d)
			run_scene(s, &sc, sst, &err, p->share ? &p->share[idx - p->s0] : NULL, idx, d);
		pthread_mutex_lock(&p->mu);
		if (!d)
			p->halt = 1;
		else if (halted(p) && cut_short(d)) {
			for (int i = 0; i < d->n; i++)
				anvil_result_free(&d->r[i]);
			free(d), d = NULL;
		}
		p->slot[idx - p->s0] = d;
		p->done += d != NULL;
		pthread_cond_broadcast(&p->cv);
	}
	if (s) {
		struct anvil_solver_stats st;
		anvil_solver_stats(s, &st);
		p->stats.responses += st.layer_computed;
		p->stats.mem_hits += st.cache.mem_hits;
		p->stats.disk_hits += st.cache.disk_hits;
	} else {
		p->halt = 1;
	}
	p->live--;
	pthread_cond_broadcast(&p->cv);
	pthread_mutex_unlock(&p->mu);
	anvil_solver_free(s);
	return NULL;
}

static int share_cmp(const void *a, const void *b)
{
	const struct share_key *x = a, *y = b;
	if (x->sh.acc != y->sh.acc)
		return x->sh.acc < y->sh.acc ? -1 : 1;
	if (x->sh.nu != y->sh.nu)
		return x->sh.nu < y->sh.nu ? -1 : 1;
	if (x->sh.hh != y->sh.hh)
		return x->sh.hh < y->sh.hh ? -1 : 1;
	return x->s < y->s ? -1 : x->s > y->s;
}

/* The envelope of each scene's group over the whole sweep (every shard's
 * scenes: the same choice in every shard), for the scenes [s0, s1).  A
 * scene that cannot be planned adds nothing (its row says why). */
static int pool_shares(struct pool *p)
{
	size_t n = p->sw->nscenes, n1 = p->s1 - p->s0;
	struct share_key *k = calloc(n + 1, sizeof *k);
	p->share = calloc(n1 + 1, sizeof *p->share);
	if (!k || !p->share) {
		free(k);
		return ANVIL_ENOMEM;
	}
	for (size_t i = 0; i < n; i++) {
		struct anvil_scene sc;
		struct anvil_plan pl;
		k[i].s = i;
		if (!sweep_scene(p->sw, i, &sc, NULL) && !cli_plan(&sc, NULL, &pl, NULL))
			anvil_plan_share_add(&k[i].sh, &pl);
	}
	qsort(k, n, sizeof *k, share_cmp);
	for (size_t i = 0, j; i < n; i = j) {
		struct anvil_plan_share env = k[i].sh;
		for (j = i + 1; j < n && !share_cmp(&(struct share_key){ k[i].sh, 0 },
						    &(struct share_key){ k[j].sh, 0 }); j++)
			anvil_plan_share_merge(&env, &k[j].sh);
		for (size_t m = i; m < j; m++)
			if (k[m].s >= p->s0 && k[m].s < p->s1)
				p->share[k[m].s - p->s0] = env;
	}
	free(k);
	return ANVIL_OK;
}

/* Units: the scenes sorted by response key, cut where the key changes. */
static int pool_units(struct pool *p)
{
	size_t n = p->s1 - p->s0;
	p->order = malloc((n + 1) * sizeof *p->order);
	p->front = malloc((n + 1) * sizeof *p->front);
	p->end = malloc((n + 1) * sizeof *p->end);
	p->slot = calloc(n + 1, sizeof *p->slot);
	if (!p->order || !p->front || !p->end || !p->slot)
		return ANVIL_ENOMEM;
	for (size_t i = 0; i < n; i++) {
		struct anvil_scene sc;
		sweep_scene(p->sw, p->s0 + i, &sc, NULL);
		p->order[i] = (struct unit_key){anvil_scene_h(&sc) / sc.radius, sc.layer.mat.nu,
						(int)sc.accuracy, p->s0 + i};
	}
	qsort(p->order, n, sizeof *p->order, key_cmp);
	p->nunit = 0;
	for (size_t i = 0; i < n; i++)
		if (i == 0 || p->order[i].hr0 != p->order[i - 1].hr0 || p->order[i].nu != p->order[i - 1].nu ||
		    p->order[i].acc != p->order[i - 1].acc) {
			if (p->nunit)
				p->end[p->nunit - 1] = i;
			p->front[p->nunit++] = i;
		}
	if (p->nunit)
		p->end[p->nunit - 1] = n;
	return ANVIL_OK;
}

static void deadline(struct timespec *ts, double seconds)
{
	clock_gettime(CLOCK_REALTIME, ts);
	long ns = ts->tv_nsec + (long)(seconds * 1e9);
	ts->tv_sec += ns / 1000000000L;
	ts->tv_nsec = ns % 1000000000L;
}

/* Hand results to emit in scene order as they arrive. */
static int pool_drain(struct pool *p, sweep_emit_fn emit, sweep_tick_fn tick, void *ctx)
{
	size_t next = 0, n = p->s1 - p->s0;
	int st = ANVIL_OK;
	double ticked = 0;
	pthread_mutex_lock(&p->mu);
	while (next < n) {
		if (p->skip && p->skip[next]) {
			next++;
			continue;
		}
		struct sweep_done *d = p->slot[next];
		if (!d) {
			/* stopped: nothing more will come, or a signal, which wakes
			 * no condition: looked at every 20 ms (the runs under way
			 * are not waited for: sweep_run) */
			if (p->live == 0 || (p->stop && *p->stop))
				break;
			struct timespec ts;
			deadline(&ts, 0.02);
			pthread_cond_timedwait(&p->cv, &p->mu, &ts);
			size_t done = p->done;
			pthread_mutex_unlock(&p->mu);
			if (tick && cli_now() - ticked >= 0.2) {
				ticked = cli_now();
				tick(ctx, done);
			}
			pthread_mutex_lock(&p->mu);
			continue;
		}
		p->slot[next++] = NULL;
		pthread_mutex_unlock(&p->mu);
		if (!st && emit)
			st = emit(ctx, d);
		for (int i = 0; i < d->n; i++)
			anvil_result_free(&d->r[i]);
		free(d);
		pthread_mutex_lock(&p->mu);
		if (st)
			p->halt = 1;
	}
	pthread_mutex_unlock(&p->mu);
	if (!st && next < n)
		st = p->stop && *p->stop ? ANVIL_ECANCEL : ANVIL_ENOMEM;
	return st;
}

static void pool_free(struct pool *p)
{
	if (p->slot)
		for (size_t i = 0; i < p->s1 - p->s0; i++)
			if (p->slot[i]) {
				for (int j = 0; j < p->slot[i]->n; j++)
					anvil_result_free(&p->slot[i]->r[j]);
				free(p->slot[i]);
			}
	free(p->slot);
	free(p->share);
	free(p->order);
	free(p->front);
	free(p->end);
	pthread_mutex_destroy(&p->mu);
	pthread_cond_destroy(&p->cv);
}

int sweep_run(const struct sweep *sw, size_t s0, size_t s1, const unsigned char *skip,
	      int nthreads, sweep_emit_fn emit, sweep_tick_fn tick, void *ctx,
	      volatile sig_atomic_t *stop, struct sweep_stats *stats)
{
	/* on the heap: stopped by a signal, the threads still running hold it
	 * after the return (below) */
	struct pool *pp = calloc(1, sizeof *pp);
	pthread_t tid[256];
	sigset_t all, old;
	int st;
	if (!pp)
		return ANVIL_ENOMEM;
	struct pool *p = pp;
	*p = (struct pool){.sw = sw, .s0 = s0, .s1 = s1, .skip = skip, .stop = stop};
	pthread_mutex_init(&p->mu, NULL);
	pthread_cond_init(&p->cv, NULL);
	if ((st = pool_units(p)) || (st = pool_shares(p))) {
		pool_free(p);
		free(p);
		return st;
	}
	if (nthreads > (int)p->nunit)
		nthreads = (int)p->nunit;
	if (nthreads > 256)
		nthreads = 256;
	/* signals go to the calling thread, which sets *stop */
	sigfillset(&all);
	pthread_sigmask(SIG_BLOCK, &all, &old);
	int started = 0;
	for (; started < nthreads; started++) {
		pthread_mutex_lock(&p->mu);
		p->live++;
		pthread_mutex_unlock(&p->mu);
		if (pthread_create(&tid[started], NULL, worker, p) != 0) {
			p->live--;
			break;
		}
	}
	pthread_sigmask(SIG_SETMASK, &old, NULL);
	st = started || !nthreads ? pool_drain(p, emit, tick, ctx) : ANVIL_ENOMEM;
	pthread_mutex_lock(&p->mu);
	p->halt = 1;
	/* Stopped by a signal with runs under way: they would end first (an
	 * impact's march has no point to cancel at: a slow scene kept a Ctrl-C
	 * waiting for seconds, qa7), and their scenes are no result
	 * (cut_short).  Left to end with the process, which the caller ends
	 * now; p stays theirs. */
	int orphan = st == ANVIL_ECANCEL && p->live > 0;
	if (stats)
		*stats = p->stats;
	pthread_mutex_unlock(&p->mu);
	if (orphan) {
		for (int i = 0; i < started; i++)
			pthread_detach(tid[i]);
		return st;
	}
	for (int i = 0; i < started; i++)
		pthread_join(tid[i], NULL);
	if (stats)
		*stats = p->stats;
	pool_free(p);
	free(p);
	return st;
}
