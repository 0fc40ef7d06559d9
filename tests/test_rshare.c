/* test_rshare: the ramps' tables shared by impacts (impact_rtab.c,
 * impact.h anvil_ramp_share), as a physical row shares them: three
 * physical impacts with one ramp and two different ramp2's (one fn, other
 * contexts: only the names tell them apart), on the growing step, in and
 * out of long mode (the rows beyond the table), each alone and then
 * through one share:
 *  - one after another through the share: every impact's results have
 *    the bits it has alone (the values are the same calls', and the
 *    names keep the two ramp2's apart);
 *  - the share serves: an impact after another with the same ramp makes
 *    fewer ramp calls than alone (counted);
 *  - on two threads side by side through a fresh share, several times:
 *    the same bits again (the tables' entries published atomically). */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "impact.h"
#include "params.h"
#include "paper.h"
#include "tap.h"

/* A smooth kernel (test_grow's): a dashpot w' = P/c plus b t log(1 +
 * t/t1); calls counted (atomic: impacts on threads call it too). */
struct kern {
	const struct anvil_params *p;
	double c, b, t1;
	atomic_size_t calls;
};

static int kern_ramp(void *ctx, double tau, double *val)
{
	struct kern *k = ctx;
	const struct anvil_params *p = k->p;
	double t = tau * p->r0 / p->c2;
	atomic_fetch_add_explicit(&k->calls, 1, memory_order_relaxed);
	*val = p->mu * p->c2 * (t * t / (2.0 * k->c) + k->b * t * log1p(t / k->t1));
	return ANVIL_OK;
}

/* One impact: ramp r0, ramp2 r2 (NULL: none) with its name, long mode
 * (nodes) or not (0), through share (NULL: alone). */
struct job {
	struct kern *r0, *r2;
	double name2;
	size_t nodes;
	struct anvil_ramp_share *share;
	struct anvil_result r;
	int st;
};

static void *job_run(void *arg)
{
	struct job *j = arg;
	const struct anvil_params *p = j->r0->p;
	double dt = p->T / 400;
	struct anvil_impact_opts o = { .scheme = ANVIL_SCHEME_IMPLICIT, .dt = dt,
				       .max_steps = j->nodes ? j->nodes : 100000000,
				       .grow_after = 8 * 400,
				       .grow_eta = (M_PI / 400) * (M_PI / 400), .physical = 1,
				       .beta = 0, .t_smooth = j->nodes ? 0.5 * p->T : 0.0,
				       .share = j->share, .ramp_name = { 1, 0, 0 },
				       .ramp2_name = { j->name2, 0, 0 } };
	if (j->r2) {
		o.ramp2 = kern_ramp;
		o.ramp2_ctx = j->r2;
		o.alpha_ref = 2e-6;
	}
	struct anvil_err e;
	anvil_result_init(&j->r, ANVIL_MODEL_LAYER);
	j->st = anvil_impact_run(p, kern_ramp, j->r0, 300 * p->T * p->c2 / p->r0, &o, &j->r, &e);
	if (j->st)
		diag("impact: %s", e.msg);
	return NULL;
}

/* The same bits in every value and estimate. */
static int same(const struct anvil_result *a, const struct anvil_result *b)
{
	const struct anvil_val *x[] = { &a->ts, &a->tmax, &a->Pmax, &a->Vs, &a->Rf, &a->Ea };
	const struct anvil_val *y[] = { &b->ts, &b->tmax, &b->Pmax, &b->Vs, &b->Rf, &b->Ea };
	for (size_t i = 0; i < sizeof x / sizeof *x; i++)
		if (memcmp(&x[i]->val, &y[i]->val, sizeof(double)) ||
		    memcmp(&x[i]->err, &y[i]->err, sizeof(double)))
			return 0;
	return a->ncontacts == b->ncontacts;
}

#define NJ 3

int main(void)
{
	gsl_set_error_handler_off();
	plan(8);
	struct anvil_params p;
	paper_params(&p, INFINITY, 10);
	double c = p.m1 / (10 * p.T);
	/* the ramp, and two a little stiffer as the patches' */
	struct kern k0 = { &p, c, 0.2 * p.T / c, 2.0 * p.T, 0 };
	struct kern k1 = { &p, 1.02 * c, 0.2 * p.T / c, 2.0 * p.T, 0 };
	struct kern k2 = { &p, c, 0.19 * p.T / c, 2.0 * p.T, 0 };
	for (int lng = 0; lng < 2; lng++) {
		size_t nodes = lng ? 20000 : 0;
		const char *mode = lng ? "long mode" : "one table";
		struct job a[NJ] = { { &k0, &k1, 2, nodes, NULL, { 0 }, 0 },
				     { &k0, &k2, 3, nodes, NULL, { 0 }, 0 },
				     { &k0, NULL, 0, nodes, NULL, { 0 }, 0 } };
		struct job b[NJ];
		size_t alone = 0;
		int st = 0;
		for (int i = 0; i < NJ; i++) {
			atomic_store(&k0.calls, 0);
			job_run(&a[i]);
			st |= a[i].st;
			if (i == NJ - 1)
				alone = atomic_load(&k0.calls);
		}
		if (!ok(!st, "%s: three physical impacts, one ramp, two ramp2's, alone", mode))
			return done_testing();
		diag("%s: t_s = %.10g T, %.10g T, %.10g T", mode, a[0].r.ts.val / p.T,
		     a[1].r.ts.val / p.T, a[2].r.ts.val / p.T);
		/* one after another through one share */
		struct anvil_ramp_share *sh = anvil_ramp_share_alloc();
		size_t shared = 0;
		int eq = sh != NULL;
		for (int i = 0; i < NJ && sh; i++) {
			b[i] = a[i];
			b[i].share = sh;
			atomic_store(&k0.calls, 0);
			job_run(&b[i]);
			if (i == NJ - 1)
				shared = atomic_load(&k0.calls);
			eq = eq && !b[i].st && same(&a[i].r, &b[i].r);
			anvil_result_free(&b[i].r);
		}
		anvil_ramp_share_free(sh);
		ok(eq, "%s: one after another through a share, each impact's bits are its own alone",
		   mode);
		ok(shared < alone,
		   "%s: the share serves: the third impact calls the ramp %zu times, %zu alone",
		   mode, shared, alone);
		/* side by side on two threads, a fresh share each round */
		int teq = 1, rounds = 4;
		for (int k = 0; k < rounds && teq; k++) {
			pthread_t th;
			sh = anvil_ramp_share_alloc();
			for (int i = 0; i < NJ; i++)
				b[i] = a[i], b[i].share = sh;
			int i0 = k % NJ, i1 = (k + 1) % NJ, i2 = (k + 2) % NJ;
			int made = sh && !pthread_create(&th, NULL, job_run, &b[i0]);
			if (made) {
				job_run(&b[i1]);
				pthread_join(th, NULL);
				job_run(&b[i2]);
			}
			teq = made;
			for (int i = 0; i < NJ && made; i++) {
				teq = teq && !b[i].st && same(&a[i].r, &b[i].r);
				anvil_result_free(&b[i].r);
			}
			anvil_ramp_share_free(sh);
		}
		ok(teq, "%s: two impacts on two threads through one share (%d rounds): the same bits",
		   mode, rounds);
		for (int i = 0; i < NJ; i++)
			anvil_result_free(&a[i].r);
	}
	return done_testing();
}
