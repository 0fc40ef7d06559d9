/* test_fastconv: the online fast convolution (fastconv.c) against the
 * direct sum in long double, on random data and on the impact's own kind
 * of kernel; determinism; the error path. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fastconv.h"
#include "tap.h"

/* A reproducible uniform number in [-1, 1) (xorshift64). */
static double urand(unsigned long long *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 7;
	*s ^= *s << 17;
	return (double)(*s >> 11) / 4503599627370496.0 - 1.0;
}

/* Worst |c_fast - c_exact| / sum |x_m g_{n-m}| over n, with c_fast from
 * pushing x through f (c_n read before x_n is pushed, as the scheme does). */
static double worst_error(struct anvil_fastconv *f, const double *x, const double *g, size_t N)
{
	double worst = 0;
	for (size_t n = 0; n < N; n++) {
		long double c = 0, a = 0;
		for (size_t m = 0; m < n; m++) {
			c += (long double)x[m] * g[n - m];
			a += fabsl((long double)x[m] * g[n - m]);
		}
		double e = a > 0 ? (double)(fabsl(anvil_fastconv_next(f) - c) / a) : fabs(anvil_fastconv_next(f));
		worst = fmax(worst, e);
		anvil_fastconv_push(f, x[n]);
	}
	return worst;
}

static void test_random(size_t N, size_t direct_max, double bound, const char *what)
{
	unsigned long long s = 88172645463325252ULL + N;
	double *x = malloc(N * sizeof *x), *g = malloc(N * sizeof *g);
	for (size_t i = 0; i < N; i++) {
		x[i] = urand(&s);
		g[i] = urand(&s) / (1.0 + 0.01 * (double)i);
	}
	struct anvil_fastconv *f = anvil_fastconv_alloc(g, N, direct_max);
	double e = worst_error(f, x, g, N);
	ok(e < bound, "%s, N = %zu: worst error %.2g of sum |x g| (< %.0g)", what, N, e, bound);
	anvil_fastconv_free(f);
	free(x);
	free(g);
}

/* The impact's kernel: second differences of a ramp response, here of
 * R(t) = t^2/2 + sin(t) - t (a plate-like late part plus an oscillation),
 * against a smooth positive force pulse; and two runs give the same bits. */
static void test_impact_like(void)
{
	size_t N = 5000;
	double dt = 0.01, *x = malloc(N * sizeof *x), *g = malloc(N * sizeof *g);
	for (size_t j = 0; j < N; j++) {
		double t = (double)j * dt, R0 = t * t / 2 + sin(t) - t;
		double Rp = t + dt, Rm = t - dt;
		double R1 = Rp * Rp / 2 + sin(Rp) - Rp, Rm1 = j ? Rm * Rm / 2 + sin(Rm) - Rm : 0;
		g[j] = (R1 - 2 * R0 + Rm1) / dt;
		x[j] = pow(fmax(sin(M_PI * t / 30.0), 0.0), 1.5);
	}
	struct anvil_fastconv *f = anvil_fastconv_alloc(g, N, 0);
	double e = worst_error(f, x, g, N);
	ok(e < 5e-15, "impact-like kernel, N = %zu: worst error %.2g of sum |x g|", N, e);
	double last = anvil_fastconv_next(f);
	anvil_fastconv_reset(f);
	for (size_t n = 0; n + 1 < N; n++)
		anvil_fastconv_push(f, x[n]);
	ok(anvil_fastconv_count(f) == N - 1 && anvil_fastconv_next(f) != last,
	   "reset forgets the pushed values");
	double c1 = anvil_fastconv_next(f);
	anvil_fastconv_reset(f);
	for (size_t n = 0; n + 1 < N; n++)
		anvil_fastconv_push(f, x[n]);
	ok(anvil_fastconv_next(f) == c1, "the same pushes give the same bits");
	anvil_fastconv_push(f, x[N - 1]);
	ok(anvil_fastconv_push(f, 1.0) == -1 && anvil_fastconv_next(f) == 0.0,
	   "a push past the capacity is refused");
	anvil_fastconv_free(f);
	free(x);
	free(g);
}

