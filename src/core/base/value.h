/* value.h: a number and its estimated error, travelling together
 * (as GSL's gsl_sf_result {val, err}). */
#ifndef ANVIL_VALUE_H
#define ANVIL_VALUE_H

struct anvil_val {
	double val; /* the value */
	double err; /* its estimated absolute error; NaN when not estimated */
};

#endif
