/* field.c: displacements and stresses anywhere in the layer.  See field.h.
 *
 * Dimensionless inside (mu = rho = c2 = r0 = 1, time tau = t c2/r0, the
 * load in newtons): a displacement is value/(mu r0) m, a stress
 * value/r0^2 Pa.
 *
 * The remainder (field minus P(t) times the static Hertz field) at one
 * instant is
 *   (e^{c0 tau}/T') sum_{n<=M} g_n sigma_n Re[ Phat(s_n) e^{i w_n tau}
 *        int_0^kend (K(k,z,s_n) - K_st(k,z)) Z^H(k) k J(kr) dk ]
 * (Durbin, s_n = c0 + i w_n, w_n = n pi/T', g_0 = 1/2, g_n = 1, sigma_n the
 * spectral filter, see durbin_weights()), where
 * Phat is the exact Laplace transform of the piecewise-linear P(t): this is
 * the Duhamel convolution (13)-(14) done in the transform domain, exact for
 * that P.  For stresses it is the same as eq (36) (the step response
 * against dP/dt) or the ramp response against the second differences of P,
 * which is how impact.c convolves the centre deflection: all three are one
 * linear functional of the same load, and the transform domain needs
 * neither the step response's jumps (Gibbs) nor a ramp that grows like t^2.
 *
 * The k-integral of the remainder: K - K_st = O(s^2/k^2) K_st at large k
 * (the static half-space kernels are the high-k asymptote), so the
 * integrand decays like exp(-kz) times an extra k^-2 even at z = 0, where
 * J0(kr) Z^H(k) alone would converge only like cos(k)/k^(3/2): the slowly
 * converging surface tail is in the static part, which is summed in closed
 * form.  The integrand has the Lamb-mode (half-space: Rayleigh) poles
 * within c0/c_group >= c0/c1 of the real axis for k below about
 * w_max/c_R: that band is cut into Gauss-Kronrod panels no wider than a few
 * pole distances; beyond it the integrand is smooth and panels are as wide
 * as the oscillation of J(k r_max) allows.  The same nodes serve every z,
 * every s_n and every r: for a map, each (k, z) is first summed over the
 * frequencies into the instants' time-domain values (real), and the
 * Hankel sums over k for all radii are then dense axpy loops. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_bessel.h>

#include "accuracy.h"
#include "durbin.h"
#include "field.h"
#include "field_kernel.h"
#include "gk21.h"
#include "hertz_field.h"
#include "kernel.h"
#include "material.h"

typedef double complex cplx;

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

/* Each output (but von Mises) as a combination of the Hankel integrals:
 * sigma_rr = lambda e + 2 (1/r) d(r u)/dr - 2 u/r, sigma_tt = lambda e + 2 u/r. */
static const double combo[ANVIL_FQ_VM][HS_COUNT] = {
	[ANVIL_FQ_U] = {[HS_U] = 1},
	[ANVIL_FQ_W] = {[HS_W] = 1},
	[ANVIL_FQ_SZZ] = {[HS_SZZ] = 1},
	[ANVIL_FQ_SRR] = {[HS_LAM] = 1, [HS_KU] = 2, [HS_UR] = -2},
	[ANVIL_FQ_STT] = {[HS_LAM] = 1, [HS_UR] = 2},
	[ANVIL_FQ_SRZ] = {[HS_SRZ] = 1},
};

/* The Hankel integrals each output needs (von Mises: all the stresses). */
static unsigned hs_needed(unsigned quantities)
{
	unsigned m = 0;
	for (int q = 0; q < ANVIL_FQ_VM; q++)
		if (quantities & (1u << q) || (q >= ANVIL_FQ_SZZ && quantities & (1u << ANVIL_FQ_VM)))
			for (int h = 0; h < HS_COUNT; h++)
				if (combo[q][h] != 0)
					m |= 1u << h;
	return m;
}

/* ---- accuracy levels ------------------------------------------------------- */

/* The field's columns of the accuracy table (base/accuracy.c).  Per level, from convergence studies against runs at the reference
 * level with three times its bandwidth and a window of 3 t_last (25 x 25
 * maps of every stress over 3 r0 x h at t_max/2, t_max and t_s, for h = r0,
 * 0.5 r0 and the half-space; tests/test_field.c keeps normal against
 * reference).  Largest error over a map, relative to the peak stress:
 *   draft 1.5e-4 (h = r0) .. 8e-4 (half-space, at t_s),
 *   normal 1.2e-4 / 5e-5 / 1.6e-4 (h = r0), 4e-6 / 3e-7 / 5e-4 (half-space),
 *   fine 4e-5 / 2e-5 / 5e-5 (h = r0), 2e-8 / 1e-7 / 2.4e-4 (half-space);
 * the instant the contact ends is the hardest (the load's singularity sits
 * at the surface then).
 *   cycles, omega_min: the bandwidth, omega_max = max(omega_min, cycles /
 *     tau_load), the centre response's rule (solver.c) with twice its
 *     cycles: the stresses follow the load's own t^(3/2) start and
 *     (t_s - t)^(3/2) end, whose spectrum decays only like omega^(-5/2),
 *     so their series converges like omega_max^(-3/2) near those times
 *     (the deflection's like omega_max^(-5/2));
 *   tw, c0t: the Durbin window T' = tw t_last and c0 = c0t / t_last, t_last
 *     the latest instant asked for: the inversion multiplies the spectral
 *     errors by e^{c0 t} (e^5 here, as green.c's output window) and
 *     aliases e^{-2 c0 T'} (3.7e-6 .. 7e-8) of the field's size; a window
 *     1.25 t_last long is as accurate as 2 t_last and 40 % cheaper;
 *   band_w: panel width in the pole band, in pole distances c0/c1: the
 *     results do not move between 2 and 8 (the errors of the panels that a
 *     pole crosses alternate in sign from one frequency to the next and
 *     cancel in the time domain), so the band costs little;
 *   ktail: how far past the band the k-integral goes where z -> 0 (the
 *     remainder decays like k^-(5/2) there; twice as far moves nothing);
 *   L: exp(-L) ends the integral where e^{-kz} decays first. */
#define FLEVEL(acc) (&anvil_level(acc)->field)
typedef struct anvil_field_level flevel_t;

/* ---- the object ------------------------------------------------------------ */

