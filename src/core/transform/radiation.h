/* radiation.h: what a small contact radiates into an elastic half-space.
 *
 * A normal force P(t) on the surface of a half-space (mu, nu, rho; shear
 * speed c2), spread over a patch of radius a.  In the frequency domain
 * (time factor exp(i omega t)) the centre displacement is
 *   w(omega) = [ C(a) - i omega beta + O(omega^2 a / c2^2 ...) ] P(omega),
 * where C(a) is the static compliance of the patch (for a Hertz-shaped
 * pressure 3 (1 - nu^2) / (4 E a), Johnson 1985 sec. 3.4) and the term
 * linear in i omega does not depend on the patch at all:
 *
 *  - The mobility Y = i omega w / P has Re Y = omega^2 beta + O(omega^3):
 *    the power the force puts into the solid, (1/2) |P|^2 Re Y, leaves as
 *    waves to infinity, and at wavelengths long against a the far field of
 *    any patch is that of a point force of the same resultant (Miller and
 *    Pursey 1954).  So beta = xi(nu) / (rho c2^3), where
 *      Re Y_point = xi(nu) omega^2 / (rho c2^3)
 *    is the point force's radiation mobility: xi is dimensionless (the
 *    only scales are rho, c2 and omega) and depends on nu alone.
 *  - Sign: the power absorbed must be positive, so beta > 0.
 *
 * In time, w = C P - beta dP/dt (+ terms in d^2P/dt^2 of relative size
 * (omega a / c2)).  The remainder w_dyn = -beta dP/dt is the layer's
 * response beyond its static indentation: a short lag of the surface
 * behind the static value (w ~ C P(t - beta/C)).  For a load that starts
 * and ends at zero it takes the energy
 *   int P dw_dyn/dt dt = beta int (dP/dt)^2 dt >= 0   (by parts),
 * Hunter's (1957) radiation loss.
 * The ramp response (P = t) of w_dyn is -beta H(t); in the units of the
 * half-space response (halfspace.h: time c2 t / r, response mu c2 w) it is
 *   -mu c2 beta = -xi(nu),
 * independent of the patch radius: the exact response of any patch obeys
 * ramp(tau) - C tau -> -xi once its transients have passed (for the Hertz
 * patch, for tau >= tau_R exactly; tests/test_radiation.c checks this
 * against halfspace.c, which is an independent computation).
 *
 * xi is computed here by the wavenumber integral of the point force's
 * surface Green function at s = i omega (units mu = c2 = rho = omega = 1):
 *   U = (1 / 2 pi) int_0^inf W_hs(q, s) q dq,  Re Y = -Im U ...
 * on a contour lifted above the real axis (past the branch points kappa
 * and 1 and the Rayleigh pole c2/c_R), where the integrand is analytic. */
#ifndef ANVIL_RADIATION_H
#define ANVIL_RADIATION_H

/* Relative accuracy of anvil_radiation_xi (QUADPACK's estimate is checked
 * against it: a failed quadrature gives NaN, never a rough value). */
#define ANVIL_RADIATION_XI_TOL 1e-10

/* xi(nu) for nu in (-1, 0.5): Re Y = xi omega^2 / (rho c2^3) for a point
 * force on a half-space at low frequency.  NaN outside the range or when the
 * quadrature fails (or cannot allocate).  xi(0.3) = 0.137227... */
double anvil_radiation_xi(double nu);

/* beta = xi(nu) / (rho c2^3) in m s / N: the dynamic remainder of a small
 * contact on a half-space is w_dyn = -beta dP/dt.  NaN for bad input. */
double anvil_radiation_beta(double nu, double rho, double c2);

/* The share of the radiated power carried by the Rayleigh wave, from the
 * residue at the Rayleigh pole alone (closed form in the Rayleigh root):
 * an independent check of xi against Miller and Pursey (1955), who found
 * about 67 % Rayleigh, 26 % shear, 7 % compressional for nu = 0.25.  NaN
 * outside (-1, 0.5). */
double anvil_radiation_rayleigh_share(double nu);

/* The next term, (i omega)^2 gamma a / (mu c2^2), for a Hertz contact of
 * radius a (issue 11).  It is reactive (real for real omega: no power),
 * and analytic in omega: the exact ramp response differs from C tau - xi
 * only over [0, tau_R], so the difference has a transform that is entire.
 *
 * At the centre of a Hertz patch gamma_c is the area of that difference
 * (the ramp response in the units above).  A point load at distance s has,
 * by the same dimensional argument, kappa s / (mu c2^2) with one kappa(nu);
 * so gamma_c a = kappa E_H|x| (E_H: the mean over the Hertz pressure,
 * E_H|x| = 3 pi a / 16).  The contact's approach is not the centre's
 * displacement: an extra displacement d(x) under a Hertz contact moves the
 * approach by d's mean weighted by the flat punch's pressure
 * 1/sqrt(a^2 - r^2) (Betti's reciprocity with the punch; the contact radius
 * is stationary there, dP/da = 0 at Hertz's a^2 = R alpha).  With
 * d(x') = kappa E_H|x - x'| that mean is kappa a 3 pi / 10 (the Hertz and
 * punch weights over the disc, tests/test_radiation.c), so
 *   gamma = gamma_c (3 pi / 10) / (3 pi / 16) = (8/5) gamma_c.
 * gamma(0) = 21/160, gamma(0.25) = 27/320, gamma(0.3) = 0.0772500.
 * For a contact whose radius grows with the load (a P = K sqrt(R) alpha^2)
 * the term in time is gamma / (mu c2^2) d^2(a P)/dt^2: linear in the
 * pressure, whose moment of |x - x'| is a P times the constant above. */
#define ANVIL_RADIATION_PUNCH_MEAN 1.6
double anvil_radiation_gamma(double nu);

/* g2 = gamma(nu) / (mu c2^2) = gamma / (rho c2^4), s^4/(kg m): the approach's
 * remainder beyond -beta dP/dt is + g2 d^2(a P)/dt^2.  NaN for bad input. */
double anvil_radiation_g2(double nu, double rho, double c2);

#endif
