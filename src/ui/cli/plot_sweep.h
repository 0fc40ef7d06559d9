/* plot_sweep.h: the charts made from sweeps (`anvil plot
 * restitution-velocity`, `anvil plot restitution-map FILE`). */
#ifndef ANVIL_UI_PLOT_SWEEP_H
#define ANVIL_UI_PLOT_SWEEP_H

#include "plot.h"
#include "scene.h"

/* Run the velocity sweep of sc (V0 from 1 to 100 m/s, PLOT_SWEEP_NV
 * log-spaced; the thicknesses 1, 2, 5, 10 r0, or sc's own when fixed_h)
 * on every core and build the chart.  Returns an exit code; messages
 * printed. */
int plot_sweep_rf_velocity(struct plot_chart *c, const struct anvil_scene *sc, int fixed_h);

/* `anvil plot restitution-map FILE`: read the sweep's rows (TSV, CSV or
 * JSON by the extension), the layer model's R_f on the V0 x h grid, and
 * draw it to path/script.  Returns an exit code; messages printed. */
int plot_sweep_rf_map(const char *file, const struct plot_opts *o, const char *path,
		      const char *script);

#endif
