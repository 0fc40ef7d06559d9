/* plot_sweep.h: the charts made from sweeps (`anvil plot
 * restitution-velocity`, `anvil plot restitution-map FILE`). */
#ifndef ANVIL_UI_PLOT_SWEEP_H
#define ANVIL_UI_PLOT_SWEEP_H

#include "plot.h"
#include "scene.h"

/* Run the velocity sweep of sc (velocities: a sweep spec such as
 * "1..100m/s:13:log", the default when NULL) on every core and build the
 * chart: a curve per thickness (1, 2, 5, 10 r0, or sc's own when fixed_h),
 * or with materials ("copper/steel,steel,glass": IMPACTOR/LAYER or LAYER,
 * at most PLOT_MAX_GROUPS) a curve per material pair at sc's thickness.
 * The footnote names the contact model.  Returns an exit code (2 for a
 * bad list); messages printed. */
int plot_sweep_rf_velocity(struct plot_chart *c, const struct anvil_scene *sc, int fixed_h,
			   const char *materials, const char *velocities);

/* `anvil plot restitution-map FILE`: read the sweep's rows (TSV, CSV or
 * JSON by the extension), the layer model's R_f on the V0 x h grid, and
 * draw it to path/script.  Returns an exit code; messages printed. */
int plot_sweep_rf_map(const char *file, const struct plot_opts *o, const char *path,
		      const char *script);

#endif
