/* green_tail.c: the tail's kernel by Chebyshev interpolation on panels
 * (green_tail.h).
 *
 * The coefficients come from the values at the points t_i = cos(pi i/n)
 * by the DCT-I (Trefethen, Approximation Theory and Approximation
 * Practice, ch. 3), hand-written: 17 points, where GSL's FFT would want a
 * complex transform of 32 and its workspaces.  The error estimate follows
 * the coefficients' geometric decay: with S3 and S4 the sums of |c_j|
 * over j = 9..12 and 13..16 and r = S4/S3 (about rho^-4), what lies
 * beyond degree 16 is about S4 r/(1 - r), doubled for the aliasing (the
 * interpolant's error is at most twice the truncation's, ATAP ch. 4).
 * Where the coefficients do not fall that fast (r > 1/16: rho < 2, or
 * their rounding plateau), S3 + S4, which bounds what degree 8 would
 * leave out.  To either is added the values' own rounding, TAIL_ROUND of
 * the largest: the kernel's B jitters by up to 2.7e-13 of itself between
 * neighbouring k at omega = 0, k hh = 0.2 (W_c's cancellation there; a
 * few 1e-15 further out), below any coefficient's sight (tests/test_kcut.c
 * measures the interpolant against the kernel within this estimate; the
 * floor cost 2 % more evaluations on h = 0.02 r0). */
#include <math.h>

#include "green_tail.h"
#include "layer_bc.h"

typedef double complex cplx;

/* the panels' width times hh: half of it 2/3 of the complex modes'
 * height 2.25/hh; and at most TAIL_GROW of its start: the Lamb modes'
 * poles 0.375 kb before it are then 1.9 half-widths away.  (2, 3, 4 and
 * 6 with 0.4-0.6 took 1.47, 1.44, 1.43 and 1.45 M evaluations on h =
 * 0.02 r0, 1 kg at 10 m/s: wider panels are refused more often) */
#define TAIL_PANEL 3.0
#define TAIL_GROW 0.4
/* exp(2 k hh) stays finite below this */
#define TAIL_EXP_MAX 600.0
#define N GREEN_TAIL_DEG
#define TAIL_ROUND 1e-12 /* the values' rounding, relative (above) */

/* the panel after the one starting at a */
static double next_start(double a, double hh)
{
	return a + fmin(TAIL_PANEL / hh, TAIL_GROW * a);
}

int green_tail_count(double hh, double kb, double kend)
{
	int i = 0;
	for (double a = kb; i < GREEN_TAIL_PANELS && a < kend; i++)
		a = next_start(a, hh);
	return i;
}

void green_tail_key(struct green_tail *t, cplx s, double kap2, double hh, double kb, double kend)
{
	if (t->np && t->s == s && t->kap2 == kap2 && t->hh == hh && t->kb == kb && t->kend == kend)
		return;
	/* the DCT's cosines once (fit took them at every panel: 32 cos) */
	for (int m = 0; !t->cs_on && m < 2 * N; m++)
		t->cs[m] = cos(M_PI * m / N);
	t->cs_on = 1;
	t->s = s;
	t->kap2 = kap2;
	t->hh = hh;
	t->kb = kb;
	t->kend = kend;
	t->a[0] = kb;
	int i = 0;
	while (i < GREEN_TAIL_PANELS - 1 && t->a[i] < kend) {
		t->a[i + 1] = next_start(t->a[i], hh);
		t->p[i++].n = 0;
	}
	if (t->a[i] < kend) /* the last panel reaches kend (its delta says how well) */
		t->p[i++].n = 0;
	t->a[i] = fmax(t->a[i], kend);
	t->np = i;
}

/* B at k: W_c k exp(2 k hh)/(1 + k hh)^2 */
static cplx b_at(const struct green_tail *t, double k)
{
	struct anvil_layer_bc bc;
	anvil_layer_bc_solve(k, t->s, t->kap2, t->hh, &bc);
	double q = 1.0 + k * t->hh;
	return anvil_layer_bc_w_correction(&bc) * k * exp(2.0 * t->hh * k) / (q * q);
}

