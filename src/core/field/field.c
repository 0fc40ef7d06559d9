/* field.c: the field object, its quantities and the checks of what is
 * asked of it.  See field.h; the method is in field_sum.c, maps in
 * field_map.c, single points in field_points.c, the peak in field_peak.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "field_impl.h"
#include "kernel.h"
#include "material.h"

/* ---- quantities ----------------------------------------------------------- */

static const struct {
	const char *name, *title;
	int stress;
} fq_info[ANVIL_FQ_COUNT] = {
	[ANVIL_FQ_U] = {"u", "radial displacement u", 0},
	[ANVIL_FQ_W] = {"w", "axial displacement w", 0},
	[ANVIL_FQ_SZZ] = {"szz", "normal stress sigma_zz", 1},
	[ANVIL_FQ_SRR] = {"srr", "radial stress sigma_rr", 1},
	[ANVIL_FQ_STT] = {"stt", "hoop stress sigma_tt", 1},
	[ANVIL_FQ_SRZ] = {"srz", "shear stress sigma_rz", 1},
	[ANVIL_FQ_VM] = {"vm", "von Mises stress", 1},
};

const char *anvil_fq_name(enum anvil_fq q)
{
	return (unsigned)q < ANVIL_FQ_COUNT ? fq_info[q].name : NULL;
}

const char *anvil_fq_title(enum anvil_fq q)
{
	return (unsigned)q < ANVIL_FQ_COUNT ? fq_info[q].title : NULL;
}

int anvil_fq_is_stress(enum anvil_fq q)
{
	return (unsigned)q < ANVIL_FQ_COUNT && fq_info[q].stress;
}

int anvil_fq_parse(const char *name)
{
	for (int q = 0; name && q < ANVIL_FQ_COUNT; q++)
		if (strcasecmp(name, fq_info[q].name) == 0)
			return q;
	return -1;
}

/* ---- the object ------------------------------------------------------------ */

static int check_load(const double *P, size_t n, double dt)
{
	if (!P || n < 3 || !(dt > 0) || !isfinite(dt))
		return 0;
	for (size_t i = 0; i < n; i++)
		if (!(P[i] >= 0) || !isfinite(P[i]))
			return 0;
	return 1;
}

struct anvil_field *anvil_field_alloc(const struct anvil_params *p, const double *P,
				      size_t n, double dt, double load_rel,
				      enum anvil_accuracy acc, struct anvil_err *err)
{
	if (!check_load(P, n, dt) || (unsigned)acc >= ANVIL_ACC_COUNT || !(p->r0 > 0) ||
	    !(p->nu > -1 && p->nu < 0.5) || !(p->h > 0)) {
		anvil_err_set(err, ANVIL_EINVAL, "field: bad load or layer (%zu samples, dt = %g s)", n, dt);
		return NULL;
	}
	struct anvil_field *f = calloc(1, sizeof *f);
	double *copy = malloc(n * sizeof *copy);
	if (!f || !copy) {
		free(f);
		free(copy);
		anvil_err_set(err, ANVIL_ENOMEM, "field: out of memory");
		return NULL;
	}
	memcpy(copy, P, n * sizeof *copy);
	*f = (struct anvil_field){
		.r0 = p->r0, .mu = p->mu, .c2 = p->c2, .nu = p->nu,
		.kap2 = anvil_kappa2(p->nu), .hh = p->h / p->r0,
		.cr = p->cR / p->c2, .acc = acc, .P = copy, .nP = n,
		.dtau = dt * p->c2 / p->r0, .load_rel = isfinite(load_rel) ? fabs(load_rel) : 0.0,
		.R = p->r0, .Estar = p->Estar,
	};
	/* where the load is back to 0 */
	f->tau_load = (double)(P[n - 1] > 0 ? n : n - 1) * f->dtau;
	return f;
}

