/* kernel.h: pieces of the layer's transformed kernels shared by the centre
 * response (green.c) and the field at depth (field_kernel.c).  Internal to
 * the core.  Units mu = rho = c2 = r0 = 1; a = k^2, b = s^2,
 * alpha_j = sqrt(a + kappa_j^2 b), gamma = 2a + b, X = 4 a alpha1 alpha2. */
#ifndef ANVIL_KERNEL_H
#define ANVIL_KERNEL_H

#include <complex.h>

/* Hankel transform of the Hertz patch (eq 32) with r0 = 1; its Taylor
 * series for small k, where the closed form cancels catastrophically. */
double anvil_kernel_zhat(double k);

/* The same at a complex k (the layer correction's lifted contour,
 * green_spectrum.c): the series where |k| < 0.1, else sin and cos of k
 * from one sincos and one exp; |zhat| grows like exp(|Im k|) off the real
 * axis. */
double complex anvil_kernel_zhat_c(double complex k);
/* The same from sx, cx: sin and cos of Re k (or values within a few ulp
 * of them, e.g. by angle sums), for callers that have them cheaper. */
double complex anvil_kernel_zhat_c_sc(double complex k, double sx, double cx);

/* re + i im with the sign of a zero im kept (C11's CMPLX, which not every
 * C library offers, e.g. glibc 2.36 to clang 14): the static field's branch
 * cuts rely on -0.0 (field_kernel.c); x + I * y need not keep it.  Inline:
 * the lifted band's integrand makes two a node (green_spectrum.c). */
static inline double complex anvil_kernel_cmplx(double re, double im)
{
	/* a complex has the representation of double[2] (C11 6.2.5p13) */
	double complex z;
	double *p = (double *)&z;
	p[0] = re;
	p[1] = im;
	return z;
}

/* exp(z) - 1 without cancellation for small |z| (C11 has no cexpm1). */
double complex anvil_kernel_expm1(double complex z);

/* The principal square root, as csqrt for the kernels' arguments (finite,
 * |z| < 1e150): sqrt((|x| + |z|)/2) and y over twice it, without cancellation
 * and without hypot's care for overflow, which the kernels never need
 * (csqrt was a fifth of a kernel evaluation). */
double complex anvil_kernel_csqrt(double complex z);

/* 1/z for finite z != 0: conj(z)/|z|^2, scaled by 1/(|x| + |y|) where |z|^2
 * would overflow or underflow: one or two real divisions, where C's complex division (__divdc3, with
 * its inf/nan recovery the kernels never need) cost a sixth of an
 * evaluation.  Relative error a few ulp, as the division's. */
double complex anvil_kernel_recip(double complex z);

/* exp(z) and 1 - exp(z) together, Re z <= 0 (the kernels' e^{-hh alpha}):
 * one exp and one sincos for both, expm1 only where Re z is small (there
 * 1 - exp(Re z) would cancel); 1 - cos y as sin^2 y/(1 + cos y) where
 * cos y > 0, so no digit is lost for small y either. */
void anvil_kernel_exp_1m(double complex z, double complex *E, double complex *m);

/* The Rayleigh function R = gamma^2 - X.  Rationalised, R = b Q /
 * (gamma^2 + X) with the k^8 terms of Q cancelled by hand, where that is the
 * larger denominator (the plain form loses every digit at large k); the
 * plain form near the rationalised one's spurious root gamma^2 + X = 0,
 * which can sit on the integration path (a 0/0 there). */
double complex anvil_kernel_rayleigh(double a, double complex b, double kap2,
				     double complex gam, double complex X);

/* The same at a complex a = k^2 (a lifted k-contour, layer_bc.h). */
double complex anvil_kernel_rayleigh_c(double complex a, double complex b, double kap2,
				       double complex gam, double complex X);

