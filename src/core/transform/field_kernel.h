/* field_kernel.h: the transformed fields at depth z, and the static field of
 * the Hertz patch on a half-space in closed form.  Internal to the field
 * module (field.c) and its tests.
 *
 * Units mu = rho = c2 = r0 = 1 (so lambda = 1/kappa^2 - 2, kappa = c2/c1);
 * per unit Hankel-transformed load (the factor Z^H(k) is applied by the
 * caller, once).  The layer is 0 <= z <= hh, loaded on z = 0
 * (sigma_zz = -1, sigma_rz = 0), free at z = hh; hh = INFINITY is the
 * half-space.
 *
 * Representation (the paper's eqs 23-26 with its potentials written in
 * exponentials instead of ch/sh, so that nothing overflows):
 *   phi(z) = A1 e^{-alpha1 z} + B1 e^{-alpha1 (hh - z)},
 *   chi(z) = A2 e^{-alpha2 z} + B2 e^{-alpha2 (hh - z)},
 *   U = -(k phi + chi'),  W = phi' + k chi                (u: k J1, w: k J0)
 *   S_zz = gamma phi + 2k chi',  S_rz = -(2k phi' + gamma chi)
 *   L = lambda e = lambda kappa^2 s^2 phi                 (e: the dilatation)
 * with gamma = 2k^2 + s^2 (notes.md), alpha_j = sqrt(k^2 + kappa_j^2 s^2).
 * Every exponential has a non-positive real exponent for 0 <= z <= hh. */
#ifndef ANVIL_FIELD_KERNEL_H
#define ANVIL_FIELD_KERNEL_H

#include <complex.h>

/* The inversion and the quadrature rule field.c shares with green.c. */

/* The transformed quantities at depth (coefficients of the inverse Hankel
 * transforms: U and S_rz against k J1(kr), the others against k J0(kr)). */
enum { FK_U, FK_W, FK_SZZ, FK_SRZ, FK_LAM, FK_COUNT };

/* The seven Hankel integrals the stresses are made of:
 *   HS_U   = u        = int U k J1 dk
 *   HS_UR  = u / r    = int U k J1(kr)/r dk     (-> int U k^2/2 at r = 0)
 *   HS_KU  = (1/r) d(r u)/dr = int U k^2 J0 dk
 *   HS_W   = w,  HS_SZZ = sigma_zz,  HS_SRZ = sigma_rz,  HS_LAM = lambda e
 * so that sigma_rr = LAM + 2 KU - 2 UR and sigma_tt = LAM + 2 UR. */
enum { HS_U, HS_UR, HS_KU, HS_W, HS_SZZ, HS_SRZ, HS_LAM, HS_COUNT };

/* Which transformed quantity each Hankel integral takes. */
extern const int anvil_fk_of_hs[HS_COUNT];

/* Everything at one (k, s) that does not depend on z. */
struct anvil_fk_coef {
	double k;
	double complex b;        /* s^2 */
	double complex al1, al2, gam;
	double complex A1, B1, A2, B2;
};


/* The coefficients at (k, s), Re s > 0, kap2 = kappa^2. */
void anvil_fk_coef(double k, double complex s, double kap2, double hh,
		   struct anvil_fk_coef *c);

/* The transformed quantities at a depth where e_j = exp(-alpha_j z) and
 * f_j = exp(-alpha_j (hh - z)) (f_j unused for the half-space). */
void anvil_fk_at(const struct anvil_fk_coef *c, double kap2, double complex e1,
		 double complex f1, double complex e2, double complex f2,
		 double complex out[FK_COUNT]);

/* Both steps at once, for tests and single points: out[FK_COUNT] at
 * (k, s, z) for Poisson ratio nu. */
void anvil_fk_eval(double k, double complex s, double nu, double hh, double z,
		   double complex out[FK_COUNT]);

/* The static half-space kernels (s -> 0 limit of the half-space, Boussinesq):
 * out[FK_COUNT] at (k, z). */
void anvil_fk_static(double k, double z, double nu, double out[FK_COUNT]);

/* The static half-space field of the unit Hertz patch load at (r, z), as the
 * seven Hankel integrals hs[HS_COUNT] of anvil_fk_static times Z^H, in
 * closed form (see field_kernel.c).  r >= 0, z >= 0. */
void anvil_fk_static_field(double nu, double r, double z, double hs[HS_COUNT]);

#endif
