/* maxscan.h: a scanned maximum, refined.  Where a scan over t found its
 * largest value sv[1] at ts[1], between ts[0] and ts[2], Brent's minimiser
 * (GSL) on -f inside that bracket finds the peak between the scan's
 * points: the plate's bending peak (plate_bending.c) and the near face's
 * sum (verdict_near.c) both do so. */
#ifndef ANVIL_MAXSCAN_H
#define ANVIL_MAXSCAN_H

#include <gsl/gsl_math.h>

/* minus_f: -f.  ts[0] < ts[1] < ts[2] with sv[1] >= sv[0], sv[2] (the
 * values of f).  The interval is closed to 1e-4 relative, in at most 60
 * iterations.  *t and *s are set to the maximiser and its value only when
 * it beats sv[1]; a failing iteration leaves them.  ANVIL_OK, or
 * ANVIL_ENOMEM. */
int anvil_max_refine(gsl_function *minus_f, const double ts[3], const double sv[3], double *t,
		     double *s);

#endif
