/* tui_model.c: the TUI's state, as plain functions (no curses); its keys
 * in tui_keys.c. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "material.h"
#include "tui_model.h"
#include "tui_model_impl.h"

const enum anvil_model tui_model_order[ANVIL_MODEL_COUNT] = {
	ANVIL_MODEL_LAYER, ANVIL_MODEL_HALFSPACE, ANVIL_MODEL_ZENER,
	ANVIL_MODEL_HERTZ};

const char *const tui_help_lines[] = {
	"anvil tui: the impact explorer",
	"",
	"  Up/Down, k/j          select a parameter",
	"  Left/Right, h/l       change it by a fine step (4 -> 4.1)",
	"  Shift-Left/Right, H/L change it by a coarse step (4 -> 5)",
	"  Enter                 type a value with its unit (e.g. 8 mm, 2 r0, inf);",
	"                        a number needs its unit, as in files; Esc cancels",
	"  Space                 switch a model on or off (on a model row)",
	"  :                     set any scene key: KEY=VALUE (e.g. layer.E=200GPa)",
	"  m                     next material of the selected body (clears its",
	"                        E, nu, rho and yield overrides)",
	"  a                     next accuracy level",
	"  b                     impactor shape: rod (hemispherical tip) or ball",
	"  D                     type the impactor's diameter (e.g. 10 mm)",
	"  d                     type a drop height (e.g. 50 mm): V0 = sqrt(2 g H)",
	"  v                     plot P(t), v(t), w(t), R_f(lambda*) or R_f(h)",
	"  p                     export the charts as PNG (gnuplot) into the",
	"                        current directory or $ANVIL_PNG_DIR",
	"  s                     save the scene (to its file, else " TUI_DEFAULT_SAVE ")",
	"  Ctrl-L                repaint the screen",
	"  P                     the plan: how each row is computed, and why",
	"  n                     the notes in full: the verdict, each row's note",
	"                        or refusal (the main screen cuts them with ...)",
	"  ?, F1                 this help",
	"  q                     quit (asks first when the scene has unsaved changes)",
	"  Q                     quit without asking",
	"",
	"Every change recomputes in the background; dimmed values are being",
	"recomputed.  '~' marks a value whose accuracy target was not reached.",
	"",
	"Press any key to return.",
	NULL};

const char *tui_model_title(enum anvil_model m)
{
	static const char *const t[ANVIL_MODEL_COUNT] = {
		[ANVIL_MODEL_HERTZ] = "Hertz",
		[ANVIL_MODEL_ZENER] = "Zener",
		[ANVIL_MODEL_LAYER] = "layer",
		[ANVIL_MODEL_HALFSPACE] = "half-space"};
	return (unsigned)m < ANVIL_MODEL_COUNT ? t[m] : "?";
}

const char *tui_quantity_name(enum tui_quantity q)
{
	static const char *const n[TUI_Q_COUNT] = {"P(t)", "v(t)", "w(t)", "R_f(lambda*)",
						   "R_f(h)"};
	return (unsigned)q < TUI_Q_COUNT ? n[q] : "?";
}

const char *tui_quantity_unit(enum tui_quantity q)
{
	static const char *const u[TUI_Q_COUNT] = {"kN", "m/s", "um", "1", "1"};
	return (unsigned)q < TUI_Q_COUNT ? u[q] : "?";
}

/* ---- panel rows ---- */


/* The row's usual unit (g, mm, m/s) holds down to a tenth of itself
 * (0.5 mm, not 500 um) and gives way to the next larger one from 1 of
 * it (1 kg, not 1000 g: a drop weight read 100000 g).  Powers of 1000
 * apart, so a step's grid (a tenth of the leading digit) is the same in
 * either unit: 990 g -> 1 kg -> 1.1 kg, and back. */
static const struct shown_unit mass_shown[] = {
	{"mg", -6, 0}, {"g", -3, 1e-4}, {"kg", 0, 1}, {NULL, 0, 0}};
