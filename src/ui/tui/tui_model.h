/* tui_model.h: the state of the terminal explorer, without curses.
 *
 * The model holds the scene being explored, the selection, the plot
 * quantity, the results of each model (tagged with the generation of the
 * request that produced them), a small cache of earlier results, and the
 * message of the status line.  Keys arrive as plain ints (ASCII, or the
 * TUI_KEY_* codes below, to which the curses loop maps its own) and come
 * back as an action for the loop to carry out; nothing here draws, blocks
 * or starts a thread, so the tests drive it directly.
 *
 * The life of a change: tui_model_key() changes the scene and returns
 * TUI_ACT_RECOMPUTE; the loop calls tui_model_request(), which opens a new
 * generation, fills the models it finds in the cache and returns the set
 * still to compute; the loop has them computed (from tui_model_scene(), the
 * exact scene `s` saves) and hands each back with tui_model_deliver(),
 * which drops anything from an older generation. */
#ifndef ANVIL_UI_TUI_MODEL_H
#define ANVIL_UI_TUI_MODEL_H

#include <stddef.h>

#include "plan.h"
#include "result.h"
#include "scene.h"
#include "status.h"
#include "verdict.h"

/* Keys beyond ASCII.  Plain characters ('k', 'H', ':' ...) are themselves. */
enum tui_key {
	TUI_KEY_UP = 0x100,
	TUI_KEY_DOWN,
	TUI_KEY_LEFT,
	TUI_KEY_RIGHT,
	TUI_KEY_SLEFT,  /* shift-left: coarse step down */
	TUI_KEY_SRIGHT, /* shift-right: coarse step up */
	TUI_KEY_ENTER,
	TUI_KEY_BACKSPACE,
	TUI_KEY_ESC,
	TUI_KEY_HELP    /* F1 */
};
#define TUI_CTRL(c) ((c) & 0x1f)

/* What the loop must do after a key. */
enum tui_action {
	TUI_ACT_NONE,      /* nothing changed */
	TUI_ACT_REDRAW,    /* the screen changed */
	TUI_ACT_REPAINT,   /* repaint everything from scratch (Ctrl-L) */
	TUI_ACT_RECOMPUTE, /* the scene changed: request and compute */
	TUI_ACT_EXPORT,    /* write the PNG charts */
	TUI_ACT_SAVE,      /* save the scene to tui_model_save_path() */
	TUI_ACT_QUIT
};

/* The rows of the parameter panel, top to bottom. */
enum tui_field {
	TUI_F_THICK_MM,   /* layer thickness in um, mm or m (the unit that fits) */
	TUI_F_THICK_R0,   /* the same thickness in multiples of r0 */
	TUI_F_VELOCITY,
	TUI_F_IMPACTOR,   /* impactor material */
	TUI_F_LAYER,      /* layer material */
	TUI_F_MASS,
	TUI_F_RADIUS,
	TUI_F_SHAPE,      /* impactor.shape: rod or ball */
	TUI_F_ACCURACY,
	TUI_F_SHOW_LAYER, /* which models are computed and shown */
	TUI_F_SHOW_HALFSPACE,
	TUI_F_SHOW_ZENER,
	TUI_F_SHOW_HERTZ,
	TUI_F_COUNT
};

/* What the plot shows: a history, or R_f against lambda* / h (charts). */
enum tui_quantity { TUI_Q_FORCE, TUI_Q_VELOCITY, TUI_Q_DEFLECTION, TUI_Q_RF_LAMBDA,
		    TUI_Q_RF_THICKNESS, TUI_Q_COUNT };

enum tui_screen { TUI_SCREEN_MAIN, TUI_SCREEN_HELP, TUI_SCREEN_PLAN, TUI_SCREEN_NOTES };

enum tui_row_state {
	TUI_ROW_OFF,     /* model not selected */
	TUI_ROW_PENDING, /* being computed; res may still hold older values */
	TUI_ROW_DONE
};