struct anvil_field {
	double r0, mu, c2, nu, kap2, hh, cr; /* cr = c_R/c2 */
	enum anvil_accuracy acc;
	double *P;        /* the load, N, at tau_i = i dtau */
	size_t nP;
	double dtau, tau_load, load_rel;
	anvil_progress_fn progress;
	void *pctx;
	int true_contact;   /* the static part over a(t), not r0 (field.h) */
	double R, Estar;    /* tip radius and contact modulus, for a(t) */
};

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
	return anvil_field_alloc(&p, h->P, h->n, h->t[1] - h->t[0], rel, acc, err);
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
static double load_at(const struct anvil_field *f, double tau)
{
	double x = tau / f->dtau;
	if (!(x >= 0) || x >= (double)f->nP)
		return 0.0;
	size_t i = (size_t)x;
	double a = x - (double)i, next = i + 1 < f->nP ? f->P[i + 1] : 0.0;
	return (1 - a) * f->P[i] + a * next;
}

/* ---- the Bromwich line ---------------------------------------------------- */

struct window {
	struct anvil_durbin dl; /* the line: half period T', abscissa c0, terms 0..M */
	double omega;   /* highest frequency summed */
	size_t M, Mh;   /* terms n = 0..M; the coarse twin n = 0..Mh (2M/3) */
	cplx *s, *Phat; /* M + 1 each, one block */
};

/* The Laplace transform of the piecewise-linear load: each hat function of
 * half-width d centred at tau_i transforms to e^{-s tau_i} d (sinh x / x)^2,
 * x = s d / 2. */
static cplx load_transform(const struct anvil_field *f, cplx s)
{
	double d = f->dtau;
	cplx q = cexp(-s * d), e = 1.0, sum = 0.0, x = 0.5 * s * d, sx;
	for (size_t i = 0; i < f->nP; i++) {
		sum += f->P[i] * e;
		e *= q;
	}
	sx = cabs(x) < 1e-4 ? 1.0 + x * x / 6.0 : csinh(x) / x;
	return d * sx * sx * sum;
}

static int window_init(const struct anvil_field *f, const flevel_t *lv, double tau_hi,
		       struct window *w)
{
	double omega = fmax(lv->omega_min, lv->cycles / f->tau_load);
	tau_hi = fmax(tau_hi, 4.0 * f->dtau);
	/* at least 16 terms; at most ANVIL_DURBIN_M_MAX (a load so long that it
	 * needs more is refused, not summed for ever) */
	if (anvil_durbin_init(&w->dl, lv->tw * tau_hi, lv->c0t / tau_hi, omega, 16))
		return ANVIL_EINVAL;
	w->M = w->dl.M;
	/* the twin at 2/3 of the band: at 1/2 its smoothing in time, amplified
	 * by e^{c0 t}, made the estimates up to 1000 times the error (thin
	 * layers); at 3/4 it agreed with the series too often by chance */
	w->Mh = 2 * w->M / 3;
	w->omega = anvil_durbin_omega(&w->dl);
	w->s = malloc(2 * (w->M + 1) * sizeof *w->s);
	if (!w->s)
		return ANVIL_ENOMEM;
	w->Phat = w->s + w->M + 1;
	for (size_t n = 0; n <= w->M; n++) {
		w->s[n] = anvil_durbin_s(&w->dl, n);
		w->Phat[n] = load_transform(f, w->s[n]);
	}
	return ANVIL_OK;
}

/* The series is filtered (anvil_durbin_filter, Vandeven's exp(-36 eta^8)):
 * a sharply truncated series spreads the error of the load's t^(3/2)
 * singularities over the whole window as Gibbs tails, which the e^{c0 t}
 * of the inversion then amplifies; the filter keeps it near the singular
 * instants.  Against a reference with the unfiltered series at three times
 * the bandwidth and twice the window, the maps' error at half the time of
 * the peak force fell from 1.7e-3 to 1e-4 of the peak stress (h = r0) and
 * from 1.6e-3 to 4e-6 (half-space); at the end of the load itself it stays
 * near 5e-4.  The weights of instant tau for the terms n <= nmax (M, or Mh
 * for the coarse twin): a_n = (e^{c0 tau}/T') g_n sigma(n/nmax) Phat_n
 * e^{i w_n tau}. */
static void durbin_weights(const struct window *w, double tau, size_t nmax, cplx *a,
			   size_t stride)
{
	anvil_durbin_weights(&w->dl, tau, nmax, w->Phat, a, stride);
}

/* ---- the k panels ------------------------------------------------------------ */

/* The panels' nodes: the 21-point Gauss-Kronrod rule (gk21.h), walked
 * node by node, since each node serves every depth, frequency and radius. */

struct kgrid {
	size_t np;   /* panels */
	double *a;   /* np + 1 ends */
	double kb;   /* end of the pole band */
	double wt;   /* width of the panels beyond it */
	double ktail, L;
};

/* Where the k-integral of depth z ends. */
static double kgrid_end(const struct kgrid *g, double z)
{
	return g->kb + (z > 0 ? fmin(g->ktail, g->L / z) : g->ktail);
}

/* How many panels depth z uses (its last is the returned value - 1). */
static size_t kgrid_panels(const struct kgrid *g, double z)
{
	double kend = kgrid_end(g, z);
	size_t n = 0;
	while (n < g->np && g->a[n] < kend - 1e-12)
		n++;
	return n;
}

/* The truncated tail beyond a depth's last panel, as a multiple of that
 * panel's contribution: 1 where e^{-kz} ended the integral (the rest is
 * below e^{-L}); where ktail did (z -> 0, the remainder decaying like
 * k^-(5/2) or faster), int_K^inf k^-(5/2) = K/(1.5 w) of the last panel. */
static double kgrid_tail_factor(const struct kgrid *g, double z)
{
	if (z > 0 && g->L / z < g->ktail)
		return 1.0;
	return (g->kb + g->ktail) / (1.5 * g->wt);
}

/* The most panels one k-grid may have: 2^20 (8 MB of ends; the normal
 * level's maps use a few hundred).  Their number grows with the band (the
 * window's M, itself bounded by ANVIL_DURBIN_M_MAX) and with the largest
 * radius asked for (panels no wider than 8/(1 + r_max)): past this an
 * input is refused rather than computed for days. */
#define KGRID_NP_MAX 1048576.0