const struct shown_unit tui_length_shown[] = {
	{"um", -6, 0}, {"mm", -3, 1e-4}, {"m", 0, 1}, {NULL, 0, 0}};
static const struct shown_unit velocity_shown[] = {
	{"mm/s", -3, 0}, {"m/s", 0, 0.1}, {"km/s", 3, 1e3}, {NULL, 0, 0}};
static const struct shown_unit r0_shown[] = {{"r0", 0, 0}, {NULL, 0, 0}};


const struct numeric tui_numerics[TUI_F_COUNT] = {
	[TUI_F_THICK_MM] = {"layer.thickness", tui_length_shown},
	[TUI_F_THICK_R0] = {"layer.thickness", r0_shown},
	[TUI_F_VELOCITY] = {"impact.velocity", velocity_shown},
	[TUI_F_MASS] = {"impactor.mass", mass_shown},
	[TUI_F_RADIUS] = {"impactor.radius", tui_length_shown},
};

static const char *const labels[TUI_F_COUNT] = {
	[TUI_F_THICK_MM] = "thickness",
	[TUI_F_THICK_R0] = "thickness",
	[TUI_F_VELOCITY] = "velocity",
	[TUI_F_IMPACTOR] = "impactor",
	[TUI_F_LAYER] = "layer",
	[TUI_F_MASS] = "mass",
	[TUI_F_RADIUS] = "radius r0",
	[TUI_F_SHAPE] = "shape",
	[TUI_F_ACCURACY] = "accuracy",
	[TUI_F_SHOW_LAYER] = "models",
	[TUI_F_SHOW_HALFSPACE] = "",
	[TUI_F_SHOW_ZENER] = "",
	[TUI_F_SHOW_HERTZ] = "",
};

const char *tui_field_label(enum tui_field f)
{
	return (unsigned)f < TUI_F_COUNT ? labels[f] : "?";
}

int tui_is_numeric(int f)
{
	return (unsigned)f < TUI_F_COUNT && tui_numerics[f].key != NULL;
}

/* The model a "models" row switches, or -1. */
int tui_field_model(int f)
{
	if (f < TUI_F_SHOW_LAYER || f > TUI_F_SHOW_HERTZ)
		return -1;
	return (int)tui_model_order[f - TUI_F_SHOW_LAYER];
}

/* The value of a numeric row in SI (r0 for the thickness in r0). */
static double field_si(const struct anvil_scene *sc, int f)
{
	switch (f) {
	case TUI_F_THICK_MM:
		return anvil_scene_h(sc);
	case TUI_F_THICK_R0:
		return anvil_scene_h(sc) / sc->radius;
	case TUI_F_VELOCITY:
		return sc->velocity;
	case TUI_F_MASS:
		return sc->mass;
	case TUI_F_RADIUS:
		return sc->radius;
	default:
		return NAN;
	}
}

/* SI -> unit u: by an exact power of ten (0.0122 kg * 1e3 is 12.2 g). */
double tui_in_unit(double si, const struct shown_unit *u)
{
	return u->exp10 < 0 ? si * pow(10, -u->exp10) : si / pow(10, u->exp10);
}

static int has_overrides(const struct anvil_body *b)
{
	return !isnan(b->E) || !isnan(b->nu) || !isnan(b->rho) || !isnan(b->yield);
}

/* x with p significant digits, positional, trailing zeros dropped. */
static void number_digits(double x, int p, char *buf, size_t n)
{
	int dec = p - 1 - (int)floor(log10(fabs(x)));
	snprintf(buf, n, "%.*f", dec > 0 ? dec : 0, x);
	if (dec > 0 && strchr(buf, '.')) {
		size_t k = strlen(buf);
		while (k && buf[k - 1] == '0')
			buf[--k] = '\0';
		if (k && buf[k - 1] == '.')
			buf[--k] = '\0';
	}
}

