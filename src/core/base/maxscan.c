/* maxscan.c: a scanned maximum, refined (maxscan.h). */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include "maxscan.h"
#include "status.h"

int anvil_max_refine(gsl_function *minus_f, const double ts[3], const double sv[3], double *t,
		     double *s)
{
	gsl_min_fminimizer *m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
	if (!m)
		return ANVIL_ENOMEM;
	int gs = gsl_min_fminimizer_set_with_values(m, minus_f, ts[1], -sv[1], ts[0], -sv[0], ts[2],
						    -sv[2]);
	for (int it = 0; !gs && it < 60; it++) {
		gs = gsl_min_fminimizer_iterate(m);
		double lo = gsl_min_fminimizer_x_lower(m), hi = gsl_min_fminimizer_x_upper(m);
		if (gs || gsl_min_test_interval(lo, hi, 0, 1e-4) == GSL_SUCCESS)
			break;
	}
	if (!gs && -gsl_min_fminimizer_f_minimum(m) > sv[1]) {
		*t = gsl_min_fminimizer_x_minimum(m);
		*s = -gsl_min_fminimizer_f_minimum(m);
	}
	gsl_min_fminimizer_free(m);
	return ANVIL_OK;
}