static int kgrid_init(struct kgrid *g, const struct anvil_field *f, const flevel_t *lv,
		      const struct window *w, double rmax)
{
	double nu = f->nu, om = w->omega;
	/* no wider than a few pole distances, nor than J(k r_max) allows */
	double wb = fmin(fmin(1.0, lv->band_w * w->dl.c0 * sqrt(f->kap2)), 8.0 / (1.0 + rmax));
	g->kb = anvil_kband(om, om, nu, f->hh, f->cr);
	g->wt = fmin(2.0, 8.0 / (1.0 + rmax));
	g->ktail = lv->ktail;
	g->L = lv->L;
	double nbd = ceil(g->kb / wb), ntd = ceil(g->ktail / g->wt);
	/* compared as doubles before the casts: a radius of 1e6 r0 asks for
	 * more panels than size_t holds */
	if (!(nbd + ntd <= KGRID_NP_MAX))
		return ANVIL_EINVAL;
	size_t nb = (size_t)nbd, nt = (size_t)ntd;
	g->np = nb + nt;
	g->a = malloc((g->np + 1) * sizeof *g->a);
	if (!g->a)
		return ANVIL_ENOMEM;
	for (size_t i = 0; i <= nb; i++)
		g->a[i] = g->kb * (double)i / (double)nb;
	g->wt = g->ktail / (double)nt;
	for (size_t i = 1; i <= nt; i++)
		g->a[nb + i] = g->kb + g->wt * (double)i;
	return ANVIL_OK;
}

/* ---- Bessel factors ------------------------------------------------------ */

/* The k-dependence of each Hankel integral at radius r, times Z^H(k):
 * k J0, k J1, k J1(kr)/r, k^2 J0. */
enum { JK_J0, JK_J1, JK_J1R, JK_KJ0, JK_COUNT };
static const int jkind_of_hs[HS_COUNT] = {
	[HS_U] = JK_J1, [HS_UR] = JK_J1R, [HS_KU] = JK_KJ0, [HS_W] = JK_J0,
	[HS_SZZ] = JK_J0, [HS_SRZ] = JK_J1, [HS_LAM] = JK_J0,
};

static int bessel_at(double k, double r, double zh, double out[JK_COUNT])
{
	double x = k * r, j0 = 1.0, j1r = 0.5 * k; /* J1(kr)/r -> k/2 */
	if (x > 1e-8) {
		gsl_sf_result a, b;
		if (gsl_sf_bessel_J0_e(x, &a) || gsl_sf_bessel_J1_e(x, &b))
			return ANVIL_ENUM;
		j0 = a.val;
		j1r = b.val / r;
	} else if (x > 0) {
		j0 = 1.0 - 0.25 * x * x;
	}
	out[JK_J0] = zh * k * j0;
	out[JK_J1] = zh * k * j1r * r;
	out[JK_J1R] = zh * k * j1r;
	out[JK_KJ0] = zh * k * k * j0;
	return ANVIL_OK;
}

/* ---- assembling the outputs ----------------------------------------------- */

/* The seven Hankel integrals at one (r, z, t) and their error parts: the
 * Gauss-Kronrod difference, the half-band difference and the last panel. */
struct hsv {
	double v[HS_COUNT], dG[HS_COUNT], dH[HS_COUNT], dT[HS_COUNT];
	double tailf;
};

static double combine(const double *c, const double *x)
{
	double s = 0;
	for (int h = 0; h < HS_COUNT; h++)
		s += c[h] * x[h];
	return s;
}

static void von_mises(struct anvil_fval *o)
{
	double zz = o->v[ANVIL_FQ_SZZ], rr = o->v[ANVIL_FQ_SRR], tt = o->v[ANVIL_FQ_STT],
	       rz = o->v[ANVIL_FQ_SRZ];
	o->v[ANVIL_FQ_VM] = sqrt(0.5 * ((rr - tt) * (rr - tt) + (tt - zz) * (tt - zz) +
					(zz - rr) * (zz - rr)) + 3.0 * rz * rz);
}

static void assemble(const struct anvil_field *f, const struct hsv *x, struct anvil_fval *o)
{
	double sd = 1.0 / (f->mu * f->r0), ss = 1.0 / (f->r0 * f->r0);
	for (int q = 0; q < ANVIL_FQ_VM; q++) {
		double sc = fq_info[q].stress ? ss : sd, v = combine(combo[q], x->v);
		/* twice the change from cutting the bandwidth by a third: the series
		 * converges like omega^(-3/2) near the load's ends, not monotonically */
		double e = fabs(combine(combo[q], x->dG)) + 2.0 * fabs(combine(combo[q], x->dH)) +
			   x->tailf * fabs(combine(combo[q], x->dT)) + f->load_rel * fabs(v);
		o->v[q] = sc * v;
		o->err[q] = sc * e;
	}
	von_mises(o);
}

/* The true contact (field.h): the static stresses of the Hertz contact of
 * radius a(t) in place of those of the r0 patch, both Huber's closed form
 * (hertz_field.c; the r0 patch's is what the Hankel sums hold, see
 * add_static), at (x, y) in units of r0.  The dynamic remainder is the r0
 * patch's.  Error: the load's, relative (the stresses grow like P^(1/3)). */
static void true_contact(const struct anvil_field *f, double x, double y, double tau,
			 struct anvil_fval *o)
{
	double P = load_at(f, tau);
	if (!f->true_contact || !(P > 0))
		return;
	double a = anvil_field_contact_radius(f, P), r = x * f->r0, z = y * f->r0;
	struct anvil_hertz_stress sa, sr;
	if (anvil_hertz_stress(a, 1.5 * P / (M_PI * a * a), f->nu, r, z, &sa) ||
	    anvil_hertz_stress(f->r0, 1.5 * P / (M_PI * f->r0 * f->r0), f->nu, r, z, &sr))
		return;
	const double d[4] = {sa.zz - sr.zz, sa.rr - sr.rr, sa.tt - sr.tt, sa.rz - sr.rz};
	const int q[4] = {ANVIL_FQ_SZZ, ANVIL_FQ_SRR, ANVIL_FQ_STT, ANVIL_FQ_SRZ};
	for (int i = 0; i < 4; i++) {
		o->v[q[i]] += d[i];
		o->err[q[i]] += f->load_rel * fabs(d[i]);
	}
	von_mises(o);
}

/* The von Mises error from the stresses': von Mises is sqrt(3/2) |dev sigma|
 * and |dev d| <= |d| (Frobenius). */
static void vm_error(struct anvil_fval *o)
{
	double ezz = o->err[ANVIL_FQ_SZZ], err_ = o->err[ANVIL_FQ_SRR],
	       ett = o->err[ANVIL_FQ_STT], erz = o->err[ANVIL_FQ_SRZ];
	o->err[ANVIL_FQ_VM] = sqrt(1.5 * (ezz * ezz + err_ * err_ + ett * ett + 2 * erz * erz));
}

