/* plan_share.c: responses shared by the scenes of a sweep (plan.h,
 * anvil_plan_share): the envelope of their jobs, a function of the sweep
 * alone, so shards, cold and warm runs give the same bits. */
#include <math.h>

#include "cache.h"
#include "plan.h"

static int share_group(const struct anvil_plan_share *sh, const struct anvil_plan *pl)
{
	return sh->hh == pl->pb.hh && sh->nu == pl->pb.p.nu && sh->acc == pl->pb.accuracy;
}

/* Whether job j of a row asks for a layer response at all. */
static int share_job_uses(const struct anvil_wave_job *j)
{
	return isfinite(j->hh);
}

static void share_widen(struct anvil_plan_share *sh, const struct anvil_wave_job *j, int phys)
{
	int t = anvil_cache_grid_up(anvil_wave_window(j, 0));
	if (!share_job_uses(j))
		return;
	sh->used++;
	if (!sh->n[phys]++ || j->omega_idx > sh->omega_idx[phys])
		sh->omega_idx[phys] = j->omega_idx;
	if (sh->n[phys] == 1 || t > sh->tau_idx[phys])
		sh->tau_idx[phys] = t;
	if (phys)
		sh->patch = fmax(sh->patch, j->patch);
}

static void share_add_row(struct anvil_plan_share *sh, const struct anvil_plan_row *r)
{
	if (r->status || (r->method != ANVIL_METHOD_LAYER && !r->fallback))
		return;
	share_widen(sh, r->method == ANVIL_METHOD_LAYER ? &r->job : &r->fallback_job,
		    r->contact == ANVIL_CONTACT_PHYSICAL);
}

int anvil_plan_share_add(struct anvil_plan_share *sh, const struct anvil_plan *pl)
{
	if (!sh->used && !sh->hh) {
		*sh = (struct anvil_plan_share){ .hh = pl->pb.hh, .nu = pl->pb.p.nu,
						 .acc = pl->pb.accuracy };
	} else if (!share_group(sh, pl)) {
		return ANVIL_EINVAL;
	}
	share_add_row(sh, &pl->row[ANVIL_MODEL_LAYER]);
	share_add_row(sh, &pl->paper[ANVIL_MODEL_LAYER]);
	return ANVIL_OK;
}

int anvil_plan_share_merge(struct anvil_plan_share *a, const struct anvil_plan_share *b)
{
	if (a->hh != b->hh || a->nu != b->nu || a->acc != b->acc)
		return ANVIL_EINVAL;
	for (int k = 0; k < 2; k++) {
		if (!b->n[k])
			continue;
		if (!a->n[k] || b->omega_idx[k] > a->omega_idx[k])
			a->omega_idx[k] = b->omega_idx[k];
		if (!a->n[k] || b->tau_idx[k] > a->tau_idx[k])
			a->tau_idx[k] = b->tau_idx[k];
		a->n[k] += b->n[k];
	}
	a->patch = fmax(a->patch, b->patch);
	a->used += b->used;
	return ANVIL_OK;
}

/* Job j on its contact's envelope, unless the envelope would be refused
 * where j is not (more terms than the solver takes). */
static void share_job(struct anvil_wave_job *j, const struct anvil_plan_share *sh,
		      const struct anvil_plan *pl, enum anvil_model m, int physical)
{
	struct anvil_wave_job w = *j;
	if (!share_job_uses(j) || !sh->n[physical])
		return;
	if (sh->omega_idx[physical] > w.omega_idx) {
		w.omega_idx = sh->omega_idx[physical];
		w.omega = anvil_cache_grid(w.omega_idx);
		w.twin_idx = w.omega_idx - ANVIL_CACHE_STEPS;
	}
	w.tau_idx_min = sh->tau_idx[physical];
	if (physical)
		w.patch = fmax(w.patch, sh->patch);
	if (!anvil_wave_refuse(&pl->pb.p, pl->pb.dt, m, &w, anvil_wave_window(&w, 0), w.omega,
			       NULL))
		*j = w;
}

static void share_row(struct anvil_plan_row *r, const struct anvil_plan_share *sh,
		      const struct anvil_plan *pl)
{
	int phys = r->contact == ANVIL_CONTACT_PHYSICAL;
	if (r->status)
		return;
	if (r->method == ANVIL_METHOD_LAYER)
		share_job(&r->job, sh, pl, ANVIL_MODEL_LAYER, phys);
	if (r->fallback)
		share_job(&r->fallback_job, sh, pl, ANVIL_MODEL_LAYER, phys);
}

void anvil_plan_share_apply(struct anvil_plan *pl, const struct anvil_plan_share *sh)
{
	if (!sh->used || !share_group(sh, pl))
		return;
	share_row(&pl->row[ANVIL_MODEL_LAYER], sh, pl);
	share_row(&pl->paper[ANVIL_MODEL_LAYER], sh, pl);
}

