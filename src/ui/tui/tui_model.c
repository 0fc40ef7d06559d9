/* tui_model.c: the TUI's state and keys, as plain functions (no curses). */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "material.h"
#include "tui_model.h"

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

/* A unit a numeric row may be shown in: SI per unit is 10^exp10, and it
 * is shown from `from` (SI) up, until the next unit's `from`. */
struct shown_unit {
	const char *name;
	int exp10;
	double from;
};

/* The row's usual unit (g, mm, m/s) holds down to a tenth of itself
 * (0.5 mm, not 500 um) and gives way to the next larger one from 1 of
 * it (1 kg, not 1000 g: a drop weight read 100000 g).  Powers of 1000
 * apart, so a step's grid (a tenth of the leading digit) is the same in
 * either unit: 990 g -> 1 kg -> 1.1 kg, and back. */
static const struct shown_unit mass_shown[] = {
	{"mg", -6, 0}, {"g", -3, 1e-4}, {"kg", 0, 1}, {NULL, 0, 0}};
static const struct shown_unit length_shown[] = {
	{"um", -6, 0}, {"mm", -3, 1e-4}, {"m", 0, 1}, {NULL, 0, 0}};
static const struct shown_unit velocity_shown[] = {
	{"mm/s", -3, 0}, {"m/s", 0, 0.1}, {"km/s", 3, 1e3}, {NULL, 0, 0}};
static const struct shown_unit r0_shown[] = {{"r0", 0, 0}, {NULL, 0, 0}};

/* A numeric row: the scene key it sets, the units it is shown and
 * stepped in.  Steps happen in the shown unit so that the values stay
 * round. */
struct numeric {
	const char *key;
	const struct shown_unit *units;
};

