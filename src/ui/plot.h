/* plot.h: charts through gnuplot (outside the core).
 * The chart module writes gnuplot scripts, with the data inline, to any
 * FILE *; a pipe to a gnuplot process is one sink among others, so scripts
 * can be tested as text.  (The plot engineer extends this header.) */
#ifndef ANVIL_UI_PLOT_H
#define ANVIL_UI_PLOT_H

#include <stddef.h>

#include "core/result.h"
#include "core/scene.h"

/* Write the charts of one run (histories of every model in res that has
 * them: force, velocity, deflection) into directory dir as PNG files.
 * The paths written are listed, one per line, into paths (may be NULL).
 * Returns 0, or 1 after printing a one-line error naming gnuplot. */
int plot_run_charts(const char *dir, const struct anvil_scene *sc,
		    const struct anvil_result *res, int nres, char *paths,
		    size_t paths_len);

#endif
