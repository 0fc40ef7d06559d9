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

/* zhat's series where |k| < 0.1 (1 otherwise: not used) */
static int zhat_series(cplx k, cplx *z)
{
	cplx a = k * k;
	if (!(creal(k) * creal(k) + cimag(k) * cimag(k) < 0.01))
		return 0;
	*z = (1.0 - a / 10.0 + a * a / 280.0 - a * a * a / 15120.0 + a * a * a * a / 1330560.0) /
	     (2.0 * M_PI);
	return 1;
}

cplx anvil_kernel_zhat_c(cplx k)
{
	cplx z;
	if (zhat_series(k, &z))
		return z;
	return anvil_kernel_zhat_c_sc(k, sin(creal(k)), cos(creal(k)));
}

cplx anvil_kernel_zhat_c_sc(cplx k, double sx, double cx)
{
	cplx a = k * k, z;
	if (zhat_series(k, &z))
		return z;
	/* sin k and cos k from sin and cos of Re k and one exp (csin and ccos
	 * would take two of each) */
	double y = cimag(k), ey = exp(y), ie = 1.0 / ey;
	double ch = 0.5 * (ey + ie), sh = fabs(y) < 0.5 ? sinh(y) : 0.5 * (ey - ie);
	cplx sk = anvil_kernel_cmplx(sx * ch, cx * sh), ck = anvil_kernel_cmplx(cx * ch, -sx * sh);
	return 3.0 * (sk - k * ck) * anvil_kernel_recip(2.0 * M_PI * a * k);
}

cplx anvil_kernel_expm1(cplx z)
{
	double x = creal(z), y = cimag(z), s = sin(0.5 * y);
	return (expm1(x) * cos(y) - 2.0 * s * s) + I * (exp(x) * sin(y));
}

static double norm2(cplx z)
{
	double x = creal(z), y = cimag(z);
	return x * x + y * y;
}

cplx anvil_kernel_csqrt(cplx z)
{
	double x = creal(z), y = cimag(z);
	double t = sqrt(0.5 * (fabs(x) + sqrt(x * x + y * y)));
	if (t == 0)
		return anvil_kernel_cmplx(0.0, y);
	if (x >= 0)
		return anvil_kernel_cmplx(t, 0.5 * y / t);
	return anvil_kernel_cmplx(0.5 * fabs(y) / t, copysign(t, y));
}

cplx anvil_kernel_recip(cplx z)
{
	double x = creal(z), y = cimag(z), n = x * x + y * y;
	if (n > 1e-290 && n < 1e290) { /* no overflow or underflow: one division */
		double r = 1.0 / n;
		return anvil_kernel_cmplx(x * r, -y * r);
	}
	double sc = 1.0 / (fabs(x) + fabs(y)), xs = x * sc, ys = y * sc, r = sc / (xs * xs + ys * ys);
	return anvil_kernel_cmplx(xs * r, -ys * r);
}

void anvil_kernel_exp_1m(cplx z, cplx *E, cplx *m)
{
	double x = creal(z), y = cimag(z), ex = exp(x), cs = cos(y), sn = sin(y);
	double em1 = fabs(x) < 0.5 ? expm1(x) : ex - 1.0;
	double omc = cs > 0 ? sn * sn / (1.0 + cs) : 1.0 - cs; /* 1 - cos y */
	*E = anvil_kernel_cmplx(ex * cs, ex * sn);
	*m = anvil_kernel_cmplx(omc - em1 * cs, -ex * sn);
}

cplx anvil_kernel_rayleigh(double a, cplx b, double kap2, cplx gam, cplx X)
{
	cplx g2 = gam * gam, g2X = g2 + X, g2mX = g2 - X;
	if (norm2(g2mX) >= norm2(g2X))
		return g2mX;
	cplx Q = 16.0 * (1.0 - kap2) * a * a * a + (24.0 - 16.0 * kap2) * a * a * b +
		 8.0 * a * b * b + b * b * b;
	return b * Q * anvil_kernel_recip(g2X);
}

