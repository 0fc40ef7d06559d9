/* tui_keys.c: the TUI's keys: what each does to the model's scene
 * (tui_model.h), as plain functions (no curses). */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "material.h"
#include "tui_model.h"
#include "tui_model_impl.h"

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
	const struct shown_unit *u = tui_field_shown(&m->sc, m->sel, &x);
	if (isinf(x)) {
		tui_model_message(m, 1, "the layer is a half-space (inf): press Enter to type a thickness");
		return TUI_ACT_REDRAW;
	}
	/* in the unit shown, which the new value may leave (990 g -> 1 kg) */
	shortest(tui_step(x, dir, coarse), num, sizeof num);
	/* "2.5r0" without a space: the thickness key reads the r0 suffix */
	snprintf(value, sizeof value, "%s%s%s", num, m->sel == TUI_F_THICK_R0 ? "" : " ", u->name);
	return apply(m, tui_numerics[m->sel].key, value);
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
	if (tui_is_numeric(f))
		return step_number(m, dir, coarse);
	if (f == TUI_F_IMPACTOR || f == TUI_F_LAYER)
		return cycle_material(m, f == TUI_F_IMPACTOR, dir);
	if (f == TUI_F_ACCURACY)
		return cycle_accuracy(m, dir);
	if (f == TUI_F_SHAPE)
		return cycle_shape(m, dir);
	if (tui_field_model(f) >= 0)
		return toggle_model(m, tui_field_model(f));
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
	if (tui_field_model(f) >= 0)
		return toggle_model(m, tui_field_model(f));
	tui_model_field_text(m, f, text, sizeof text);
	if (f == TUI_F_IMPACTOR || f == TUI_F_LAYER) /* drop the override mark */
		text[strcspn(text, "*")] = '\0';
	if (tui_is_numeric(f)) { /* the text as shown, with its unit ("1.5 kg") */
		double x;
		edit_begin(m, tui_numerics[f].key, tui_field_shown(&m->sc, f, &x)->name, text);
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

/* A finite number with nothing after it ("0.1", "2e-3"; not "inf",
 * which is a word the thickness takes as it is). */
static int bare_number(const char *v)
{
	char *end;
	double x = strtod(v, &end);
	return end != v && *end == '\0' && isfinite(x);
}

/* A bare number typed into a numeric field: a scene file refuses it (a
 * length in mm or in r0?), but the field shows its unit beside the value,
 * so the number is taken in it, and the message line says so. */
static enum tui_action apply_in_unit(struct tui_model *m, const char *v)
{
	char value[TUI_EDIT_MAX + 16];
	/* "2.5r0" without a space: the thickness key reads the r0 suffix */
	snprintf(value, sizeof value, "%s%s%s", v, strcmp(m->edit_unit, "r0") == 0 ? "" : " ",
		 m->edit_unit);
	enum tui_action a = apply(m, m->edit_key, value);
	if (a == TUI_ACT_RECOMPUTE)
		tui_model_message(m, 0, "%s = %s (a bare number is taken in the field's unit)",
				  m->edit_key, value);
	return a;
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
	else if (m->edit_unit[0] && bare_number(v)) /* in the unit the field shows */
		a = apply_in_unit(m, v);
	else
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
	const struct shown_unit *u = tui_pick_unit(tui_length_shown, x);
	tui_number(tui_in_unit(x, u), num, sizeof num);
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
		return tui_field_model(m->sel) >= 0 ? toggle_model(m, tui_field_model(m->sel))
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