struct tui_row {
	enum tui_row_state state;
	int status;              /* of the last delivery: ANVIL_OK, WTOL, ... */
	int have;                /* res holds values (status >= 0) */
	char msg[ANVIL_ERR_MSG]; /* the solver's message when status != OK */
	struct anvil_result res; /* owned, with its history */
};

/* History samples the TUI asks of each run (part of a result's key). */
#define TUI_NHIST 512

/* What a result depends on: the engine's key (anvil_plan_key: the
 * problem's numbers and options, [effects] included, the model, nhist);
 * ok = 0 for a scene that gives no problem (nothing is cached for it).
 * Compared with memcmp, so built zeroed. */
struct tui_cache_key {
	int ok;
	struct anvil_plan_key plan;
};

#define TUI_CACHE_SIZE 32
struct tui_cache_entry {
	int used;
	unsigned long stamp; /* last use, for eviction */
	struct tui_cache_key key;
	int status;
	char msg[ANVIL_ERR_MSG];
	struct anvil_result res;
};

#define TUI_PATH_MAX 4096
#define TUI_EDIT_MAX 256
#define TUI_DEFAULT_SAVE "anvil-scene.scene"

struct tui_model {
	struct anvil_scene sc;      /* the scene as edited */
	struct anvil_scene req_sc;  /* the scene of generation gen */
	char path[TUI_PATH_MAX];    /* file the scene came from, "" for none */
	int modified;               /* changed since loaded or saved */
	int sel;                    /* enum tui_field */
	enum tui_screen screen;
	enum tui_quantity quantity;
	int editing;                /* the status line is a text field */
	int confirm_quit;           /* q with unsaved changes: y quits */
	char edit_key[64];          /* scene key being edited; "" for ':' */
	char edit_unit[8];          /* the unit of the number the field opened on; "" for text */
	char edit[TUI_EDIT_MAX];
	char edit_orig[TUI_EDIT_MAX]; /* the text the field opened on */
	char msg[ANVIL_ERR_MSG];    /* status-line message, "" for none */
	int msg_error;
	unsigned gen;               /* current request */
	unsigned pending;           /* model bits still to come for gen */
	double progress;            /* of the running job, 0..1 */
	char progress_what[64];
	double run_seconds;         /* solver time spent for gen */
	int run_cached, run_computed; /* rows of gen from cache / computed */
	struct tui_row rows[ANVIL_MODEL_COUNT]; /* by enum anvil_model */
	/* The plan the worker ran generation plan_gen's rows from (the same
	 * object `anvil plan` prints); have_plan 0 until one arrives. */
	int have_plan;
	unsigned plan_gen;
	struct anvil_plan plan;
	/* The verdict at the layer (else half-space) row of generation
	 * verdict_gen, made once that row and the plan are both in (the
	 * plate's bending estimate costs tens of ms: never per redraw). */
	int have_verdict;
	unsigned verdict_gen;
	struct anvil_verdict verdict;
	unsigned long stamp;
	struct tui_cache_entry cache[TUI_CACHE_SIZE];
};

/* The order of the models in the panel, the table and the plot legend. */
extern const enum anvil_model tui_model_order[ANVIL_MODEL_COUNT];
/* "layer", "half-space", "Zener", "Hertz". */
const char *tui_model_title(enum anvil_model m);
/* "P(t)", "v(t)", "w(t)" and the unit the plot shows them in. */
const char *tui_quantity_name(enum tui_quantity q);
const char *tui_quantity_unit(enum tui_quantity q);
/* The help screen, NULL-terminated; the one list of keys. */
extern const char *const tui_help_lines[];

/* Start from a checked scene; path names the file it came from (NULL or
 * "" for none).  tui_model_free releases the results and the cache. */
void tui_model_init(struct tui_model *m, const struct anvil_scene *sc,
		    const char *path);
void tui_model_free(struct tui_model *m);

/* Handle one key (see enum tui_key); the model changes, the action says
 * what else is needed.  Errors (a value that does not parse, a step past
 * a limit) go to the message, never anywhere else. */
enum tui_action tui_model_key(struct tui_model *m, int key);

