/* green_cut.c: a k-integral's cut and the bound on its remainder
 * (green_cut.h).
 *
 * The layer correction f(k) = W_c(k) zhat(k p) k beyond the band.  At large
 * k the correction is O(E1^2) (layer_bc.c: its O(E) parts cancel between
 * the symmetric and antisymmetric solves), and in the static limit of the
 * free layer |W_c| k -> 4 (1 - nu) (k hh)^2 exp(-2 k hh).  So with
 *   Q(k) = (1 + k hh)^2 exp(-2 Re(alpha1) hh),  A(k) = |W_c(k)| k / Q(k),
 * A tends to A_INF = 4 (1 - nu); nearer the band the dynamic terms make it
 * larger, and it falls from there towards A_INF (from below or above):
 * sup_{k >= K} A(k) <= max(A(K), A_INF) to 0.31 % (measured on every k
 * from the band's end to 2.5 times the cut at ktail 1e-10, nu = 0-0.49,
 * hh = 0.01-100, omega = 0-400: the O(|s|^2/k^2) corrections to the
 * static limit).  The patch's transform has the envelope
 *   |zhat(y)| <= zenv(y) = min(1, 3 (1 + y)/y^3)/(2 pi),  nonincreasing,
 * and d Re(alpha1)/dk = Re (1 + z)^(-1/2), z = kap2 s^2/k^2, is at least
 * (1 + z0)^(-1/2) cos(asin(z0)/2) for |z| <= z0 < 1, so past K the
 * envelope c Q(k) zenv(k p) (c = max(A(K0), A_INF), K >= K0) falls at
 * least at the rate
 *   r(K) = 2 hh [(1 + z0)^(-1/2) cos(asin(z0)/2) - 1/(1 + K hh)],
 * z0 = kap2 |s|^2/K^2, and the remainder is at most c Q(K) zenv(K p)/r(K).
 *
 * The half-space's integrand (k W_hs - (1 - nu)) zhat(k): its bracket is
 * O(|s|^2/k^2) with G(k) = |bracket| k^2 nonincreasing past the band to
 * 0.13 % (the same grid, to ktail 1e-16), so the remainder past K >= K0
 * is at most G(K0) times the integral of zenv(x)/x^2 over [K, inf).
 *
 * Both bounds carry the factor SAFETY = 2 for those measured departures
 * (0.3 %) and the dynamic corrections' spread beyond the measured grid:
 * it moves a thin plate's cut by ln 2/(2 hh), one of its tail's 16-wide
 * pieces at hh = 0.02. */
#include <math.h>

#include <gsl/gsl_errno.h>

#include "green_cut.h"
#include "layer_bc.h"

typedef double complex cplx;

#define SAFETY 2.0
/* where 3 (1 + y)/y^3 = 1: zenv's two branches meet */
#define ZENV_Y 2.1038034027355366

static double zenv(double y)
{
	return (y > ZENV_Y ? 3.0 * (1.0 + y) / (y * y * y) : 1.0) / (2.0 * M_PI);
}

/* ln of Q(K) zenv(K p)/r(K) (the layer's bound over c); +HUGE where the
 * envelope does not yet fall (r <= 0: K hh below about z0) */
#define LN_HUGE 1e3
static double layer_ln_m(const struct green_cut *c, double K)
{
	double hh = c->hh, z0 = c->kap2 * creal(c->s * conj(c->s)) / (K * K);
	if (!(z0 < 1.0))
		return LN_HUGE;
	double r = 2.0 * hh * (cos(0.5 * asin(z0)) / sqrt(1.0 + z0) - 1.0 / (1.0 + K * hh));
	if (!(r > 0.0))
		return LN_HUGE;
	double al1 = creal(csqrt(K * K + c->kap2 * c->s * c->s));
	double zp = c->patch > 0 ? zenv(K * c->patch) : 1.0 / (2.0 * M_PI);
	return 2.0 * log1p(K * hh) - 2.0 * al1 * hh + log(zp) - log(r);
}

/* the integral of zenv(x)/x^2 over [K, inf), K > 0 */
static double hs_tail(double K)
{
	double y = fmax(K, ZENV_Y), in = 3.0 / (2.0 * M_PI) * (1.0 / (3.0 * y * y * y) + 0.25 / (y * y * y * y));
	return K < ZENV_Y ? in + (1.0 / K - 1.0 / ZENV_Y) / (2.0 * M_PI) : in;
}

/* ln of the bound past K with amplitude lc = ln(SAFETY c) */
struct lnb {
	const struct green_cut *c;
	double lc, lt; /* ln target */
};

static double ln_bound(double K, const struct lnb *b)
{
	return b->lc + (b->c->mode == ANVIL_GREEN_HALFSPACE ? log(hs_tail(K)) : layer_ln_m(b->c, K));
}

static double excess(double K, void *vb)
{
	const struct lnb *b = vb;
	return ln_bound(K, b) - b->lt;
}

/* The least K in [lo, hi] where the bound meets the target (its log is
 * decreasing in K): lo or hi when it does there, else Brent's bracket's
 * upper end (where it is met) to 1e-9 of K. */
static double solve(struct green_cut *c, struct lnb *b, double lo, double hi)
{
	if (excess(lo, b) <= 0 || !(excess(hi, b) < 0) || !c->root)
		return excess(lo, b) <= 0 ? lo : hi;
	gsl_function F = { excess, b };
	if (gsl_root_fsolver_set(c->root, &F, lo, hi))
		return hi;
	for (int i = 0; i < 100; i++) {
		if (gsl_root_fsolver_iterate(c->root))
			break;
		lo = gsl_root_fsolver_x_lower(c->root);
		hi = gsl_root_fsolver_x_upper(c->root);
		if (gsl_root_test_interval(lo, hi, 0.0, 1e-9) == GSL_SUCCESS)
			break;
	}
	return gsl_root_fsolver_x_upper(c->root);
}

/* ln(SAFETY c) for K >= K0, from one evaluation at K0 */
static double amplitude(struct green_cut *c, double K0)
{
	struct anvil_layer_bc bc;
	int hs = c->mode == ANVIL_GREEN_HALFSPACE;
	c->evals++;
	anvil_layer_bc_solve(K0, c->s, c->kap2, hs ? INFINITY : c->hh, &bc);
	if (hs) {
		double g = cabs(K0 * anvil_layer_bc_w_halfspace(&bc) - 0.5 / (1.0 - c->kap2));
		return log(SAFETY * g * K0 * K0);
	}
	double a = cabs(anvil_layer_bc_w_correction(&bc)) * K0;
	double lq = 2.0 * log1p(K0 * c->hh) - 2.0 * creal(bc.al1) * c->hh;
	double la = a > 0 ? log(a) - lq : -INFINITY;
	return log(SAFETY) + fmax(la, log(4.0 * (1.0 - c->nu)));
}

double green_cut_env(const struct green_cut *c, double K)
{
	double l = layer_ln_m(c, K);
	return l < LN_HUGE ? exp(l) : INFINITY;
}

double green_cut_find(struct green_cut *c, double k0, double kmax, double target, double *tail)
{
	struct lnb b = { c, 0.0, log(target) };
	double K = k0;
	if (c->mode != ANVIL_GREEN_HALFSPACE && kmax > k0) {
		/* first where the static asymptote's amplitude would meet it */
		b.lc = log(SAFETY * 4.0 * (1.0 - c->nu));
		K = solve(c, &b, k0, kmax);
	}
	b.lc = amplitude(c, K);
	K = solve(c, &b, K, kmax);
	*tail = exp(ln_bound(K, &b));
	return K;
}