void tui_number(double x, char *buf, size_t n)
{
	if (!isfinite(x) || x == 0 || fabs(x) < 1e-4 || fabs(x) >= 1e9) {
		snprintf(buf, n, "%.*g", TUI_DIGITS, x);
		return;
	}
	for (int p = 1; p <= TUI_DIGITS_EXACT; ++p) {
		number_digits(x, p, buf, n);
		if (fabs(strtod(buf, NULL) - x) <= 1e-12 * fabs(x))
			return;
	}
	number_digits(x, TUI_DIGITS, buf, n);
}

/* The unit of units that si is shown in: the largest whose `from` it
 * reaches; then the next one up if the number as shown rounds onto that
 * one's start (a derived 999.99999 g reads "1000" to TUI_DIGITS: 1 kg). */
const struct shown_unit *tui_pick_unit(const struct shown_unit *u, double si)
{
	while (u[1].name && fabs(si) >= u[1].from)
		u++;
	if (u[1].name && isfinite(si)) {
		char num[48];
		tui_number(tui_in_unit(si, u), num, sizeof num);
		if (fabs(strtod(num, NULL)) >= tui_in_unit(u[1].from, u) * (1 - 1e-12))
			u++;
	}
	return u;
}

/* The unit row f shows its value in, and the value in it (*x). */
const struct shown_unit *tui_field_shown(const struct anvil_scene *sc, int f, double *x)
{
	double si = field_si(sc, f);
	const struct shown_unit *u = tui_pick_unit(tui_numerics[f].units, si);
	*x = tui_in_unit(si, u);
	return u;
}

void tui_model_field_text(const struct tui_model *m, enum tui_field f,
			  char *buf, size_t n)
{
	const struct anvil_scene *sc = &m->sc;
	int mod = tui_field_model(f);
	if (tui_is_numeric(f)) {
		double v;
		const struct shown_unit *u = tui_field_shown(sc, f, &v);
		char num[48];
		tui_number(v, num, sizeof num);
		if (isinf(v))
			snprintf(buf, n, "inf");
		else
			snprintf(buf, n, "%s %s", num, u->name);
	} else if (f == TUI_F_IMPACTOR || f == TUI_F_LAYER) {
		const struct anvil_body *b = f == TUI_F_IMPACTOR ? &sc->impactor : &sc->layer;
		/* '*': the named material's numbers are not the ones used */
		snprintf(buf, n, "%s%s", b->material, has_overrides(b) ? "*" : "");
	} else if (f == TUI_F_ACCURACY) {
		snprintf(buf, n, "%s", anvil_accuracy_name(sc->accuracy));
	} else if (f == TUI_F_SHAPE) {
		snprintf(buf, n, "%s", anvil_shape_name(sc->shape));
	} else if (mod >= 0) {
		snprintf(buf, n, "[%c] %s", sc->models & (1u << mod) ? 'x' : ' ',
			 tui_model_title((enum anvil_model)mod));
	} else if (n) {
		buf[0] = '\0';
	}
}

int tui_model_verdict(const struct tui_model *m, char *layer, char *imp, size_t n)
{
	if (n) {
		layer[0] = '\0';
		imp[0] = '\0';
	}
	if (!m->have_plan || m->plan_gen != m->gen)
		return -1;
	const struct anvil_verdict *v = m->have_verdict && m->verdict_gen == m->gen
						? &m->verdict : &m->plan.verdict;
	anvil_verdict_text_screen(v, layer, n);
	if (v->imp.fate != ANVIL_HERTZ_ELASTIC)
		anvil_verdict_impactor_text_screen(v, imp, n);
	return anvil_verdict_fails(v);
}

/* The verdict once the plan and the layer (else half-space) row of the
 * current generation are both in: quasi-static Hertz at the row's own
 * computed peak force (on a thin plate a fraction of the rigid anvil's
 * the plan judges), and on a finite layer the plate's bending stress
 * under the row's history, as `anvil run` judges a quasi-static one
 * (yield.c): the fate takes the larger stress.  Where none of verdict.h's
 * quasi-static rules holds (a plate whose bending matters, a fast impact),
 * `anvil run` searches the transform field instead (seconds: not for a
 * knob). */
