/* material.c: the built-in materials and the constants derived from E, nu, rho. */
#include <float.h>
#include <math.h>
#include <string.h>
#include <strings.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "material.h"

#define PAPER "Pyr'yev et al. 2024, Table 1"

/* Copper and steel exactly as the paper's Table 1 (the other rows of that
 * table, c1, c2, lambda and mu, follow from these and are tested).  The rest
 * are typical room-temperature values; yield 0 means none or unknown. */
static const struct anvil_material table[] = {
	{"copper", 123e9, 0.34, 8960, 57e6, PAPER, 0, 0},
	{"steel", 209e9, 0.3, 7830, 1000e6, PAPER, 0, 0},
	{"aluminium", 68.9e9, 0.33, 2700, 276e6,
	 "ASM Handbook Vol. 2 (1990) / MatWeb: aluminium alloy 6061-T6", 0, 0},
	{"titanium", 113.8e9, 0.342, 4430, 880e6,
	 "ASM Aerospace Specification Metals / MatWeb: Ti-6Al-4V (grade 5), annealed", 0, 0},
	/* Brittle: a Hertz contact cracks them at the contact edge, where the
	 * surface tension (1 - 2 nu) p0 / 3 meets the tensile strength.  Both
	 * strengths are flaw-controlled bulk values: small contacts crack at
	 * higher nominal stress (Auerbach's law, Johnson 1985 sec. 4.2), so the
	 * verdict is on the safe side. */
	{"tungsten-carbide", 600e9, 0.22, 14950, 0,
	 "cemented carbide WC-6Co, typical grade datasheet values (ASM Handbook "
	 "Vol. 2); brittle: yield 0, compressive strength about 5 GPa, tensile "
	 "strength about 1.4 GPa (typical; transverse rupture strength 2-3 GPa)",
	 1.4e9, 1},
	{"glass", 72e9, 0.22, 2500, 0,
	 "soda-lime float glass, typical (MatWeb; Shelby, Introduction to Glass "
	 "Science and Technology); brittle: yield 0, tensile strength 45 MPa "
	 "(characteristic bending strength of annealed float glass, EN 572-1)",
	 45e6, 1},
	{"pmma", 3.0e9, 0.37, 1180, 70e6,
	 "MatWeb: PMMA (acrylic, Plexiglas/Perspex), typical; yield = tensile strength", 0, 0},
};
#define NTABLE ((int)(sizeof table / sizeof table[0]))

/* Other spellings people type. */
static const struct {
	const char *alias, *name;
} aliases[] = {
	{"aluminum", "aluminium"},
	{"wc", "tungsten-carbide"},
	{"soda-lime-glass", "glass"},
	{"acrylic", "pmma"},
};

int anvil_material_count(void) { return NTABLE; }

const struct anvil_material *anvil_material_at(int i)
{
	return i >= 0 && i < NTABLE ? &table[i] : NULL;
}

const struct anvil_material *anvil_material_find(const char *name)
{
	if (!name)
		return NULL;
	for (int i = 0; i < NTABLE; ++i)
		if (strcasecmp(name, table[i].name) == 0)
			return &table[i];
	for (size_t i = 0; i < sizeof aliases / sizeof aliases[0]; ++i)
		if (strcasecmp(name, aliases[i].alias) == 0)
			return anvil_material_find(aliases[i].name);
	return NULL;
}

double anvil_material_lambda(const struct anvil_material *m)
{
	return m->E * m->nu / ((1 + m->nu) * (1 - 2 * m->nu));
}

double anvil_material_mu(const struct anvil_material *m)
{
	return m->E / (2 * (1 + m->nu));
}

double anvil_material_c1(const struct anvil_material *m)
{
	return sqrt((anvil_material_lambda(m) + 2 * anvil_material_mu(m)) / m->rho);
}

double anvil_material_c2(const struct anvil_material *m)
{
	return sqrt(anvil_material_mu(m) / m->rho);
}

#define RAYLEIGH_MAXITER 200

/* The Rayleigh equation rationalised, in xi = (c/c2)^2, divided by xi:
 * xi^3 - 8 xi^2 + (24 - 16 kappa^2) xi - 16 (1 - kappa^2).  It is -16 (1 -
 * kappa^2) < 0 at 0 and 1 at 1, and its one root in (0,1) is the Rayleigh
 * root (there both sides of (2 - xi)^2 = 4 a1 a2 are positive). */
static double rayleigh_cubic(double xi, void *p)
{
	double k2 = *(const double *)p;
	return ((xi - 8.0) * xi + (24.0 - 16.0 * k2)) * xi - 16.0 * (1.0 - k2);
}

