/* test_material: the built-in table against the paper's Table 1, derived
 * constants, the Rayleigh speed, the inverse from wave speeds, check(). */
#include <ctype.h>
#include <math.h>
#include <string.h>

#include "material.h"
#include "tap.h"

#define TABLE1_TOL 1e-3 /* Table 1 prints 4 significant digits */

static void table1(const char *name, double c1, double c2, double lambda, double mu)
{
	const struct anvil_material *m = anvil_material_find(name);
	if (!ok(m != NULL, "%s is built in", name))
		return;
	ok(m->source && strstr(m->source, "Pyr'yev et al. 2024, Table 1"),
	   "%s cites the paper's Table 1", name);
	is_rel(anvil_material_c1(m), c1, TABLE1_TOL, "%s c1 = %g m/s (Table 1)", name, c1);
	is_rel(anvil_material_c2(m), c2, TABLE1_TOL, "%s c2 = %g m/s (Table 1)", name, c2);
	is_rel(anvil_material_lambda(m), lambda, TABLE1_TOL, "%s lambda = %g GPa (Table 1)",
	       name, lambda / 1e9);
	is_rel(anvil_material_mu(m), mu, TABLE1_TOL, "%s mu = %g GPa (Table 1)", name, mu / 1e9);
}

/* The Rayleigh equation (2 - x)^2 = 4 sqrt(1 - x k^2) sqrt(1 - x). */
static double rayleigh_residual(const struct anvil_material *m)
{
	double c1 = anvil_material_c1(m), c2 = anvil_material_c2(m), cr = anvil_material_cr(m);
	double x = (cr / c2) * (cr / c2), k2 = (c2 / c1) * (c2 / c1);
	return (2 - x) * (2 - x) - 4 * sqrt(1 - x * k2) * sqrt(1 - x);
}

static struct anvil_material make(const char *name, double E, double nu, double rho,
				  double yield)
{
	struct anvil_material m = {"", E, nu, rho, yield, NULL, 0, 0};
	snprintf(m.name, sizeof m.name, "%s", name);
	return m;
}

static void check_fails(struct anvil_material m, const char *want)
{
	struct anvil_err err;
	anvil_err_clear(&err);
	int st = anvil_material_check(&m, &err);
	ok(st == ANVIL_EINVAL && err.status == ANVIL_EINVAL, "check rejects: %s", want);
	if (!ok(strstr(err.msg, want) != NULL, "  message has \"%s\"", want))
		diag("  got: %s", err.msg);
}

