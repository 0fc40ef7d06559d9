/* durbin.c: the Fourier-series inversion on the Bromwich line.  See durbin.h. */
#include <complex.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_complex.h>

#include "durbin.h"
#include "status.h"

typedef double complex cplx;

int anvil_durbin_init(struct anvil_durbin *d, double Tp, double c0, double omega_max,
		      size_t m_min)
{
	if (!(Tp > 0 && isfinite(Tp)) || !(c0 > 0 && isfinite(c0)) ||
	    !(omega_max >= 0 && isfinite(omega_max)))
		return ANVIL_EINVAL;
	double m = ceil(omega_max * Tp / M_PI);
	/* compared as doubles, before any cast: m can be far beyond size_t */
	if (!(m <= (double)ANVIL_DURBIN_M_MAX) || m_min > ANVIL_DURBIN_M_MAX)
		return ANVIL_EINVAL;
	*d = (struct anvil_durbin){ .Tp = Tp, .c0 = c0, .M = (size_t)m };
	if (d->M < m_min)
		d->M = m_min;
	return ANVIL_OK;
}

cplx anvil_durbin_s(const struct anvil_durbin *d, size_t n)
{
	return d->c0 + I * ((double)n * M_PI / d->Tp);
}

double anvil_durbin_omega(const struct anvil_durbin *d)
{
	return (double)d->M * M_PI / d->Tp;
}

/* Vandeven's exponential filter exp(-36 eta^8), eta = n/nmax (Gottlieb and
 * Hesthaven, J. Comput. Appl. Math. 128, 2001): 36 makes the last term's
 * weight e^-36, the rounding level; order 8 leaves the first quarter of
 * the band within 6e-4 of 1 (36/4^8 = 5.5e-4; it is 0.87 at half the band,
 * 0.24 at three quarters).  field.c says why it filters. */
#define FILTER_A 36.0

double anvil_durbin_filter(size_t n, size_t nmax)
{
	double e = (double)n / (double)nmax, e2 = e * e, e4 = e2 * e2;
	return exp(-FILTER_A * e4 * e4);
}

/* e^{i n pi t/T'} by recurrence, resynchronised every 32 terms (the
 * recurrence's rounding grows like n eps). */
void anvil_durbin_weights(const struct anvil_durbin *d, double t, size_t nmax, const cplx *F,
			  cplx *a, size_t stride)
{
	double amp = exp(d->c0 * t) / d->Tp;
	cplx step = cexp(I * M_PI * t / d->Tp), ph = 1.0;
	for (size_t n = 0; n <= nmax; n++) {
		cplx v = (n == 0 ? 0.5 : 1.0) * amp * anvil_durbin_filter(n, nmax) * ph;
		a[n * stride] = v * F[n];
		ph *= step;
		if (n % 32 == 31)
			ph = cexp(I * M_PI * t * (double)(n + 1) / d->Tp);
	}
}

int anvil_durbin_fft(const struct anvil_durbin *d, const cplx *F, size_t N, double *out,
		     size_t nout)
{
	if (N <= d->M || (N & (N - 1)) != 0 || nout > N)
		return ANVIL_EINVAL;
	double *z = calloc(2 * N, sizeof *z);
	if (!z)
		return ANVIL_ENOMEM;
	for (size_t n = 0; n <= d->M; n++) {
		double g = n == 0 ? 0.5 : 1.0;
		z[2 * n] = g * creal(F[n]);
		z[2 * n + 1] = g * cimag(F[n]);
	}
	/* sum_n z_n e^{+2 pi i n j/N}, and t_j = j 2T'/N makes the phase n pi t_j/T' */
	int st = gsl_fft_complex_radix2_backward(z, 1, N);
	for (size_t j = 0; !st && j < nout; j++) {
		double t = (double)j * 2.0 * d->Tp / (double)N;
		out[j] = exp(d->c0 * t) / d->Tp * z[2 * j];
	}
	free(z);
	return st ? ANVIL_ENUM : ANVIL_OK;
}

size_t anvil_durbin_fft_size(const struct anvil_durbin *d, size_t n_min)
{
	size_t want = 4 * (d->M + 1), p = 1;
	if (want < n_min)
		want = n_min;
	while (p < want && p <= SIZE_MAX / 2) /* 23 doublings at most: M <= 2^20 */
		p <<= 1;
	return p;
}