struct anvil_field *anvil_field_from_result(const struct anvil_params *lp,
					    enum anvil_accuracy acc,
					    const struct anvil_result *r,
					    struct anvil_err *err)
{
	struct anvil_params p = *lp;
	const struct anvil_history *h = &r->hist;
	if (h->n < 3 || !(h->t[1] > h->t[0])) {
		anvil_err_set(err, ANVIL_EINVAL, "field: the impact kept no force history");
		return NULL;
	}
	if (r->model == ANVIL_MODEL_HALFSPACE)
		p.h = INFINITY;
	double rel = r->Pmax.val > 0 && isfinite(r->Pmax.err) ? r->Pmax.err / r->Pmax.val : 0.0;
	double dt = h->t[1] - h->t[0], ts = h->t[h->n - 1];
	if (fabs(ts - (double)(h->n - 1) * dt) <= 1e-9 * ts)
		return anvil_field_alloc(&p, h->P, h->n, dt, rel, acc, err);
	/* A long contact's history is denser near its peak (result.h); the
	 * field's convolution takes an even load, as many samples over t_s. */
	double *even = malloc(h->n * sizeof *even);
	if (!even) {
		anvil_err_set(err, ANVIL_ENOMEM, "field: out of memory");
		return NULL;
	}
	dt = ts / (double)(h->n - 1);
	for (size_t i = 0; i < h->n; i++)
		even[i] = anvil_history_at(h, h->P, i + 1 < h->n ? (double)i * dt : ts);
	struct anvil_field *f = anvil_field_alloc(&p, even, h->n, dt, rel, acc, err);
	free(even);
	return f;
}

void anvil_field_free(struct anvil_field *f)
{
	if (!f)
		return;
	free(f->P);
	free(f);
}

void anvil_field_set_progress(struct anvil_field *f, anvil_progress_fn fn, void *ctx)
{
	f->progress = fn;
	f->pctx = ctx;
}

void anvil_field_set_contact(struct anvil_field *f, int true_contact)
{
	f->true_contact = true_contact && f->Estar > 0 && isfinite(f->Estar);
}

double anvil_field_contact_radius(const struct anvil_field *f, double P)
{
	if (!f->true_contact)
		return f->r0;
	return P > 0 ? cbrt(3.0 * P * f->R / (4.0 * f->Estar)) : 0.0;
}

double anvil_field_load(const struct anvil_field *f, double t)
{
	double x = t * f->c2 / f->r0 / f->dtau;
	if (!(x >= 0) || x >= (double)f->nP)
		return 0.0;
	size_t i = (size_t)x;
	double a = x - (double)i, next = i + 1 < f->nP ? f->P[i + 1] : 0.0;
	return (1 - a) * f->P[i] + a * next;
}

double anvil_field_t_load(const struct anvil_field *f)
{
	return f->tau_load * f->r0 / f->c2;
}

double anvil_field_h(const struct anvil_field *f)
{
	return f->hh * f->r0;
}
/* P at tau: the piecewise-linear load, back to 0 one step after its last
 * sample (the function load_transform transforms, exactly: the static
 * part's subtraction relies on it). */
double anvil_field_load_at(const struct anvil_field *f, double tau)
{
	double x = tau / f->dtau;
	if (!(x >= 0) || x >= (double)f->nP)
		return 0.0;
	size_t i = (size_t)x;
	double a = x - (double)i, next = i + 1 < f->nP ? f->P[i + 1] : 0.0;
	return (1 - a) * f->P[i] + a * next;
}

/* ---- checks ----------------------------------------------------------------- */

int anvil_field_check_times(const struct anvil_field *f, size_t nt, const double *t,
		       double *tau_hi, struct anvil_err *err)
{
	double tmax = ANVIL_FIELD_T_MAX * anvil_field_t_load(f);
	*tau_hi = 0;
	for (size_t i = 0; i < nt; i++) {
		if (!(t[i] >= 0) || t[i] > tmax)
			return anvil_err_set(err, ANVIL_EINVAL,
					     "field: time %.4g us is outside 0 .. %.4g us (%g times the contact)",
					     t[i] * 1e6, tmax * 1e6, ANVIL_FIELD_T_MAX);
		*tau_hi = fmax(*tau_hi, t[i] * f->c2 / f->r0);
	}
	return nt ? ANVIL_OK : anvil_err_set(err, ANVIL_EINVAL, "field: no time given");
}