/* A pair (x against g plus y against h, added in the spectrum) against
 * the direct sum in long double, with zero runs in both inputs (the
 * squares of all-zero sources are skipped); its FFT tables shared
 * (anvil_fastconv_fft) with a single convolution run alongside, which
 * must give the bits of one with its own tables. */
static void test_pair(size_t N, size_t direct_max, double bound)
{
	unsigned long long s = 1234567ULL + N;
	double *x = malloc(N * sizeof *x), *y = malloc(N * sizeof *y);
	double *g = malloc(N * sizeof *g), *h = malloc(N * sizeof *h), worst = 0;
	for (size_t i = 0; i < N; i++) {
		int gap = (i / 300) % 3 == 2; /* free flight: both zero */
		x[i] = gap ? 0.0 : urand(&s);
		y[i] = gap ? 0.0 : urand(&s);
		g[i] = urand(&s) / (1.0 + 0.01 * (double)i);
		h[i] = urand(&s) / (1.0 + 0.02 * (double)i);
	}
	struct anvil_fastconv_fft *t = anvil_fastconv_fft_alloc(N, direct_max);
	struct anvil_fastconv *f = anvil_fastconv_alloc_pair(g, h, N, direct_max, t);
	struct anvil_fastconv *a = anvil_fastconv_alloc_fft(g, N, direct_max, t);
	struct anvil_fastconv *b = anvil_fastconv_alloc(g, N, direct_max);
	int same = 1;
	for (size_t n = 0; n < N; n++) {
		long double c = 0, m = 0;
		for (size_t j = 0; j < n; j++) {
			c += (long double)x[j] * g[n - j] + (long double)y[j] * h[n - j];
			m += fabsl((long double)x[j] * g[n - j]) + fabsl((long double)y[j] * h[n - j]);
		}
		double e = m > 0 ? (double)(fabsl(anvil_fastconv_next(f) - c) / m)
				 : fabs(anvil_fastconv_next(f));
		worst = fmax(worst, e);
		same &= anvil_fastconv_next(a) == anvil_fastconv_next(b);
		anvil_fastconv_push_pair(f, x[n], y[n]);
		anvil_fastconv_push(a, x[n]);
		anvil_fastconv_push(b, x[n]);
	}
	ok(worst < bound, "pair, N = %zu, direct up to %zu: worst error %.2g of sum |x g| + |y h| (< %.0g)",
	   N, direct_max, worst, bound);
	ok(same, "shared FFT tables give the bits of own ones (N = %zu)", N);
	ok(anvil_fastconv_push_pair(a, 0.0, 1.0) == -1, "a single convolution refuses a second input");
	ok(anvil_fastconv_alloc_fft(g, 2 * N, direct_max, t) == NULL,
	   "tables that do not cover the capacity are refused");
	anvil_fastconv_free(f);
	anvil_fastconv_free(a);
	anvil_fastconv_free(b);
	anvil_fastconv_fft_free(t);
	free(x);
	free(y);
	free(g);
	free(h);
}

/* A lazy kernel: filled from the whole one as asked; fails past fail_at. */
struct lazy {
	const double *src[2];
	double *g[2];
	size_t asked, most, fail_at;
	int order_ok;
};

static int lazy_fill(void *ctx, size_t need)
{
	struct lazy *l = ctx;
	l->order_ok &= need > l->asked; /* asked only for more */
	if (need > l->fail_at)
		return 1;
	for (size_t j = l->asked; j < need; j++)
		for (int i = 0; i < 2; i++)
			if (l->g[i])
				l->g[i][j] = l->src[i][j];
	l->asked = need;
	return 0;
}

/* The lazy kernel gives the bits of the whole one, asks for no more than
 * the pushes read (2B before a square of side B: below 2n after n pushes),
 * keeps them after a reset, and a failing fill stops a push with -3. */
