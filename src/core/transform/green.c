#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "accuracy.h"
#include "durbin.h"
#include "gk21.h"
#include "green.h"
#include "kernel.h"
#include "layer_bc.h"
#include "material.h"
#include "green_spectrum.h"
#include "plate.h"

typedef double complex cplx;

/* The FFT's length, hence the output grid: at least 8192 points over the
 * period 2T' = 4 T_inv (2048 steps over the inversion's window, tau_end or
 * the plate's T1), more when the band asks for it (4 (M + 1)).  With M <=
 * ANVIL_DURBIN_M_MAX = 2^20 the length is at most 2^23, so an inversion
 * gives at most 2^21 + 2 samples; a response with the plate's tail keeps
 * those to T1 and ANVIL_PLATE_PAD more, whatever its window. */
#define GREEN_N_MIN 8192
#define GREEN_SAMPLES_MAX (((size_t)1 << 21) + 2)

struct anvil_green {
	enum anvil_green_mode mode;
	double hh, nu, kap2, tau_end;
	double patch;         /* load radius / r0: 1 the paper's patch, 0 a point */
	double dtau;          /* output grid step */
	size_t n;             /* samples at tau_j = j dtau, j < n */
	double *tau, *ramp;   /* one block, owned */
	double *coef;         /* per interval: its y, b, c, d (green_spline), owned */
	double *curv;         /* the spline's c_i (spline_cs), n of them, owned */
	int tailed;           /* 1: beyond tail.t1 the plate's closed form (plate.h) */
	struct anvil_plate_tail tail; /* its arrays owned */
	double abserr;        /* over [0, T1] when tailed (the tail's misfit included) */
	size_t evals;
	int filtered;         /* Vandeven's filter on the band (band_finish) */
};

/* The level's inversion settings (base/accuracy.h); the bandwidth
 * omega_max is the caller's, scaled to the contact time (engine/plan.c),
 * and is left 0 here. */
void anvil_green_settings(enum anvil_accuracy acc, struct anvil_green_settings *gs)
{
	const struct anvil_level *lv = anvil_level(acc);
	if (!lv)
		lv = anvil_level(ANVIL_ACC_NORMAL);
	*gs = (struct anvil_green_settings){ .c0T = lv->green_c0T, .omega_max = 0.0,
					     .tol = lv->green_tol, .ktail = lv->green_ktail };
}

void anvil_green_free(struct anvil_green *g)
{
	if (!g)
		return;
	free(g->coef);
	free(g->curv);
	anvil_plate_tail_free(&g->tail);
	free(g->tau);
	free(g);
}

/* The natural spline's c_i = y''(tau_i)/2 (c[0] = c[n-1] = 0) by the
 * system GSL's cspline_init solves, formed as it forms it and solved by the
 * same public gsl_linalg_solve_symm_tridiag: the same bits as GSL's
 * (tests/test_green.c compares values and slopes with gsl_interp_eval).
 * 0, or -1 (out of memory or a singular system). */
static int spline_cs(const double *x, const double *y, size_t n, double *c)
{
	size_t m = n - 2;
	c[0] = c[n - 1] = 0.0;
	if (m == 0)
		return 0;
	double *w = malloc(3 * m * sizeof *w), *diag = w, *off = w + m, *gv = w + 2 * m;
	if (!w)
		return -1;
	for (size_t i = 0; i < m; i++) {
		double h_i = x[i + 1] - x[i], h_ip1 = x[i + 2] - x[i + 1];
		double g_i = h_i != 0.0 ? 1.0 / h_i : 0.0, g_ip1 = h_ip1 != 0.0 ? 1.0 / h_ip1 : 0.0;
		off[i] = h_ip1;
		diag[i] = 2.0 * (h_ip1 + h_i);
		gv[i] = 3.0 * ((y[i + 2] - y[i + 1]) * g_ip1 - (y[i + 1] - y[i]) * g_i);
	}
	int st = 0;
	if (m == 1) {
		c[1] = gv[0] / diag[0];
	} else {
		gsl_vector_view d = gsl_vector_view_array(diag, m), o = gsl_vector_view_array(off, m - 1),
				b = gsl_vector_view_array(gv, m), sol = gsl_vector_view_array(c + 1, m);
		st = gsl_linalg_solve_symm_tridiag(&d.vector, &o.vector, &b.vector, &sol.vector) ? -1 : 0;
	}
	free(w);
	return st;
}

