/* tui_model_impl.h: what tui_model.c (the state) and tui_keys.c (the
 * keys) share of the numeric rows; not for the rest of the TUI. */
#ifndef ANVIL_TUI_MODEL_IMPL_H
#define ANVIL_TUI_MODEL_IMPL_H

#include "tui_model.h"

/* A unit a numeric row may be shown in: SI per unit is 10^exp10, and it
 * is shown from `from` (SI) up, until the next unit's `from`. */
struct shown_unit {
	const char *name;
	int exp10;
	double from;
};

/* A numeric row: the scene key it sets, the units it is shown and
 * stepped in.  Steps happen in the shown unit so that the values stay
 * round. */
struct numeric {
	const char *key;
	const struct shown_unit *units;
};

extern const struct numeric tui_numerics[TUI_F_COUNT];
extern const struct shown_unit tui_length_shown[];

int tui_is_numeric(int f);
/* The model a "models" row switches, or -1. */
int tui_field_model(int f);
/* SI -> unit u: by an exact power of ten (0.0122 kg * 1e3 is 12.2 g). */
double tui_in_unit(double si, const struct shown_unit *u);
/* The unit of units that si is shown in (tui_model.c). */
const struct shown_unit *tui_pick_unit(const struct shown_unit *u, double si);
/* The unit row f shows its value in, and the value in it (*x). */
const struct shown_unit *tui_field_shown(const struct anvil_scene *sc, int f, double *x);

#endif
