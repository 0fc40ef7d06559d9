/* tui_draw.h: the TUI's screens on curses; drawing only reads the model.
 *
 * A screen is an init / draw / key triple: init is tui_draw_init (colours,
 * once), draw is tui_draw (by m->screen), key is tui_model_key. */
#ifndef ANVIL_UI_TUI_DRAW_H
#define ANVIL_UI_TUI_DRAW_H

#include "tui_model.h"

#define TUI_MIN_COLS 80
#define TUI_MIN_ROWS 24

struct tui_view {
	int color; /* colour pairs may be used (has_colors, no NO_COLOR) */
	int utf8;  /* the locale is UTF-8: braille plot, a few symbols */
};

/* After the screen is set up: the colour pairs when want_color and the
 * terminal has colours.  Fills v. */
void tui_draw_init(struct tui_view *v, int want_color, int utf8);

/* Draw the whole screen for m (erase, draw, refresh).  Below
 * TUI_MIN_COLS x TUI_MIN_ROWS only a centred message. */
void tui_draw(const struct tui_model *m, const struct tui_view *v);

#endif