static void test_lazy(size_t N, size_t direct_max)
{
	unsigned long long s = 7654321ULL + N;
	double *x = malloc(N * sizeof *x), *g = malloc(N * sizeof *g), *h = malloc(N * sizeof *h);
	double *lg = malloc(N * sizeof *lg), *lh = malloc(N * sizeof *lh);
	for (size_t i = 0; i < N; i++) {
		x[i] = (i / 200) % 4 == 3 ? 0.0 : urand(&s);
		g[i] = urand(&s) / (1.0 + 0.01 * (double)i);
		h[i] = urand(&s) / (1.0 + 0.03 * (double)i);
	}
	struct lazy l = { { g, h }, { lg, lh }, 0, 0, (size_t)-1, 1 };
	struct anvil_fastconv *w = anvil_fastconv_alloc_pair(g, h, N, direct_max, NULL);
	struct anvil_fastconv *z = anvil_fastconv_alloc_lazy(lg, lh, N, direct_max, NULL, lazy_fill, &l);
	int same = 1, bounded = l.asked == 2;
	for (int round = 0; round < 2; round++) {
		size_t stop = round ? N : N / 3; /* a march that stops early, then a whole one */
		for (size_t n = 0; n < stop; n++) {
			same &= anvil_fastconv_next(w) == anvil_fastconv_next(z);
			anvil_fastconv_push_pair(w, x[n], 0.5 * x[n]);
			anvil_fastconv_push_pair(z, x[n], 0.5 * x[n]);
			bounded &= l.asked <= N && (round || l.asked <= 2 * (n + 1) || l.asked == 2);
		}
		if (!round)
			ok(l.asked < N, "lazy kernel, N = %zu: %zu of it made for %zu pushes", N, l.asked,
			   stop);
		anvil_fastconv_reset(w);
		anvil_fastconv_reset(z);
	}
	ok(same, "lazy kernel (N = %zu, direct up to %zu): the bits of the whole one, also after a reset",
	   N, direct_max);
	ok(bounded && l.order_ok, "lazy kernel: asked for no more than 2n after n pushes, never twice");
	struct lazy f = { { g, h }, { lg, lh }, 0, 0, 40, 1 };
	struct anvil_fastconv *e = anvil_fastconv_alloc_lazy(lg, NULL, N, direct_max, NULL, lazy_fill, &f);
	int r = 0;
	for (size_t n = 0; n < N && !r; n++)
		r = anvil_fastconv_push(e, x[n] + 1.0);
	ok(r == -3 && f.asked <= 40, "a failing fill stops the push with -3");
	ok(anvil_fastconv_alloc_lazy(lg, NULL, N, 0, NULL, NULL, NULL) == NULL, "a lazy kernel needs its fill");
	anvil_fastconv_free(e);
	anvil_fastconv_free(w);
	anvil_fastconv_free(z);
	free(x);
	free(g);
	free(h);
	free(lg);
	free(lh);
}

/* A late read (anvil_fastconv_at) of a complete target gives the bits
 * next() gave when it was the next, also with free flights (zero runs)
 * whose squares are skipped; a target not yet complete is refused. */
static void test_at(size_t N)
{
	unsigned long long s = 99991ULL + N;
	double *x = malloc(N * sizeof *x), *g = malloc(N * sizeof *g), *c = malloc(N * sizeof *c);
	for (size_t i = 0; i < N; i++) {
		x[i] = (i / 300) % 3 == 2 ? 0.0 : urand(&s);
		g[i] = urand(&s) / (1.0 + 0.01 * (double)i);
	}
	struct anvil_fastconv *f = anvil_fastconv_alloc(g, N, 0);
	int same = 1, refused = 1;
	double v = 0;
	for (size_t n = 0; n < N; n++) {
		c[n] = anvil_fastconv_next(f);
		refused &= anvil_fastconv_at(f, n + 1, &v) == -1;
		anvil_fastconv_push(f, x[n]);
		for (size_t t = n > 40 ? n - 40 : 0; t <= n; t++) /* the ends' reads: just behind */
			same &= anvil_fastconv_at(f, t, &v) == 0 && v == c[t];
	}
	for (size_t t = 0; t < N; t++)
		same &= anvil_fastconv_at(f, t, &v) == 0 && v == c[t];
	ok(same, "a late read of a complete target, N = %zu: next()'s bits", N);
	ok(refused, "a target not yet complete is refused");
	anvil_fastconv_free(f);
	free(x);
	free(g);
	free(c);
}

