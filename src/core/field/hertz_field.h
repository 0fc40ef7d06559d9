/* hertz_field.h: the quasi-static stress field of a Hertz contact on a
 * half-space, in closed form, and what it says about failure.
 *
 * Pressure p(r) = p0 sqrt(1 - r^2/a^2) on r < a of the surface z = 0 of a
 * half-space z > 0 with Poisson ratio nu (total load P = (2/3) pi a^2 p0).
 * The field is Huber's (1904) closed form as given by Johnson (Contact
 * Mechanics, 1985, sec. 3.4, eq. 3.44 after Huber; Hamilton 1983 for the
 * equivalent form), in terms of u, the positive root of
 *   r^2 / (a^2 + u) + z^2 / u = 1,
 *   u = (1/2) [ (r^2 + z^2 - a^2) + sqrt((r^2 + z^2 - a^2)^2 + 4 a^2 z^2) ],
 * with s = z / sqrt(u) and A = atan(a / sqrt(u)):
 *   sigma_rr/p0 = (1-2nu)/3 (a^2/r^2)(1 - s^3) + s^3 a^2 u / (u^2 + a^2 z^2)
 *                 + s [ u (1-nu)/(a^2+u) + (1+nu)(sqrt(u)/a) A - 2 ]
 *   sigma_tt/p0 = -(1-2nu)/3 (a^2/r^2)(1 - s^3)
 *                 - s [ 2 nu + u (1-nu)/(a^2+u) - (1+nu)(sqrt(u)/a) A ]
 *   sigma_zz/p0 = -s^3 a^2 u / (u^2 + a^2 z^2)
 *   sigma_rz/p0 = -r z^2 / (u^2 + a^2 z^2) a^2 sqrt(u) / (a^2 + u)
 * (tension positive).  The tests check these against the surface and axis
 * forms (Johnson eqs. 3.41-3.43, 3.45), against equilibrium (the
 * divergence of the stress, by finite differences) and against Boussinesq's
 * point load far away, so a misprint cannot pass.  On the axis (r = 0) and
 * the surface (z = 0) the limits are taken analytically, not by division.
 * Accuracy: a few ulps times the condition of the formula (measured
 * better than 1e-12 p0 against the axis and surface forms). */
#ifndef ANVIL_HERTZ_FIELD_H
#define ANVIL_HERTZ_FIELD_H

#include "status.h"

struct anvil_hertz_stress {
	double rr, tt, zz, rz; /* Pa, tension positive */
	double vm;             /* von Mises equivalent stress, Pa */
};

/* The stress at (r >= 0, z >= 0) for contact radius a > 0, peak pressure
 * p0 and nu in (-1, 0.5).  ANVIL_EINVAL (stress NaN) for bad arguments. */
int anvil_hertz_stress(double a, double p0, double nu, double r, double z,
		       struct anvil_hertz_stress *s);

/* s's von Mises stress from its components (rr, tt, zz, rz): what
 * anvil_hertz_stress puts in s->vm, for a state other stresses were added
 * to (plate_bending.c: the plate's bending on the near face). */
double anvil_hertz_von_mises(const struct anvil_hertz_stress *s);

/* The largest von Mises stress, which for nu in [0, 0.5) lies on the axis
 * below the surface: its value *vm (Pa) and depth *z (m), by GSL's Brent
 * minimiser to relative tolerance 1e-12 in z.  ANVIL_EINVAL for bad
 * arguments, ANVIL_ENUM if the minimiser fails.  For nu = 0.3:
 * 0.620041 p0 at 0.480864 a (tests/test_hertz_field.c). */
int anvil_hertz_vm_peak(double a, double p0, double nu, double *vm, double *z);

/* The largest tensile stress, the radial stress at the contact edge on the
 * surface: (1 - 2 nu) p0 / 3 (Johnson eq. 3.41). */
double anvil_hertz_tension(double p0, double nu);

/* What the contact does to the layer. */
enum anvil_hertz_fate {
	ANVIL_HERTZ_ELASTIC, /* neither criterion met (or none known) */
	ANVIL_HERTZ_YIELDS,  /* von Mises peak > yield stress (ductile) */
	ANVIL_HERTZ_CRACKS   /* edge tension > tensile strength (brittle) */
};

struct anvil_hertz_verdict {
	enum anvil_hertz_fate fate;
	double vm, z_vm;   /* peak von Mises (Pa) and its depth (m) */
	double tension;    /* largest tensile stress (Pa), at r = a, z = 0 */
	double yield_ratio;   /* vm / yield, NaN when the yield stress is NaN */
	double tension_ratio; /* tension / strength, NaN when the strength is NaN */
};

/* Judge a contact of radius a and peak pressure p0 on a layer of Poisson
 * ratio nu with yield stress Y and tensile strength St (either may be NaN:
 * unknown, not checked).  When both criteria are met the one with the larger
 * ratio is named (the first to be reached as the load grows: both grow like
 * p0).  ANVIL_EINVAL for bad arguments (Y or St <= 0), ANVIL_ENUM as for
 * anvil_hertz_vm_peak. */
int anvil_hertz_judge(double a, double p0, double nu, double Y, double St,
		      struct anvil_hertz_verdict *v);

#endif
