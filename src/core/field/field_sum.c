/* field_sum.c: the sums every field evaluation makes (field.h, field_impl.h).
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
 * spectral filter, see anvil_field_weights()), where
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

#include <gsl/gsl_sf_bessel.h>

#include "field_impl.h"
#include "hertz_field.h"
#include "kernel.h"

/* Each output (but von Mises) as a combination of the Hankel integrals:
 * sigma_rr = lambda e + 2 (1/r) d(r u)/dr - 2 u/r, sigma_tt = lambda e + 2 u/r. */
const double anvil_field_combo[ANVIL_FQ_VM][HS_COUNT] = {
	[ANVIL_FQ_U] = {[HS_U] = 1},
	[ANVIL_FQ_W] = {[HS_W] = 1},
	[ANVIL_FQ_SZZ] = {[HS_SZZ] = 1},
	[ANVIL_FQ_SRR] = {[HS_LAM] = 1, [HS_KU] = 2, [HS_UR] = -2},
	[ANVIL_FQ_STT] = {[HS_LAM] = 1, [HS_UR] = 2},
	[ANVIL_FQ_SRZ] = {[HS_SRZ] = 1},
};

/* The Hankel integrals each output needs (von Mises: all the stresses). */
unsigned anvil_field_hs_needed(unsigned quantities)
{
	unsigned m = 0;
	for (int q = 0; q < ANVIL_FQ_VM; q++)
		if (quantities & (1u << q) || (q >= ANVIL_FQ_SZZ && quantities & (1u << ANVIL_FQ_VM)))
			for (int h = 0; h < HS_COUNT; h++)
				if (anvil_field_combo[q][h] != 0)
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

/* ---- the Bromwich line ---------------------------------------------------- */

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

int anvil_field_window_init(const struct anvil_field *f, const flevel_t *lv, double tau_hi,
		       struct anvil_field_window *w)
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
void anvil_field_weights(const struct anvil_field_window *w, double tau, size_t nmax, cplx *a,
			   size_t stride)
{
	anvil_durbin_weights(&w->dl, tau, nmax, w->Phat, a, stride);
}

/* ---- the k panels ------------------------------------------------------------ */

/* Where the k-integral of depth z ends. */
static double kgrid_end(const struct anvil_field_kgrid *g, double z)
{
	return g->kb + (z > 0 ? fmin(g->ktail, g->L / z) : g->ktail);
}

/* How many panels depth z uses (its last is the returned value - 1). */
size_t anvil_field_kgrid_panels(const struct anvil_field_kgrid *g, double z)
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
double anvil_field_kgrid_tail_factor(const struct anvil_field_kgrid *g, double z)
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

int anvil_field_kgrid_init(struct anvil_field_kgrid *g, const struct anvil_field *f, const flevel_t *lv,
		      const struct anvil_field_window *w, double rmax)
{
	double nu = f->nu, om = w->omega;
	/* no wider than a few pole distances, nor than J(k r_max) allows */
	double wb = fmin(fmin(1.0, lv->band_w * w->dl.c0 * sqrt(f->kap2)), 8.0 / (1.0 + rmax));
	g->kb = anvil_kband(om, om, nu, f->hh, f->cr);
	g->wt = fmin(2.0, 8.0 / (1.0 + rmax));
	g->ktail = lv->ktail;
	g->L = lv->L;
	/* the poles' part of the band in pole-distance panels; past it (the
	 * band's + 3 is 3/hh or less where hh > 1: kernel.h
	 * anvil_kband_poles) the kernel has no pole and the panels are the
	 * tail's: on h = 100 r0 the band's last 3 wide held 5 of 33 panels */
	double kp = anvil_kband_poles(om, om, nu, f->hh, f->cr);
	double nbd = ceil(kp / wb), npd = kp < g->kb ? ceil((g->kb - kp) / g->wt) : 0,
	       ntd = ceil(g->ktail / g->wt);
	/* compared as doubles before the casts: a radius of 1e6 r0 asks for
	 * more panels than size_t holds */
	if (!(nbd + npd + ntd <= KGRID_NP_MAX))
		return ANVIL_EINVAL;
	size_t nb = (size_t)nbd, npl = (size_t)npd, nt = (size_t)ntd;
	g->np = nb + npl + nt;
	g->a = malloc((g->np + 1) * sizeof *g->a);
	if (!g->a)
		return ANVIL_ENOMEM;
	for (size_t i = 0; i <= nb; i++)
		g->a[i] = kp * (double)i / (double)nb;
	for (size_t i = 1; i <= npl; i++)
		g->a[nb + i] = i == npl ? g->kb : kp + (g->kb - kp) * (double)i / (double)npl;
	nb += npl;
	g->wt = g->ktail / (double)nt;
	for (size_t i = 1; i <= nt; i++)
		g->a[nb + i] = g->kb + g->wt * (double)i;
	return ANVIL_OK;
}

/* ---- Bessel factors ------------------------------------------------------ */

const int anvil_field_jkind_of_hs[HS_COUNT] = {
	[HS_U] = JK_J1, [HS_UR] = JK_J1R, [HS_KU] = JK_KJ0, [HS_W] = JK_J0,
	[HS_SZZ] = JK_J0, [HS_SRZ] = JK_J1, [HS_LAM] = JK_J0,
};

int anvil_field_bessel_at(double k, double r, double zh, double out[JK_COUNT])
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

void anvil_field_assemble(const struct anvil_field *f, const struct anvil_field_hsv *x, struct anvil_fval *o)
{
	double sd = 1.0 / (f->mu * f->r0), ss = 1.0 / (f->r0 * f->r0);
	for (int q = 0; q < ANVIL_FQ_VM; q++) {
		double sc = anvil_fq_is_stress(q) ? ss : sd, v = combine(anvil_field_combo[q], x->v);
		/* twice the change from cutting the bandwidth by a third: the series
		 * converges like omega^(-3/2) near the load's ends, not monotonically */
		double e = fabs(combine(anvil_field_combo[q], x->dG)) + 2.0 * fabs(combine(anvil_field_combo[q], x->dH)) +
			   x->tailf * fabs(combine(anvil_field_combo[q], x->dT)) + f->load_rel * fabs(v);
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
void anvil_field_true_contact(const struct anvil_field *f, double x, double y, double tau,
			 struct anvil_fval *o)
{
	double P = anvil_field_load_at(f, tau);
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
void anvil_field_error_floor(struct anvil_fval *o, size_t n, size_t stride)
{
	double m[ANVIL_FQ_VM] = {0};
	for (size_t i = 0; i < n; i++)
		for (int q = 0; q < ANVIL_FQ_VM; q++) {
			int g = anvil_fq_is_stress(q) ? ANVIL_FQ_SZZ : q;
			m[g] = fmax(m[g], o[i * stride].err[q]);
		}
	for (size_t i = 0; i < n; i++) {
		for (int q = 0; q < ANVIL_FQ_VM; q++)
			o[i * stride].err[q] += m[anvil_fq_is_stress(q) ? ANVIL_FQ_SZZ : q];
		vm_error(&o[i * stride]);
	}
}

/* The static part P(tau) F_st(r, z) added to the remainder's integrals. */
void anvil_field_add_static(const struct anvil_field *f, double tau, const double *fst,
		       struct anvil_field_hsv *x)
{
	double P = anvil_field_load_at(f, tau);
	for (int h = 0; h < HS_COUNT; h++)
		x->v[h] += P * fst[h];
}
