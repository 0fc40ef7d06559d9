/* test_hertz_field: Huber's closed-form Hertz field (hertz_field.c)
 *  - the full-field formula against the axis (Johnson eq. 3.45) and surface
 *    (eqs. 3.41-3.42) forms, approached from inside;
 *  - equilibrium: the divergence of the stress vanishes (finite differences);
 *  - far away, Boussinesq's point load P = (2/3) pi a^2 p0;
 *  - the peak von Mises stress (0.62 p0 at 0.48 a for nu = 0.3, Johnson
 *    sec. 4.2) by the minimiser, by a scan, and nowhere larger off the axis;
 *  - the edge tension (1 - 2 nu) p0 / 3 and the verdict. */
#include <math.h>

#include <gsl/gsl_errno.h>

#include "hertz_field.h"
#include "tap.h"

static struct anvil_hertz_stress at(double nu, double r, double z)
{
	struct anvil_hertz_stress s;
	anvil_hertz_stress(1.0, 1.0, nu, r, z, &s);
	return s;
}

static void test_limits(void)
{
	double d = 0;
	for (double z = 0.05; z < 5; z *= 1.7) { /* axis, approached at r = 1e-7 a */
		struct anvil_hertz_stress s = at(0.3, 1e-7, z), t = at(0.3, 0.0, z);
		d = fmax(d, fmax(fabs(s.rr - t.rr), fmax(fabs(s.tt - t.tt), fabs(s.zz - t.zz))));
	}
	ok(d < 1e-10, "full field at r = 1e-7 a = Johnson's axis forms (3.45): %.2g p0", d);
	d = 0;
	for (double r = 0.05; r < 3; r += 0.1) { /* surface, approached at z = 1e-10 a */
		struct anvil_hertz_stress s = at(0.3, r, 1e-10), t = at(0.3, r, 0.0);
		if (fabs(r - 1) > 0.01)
			d = fmax(d, fmax(fabs(s.rr - t.rr), fmax(fabs(s.tt - t.tt), fabs(s.zz - t.zz))));
	}
	ok(d < 1e-8, "full field at z = 1e-10 a = the surface forms (3.41-3.42): %.2g p0", d);
	/* the Hertz pressure, no shear on the surface */
	struct anvil_hertz_stress s = at(0.3, 0.6, 1e-12);
	is_rel(s.zz, -0.8, 1e-10, "sigma_zz(0.6 a, 0) = -p0 sqrt(1 - 0.36)");
	is_abs(s.rz, 0.0, 1e-10, "sigma_rz = 0 on the surface");
	for (double nu = 0.0; nu < 0.5; nu += 0.2) {
		struct anvil_hertz_stress e = at(nu, 1.0, 0.0);
		is_rel(e.rr, (1 - 2 * nu) / 3, 1e-12, "nu = %.1f: sigma_rr(a, 0) = (1 - 2 nu) p0 / 3", nu);
		is_rel(anvil_hertz_tension(1.0, nu), (1 - 2 * nu) / 3, 1e-15,
		       "nu = %.1f: anvil_hertz_tension", nu);
	}
	/* just inside the edge, by the full-field formula at z = 1e-13 a */
	double x = 1.0 - 1e-9, q = sqrt(1 - x * x);
	struct anvil_hertz_stress in = at(0.3, x, 1e-13);
	is_rel(in.rr, 0.4 / 3 * (1 - q * q * q) / (x * x) - q, 1e-6,
	       "the edge tension from inside the contact too (%.8f)", in.rr);
}

/* div sigma in cylindrical coordinates, central differences of step h */
static double divergence(double nu, double r, double z, double h)
{
	struct anvil_hertz_stress c = at(nu, r, z), rp = at(nu, r + h, z), rm = at(nu, r - h, z);
	struct anvil_hertz_stress zp = at(nu, r, z + h), zm = at(nu, r, z - h);
	double er = (rp.rr - rm.rr) / (2 * h) + (zp.rz - zm.rz) / (2 * h) + (c.rr - c.tt) / r;
	double ez = (rp.rz - rm.rz) / (2 * h) + (zp.zz - zm.zz) / (2 * h) + c.rz / r;
	return fmax(fabs(er), fabs(ez));
}

static void test_equilibrium(void)
{
	double worst = 0;
	for (double r = 0.15; r < 3; r += 0.35)
		for (double z = 0.12; z < 3; z += 0.33)
			worst = fmax(worst, divergence(0.3, r, z, 1e-4));
	/* truncation h^2 f''' / 6 ~ 1e-8 and rounding 1e-16 / h ~ 1e-12 */
	ok(worst < 1e-6, "equilibrium: |div sigma| < %.2g p0/a on a grid in 0 < r, z < 3 a", worst);
}

/* Largest deviation from Boussinesq on the half-circle of radius R (units
 * of a), relative to P / (2 pi R^2) */