static void verdict_update(struct tui_model *m)
{
	const struct anvil_problem *pb = &m->plan.pb;
	int finite = isfinite(pb->p.h);
	const struct tui_row *r = &m->rows[anvil_verdict_model(&m->plan)];
	if (!m->have_plan || m->plan_gen != m->gen || r->state != TUI_ROW_DONE || !r->have ||
	    (m->have_verdict && m->verdict_gen == m->gen))
		return;
	struct anvil_verdict v;
	if (anvil_verdict_at(pb, r->res.Pmax.val, r->res.tmax.val, &v) != ANVIL_OK)
		return; /* the plan's verdict stays */
	/* as anvil run: the plan decides, the row's t_s says */
	anvil_verdict_qs_mark(&m->plan, anvil_verdict_quasi_static(&m->plan), &r->res, &v);
	if (finite)
		anvil_verdict_bending(pb, &r->res.hist, &v);
	m->verdict = v;
	m->verdict_gen = m->gen;
	m->have_verdict = 1;
}

/* ---- messages ---- */

void tui_model_message(struct tui_model *m, int error, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(m->msg, sizeof m->msg, fmt, ap);
	va_end(ap);
	m->msg_error = error;
}

const char *tui_model_save_path(const struct tui_model *m)
{
	return m->path[0] ? m->path : TUI_DEFAULT_SAVE;
}

void tui_model_saved(struct tui_model *m, const char *path)
{
	if (path != m->path)
		snprintf(m->path, sizeof m->path, "%s", path);
	m->modified = 0;
	tui_model_message(m, 0, "saved to %s", path);
}

/* ---- results and the cache ---- */

/* A deep copy of src's history into dst (whose history is dropped).
 * Without memory the copy keeps the numbers and loses the history: the
 * table is still right, only the plot misses a curve. */
static void result_copy(struct anvil_result *dst, const struct anvil_result *src)
{
	anvil_result_free(dst);
	*dst = *src;
	memset(&dst->hist, 0, sizeof dst->hist);
	size_t n = src->hist.n;
	if (n && anvil_history_alloc(&dst->hist, n) == ANVIL_OK)
		memcpy(dst->hist.t, src->hist.t, 6 * n * sizeof(double));
}

int tui_cache_key_make(struct tui_cache_key *k, const struct anvil_scene *sc,
		       enum anvil_model model)
{
	struct anvil_problem pb;
	memset(k, 0, sizeof *k); /* padding too: keys are compared with memcmp */
	if (anvil_problem_init(&pb, sc, NULL))
		return 0;
	anvil_plan_key(&pb, model, TUI_NHIST, &k->plan);
	return k->ok = 1;
}

static struct tui_cache_entry *cache_find(struct tui_model *m,
					  const struct tui_cache_key *k)
{
	for (int i = 0; i < TUI_CACHE_SIZE; ++i) {
		struct tui_cache_entry *e = &m->cache[i];
		if (k->ok && e->used && memcmp(&e->key, k, sizeof *k) == 0) {
			e->stamp = ++m->stamp;
			return e;
		}
	}
	return NULL;
}

static void cache_put(struct tui_model *m, const struct tui_cache_key *k,
		      const struct tui_row *row)
{
	struct tui_cache_entry *e = cache_find(m, k);
	for (int i = 0; !e && i < TUI_CACHE_SIZE; ++i)
		if (!m->cache[i].used)
			e = &m->cache[i];
	for (int i = 0; !e && i < TUI_CACHE_SIZE; ++i) /* evict the least recent */
		if (i == 0 || m->cache[i].stamp < e->stamp)
			e = &m->cache[i];
	e->used = 1;
	e->stamp = ++m->stamp;
	e->key = *k;
	e->status = row->status;
	snprintf(e->msg, sizeof e->msg, "%s", row->msg);
	result_copy(&e->res, &row->res);
}

