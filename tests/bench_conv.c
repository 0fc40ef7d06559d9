/* bench_conv: seconds of the online convolution (fastconv.c) at N steps,
 * direct and fast, and the cross-over side of the direct squares.  A
 * benchmark run by scripts/bench, not a test: prints timings.
 *   bench_conv            N = 1e3 .. 1e6, direct (up to 1e5) and fast
 *   bench_conv cross N    the fast convolution at N for direct sides 8..1024 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <math.h>

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

int main(int argc, char **argv)
{
	double sink = 0;
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
