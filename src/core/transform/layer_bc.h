/* layer_bc.h: the free layer's boundary conditions at one (k, s), solved
 * once for both the centre response (green.c) and the field at depth
 * (field_kernel.c, field.c).  Internal to the core.
 *
 * Units mu = rho = c2 = r0 = 1; a = k^2, b = s^2, kap2 = kappa^2 = (c2/c1)^2,
 * alpha_j = sqrt(a + kappa_j^2 b), gamma = 2a + b, X = 4 a alpha1 alpha2,
 * R = gamma^2 - X the Rayleigh function (rationalised, kernel.h).  The layer
 * 0 <= z <= hh is loaded on z = 0 (sigma_zz = -1 per unit Hankel-transformed
 * load, sigma_rz = 0) and free at z = hh; hh = INFINITY is the half-space.
 * Potentials (field_kernel.h):
 *   phi(z) = A1 e^{-alpha1 z} + B1 e^{-alpha1 (hh - z)},
 *   chi(z) = A2 e^{-alpha2 z} + B2 e^{-alpha2 (hh - z)}.
 *
 * The conditions split into parts symmetric and antisymmetric about the
 * mid-plane: with S_j = A_j + B_j, D_j = A_j - B_j, E_j = exp(-alpha_j hh),
 *   gamma (1+E1) S1 - 2k alpha2 (1+E2) D2 = -1,  -2k alpha1 (1-E1) S1 + gamma (1-E2) D2 = 0,
 *   gamma (1-E1) D1 - 2k alpha2 (1-E2) S2 = -1,  -2k alpha1 (1+E1) D1 + gamma (1+E2) S2 = 0,
 * two 2x2 systems whose determinants, over (1+E1)(1+E2), are
 *   den1 = t2 R + X d (symmetric),  den2 = t1 R - X d (antisymmetric),
 * t_j = (1 - E_j)/(1 + E_j) = tanh(alpha_j hh/2), d = t2 - t1.  Everything is
 * written with E_j (|E_j| <= 1), expm1 for 1 - E_j and d from
 * anvil_kernel_exp2, so nothing overflows and nothing cancels whatever
 * hh |alpha| is; B1, B2 and the layer's difference from the half-space
 * are O(E) and formed from u1 = 1 - t1 and d without cancellation. */
#ifndef ANVIL_LAYER_BC_H
#define ANVIL_LAYER_BC_H

#include <complex.h>

struct anvil_layer_bc {
	double k, kap2, hh;
	double complex b, al1, al2, gam, X, R;
	/* the layer (finite hh) only: */
	double complex E1, E2, p1, p2; /* E_j, 1 + E_j */
	double complex t1, t2, u1, d;  /* tanh(alpha_j hh/2), 1 - t1, t2 - t1 */
	double complex Xd, den1, den2;
};

/* The solve at (k, s), Re s > 0, k >= 0, kap2 = kappa^2, hh > 0 or INFINITY. */
void anvil_layer_bc_solve(double k, double complex s, double kap2, double hh,
			  struct anvil_layer_bc *bc);

/* The same at a complex k, Re k >= 0, Im k >= 0, where the principal
 * alpha_j are the analytic continuation from the real axis (no branch cut
 * of theirs crosses that quadrant for Re s > 0, Im s >= 0): for a
 * k-contour lifted off the real axis (green_spectrum.c).  bc->k is NaN:
 * anvil_layer_bc_potentials needs a real k. */
void anvil_layer_bc_solve_c(double complex k, double complex s, double kap2, double hh,
			    struct anvil_layer_bc *bc);

/* The half-space's transformed surface displacement w(z = 0) (against
 * k J0(kr)), alpha1 b / R. */
double complex anvil_layer_bc_w_halfspace(const struct anvil_layer_bc *bc);

/* The layer's w(z = 0) less the half-space's (0 for the half-space):
 *   (W_hs/2) [ (R u1 + X d)/den2 - (t2 R u1 + X d)/den1 ],
 * the surface value of the potentials' w = phi' + k chi (checked against
 * them in tests/test_green.c), without the cancellation of taking their
 * difference: it decays like exp(-k hh) in k. */
double complex anvil_layer_bc_w_correction(const struct anvil_layer_bc *bc);

/* The potentials' coefficients A1, B1, A2, B2 (B_j = 0 for the half-space). */
void anvil_layer_bc_potentials(const struct anvil_layer_bc *bc, double complex *A1,
			       double complex *B1, double complex *A2, double complex *B2);

#endif