/* GSL's natural cubic spline through the samples: each interval's
 * polynomial y + x (b + x (c + x d)) as GSL's cspline_eval forms it
 * (coeff_calc), kept: GSL forms the interval's coefficients, three
 * divisions, on every call, and the exact end of a contact evaluates the
 * ramp ~10^4 times per impact.  The c_i from spline_cs, not from a
 * gsl_interp: its init solves the same system again (a sixth of a warm
 * run's reading of a response), and nothing else was asked of it once
 * slopes came from these coefficients too (anvil_green_step).  The c_i
 * are kept (g->curv, exported): curv, when given, holds them as spline_cs
 * made them for these samples, and the system is not solved again.
 * ANVIL_ENOMEM, ANVIL_ENUM. */
static int green_spline(struct anvil_green *g, const double *curv)
{
	size_t n = g->n;
	g->coef = malloc(4 * (n - 1) * sizeof *g->coef);
	double *c = g->curv = malloc(n * sizeof *c);
	if (!g->coef || !c)
		return ANVIL_ENOMEM;
	if (n < 3) /* GSL's cspline's minimum */
		return ANVIL_ENUM;
	if (curv) /* spline_cs's, kept by the exporter (the disk cache) */
		memcpy(c, curv, n * sizeof *c);
	else if (spline_cs(g->tau, g->ramp, n, c))
		return ANVIL_ENUM;
	for (size_t i = 0; i + 1 < n; i++) {
		double dx = g->tau[i + 1] - g->tau[i], dy = g->ramp[i + 1] - g->ramp[i];
		double *cf = g->coef + 4 * i;
		cf[0] = g->ramp[i];
		cf[1] = (dy / dx) - dx * (c[i + 1] + 2.0 * c[i]) / 3.0;
		cf[2] = c[i];
		cf[3] = (c[i + 1] - c[i]) / (3.0 * dx);
	}
	return ANVIL_OK;
}

/* The response g from the first dl->M + 1 terms of the spectrum (the main
 * line's, or the twin's: the same line with fewer terms), err[n] the terms'
 * quadrature bounds, summed in order n = 0, 1, ... (fixed: the same bits
 * whatever the threads). */
static int green_finish(struct anvil_green *g, const struct anvil_durbin *dl, const cplx *spec,
			const double *err, const struct green_plate *pl, struct anvil_plate_memo *memo)
{
	size_t M = dl->M, N = anvil_durbin_fft_size(dl, GREEN_N_MIN);
	double Tp = dl->Tp, qsum = 0, t_inv = 0.5 * Tp;
	g->dtau = 2.0 * Tp / (double)N;
	/* the inversion's samples (about N/4: bounded with M); beyond its
	 * window (line_window: the plate's T1), the plate in closed form and
	 * only the spline's pad in samples (plate.h) */
	int tailed = t_inv < g->tau_end;
	size_t n1 = (size_t)floor(fmin(t_inv, g->tau_end) / g->dtau) + 2;
	g->n = tailed ? n1 + ANVIL_PLATE_PAD : n1;
	if (g->n > GREEN_SAMPLES_MAX)
		return ANVIL_EINVAL;
	g->tau = malloc(2 * g->n * sizeof *g->tau);
	if (!g->tau)
		return ANVIL_ENOMEM;
	g->ramp = g->tau + g->n;
	int st = anvil_durbin_fft(dl, spec, N, g->ramp, n1);
	if (st)
		return st;
	for (size_t n = 0; n <= M; n++)
		qsum += err[n];
	double amp = exp(dl->c0 * fmin(t_inv, g->tau_end)) / Tp; /* series -> time at its end */
	double tail = cabs(spec[M]) * (double)M * 0.5;
	for (size_t j = 0; j < n1; j++) {
		double t = (double)j * g->dtau;
		/* the half-space's static part, (1-nu) 3/8 = 3/(16 (1-kappa^2)), as a ramp */
		if (g->mode == ANVIL_GREEN_HALFSPACE)
			g->ramp[j] += 3.0 / (16.0 * (1.0 - g->kap2)) * t;
		else
			g->ramp[j] += green_plate_t(pl, t);
	}
	g->ramp[0] = 0.0; /* exact: nothing has moved at t = 0 */
	g->tailed = tailed;
	if (tailed && (st = anvil_plate_tail_make(g->hh, g->nu, g->patch, g->dtau, n1, g->n,
						  g->ramp, g->tau_end, memo, &g->tail)))
		return st;
	/* the tail's bound grows with t (anvil_green_abserr_at): its value at T1 here */
	g->abserr = amp * qsum + amp * tail + (tailed ? g->tail.misfit : 0.0);
	for (size_t j = 0; j < g->n; j++)
		g->tau[j] = (double)j * g->dtau;
	return green_spline(g, NULL);
}

