/* green_spectrum.h: the layer response's spectrum on an inversion line
 * (green.c's; internal to the core): the k-integrals of the layer
 * correction (or of the half-space) at each s of the line, on all cores,
 * with one kernel memo for the loads of a set, and the Zener plate's late
 * growth taken out of the spectrum (to be put back in time). */
#ifndef ANVIL_GREEN_SPECTRUM_H
#define ANVIL_GREEN_SPECTRUM_H

#include <complex.h>
#include <stddef.h>

#include "durbin.h"
#include "green.h"

/* The plate's late growth: alpha* / (s^3 (1 + s tp)) <-> alpha* [t^2/2 -
 * tp t + tp^2 (1 - exp(-t/tp))] (green_spectrum.c says why); zero for the
 * half-space. */
struct green_plate {
	double alpha, tp;
};
struct green_plate green_plate_term(enum anvil_green_mode mode, double hh, double nu);
double complex green_plate_s(const struct green_plate *pl, double complex s);
double green_plate_t(const struct green_plate *pl, double t);

/* One load's spectrum on the line dl: its patch (r0 units; 0 a point),
 * each k-integral's share epsF of the error budget; out, spec[0..M] and
 * err[n], the time-domain bound of term n's quadrature error. */
struct green_spectrum {
	const struct anvil_durbin *dl;
	double cr, ktail, epsF;
	const struct green_plate *pl;
	anvil_progress_fn progress;
	void *ctx;
	double patch;
	int no_lift; /* the band's k-integral on the real axis (kernel.h: anvil_kband_lift),
		      * for tests; a set's is sp[0]'s */
	int far_cut; /* each k-integral to its hard limit (ktail), not where the budget
		      * allows: a reference for tests; a set's is sp[0]'s */
	int full_band; /* the band's small starting pieces to its end, not only to
			* kernel.h anvil_kband_poles: a reference for tests; a set's
			* is sp[0]'s */
	double lift_patch; /* the widest patch (r0 units) the band's lifted contour
			    * serves, at least patch (green.h anvil_green_settings);
			    * 0: r0's; a set's is sp[0]'s */
	double complex *spec;
	double *err;
};

/* The spectra sp[0..nsp-1] (nsp <= GREEN_SPECTRA_MAX; one line: the same
 * s at each n, the bands may differ) of mode at (kap2, nu, hh); evals[i]
 * the kernel evaluations sp[i]'s integrals made (memo hits not counted).
 * ANVIL_OK, ANVIL_ETOL (a k-integral missed its share: it is in err),
 * ANVIL_ENUM, ANVIL_ENOMEM, ANVIL_ECANCEL (sp[0]'s progress callback). */
#define GREEN_SPECTRA_MAX 8
/* lift_patch as anvil_kband_lift's wide: 0 (unset) is r0's, 1 */
double green_lift_wide(double lift_patch);
int green_sample_spectra(enum anvil_green_mode mode, double kap2, double nu, double hh,
			 const struct green_spectrum *sp, size_t nsp, size_t *evals);

#endif
