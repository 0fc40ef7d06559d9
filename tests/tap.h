/* tap.h: a tiny TAP producer for the automake TAP driver.
 * plan(n); ok(cond, fmt, ...); is_rel(got, want, tol, fmt, ...);
 * is_abs(...); diag(fmt, ...); done_testing() returns the exit status. */
#ifndef ANVIL_TAP_H
#define ANVIL_TAP_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

static int tap_n, tap_failed;

static inline void plan(int n) { printf("1..%d\n", n); fflush(stdout); }

static inline void tap_vreport(int pass, const char *fmt, va_list ap)
{
	++tap_n;
	if (!pass)
		++tap_failed;
	printf("%s %d - ", pass ? "ok" : "not ok", tap_n);
	vprintf(fmt, ap);
	printf("\n");
	fflush(stdout);
}

static inline void diag(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static inline void diag(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	printf("# ");
	vprintf(fmt, ap);
	printf("\n");
	va_end(ap);
	fflush(stdout);
}

static inline int ok(int pass, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static inline int ok(int pass, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	tap_vreport(pass, fmt, ap);
	va_end(ap);
	return pass;
}

/* As gsl_test_rel: NaN matches only NaN, infinities match their own sign,
 * want == 0 compares absolutely. */
static inline int tap_close(double got, double want, double tol, int relative)
{
	if (isnan(want) || isnan(got))
		return isnan(want) && isnan(got);
	if (isinf(want) || isinf(got))
		return got == want;
	double d = fabs(got - want);
	if (relative && want != 0.0)
		d /= fabs(want);
	return d <= tol;
}

static inline int is_rel(double got, double want, double tol, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
static inline int is_rel(double got, double want, double tol, const char *fmt, ...)
{
	va_list ap;
	int pass = tap_close(got, want, tol, 1);
	va_start(ap, fmt);
	tap_vreport(pass, fmt, ap);
	va_end(ap);
	if (!pass)
		diag("  got %.10g, want %.10g, relative error %.3g > %.3g", got, want,
		     want != 0 ? fabs(got - want) / fabs(want) : fabs(got), tol);
	return pass;
}

static inline int is_abs(double got, double want, double tol, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
static inline int is_abs(double got, double want, double tol, const char *fmt, ...)
{
	va_list ap;
	int pass = tap_close(got, want, tol, 0);
	va_start(ap, fmt);
	tap_vreport(pass, fmt, ap);
	va_end(ap);
	if (!pass)
		diag("  got %.10g, want %.10g, difference %.3g > %.3g", got, want,
		     fabs(got - want), tol);
	return pass;
}

static inline int done_testing(void) { return tap_failed ? 1 : 0; }

#endif