/* The band's edge.  The series cut at term M is the response convolved
 * with Dirichlet's kernel: a ringing at the band's top frequency omega_M
 * whose envelope, times the line's e^{c0 t}, lasts the whole inversion
 * window (to T1 for a layer correction, 80 us on the thin plates of issue
 * 11).  To the physical contact that is a resonance at omega_M as sharp
 * as the window is long, which the contact's stiffness closes into a loop
 * that grows: on h = 0.1 r0 (12.2 g, 10 m/s, normal) P oscillated at the
 * band's period (1.94 us at omega_M = 4 c2/r0, 3.77 us at half that; the
 * same at dt and dt/2, not 2h/c1 = 0.13 us, not the contact's 130 us)
 * and grew 1.25 times every 20 us until the bodies parted and touched
 * again every period: more contacts than the budget.  Vandeven's filter
 * (durbin.h, the field's) makes the cut smooth, so the kernel holds no
 * lasting ringing; it takes the top of the band (weight 0.87 at half of
 * it), an error the caller measures as the band's own, by an inversion at
 * half the bandwidth, filtered on its own terms (solver_phys.c). */
static int band_finish(struct anvil_green *g, const struct anvil_durbin *dl, const cplx *spec,
		       const double *err, const struct green_plate *pl,
		       struct anvil_plate_memo *memo, int filter)
{
	g->filtered = filter != 0;
	if (!filter)
		return green_finish(g, dl, spec, err, pl, memo);
	cplx *sf = malloc((dl->M + 1) * sizeof *sf);
	if (!sf)
		return ANVIL_ENOMEM;
	for (size_t n = 0; n <= dl->M; n++)
		sf[n] = spec[n] * anvil_durbin_filter(n, dl->M);
	int st = green_finish(g, dl, sf, err, pl, memo);
	free(sf);
	return st;
}

int anvil_green_fits(enum anvil_green_mode mode, double hh, double tau_end, double omega_max)
{
	double t1 = mode == ANVIL_GREEN_LAYER_CORRECTION ? anvil_plate_t1(hh, tau_end) : 0;
	double t_inv = t1 > 0 ? t1 : tau_end, Tp = 2.0 * t_inv;
	struct anvil_durbin dl;
	if (!(tau_end > 0) || anvil_durbin_init(&dl, Tp, 1.0 / Tp, omega_max, 0))
		return 0;
	double dtau = 2.0 * Tp / (double)anvil_durbin_fft_size(&dl, GREEN_N_MIN);
	double n = floor(t_inv / dtau) + 2 + (t1 > 0 ? ANVIL_PLATE_PAD : 0);
	return n <= (double)GREEN_SAMPLES_MAX;
}

/* The inversion's line for g's window: output kept to [0, T'/2] of the
 * period Tp = 2T'; for a long window of a layer correction, only over
 * [0, T1] (t1 > 0), the plate beyond. */
static double line_window(const struct anvil_green *g, const struct anvil_green_settings *gs,
			  double *t1)
{
	*t1 = g->mode == ANVIL_GREEN_LAYER_CORRECTION && !gs->no_plate
		      ? anvil_plate_t1(g->hh, g->tau_end) : 0;
	return *t1 > 0 ? *t1 : g->tau_end;
}

/* Spectrum sp of g's load over the line of window t_inv at bandwidth
 * omega (dl initialised here): each term's k-integral gets its share of
 * the level's tolerance on the half-space ramp's scale; spec and err
 * allocated (the caller frees them, also on failure).  ANVIL_EINVAL,
 * ANVIL_ENOMEM. */
static int spectrum_init(struct green_spectrum *sp, struct anvil_durbin *dl, const struct anvil_green *g,
			 double t_inv, double omega, double cr, const struct green_plate *pl,
			 const struct anvil_green_settings *gs, anvil_progress_fn progress,
			 void *ctx)
{
	double Tp = 2.0 * t_inv;
	*sp = (struct green_spectrum){ 0 };
	if (anvil_durbin_init(dl, Tp, gs->c0T / Tp, omega, 0))
		return ANVIL_EINVAL;
	size_t M = dl->M;
	double scale = 3.0 / (16.0 * (1.0 - g->kap2)) * t_inv; /* half-space ramp */
	double amp = exp(dl->c0 * t_inv) / Tp;
	*sp = (struct green_spectrum){ .dl = dl, .cr = cr, .ktail = gs->ktail,
				 .epsF = gs->tol * scale / (amp * (double)(M + 1)), .pl = pl,
				 .lift_patch = gs->lift_patch,
				 .progress = progress, .ctx = ctx, .patch = g->patch,
				 .spec = malloc((M + 1) * sizeof(cplx)),
				 .err = malloc((M + 1) * sizeof(double)) };
	return sp->spec && sp->err ? ANVIL_OK : ANVIL_ENOMEM;
}

