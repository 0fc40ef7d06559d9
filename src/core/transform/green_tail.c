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

/* panel i: its coefficients from the values at its Chebyshev points */
static void fit(struct green_tail *t, int i, size_t *evals)
{
	struct green_tail_panel *p = &t->p[i];
	double a = t->a[i], w = t->a[i + 1] - a, cs[2 * N];
	cplx f[N + 1];
	p->n = -1;
	if (!(2.0 * t->hh * (a + w) < TAIL_EXP_MAX))
		return;
	for (int m = 0; m < 2 * N; m++)
		cs[m] = cos(M_PI * m / N);
	for (int j = 0; j <= N; j++)
		f[j] = b_at(t, a + 0.5 * w * (1.0 + cs[j]));
	*evals += N + 1;
	double s3 = 0, s4 = 0, fmax_ = 0;
	for (int j = 0; j <= N; j++)
		fmax_ = fmax(fmax_, cabs(f[j]));
	for (int j = 0; j <= N; j++) {
		cplx sum = 0.5 * (f[0] + (j % 2 ? -f[N] : f[N]));
		for (int m = 1; m < N; m++)
			sum += f[m] * cs[(m * j) % (2 * N)];
		/* halved at j = 0 and N: then the interpolant is the plain sum */
		p->c[j] = sum * (j == 0 || j == N ? 1.0 : 2.0) / N;
		if (j > 3 * N / 4)
			s4 += cabs(p->c[j]);
		else if (j > N / 2)
			s3 += cabs(p->c[j]);
	}
	double r = s4 / s3, up = r <= 1.0 / 16 ? 2.0 * s4 * r / (1.0 - r) : s3 + s4;
	up += TAIL_ROUND * fmax_;
	if (isfinite(up) && isfinite(creal(p->c[0])) && isfinite(cimag(p->c[0]))) {
		p->n = N;
		p->delta = up;
	}
}

double green_tail_bound(struct green_tail *t, double kend, double (*env)(void *, double),
			void *ctx, size_t *evals)
{
	double e = 0;
	for (int i = 0; i < t->np && t->a[i] < kend; i++) {
		if (t->p[i].n == 0)
			fit(t, i, evals);
		if (t->p[i].n < 0)
			return INFINITY;
		e += t->p[i].delta * env(ctx, t->a[i]);
	}
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
	double a = t->a[lo], w = t->a[lo + 1] - a;
	double x = 2.0 * (k - a) / w - 1.0, q = 1.0 + k * t->hh;
	cplx b1 = 0, b2 = 0;
	for (int j = N; j >= 1; j--) {
		cplx b = 2.0 * x * b1 - b2 + p->c[j];
		b2 = b1;
		b1 = b;
	}
	return (x * b1 - b2 + p->c[0]) * (q * q * exp(-2.0 * t->hh * k) / k);
}

/* green_tail_w at TAIL_LANES points at once: each its own recurrence in
 * the same operations (the same bits), side by side in registers, where
 * one alone waits on each step's multiply and add (the recurrence is a
 * chain); lanes past n repeat the last point (made, not kept) */
#define TAIL_LANES 3
static void tail_w_lanes(const struct green_tail *t, const double *k, int n, cplx *out)
{
	const struct green_tail_panel *p[TAIL_LANES];
	double x[TAIL_LANES], q[TAIL_LANES], kk[TAIL_LANES];
	for (int i = 0; i < TAIL_LANES; i++) {
		kk[i] = k[i < n ? i : n - 1];
		int lo = panel_of(t, kk[i]);
		double a = t->a[lo], w = t->a[lo + 1] - a;
		p[i] = &t->p[lo];
		x[i] = 2.0 * (kk[i] - a) / w - 1.0;
		q[i] = 1.0 + kk[i] * t->hh;
	}
	cplx b1a = 0, b2a = 0, b1b = 0, b2b = 0, b1c = 0, b2c = 0;
	for (int j = N; j >= 1; j--) {
		cplx ba = 2.0 * x[0] * b1a - b2a + p[0]->c[j];
		cplx bb = 2.0 * x[1] * b1b - b2b + p[1]->c[j];
		cplx bc = 2.0 * x[2] * b1c - b2c + p[2]->c[j];
		b2a = b1a, b1a = ba;
		b2b = b1b, b1b = bb;
		b2c = b1c, b1c = bc;
	}
	cplx s[TAIL_LANES] = { x[0] * b1a - b2a + p[0]->c[0], x[1] * b1b - b2b + p[1]->c[0],
			       x[2] * b1c - b2c + p[2]->c[0] };
	for (int i = 0; i < n; i++)
		out[i] = s[i] * (q[i] * q[i] * exp(-2.0 * t->hh * kk[i]) / kk[i]);
}

void green_tail_w_n(const struct green_tail *t, const double *k, int n, cplx *out)
{
	for (int i = 0; i < n; i += TAIL_LANES)
		tail_w_lanes(t, k + i, n - i < TAIL_LANES ? n - i : TAIL_LANES, out + i);
}