static double boussinesq(double R)
{
	double nu = 0.3, P = 2.0 / 3.0 * M_PI, worst = 0;
	for (double th = 0.2; th < 1.5; th += 0.3) {
		double r = R * sin(th), z = R * cos(th), R5 = pow(R, 5);
		struct anvil_hertz_stress s = at(nu, r, z);
		double k = P / (2 * M_PI), b = (1 - 2 * nu) * (1 - z / R) / (r * r);
		double rr = k * (b - 3 * z * r * r / R5), tt = -k * (1 - 2 * nu) *
			    ((1 - z / R) / (r * r) - z / (R * R * R));
		double zz = -3 * k * z * z * z / R5, rz = -3 * k * r * z * z / R5;
		double scale = k / (R * R);
		worst = fmax(worst, fmax(fmax(fabs(s.rr - rr), fabs(s.tt - tt)),
					 fmax(fabs(s.zz - zz), fabs(s.rz - rz))) / scale);
	}
	return worst;
}

static void test_boussinesq(void)
{
	/* the next term of the multipole expansion is O((a/R)^2): the
	 * deviation falls four times when R doubles */
	double d40 = boussinesq(40.0), d80 = boussinesq(80.0);
	ok(d80 < 3.0 / (80.0 * 80.0), "at 80 a: Boussinesq's point load (Johnson 3.21) to "
	   "%.2g of P/(2 pi R^2) (< 3 (a/R)^2)", d80);
	is_abs(d40 / d80, 4.0, 0.1, "the deviation is O((a/R)^2): ratio %.3f from 40 a to 80 a",
	       d40 / d80);
}

static void test_peak(void)
{
	double vm, z;
	int st = anvil_hertz_vm_peak(2e-3, 1e9, 0.3, &vm, &z);
	diag("peak von Mises for nu = 0.3: %.6f p0 at z = %.6f a", vm / 1e9, z / 2e-3);
	ok(st == ANVIL_OK, "vm peak found");
	is_abs(vm / 1e9, 0.62, 0.005, "peak von Mises %.4f p0 ~ 0.62 p0 (Johnson sec. 4.2)", vm / 1e9);
	is_abs(z / 2e-3, 0.48, 0.005, "at depth %.4f a ~ 0.48 a", z / 2e-3);
	/* a scan of the axis, independent of the minimiser */
	double best = 0, zb = 0;
	for (double y = 0; y < 2; y += 1e-5) {
		double v = at(0.3, 0, y).vm;
		if (v > best)
			best = v, zb = y;
	}
	is_abs(vm / 1e9, best, 1e-9, "the minimiser's value = the axis scan's (%.8f)", best);
	is_abs(z / 2e-3, zb, 1e-4, "the minimiser's depth = the axis scan's (%.5f)", zb);
	double off = 0;
	for (double r = 0.02; r < 2; r += 0.02)
		for (double y = 0.01; y < 2; y += 0.01)
			off = fmax(off, at(0.3, r, y).vm);
	ok(off < best, "no point off the axis exceeds it (largest off-axis %.5f)", off);
}

static void test_verdict(void)
{
	struct anvil_hertz_verdict v;
	/* yield: first yield at p0 = Y / 0.62 = 1.61 Y */
	int st = anvil_hertz_judge(1e-3, 1.7e9, 0.3, 1e9, NAN, &v);
	ok(st == ANVIL_OK && v.fate == ANVIL_HERTZ_YIELDS && isnan(v.tension_ratio),
	   "steel-like, p0 = 1.7 Y: yields (vm/Y = %.3f)", v.yield_ratio);
	st = anvil_hertz_judge(1e-3, 1.5e9, 0.3, 1e9, NAN, &v);
	ok(st == ANVIL_OK && v.fate == ANVIL_HERTZ_ELASTIC, "p0 = 1.5 Y: elastic (vm/Y = %.3f)",
	   v.yield_ratio);
	/* glass (nu 0.22, tensile strength ~ 50 MPa): cracks long before it yields */
	st = anvil_hertz_judge(1e-4, 1e9, 0.22, NAN, 50e6, &v);
	ok(st == ANVIL_OK && v.fate == ANVIL_HERTZ_CRACKS && fabs(v.tension - 0.56e9 / 3) < 1,
	   "glass, p0 = 1 GPa: cracks at the edge (tension %.0f MPa = %.1f x strength)",
	   v.tension / 1e6, v.tension_ratio);
	st = anvil_hertz_judge(1e-4, 1e9, 0.22, 5e9, 50e6, &v);
	ok(st == ANVIL_OK && v.fate == ANVIL_HERTZ_CRACKS, "with both criteria the one reached "
	   "first is named");
	st = anvil_hertz_judge(1e-4, 1e12, 0.3, NAN, NAN, &v);
	ok(st == ANVIL_OK && v.fate == ANVIL_HERTZ_ELASTIC, "no strengths known: nothing judged");
	ok(anvil_hertz_judge(1e-4, 1e9, 0.3, -1, NAN, &v) == ANVIL_EINVAL &&
	   anvil_hertz_judge(0, 1e9, 0.3, 1, NAN, &v) == ANVIL_EINVAL, "bad strength or a: EINVAL");
	struct anvil_hertz_stress s;
	ok(anvil_hertz_stress(1, 1, 0.3, -1, 0, &s) == ANVIL_EINVAL && isnan(s.vm) &&
	   anvil_hertz_stress(1, 1, 0.5, 0, 1, &s) == ANVIL_EINVAL, "bad point or nu: EINVAL, NaN");
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(11 + 1 + 2 + 6 + 7);
	test_limits();
	test_equilibrium();
	test_boussinesq();
	test_peak();
	test_verdict();
	return done_testing();
}