/* The main response g and, when tw is not NULL, its twin at half the
 * bandwidth from the same spectrum: the twin's line is the same (same
 * window, same c0), its terms n <= M' the first of the main's.  Every
 * k-integral meets the main's tolerance, which is tighter than a twin
 * computed alone would ask (the budget is shared among M + 1 terms, not
 * M' + 1): the twin's error estimate is its own, over its own terms. */
static int green_compute(struct anvil_green *g, struct anvil_green *tw,
			 const struct anvil_green_settings *gs, anvil_progress_fn progress,
			 void *ctx)
{
	double t1, t_inv = line_window(g, gs, &t1), xr;
	struct anvil_durbin dl, dt;
	struct green_spectrum sp;
	if (tw && anvil_durbin_init(&dt, 2.0 * t_inv, gs->c0T / (2.0 * t_inv), 0.5 * gs->omega_max, 0))
		return ANVIL_EINVAL;
	if (anvil_rayleigh_x(g->kap2, &xr, NULL))
		return ANVIL_ENUM;
	struct green_plate pl = green_plate_term(g->mode, g->hh, g->nu);
	int st = spectrum_init(&sp, &dl, g, t_inv, gs->omega_max, sqrt(xr), &pl, gs, progress, ctx);
	if (!st)
		st = green_sample_spectra(g->mode, g->kap2, g->nu, g->hh, &sp, 1, &g->evals);
	/* A k-integral that missed its share of the budget is not fatal: its
	 * error estimate is in err, hence in abserr, for the caller to judge. */
	if (st == ANVIL_ETOL)
		st = ANVIL_OK;
	/* the plate's K(t) table: the caller's memo, or one for g and its twin */
	struct anvil_plate_memo *own = !gs->plate && tw && t1 > 0 ? anvil_plate_memo_alloc() : NULL;
	struct anvil_plate_memo *memo = gs->plate ? gs->plate : own;
	if (!st)
		st = band_finish(g, &dl, sp.spec, sp.err, &pl, memo, gs->filter);
	if (!st && tw)
		st = band_finish(tw, &dt, sp.spec, sp.err, &pl, memo, gs->filter);
	anvil_plate_memo_free(own);
	free(sp.err);
	free(sp.spec);
	return st;
}

static struct anvil_green *green_new(enum anvil_green_mode mode, double hh, double nu,
				     double patch, double tau_end)
{
	struct anvil_green *g = calloc(1, sizeof *g);
	if (!g)
		return NULL;
	g->mode = mode;
	g->hh = hh;
	g->patch = patch;
	g->nu = nu;
	g->kap2 = anvil_kappa2(nu);
	g->tau_end = tau_end;
	return g;
}

/* The layer corrections g[0..n-1] (their patches set, one hh, nu and
 * window) at bandwidths omega[i], on one line: each as green_compute
 * makes it alone (same tolerance per term, same finish), their spectra
 * sampled together (sample_spectra: the kernel shared). */
static int green_set_compute(struct anvil_green **g, const double *omega, size_t n,
			     const struct anvil_green_settings *gs, anvil_progress_fn progress,
			     void *ctx)
{
	double t1, t_inv = line_window(g[0], gs, &t1), xr;
	struct anvil_durbin dl[GREEN_SPECTRA_MAX];
	struct green_spectrum sp[GREEN_SPECTRA_MAX];
	size_t evals[GREEN_SPECTRA_MAX];
	if (anvil_rayleigh_x(g[0]->kap2, &xr, NULL))
		return ANVIL_ENUM;
	struct green_plate pl = green_plate_term(g[0]->mode, g[0]->hh, g[0]->nu);
	int st = ANVIL_OK;
	size_t made = 0;
	while (made < n && !st) {
		st = spectrum_init(&sp[made], &dl[made], g[made], t_inv, omega[made], sqrt(xr), &pl,
				   gs, progress, ctx);
		made++;
	}
	if (!st)
		st = green_sample_spectra(g[0]->mode, g[0]->kap2, g[0]->nu, g[0]->hh, sp, n,
					  evals);
	if (st == ANVIL_ETOL) /* as green_compute: in err, for the caller to judge */
		st = ANVIL_OK;
	struct anvil_plate_memo *own = !gs->plate && t1 > 0 ? anvil_plate_memo_alloc() : NULL;
	struct anvil_plate_memo *memo = gs->plate ? gs->plate : own;
	for (size_t i = 0; !st && i < n; i++) {
		g[i]->evals = evals[i];
		st = band_finish(g[i], &dl[i], sp[i].spec, sp[i].err, &pl, memo, gs->filter);
	}
	anvil_plate_memo_free(own);
	for (size_t i = 0; i < made; i++) {
		free(sp[i].spec);
		free(sp[i].err);
	}
	return st;
}

