/* layer_bc.c: the free layer's boundary conditions at one (k, s).  See
 * layer_bc.h. */
#include <complex.h>
#include <math.h>

#include "kernel.h"
#include "layer_bc.h"

typedef double complex cplx;

/* The layer's part of the solve, from alpha_j, gamma, X and R. */
static void layer_solve(struct anvil_layer_bc *bc)
{
	cplx m1, m2, diff; /* 1 - E_j, E1 - E2 */
	double hh = bc->hh;
	/* E_j itself, not 1 - m_j: that would leave rounding noise (1e-16)
	 * where E1 is 1e-23, later multiplied by a large exp(-hh (alpha2 - alpha1)) */
	anvil_kernel_exp_1m(-hh * bc->al1, &bc->E1, &m1);
	anvil_kernel_exp2(bc->al1, bc->al2, bc->b, bc->kap2, hh, bc->E1, m1, &bc->E2, &m2, &diff);
	bc->p1 = 2.0 - m1;
	bc->p2 = 2.0 - m2;
	cplx ip1 = anvil_kernel_recip(bc->p1), ip2 = anvil_kernel_recip(bc->p2);
	bc->t1 = m1 * ip1;
	bc->t2 = m2 * ip2;
	bc->u1 = 2.0 * bc->E1 * ip1;
	bc->d = 2.0 * diff * (ip1 * ip2);
	bc->Xd = bc->X * bc->d;
	bc->den1 = bc->t2 * bc->R + bc->Xd;
	bc->den2 = bc->t1 * bc->R - bc->Xd;
}

/* Every quotient through one reciprocal (kernel.h: anvil_kernel_recip) and
 * each E_j with its 1 - E_j from one exponential (anvil_kernel_exp_1m):
 * that halved the cost of an evaluation (scripts/bench); E2 from E1 where
 * the difference's exponential is taken anyway (anvil_kernel_exp2): on
 * h = 0.02 r0, 100 kg at 10 m/s the kernel's instructions fell by 8.6 %,
 * the run's by 3.5 %. */
void anvil_layer_bc_solve(double k, cplx s, double kap2, double hh, struct anvil_layer_bc *bc)
{
	double a = k * k;
	cplx b = s * s;
	cplx al1 = anvil_kernel_csqrt(a + kap2 * b), al2 = anvil_kernel_csqrt(a + b);
	cplx gam = 2.0 * a + b, X = 4.0 * a * al1 * al2;
	bc->k = k;
	bc->kap2 = kap2;
	bc->hh = hh;
	bc->b = b;
	bc->al1 = al1;
	bc->al2 = al2;
	bc->gam = gam;
	bc->X = X;
	bc->R = anvil_kernel_rayleigh(a, b, kap2, gam, X);
	if (isfinite(hh))
		layer_solve(bc);
}

/* The same operations with a complex: the real solve above stays as it
 * was (its bits, and its cost). */
void anvil_layer_bc_solve_c(cplx k, cplx s, double kap2, double hh, struct anvil_layer_bc *bc)
{
	cplx a = k * k, b = s * s;
	cplx al1 = anvil_kernel_csqrt(a + kap2 * b), al2 = anvil_kernel_csqrt(a + b);
	cplx gam = 2.0 * a + b, X = 4.0 * a * al1 * al2;
	bc->k = NAN; /* no potentials */
	bc->kap2 = kap2;
	bc->hh = hh;
	bc->b = b;
	bc->al1 = al1;
	bc->al2 = al2;
	bc->gam = gam;
	bc->X = X;
	bc->R = anvil_kernel_rayleigh_c(a, b, kap2, gam, X);
	if (isfinite(hh))
		layer_solve(bc);
}

cplx anvil_layer_bc_w_halfspace(const struct anvil_layer_bc *bc)
{
	return bc->al1 * bc->b * anvil_kernel_recip(bc->R);
}

/* The two fractions of layer_bc.h over one denominator den1 den2: with
 * u1 = 1 - t1 and d = t2 - t1 the numerator
 *   (R u1 + Xd) den1 - (t2 R u1 + Xd) den2
 *     = t2 R^2 u1^2 + R Xd (u1 + d + t2 u1) + 2 Xd^2
 * is a sum of products of the small u1 and d: the O(E) parts of the two
 * fractions, which cancel, are never formed. */
cplx anvil_layer_bc_w_correction(const struct anvil_layer_bc *bc)
{
	if (!isfinite(bc->hh))
		return 0.0;
	cplx R = bc->R, Xd = bc->Xd, u1 = bc->u1, t2 = bc->t2;
	cplx num = t2 * R * R * u1 * u1 + R * Xd * (u1 + bc->d + t2 * u1) + 2.0 * Xd * Xd;
	return 0.5 * anvil_layer_bc_w_halfspace(bc) * num * anvil_kernel_recip(bc->den1 * bc->den2);
}

void anvil_layer_bc_potentials(const struct anvil_layer_bc *bc, cplx *A1, cplx *B1, cplx *A2,
			       cplx *B2)
{
	double k = bc->k;
	cplx gam = bc->gam, al1 = bc->al1, R = bc->R;
	if (!isfinite(bc->hh)) {
		*A1 = -gam / R;
		*A2 = -2.0 * k * al1 / R;
		*B1 = *B2 = 0.0;
		return;
	}
	cplx t1 = bc->t1, t2 = bc->t2, u1 = bc->u1, d = bc->d, Xd = bc->Xd;
	cplx p1 = bc->p1, p2 = bc->p2, den1 = bc->den1, den2 = bc->den2, dd = den1 * den2;
	cplx S1 = -gam * t2 / (p1 * den1), D1 = -gam / (p1 * den2);
	cplx S2 = -2.0 * k * al1 / (p2 * den2), D2 = -2.0 * k * al1 * t1 / (p2 * den1);
	*A1 = 0.5 * (S1 + D1);
	*A2 = 0.5 * (S2 + D2);
	*B1 = gam * (t2 * u1 * R + Xd * (1.0 + t2)) / (2.0 * p1 * dd);
	*B2 = -k * al1 * ((d + t1 * u1) * R + Xd * (1.0 + t1)) / (p2 * dd);
}
