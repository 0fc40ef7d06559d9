/* plate_bending.h: the bending stress at the centre of a thin plate under
 * an impact's force history, for long contacts whose transform field
 * (field.h) costs minutes.
 *
 * The plate: Kirchhoff's, infinite, D lap^2 w + rho h w_tt = P(t) Z(r, t),
 * D = E h^3 / (12 (1 - nu^2)), under the Hertz-shaped patch Z of radius c
 * (Z(r) = 3/(2 pi c^2) sqrt(1 - r^2/c^2), Hankel transform
 * Z^H(k) = 3 (sin x - x cos x) / (2 pi x^3), x = k c).  Each Hankel mode is
 * an oscillator of frequency omega = beta k^2, beta = sqrt(D / (rho h)), so
 *   w^H(k, t) = Z^H(k) / (rho h omega) int_0^t P(tau) sin(omega (t - tau)) dtau
 * and the radial moment at the centre, M_r(0) = -D (1 + nu)/2 lap w(0), is
 *   M_r(0, t) = D (1 + nu)/2 int_0^inf k^3 w^H(k, t) dk.
 * The far face's stress is sigma_rr = sigma_tt = 6 M_r / h^2 (tension),
 * the near face's -6 M_r / h^2 plus the contact's own stress.
 *
 * Numerics: the k-integral done first, in closed form: an impulse on the
 * patch gives M_r(0, s) = (1 + nu) Gamma(c^2 / (beta s)) / (8 pi s), Gamma
 * a one-line integral (plate_bending.c) tabulated once per call (QUADPACK
 * qaws, a cubic spline; its asymptotic series for large argument); then
 *   sigma(t) = 3 (1 + nu) / (4 pi h^2) int_0^t P(tau) Gamma(...) / (t - tau) dtau,
 * one QUADPACK integral (qag) in ln (t - tau) per instant, P(t) linear
 * between the history's samples (any spacing).  Its error estimate is the
 * quadrature's plus the truncated tail's; against the step load's closed
 * form (tests/test_plate_bending.c) within 1.4e-6 relative.  A contact's
 * maximum costs about 60 ms.
 *
 * The patch (c): a fixed radius, or the Hertz contact's a(t) = sqrt(r0
 * alpha_H), alpha_H = (P/K)^(2/3), as the true contact loads the plate;
 * and the thick plate's equivalent radius (Timoshenko and Woinowsky-Krieger,
 * Theory of Plates and Shells, 1959, sec. 19, after Westergaard): a load
 * spread over c < 1.724 h acts on the mid-plane like one over
 * b = sqrt(1.6 c^2 + h^2) - 0.675 h, because it spreads through the
 * thickness before it bends the plate.  Where the estimate holds against
 * the transform field (its stated accuracy) is anvil_plate_bending_peak's. */
#ifndef ANVIL_PLATE_BENDING_H
#define ANVIL_PLATE_BENDING_H

#include "params.h"
#include "result.h"
#include "status.h"

/* How the patch's radius is taken: FIXED or HERTZ, optionally with
 * WESTERGAARD (bit or). */
enum anvil_plate_patch {
	ANVIL_PLATE_PATCH_FIXED = 0,      /* c given (the paper's r0 patch) */
	ANVIL_PLATE_PATCH_HERTZ = 1,      /* c = a(t) of the Hertz contact */
	ANVIL_PLATE_PATCH_WESTERGAARD = 2 /* the radius c replaced by b(c) (above) */
};
/* The estimate's patch: the true contact, spread through the thickness. */
#define ANVIL_PLATE_PATCH_TRUE (ANVIL_PLATE_PATCH_HERTZ | ANVIL_PLATE_PATCH_WESTERGAARD)

/* The far-face bending stress at the centre at time t (s) of the plate p
 * (finite h) under history hist's P(t) (any spacing, t_0 = 0): *sigma (Pa)
 * and its numerical error *err (the quadrature's, Pa).  patch FIXED uses
 * radius c (m, > 0); HERTZ ignores c.  ANVIL_OK, ANVIL_EINVAL (infinite
 * h, no history, c <= 0 for FIXED), ANVIL_ENUM (the quadrature failed). */
int anvil_plate_bending_at(const struct anvil_params *p, const struct anvil_history *hist,
			   unsigned patch, double c, double t, double *sigma,
			   double *err);

/* The maximum over the contact. */
struct anvil_plate_bending {
	double sigma, err; /* the far face's sigma_rr at its maximum, and the quadrature's error, Pa */
	double t;          /* when, s */
	double P, a;       /* the force (N) and the Hertz contact radius (m) at t */
	double a_h, t_h;   /* a / h and t / (2h/c1) at t: the estimate's coordinates */
	double tol;        /* the model's stated relative accuracy (against the transform field)
			    * in its range; 0 outside it */
	char why[160];     /* outside the range: why ("" inside) */
};