/* Open a new generation for the current scene: rows of models not selected
 * go off, rows found in the cache are filled, the others go pending.
 * Returns the model bits (1u << enum anvil_model) still to compute. */
unsigned tui_model_request(struct tui_model *m);
/* The scene of the current generation (what to compute and what `s`
 * saves are the same numbers). */
const struct anvil_scene *tui_model_scene(const struct tui_model *m);
/* Hand back the result of model for generation gen; the model takes r
 * (and its history) in any case.  msg may be NULL.  Returns 1 when used, 0
 * when dropped as stale or cancelled. */
int tui_model_deliver(struct tui_model *m, unsigned gen, enum anvil_model model,
		      int status, const char *msg, struct anvil_result *r);
/* The plan of generation gen, as the worker made it and ran its rows from
 * (copied; ignored when stale). */
void tui_model_deliver_plan(struct tui_model *m, unsigned gen, const struct anvil_plan *pl);
/* Progress of the running job of generation gen (ignored when stale). */
void tui_model_progress(struct tui_model *m, unsigned gen, double fraction,
			const char *what);
int tui_model_busy(const struct tui_model *m);

/* The status-line message; error 1 shows it as an error. */
void tui_model_message(struct tui_model *m, int error, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* Where `s` saves: the scene's file, else TUI_DEFAULT_SAVE. */
const char *tui_model_save_path(const struct tui_model *m);
/* After a successful save to path. */
void tui_model_saved(struct tui_model *m, const char *path);

/* The one verdict (verdict.h) of the current generation: the plan's
 * (quasi-static Hertz at the rigid anvil's force, as `anvil plan` prints
 * it) until the layer (else half-space) row is in, then quasi-static Hertz
 * at that row's computed P_max and, on a finite layer, the plate's bending
 * stress under its history (anvil_verdict_bending; qs_ratio set where the
 * plan's contact is long, as `anvil run` gives it: the same words).  The
 * layer's line into layer, the impactor's into imp when it yields or
 * cracks ("" when it does not); n = ANVIL_VERDICT_TEXT_MAX holds any line.
 * Returns -1 with no plan yet for this generation (both ""), 1 when a body
 * yields or cracks, 0 when not (or not judged).  Reads only: the verdict
 * was made when the row or the plan arrived. */
int tui_model_verdict(const struct tui_model *m, char *layer, char *imp, size_t n);

/* The label and the value (with its unit) of a panel row.  A length,
 * mass or velocity is shown in the unit that fits it: its usual one (mm,
 * g, m/s) from a tenth of it, the next smaller (um, mg, mm/s) below,
 * the next larger (m, kg, km/s) from 1 of that; steps and Enter work in
 * the unit shown. */
const char *tui_field_label(enum tui_field f);
void tui_model_field_text(const struct tui_model *m, enum tui_field f,
			  char *buf, size_t n);

/* x as the panel and the text field show it, positional (no exponent
 * for 1e-4 <= |x| < 1e9): exactly when x is a number of at most
 * TUI_DIGITS_EXACT significant digits (what a step or the user typed,
 * to 1e-12 relative: "4.1255"), else TUI_DIGITS significant digits
 * (a value derived from others: 3.2 mm / 19 mm is "0.1684", not
 * "0.168421"); trailing zeros dropped. */
#define TUI_DIGITS 4
#define TUI_DIGITS_EXACT 6
void tui_number(double x, char *buf, size_t n);

/* The next "round" value after x > 0 in direction dir (+1/-1): fine steps
 * are a tenth of the leading decimal digit, coarse steps one leading digit
 * (4 -> 4.1 / 5; 1 -> 0.99 / 0.9).  Up then down returns to x.  Values that
 * are not finite and positive come back unchanged. */
double tui_step(double x, int dir, int coarse);

/* The cache key of model for scene sc, from the engine (anvil_plan_key);
 * returns k->ok. */
int tui_cache_key_make(struct tui_cache_key *k, const struct anvil_scene *sc,
		       enum anvil_model model);

#endif
