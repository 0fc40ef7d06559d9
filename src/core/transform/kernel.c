#include <math.h>

#include "kernel.h"

typedef double complex cplx;

double anvil_kernel_zhat(double k)
{
	if (k < 0.1) {
		double a = k * k;
		return (1.0 - a / 10.0 + a * a / 280.0 - a * a * a / 15120.0 +
			a * a * a * a / 1330560.0) / (2.0 * M_PI);
	}
	return 3.0 * (sin(k) - k * cos(k)) / (2.0 * M_PI * k * k * k);
}

cplx anvil_kernel_cmplx(double re, double im)
{
	/* a complex has the representation of double[2] (C11 6.2.5p13) */
	cplx z;
	double *p = (double *)&z;
	p[0] = re;
	p[1] = im;
	return z;
}

cplx anvil_kernel_expm1(cplx z)
{
	double x = creal(z), y = cimag(z), s = sin(0.5 * y);
	return (expm1(x) * cos(y) - 2.0 * s * s) + I * (exp(x) * sin(y));
}

cplx anvil_kernel_rayleigh(double a, cplx b, double kap2, cplx gam, cplx X)
{
	cplx Q = 16.0 * (1.0 - kap2) * a * a * a + (24.0 - 16.0 * kap2) * a * a * b +
		 8.0 * a * b * b + b * b * b;
	cplx g2X = gam * gam + X, g2mX = gam * gam - X;
	return cabs(g2mX) >= cabs(g2X) ? g2mX : b * Q / g2X;
}

cplx anvil_kernel_tdiff(cplx al1, cplx al2, cplx b, double kap2, double hh, cplx E1, cplx E2,
			cplx p1, cplx p2)
{
	/* alpha2 - alpha1 = (1 - kappa^2) s^2 / (alpha1 + alpha2): no cancellation */
	cplx dal = (1.0 - kap2) * b / (al1 + al2);
	if (cabs(hh * dal) < 1.0)
		return 2.0 * E1 * (-anvil_kernel_expm1(-hh * dal)) / (p1 * p2);
	return 2.0 * (E1 - E2) / (p1 * p2);
}

double anvil_kband(double omega, double wabs, double nu, double hh, double cr)
{
	double kflex = isfinite(hh) ? pow(6.0 * (1.0 - nu) * wabs * wabs / (hh * hh), 0.25) : 0.0;
	return 1.6 * fmax(omega / cr, kflex) + 3.0;
}