int main(void)
{
	struct anvil_err err;

	/* Table 1 of the paper, exactly. */
	const struct anvil_material *cu = anvil_material_find("copper");
	const struct anvil_material *st = anvil_material_find("steel");
	ok(cu && cu->E == 123e9 && cu->nu == 0.34 && cu->rho == 8960 && cu->yield == 57e6,
	   "copper is E 123 GPa, nu 0.34, rho 8960, yield 57 MPa");
	ok(st && st->E == 209e9 && st->nu == 0.3 && st->rho == 7830 && st->yield == 1000e6,
	   "steel is E 209 GPa, nu 0.3, rho 7830, yield 1000 MPa");
	table1("steel", 5994, 3204, 120.6e9, 80.4e9);
	table1("copper", 4597, 2263, 97.53e9, 45.9e9);

	/* The table. */
	int n = anvil_material_count();
	ok(n >= 7, "at least 7 built-in materials (%d)", n);
	ok(anvil_material_at(-1) == NULL && anvil_material_at(n) == NULL, "at() out of range is NULL");
	static const char *const want[] = {"copper", "steel", "aluminium", "titanium",
					   "tungsten-carbide", "glass", "pmma"};
	for (size_t i = 0; i < sizeof want / sizeof want[0]; ++i)
		ok(anvil_material_find(want[i]) != NULL, "'%s' is built in", want[i]);
	for (int i = 0; i < n; ++i) {
		const struct anvil_material *m = anvil_material_at(i);
		int lower = 1;
		for (const char *p = m->name; *p; ++p)
			lower &= !isupper((unsigned char)*p) && !isspace((unsigned char)*p);
		ok(lower && m->name[0], "'%s' is a lowercase identifier", m->name);
		ok(m->source && m->source[0], "'%s' has a source: %s", m->name,
		   m->source ? m->source : "(none)");
		ok(anvil_material_check(m, &err) == ANVIL_OK, "'%s' passes check", m->name);
		ok(anvil_material_find(m->name) == m, "find('%s') finds it", m->name);
		double cr = anvil_material_cr(m), c2 = anvil_material_c2(m);
		ok(cr > 0 && cr < c2, "'%s' 0 < cR = %.1f < c2 = %.1f m/s", m->name, cr, c2);
		is_abs(rayleigh_residual(m), 0, 1e-13, "'%s' cR solves the Rayleigh equation",
		       m->name);
		/* from_speeds inverts c1, c2. */
		struct anvil_material back = make(m->name, 0, 0, 0, 0);
		ok(anvil_material_from_speeds(&back, anvil_material_c1(m), c2, m->rho, &err) ==
			   ANVIL_OK, "'%s' from its own wave speeds", m->name);
		is_rel(back.E, m->E, 1e-13, "  E back");
		is_rel(back.nu, m->nu, 1e-13, "  nu back");
		ok(back.rho == m->rho, "  rho set");
	}
	ok(anvil_material_find("STEEL") == st && anvil_material_find("Copper") == cu,
	   "lookup is case-insensitive");
	ok(anvil_material_find("aluminum") == anvil_material_find("aluminium"),
	   "'aluminum' is an alias");
	ok(anvil_material_find("unobtainium") == NULL && anvil_material_find(NULL) == NULL,
	   "unknown names give NULL");

	/* Rayleigh speed: nu = 1/4 has a closed form, cR/c2 = sqrt(2 - 2/sqrt(3)). */
	struct anvil_material q = make("poisson-solid", 100e9, 0.25, 5000, 0);
	is_rel(anvil_material_cr(&q) / anvil_material_c2(&q), sqrt(2 - 2 / sqrt(3.0)), 1e-13,
	       "cR/c2 = 0.919402 at nu = 1/4");
	/* Viktorov's approximation (0.862 + 1.14 nu)/(1 + nu), good to about 0.5 %. */
	is_rel(anvil_material_cr(st) / anvil_material_c2(st), (0.862 + 1.14 * 0.3) / 1.3, 5e-3,
	       "steel cR/c2 near Viktorov's 0.926");
	const double extreme[] = {-0.999, -0.5, 0, 0.49, 0.4999};
	for (size_t i = 0; i < sizeof extreme / sizeof extreme[0]; ++i) {
		q.nu = extreme[i];
		double r = anvil_material_cr(&q) / anvil_material_c2(&q);
		ok(r > 0.6 && r < 0.96, "cR/c2 = %.4f at nu = %g", r, extreme[i]);
		is_abs(rayleigh_residual(&q), 0, 1e-12, "  solves the Rayleigh equation");
	}
	q.nu = 0.6;
	ok(isnan(anvil_material_cr(&q)), "cR is NaN for an unphysical material");

	/* from_speeds: -1 < nu < 1/2 is exactly c2 > 0 and c1 > c2 sqrt(4/3). */
	struct anvil_material f = make("f", 0, 0, 0, 0);
	ok(anvil_material_from_speeds(&f, 5994, 3204, 7830, &err) == ANVIL_OK,
	   "steel's Table 1 speeds");
	is_rel(f.nu, 0.3, 2e-3, "  give nu = 0.3");
	is_rel(f.E, 209e9, 2e-3, "  and E = 209 GPa");
	ok(anvil_material_from_speeds(&f, 3000 * sqrt(4.0 / 3) * (1 + 1e-9), 3000, 1000, &err) ==
		   ANVIL_OK && f.nu > -1 && f.nu < -0.99999,
	   "c1 just above c2 sqrt(4/3): nu just above -1 (%.9f)", f.nu);
	ok(anvil_material_from_speeds(&f, 3000 * sqrt(2.0), 3000, 1000, &err) == ANVIL_OK &&
		   fabs(f.nu) < 1e-15, "c1 = c2 sqrt(2): nu = 0");
	static const struct {
		double c1, c2, rho;
		const char *msg;
	} badspeeds[] = {
		{3000 * 1.15, 3000, 1000, "need c2 > 0 and c1 > c2 sqrt(4/3)"},
		{3000, 3000, 1000, "c1 > c2 sqrt(4/3)"},
		{2000, 3000, 1000, "c1 > c2 sqrt(4/3)"},
		{3000, 0, 1000, "need c2 > 0"},
		{3000, -1, 1000, "need c2 > 0"},
		{NAN, 1000, 1000, "wave speeds"},
		{INFINITY, 1000, 1000, "wave speeds"},
		{3000, 1000, 0, "material 'f': rho = 0 kg/m^3 is not > 0"},
		{3000, 1000, NAN, "rho = nan"},
	};
	for (size_t i = 0; i < sizeof badspeeds / sizeof badspeeds[0]; ++i) {
		f = make("f", 1, 0.1, 1, 0);
		int s = anvil_material_from_speeds(&f, badspeeds[i].c1, badspeeds[i].c2,
						   badspeeds[i].rho, &err);
		ok(s == ANVIL_EINVAL && f.E == 1 && f.nu == 0.1,
		   "from_speeds(%g, %g, %g) is ANVIL_EINVAL, m untouched", badspeeds[i].c1,
		   badspeeds[i].c2, badspeeds[i].rho);
		if (!ok(strstr(err.msg, badspeeds[i].msg) != NULL, "  message has \"%s\"",
			badspeeds[i].msg))
			diag("  got: %s", err.msg);
	}

	/* check(): every field, every way. */
	check_fails(make("x", 1e9, 0.6, 1000, 0), "material 'x': nu = 0.6 is not in (-1, 0.5)");
	check_fails(make("x", 1e9, 0.5, 1000, 0), "nu = 0.5 is not in (-1, 0.5)");
	check_fails(make("x", 1e9, -1, 1000, 0), "nu = -1 is not in (-1, 0.5)");
	check_fails(make("x", 1e9, NAN, 1000, 0), "nu = nan");
	check_fails(make("x", 0, 0.3, 1000, 0), "material 'x': E = 0 Pa is not > 0");
	check_fails(make("x", -1e9, 0.3, 1000, 0), "E = -1e+09 Pa is not > 0");
	check_fails(make("x", INFINITY, 0.3, 1000, 0), "E = inf");
	check_fails(make("x", 1e9, 0.3, 0, 0), "material 'x': rho = 0 kg/m^3 is not > 0");
	check_fails(make("x", 1e9, 0.3, NAN, 0), "rho = nan");
	check_fails(make("x", 1e9, 0.3, 1000, -1), "material 'x': yield = -1 Pa is not >= 0");
	check_fails(make("x", 1e9, 0.3, 1000, NAN), "yield = nan");
	check_fails(make("", 1e9, 0.7, 1000, 0), "material '(unnamed)': nu");
	struct anvil_material good = make("x", 1e9, 0.3, 1000, 0);
	ok(anvil_material_check(&good, NULL) == ANVIL_OK, "a valid material passes, NULL err");
	good.nu = -0.99;
	ok(anvil_material_check(&good, NULL) == ANVIL_OK, "nu = -0.99 is valid");

	plan(tap_n);
	return done_testing();
}