static const struct numeric numerics[TUI_F_COUNT] = {
	[TUI_F_THICK_MM] = {"layer.thickness", length_shown},
	[TUI_F_THICK_R0] = {"layer.thickness", r0_shown},
	[TUI_F_VELOCITY] = {"impact.velocity", velocity_shown},
	[TUI_F_MASS] = {"impactor.mass", mass_shown},
	[TUI_F_RADIUS] = {"impactor.radius", length_shown},
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

static int is_numeric(int f)
{
	return (unsigned)f < TUI_F_COUNT && numerics[f].key != NULL;
}

/* The model a "models" row switches, or -1. */
static int field_model(int f)
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
static double in_unit(double si, const struct shown_unit *u)
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
static const struct shown_unit *pick_unit(const struct shown_unit *u, double si)
{
	while (u[1].name && fabs(si) >= u[1].from)
		u++;
	if (u[1].name && isfinite(si)) {
		char num[48];
		tui_number(in_unit(si, u), num, sizeof num);
		if (fabs(strtod(num, NULL)) >= in_unit(u[1].from, u) * (1 - 1e-12))
			u++;
	}
	return u;
}

/* The unit row f shows its value in, and the value in it (*x). */
static const struct shown_unit *field_shown(const struct anvil_scene *sc, int f, double *x)
{
	double si = field_si(sc, f);
	const struct shown_unit *u = pick_unit(numerics[f].units, si);
	*x = in_unit(si, u);
	return u;
}

void tui_model_field_text(const struct tui_model *m, enum tui_field f,
			  char *buf, size_t n)
{
	const struct anvil_scene *sc = &m->sc;
	int mod = field_model(f);
	if (is_numeric(f)) {
		double v;
		const struct shown_unit *u = field_shown(sc, f, &v);
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
	anvil_verdict_text(v, layer, n);
	if (v->imp.fate != ANVIL_HERTZ_ELASTIC)
		anvil_verdict_impactor_text(v, imp, n);
	return anvil_verdict_fails(v);
}

/* The verdict once the plan and the layer (else half-space) row of the
 * current generation are both in: quasi-static Hertz at the row's own
 * computed peak force (on a thin plate a fraction of the rigid anvil's
 * the plan judges), and on a finite layer the plate's bending stress
 * under the row's history, as `anvil run` judges a long contact
 * (yield.c): the fate takes the larger stress.  A short contact's `anvil
 * run` searches the transform field instead (seconds: not for a knob). */
static void verdict_update(struct tui_model *m)
{
	const struct anvil_problem *pb = &m->plan.pb;
	int finite = isfinite(pb->p.h);
	const struct tui_row *r = &m->rows[finite ? ANVIL_MODEL_LAYER : ANVIL_MODEL_HALFSPACE];
	if (!m->have_plan || m->plan_gen != m->gen || r->state != TUI_ROW_DONE || !r->have ||
	    (m->have_verdict && m->verdict_gen == m->gen))
		return;
	struct anvil_verdict v;
	if (anvil_verdict_at(pb, r->res.Pmax.val, r->res.tmax.val, &v) != ANVIL_OK)
		return; /* the plan's verdict stays */
	if (finite) {
		double ratio = m->plan.row[ANVIL_MODEL_LAYER].job.ts / m->plan.fig[ANVIL_FIG_T_REFLECT];
		if (ratio > ANVIL_VERDICT_QS_RATIO)
			v.qs_ratio = ratio;
		anvil_verdict_bending(pb, &r->res.hist, &v);
	}
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

/* ---- changing the scene ---- */

/* Set key to value through the scene parser, as a scene file would; on an
 * error the scene is left as it was and the message says why. */
static enum tui_action apply(struct tui_model *m, const char *key,
			     const char *value)
{
	struct anvil_scene old = m->sc;
	struct anvil_err err = {0};
	int st = anvil_scene_set(&m->sc, key, value, "tui", 0, &err);
	if (!st)
		st = anvil_scene_check(&m->sc, &err);
	if (st) {
		m->sc = old;
		tui_model_message(m, 1, "%s", err.msg[0] ? err.msg : anvil_strerror(st));
		return TUI_ACT_REDRAW;
	}
	m->modified = 1;
	m->msg[0] = '\0';
	return TUI_ACT_RECOMPUTE;
}

double tui_step(double x, int dir, int coarse)
{
	if (!(x > 0) || !isfinite(x) || dir == 0)
		return x;
	/* Going down, the step comes from the decade just below x, so that
	 * 1 -> 0.99 and 0.99 -> 1 retrace each other. */
	double probe = dir < 0 ? x * (1 - 1e-9) : x;
	int d = (int)floor(log10(probe)) - (coarse ? 0 : 1);
	/* n / 10^k rather than n * 10^-k: 41 / 10 is the double nearest 4.1 */
	double unit = pow(10, abs(d));
	double q = d >= 0 ? x / unit : x * unit;
	double n = dir > 0 ? floor(q + 1e-6) + 1 : ceil(q - 1e-6) - 1;
	double y = d >= 0 ? n * unit : n / unit;
	return y > 0 ? y : x;
}

/* x as the shortest decimal that reads back as x: a step's 0.099 g goes
 * to the parser as "0.099 g", the double nearest 9.9e-5 kg that "99 mg"
 * gives too ("%.17g" would pass 0.099000000000000005). */
static void shortest(double x, char *buf, size_t n)
{
	for (int p = 1; p <= 17; ++p) {
		snprintf(buf, n, "%.*g", p, x);
		if (strtod(buf, NULL) == x)
			return;
	}
}

static enum tui_action step_number(struct tui_model *m, int dir, int coarse)
{
	char num[40], value[64];
	double x;
	const struct shown_unit *u = field_shown(&m->sc, m->sel, &x);
	if (isinf(x)) {
		tui_model_message(m, 1, "the layer is a half-space (inf): press Enter to type a thickness");
		return TUI_ACT_REDRAW;
	}
	/* in the unit shown, which the new value may leave (990 g -> 1 kg) */
	shortest(tui_step(x, dir, coarse), num, sizeof num);
	/* "2.5r0" without a space: the thickness key reads the r0 suffix */
	snprintf(value, sizeof value, "%s%s%s", num, m->sel == TUI_F_THICK_R0 ? "" : " ", u->name);
	return apply(m, numerics[m->sel].key, value);
}

/* Material names in cycling order: the built-in table, then the scene's
 * own [material NAME] sections. */
static int material_count(const struct anvil_scene *sc)
{
	return anvil_material_count() + sc->ncustom;
}

static const char *material_name(const struct anvil_scene *sc, int i)
{
	int nb = anvil_material_count();
	return i < nb ? anvil_material_at(i)->name : sc->custom[i - nb].name;
}

static enum tui_action set_material(struct tui_model *m, int impactor,
				    const char *name)
{
	struct anvil_scene old = m->sc;
	struct anvil_body *b = impactor ? &m->sc.impactor : &m->sc.layer;
	/* A new material means its own numbers: overrides belonged to the old. */
	b->E = b->nu = b->rho = b->yield = NAN;
	enum tui_action a = apply(m, impactor ? "impactor.material" : "layer.material", name);
	if (a != TUI_ACT_RECOMPUTE)
		m->sc = old; /* the overrides too */
	return a;
}

static enum tui_action cycle_material(struct tui_model *m, int impactor, int dir)
{
	const struct anvil_body *b = impactor ? &m->sc.impactor : &m->sc.layer;
	int n = material_count(&m->sc), cur = -1;
	for (int i = 0; i < n && cur < 0; ++i)
		if (strcasecmp(material_name(&m->sc, i), b->material) == 0)
			cur = i;
	int next = cur < 0 ? 0 : ((cur + dir) % n + n) % n;
	return set_material(m, impactor, material_name(&m->sc, next));
}

/* The body a row belongs to: 1 impactor, 0 layer, -1 neither. */
static int field_body(int f)
{
	switch (f) {
	case TUI_F_VELOCITY:
	case TUI_F_IMPACTOR:
	case TUI_F_MASS:
	case TUI_F_RADIUS:
	case TUI_F_SHAPE:
		return 1;
	case TUI_F_THICK_MM:
	case TUI_F_THICK_R0:
	case TUI_F_LAYER:
		return 0;
	default:
		return -1;
	}
}

static enum tui_action cycle_accuracy(struct tui_model *m, int dir)
{
	int a = (((int)m->sc.accuracy + dir) % ANVIL_ACC_COUNT + ANVIL_ACC_COUNT) %
		ANVIL_ACC_COUNT;
	return apply(m, "solver.accuracy", anvil_accuracy_name((enum anvil_accuracy)a));
}

static enum tui_action cycle_shape(struct tui_model *m, int dir)
{
	int s = (((int)m->sc.shape + dir) % ANVIL_SHAPE_COUNT + ANVIL_SHAPE_COUNT) %
		ANVIL_SHAPE_COUNT;
	return apply(m, "impactor.shape", anvil_shape_name((enum anvil_shape)s));
}

static enum tui_action toggle_model(struct tui_model *m, int model)
{
	unsigned bit = 1u << model;
	if (m->sc.models == bit) {
		tui_model_message(m, 1, "at least one model must be on");
		return TUI_ACT_REDRAW;
	}
	m->sc.models ^= bit;
	m->modified = 1;
	m->msg[0] = '\0';
	return TUI_ACT_RECOMPUTE;
}

/* Left/right on the selected row. */
static enum tui_action change(struct tui_model *m, int dir, int coarse)
{
	int f = m->sel;
	if (is_numeric(f))
		return step_number(m, dir, coarse);
	if (f == TUI_F_IMPACTOR || f == TUI_F_LAYER)
		return cycle_material(m, f == TUI_F_IMPACTOR, dir);
	if (f == TUI_F_ACCURACY)
		return cycle_accuracy(m, dir);
	if (f == TUI_F_SHAPE)
		return cycle_shape(m, dir);
	if (field_model(f) >= 0)
		return toggle_model(m, field_model(f));
	return TUI_ACT_NONE;
}

/* ---- the text field ---- */

static void edit_begin(struct tui_model *m, const char *key, const char *unit,
		       const char *text)
{
	m->editing = 1;
	snprintf(m->edit_key, sizeof m->edit_key, "%s", key);
	snprintf(m->edit_unit, sizeof m->edit_unit, "%s", unit ? unit : "");
	snprintf(m->edit, sizeof m->edit, "%s", text);
	snprintf(m->edit_orig, sizeof m->edit_orig, "%s", text);
	m->msg[0] = '\0';
}

static enum tui_action edit_field(struct tui_model *m)
{
	static const char *const keys[TUI_F_COUNT] = {
		[TUI_F_IMPACTOR] = "impactor.material",
		[TUI_F_LAYER] = "layer.material",
		[TUI_F_ACCURACY] = "solver.accuracy",
		[TUI_F_SHAPE] = "impactor.shape"};
	char text[TUI_EDIT_MAX];
	int f = m->sel;
	if (field_model(f) >= 0)
		return toggle_model(m, field_model(f));
	tui_model_field_text(m, f, text, sizeof text);
	if (f == TUI_F_IMPACTOR || f == TUI_F_LAYER) /* drop the override mark */
		text[strcspn(text, "*")] = '\0';
	if (is_numeric(f)) { /* the text as shown, with its unit ("1.5 kg") */
		double x;
		edit_begin(m, numerics[f].key, field_shown(&m->sc, f, &x)->name, text);
	} else {
		edit_begin(m, keys[f], NULL, text);
	}
	return TUI_ACT_REDRAW;
}

static void trim(char *s)
{
	size_t n = strlen(s), i = 0;
	while (n && isspace((unsigned char)s[n - 1]))
		s[--n] = '\0';
	while (isspace((unsigned char)s[i]))
		i++;
	memmove(s, s + i, n - i + 1);
}

/* ':' KEY=VALUE */
static enum tui_action commit_any(struct tui_model *m, char *text)
{
	char *eq = strchr(text, '=');
	if (!eq) {
		tui_model_message(m, 1, "expected KEY=VALUE, e.g. layer.E=200GPa");
		return TUI_ACT_REDRAW;
	}
	*eq = '\0';
	trim(text);
	trim(eq + 1);
	return apply(m, text, eq + 1);
}

static enum tui_action edit_commit(struct tui_model *m)
{
	char v[TUI_EDIT_MAX + 8];
	enum tui_action a;
	snprintf(v, sizeof v, "%s", m->edit);
	trim(v);
	if (m->edit_unit[0] && strcmp(m->edit, m->edit_orig) == 0) {
		/* a number opened and left as shown (to TUI_DIGITS when derived,
		 * 3.2 mm / 19 mm as 0.1684 r0): the exact value stays */
		m->editing = 0;
		return TUI_ACT_REDRAW;
	}
	if (!m->edit_key[0])
		a = commit_any(m, v);
	else if (strcmp(m->edit_key, "impactor.material") == 0 ||
		 strcmp(m->edit_key, "layer.material") == 0)
		a = set_material(m, m->edit_key[0] == 'i', v);
	else /* the line starts with the unit; a bare number is refused as in files */
		a = apply(m, m->edit_key, v);
	/* on an error the field stays open, with the message, to be fixed */
	if (a == TUI_ACT_RECOMPUTE)
		m->editing = 0;
	return a == TUI_ACT_RECOMPUTE ? a : TUI_ACT_REDRAW;
}

static void edit_backspace(char *s)
{
	size_t n = strlen(s);
	/* a whole UTF-8 character: continuation bytes are 10xxxxxx */
	while (n && ((unsigned char)s[n - 1] & 0xC0) == 0x80)
		n--;
	if (n)
		n--;
	s[n] = '\0';
}

static enum tui_action edit_key(struct tui_model *m, int key)
{
	size_t n = strlen(m->edit);
	switch (key) {
	case TUI_KEY_ENTER:
	case '\n':
	case '\r':
		return edit_commit(m);
	case TUI_KEY_ESC:
	case 27:
		m->editing = 0;
		m->msg[0] = '\0';
		return TUI_ACT_REDRAW;
	case TUI_KEY_BACKSPACE:
	case 127:
	case TUI_CTRL('h'):
		edit_backspace(m->edit);
		return TUI_ACT_REDRAW;
	case TUI_CTRL('u'):
		m->edit[0] = '\0';
		return TUI_ACT_REDRAW;
	}
	/* printable ASCII, and the bytes of UTF-8 text ("µs") */
	if (((key >= 0x20 && key < 0x7f) || (key >= 0x80 && key < 0x100)) &&
	    n + 1 < sizeof m->edit) {
		m->edit[n] = (char)key;
		m->edit[n + 1] = '\0';
		return TUI_ACT_REDRAW;
	}
	return TUI_ACT_NONE;
}

/* ---- the screens' keys ---- */

static enum tui_action select_row(struct tui_model *m, int dir)
{
	m->sel = ((m->sel + dir) % TUI_F_COUNT + TUI_F_COUNT) % TUI_F_COUNT;
	return TUI_ACT_REDRAW;
}

static enum tui_action material_key(struct tui_model *m)
{
	int body = field_body(m->sel);
	if (body < 0) {
		tui_model_message(m, 1, "m: select a row of the impactor or the layer first");
		return TUI_ACT_REDRAW;
	}
	return cycle_material(m, body, +1);
}

/* D, d: the diameter and the drop height, typed with their unit through
 * the text field (the scene replaces the radius, the velocity); the field
 * opens on the values in use (the drop height V0^2 / 2g of the velocity). */
static enum tui_action geometry_edit(struct tui_model *m, int drop)
{
	char text[64], num[48];
	double g = ANVIL_G_STANDARD;
	double x = drop ? 0.5 * m->sc.velocity * m->sc.velocity / g : 2 * m->sc.radius;
	const struct shown_unit *u = pick_unit(length_shown, x);
	tui_number(in_unit(x, u), num, sizeof num);
	snprintf(text, sizeof text, "%s %s", num, u->name);
	edit_begin(m, drop ? "impact.drop_height" : "impactor.diameter", u->name, text);
	return TUI_ACT_REDRAW;
}

static enum tui_action main_key(struct tui_model *m, int key)
{
	switch (key) {
	case TUI_KEY_UP: case 'k': return select_row(m, -1);
	case TUI_KEY_DOWN: case 'j': return select_row(m, +1);
	case TUI_KEY_LEFT: case 'h': return change(m, -1, 0);
	case TUI_KEY_RIGHT: case 'l': return change(m, +1, 0);
	case TUI_KEY_SLEFT: case 'H': return change(m, -1, 1);
	case TUI_KEY_SRIGHT: case 'L': return change(m, +1, 1);
	case TUI_KEY_ENTER: case '\n': case '\r': return edit_field(m);
	case ':':
		edit_begin(m, "", NULL, "");
		return TUI_ACT_REDRAW;
	case ' ':
		return field_model(m->sel) >= 0 ? toggle_model(m, field_model(m->sel))
						: TUI_ACT_NONE;
	case 'm': return material_key(m);
	case 'a': return cycle_accuracy(m, +1);
	case 'b': return cycle_shape(m, +1);
	case 'D': return geometry_edit(m, 0);
	case 'd': return geometry_edit(m, 1);
	case 'v':
		m->quantity = (enum tui_quantity)((m->quantity + 1) % TUI_Q_COUNT);
		return TUI_ACT_REDRAW;
	case 'p': return TUI_ACT_EXPORT;
	case 's': return TUI_ACT_SAVE;
	case '?': case TUI_KEY_HELP:
		m->screen = TUI_SCREEN_HELP;
		return TUI_ACT_REDRAW;
	case 'P':
		m->screen = TUI_SCREEN_PLAN;
		return TUI_ACT_REDRAW;
	case 'n':
		m->screen = TUI_SCREEN_NOTES;
		return TUI_ACT_REDRAW;
	case 'q':
		if (!m->modified)
			return TUI_ACT_QUIT;
		m->confirm_quit = 1;
		tui_model_message(m, 1, "the scene has unsaved changes: quit anyway? (y/n; s saves)");
		return TUI_ACT_REDRAW;
	case 'Q': return TUI_ACT_QUIT;
	case TUI_CTRL('l'): return TUI_ACT_REPAINT;
	case TUI_KEY_ESC: case 27:
		m->msg[0] = '\0';
		return TUI_ACT_REDRAW;
	}
	return TUI_ACT_NONE;
}

static enum tui_action help_key(struct tui_model *m, int key)
{
	(void)key; /* any key goes back */
	m->screen = TUI_SCREEN_MAIN;
	return TUI_ACT_REDRAW;
}

/* The answer to "quit anyway?": y quits, s saves (and stays), anything
 * else goes back. */
static enum tui_action confirm_key(struct tui_model *m, int key)
{
	m->confirm_quit = 0;
	m->msg[0] = '\0';
	if (key == 'y' || key == 'Y' || key == 'Q')
		return TUI_ACT_QUIT;
	return key == 's' ? TUI_ACT_SAVE : TUI_ACT_REDRAW;
}

enum tui_action tui_model_key(struct tui_model *m, int key)
{
	if (m->confirm_quit)
		return confirm_key(m, key);
	if (m->screen != TUI_SCREEN_MAIN)
		return help_key(m, key);
	if (m->editing)
		return edit_key(m, key);
	return main_key(m, key);
}