int anvil_rayleigh_x(double k2, double *xi_out, struct anvil_err *err)
{
	gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	if (!s)
		return anvil_err_set(err, ANVIL_ENOMEM, "Rayleigh speed: out of memory");
	double kk = k2;
	gsl_function f = { rayleigh_cubic, &kk };
	int st = gsl_root_fsolver_set(s, &f, 0.0, 1.0), rc = ANVIL_ENUM;
	for (int it = 0; st == GSL_SUCCESS && it < RAYLEIGH_MAXITER; it++) {
		st = gsl_root_fsolver_iterate(s);
		if (st != GSL_SUCCESS)
			break;
		st = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s),
					    0.0, 4.0 * DBL_EPSILON);
		if (st == GSL_SUCCESS) {
			rc = ANVIL_OK;
			break;
		}
		if (st != GSL_CONTINUE)
			break;
		st = GSL_SUCCESS;
	}
	double xi = gsl_root_fsolver_root(s);
	gsl_root_fsolver_free(s);
	if (rc != ANVIL_OK)
		return anvil_err_set(err, ANVIL_ENUM,
				     "Rayleigh speed: Rayleigh root not found (%s)", gsl_strerror(st));
	/* one Newton step on the cubic polishes the last bits */
	double d = (3.0 * xi - 16.0) * xi + (24.0 - 16.0 * k2);
	if (d != 0)
		xi -= rayleigh_cubic(xi, &kk) / d;
	/* the unrationalised equation must hold too */
	double res = (2.0 - xi) * (2.0 - xi) - 4.0 * sqrt(1.0 - k2 * xi) * sqrt(1.0 - xi);
	if (!(xi > 0 && xi < 1) || !(fabs(res) < 1e-12))
		return anvil_err_set(err, ANVIL_ENUM,
				     "Rayleigh speed: bad Rayleigh root xi = %g (residual %g)", xi, res);
	*xi_out = xi;
	return ANVIL_OK;
}

double anvil_material_cr(const struct anvil_material *m)
{
	if (anvil_material_check(m, NULL) != ANVIL_OK)
		return NAN;
	double c1 = anvil_material_c1(m), c2 = anvil_material_c2(m), x;
	if (anvil_rayleigh_x((c2 / c1) * (c2 / c1), &x, NULL) != ANVIL_OK)
		return NAN;
	return c2 * sqrt(x);
}

/* nu = (c1^2 - 2 c2^2) / (2 (c1^2 - c2^2)).  With c1 > c2 > 0, nu < 1/2
 * always holds, and nu > -1 is 3 c1^2 > 4 c2^2: so the physical speeds are
 * exactly c2 > 0 and c1 > c2 sqrt(4/3) (c1 > c2 sqrt(2) is nu > 0). */
int anvil_material_from_speeds(struct anvil_material *m, double c1, double c2,
			       double rho, struct anvil_err *err)
{
	const char *name = m->name[0] ? m->name : "(unnamed)";
	if (!(isfinite(c1) && isfinite(c2) && c2 > 0 && 3 * c1 * c1 > 4 * c2 * c2))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "material '%s': wave speeds c1 = %g m/s, c2 = %g m/s "
				     "need c2 > 0 and c1 > c2 sqrt(4/3) (-1 < nu < 0.5)",
				     name, c1, c2);
	if (!(isfinite(rho) && rho > 0))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "material '%s': rho = %g kg/m^3 is not > 0", name, rho);
	double a = c1 * c1, b = c2 * c2;
	double nu = (a - 2 * b) / (2 * (a - b));
	m->nu = nu;
	m->rho = rho;
	m->E = 2 * rho * b * (1 + nu);
	return ANVIL_OK;
}

int anvil_material_check(const struct anvil_material *m, struct anvil_err *err)
{
	const char *name = m->name[0] ? m->name : "(unnamed)";
	if (!(isfinite(m->E) && m->E > 0))
		return anvil_err_set(err, ANVIL_EINVAL, "material '%s': E = %g Pa is not > 0",
				     name, m->E);
	if (!(isfinite(m->nu) && m->nu > -1 && m->nu < 0.5))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "material '%s': nu = %g is not in (-1, 0.5)", name, m->nu);
	if (!(isfinite(m->rho) && m->rho > 0))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "material '%s': rho = %g kg/m^3 is not > 0", name, m->rho);
	if (!(isfinite(m->yield) && m->yield >= 0))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "material '%s': yield = %g Pa is not >= 0", name, m->yield);
	if (!(isfinite(m->tensile) && m->tensile >= 0))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "material '%s': tensile = %g Pa is not >= 0", name, m->tensile);
	return ANVIL_OK;
}

double anvil_kappa2(double nu)
{
	return (1 - 2 * nu) / (2 * (1 - nu));
}

double anvil_patch_compliance(double E, double nu, double r0)
{
	return 3.0 * (1.0 - nu * nu) / (4.0 * E * r0);
}