cplx anvil_kernel_rayleigh_c(cplx a, cplx b, double kap2, cplx gam, cplx X)
{
	cplx g2 = gam * gam, g2X = g2 + X, g2mX = g2 - X;
	if (norm2(g2mX) >= norm2(g2X))
		return g2mX;
	cplx Q = 16.0 * (1.0 - kap2) * a * a * a + (24.0 - 16.0 * kap2) * a * a * b +
		 8.0 * a * b * b + b * b * b;
	return b * Q * anvil_kernel_recip(g2X);
}

void anvil_kernel_exp2(cplx al1, cplx al2, cplx b, double kap2, double hh, cplx E1, cplx m1,
		       cplx *E2, cplx *m2, cplx *diff)
{
	/* alpha2 - alpha1 = (1 - kappa^2) s^2 / (alpha1 + alpha2): no cancellation */
	cplx dal = (1.0 - kap2) * b * anvil_kernel_recip(al1 + al2), E, m;
	if (norm2(hh * dal) < 1.0) {
		anvil_kernel_exp_1m(-hh * dal, &E, &m);
		*diff = E1 * m;
		*E2 = E1 * E;
		/* 1 - E1 E = (1 - E1) + E1 (1 - E), both parts O(hh alpha) where
		 * E2 is near 1: no cancellation unless |alpha2| << |alpha1| */
		*m2 = m1 + *diff;
		return;
	}
	anvil_kernel_exp_1m(-hh * al2, E2, m2);
	*diff = E1 - *E2;
}

/* 1.6 max(omega/c_R, k_flex): where the Lamb-mode poles end (kernel.h) */
static double kpoles(double omega, double wabs, double nu, double hh, double cr)
{
	double kflex = isfinite(hh) ? pow(6.0 * (1.0 - nu) * wabs * wabs / (hh * hh), 0.25) : 0.0;
	return 1.6 * fmax(omega / cr, kflex);
}

double anvil_kband(double omega, double wabs, double nu, double hh, double cr)
{
	return kpoles(omega, wabs, nu, hh, cr) + 3.0;
}

double anvil_kband_poles(double omega, double wabs, double nu, double hh, double cr)
{
	double kp = kpoles(omega, wabs, nu, hh, cr);
	return fmin(kp + 3.0, kp + ANVIL_KPOLE_MARGIN / hh);
}

double anvil_kband_piece(double hh, double kband)
{
	return fmin(2.0 / hh, fmin(4.0, fmax(1.0, kband / 32.0)));
}

double anvil_lift_cutoff(double nu)
{
	double c1 = sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu)); /* c1/c2 */
	return fmax(ANVIL_LIFT_CUTOFF, ANVIL_LIFT_S1 * fmin(c1, 2.0));
}

double anvil_kband_lift(double omega, double hh, double nu, double kband, double wide,
			double *kstart)
{
	*kstart = 0.0;
	if (!isfinite(hh))
		return 0.0;
	if (omega * hh < anvil_lift_cutoff(nu) * M_PI)
		return fmin(fmin(ANVIL_LIFT_MAX / wide, 0.5 / hh), 0.5 * kband / M_PI);
	double ks = ANVIL_LIFT_KS / hh;
	double H = fmin(fmin(ANVIL_LIFT_MAX / wide, 0.5 / hh), 0.5 * (kband - ks) / M_PI);
	if (!(omega * hh < ANVIL_LIFT_TOP * M_PI && kband - ks > 4.0 / hh &&
	      2.0 * H > anvil_kband_piece(hh, kband)))
		return 0.0;
	*kstart = ks;
	return H;
}

double anvil_kband_lift_piece(double hh, double kband, double lift)
{
	return fmin(kband, fmax(anvil_kband_piece(hh, kband), 2.0 * lift));
}