int anvil_green_alloc_set(double hh, double nu, double tau_end,
			  const struct anvil_green_settings *gs, const struct anvil_green_load *load,
			  size_t n, anvil_progress_fn progress, void *ctx, struct anvil_green **out,
			  struct anvil_err *err)
{
	int st = ANVIL_OK;
	for (size_t i = 0; i < n; i++)
		out[i] = NULL;
	if (!(n >= 1 && n <= GREEN_SPECTRA_MAX) || !(nu > -1 && nu < 0.5) || !(tau_end > 0) ||
	    !isfinite(tau_end) || !(hh > 0 && isfinite(hh)))
		st = ANVIL_EINVAL;
	for (size_t i = 0; !st && i < n; i++)
		if (!(load[i].patch >= 0 && load[i].patch <= green_lift_wide(gs->lift_patch)))
			st = ANVIL_EINVAL;
	if (st)
		return anvil_err_set(err, st, "layer responses: bad parameters (h/r0 = %g, nu = %g, window %g, %zu loads)",
				     hh, nu, tau_end, n);
	double omega[GREEN_SPECTRA_MAX];
	for (size_t i = 0; !st && i < n; i++) {
		omega[i] = load[i].omega_max;
		out[i] = green_new(ANVIL_GREEN_LAYER_CORRECTION, hh, nu, load[i].patch, tau_end);
		st = out[i] ? ANVIL_OK : ANVIL_ENOMEM;
	}
	if (!st)
		st = green_set_compute(out, omega, n, gs, progress, ctx);
	if (st) {
		for (size_t i = 0; i < n; i++) {
			anvil_green_free(out[i]);
			out[i] = NULL;
		}
		return anvil_err_set(err, st, st == ANVIL_ECANCEL ? "layer response: cancelled" :
				     "layer response (h/r0 = %g, nu = %g): %s", hh, nu,
				     anvil_strerror(st));
	}
	return ANVIL_OK;
}

struct anvil_green *anvil_green_alloc(enum anvil_green_mode mode, double hh,
				      double nu, double tau_end,
				      const struct anvil_green_settings *gs,
				      anvil_progress_fn progress, void *ctx,
				      struct anvil_err *err)
{
	return anvil_green_alloc_twin(mode, hh, nu, tau_end, gs, progress, ctx, NULL, err);
}

static struct anvil_green *green_make(enum anvil_green_mode mode, double hh, double nu,
				      double patch, double tau_end,
				      const struct anvil_green_settings *gs,
				      anvil_progress_fn progress, void *ctx,
				      struct anvil_green **twin, struct anvil_err *err);

struct anvil_green *anvil_green_alloc_twin(enum anvil_green_mode mode, double hh, double nu,
					   double tau_end, const struct anvil_green_settings *gs,
					   anvil_progress_fn progress, void *ctx,
					   struct anvil_green **twin, struct anvil_err *err)
{
	return green_make(mode, hh, nu, 1.0, tau_end, gs, progress, ctx, twin, err);
}

struct anvil_green *anvil_green_alloc_patch(enum anvil_green_mode mode, double hh, double nu,
					    double patch, double tau_end,
					    const struct anvil_green_settings *gs,
					    anvil_progress_fn progress, void *ctx,
					    struct anvil_err *err)
{
	if (!(patch >= 0 && patch <= 1) || (mode == ANVIL_GREEN_HALFSPACE && patch != 1.0)) {
		anvil_err_set(err, ANVIL_EINVAL,
			      "layer response: patch %g r0 (0..1; the half-space mode takes r0 only)",
			      patch);
		return NULL;
	}
	return green_make(mode, hh, nu, patch, tau_end, gs, progress, ctx, NULL, err);
}

