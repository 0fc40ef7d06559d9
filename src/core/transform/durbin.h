/* durbin.h: the inverse Laplace transform by Durbin's Fourier series on the
 * Bromwich line, for the centre response (green.c) and the field (field.c).
 * Internal to the core.
 *
 * With the line s_n = c0 + i n pi/T' (n = 0..M) and F_n = F(s_n),
 *   f(t) = (e^{c0 t}/T') Re sum_{n<=M} g_n sigma_n F_n e^{i n pi t/T'},
 * g_0 = 1/2, g_n = 1, sigma_n a spectral filter (1: none), for
 * 0 <= t < 2T' (Durbin, Comput. J. 17, 1974).  Aliasing brings in
 * e^{-2 c0 T'} of the function's size; the e^{c0 t} factor multiplies the
 * spectral errors: callers choose c0 and T' for both (their headers say
 * how). */
#ifndef ANVIL_DURBIN_H
#define ANVIL_DURBIN_H

#include <complex.h>
#include <stddef.h>

struct anvil_durbin {
	double Tp; /* the half period T' */
	double c0; /* the line's abscissa */
	size_t M;  /* terms n = 0..M */
};

/* The most terms one inversion may sum: 2^20, some 500 times what the
 * reference level asks of the longest window (a few thousand), so that no
 * input makes the k-integrals (one per term) run without end. */
#define ANVIL_DURBIN_M_MAX ((size_t)1 << 20)

/* The line for half period Tp, abscissa c0 and frequencies up to
 * omega_max: M = max(m_min, ceil(omega_max Tp / pi)).  ANVIL_EINVAL when
 * Tp, c0 or omega_max is not finite and positive (omega_max >= 0), or M
 * would exceed ANVIL_DURBIN_M_MAX. */
int anvil_durbin_init(struct anvil_durbin *d, double Tp, double c0, double omega_max,
		      size_t m_min);

/* s_n = c0 + i n pi/T'. */
double complex anvil_durbin_s(const struct anvil_durbin *d, size_t n);

/* The highest frequency summed, M pi/T'. */
double anvil_durbin_omega(const struct anvil_durbin *d);

/* Vandeven's exponential filter sigma(n/nmax) = exp(-36 (n/nmax)^8). */
double anvil_durbin_filter(size_t n, size_t nmax);

/* The filtered weights of instant t for terms n <= nmax (nmax <= M):
 * a[n stride] = (e^{c0 t}/T') g_n sigma(n/nmax) F[n] e^{i n pi t/T'},
 * so that f(t) = Re sum a_n G_n for a transform F G. */
void anvil_durbin_weights(const struct anvil_durbin *d, double t, size_t nmax,
			  const double complex *F, double complex *a, size_t stride);

/* The unfiltered series at t_j = j 2T'/N, j < nout <= N, by one complex
 * FFT (GSL) of length N (a power of two > M, see anvil_durbin_fft_size).
 * ANVIL_ENOMEM, ANVIL_ENUM (FFT failed), ANVIL_EINVAL (bad N or nout). */
int anvil_durbin_fft(const struct anvil_durbin *d, const double complex *F, size_t N,
		     double *out, size_t nout);

/* The smallest power of two >= max(4 (M + 1), n_min). */
size_t anvil_durbin_fft_size(const struct anvil_durbin *d, size_t n_min);

#endif
