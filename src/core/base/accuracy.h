/* accuracy.h: the accuracy levels, in one table.
 *
 * A level is a promise (the target relative error of P_max, t_s and R_f)
 * and the numerical settings that keep it, for every part of the engine:
 * the centre response and the coupled impact (engine), the layer
 * correction's inversion (transform/green) and the field (field).  Every
 * module reads its settings from here; none keeps a table of its own.  The
 * values come from convergence studies; each column's comment says which. */
#ifndef ANVIL_ACCURACY_H
#define ANVIL_ACCURACY_H

enum anvil_accuracy {
	ANVIL_ACC_DRAFT,
	ANVIL_ACC_NORMAL,
	ANVIL_ACC_FINE,
	ANVIL_ACC_REFERENCE,
	ANVIL_ACC_COUNT
};

struct anvil_level {
	const char *name;
	double target; /* relative error promised for P_max, t_s and R_f */

	/* The centre response and the coupled impact (engine/plan.c), from
	 * convergence studies on the paper's ten cases (scripts/bench,
	 * tests/test_layer.c):
	 *   cycles, omega_min: the layer correction's bandwidth
	 *     omega_max = max(omega_min, cycles / tau_contact), dimensionless,
	 *     so that fast impacts get more frequencies;
	 *   nsteps: time steps per Hertz contact time (the dt/2 pass doubles);
	 *   hs_tol: tolerance of the exact half-space response. */
	double cycles, omega_min, nsteps, hs_tol;

	/* The layer correction's Durbin inversion (transform/green.c);
	 * tests/test_layer.c shows each level meeting its target, and
	 * tests/test_green.c that c0T = 8 and 13 agree:
	 *   c0T: the abscissa c0 times the half period T';
	 *   tol: ramp error target, relative to its half-space size;
	 *   ktail: integrand cut-off, exp(-2 Re(alpha1) H) below this. */
	double green_c0T, green_tol, green_ktail;

	/* The field (field/field.c), from convergence studies against runs at
	 * the reference level with three times its bandwidth and a window of
	 * 3 t_last; the derivation of each column is at field.c's use:
	 *   cycles, omega_min: bandwidth, as above with twice the cycles;
	 *   tw, c0t: the Durbin window T' = tw t_last and c0 = c0t / t_last;
	 *   band_w: panel width in the pole band, in pole distances c0/c1;
	 *   ktail: how far past the band the k-integral goes where z -> 0;
	 *   L: exp(-L) ends the integral where e^{-kz} decays first. */
	struct anvil_field_level {
		double cycles, omega_min, tw, c0t, band_w, ktail, L;
	} field;
};

/* The level's settings; NULL for a value out of range. */
const struct anvil_level *anvil_level(enum anvil_accuracy a);

/* Names <-> enums; parse returns -1 for an unknown name (case ignored). */
const char *anvil_accuracy_name(enum anvil_accuracy a);
int anvil_accuracy_parse(const char *name);
/* The documented target relative error of P_max, t_s and R_f at a level
 * (NaN out of range). */
double anvil_accuracy_target(enum anvil_accuracy a);

#endif