/* The coefficients c[0..n] of degree n (N or N0) from the values at its
 * points, f[j N/n] (the degree-N points, every (N/n)-th), and the
 * estimate of the error (above); 0 when not finite. */
#define N0 GREEN_TAIL_DEG0
static int coefs(const struct green_tail *t, const cplx *f, int n, cplx *c, double *delta)
{
	int d = N / n;
	double s3 = 0, s4 = 0, fmax_ = 0;
	for (int j = 0; j <= n; j++)
		fmax_ = fmax(fmax_, cabs(f[d * j]));
	for (int j = 0; j <= n; j++) {
		cplx sum = 0.5 * (f[0] + (j % 2 ? -f[N] : f[N]));
		for (int m = 1; m < n; m++)
			sum += f[d * m] * t->cs[(d * m * j) % (2 * N)];
		/* halved at j = 0 and n: then the interpolant is the plain sum */
		c[j] = sum * (j == 0 || j == n ? 1.0 : 2.0) / n;
		if (j > 3 * n / 4)
			s4 += cabs(c[j]);
		else if (j > n / 2)
			s3 += cabs(c[j]);
	}
	/* at N the last quarter's coefficients against the one before, r
	 * about rho^-4; at N0 twice S4 (|c7| + |c8|), what lies beyond while
	 * each pair is at most half the one before (rho >= sqrt 2): there the
	 * quarters are two coefficients, and their ratio's extrapolation fell
	 * short of the error by up to 12 times (tests/test_kcut.c), where 2 S4
	 * bounds it 17 times over (S3 + S4 130 times: 1 % more instructions
	 * on h = 0.02 r0, 100 kg at 10 m/s) */
	double r = s4 / s3;
	double up = n == N ? (r <= 1.0 / 16 ? 2.0 * s4 * r / (1.0 - r) : s3 + s4) : 2.0 * s4;
	up += TAIL_ROUND * fmax_;
	*delta = up;
	return isfinite(up) && isfinite(creal(c[0])) && isfinite(cimag(c[0]));
}

/* panel i at degree n (N0 or N): the values at its points not yet made,
 * then its coefficients.  The degree-N0 points are every other of N's,
 * so N after N0 takes the N - N0 others only: the same values (the same
 * bits) whichever came first. */
static void fit(struct green_tail *t, int i, int n, size_t *evals)
{
	struct green_tail_panel *p = &t->p[i];
	double a = t->a[i], w = t->a[i + 1] - a;
	int had = p->n, step = n == N ? (had == N0 ? 2 : 1) : 2, from = had == N0 ? 1 : 0;
	p->n = -1;
	if (!(2.0 * t->hh * (a + w) < TAIL_EXP_MAX))
		return;
	for (int j = from; j <= N; j += step)
		p->f[j] = b_at(t, a + 0.5 * w * (1.0 + t->cs[j]));
	*evals += (size_t)((N - from) / step + 1);
	if (n == N0) {
		if (coefs(t, p->f, N0, p->c0, &p->d0)) {
			for (int j = N0 + 1; j <= N; j++)
				p->c0[j] = 0;
			p->n = N0;
		}
	} else if (coefs(t, p->f, N, p->c, &p->d1)) {
		p->n = N;
	}
}

double green_tail_bound(struct green_tail *t, double kend, double (*env)(void *, double),
			void *ctx, double allow, size_t *evals)
{
	double e = 0, en[GREEN_TAIL_PANELS];
	int np = 0;
	for (; np < t->np && t->a[np] < kend; np++) {
		struct green_tail_panel *p = &t->p[np];
		if (p->n == 0)
			fit(t, np, N0, evals);
		if (p->n < 0)
			return INFINITY;
		en[np] = env(ctx, t->a[np]);
		p->deg = N0;
		p->delta = p->d0;
		e += p->d0 * en[np];
	}
	/* the larger degree from the first panel on (env falls with k: the
	 * first weigh most) while the sum exceeds allow.  On h = 0.02 r0, 100
	 * kg at 10 m/s the fits' evaluations fell by 13 %: the first panel or
	 * two at degree 16 carry the share, the rest stay at 8 */
	for (int i = 0; i < np && !(e <= allow); i++) {
		struct green_tail_panel *p = &t->p[i];
		if (p->n == N0)
			fit(t, i, N, evals);
		if (p->n < 0)
			return INFINITY;
		if (p->d1 < p->d0) {
			e += (p->d1 - p->d0) * en[i];
			p->deg = N;
			p->delta = p->d1;
		}
	}
	e = 0; /* added afresh, in order */
	for (int i = 0; i < np; i++)
		e += t->p[i].delta * en[i];
	return e;
}