/* The bandwidth error converges irregularly from point to point: the twin
 * can agree with the series by chance where both are off.  In the maximum
 * norm over a map (or a history) the local estimates did hold in every
 * study; pointwise they fell short by up to 0.7 of the largest one.  So
 * each estimate gets the largest of its set (n values, stride apart) on
 * top, the stresses one floor together (they share their errors' scale):
 * the estimates are those of the set in the maximum norm, plus local. */
static void error_floor(struct anvil_fval *o, size_t n, size_t stride)
{
	double m[ANVIL_FQ_VM] = {0};
	for (size_t i = 0; i < n; i++)
		for (int q = 0; q < ANVIL_FQ_VM; q++) {
			int g = fq_info[q].stress ? ANVIL_FQ_SZZ : q;
			m[g] = fmax(m[g], o[i * stride].err[q]);
		}
	for (size_t i = 0; i < n; i++) {
		for (int q = 0; q < ANVIL_FQ_VM; q++)
			o[i * stride].err[q] += m[fq_info[q].stress ? ANVIL_FQ_SZZ : q];
		vm_error(&o[i * stride]);
	}
}

/* The static part P(tau) F_st(r, z) added to the remainder's integrals. */
static void add_static(const struct anvil_field *f, double tau, const double *fst,
		       struct hsv *x)
{
	double P = load_at(f, tau);
	for (int h = 0; h < HS_COUNT; h++)
		x->v[h] += P * fst[h];
}

/* ---- maps: many radii, depths and instants ------------------------------- */

struct mapjob {
	const struct anvil_field *f;
	struct window w;
	struct kgrid g;
	size_t nr, nz, nt;
	double r_lo, dr, z_lo, dz;   /* dimensionless */
	const double *tau;           /* nt instants */
	cplx *an, *bn;               /* (M+1) x nt and (Mh+1) x nt Durbin weights
				      * with the load: the series and its twin */
	double *Pt, *Pth;            /* nt: the same sums of the load alone */
	double *acc, *acch;          /* nz x nt x FK: one node's time-domain kernels */
	cplx *f1, *f2;               /* nz: e^{-alpha (hh - z)} */
	double *jf;                  /* JK x nr */
	double *sK, *sG, *sH, *sT;   /* nz x nt x HS x nr: the Hankel sums */
	size_t *npan;                /* nz: panels used by each row */
	double *block;               /* owns the doubles above */
	unsigned hs;                 /* the Hankel integrals wanted (bits) */
};

static void mapjob_free(struct mapjob *m)
{
	free(m->w.s);
	free(m->g.a);
	free(m->an);
	free(m->f1);
	free(m->npan);
	free(m->block);
}

static int mapjob_alloc(struct mapjob *m)
{
	size_t nz = m->nz, nt = m->nt, nr = m->nr, M1 = m->w.M + 1;
	size_t nacc = nz * nt * FK_COUNT, nsum = nz * nt * HS_COUNT * nr;
	m->an = malloc((M1 + m->w.Mh + 1) * nt * sizeof *m->an);
	m->f1 = malloc(2 * nz * sizeof *m->f1);
	m->npan = malloc(nz * sizeof *m->npan);
	m->block = calloc(2 * nt + 2 * nacc + JK_COUNT * nr + 4 * nsum, sizeof *m->block);
	if (!m->an || !m->f1 || !m->npan || !m->block)
		return ANVIL_ENOMEM;
	m->f2 = m->f1 + nz;
	m->bn = m->an + M1 * nt;
	m->Pt = m->block;
	m->Pth = m->Pt + nt;
	m->acc = m->Pth + nt;
	m->acch = m->acc + nacc;
	m->jf = m->acch + nacc;
	m->sK = m->jf + JK_COUNT * nr;
	m->sG = m->sK + nsum;
	m->sH = m->sG + nsum;
	m->sT = m->sH + nsum;
	return ANVIL_OK;
}

/* The Durbin weights of every instant, and the load's own Durbin sums (the
 * static kernels are subtracted with these, so that the subtraction is
 * exact for the truncated series too). */
static void mapjob_weights(struct mapjob *m)
{
	size_t nt = m->nt;
	for (size_t it = 0; it < nt; it++) {
		durbin_weights(&m->w, m->tau[it], m->w.M, m->an + it, nt);
		durbin_weights(&m->w, m->tau[it], m->w.Mh, m->bn + it, nt);
		m->Pt[it] = m->Pth[it] = 0;
		for (size_t n = 0; n <= m->w.M; n++)
			m->Pt[it] += creal(m->an[n * nt + it]);
		for (size_t n = 0; n <= m->w.Mh; n++)
			m->Pth[it] += creal(m->bn[n * nt + it]);
	}
	for (size_t iz = 0; iz < m->nz; iz++)
		m->npan[iz] = kgrid_panels(&m->g, m->z_lo + m->dz * (double)iz);
}

/* Drop what would turn denormal: far below anything summed here. */
static cplx tiny0(cplx x)
{
	return fabs(creal(x)) + fabs(cimag(x)) < 1e-250 ? 0.0 : x;
}

/* e^{-alpha (hh - z)} for the rows below nza, from the deepest up (so the
 * recurrence decays). */
static void rows_bottom(const struct mapjob *m, cplx al, size_t nza, cplx *fv)
{
	cplx step = cexp(-al * m->dz);
	fv[nza - 1] = cexp(-al * (m->f->hh - (m->z_lo + m->dz * (double)(nza - 1))));
	for (size_t iz = nza - 1; iz-- > 0;)
		fv[iz] = tiny0(fv[iz + 1] * step);
}

/* acc[it][q] += Re(a[it] out[q]) for every instant. */
static void accumulate(size_t nt, const cplx *a, const cplx *out, double *acc)
{
	for (size_t it = 0; it < nt; it++, acc += FK_COUNT) {
		double ar = creal(a[it]), ai = cimag(a[it]);
		for (int q = 0; q < FK_COUNT; q++)
			acc[q] += ar * creal(out[q]) - ai * cimag(out[q]);
	}
}

/* Add term n of the Durbin series (and of its twin) at one k to every row
 * and instant. */
