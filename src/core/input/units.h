/* units.h: physical quantities with units, parsed and printed at the edges.
 *
 * Inside anvil everything is SI.  Text like "12.2 g", "4mm", "200 GPa",
 * "7.8 g/cm3", "10 m/s", "0.16 us" is turned into SI here, and nowhere else. */
#ifndef ANVIL_UNITS_H
#define ANVIL_UNITS_H

#include "status.h"

enum anvil_dim {
	ANVIL_DIM_NONE,     /* dimensionless number */
	ANVIL_DIM_MASS,     /* kg:  kg g mg */
	ANVIL_DIM_LENGTH,   /* m:   m cm mm um */
	ANVIL_DIM_VELOCITY, /* m/s: m/s km/s mm/us km/h */
	ANVIL_DIM_PRESSURE, /* Pa:  Pa kPa MPa GPa */
	ANVIL_DIM_DENSITY,  /* kg/m^3: kg/m3 kg/m^3 g/cm3 g/cm^3 */
	ANVIL_DIM_TIME      /* s:   s ms us ns */
};

/* Parse "NUMBER [UNIT]" of dimension dim into SI.  A bare number is taken as
 * SI.  Returns ANVIL_EPARSE with a message saying what was expected (e.g.
 * "expected a length such as '4 mm'") for anything else, including NaN,
 * infinity and trailing text. */
int anvil_units_parse(const char *text, enum anvil_dim dim, double *si,
		      struct anvil_err *err);

/* The name of a dimension's SI unit, e.g. "kg", "m/s". */
const char *anvil_units_si_name(enum anvil_dim dim);

#endif
