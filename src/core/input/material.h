/* material.h: isotropic elastic materials, built in and derived constants.
 *
 * A material is E, nu, rho (SI) plus an optional yield stress, and for a
 * brittle one (glass, cemented carbide) a tensile strength: what fails
 * first under a contact is then a ring crack at the contact's edge, not
 * yield below it (hertz_field.h, anvil_hertz_judge).  The
 * built-in table holds copper and steel exactly as Table 1 of the paper, and
 * further engineering materials, each with its source. */
#ifndef ANVIL_MATERIAL_H
#define ANVIL_MATERIAL_H

#include "status.h"

#define ANVIL_NAME_MAX 32

struct anvil_material {
	char name[ANVIL_NAME_MAX];
	double E;      /* Young's modulus, Pa */
	double nu;     /* Poisson's ratio */
	double rho;    /* density, kg/m^3 */
	double yield;  /* yield stress, Pa; 0 when unknown */
	const char *source; /* where the numbers come from (static string) or NULL */
	/* After source, so that {name, E, nu, rho, yield, source} initialisers
	 * still read: a ductile material of unknown tensile strength. */
	double tensile; /* tensile strength, Pa; 0 when unknown */
	int brittle;    /* 1: fails in tension (cracks), not by yield */
};

/* The built-in table: index 0 .. count-1.  at() returns NULL out of range. */
int anvil_material_count(void);
const struct anvil_material *anvil_material_at(int i);
/* Case-insensitive lookup by name; NULL when there is none. */
const struct anvil_material *anvil_material_find(const char *name);

/* Derived constants (SI). */
double anvil_material_lambda(const struct anvil_material *m); /* Lame lambda, Pa */
double anvil_material_mu(const struct anvil_material *m);     /* shear modulus, Pa */
double anvil_material_c1(const struct anvil_material *m);     /* P-wave speed, m/s */
double anvil_material_c2(const struct anvil_material *m);     /* S-wave speed, m/s */
double anvil_material_cr(const struct anvil_material *m);     /* Rayleigh speed, m/s */

/* (c_R/c2)^2, the Rayleigh root, for k2 = (c2/c1)^2: Brent on the
 * rationalised cubic, polished by Newton and checked against the
 * unrationalised equation.  ANVIL_ENUM (message in err) if that fails. */
/* kappa^2 = (c2/c1)^2 = (1 - 2 nu) / (2 (1 - nu)): the one place it is
 * written. */
double anvil_kappa2(double nu);
/* The static centre compliance w/P of a Hertz-shaped pressure of radius r0
 * on a half-space, 3 (1 - nu^2) / (4 E r0) (Johnson 1985, sec. 3.4; the
 * late-time limit of the half-space response, halfspace.h, where it is
 * 3 (1 - nu) / 8 in units 1/(mu r0)). */
double anvil_patch_compliance(double E, double nu, double r0);
int anvil_rayleigh_x(double k2, double *x, struct anvil_err *err);

/* Back from wave speeds: sets E, nu and rho of m from c1, c2 and rho; the
 * speeds must give -1 < nu < 0.5, i.e. c2 > 0 and c1 > c2 sqrt(4/3).
 * ANVIL_EINVAL (message in err) when they do not. */
int anvil_material_from_speeds(struct anvil_material *m, double c1, double c2,
			       double rho, struct anvil_err *err);

/* E > 0, rho > 0, -1 < nu < 0.5, yield >= 0, tensile >= 0; else ANVIL_EINVAL naming the
 * material and the field. */
int anvil_material_check(const struct anvil_material *m, struct anvil_err *err);

#endif
