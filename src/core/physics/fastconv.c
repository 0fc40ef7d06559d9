#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_fft_halfcomplex.h>
#include <gsl/gsl_fft_real.h>

#include "fastconv.h"

struct anvil_fastconv {
	size_t cap, n, direct_max;
	double *g;    /* kernel, cap */
	double *x;    /* pushed values, cap */
	double *acc;  /* partial sums c_n, cap */
	double *buf;  /* scratch, 2 B_max */
	double **spec; /* spec[k]: halfcomplex FFT of g_0..g_{2B-1}, B = 2^k; NULL if direct */
	int nlev;
};

void anvil_fastconv_free(struct anvil_fastconv *f)
{
	if (!f)
		return;
	for (int k = 0; k < f->nlev; k++)
		free(f->spec[k]);
	free(f->spec);
	free(f->g);
	free(f->x);
	free(f->acc);
	free(f->buf);
	free(f);
}

/* The kernel's spectrum for squares of side B: g_0 .. g_{2B-1}, zero past cap. */
static double *level_spectrum(const struct anvil_fastconv *f, size_t B)
{
	double *s = calloc(2 * B, sizeof *s);
	if (!s)
		return NULL;
	memcpy(s, f->g, (2 * B < f->cap ? 2 * B : f->cap) * sizeof *s);
	gsl_fft_real_radix2_transform(s, 1, 2 * B);
	return s;
}

struct anvil_fastconv *anvil_fastconv_alloc(const double *g, size_t cap, size_t direct_max)
{
	if (!cap)
		return NULL;
	struct anvil_fastconv *f = calloc(1, sizeof *f);
	if (!f)
		return NULL;
	f->cap = cap;
	f->direct_max = direct_max ? direct_max : ANVIL_FASTCONV_DIRECT;
	while (((size_t)1 << f->nlev) < cap)
		f->nlev++; /* squares have B < cap */
	f->g = malloc(cap * sizeof *f->g);
	f->x = calloc(cap, sizeof *f->x);
	f->acc = calloc(cap, sizeof *f->acc);
	f->buf = malloc(2 * ((size_t)1 << f->nlev) * sizeof *f->buf);
	f->spec = calloc((size_t)f->nlev + 1, sizeof *f->spec);
	if (!f->g || !f->x || !f->acc || !f->buf || !f->spec) {
		anvil_fastconv_free(f);
		return NULL;
	}
	memcpy(f->g, g, cap * sizeof *g);
	for (int k = 0; k < f->nlev; k++) {
		size_t B = (size_t)1 << k;
		if (B <= f->direct_max)
			continue;
		if (!(f->spec[k] = level_spectrum(f, B))) {
			anvil_fastconv_free(f);
			return NULL;
		}
	}
	return f;
}

void anvil_fastconv_reset(struct anvil_fastconv *f)
{
	memset(f->x, 0, f->cap * sizeof *f->x);
	memset(f->acc, 0, f->cap * sizeof *f->acc);
	f->n = 0;
}

double anvil_fastconv_next(const struct anvil_fastconv *f)
{
	return f->n < f->cap ? f->acc[f->n] : 0.0;
}

size_t anvil_fastconv_count(const struct anvil_fastconv *f) { return f->n; }

/* Sources [L-B, L) into targets [L, min(L+B, cap)), directly. */
static void square_direct(struct anvil_fastconv *f, size_t L, size_t B)
{
	size_t end = L + B < f->cap ? L + B : f->cap;
	for (size_t t = L; t < end; t++) {
		double s = 0;
		for (size_t m = L - B; m < L; m++)
			s += f->x[m] * f->g[t - m];
		f->acc[t] += s;
	}
}

/* The same square by a cyclic convolution of size 2B: for targets
 * L + i (i < B) the lags B + i - s lie in [1, 2B), so nothing wraps. */
static void square_fft(struct anvil_fastconv *f, size_t L, size_t B, const double *G)
{
	size_t N = 2 * B, end = L + B < f->cap ? L + B : f->cap;
	double *b = f->buf;
	memcpy(b, f->x + (L - B), B * sizeof *b);
	memset(b + B, 0, B * sizeof *b);
	gsl_fft_real_radix2_transform(b, 1, N);
	/* halfcomplex product: b[0], b[N/2] real; (b[j], b[N-j]) = (re, im) */
	b[0] *= G[0];
	b[B] *= G[B];
	for (size_t j = 1; j < B; j++) {
		double re = b[j] * G[j] - b[N - j] * G[N - j];
		double im = b[j] * G[N - j] + b[N - j] * G[j];
		b[j] = re;
		b[N - j] = im;
	}
	gsl_fft_halfcomplex_radix2_inverse(b, 1, N);
	for (size_t t = L; t < end; t++)
		f->acc[t] += b[B + (t - L)];
}

int anvil_fastconv_push(struct anvil_fastconv *f, double x)
{
	if (f->n >= f->cap)
		return -1;
	f->x[f->n++] = x;
	size_t L = f->n;
	if (L >= f->cap)
		return 0; /* no target left */
	int k = 0; /* the trailing zeros of L */
	while (!((L >> k) & 1))
		k++;
	size_t B = (size_t)1 << k;
	if (k < f->nlev && f->spec[k])
		square_fft(f, L, B, f->spec[k]);
	else
		square_direct(f, L, B);
	return 0;
}
