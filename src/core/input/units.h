/* units.h: physical quantities with units, parsed and printed at the edges.
 *
 * Inside anvil everything is SI.  Text like "12.2 g", "4mm", "200 GPa",
 * "7.8 g/cm3", "10 m/s", "0.16 us" is turned into SI here, and nowhere else. */
#ifndef ANVIL_UNITS_H
#define ANVIL_UNITS_H

#include <stddef.h>

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

/* As anvil_units_parse, but a dimensional quantity must carry its unit:
 * a bare number is ANVIL_EPARSE with "'4' needs a unit, e.g. 4 mm
 * (lengths: m, cm, mm, um)".  Dimensionless numbers (ANVIL_DIM_NONE) stay
 * bare.  This is the rule of scene files, -s KEY=VALUE and the TUI. */
int anvil_units_parse_with_unit(const char *text, enum anvil_dim dim, double *si,
				struct anvil_err *err);

/* si (in the SI unit of dim) as "50 g", "4 mm", "10 m/s": three significant
 * digits in the listed unit that puts the number in [1, 1000) where there
 * is one (else the nearest).  For titles and messages, not for reading
 * back exactly (anvil_scene_write prints SI with all digits). */
void anvil_units_format(double si, enum anvil_dim dim, char *buf, size_t n);

/* The name of a dimension's SI unit, e.g. "kg", "m/s". */
const char *anvil_units_si_name(enum anvil_dim dim);

#endif