static struct anvil_green *green_make(enum anvil_green_mode mode, double hh, double nu,
				      double patch, double tau_end,
				      const struct anvil_green_settings *gs,
				      anvil_progress_fn progress, void *ctx,
				      struct anvil_green **twin, struct anvil_err *err)
{
	if (twin)
		*twin = NULL;
	if (!(nu > -1 && nu < 0.5) || !(tau_end > 0) || !isfinite(tau_end) ||
	    (mode == ANVIL_GREEN_LAYER_CORRECTION && !(hh > 0 && isfinite(hh))) ||
	    !(patch <= green_lift_wide(gs->lift_patch))) {
		anvil_err_set(err, ANVIL_EINVAL, "layer response: bad parameters (h/r0 = %g, nu = %g, window %g, patch %g over the contour's %g)",
			      hh, nu, tau_end, patch, green_lift_wide(gs->lift_patch));
		return NULL;
	}
	struct anvil_green *g = green_new(mode, hh, nu, patch, tau_end);
	struct anvil_green *tw = twin ? green_new(mode, hh, nu, patch, tau_end) : NULL;
	int st = !g || (twin && !tw) ? ANVIL_ENOMEM : green_compute(g, tw, gs, progress, ctx);
	if (st) {
		anvil_err_set(err, st, st == ANVIL_ECANCEL ? "layer response: cancelled" :
			      "layer response (h/r0 = %g, nu = %g): %s", hh, nu, anvil_strerror(st));
		anvil_green_free(g);
		anvil_green_free(tw);
		return NULL;
	}
	if (twin)
		*twin = tw;
	return g;
}

/* The interval of tau, 0 < tau <= tau_{n-1}: the one with tau_i <= tau <
 * tau_i+1, the last for the last node, as GSL's gsl_interp_accel_find
 * settles it.  The samples are uniform (tau_j = j dtau): the interval is
 * known from tau / dtau without GSL's bisection (a third of a warm run's
 * time went there), up to the quotient's rounding, which the walk to the
 * neighbour settles.  The quotient is positive and below n here: a
 * signed truncation is its floor, one instruction where floor and the
 * unsigned conversion took 35 (a twentieth of a warm run's). */
static size_t spline_interval(const struct anvil_green *g, double tau)
{
	double j = tau / g->dtau;
	size_t last = g->n - 2;
	size_t i = j < (double)last ? (size_t)(long)j : last;
	while (i > 0 && tau < g->tau[i])
		i--;
	while (i < last && tau >= g->tau[i + 1])
		i++;
	return i;
}

int anvil_green_ramp(const struct anvil_green *g, double tau, double *val)
{
	if (tau <= 0) {
		*val = 0;
		return ANVIL_OK;
	}
	if (tau > g->tau_end)
		return ANVIL_EINVAL;
	if (g->tailed && tau > g->tail.t1) {
		*val = anvil_plate_tail_ramp(&g->tail, tau);
		return ANVIL_OK;
	}
	if (!(tau <= g->tau[g->n - 1])) { /* gsl_interp_eval's domain */
		*val = NAN;
		return ANVIL_OK;
	}
	size_t i = spline_interval(g, tau);
	const double *cf = g->coef + 4 * i;
	double delx = tau - g->tau[i];
	*val = cf[0] + delx * (cf[1] + delx * (cf[2] + delx * cf[3]));
	return ANVIL_OK;
}

/* The spline's slope as gsl_interp_eval_deriv forms it (cspline_eval_deriv:
 * b + x (2 c + 3 d x)): the same bits. */
int anvil_green_step(const struct anvil_green *g, double tau, double *val)
{
	if (tau <= 0) {
		*val = 0;
		return ANVIL_OK;
	}
	if (tau > g->tau_end)
		return ANVIL_EINVAL;
	if (g->tailed && tau > g->tail.t1) {
		*val = anvil_plate_tail_step(&g->tail, tau);
		return ANVIL_OK;
	}
	if (!(tau <= g->tau[g->n - 1])) { /* gsl_interp_eval_deriv's domain */
		*val = NAN;
		return ANVIL_OK;
	}
	size_t i = spline_interval(g, tau);
	const double *cf = g->coef + 4 * i;
	double delx = tau - g->tau[i];
	*val = cf[1] + delx * (2.0 * cf[2] + 3.0 * cf[3] * delx);
	return ANVIL_OK;
}

int anvil_green_impulse(const struct anvil_green *g, double tau, double *val)
{
	if (!(g->tailed && tau > g->tail.t1 && tau <= g->tau_end))
		return ANVIL_EINVAL;
	*val = anvil_plate_tail_impulse(&g->tail, tau);
	return ANVIL_OK;
}

void anvil_green_kernel(double k, double complex s, double nu, double hh,
			double complex *layer, double complex *halfspace)
{
	struct anvil_layer_bc bc;
	anvil_layer_bc_solve(k, s, anvil_kappa2(nu), hh, &bc);
	*halfspace = anvil_layer_bc_w_halfspace(&bc);
	*layer = *halfspace + anvil_layer_bc_w_correction(&bc);
}