static void rows_term(struct mapjob *m, const struct anvil_fk_coef *c, size_t n, size_t nza)
{
	const struct anvil_field *f = m->f;
	size_t nt = m->nt;
	int layer = isfinite(f->hh);
	cplx s1 = cexp(-c->al1 * m->dz), s2 = cexp(-c->al2 * m->dz);
	cplx e1 = cexp(-c->al1 * m->z_lo), e2 = cexp(-c->al2 * m->z_lo);
	const cplx *an = m->an + n * nt, *bn = m->bn + n * nt;
	if (layer) {
		rows_bottom(m, c->al1, nza, m->f1);
		rows_bottom(m, c->al2, nza, m->f2);
	}
	for (size_t iz = 0; iz < nza; iz++) {
		cplx out[FK_COUNT];
		anvil_fk_at(c, f->kap2, e1, layer ? m->f1[iz] : 0, e2, layer ? m->f2[iz] : 0, out);
		accumulate(nt, an, out, m->acc + iz * nt * FK_COUNT);
		if (n <= m->w.Mh)
			accumulate(nt, bn, out, m->acch + iz * nt * FK_COUNT);
		e1 = tiny0(e1 * s1);
		e2 = tiny0(e2 * s2);
	}
}

/* y += a x, four at a time so that -O2's straight-line vectoriser packs it. */
static void axpy(size_t n, double a, const double *restrict x, double *restrict y)
{
	size_t i = 0;
	for (; i + 4 <= n; i += 4) {
		y[i] += a * x[i];
		y[i + 1] += a * x[i + 1];
		y[i + 2] += a * x[i + 2];
		y[i + 3] += a * x[i + 3];
	}
	for (; i < n; i++)
		y[i] += a * x[i];
}

/* One row and instant of a node: the static kernels off, then into the
 * Hankel sums of every radius. */
static void node_row_sums(struct mapjob *m, size_t iz, size_t it, const double *st,
			  double wk, double wgs, int tail)
{
	size_t nr = m->nr, base = ((iz * m->nt + it) * HS_COUNT) * nr;
	const double *a = m->acc + (iz * m->nt + it) * FK_COUNT;
	const double *ah = m->acch + (iz * m->nt + it) * FK_COUNT;
	for (int h = 0; h < HS_COUNT; h++) {
		if (!(m->hs & 1u << h))
			continue;
		int q = anvil_fk_of_hs[h];
		const double *J = m->jf + jkind_of_hs[h] * nr;
		double v = a[q] - st[q] * m->Pt[it], vh = ah[q] - st[q] * m->Pth[it];
		size_t o = base + (size_t)h * nr;
		axpy(nr, wk * v, J, m->sK + o);
		if (wgs != 0)
			axpy(nr, wgs * v, J, m->sG + o);
		axpy(nr, wk * vh, J, m->sH + o);
		if (tail)
			axpy(nr, wk * v, J, m->sT + o);
	}
}

static int node_hankel(struct mapjob *m, double k, double wk, double wgs, size_t p,
		       size_t nza)
{
	double zh = anvil_kernel_zhat(k), b[JK_COUNT];
	for (size_t ir = 0; ir < m->nr; ir++) {
		if (bessel_at(k, m->r_lo + m->dr * (double)ir, zh, b))
			return ANVIL_ENUM;
		for (int j = 0; j < JK_COUNT; j++)
			m->jf[j * m->nr + ir] = b[j];
	}
	for (size_t iz = 0; iz < nza; iz++) {
		double st[FK_COUNT];
		anvil_fk_static(k, m->z_lo + m->dz * (double)iz, m->f->nu, st);
		for (size_t it = 0; it < m->nt; it++)
			node_row_sums(m, iz, it, st, wk, wgs, m->npan[iz] == p + 1);
	}
	return ANVIL_OK;
}

static int map_node(struct mapjob *m, double k, double wk, double wgs, size_t p, size_t nza)
{
	const struct anvil_field *f = m->f;
	size_t nacc = nza * m->nt * FK_COUNT;
	memset(m->acc, 0, nacc * sizeof *m->acc);
	memset(m->acch, 0, nacc * sizeof *m->acch);
	for (size_t n = 0; n <= m->w.M; n++) {
		struct anvil_fk_coef c;
		anvil_fk_coef(k, m->w.s[n], f->kap2, f->hh, &c);
		rows_term(m, &c, n, nza);
	}
	for (size_t i = 0; i < nacc; i++)
		if (!isfinite(m->acc[i]))
			return ANVIL_ENUM;
	return node_hankel(m, k, wk, wgs, p, nza);
}

static int map_panels(struct mapjob *m)
{
	const struct anvil_field *f = m->f;
	for (size_t p = 0; p < m->g.np; p++) {
		size_t nza = 0;
		while (nza < m->nz && m->npan[nza] > p)
			nza++;
		if (nza == 0)
			break; /* rows are sorted by depth: deeper ones end sooner */
		for (int j = 0; j < ANVIL_GK21_NODES; j++) {
			double k, wk, wgs;
			anvil_gk21_node(m->g.a[p], m->g.a[p + 1], j, &k, &wk, &wgs);
			int st = map_node(m, k, wk, wgs, p, nza);
			if (st)
				return st;
		}
		if (f->progress && f->progress(f->pctx, (double)(p + 1) / (double)m->g.np, "field"))
			return ANVIL_ECANCEL;
	}
	return ANVIL_OK;
}

/* Unwanted quantities (not computed) as NaN. */
static void drop_unwanted(unsigned want, struct anvil_fval *o)
{
	for (int q = 0; q < ANVIL_FQ_COUNT; q++)
		if (!(want & 1u << q))
			o->v[q] = o->err[q] = NAN;
}

static void map_values(const struct mapjob *m, struct anvil_fval *out)
{
	size_t nr = m->nr, nz = m->nz;
	double fst[HS_COUNT];
	for (size_t iz = 0; iz < nz; iz++) {
		double z = m->z_lo + m->dz * (double)iz, tf = kgrid_tail_factor(&m->g, z);
		for (size_t ir = 0; ir < nr; ir++) {
			anvil_fk_static_field(m->f->nu, m->r_lo + m->dr * (double)ir, z, fst);
			for (size_t it = 0; it < m->nt; it++) {
				struct hsv x = {.tailf = tf};
				size_t base = ((iz * m->nt + it) * HS_COUNT) * nr + ir;
				for (int h = 0; h < HS_COUNT; h++) {
					size_t o = base + (size_t)h * nr;
					x.v[h] = m->sK[o];
					x.dG[h] = m->sK[o] - m->sG[o];
					x.dH[h] = m->sK[o] - m->sH[o];
					x.dT[h] = m->sT[o];
				}
				add_static(m->f, m->tau[it], fst, &x);
				assemble(m->f, &x, &out[(it * nz + iz) * nr + ir]);
				true_contact(m->f, m->r_lo + m->dr * (double)ir, z, m->tau[it],
					     &out[(it * nz + iz) * nr + ir]);
			}
		}
	}
}

