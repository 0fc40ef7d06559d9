/* gk21.c: the 21-point Gauss-Kronrod rule.  See gk21.h. */
#include <float.h>
#include <stddef.h>
#include <math.h>

#include "gk21.h"

typedef double complex cplx;

/* The 21-point Gauss-Kronrod rule and its embedded 10-point Gauss rule
 * (QUADPACK qk21; Piessens et al., QUADPACK, Springer 1983, the values GSL's
 * qk21 carries): abscissae on [-1, 1], largest first; xgk[1], xgk[3], ...
 * are the Gauss nodes, xgk[10] = 0 the centre. */
static const double xgk[11] = {
	0.995657163025808080735527280689003, 0.973906528517171720077964012084452,
	0.930157491355708226001207180059508, 0.865063366688984510732096688423493,
	0.780817726586416897063717578345042, 0.679409568299024406234327365114874,
	0.562757134668604683339000099272694, 0.433395394129247190799265943165784,
	0.294392862701460198131126603103866, 0.148874338981631210884826001129720,
	0.000000000000000000000000000000000};
static const double wgk[11] = {
	0.011694638867371874278064396062192, 0.032558162307964727478818972459390,
	0.054755896574351996031381300244580, 0.075039674810919952767043140916190,
	0.093125454583697605535065465083366, 0.109387158802297641899210590325805,
	0.123491976262065851077958109831074, 0.134709217311473325928054001771707,
	0.142775938577060080797094273138717, 0.147739104901338491374841515972068,
	0.149445554002916905664936468389821};
static const double wg[5] = {
	0.066671344308688137593568809893332, 0.149451349150580593145776339657697,
	0.219086362515982043995534934228163, 0.269266719309996355091226921569469,
	0.295524224714752870173892994651338};

void anvil_gk21_node(double a, double b, int j, double *x, double *wk, double *wgauss)
{
	double c = 0.5 * (a + b), h = 0.5 * (b - a);
	int i = j <= 10 ? j : 20 - j;
	*x = j <= 10 ? c - h * xgk[i] : c + h * xgk[i];
	*wk = h * wgk[i];
	*wgauss = i % 2 == 1 ? h * wg[i / 2] : 0.0;
}

void anvil_gk21_called_nodes(double a, double b, double *x)
{
	double c = 0.5 * (a + b), h = 0.5 * (b - a);
	x[0] = c - h * xgk[10];
	for (int n = 1; n < ANVIL_GK21_NODES; n++) {
		int pair = (n - 1) / 2, i = pair < 5 ? 2 * pair + 1 : 2 * (pair - 5);
		x[n] = (n - 1) % 2 == 0 ? c - h * xgk[i] : c + h * xgk[i];
	}
}

/* QUADPACK's error estimate of one real part (qk21's dqk21, as GSL's qk):
 * the Gauss-Kronrod difference diff, taken as resasc min(1, (200 |diff| /
 * resasc)^1.5), and never below 50 eps resabs (rounding).  x^1.5 as x
 * sqrt(x) for x < 1 (pow was 1.5 % of a thin plate's run; the two agree
 * to an ulp or two, in an estimate). */
static double rescale(double diff, double resabs, double resasc)
{
	double e = fabs(diff);
	if (resasc != 0 && e != 0) {
		double x = 200.0 * e / resasc;
		e = resasc * (x < 1.0 ? x * sqrt(x) : 1.0);
	}
	if (resabs > DBL_MIN / (50.0 * DBL_EPSILON))
		e = fmax(e, 50.0 * DBL_EPSILON * resabs);
	return e;
}

/* sqrt(x^2 + y^2) for x, y >= 0: directly where no square can overflow
 * or lose the sum to underflow, else hypot (glibc's hypot, careful
 * everywhere, was 1.5 % of a thin plate's run) */
static double norm(double x, double y)
{
	double m = fmax(x, y);
	return m > 1e-150 && m < 1e150 ? sqrt(x * x + y * y) : hypot(x, y);
}

static double dev(cplx f, cplx mean, int im)
{
	return im ? fabs(cimag(f) - cimag(mean)) : fabs(creal(f) - creal(mean));
}

void anvil_gk21_complex_floor(anvil_gk21_fn f, void *ctx, double a, double b, cplx *val,
			      double *err, double *floor)
{
	double c = 0.5 * (a + b), h = 0.5 * (b - a);
	cplx fc = f(c, ctx), f1[10], f2[10];
	cplx rk = fc * wgk[10], rg = 0;
	double abs_re = fabs(creal(rk)), abs_im = fabs(cimag(rk));
	/* the Gauss nodes first, then the Kronrod-only ones: QUADPACK's order of
	 * summation, so the sums round as qk21's do */
	for (int pass = 1; pass >= 0; pass--)
		for (int i = pass; i < 10; i += 2) {
			cplx u = f(c - h * xgk[i], ctx), v = f(c + h * xgk[i], ctx);
			f1[i] = u;
			f2[i] = v;
			if (pass)
				rg += wg[i / 2] * (u + v);
			rk += wgk[i] * (u + v);
			abs_re += wgk[i] * (fabs(creal(u)) + fabs(creal(v)));
			abs_im += wgk[i] * (fabs(cimag(u)) + fabs(cimag(v)));
		}
	cplx mean = 0.5 * rk;
	double asc[2];
	for (int im = 0; im < 2; im++) {
		asc[im] = wgk[10] * dev(fc, mean, im);
		for (int i = 0; i < 10; i++)
			asc[im] += wgk[i] * (dev(f1[i], mean, im) + dev(f2[i], mean, im));
	}
	cplx diff = (rk - rg) * h;
	double ah = fabs(h);
	*val = rk * h;
	*err = norm(rescale(creal(diff), abs_re * ah, asc[0] * ah),
		     rescale(cimag(diff), abs_im * ah, asc[1] * ah));
	if (floor)
		*floor = 50.0 * DBL_EPSILON * norm(abs_re * ah, abs_im * ah);
}

void anvil_gk21_complex(anvil_gk21_fn f, void *ctx, double a, double b, cplx *val, double *err)
{
	anvil_gk21_complex_floor(f, ctx, a, b, val, err, NULL);
}