/* E2 = exp(-hh alpha2), m2 = 1 - E2 and diff = E1 - E2 (d = t2 - t1 = 2 diff/(p1 p2),
 * p_j = 2 - m_j) from E1 = exp(-hh alpha1) and m1 = 1 - E1: where E1 and E2
 * are close (|hh (alpha2 - alpha1)| < 1, their difference would cancel)
 * through E = exp(-hh (alpha2 - alpha1)), E2 = E1 E, diff = E1 (1 - E),
 * m2 = m1 + diff, one exponential where there were two; directly
 * elsewhere (there exp(-hh alpha2)/E1 can overflow while E1 underflows). */
void anvil_kernel_exp2(double complex al1, double complex al2, double complex b, double kap2,
		       double hh, double complex E1, double complex m1, double complex *E2,
		       double complex *m2, double complex *diff);

/* The band of wavenumbers that holds the Lamb-mode poles at angular
 * frequency omega (units c2 = r0 = 1): 1.6 max(omega/c_R, k_flex) + 3, with
 * k_flex = (6 (1 - nu) wabs^2 / hh^2)^(1/4) the thin plate's flexural (A0)
 * wavenumber at |s| = wabs (0 for hh = inf).  The poles sit below the
 * slower of the Rayleigh and flexural waves; 1.6 and 3 leave room for the
 * pole band's width (green.c: results do not move when both grow).  One
 * rule for the centre response (green.c), the field (field.c) and the
 * planner's cost model (plan.c). */
double anvil_kband(double omega, double wabs, double nu, double hh, double cr);

/* The part of the band [0, kband] that the layer correction's starting
 * pieces cover (green_spectrum.c), at most kband: the poles' band
 * 1.6 max(omega/c_R, k_flex) and ANVIL_KPOLE_MARGIN/hh past it, where the
 * static correction, (k hh)^2 exp(-2 k hh), has passed its peak at 1/hh.
 * Beyond it the correction only decays (exp(-2 Re(alpha1) hh)): the rest
 * of the band is one starting piece, which the bisection splits where it
 * must.  It differs from kband only where hh > 1 (kband's + 3 is 3/hh or
 * less there): h = 100 r0, 10 kg at 0.01 m/s spent 150 of its 170 pieces
 * a k-integral on [0.3, 3], where exp(-2 k hh) < 1e-26; now 23 pieces,
 * 0.49 -> 0.13 s CPU.  The planner's cost model (plan_work.c) is to
 * price the same: kpole/piece pieces, and the one past it with its
 * halvings, about log2(1 + (kband - kpole) hh). */
#define ANVIL_KPOLE_MARGIN 3.0
double anvil_kband_poles(double omega, double wabs, double nu, double hh, double cr);

/* The layer correction's starting pieces (green_spectrum.c; the planner
 * prices the same, plan_work.c): in the band [0, kband], about the Lamb
 * modes' spacing pi/h, at most 1 wide, or kband/32 up to 4 wide in a wide
 * band (a thin plate's, which holds two poles); beyond it,
 * ANVIL_KTAIL_PIECE wide. */
#define ANVIL_KTAIL_PIECE 16.0
double anvil_kband_piece(double hh, double kband);

