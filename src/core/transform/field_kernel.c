/* field_kernel.c: the layer's transformed fields at depth, and the static
 * Hertz field of a half-space in closed form.  See field_kernel.h. */
#include <complex.h>
#include <math.h>

#include "field_kernel.h"
#include "kernel.h"
#include "layer_bc.h"
#include "material.h"

typedef double complex cplx;

const int anvil_fk_of_hs[HS_COUNT] = {
	[HS_U] = FK_U, [HS_UR] = FK_U, [HS_KU] = FK_U, [HS_W] = FK_W,
	[HS_SZZ] = FK_SZZ, [HS_SRZ] = FK_SRZ, [HS_LAM] = FK_LAM,
};

/* The coefficients from the one boundary-condition solve (layer_bc.h). */
void anvil_fk_coef(double k, cplx s, double kap2, double hh, struct anvil_fk_coef *c)
{
	struct anvil_layer_bc bc;
	anvil_layer_bc_solve(k, s, kap2, hh, &bc);
	c->k = k;
	c->b = bc.b;
	c->al1 = bc.al1;
	c->al2 = bc.al2;
	c->gam = bc.gam;
	anvil_layer_bc_potentials(&bc, &c->A1, &c->B1, &c->A2, &c->B2);
}

void anvil_fk_at(const struct anvil_fk_coef *c, double kap2, cplx e1, cplx f1, cplx e2,
		 cplx f2, cplx out[FK_COUNT])
{
	double k = c->k;
	cplx P1 = c->A1 * e1, Q1 = c->B1 * f1, P2 = c->A2 * e2, Q2 = c->B2 * f2;
	cplx phi = P1 + Q1, dphi = c->al1 * (Q1 - P1);
	cplx chi = P2 + Q2, dchi = c->al2 * (Q2 - P2);
	out[FK_U] = -(k * phi + dchi);
	out[FK_W] = dphi + k * chi;
	out[FK_SZZ] = c->gam * phi + 2.0 * k * dchi;
	out[FK_SRZ] = -(2.0 * k * dphi + c->gam * chi);
	/* lambda kappa^2 = 1 - 2 kappa^2 in these units */
	out[FK_LAM] = (1.0 - 2.0 * kap2) * c->b * phi;
}

void anvil_fk_eval(double k, cplx s, double nu, double hh, double z, cplx out[FK_COUNT])
{
	double kap2 = anvil_kappa2(nu);
	struct anvil_fk_coef c;
	anvil_fk_coef(k, s, kap2, hh, &c);
	int layer = isfinite(hh);
	anvil_fk_at(&c, kap2, cexp(-c.al1 * z), layer ? cexp(-c.al1 * (hh - z)) : 0,
		    cexp(-c.al2 * z), layer ? cexp(-c.al2 * (hh - z)) : 0, out);
}

/* Boussinesq's half-space under a static pressure, in these units and
 * conventions (Sneddon, Fourier Transforms, 1951, ch. 10): the s -> 0 limit
 * of the half-space kernels (checked in tests/test_field.c). */
void anvil_fk_static(double k, double z, double nu, double out[FK_COUNT])
{
	double e = exp(-k * z), kz = k * z;
	out[FK_U] = -((1.0 - 2.0 * nu) - kz) * e / (2.0 * k);
	out[FK_W] = (2.0 * (1.0 - nu) + kz) * e / (2.0 * k);
	out[FK_SZZ] = -(1.0 + kz) * e;
	out[FK_SRZ] = -kz * e;
	out[FK_LAM] = -2.0 * nu * e;
}

/* ---- the static Hertz field in closed form --------------------------------
 *
 * The static fields are sums of I(m,n) = int_0^inf k^m e^{-kz} Z^H(k)
 * J_n(kr) dk, m = 0..2, n = 0, 1.  With the Hertz patch
 *   Z^H(k) = (3/2pi) (sin k - k cos k)/k^3 = (3/2pi) (1/k) int_0^1 t sin(kt) dt
 * the k-integral becomes Lipschitz-Hankel (Watson sec. 13.2):
 *   I(m,n) = (3/2pi) int_0^1 t Im L_{m-1,n}(z - i t) dt,
 *   L_{j,n}(p) = int_0^inf k^j e^{-pk} J_n(kr) dk, elementary in p and
 *   rho = sqrt(p^2 + r^2):  L_{0,0} = 1/rho, L_{1,0} = p/rho^3,
 *   L_{-1,0} = -ln(p + rho) + real const, L_{-1,1} = (rho - p)/r,
 *   L_{0,1} = (1 - p/rho)/r, L_{1,1} = r/rho^3,
 * and with p = z - i t (t dt = -(p - z) dp) the t-integral is elementary
 * too: I(m,n) = -(3/2pi) Im [G_{m-1,n}]_{t=0}^{t=1}, G' = (p - z) L.
 * (This is Huber's 1904 solution, written with complex square roots.)
 * Branches: for z > 0, p^2 + r^2 stays off the negative real axis and
 * Re(p + rho) > 0, so the principal sqrt and log are continuous along the
 * path; at z = 0 the limit z -> 0+ is the side -0i of the cut, which C's
 * csqrt takes when the imaginary part is -0.0 (as -2 z t is). */