int anvil_field_check_point(const struct anvil_field *f, double r, double z, struct anvil_err *err)
{
	double h = anvil_field_h(f);
	if (!(r >= 0) || !isfinite(r))
		return anvil_err_set(err, ANVIL_EINVAL, "field: r = %g mm is not >= 0", r * 1e3);
	if (isfinite(h) && !(z >= 0 && z <= h * (1 + 1e-12)))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "field: z = %g mm is outside the layer (0 .. %g mm)", z * 1e3, h * 1e3);
	if (!(z >= 0) || !isfinite(z))
		return anvil_err_set(err, ANVIL_EINVAL, "field: z = %g mm is not a depth >= 0", z * 1e3);
	return ANVIL_OK;
}

int anvil_field_check_grid(const struct anvil_field *f, const struct anvil_field_grid *g,
		      struct anvil_err *err)
{
	int st = anvil_field_check_point(f, g->r_lo, g->z_lo, err);
	if (!st)
		st = anvil_field_check_point(f, g->r_hi, g->z_hi, err);
	if (!st && (g->nr < 1 || g->nz < 1 || g->r_hi < g->r_lo || g->z_hi < g->z_lo ||
		    (g->nr == 1 && g->r_hi != g->r_lo) || (g->nz == 1 && g->z_hi != g->z_lo)))
		st = anvil_err_set(err, ANVIL_EINVAL, "field: bad grid (%zu x %zu)", g->nr, g->nz);
	return st;
}

/* CPU seconds per term and k panel: the layer solved (shared by the
 * depths), and one depth's sums; fitted on `anvil field --at` runs (h =
 * 0.35 and 0.5 r0, one and two depths, 1800 terms on 800-900 panels:
 * 7.9-13 s, within 10 %) on the development machine. */
#define FIELD_COST_SOLVE 3.4e-6
#define FIELD_COST_DEPTH 1.9e-6

/* The load's length in 2h/c1 (0 for a half-space): what the field's work
 * grows with.  c1 = c2 / kappa (kap2 = (c2/c1)^2: the budget's message had
 * c2 kappa, 0.29 of the count on steel). */
static double load_reflections(const struct anvil_field *f)
{
	return isfinite(anvil_field_h(f))
		       ? anvil_field_t_load(f) * f->c2 / sqrt(f->kap2) / (2.0 * anvil_field_h(f))
		       : 0.0;
}

int anvil_field_check_work(const struct anvil_field *f, const struct anvil_field_window *w,
			   const struct anvil_field_kgrid *g, size_t depth_panels, const char *what,
			   struct anvil_err *err)
{
	double terms = (double)w->M + 1.0;
	double s = terms * (FIELD_COST_SOLVE * (double)g->np + FIELD_COST_DEPTH * (double)depth_panels);
	if (!(s > ANVIL_FIELD_BUDGET_S))
		return ANVIL_OK;
	return anvil_err_set(err, ANVIL_ETOL,
			     "%s: at least %.2g min of work (%zu Fourier terms on %zu k panels: the load lasts %.4g ms, %.3g times 2h/c1), over the budget of %g min; anvil run judges such a contact by quasi-static Hertz",
			     what, s / 60.0, w->M + 1, g->np, anvil_field_t_load(f) * 1e3,
			     load_reflections(f),
			     ANVIL_FIELD_BUDGET_S / 60.0);
}

int anvil_field_window_fail(const struct anvil_field *f, const char *what,
			    struct anvil_err *err)
{
	return anvil_err_set(err, ANVIL_ETOL,
			     "%s: the load lasts %.4g ms, %.3g times 2h/c1: its window needs more Fourier terms than the bound of %zu; anvil run judges such a contact by quasi-static Hertz",
			     what, anvil_field_t_load(f) * 1e3, load_reflections(f),
			     (size_t)ANVIL_DURBIN_M_MAX);
}

/* The message of a failed map or history: ANVIL_EINVAL there is a window
 * or k-grid past its bound (window_init, kgrid_init). */
int anvil_field_fail(const struct anvil_field *f, int st, const char *what,
		      struct anvil_err *err)
{
	if (st == ANVIL_EINVAL)
		return anvil_err_set(err, st, "%s: the load (%.4g us) or the radii asked for need "
				     "more Fourier terms or k panels than the bounds allow", what,
				     anvil_field_t_load(f) * 1e6);
	return anvil_err_set(err, st, "%s: %s", what, anvil_strerror(st));
}