static void map_output(const struct mapjob *m, unsigned want, struct anvil_fval *out)
{
	size_t nr = m->nr, nz = m->nz;
	map_values(m, out);
	for (size_t it = 0; it < m->nt; it++)
		error_floor(out + it * nz * nr, nz * nr, 1);
	for (size_t i = 0; i < m->nt * nz * nr; i++)
		drop_unwanted(want, &out[i]);
}

static int check_times(const struct anvil_field *f, size_t nt, const double *t,
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

static int check_point(const struct anvil_field *f, double r, double z, struct anvil_err *err)
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

static int check_grid(const struct anvil_field *f, const struct anvil_field_grid *g,
		      struct anvil_err *err)
{
	int st = check_point(f, g->r_lo, g->z_lo, err);
	if (!st)
		st = check_point(f, g->r_hi, g->z_hi, err);
	if (!st && (g->nr < 1 || g->nz < 1 || g->r_hi < g->r_lo || g->z_hi < g->z_lo ||
		    (g->nr == 1 && g->r_hi != g->r_lo) || (g->nz == 1 && g->z_hi != g->z_lo)))
		st = anvil_err_set(err, ANVIL_EINVAL, "field: bad grid (%zu x %zu)", g->nr, g->nz);
	return st;
}

/* The message of a failed map or history: ANVIL_EINVAL there is a window
 * or k-grid past its bound (window_init, kgrid_init). */
static int field_fail(const struct anvil_field *f, int st, const char *what,
		      struct anvil_err *err)
{
	if (st == ANVIL_EINVAL)
		return anvil_err_set(err, st, "%s: the load (%.4g us) or the radii asked for need "
				     "more Fourier terms or k panels than the bounds allow", what,
				     anvil_field_t_load(f) * 1e6);
	return anvil_err_set(err, st, "%s: %s", what, anvil_strerror(st));
}

/* A map at the settings of level lv (the peak search locates at draft). */
static int field_map(struct anvil_field *f, const flevel_t *lv, size_t nt, const double *t,
		     const struct anvil_field_grid *g, unsigned quantities,
		     struct anvil_fval *out, struct anvil_err *err)
{
	double tau_hi, s = f->c2 / f->r0;
	int st = check_times(f, nt, t, &tau_hi, err);
	if (!st)
		st = check_grid(f, g, err);
	if (st)
		return st;
	unsigned want = quantities ? quantities : (1u << ANVIL_FQ_COUNT) - 1;
	struct mapjob m = {.f = f, .nr = g->nr, .nz = g->nz, .nt = nt, .hs = hs_needed(want)};
	double *tau = malloc(nt * sizeof *tau);
	m.r_lo = g->r_lo / f->r0;
	m.dr = g->nr > 1 ? (g->r_hi - g->r_lo) / f->r0 / (double)(g->nr - 1) : 0;
	m.z_lo = g->z_lo / f->r0;
	m.dz = g->nz > 1 ? (g->z_hi - g->z_lo) / f->r0 / (double)(g->nz - 1) : 0;
	m.tau = tau;
	st = tau ? window_init(f, lv, tau_hi, &m.w) : ANVIL_ENOMEM;
	for (size_t i = 0; tau && i < nt; i++)
		tau[i] = t[i] * s;
	if (!st)
		st = kgrid_init(&m.g, f, lv, &m.w, g->r_hi / f->r0);
	if (!st)
		st = mapjob_alloc(&m);
	if (!st) {
		mapjob_weights(&m);
		st = map_panels(&m);
	}
	if (!st)
		map_output(&m, want, out);
	mapjob_free(&m);
	free(tau);
	return st ? field_fail(f, st, "field map", err) : ANVIL_OK;
}

int anvil_field_map(struct anvil_field *f, size_t nt, const double *t,
		    const struct anvil_field_grid *g, unsigned quantities,
		    struct anvil_fval *out, struct anvil_err *err)
{
	return field_map(f, FLEVEL(f->acc), nt, t, g, quantities, out, err);
}

/* ---- points: few places, many times --------------------------------------- */

struct ptjob {
	const struct anvil_field *f;
	struct window w;
	struct kgrid g;
	size_t npt;
	double *r, *z;            /* dimensionless */
	size_t *npan;             /* panels used by each point */
	cplx *spK, *spG, *spT;    /* npt x (M+1) x HS: the transformed integrals */
	double *stK, *stG, *stT;  /* npt x HS: their static parts' integrals */
	double *jf;               /* npt x JK */
};

static void ptjob_free(struct ptjob *j)
{
	free(j->w.s);
	free(j->g.a);
	free(j->r);
	free(j->npan);
	free(j->spK);
}

static int ptjob_alloc(struct ptjob *j)
{
	size_t n = j->npt, ns = n * (j->w.M + 1) * HS_COUNT;
	j->r = calloc(2 * n + 3 * n * HS_COUNT + n * JK_COUNT, sizeof *j->r);
	j->npan = malloc(n * sizeof *j->npan);
	j->spK = calloc(3 * ns, sizeof *j->spK);
	if (!j->r || !j->npan || !j->spK)
		return ANVIL_ENOMEM;
	j->z = j->r + n;
	j->stK = j->z + n;
	j->stG = j->stK + n * HS_COUNT;
	j->stT = j->stG + n * HS_COUNT;
	j->jf = j->stT + n * HS_COUNT;
	j->spG = j->spK + ns;
	j->spT = j->spG + ns;
	return ANVIL_OK;
}

/* Term n of every active point at one k. */
static void points_term(struct ptjob *j, const struct anvil_fk_coef *c, size_t n, size_t p,
			double wk, double wgs)
{
	const struct anvil_field *f = j->f;
	int layer = isfinite(f->hh);
	size_t M1 = j->w.M + 1;
	for (size_t i = 0; i < j->npt; i++) {
		double z = j->z[i];
		cplx out[FK_COUNT];
		if (j->npan[i] <= p)
			continue;
		anvil_fk_at(c, f->kap2, cexp(-c->al1 * z), layer ? cexp(-c->al1 * (f->hh - z)) : 0,
			    cexp(-c->al2 * z), layer ? cexp(-c->al2 * (f->hh - z)) : 0, out);
		size_t o = (i * M1 + n) * HS_COUNT;
		for (int h = 0; h < HS_COUNT; h++) {
			cplx v = out[anvil_fk_of_hs[h]] * j->jf[i * JK_COUNT + jkind_of_hs[h]];
			j->spK[o + h] += wk * v;
			j->spG[o + h] += wgs * v;
			if (j->npan[i] == p + 1)
				j->spT[o + h] += wk * v;
		}
	}
}

/* The static kernels' integrals over the same nodes (s-independent). */
static void points_static(struct ptjob *j, double k, size_t p, double wk, double wgs)
{
	for (size_t i = 0; i < j->npt; i++) {
		double st[FK_COUNT];
		if (j->npan[i] <= p)
			continue;
		anvil_fk_static(k, j->z[i], j->f->nu, st);
		for (int h = 0; h < HS_COUNT; h++) {
			double v = st[anvil_fk_of_hs[h]] * j->jf[i * JK_COUNT + jkind_of_hs[h]];
			j->stK[i * HS_COUNT + h] += wk * v;
			j->stG[i * HS_COUNT + h] += wgs * v;
			if (j->npan[i] == p + 1)
				j->stT[i * HS_COUNT + h] += wk * v;
		}
	}
}

static int points_node(struct ptjob *j, double k, double wk, double wgs, size_t p)
{
	double zh = anvil_kernel_zhat(k);
	for (size_t i = 0; i < j->npt; i++)
		if (j->npan[i] > p && bessel_at(k, j->r[i], zh, j->jf + i * JK_COUNT))
			return ANVIL_ENUM;
	for (size_t n = 0; n <= j->w.M; n++) {
		struct anvil_fk_coef c;
		anvil_fk_coef(k, j->w.s[n], j->f->kap2, j->f->hh, &c);
		points_term(j, &c, n, p, wk, wgs);
	}
	points_static(j, k, p, wk, wgs);
	return ANVIL_OK;
}

static int points_panels(struct ptjob *j)
{
	const struct anvil_field *f = j->f;
	size_t pmax = 0;
	for (size_t i = 0; i < j->npt; i++)
		pmax = j->npan[i] > pmax ? j->npan[i] : pmax;
	for (size_t p = 0; p < pmax; p++) {
		for (int n = 0; n < ANVIL_GK21_NODES; n++) {
			double k, wk, wgs;
			anvil_gk21_node(j->g.a[p], j->g.a[p + 1], n, &k, &wk, &wgs);
			if (points_node(j, k, wk, wgs, p))
				return ANVIL_ENUM;
		}
		if (f->progress && f->progress(f->pctx, (double)(p + 1) / (double)pmax, "field"))
			return ANVIL_ECANCEL;
	}
	return ANVIL_OK;
}

/* The remainder at instant tau from one point's transformed integrals
 * (times the load's transform, less the static part), to terms nmax. */
static double points_invert(const cplx *a, const cplx *sp, double st, size_t nmax, int h)
{
	double s = 0;
	for (size_t n = 0; n <= nmax; n++)
		s += creal(a[n] * (sp[n * HS_COUNT + h] - st));
	return s;
}

static int points_output(const struct ptjob *j, size_t nt, const double *tau,
			 struct anvil_fval *out)
{
	size_t M1 = j->w.M + 1;
	cplx *a = malloc((M1 + j->w.Mh + 1) * sizeof *a), *b = a + M1;
	if (!a)
		return ANVIL_ENOMEM;
	for (size_t i = 0; i < j->npt; i++) {
		double fst[HS_COUNT], tf = kgrid_tail_factor(&j->g, j->z[i]);
		const cplx *sK = j->spK + i * M1 * HS_COUNT, *sG = j->spG + i * M1 * HS_COUNT,
			   *sT = j->spT + i * M1 * HS_COUNT;
		const double *tK = j->stK + i * HS_COUNT, *tG = j->stG + i * HS_COUNT,
			     *tT = j->stT + i * HS_COUNT;
		anvil_fk_static_field(j->f->nu, j->r[i], j->z[i], fst);
		for (size_t it = 0; it < nt; it++) {
			struct hsv x = {.tailf = tf};
			durbin_weights(&j->w, tau[it], j->w.M, a, 1);
			durbin_weights(&j->w, tau[it], j->w.Mh, b, 1);
			for (int h = 0; h < HS_COUNT; h++) {
				x.v[h] = points_invert(a, sK, tK[h], j->w.M, h);
				x.dG[h] = x.v[h] - points_invert(a, sG, tG[h], j->w.M, h);
				x.dH[h] = x.v[h] - points_invert(b, sK, tK[h], j->w.Mh, h);
				x.dT[h] = points_invert(a, sT, tT[h], j->w.M, h);
			}
			add_static(j->f, tau[it], fst, &x);
			assemble(j->f, &x, &out[i * nt + it]);
			true_contact(j->f, j->r[i], j->z[i], tau[it], &out[i * nt + it]);
		}
		error_floor(out + i * nt, nt, 1);
	}
	free(a);
	return ANVIL_OK;
}

int anvil_field_points(struct anvil_field *f, size_t npt, const double *r,
		       const double *z, size_t nt, const double *t,
		       struct anvil_fval *out, struct anvil_err *err)
{
	double tau_hi, rmax = 0;
	int st = check_times(f, nt, t, &tau_hi, err);
	for (size_t i = 0; !st && i < npt; i++) {
		st = check_point(f, r[i], z[i], err);
		rmax = fmax(rmax, r[i] / f->r0);
	}
	if (st || npt == 0)
		return st;
	struct ptjob j = {.f = f, .npt = npt};
	double *tau = malloc(nt * sizeof *tau);
	st = tau ? window_init(f, FLEVEL(f->acc), tau_hi, &j.w) : ANVIL_ENOMEM;
	if (!st)
		st = kgrid_init(&j.g, f, FLEVEL(f->acc), &j.w, rmax);
	if (!st)
		st = ptjob_alloc(&j);
	for (size_t i = 0; !st && i < npt; i++) {
		j.r[i] = r[i] / f->r0;
		j.z[i] = z[i] / f->r0;
		j.npan[i] = kgrid_panels(&j.g, j.z[i]);
	}
	for (size_t i = 0; tau && i < nt; i++)
		tau[i] = t[i] * f->c2 / f->r0;
	if (!st)
		st = points_panels(&j);
	if (!st)
		st = points_output(&j, nt, tau, out);
	ptjob_free(&j);
	free(tau);
	return st ? field_fail(f, st, "field", err) : ANVIL_OK;
}

/* ---- the peak of von Mises ---------------------------------------------------- */

/* The search: a coarse space-time grid at draft settings (it only has to
 * find the right neighbourhood: von Mises varies on the scale of r0 and of
 * the contact time), r0/8 apart in the top 3 r0 where the contact stresses
 * are (the Hertz maximum is 0.5 r0 deep) and r0/2 below (bending), then a
 * finer grid one coarse cell around the best point at the field's own
 * settings, whose best point is the answer. */
#define PEAK_NR 25
#define PEAK_NT 12
#define PEAK_FINE 7
#define PEAK_NEAR 3.0 /* r0 */

struct peak_cell {
	double dr, dz, dt; /* the coarse spacing around the best point */
};

/* A map over instants t[0..nt) and grid g; its largest von Mises into pk
 * when it beats pk's (cell: the grid's spacing, for the refinement). */
static int peak_pass(struct anvil_field *f, const flevel_t *lv, size_t nt, const double *t,
		     const struct anvil_field_grid *g, struct anvil_field_peak *pk,
		     struct peak_cell *cell, struct anvil_err *err)
{
	size_t n = nt * g->nz * g->nr, b = 0;
	struct anvil_fval *v = malloc(n * sizeof *v);
	if (!v)
		return anvil_err_set(err, ANVIL_ENOMEM, "field: out of memory");
	int st = field_map(f, lv, nt, t, g, 1u << ANVIL_FQ_VM, v, err);
	for (size_t i = 1; !st && i < n; i++)
		if (v[i].v[ANVIL_FQ_VM] > v[b].v[ANVIL_FQ_VM])
			b = i;
	if (!st && !(v[b].v[ANVIL_FQ_VM] <= pk->vm)) {
		size_t it = b / (g->nz * g->nr), iz = (b / g->nr) % g->nz, ir = b % g->nr;
		double dr = g->nr > 1 ? (g->r_hi - g->r_lo) / (double)(g->nr - 1) : 0;
		double dz = g->nz > 1 ? (g->z_hi - g->z_lo) / (double)(g->nz - 1) : 0;
		pk->vm = v[b].v[ANVIL_FQ_VM];
		pk->vm_err = v[b].err[ANVIL_FQ_VM];
		pk->t = t[it];
		pk->z = g->z_lo + dz * (double)iz;
		pk->r = g->r_lo + dr * (double)ir;
		*cell = (struct peak_cell){dr, dz, nt > 1 ? t[1] - t[0] : 0};
	}
	free(v);
	return st;
}

/* [x - d, x + d] within [lo, hi]. */
static void around(double x, double d, double lo, double hi, double *a, double *b)
{
	*a = fmax(lo, x - d);
	*b = fmin(hi, x + d);
}

static int peak_coarse(struct anvil_field *f, struct anvil_field_peak *pk,
		       struct peak_cell *cell, struct anvil_err *err)
{
	const flevel_t *lv = FLEVEL(ANVIL_ACC_DRAFT);
	double h = anvil_field_h(f), r0 = f->r0, tl = anvil_field_t_load(f), t[PEAK_NT];
	double znear = isfinite(h) ? fmin(h, PEAK_NEAR * r0) : PEAK_NEAR * r0;
	size_t nz = (size_t)ceil(8.0 * znear / r0) + 1;
	struct anvil_field_grid g = {0, PEAK_NEAR * r0, 0, znear, PEAK_NR, nz < 2 ? 2 : nz};
	for (int i = 0; i < PEAK_NT; i++)
		t[i] = tl * (i + 1) / PEAK_NT;
	int st = peak_pass(f, lv, PEAK_NT, t, &g, pk, cell, err);
	if (st || !isfinite(h) || !(h > znear))
		return st;
	g.z_lo = znear;
	g.z_hi = h;
	g.nz = (size_t)fmin(41.0, ceil(2.0 * (h - znear) / r0) + 1);
	return peak_pass(f, lv, PEAK_NT, t, &g, pk, cell, err);
}

/* The true contact's peak lies at 0.48 a (nu = 0.3) below it, a << r0 for
 * a ball: under the coarse grid.  A pass over the top 2 a_max, a_max/8
 * apart, at instants around the peak force a quarter of the coarse step
 * apart (the Hertz field scales with a(t) and p0(t), both flat there). */
#define CONTACT_NR 17
#define CONTACT_NZ 17
#define CONTACT_NT 5
static int peak_contact(struct anvil_field *f, struct anvil_field_peak *pk,
			struct peak_cell *cell, struct anvil_err *err)
{
	size_t im = 0;
	for (size_t i = 1; i < f->nP; i++)
		if (f->P[i] > f->P[im])
			im = i;
	double tl = anvil_field_t_load(f), dt = tl / PEAK_NT / 4, t[CONTACT_NT];
	double tm = (double)im * f->dtau * f->r0 / f->c2, h = anvil_field_h(f);
	double a = anvil_field_contact_radius(f, f->P[im]);
	if (!(a > 0))
		return ANVIL_OK;
	for (int i = 0; i < CONTACT_NT; i++)
		t[i] = fmin(tl, fmax(0.5 * dt, tm + (i - CONTACT_NT / 2) * dt));
	struct anvil_field_grid g = {0, 2 * a, 0, fmin(2 * a, h), CONTACT_NR, CONTACT_NZ};
	return peak_pass(f, FLEVEL(ANVIL_ACC_DRAFT), CONTACT_NT, t, &g, pk, cell, err);
}

int anvil_field_peak(struct anvil_field *f, double yield, struct anvil_field_peak *pk,
		     struct anvil_err *err)
{
	double h = anvil_field_h(f), rmax = PEAK_NEAR * f->r0, zmax = isfinite(h) ? h : rmax;
	double tl = anvil_field_t_load(f), t0, t1, tf[PEAK_FINE];
	struct peak_cell cell = {0};
	struct anvil_field_grid g = {0};
	memset(pk, 0, sizeof *pk);
	pk->vm = -1;
	int st = peak_coarse(f, pk, &cell, err);
	if (!st && f->true_contact)
		st = peak_contact(f, pk, &cell, err);
	if (st)
		return st;
	around(pk->r, cell.dr, 0, rmax, &g.r_lo, &g.r_hi);
	around(pk->z, cell.dz, 0, zmax, &g.z_lo, &g.z_hi);
	around(pk->t, cell.dt, 0.5 * cell.dt, tl, &t0, &t1);
	g.nr = g.nz = PEAK_FINE;
	for (int i = 0; i < PEAK_FINE; i++)
		tf[i] = t0 + (t1 - t0) * i / (PEAK_FINE - 1);
	pk->vm = -1;
	st = peak_pass(f, FLEVEL(f->acc), PEAK_FINE, tf, &g, pk, &cell, err);
	pk->yield = yield > 0 ? yield : 0.0;
	pk->exceeded = pk->yield > 0 && pk->vm > pk->yield;
	return st;
}
