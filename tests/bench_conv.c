/* bench_conv: seconds of the online convolution (fastconv.c) at N steps,
 * direct and fast, and the cross-over side of the direct squares.  A
 * benchmark run by scripts/bench, not a test: prints timings.
 *   bench_conv            N = 1e3 .. 1e6, direct (up to 1e5) and fast
 *   bench_conv cross N    the fast convolution at N for direct sides 8..1024
 *   bench_conv fft        microseconds per forward transform of 2B real
 *                         values, B = 2^11 .. 2^19, by GSL's four ways */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <math.h>

#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_fft_real.h>

#include "fastconv.h"

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* Seconds for N next/push pairs with squares up to direct_max summed directly. */
static double run(size_t N, size_t direct_max, double *sink)
{
	double *g = malloc(N * sizeof *g), s = 0;
	for (size_t i = 0; i < N; i++)
		g[i] = 1.0 / (1.0 + (double)i);
	double t0 = cpu();
	struct anvil_fastconv *f = anvil_fastconv_alloc(g, N, direct_max);
	for (size_t n = 0; n < N; n++) {
		double c = anvil_fastconv_next(f);
		s += c;
		anvil_fastconv_push(f, 1.0 / (1.0 + fabs(c)));
	}
	double t = cpu() - t0;
	anvil_fastconv_free(f);
	free(g);
	*sink += s;
	return t;
}

/* Microseconds per forward transform of 2B real values (a square's size),
 * best of 3 timings of enough calls: GSL's mixed-radix complex FFT of the
 * packed B points (fastconv.c, 2B >= FASTCONV_PACK), its radix-2 complex
 * one, and its real mixed-radix and radix-2 ones of the 2B points. */
static void bench_fft(double *sink)
{
	printf("%-8s %10s %10s %10s %10s\n", "2B", "cplx_mr", "cplx_r2", "real_mr", "real_r2");
	for (size_t B = 2048; B <= ((size_t)1 << 19); B *= 2) {
		size_t N = 2 * B, reps = 1 + ((size_t)1 << 24) / N;
		double *a = malloc((N + 2) * sizeof *a);
		gsl_fft_complex_wavetable *cw = gsl_fft_complex_wavetable_alloc(B);
		gsl_fft_complex_workspace *cws = gsl_fft_complex_workspace_alloc(B);
		gsl_fft_real_wavetable *rw = gsl_fft_real_wavetable_alloc(N);
		gsl_fft_real_workspace *rws = gsl_fft_real_workspace_alloc(N);
		double best[4] = { INFINITY, INFINITY, INFINITY, INFINITY };
		for (int rep = 0; rep < 3; rep++)
			for (int way = 0; way < 4; way++) {
				double t0 = cpu();
				for (size_t r = 0; r < reps; r++) {
					for (size_t i = 0; i < N; i++)
						a[i] = 1.0 / (1.0 + (double)i);
					if (way == 0)
						gsl_fft_complex_forward(a, 1, B, cw, cws);
					else if (way == 1)
						gsl_fft_complex_radix2_forward(a, 1, B);
					else if (way == 2)
						gsl_fft_real_transform(a, 1, N, rw, rws);
					else
						gsl_fft_real_radix2_transform(a, 1, N);
					*sink += a[1];
				}
				double t = (cpu() - t0) / (double)reps * 1e6;
				best[way] = t < best[way] ? t : best[way];
			}
		printf("%-8zu %10.1f %10.1f %10.1f %10.1f\n", N, best[0], best[1], best[2], best[3]);
		gsl_fft_complex_wavetable_free(cw);
		gsl_fft_complex_workspace_free(cws);
		gsl_fft_real_wavetable_free(rw);
		gsl_fft_real_workspace_free(rws);
		free(a);
	}
}

int main(int argc, char **argv)
{
	double sink = 0;
	if (argc == 2 && strcmp(argv[1], "fft") == 0) {
		bench_fft(&sink);
		return sink == 42.0;
	}
	if (argc == 3 && strcmp(argv[1], "cross") == 0) {
		size_t N = (size_t)atof(argv[2]);
		printf("%-10s %10s\n", "direct_max", "fast_s");
		for (size_t d = 8; d <= 1024; d *= 2)
			printf("%-10zu %10.4f\n", d, run(N, d, &sink));
	} else {
		printf("%-10s %10s %10s\n", "steps", "direct_s", "fast_s");
		for (size_t N = 1000; N <= 1000000; N *= 10) {
			double d = N <= 100000 ? run(N, (size_t)-1, &sink) : NAN;
			printf("%-10zu %10.4f %10.4f\n", N, d, run(N, 0, &sink));
		}
	}
	return sink == 42.0; /* keeps the work */
}