struct gpt {
	cplx p, rho, ell;
	double r, z;
};

static void gpt_at(double t, double r, double z, struct gpt *g)
{
	g->p = anvil_kernel_cmplx(z, -t);
	g->rho = csqrt(anvil_kernel_cmplx(z * z - t * t + r * r, -2.0 * z * t));
	g->ell = clog(g->p + g->rho);
	g->r = r;
	g->z = z;
}

/* x ln(p + rho), taking x ln x -> 0 at the origin (p + rho = 0). */
static cplx xl(cplx x, cplx ell)
{
	return x == 0 ? 0 : x * ell;
}

/* G_{j,n} for j = -1, 0, 1 (n = 0) and j = -1, 0, 1 (n = 1, r > 0). */
static cplx gfun(int j, int n, const struct gpt *g)
{
	cplx p = g->p, rho = g->rho, ell = g->ell;
	double r = g->r, z = g->z, r2 = r * r;
	if (n == 0) {
		switch (j) {
		case -1:
			return -(xl(0.5 * p * p + 0.25 * r2 - z * p, ell) - 0.25 * p * rho + z * rho);
		case 0:
			return rho - xl(z, ell);
		default:
			return ell - (p - z) / rho;
		}
	}
	switch (j) {
	case -1:
		return (rho * rho * rho / 3.0 - p * p * p / 3.0 - 0.5 * z * (p * rho + r2 * ell) +
			0.5 * z * p * p) / r;
	case 0:
		return (0.5 * p * p - z * p - 0.5 * (p * rho - r2 * ell) + z * rho) / r;
	default:
		return -r / rho - z * p / (r * rho);
	}
}

/* G_{2,0} on the axis (r = 0, rho = p): int (p - z) 2/p^3 dp. */
static cplx gfun_axis2(const struct gpt *g)
{
	return -2.0 / g->p + g->z / (g->p * g->p);
}

#define ZH0 (3.0 / (2.0 * M_PI))

static double idef(int j, int n, const struct gpt *g1, const struct gpt *g0)
{
	return -ZH0 * cimag(gfun(j, n, g1) - gfun(j, n, g0));
}

/* Below this radius the J1 integrals are taken from the axis, with a
 * relative error O(r^2); above it the closed forms (which cancel like
 * (r0/r)^2 as r -> 0) lose fewer digits than that. */
#define R_AXIS 1e-4

struct idx {
	double i00, i10, i20, i01, i11, i21, i01r, i11r;
};

/* The I(m,n) at (r, z); those only ever multiplied by z are left 0 at
 * z = 0, where they can be infinite (I(2,0) at the patch's rim). */
static void ints(double r, double z, struct idx *v)
{
	int axis = r < R_AXIS, deep = z > 0;
	struct gpt g0, g1;
	gpt_at(0.0, axis ? 0.0 : r, z, &g0);
	gpt_at(1.0, axis ? 0.0 : r, z, &g1);
	*v = (struct idx){0};
	v->i00 = idef(-1, 0, &g1, &g0);
	v->i10 = idef(0, 0, &g1, &g0);
	if (deep)
		v->i20 = idef(1, 0, &g1, &g0);
	if (axis) {
		/* J1(kr)/r -> k/2 */
		v->i01r = 0.5 * v->i10;
		v->i11r = 0.5 * v->i20;
		v->i01 = r * v->i01r;
		v->i11 = r * v->i11r;
		if (deep)
			v->i21 = 0.5 * r * -ZH0 * cimag(gfun_axis2(&g1) - gfun_axis2(&g0));
		return;
	}
	v->i01 = idef(-1, 1, &g1, &g0);
	v->i01r = v->i01 / r;
	if (deep) {
		v->i11 = idef(0, 1, &g1, &g0);
		v->i11r = v->i11 / r;
		v->i21 = idef(1, 1, &g1, &g0);
	}
}

/* Below this depth (in r0) the surface's values are used.  The closed forms
 * need z^2 (at r = 0, t = 0: rho = sqrt(z^2) = z, and G_{1,0} divides by it),
 * which underflows below 1e-154; the field's departure from its surface
 * value is O(sqrt(z)) at worst (at the rim, where the pressure has its
 * square-root edge), 1e-50 here, far below rounding. */
#define Z_SURFACE 1e-100

void anvil_fk_static_field(double nu, double r, double z, double hs[HS_COUNT])
{
	struct idx v;
	if (z < Z_SURFACE)
		z = 0.0;
	ints(r, z, &v);
	/* anvil_fk_static times Z^H k J_n, integrated term by term */
	hs[HS_U] = -0.5 * ((1.0 - 2.0 * nu) * v.i01 - z * v.i11);
	hs[HS_UR] = -0.5 * ((1.0 - 2.0 * nu) * v.i01r - z * v.i11r);
	hs[HS_KU] = -0.5 * ((1.0 - 2.0 * nu) * v.i10 - z * v.i20);
	hs[HS_W] = 0.5 * (2.0 * (1.0 - nu) * v.i00 + z * v.i10);
	hs[HS_SZZ] = -(v.i10 + z * v.i20);
	hs[HS_SRZ] = -z * v.i21;
	hs[HS_LAM] = -2.0 * nu * v.i10;
}
