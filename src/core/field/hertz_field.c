/* hertz_field.c: Huber's closed-form Hertz field (see hertz_field.h). */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include "hertz_field.h"

/* Searched depth range for the peak von Mises stress (units of a): the peak
 * lies at 0.45-0.8 a for nu in [0, 0.5) (Johnson 1985, fig. 4.5). */
#define VM_ZLO 0.0
#define VM_ZGUESS 0.5
#define VM_ZHI 3.0

double anvil_hertz_von_mises(const struct anvil_hertz_stress *s)
{
	double a = s->rr - s->tt, b = s->tt - s->zz, c = s->zz - s->rr;
	return sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * s->rz * s->rz);
}

/* On the surface, z = 0 (Johnson eqs. 3.41-3.42); in units of p0, x = r/a. */
static void surface(double nu, double x, struct anvil_hertz_stress *s)
{
	double k = (1.0 - 2.0 * nu) / 3.0;
	s->rz = 0;
	if (x >= 1.0) {
		s->rr = k / (x * x);
		s->tt = -s->rr;
		s->zz = 0;
		return;
	}
	double q = sqrt(1.0 - x * x);
	/* (1 - (1 - x^2)^(3/2)) / x^2, without the cancellation at small x */
	double g = x > 0 ? -expm1(1.5 * log1p(-x * x)) / (x * x) : 1.5;
	s->rr = k * g - q;
	s->tt = -k * g - 2.0 * nu * q;
	s->zz = -q;
}

/* On the axis, r = 0 (Johnson eq. 3.45); in units of p0, y = z/a > 0. */
static void axis(double nu, double y, struct anvil_hertz_stress *s)
{
	double A = y * atan(1.0 / y);
	s->rr = s->tt = -(1.0 + nu) * (1.0 - A) + 0.5 / (1.0 + y * y);
	s->zz = -1.0 / (1.0 + y * y);
	s->rz = 0;
}

/* Everywhere else, in units a = p0 = 1 (x = r/a, y = z/a). */
static void interior(double nu, double x, double y, struct anvil_hertz_stress *s)
{
	double e = x * x + y * y - 1.0, D = sqrt(e * e + 4.0 * y * y);
	/* u, the positive root, without cancellation for e < 0 (product of
	 * the roots is -y^2) */
	double u = e >= 0 ? 0.5 * (e + D) : 2.0 * y * y / (D - e);
	double ru = sqrt(u), t = x * x / (1.0 + u); /* y^2 / u = 1 - t */
	double s3 = pow(1.0 - t, 1.5), sv = sqrt(1.0 - t);
	double g = -expm1(1.5 * log1p(-t)) / (x * x); /* (1 - s^3) / x^2 */
	double k = (1.0 - 2.0 * nu) / 3.0, A = ru * atan(1.0 / ru);
	double m = u * u + y * y;
	s->rr = k * g + s3 * u / m + sv * (u * (1.0 - nu) / (1.0 + u) + (1.0 + nu) * A - 2.0);
	s->tt = -k * g - sv * (2.0 * nu + u * (1.0 - nu) / (1.0 + u) - (1.0 + nu) * A);
	s->zz = -s3 * u / m;
	s->rz = -x * y * y / m * ru / (1.0 + u);
}

int anvil_hertz_stress(double a, double p0, double nu, double r, double z,
		       struct anvil_hertz_stress *s)
{
	if (!s)
		return ANVIL_EINVAL;
	if (!(a > 0 && isfinite(a) && isfinite(p0) && nu > -1 && nu < 0.5 && r >= 0 &&
	      z >= 0 && isfinite(r) && isfinite(z))) {
		s->rr = s->tt = s->zz = s->rz = s->vm = NAN;
		return ANVIL_EINVAL;
	}
	double x = r / a, y = z / a;
	if (y == 0)
		surface(nu, x, s);
	else if (x == 0)
		axis(nu, y, s);
	else
		interior(nu, x, y, s);
	s->rr *= p0, s->tt *= p0, s->zz *= p0, s->rz *= p0;
	s->vm = anvil_hertz_von_mises(s);
	return ANVIL_OK;
}

double anvil_hertz_tension(double p0, double nu)
{
	return (1.0 - 2.0 * nu) * p0 / 3.0;
}

static double minus_vm(double y, void *vnu)
{
	struct anvil_hertz_stress s;
	anvil_hertz_stress(1.0, 1.0, *(double *)vnu, 0.0, y, &s);
	return -s.vm;
}

int anvil_hertz_vm_peak(double a, double p0, double nu, double *vm, double *z)
{
	if (!(a > 0 && isfinite(a) && p0 >= 0 && isfinite(p0) && nu >= 0 && nu < 0.5) || !vm || !z)
		return ANVIL_EINVAL;
	gsl_function f = { minus_vm, &nu };
	gsl_min_fminimizer *m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
	if (!m)
		return ANVIL_ENOMEM;
	int st = gsl_min_fminimizer_set(m, &f, VM_ZGUESS, VM_ZLO, VM_ZHI);
	for (int i = 0; !st && i < 200; i++) {
		st = gsl_min_fminimizer_iterate(m);
		double lo = gsl_min_fminimizer_x_lower(m), hi = gsl_min_fminimizer_x_upper(m);
		if (!st && gsl_min_test_interval(lo, hi, 0.0, 1e-12) == GSL_SUCCESS)
			break;
	}
	double y = gsl_min_fminimizer_x_minimum(m);
	gsl_min_fminimizer_free(m);
	if (st)
		return ANVIL_ENUM;
	*z = y * a;
	*vm = -minus_vm(y, &nu) * p0;
	return ANVIL_OK;
}

int anvil_hertz_judge(double a, double p0, double nu, double Y, double St,
		      struct anvil_hertz_verdict *v)
{
	if (!v || !(isnan(Y) || Y > 0) || !(isnan(St) || St > 0))
		return ANVIL_EINVAL;
	int st = anvil_hertz_vm_peak(a, p0, nu, &v->vm, &v->z_vm);
	if (st)
		return st;
	v->tension = anvil_hertz_tension(p0, nu);
	v->yield_ratio = v->vm / Y;       /* NaN when Y is NaN */
	v->tension_ratio = v->tension / St;
	double ry = isnan(Y) ? 0 : v->yield_ratio, rt = isnan(St) ? 0 : v->tension_ratio;
	v->fate = ANVIL_HERTZ_ELASTIC;
	if (ry > 1 || rt > 1)
		v->fate = ry >= rt ? ANVIL_HERTZ_YIELDS : ANVIL_HERTZ_CRACKS;
	return ANVIL_OK;
}