/* c_0 .. c_{N-1} of a pair (FFT squares, packed levels too) into c. */
static void pair_run(const double *x, const double *g, size_t N, double *c)
{
	struct anvil_fastconv *f = anvil_fastconv_alloc_pair(g, g, N, 0, NULL);
	for (size_t n = 0; n < N; n++) {
		c[n] = anvil_fastconv_next(f);
		anvil_fastconv_push_pair(f, x[n], 0.5 * x[n]);
	}
	anvil_fastconv_free(f);
}

/* The thread's pool of blocks (fastconv.c): a freed block comes back to
 * the next request that fits, and a convolution on blocks left full of
 * NaN by another user gives the bits of one on fresh memory. */
static void test_pool(void)
{
	size_t N = 20000, nb = 0;
	double *x = malloc(N * sizeof *x), *g = malloc(N * sizeof *g);
	double *c1 = malloc(N * sizeof *c1), *c2 = malloc(N * sizeof *c2);
	unsigned long long s = 7;
	for (size_t i = 0; i < N; i++) {
		x[i] = urand(&s);
		g[i] = urand(&s) / (1.0 + 0.01 * (double)i);
	}
	void *b = anvil_fastconv_block(300000);
	anvil_fastconv_block_free(b, 300000);
	void *b2 = anvil_fastconv_block(270000);
	ok(b2 == b, "a freed block serves the next request that fits");
	anvil_fastconv_block_free(b2, 270000);
	pair_run(x, g, N, c1);
	/* every block of the pool taken, poisoned and given back */
	double *blk[64];
	size_t sz[64];
	for (size_t bytes = (size_t)1 << 16; bytes <= ((size_t)1 << 20); bytes *= 2)
		for (int k = 0; k < 6 && nb < 64; k++) {
			sz[nb] = bytes;
			blk[nb] = anvil_fastconv_block(bytes);
			for (size_t i = 0; i < bytes / sizeof(double); i++)
				blk[nb][i] = NAN;
			nb++;
		}
	for (size_t i = 0; i < nb; i++)
		anvil_fastconv_block_free(blk[i], sz[i]);
	pair_run(x, g, N, c2);
	size_t same = 0;
	for (size_t n = 0; n < N; n++)
		same += memcmp(&c1[n], &c2[n], sizeof c1[n]) == 0;
	ok(same == N, "a convolution on poisoned pool blocks: the same bits (%zu of %zu)", same, N);
	free(x), free(g), free(c1), free(c2);
}

int main(void)
{
	/* the bound: eps log2(N) times a small constant (rounding of the FFT) */
	test_random(1000, (size_t)-1, 1e-15, "direct squares");
	test_random(1000, 0, 5e-15, "FFT squares");
	test_random(4097, 8, 5e-15, "FFT squares from side 16");
	test_random(3, 0, 1e-16, "tiny");
	test_impact_like();
	test_pair(3000, 0, 5e-15);
	test_pair(1000, (size_t)-1, 1e-15);
	test_lazy(3000, 0);
	test_lazy(1000, (size_t)-1);
	test_at(5000);
	test_pool();
	ok(anvil_fastconv_alloc(NULL, 0, 0) == NULL, "capacity 0 is refused");
	anvil_fastconv_free(NULL);
	plan(tap_n);
	return done_testing();
}