double anvil_green_tau_end(const struct anvil_green *g) { return g->tau_end; }
double anvil_green_abserr(const struct anvil_green *g) { return g->abserr; }

double anvil_green_abserr_at(const struct anvil_green *g, double tau)
{
	if (!g->tailed || !(tau > g->tail.t1))
		return g->abserr;
	return g->abserr + anvil_plate_tail_err(&g->tail, tau);
}

double anvil_green_t_plate(const struct anvil_green *g)
{
	return g->tailed ? g->tail.t1 : INFINITY;
}
size_t anvil_green_evals(const struct anvil_green *g) { return g->evals; }

/* ---- export and import (the response cache, cache.c) ---- */

void anvil_green_export(const struct anvil_green *g, struct anvil_green_samples *s)
{
	*s = (struct anvil_green_samples){ .mode = g->mode, .filtered = g->filtered,
					   .hh = g->hh, .nu = g->nu, .patch = g->patch,
					   .tau_end = g->tau_end, .dtau = g->dtau,
					   .abserr = g->abserr, .n = g->n, .ramp = g->ramp,
					   .curv = g->curv };
	if (g->tailed) {
		s->t1 = g->tail.t1;
		memcpy(s->tail_c, g->tail.c, sizeof s->tail_c);
		s->tail_v = g->tail.v;
		s->nk = g->tail.nk;
		s->k = g->tail.k;
		s->shear = g->tail.shear;
	}
}

/* The sizes and the window, checked before any cast or allocation: finite
 * and positive, the grid of green_compute (T_inv/dtau = N/4 for an FFT
 * length N, a power of two, within rounding), n = floor(T_inv/dtau) + 2
 * (T_inv = tau_end, or the plate's T1 and then ANVIL_PLATE_PAD more, and
 * a tail at T1: anvil_plate_tail_init checks its table), at most
 * GREEN_SAMPLES_MAX. */
static int sizes_ok(const struct anvil_green_samples *s)
{
	if (!(s->nu > -1 && s->nu < 0.5) || !(s->tau_end > 0 && isfinite(s->tau_end)) ||
	    !(s->dtau > 0 && isfinite(s->dtau)) || !(s->abserr > 0 && isfinite(s->abserr)) ||
	    (s->mode != ANVIL_GREEN_LAYER_CORRECTION && s->mode != ANVIL_GREEN_HALFSPACE) ||
	    (s->mode == ANVIL_GREEN_LAYER_CORRECTION && !(s->hh > 0 && isfinite(s->hh))) ||
	    !(s->patch >= 0 && s->patch <= 1) || !s->ramp)
		return 0;
	/* a long window's inversion covered [0, T1] only (plate.h) */
	double t1 = s->mode == ANVIL_GREEN_LAYER_CORRECTION ? anvil_plate_t1(s->hh, s->tau_end) : 0;
	double r1 = (t1 > 0 ? t1 : s->tau_end) / s->dtau, pad = t1 > 0 ? ANVIL_PLATE_PAD : 0;
	double N = exp2(round(log2(4.0 * r1)));
	if (!(r1 >= GREEN_N_MIN / 4 - 1 && r1 + 2 + pad <= (double)GREEN_SAMPLES_MAX) ||
	    !(fabs(4.0 * r1 - N) <= 1e-9 * N))
		return 0;
	size_t n1 = (size_t)floor(r1) + 2;
	if (t1 > 0 && !(s->t1 == (double)(n1 - 2) * s->dtau && s->k && s->shear))
		return 0;
	if (t1 == 0 && (s->t1 != 0 || s->nk != 0))
		return 0;
	return s->n == n1 + (size_t)pad;
}

/* What an importer can afford to check of the samples themselves: ramp[0] = 0
 * (nothing has moved at t = 0), all finite, and causality: the layer
 * correction is zero until the bottom reflection returns at tau = 2 hh
 * kappa (2h/c1).  The inversion's band limit smears the arrival: over
 * draft .. reference, h = 0.2 .. 40 r0, nu = 0 .. 0.45, the samples before it
 * stayed below 0.12 of the response's own error estimate abserr, and
 * those after 2 tau_refl reached 58 abserr or more.  So samples above
 * abserr before tau_refl are refused, and so is a response whose window
 * reaches 2 tau_refl and that stays within CAUSAL_AFTER abserr after it
 * (e.g. all zeros).  A half-space response must have moved by its end. */
