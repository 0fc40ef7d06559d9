/* accuracy.c: the one table of accuracy levels (accuracy.h). */
#include <math.h>
#include <stddef.h>
#include <strings.h>

#include "accuracy.h"

static const struct anvil_level levels[ANVIL_ACC_COUNT] = {
	/* name, target,
	 *   cycles omega_min nsteps hs_tol,
	 *   green: c0T tol ktail,
	 *   field: cycles omega_min tw c0t band_w ktail L */
	{ "draft", 1e-2, 60.0, 1.5, 100, 1e-6, 9.0, 1e-5, 1e-8,
	  { 120.0, 1.5, 1.25, 5.0, 10.0, 10.0, 14.0 } },
	{ "normal", 1e-3, 120.0, 2.0, 400, 1e-8, 10.0, 1e-6, 1e-10,
	  { 240.0, 2.0, 1.25, 5.0, 8.0, 15.0, 18.0 } },
	{ "fine", 1e-4, 240.0, 4.0, 1000, 1e-10, 11.0, 1e-7, 1e-12,
	  { 480.0, 4.0, 1.5, 5.0, 6.0, 30.0, 23.0 } },
	{ "reference", 1e-5, 480.0, 8.0, 3000, 1e-12, 12.0, 1e-8, 1e-14,
	  { 960.0, 8.0, 1.5, 5.5, 4.0, 60.0, 28.0 } },
};

const struct anvil_level *anvil_level(enum anvil_accuracy a)
{
	return (unsigned)a < ANVIL_ACC_COUNT ? &levels[a] : NULL;
}

const char *anvil_accuracy_name(enum anvil_accuracy a)
{
	return (unsigned)a < ANVIL_ACC_COUNT ? levels[a].name : "unknown";
}

int anvil_accuracy_parse(const char *name)
{
	for (int i = 0; name && i < ANVIL_ACC_COUNT; i++)
		if (strcasecmp(name, levels[i].name) == 0)
			return i;
	return -1;
}

double anvil_accuracy_target(enum anvil_accuracy a)
{
	return (unsigned)a < ANVIL_ACC_COUNT ? levels[a].target : NAN;
}