/* The layer correction's band [0, kband] is integrated on the contour
 * k(x) = x + i H sin(pi x/kband), x in [0, kband] (green_spectrum.c; above
 * the cutoff, below: x + i H sin(pi (x - ks)/(kband - ks)) on [ks, kband]), where
 * this returns H > 0; 0: on the real axis.  Exact by Cauchy's theorem when
 * no pole or branch point of W(k, s) lies between the two paths.  For
 * s = c0 + i omega, omega >= 0, a forward mode's pole (group velocity > 0)
 * and the branch points k = kappa_j (omega - i c0) lie below the real
 * axis, and the alpha_j's cuts never enter the first quadrant (Im (k^2 +
 * kappa_j^2 s^2) > 0 there).  Below the first thickness resonance (A1,
 * omega = pi c2/h) only A0 and S0 propagate, both forward; the first
 * quadrant holds only evanescent roots: A0's at 45 degrees or steeper
 * (Kirchhoff: k^4 = -s^2 rho h/D), and the complex modes at Im k >= 2.25/hh
 * (sin 2z + 2z = 0, z = k hh/2).  Above it A1 propagates, forward too,
 * and the branches of the modes not yet cut on lie near Re k = 0, steeper
 * than the contour; the first backward wave (pole above the axis) is
 * S1's, between its zero-group-velocity point and its cutoff omega h =
 * pi min(c1, 2 c2).  So H is taken where omega hh <
 * anvil_lift_cutoff(nu) pi, and at most 0.5 kband/pi (a slope of at most 0.5:
 * below 27 degrees), 0.5/hh (a quarter of the complex modes' height) and
 * ANVIL_LIFT_MAX / wide (zhat(k a) grows like exp(a H): a H <= 8 for the
 * widest patch a = wide the contour serves; wide = 1 for r0's, and a
 * point load's integrand, zhat = 1/(2 pi), does not grow at all).  Off the real
 * axis the poles (c0/c_group below it) are H sin(...) further from the
 * path: the peaks the bisection chased are gone.  tests/test_lift.c checks
 * the two paths agree within their error estimates to past the cutoff,
 * and finds the first disagreement (S1's backward wave, whose pole lies
 * above the axis) at omega hh/pi = 1.75 for nu = 0.3; carried to 2.2 pi/hh
 * (h = 0.05 r0, patch 0.5, T' = 64) at 0.93-0.97 of S1's cutoff over nu =
 * 0-0.38 (nu = -0.5, 0.45, 0.49: none).  The cutoff is ANVIL_LIFT_S1 of
 * S1's cutoff, at least ANVIL_LIFT_CUTOFF (the first thickness resonance's
 * 0.9, where the lift stopped before: h = 0.02 r0 at 10 m/s spent 30 % of
 * its evaluations on the terms above it).
 * Above the cutoff the backward waves' poles (S1's, and the higher modes'
 * between their zero-group-velocity points and their cutoffs) lie above
 * the axis, but at Re k below those points, k hh of order 1-2: so the band
 * is lifted from ANVIL_LIFT_KS/hh on (its kstart; the real axis before,
 * in the real band's pieces), where omega hh < ANVIL_LIFT_TOP pi, the
 * lifted part is at least 4/hh long and its pieces (2 H) are wider than
 * the real band's (anvil_kband_piece): on a thick layer the lift is
 * small (0.5/hh) and its complex kernel dearer than the real one for the
 * same evaluations (h = 100 r0, 100 kg at 1 m/s: 0.43 -> 0.50 s).  tests/test_lift.c: from k hh = 0.3 and
 * 1 the two paths disagree by up to 3.5e6 times the allowance (S1's
 * backward wave, nu = 0 and 0.3), from 2 they agree to 12 pi/hh, from 3
 * within 0.01 of the allowance to 6 pi/hh and 0.3 to 12 pi/hh (nu 0-0.45,
 * h = 0.02-0.5 r0), with 2-4 times fewer evaluations (h = 0.1 r0, 0.1 g
 * at 100 m/s: the band to 2.4 pi/hh). */
#define ANVIL_LIFT_CUTOFF 0.9
#define ANVIL_LIFT_S1 0.8
#define ANVIL_LIFT_MAX 8.0
#define ANVIL_LIFT_KS 3.0
#define ANVIL_LIFT_TOP 6.0
/* omega hh/pi below which the band is lifted: max(ANVIL_LIFT_CUTOFF,
 * ANVIL_LIFT_S1 min(c1/c2, 2)) */
double anvil_lift_cutoff(double nu);
/* wide: the widest patch (r0 units, in (0, 1]) whose zhat the band's
 * integrands carry on this contour: the loads of a set share it.  The
 * contour is lifted on [*kstart, kband] (0 below the cutoff). */
double anvil_kband_lift(double omega, double hh, double nu, double kband, double wide,
			double *kstart);

/* The starting pieces of a band lifted by H = lift: as anvil_kband_piece,
 * and at least 2 H (at most kband) wide: the path is H from the poles. */
double anvil_kband_lift_piece(double hh, double kband, double lift);

#endif