#define CAUSAL_AFTER 2.0
/* A filtered response (band_finish) moves before the reflection returns:
 * the filter spreads the arrival over a few of the band's periods, and the
 * smoothed wrap of the inversion's period shifts the first samples (ramp
 * 0.02-0.04 before tau = 2 hh/c1 on the default rod, h = r0, 10 m/s, the
 * front reaching 0.3 at twice that), far above the series' abserr, which
 * does not count the filter's error (the caller's half-band run does,
 * solver.c).  What the check still refuses: a precursor above 1e-3 of the
 * response's peak; the filtered responses of the tests reach 7.3e-5. */
#define FILTER_PRECURSOR 1e-3

int anvil_green_samples_plausible(const struct anvil_green_samples *s)
{
	if (s->ramp[0] != 0.0)
		return 0;
	for (size_t j = 0; j < s->n; j++)
		if (!isfinite(s->ramp[j]))
			return 0;
	/* the natural spline's: finite, 0 at both ends */
	if (s->curv && (s->curv[0] != 0.0 || s->curv[s->n - 1] != 0.0))
		return 0;
	for (size_t j = 0; s->curv && j < s->n; j++)
		if (!isfinite(s->curv[j]))
			return 0;
	if (s->mode == ANVIL_GREEN_HALFSPACE)
		return s->ramp[s->n - 1] > 0;
	double trefl = 2.0 * s->hh * sqrt(anvil_kappa2(s->nu)), after = 0, pre = 0, peak = 0;
	for (size_t j = 0; j < s->n; j++) { /* finite: no fmax, a libm call */
		double tau = (double)j * s->dtau, v = fabs(s->ramp[j]);
		if (tau < trefl && v > pre)
			pre = v;
		if (tau >= 2.0 * trefl && tau <= s->tau_end && v > after)
			after = v;
		peak = v > peak ? v : peak;
	}
	if (pre > (s->filtered ? FILTER_PRECURSOR * peak : s->abserr))
		return 0;
	return s->tau_end < 2.0 * trefl || after > CAUSAL_AFTER * s->abserr;
}

/* The plate's tail of s into g: its table plausible (plate.h), and the
 * spline's pad beyond T1 (tail_make wrote the model's values there) what
 * the stored coefficients and table give, to the bit. */
static int tail_import(struct anvil_green *g, const struct anvil_green_samples *s,
		       struct anvil_err *err)
{
	int st = anvil_plate_tail_init(&g->tail, s->hh, s->nu, s->patch, s->t1, s->tail_c,
				       s->tail_v, s->tau_end, s->nk, s->k, s->shear);
	g->tailed = 1;
	for (size_t j = s->n - ANVIL_PLATE_PAD; !st && j < s->n; j++)
		if (anvil_plate_tail_ramp(&g->tail, (double)j * s->dtau) != s->ramp[j])
			st = ANVIL_EINVAL;
	if (st)
		anvil_err_set(err, st, st == ANVIL_ENOMEM ? "layer response: out of memory" :
			      "layer response: the plate's tail does not match its samples");
	return st;
}

struct anvil_green *anvil_green_import(const struct anvil_green_samples *s,
				       struct anvil_err *err)
{
	if (!sizes_ok(s)) {
		anvil_err_set(err, ANVIL_EINVAL, "layer response: inconsistent sizes or window");
		return NULL;
	}
	if (!anvil_green_samples_plausible(s)) {
		anvil_err_set(err, ANVIL_EINVAL, "layer response: implausible samples "
			      "(ramp[0], finiteness, causality or the spline's ends)");
		return NULL;
	}
	struct anvil_green *g = calloc(1, sizeof *g);
	double *block = malloc(2 * s->n * sizeof *block);
	if (!g || !block) {
		free(g);
		free(block);
		anvil_err_set(err, ANVIL_ENOMEM, "layer response: out of memory");
		return NULL;
	}
	*g = (struct anvil_green){ .mode = s->mode, .filtered = s->filtered != 0,
				   .hh = s->hh, .nu = s->nu, .patch = s->patch,
				   .kap2 = anvil_kappa2(s->nu), .tau_end = s->tau_end,
				   .dtau = s->dtau, .n = s->n, .tau = block, .ramp = block + s->n,
				   .abserr = s->abserr };
	for (size_t j = 0; j < g->n; j++)
		g->tau[j] = (double)j * g->dtau; /* as green_compute: the same bits */
	memcpy(g->ramp, s->ramp, g->n * sizeof *g->ramp);
	int sst = green_spline(g, s->curv);
	if (sst) {
		anvil_err_set(err, sst, "layer response: cannot rebuild the interpolant");
		anvil_green_free(g);
		return NULL;
	}
	if (s->t1 > 0 && tail_import(g, s, err)) {
		anvil_green_free(g);
		return NULL;
	}
	return g;
}