/* panel of k: a[lo] <= k < a[lo + 1], or an end */
static int panel_of(const struct green_tail *t, double k)
{
	int lo = 0, hi = t->np - 1;
	while (lo < hi) {
		int m = (lo + hi + 1) / 2;
		if (t->a[m] <= k)
			lo = m;
		else
			hi = m - 1;
	}
	return lo;
}

/* Clenshaw's recurrence for the sum of c_j T_j(x) */
cplx green_tail_w(const struct green_tail *t, double k)
{
	int lo = panel_of(t, k);
	const struct green_tail_panel *p = &t->p[lo];
	const cplx *c = p->deg == N ? p->c : p->c0;
	double a = t->a[lo], w = t->a[lo + 1] - a;
	double x = 2.0 * (k - a) / w - 1.0, q = 1.0 + k * t->hh;
	cplx b1 = 0, b2 = 0;
	for (int j = p->deg; j >= 1; j--) {
		cplx b = 2.0 * x * b1 - b2 + c[j];
		b2 = b1;
		b1 = b;
	}
	return (x * b1 - b2 + c[0]) * (q * q * exp(-2.0 * t->hh * k) / k);
}

/* green_tail_w at TAIL_LANES points at once: each its own recurrence in
 * the same operations (the same bits), side by side in registers, where
 * one alone waits on each step's multiply and add (the recurrence is a
 * chain); lanes past n repeat the last point (made, not kept).  From the
 * lanes' largest degree: a lane of degree N0 adds its zero coefficients
 * above N0 to zeros first, which leaves them exactly zero (the same bits
 * as its own recurrence). */
#define TAIL_LANES 3
static void tail_w_lanes(const struct green_tail *t, const double *k, const double *e, int n,
			 cplx *out)
{
	const cplx *c[TAIL_LANES];
	double x[TAIL_LANES], q[TAIL_LANES], kk[TAIL_LANES];
	int deg = 0;
	for (int i = 0; i < TAIL_LANES; i++) {
		kk[i] = k[i < n ? i : n - 1];
		int lo = panel_of(t, kk[i]);
		double a = t->a[lo], w = t->a[lo + 1] - a;
		const struct green_tail_panel *p = &t->p[lo];
		c[i] = p->deg == N ? p->c : p->c0;
		deg = p->deg > deg ? p->deg : deg;
		x[i] = 2.0 * (kk[i] - a) / w - 1.0;
		q[i] = 1.0 + kk[i] * t->hh;
	}
	cplx b1a = 0, b2a = 0, b1b = 0, b2b = 0, b1c = 0, b2c = 0;
	for (int j = deg; j >= 1; j--) {
		cplx ba = 2.0 * x[0] * b1a - b2a + c[0][j];
		cplx bb = 2.0 * x[1] * b1b - b2b + c[1][j];
		cplx bc = 2.0 * x[2] * b1c - b2c + c[2][j];
		b2a = b1a, b1a = ba;
		b2b = b1b, b1b = bb;
		b2c = b1c, b1c = bc;
	}
	cplx s[TAIL_LANES] = { x[0] * b1a - b2a + c[0][0], x[1] * b1b - b2b + c[1][0],
			       x[2] * b1c - b2c + c[2][0] };
	for (int i = 0; i < n; i++)
		out[i] = s[i] * (q[i] * q[i] * (e ? e[i] : exp(-2.0 * t->hh * kk[i])) / kk[i]);
}

void green_tail_w_n(const struct green_tail *t, const double *k, const double *e, int n,
		    cplx *out)
{
	for (int i = 0; i < n; i += TAIL_LANES)
		tail_w_lanes(t, k + i, e ? e + i : NULL, n - i < TAIL_LANES ? n - i : TAIL_LANES,
			     out + i);
}
