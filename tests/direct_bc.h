/* direct_bc.h: D1..D4 of the paper's ch/sh representation (eqs 23-26) by a
 * direct 4x4 complex solve of the free layer's boundary conditions:
 * sigma_zz(0) = -1, sigma_rz(0) = 0, sigma_zz(h) = sigma_rz(h) = 0, with
 * gamma = 2k^2 + s^2 (notes.md), mu = c2 = 1.  The independent check of the
 * stable kernels (green.c, field_kernel.c); ill-conditioned for large k h. */
#ifndef ANVIL_TEST_DIRECT_BC_H
#define ANVIL_TEST_DIRECT_BC_H

#include <complex.h>

#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_linalg.h>

static inline void direct_bc(double k, double complex s, double nu, double h,
			     double complex D[4])
{
	double kap2 = (1 - 2 * nu) / (2 * (1 - nu));
	double complex a1 = csqrt(k * k + kap2 * s * s), a2 = csqrt(k * k + s * s);
	double complex g = 2 * k * k + s * s;
	gsl_matrix_complex *A = gsl_matrix_complex_alloc(4, 4);
	gsl_vector_complex *b = gsl_vector_complex_calloc(4), *x = gsl_vector_complex_alloc(4);
	gsl_permutation *perm = gsl_permutation_alloc(4);
	for (int row = 0; row < 4; row++) {
		double z = row < 2 ? 0.0 : h;
		double complex c1 = ccosh(a1 * z), s1 = csinh(a1 * z) / a1;
		double complex c2 = ccosh(a2 * z), s2 = csinh(a2 * z) / a2, m[4];
		if (row % 2 == 0) { /* sigma_zz, eq (25) */
			m[0] = g * c1; m[1] = g * s1; m[2] = 2 * k * a2 * a2 * s2; m[3] = 2 * k * c2;
		} else { /* sigma_rz, eq (26) */
			m[0] = -2 * k * a1 * a1 * s1; m[1] = -2 * k * c1; m[2] = -g * c2; m[3] = -g * s2;
		}
		for (int j = 0; j < 4; j++)
			gsl_matrix_complex_set(A, (size_t)row, (size_t)j,
					       gsl_complex_rect(creal(m[j]), cimag(m[j])));
	}
	gsl_vector_complex_set(b, 0, gsl_complex_rect(-1, 0));
	int sign;
	gsl_linalg_complex_LU_decomp(A, perm, &sign);
	gsl_linalg_complex_LU_solve(A, perm, b, x);
	for (int j = 0; j < 4; j++) {
		gsl_complex v = gsl_vector_complex_get(x, (size_t)j);
		D[j] = GSL_REAL(v) + I * GSL_IMAG(v);
	}
	gsl_matrix_complex_free(A);
	gsl_vector_complex_free(b);
	gsl_vector_complex_free(x);
	gsl_permutation_free(perm);
}

#endif