/* The model's stated accuracy and its range, measured against the
 * transform field's far face (field.h, `anvil field --at 0,h --no-yield`:
 * the paper's Hertz patch of radius r0, the same P(t) for both), copper
 * rods on steel at 3-10 m/s, 12 g-20 kg, h = 0.2-10 r0 (15 plates), the
 * patch c = r0 from 0.1 h to 5 h: the estimate with Westergaard's radius
 * was within -1.3 % .. +4.0 % of the field at every plate, the error
 * growing slowly as c/h falls below 0.5 (without Westergaard +41 % at
 * c = 0.1 h), the field's own error estimate up to 4.5 % (h = 0.2 r0);
 * the bending peaked 24-35 times 2h/c1 after impact.  Within
 * ANVIL_PLATE_BENDING_TOL relative, then, for a patch (the Hertz a at the
 * peak) of ANVIL_PLATE_BENDING_A_H_MIN .. _MAX times h and a peak at least
 * ANVIL_PLATE_BENDING_T_MIN times 2h/c1 after impact (the plate's
 * dispersion, which Kirchhoff gets wrong at the thickness's wavelengths,
 * has by then left the centre).  The field carries the r0 patch, so the
 * Hertz patch a(t) is the same model at another radius within the
 * measured range, not a separate measurement. */
#define ANVIL_PLATE_BENDING_TOL 0.05
#define ANVIL_PLATE_BENDING_A_H_MIN 0.1
#define ANVIL_PLATE_BENDING_A_H_MAX 5.0
#define ANVIL_PLATE_BENDING_T_MIN 20.0

/* The maximum over t in (0, t_end] (t_end <= the history's last sample; 0:
 * the last) of anvil_plate_bending_at (patch, c as there; the estimate's
 * is ANVIL_PLATE_PATCH_TRUE), by a scan of
 * NSCAN instants and Brent's minimiser (GSL) around the best, to 1e-4
 * relative in t; b->tol and b->why from the range above (a, a_h at the
 * Hertz contact whatever the patch).  Statuses as
 * anvil_plate_bending_at; ANVIL_EINVAL when P never exceeds 0. */
int anvil_plate_bending_peak(const struct anvil_params *p, const struct anvil_history *hist,
			     unsigned patch, double c, double t_end, struct anvil_plate_bending *b,
			     struct anvil_err *err);

/* One plate under one history, for many instants: what
 * anvil_plate_bending_at computes, its tables made once.  NULL on failure
 * (err says why). */
struct anvil_plate_bender;
struct anvil_plate_bender *anvil_plate_bender_new(const struct anvil_params *p,
						  const struct anvil_history *hist, unsigned patch,
						  double c, struct anvil_err *err);
int anvil_plate_bender_at(struct anvil_plate_bender *pb, double t, double *sigma, double *err);
void anvil_plate_bender_free(struct anvil_plate_bender *pb);

/* The patch radius the plate takes under force P (N), m: c, or the Hertz
 * contact's, Westergaard's radius of it with that bit. */
double anvil_plate_bending_patch(const struct anvil_params *p, unsigned patch, double c,
				 double P);

/* The near face under the contact: the Hertz field of (a, p0, nu) plus the
 * plate's bending at the same instant, the centre's far-face stress s_b
 * (tension) from the history, its radial fall from Kirchhoff's
 * equilibrium under the patch of radius b carrying P (plate_bending.c
 * derives both).  Bending alone at the near face's centre is -s_b in r and
 * theta, linear through the thickness to +s_b at the far face. */
struct anvil_plate_near {
	double stress; /* the largest von Mises stress, or (brittle) principal tension, Pa */
	double r, z;   /* where, m (z from the loaded face) */
};

/* The plate's own stresses at (r, z) near the centre, z < h/2: sigma_rr
 * and sigma_tt, Pa (compression negative). */
void anvil_plate_bending_near_stress(double sb, double P, double b, double nu, double h,
				     double r, double z, double *srr, double *stt);

/* The largest of the combined stress over r <= 3 a, z <= min(3 a, h/2)
 * (a grid of a/20, then Nelder-Mead, GSL), von Mises (brittle 0) or the
 * largest principal stress (brittle 1).  s_b = 0 gives Hertz's own
 * (0.620 p0 at 0.481 a for nu = 0.3; brittle (1 - 2nu) p0/3 at r = a).
 * ANVIL_OK, ANVIL_EINVAL (a, p0, h not > 0, nu outside [0, 0.5)). */
int anvil_plate_bending_near(double a, double p0, double nu, double h, double P, double b,
			     double sb, int brittle, struct anvil_plate_near *n);

#endif