/* Only answers that the same scene would give again are worth keeping. */
static int cacheable(int status)
{
	return status >= 0 || status == ANVIL_EINVAL;
}

static void row_fill(struct tui_row *row, int status, const char *msg)
{
	row->state = TUI_ROW_DONE;
	row->status = status;
	row->have = status >= 0; /* a warning (ANVIL_WTOL) keeps its values */
	snprintf(row->msg, sizeof row->msg, "%s", msg ? msg : "");
}

unsigned tui_model_request(struct tui_model *m)
{
	m->gen++;
	m->req_sc = m->sc;
	m->pending = 0;
	m->progress = 0;
	m->progress_what[0] = '\0';
	m->run_seconds = 0;
	m->run_cached = m->run_computed = 0;
	for (int k = 0; k < ANVIL_MODEL_COUNT; ++k) {
		struct tui_row *row = &m->rows[k];
		struct tui_cache_key key;
		struct tui_cache_entry *e;
		if (!(m->sc.models & (1u << k))) {
			row->state = TUI_ROW_OFF;
			continue;
		}
		tui_cache_key_make(&key, &m->sc, (enum anvil_model)k);
		e = cache_find(m, &key);
		if (e) {
			result_copy(&row->res, &e->res);
			row_fill(row, e->status, e->msg);
			m->run_cached++;
		} else {
			/* keep the old values on screen, dimmed, until the new come */
			row->state = TUI_ROW_PENDING;
			m->pending |= 1u << k;
		}
	}
	return m->pending;
}

const struct anvil_scene *tui_model_scene(const struct tui_model *m)
{
	return &m->req_sc;
}

int tui_model_deliver(struct tui_model *m, unsigned gen, enum anvil_model model,
		      int status, const char *msg, struct anvil_result *r)
{
	unsigned bit = 1u << model;
	if ((unsigned)model >= ANVIL_MODEL_COUNT || gen != m->gen ||
	    !(m->pending & bit) || status == ANVIL_ECANCEL) {
		anvil_result_free(r);
		return 0;
	}
	struct tui_row *row = &m->rows[model];
	anvil_result_free(&row->res);
	row->res = *r; /* the model now owns the history */
	memset(&r->hist, 0, sizeof r->hist);
	row_fill(row, status, msg);
	m->pending &= ~bit;
	verdict_update(m);
	m->run_seconds += row->res.seconds;
	m->run_computed++;
	if (cacheable(status)) {
		struct tui_cache_key key;
		if (tui_cache_key_make(&key, &m->req_sc, model))
			cache_put(m, &key, row);
	}
	return 1;
}

void tui_model_deliver_plan(struct tui_model *m, unsigned gen, const struct anvil_plan *pl)
{
	if (gen != m->gen)
		return;
	m->plan = *pl;
	m->plan_gen = gen;
	m->have_plan = 1;
	verdict_update(m); /* its row may have come from the cache before it */
}

void tui_model_progress(struct tui_model *m, unsigned gen, double fraction,
			const char *what)
{
	if (gen != m->gen)
		return;
	m->progress = fraction;
	snprintf(m->progress_what, sizeof m->progress_what, "%s", what ? what : "");
}

int tui_model_busy(const struct tui_model *m)
{
	return m->pending != 0;
}

/* ---- life ---- */

void tui_model_init(struct tui_model *m, const struct anvil_scene *sc,
		    const char *path)
{
	memset(m, 0, sizeof *m);
	m->sc = *sc;
	m->req_sc = *sc;
	snprintf(m->path, sizeof m->path, "%s", path ? path : "");
	for (int k = 0; k < ANVIL_MODEL_COUNT; ++k)
		anvil_result_init(&m->rows[k].res, (enum anvil_model)k);
}

void tui_model_free(struct tui_model *m)
{
	for (int k = 0; k < ANVIL_MODEL_COUNT; ++k)
		anvil_result_free(&m->rows[k].res);
	for (int i = 0; i < TUI_CACHE_SIZE; ++i)
		anvil_result_free(&m->cache[i].res);
}
