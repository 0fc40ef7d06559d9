/* test_tui_model.c: the TUI's model and canvas, driven without curses. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "material.h"
#include "plan.h"
#include "problem.h"
#include "tap.h"
#include "scene_run.h"
#include "tui_model.h"
#include "tui_plot.h"

/* ---- canvas ---- */

static void test_canvas_braille(void)
{
	struct tui_canvas c;
	char row[64], cell[4];
	double x[2] = {0, 1}, top[2] = {1, 1};
	ok(tui_canvas_init(&c, 3, 1, TUI_CANVAS_BRAILLE) == 0, "braille canvas 3x1");
	tui_canvas_polyline(&c, 2, x, top, 2);
	tui_canvas_row(&c, 0, row, sizeof row);
	/* the top dots of both columns: 1 and 4, U+2809 */
	ok(strcmp(row, "\xe2\xa0\x89\xe2\xa0\x89\xe2\xa0\x89") == 0,
	   "a line along the top lights dots 1 and 4 of every cell");
	ok(tui_canvas_cell(&c, 1, 0, cell) == 2, "the cell remembers its series");
	tui_canvas_free(&c);

	double xs[2] = {0, 0}, ys[2] = {0, 1};
	ok(tui_canvas_init(&c, 1, 1, TUI_CANVAS_BRAILLE) == 0, "braille canvas 1x1");
	tui_canvas_range(&c, 0, 1, 0, 1);
	tui_canvas_polyline(&c, 0, xs, ys, 2);
	tui_canvas_cell(&c, 0, 0, cell);
	/* the left column: dots 1, 2, 3 and 7 = bits 0x47, U+2847 */
	ok(strcmp(cell, "\xe2\xa1\x87") == 0, "a vertical line is the left column");
	tui_canvas_clear(&c);
	ok(tui_canvas_cell(&c, 0, 0, cell) == -1 && strcmp(cell, " ") == 0,
	   "a cleared cell is a blank");
	tui_canvas_free(&c);
	tui_canvas_free(&c);
	ok(1, "free twice is harmless");
}

static void test_canvas_ascii(void)
{
	struct tui_canvas c;
	char r0[16], r1[16], r2[16];
	double x[2] = {0, 1}, y[2] = {0, 1};
	ok(tui_canvas_init(&c, 3, 3, TUI_CANVAS_ASCII) == 0, "ascii canvas 3x3");
	tui_canvas_polyline(&c, 1, x, y, 2);
	tui_canvas_row(&c, 0, r0, sizeof r0);
	tui_canvas_row(&c, 1, r1, sizeof r1);
	tui_canvas_row(&c, 2, r2, sizeof r2);
	ok(!strcmp(r0, "  o") && !strcmp(r1, " o ") && !strcmp(r2, "o  "),
	   "ascii diagonal drawn with the series' glyph: '%s' '%s' '%s'", r0, r1, r2);
	ok(tui_canvas_glyph(0) != tui_canvas_glyph(1), "series have distinct glyphs");
	tui_canvas_free(&c);
}

static void test_canvas_edges(void)
{
	struct tui_canvas c;
	char r[16];
	double x[3] = {0, NAN, 1}, y[3] = {0, 0.5, 1};
	double fx[2] = {-1e300, 1e300}, fy[2] = {0.5, 0.5};
	ok(tui_canvas_init(&c, 0, 3, TUI_CANVAS_ASCII) == -1, "a zero-width canvas is refused");
	tui_canvas_init(&c, 3, 3, TUI_CANVAS_ASCII);
	tui_canvas_polyline(&c, 0, x, y, 3);
	tui_canvas_row(&c, 1, r, sizeof r);
	ok(strcmp(r, "   ") == 0, "a NaN breaks the line: no segment through the middle");
	tui_canvas_clear(&c);
	tui_canvas_polyline(&c, 0, fx, fy, 2);
	tui_canvas_row(&c, 1, r, sizeof r);
	ok(strcmp(r, "***") == 0, "a line far past both ends is clipped to the canvas");
	tui_canvas_range(&c, 2, 2, 5, 5); /* empty ranges must not divide by 0 */
	ok(c.x1 > c.x0 && c.y1 > c.y0, "a zero-width range is widened");
	tui_canvas_free(&c);
}

/* ---- steps ---- */

static void test_step(void)
{
	is_rel(tui_step(4, +1, 0), 4.1, 1e-15, "4 fine up -> 4.1");
	is_rel(tui_step(4.1, -1, 0), 4, 1e-15, "4.1 fine down -> 4");
	is_rel(tui_step(1, -1, 0), 0.99, 1e-15, "1 fine down -> 0.99");
	is_rel(tui_step(0.99, +1, 0), 1, 1e-15, "0.99 fine up -> 1");
	is_rel(tui_step(12.2, +1, 1), 20, 1e-15, "12.2 coarse up -> 20");
	is_rel(tui_step(12.2, -1, 1), 10, 1e-15, "12.2 coarse down -> 10");
	is_rel(tui_step(10, -1, 1), 9, 1e-15, "10 coarse down -> 9");
	is_rel(tui_step(9, +1, 1), 10, 1e-15, "9 coarse up -> 10");
	ok(tui_step(0.1, -1, 1) > 0, "coarse steps down never reach 0");
	ok(isinf(tui_step(INFINITY, 1, 0)) && tui_step(0, 1, 0) == 0,
	   "inf and 0 are left alone");
}

/* ---- keys ---- */

static struct tui_model *fresh(void)
{
	static struct tui_model m;
	struct anvil_scene sc;
	tui_model_free(&m); /* from the test before; zeroed static at first */
	anvil_scene_default(&sc);
	sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
	tui_model_init(&m, &sc, NULL);
	return &m;
}

static int type(struct tui_model *m, const char *s)
{
	int a = TUI_ACT_NONE;
	for (; *s; ++s)
		a = tui_model_key(m, (unsigned char)*s);
	return a;
}

static const char *text(const struct tui_model *m, enum tui_field f)
{
	static char buf[4][64];
	static int i;
	i = (i + 1) % 4;
	tui_model_field_text(m, f, buf[i], sizeof buf[i]);
	return buf[i];
}

static void test_selection(void)
{
	struct tui_model *m = fresh();
	ok(m->sel == 0, "selection starts at the top");
	tui_model_key(m, TUI_KEY_DOWN);
	tui_model_key(m, 'j');
	ok(m->sel == 2, "Down and j move down");
	ok(tui_model_key(m, 'k') == TUI_ACT_REDRAW && m->sel == 1, "k moves up");
	tui_model_key(m, TUI_KEY_UP);
	tui_model_key(m, TUI_KEY_UP);
	ok(m->sel == TUI_F_COUNT - 1, "Up from the top wraps to the bottom");
}

static void test_thickness(void)
{
	struct tui_model *m = fresh();
	double r0 = m->sc.radius;
	m->sel = TUI_F_THICK_MM;
	ok(!strcmp(text(m, TUI_F_THICK_MM), "4 mm") && !strcmp(text(m, TUI_F_THICK_R0), "1 r0"),
	   "default thickness: 4 mm = 1 r0 (%s, %s)", text(m, TUI_F_THICK_MM),
	   text(m, TUI_F_THICK_R0));
	ok(tui_model_key(m, TUI_KEY_RIGHT) == TUI_ACT_RECOMPUTE, "Right asks for a recompute");
	ok(!strcmp(text(m, TUI_F_THICK_MM), "4.1 mm") &&
	   !strcmp(text(m, TUI_F_THICK_R0), "1.025 r0") && !m->sc.thickness_per_r0,
	   "a fine step in mm updates both views: %s, %s", text(m, TUI_F_THICK_MM),
	   text(m, TUI_F_THICK_R0));
	tui_model_key(m, 'h');
	is_rel(anvil_scene_h(&m->sc), 0.004, 1e-15, "h steps back to 4 mm");
	m->sel = TUI_F_THICK_R0;
	tui_model_key(m, 'L');
	ok(!strcmp(text(m, TUI_F_THICK_R0), "2 r0") && !strcmp(text(m, TUI_F_THICK_MM), "8 mm") &&
	   m->sc.thickness_per_r0, "a coarse step in r0: %s = %s, kept in r0",
	   text(m, TUI_F_THICK_R0), text(m, TUI_F_THICK_MM));
	tui_model_key(m, TUI_KEY_SLEFT);
	is_rel(anvil_scene_h(&m->sc) / r0, 1, 1e-15, "Shift-Left: coarse step back to 1 r0");
	m->sel = TUI_F_RADIUS;
	tui_model_key(m, 'L');
	ok(!strcmp(text(m, TUI_F_THICK_R0), "1 r0") && !strcmp(text(m, TUI_F_THICK_MM), "5 mm"),
	   "a thickness in r0 follows the radius: %s, %s", text(m, TUI_F_THICK_R0),
	   text(m, TUI_F_THICK_MM));
	ok(m->modified, "the scene is marked modified");
}

static void test_numbers(void)
{
	struct tui_model *m = fresh();
	m->sel = TUI_F_VELOCITY;
	tui_model_key(m, 'h');
	is_rel(m->sc.velocity, 9.9, 1e-15, "velocity 10 -> 9.9 m/s");
	tui_model_key(m, 'H');
	is_rel(m->sc.velocity, 9, 1e-15, "coarse: 9.9 -> 9 m/s");
	tui_model_key(m, TUI_KEY_SRIGHT);
	is_rel(m->sc.velocity, 10, 1e-15, "Shift-Right: 9 -> 10 m/s");
	m->sel = TUI_F_MASS;
	tui_model_key(m, 'l');
	is_rel(m->sc.mass, 13e-3, 1e-15, "mass 12.2 -> 13 g (two digits)");
	ok(!strcmp(text(m, TUI_F_MASS), "13 g"), "shown as %s", text(m, TUI_F_MASS));
	m->sel = TUI_F_RADIUS;
	tui_model_key(m, 'l');
	is_rel(m->sc.radius, 4.1e-3, 1e-15, "radius 4 -> 4.1 mm");
}

/* The value of row f whose text is t, in t's unit (the number of t
 * should be it). */
static double shown_value(const struct tui_model *m, int f, const char *t)
{
	static const struct {
		const char *name;
		double si;
	} units[] = {{"um", 1e-6}, {"mm", 1e-3}, {"m", 1}, {"mg", 1e-6}, {"g", 1e-3},
		     {"kg", 1}, {"mm/s", 1e-3}, {"m/s", 1}, {"km/s", 1e3}};
	const char *u = strchr(t, ' ');
	double si = f == TUI_F_THICK_MM ? anvil_scene_h(&m->sc)
		: f == TUI_F_VELOCITY ? m->sc.velocity
		: f == TUI_F_MASS ? m->sc.mass : m->sc.radius;
	if (f == TUI_F_THICK_R0)
		return anvil_scene_h(&m->sc) / m->sc.radius;
	for (size_t i = 0; u && i < sizeof units / sizeof units[0]; ++i)
		if (!strcmp(u + 1, units[i].name))
			return si / units[i].si;
	return NAN;
}

/* Issue: a 100 kg drop weight read "100000 g".  Each row is shown in the
 * unit that fits (mg/g/kg, um/mm/m, mm/s, m/s, km/s); steps cross the
 * unit on the same grid and back; Enter opens the value as shown. */
static void test_units_fit(void)
{
	static const struct {
		const char *set, *want;
		enum tui_field f;
	} cases[] = {
		{":impactor.mass=100kg\n", "100 kg", TUI_F_MASS},
		{":impactor.mass=2kg\n", "2 kg", TUI_F_MASS},
		{":impactor.mass=1000g\n", "1 kg", TUI_F_MASS},
		{":impactor.mass=999.5g\n", "999.5 g", TUI_F_MASS},
		{":impactor.mass=0.5g\n", "0.5 g", TUI_F_MASS},
		{":impactor.mass=0.1g\n", "0.1 g", TUI_F_MASS},
		{":impactor.mass=50mg\n", "50 mg", TUI_F_MASS},
		{":impactor.mass=999.99999g\n", "1 kg", TUI_F_MASS}, /* "1000" to 4 digits */
		{":impactor.diameter=1m\n", "500 mm", TUI_F_RADIUS},
		{":impactor.diameter=3m\n", "1.5 m", TUI_F_RADIUS},
		{":layer.thickness=0.05mm\n", "50 um", TUI_F_THICK_MM},
		{":layer.thickness=0.5mm\n", "0.5 mm", TUI_F_THICK_MM},
		{":layer.thickness=2m\n", "2 m", TUI_F_THICK_MM},
		{":impact.velocity=1mm/s\n", "1 mm/s", TUI_F_VELOCITY},
		{":impact.velocity=0.1m/s\n", "0.1 m/s", TUI_F_VELOCITY},
		{":impact.velocity=1.5km/s\n", "1.5 km/s", TUI_F_VELOCITY},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
		struct tui_model *m = fresh();
		type(m, cases[i].set);
		ok(!strcmp(text(m, cases[i].f), cases[i].want), "%.*s shown as %s (%s)",
		   (int)strlen(cases[i].set) - 2, cases[i].set + 1, text(m, cases[i].f),
		   cases[i].want);
	}
	struct tui_model *m = fresh();
	type(m, ":impactor.mass=900g\n");
	m->sel = TUI_F_MASS;
	tui_model_key(m, 'L');
	ok(m->sc.mass == 1 && !strcmp(text(m, TUI_F_MASS), "1 kg"), "900 g, coarse up: %s",
	   text(m, TUI_F_MASS));
	tui_model_key(m, 'l');
	ok(m->sc.mass == 1.1 && !strcmp(text(m, TUI_F_MASS), "1.1 kg"),
	   "  then fine up: %s (the kg grid, not a jump)", text(m, TUI_F_MASS));
	tui_model_key(m, 'h');
	tui_model_key(m, 'h');
	ok(m->sc.mass == 0.99 && !strcmp(text(m, TUI_F_MASS), "990 g"),
	   "  fine down twice: %s, the double \"990 g\" and \"0.99 kg\" both give",
	   text(m, TUI_F_MASS));
	tui_model_key(m, 'H');
	ok(m->sc.mass == 0.9 && !strcmp(text(m, TUI_F_MASS), "900 g"), "  coarse down: %s",
	   text(m, TUI_F_MASS));
	type(m, ":impactor.mass=0.1g\n");
	tui_model_key(m, 'h');
	ok(m->sc.mass == 99e-6 && !strcmp(text(m, TUI_F_MASS), "99 mg"), "0.1 g, fine down: %s",
	   text(m, TUI_F_MASS));
	tui_model_key(m, 'l');
	ok(m->sc.mass == 1e-4 && !strcmp(text(m, TUI_F_MASS), "0.1 g"), "  and back up: %s",
	   text(m, TUI_F_MASS));
	m->sel = TUI_F_VELOCITY;
	type(m, ":impact.velocity=0.1m/s\n");
	tui_model_key(m, 'H');
	ok(m->sc.velocity == 0.09 && !strcmp(text(m, TUI_F_VELOCITY), "90 mm/s"),
	   "0.1 m/s, coarse down: %s", text(m, TUI_F_VELOCITY));
	tui_model_key(m, 'L');
	ok(m->sc.velocity == 0.1, "  and back up: %s", text(m, TUI_F_VELOCITY));
	/* Enter: the value as shown, with its unit; any unit may be typed */
	type(m, ":impactor.mass=2kg\n");
	m->sel = TUI_F_MASS;
	tui_model_key(m, TUI_KEY_ENTER);
	ok(m->editing && !strcmp(m->edit, "2 kg") && !strcmp(m->edit_unit, "kg"),
	   "Enter on a 2 kg mass opens '%s'", m->edit);
	ok(tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_REDRAW && !m->editing && m->sc.mass == 2,
	   "  Enter again: nothing changes");
	tui_model_key(m, TUI_KEY_ENTER);
	tui_model_key(m, TUI_CTRL('u'));
	int act = type(m, "1500 g\n");
	ok(act == TUI_ACT_RECOMPUTE && m->sc.mass == 1.5 &&
		   !strcmp(text(m, TUI_F_MASS), "1.5 kg"),
	   "  '1500 g' typed: 1.5 kg exactly, shown as %s", text(m, TUI_F_MASS));
	type(m, ":impactor.diameter=1.2m\n");
	tui_model_key(m, 'D');
	ok(m->editing && !strcmp(m->edit, "1.2 m"), "D on a 1.2 m ball opens '%s'", m->edit);
	tui_model_key(m, TUI_KEY_ESC);
}

/* Issue 11: values shown without float noise.  A value of at most 6
 * significant digits (typed, or a step's) exactly, a derived one to 4. */
static void test_display(void)
{
	static const struct {
		double x;
		const char *s;
	} nums[] = {{4, "4"}, {4.1255, "4.1255"}, {0.16842105263157894, "0.1684"},
		    {100000, "100000"}, {12345.678, "12346"}, {0.99028485, "0.9903"},
		    {2.5e-3, "0.0025"}, {1.000000000001, "1"}, {0.1 + 0.2, "0.3"}};
	char buf[48];
	for (size_t i = 0; i < sizeof nums / sizeof nums[0]; ++i) {
		tui_number(nums[i].x, buf, sizeof buf);
		ok(!strcmp(buf, nums[i].s), "tui_number(%.17g) = %s (%s)", nums[i].x, buf,
		   nums[i].s);
	}
	/* tests/cli.sh's long scene: a 38 mm ball on 3.2 mm of glass */
	struct tui_model *m = fresh();
	type(m, ":impactor.shape=ball\n");
	type(m, ":impactor.diameter=38mm\n");
	type(m, ":layer.thickness=3.2mm\n");
	ok(!strcmp(text(m, TUI_F_THICK_MM), "3.2 mm") && !strcmp(text(m, TUI_F_THICK_R0), "0.1684 r0"),
	   "3.2 mm over r0 = 19 mm: %s = %s", text(m, TUI_F_THICK_MM), text(m, TUI_F_THICK_R0));
	ok(!strcmp(text(m, TUI_F_MASS), "257.4 g"), "  the ball's mass rho pi D^3 / 6: %s (%.17g g)",
	   text(m, TUI_F_MASS), m->sc.mass * 1e3);
	double h = anvil_scene_h(&m->sc);
	m->sel = TUI_F_THICK_R0;
	tui_model_key(m, TUI_KEY_ENTER);
	ok(!strcmp(m->edit, "0.1684 r0") && tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_REDRAW &&
		   !m->editing && anvil_scene_h(&m->sc) == h && !m->sc.thickness_per_r0,
	   "Enter, Enter on the derived 0.1684 r0: nothing changes (h = %.17g m)", h);
	tui_model_key(m, TUI_KEY_ENTER);
	tui_model_key(m, TUI_CTRL('u'));
	int act = type(m, "0.1687 r0\n");
	ok(act == TUI_ACT_RECOMPUTE && !m->editing && !strcmp(text(m, TUI_F_THICK_R0), "0.1687 r0"),
	   "  an edited value is taken: %s", text(m, TUI_F_THICK_R0));
	is_rel(anvil_scene_h(&m->sc), 0.1687 * 19e-3, 1e-15, "  h = 0.1687 r0");
	/* every step lands on a value shown exactly, at most 3 digits */
	static const int fields[] = {TUI_F_THICK_MM, TUI_F_THICK_R0, TUI_F_VELOCITY, TUI_F_MASS,
				     TUI_F_RADIUS};
	static const int keys[] = {'l', 'l', 'L', 'h', 'H', 'H', 'h', 'l', 'L', 'L'};
	int clean = 1;
	for (size_t f = 0; f < sizeof fields / sizeof fields[0]; ++f) {
		m->sel = fields[f];
		for (int r = 0; r < 3; ++r)
			for (size_t k = 0; k < sizeof keys / sizeof keys[0]; ++k) {
				tui_model_key(m, keys[k]);
				const char *t = text(m, (enum tui_field)fields[f]);
				double want = shown_value(m, fields[f], t);
				int digits = 0, lead = 1;
				for (const char *c = t; *c && *c != ' '; ++c)
					if (*c >= '1' && *c <= '9')
						lead = 0, digits++;
					else if (*c == '0' && !lead)
						digits++;
				if (fabs(strtod(t, NULL) - want) > 1e-12 * want || digits > 3) {
					diag("field %d after '%c': %s (%.17g)", fields[f], keys[k], t, want);
					clean = 0;
				}
			}
	}
	ok(clean, "steps on every numeric row land on values of at most 3 digits, shown exactly");
}

static void test_materials(void)
{
	struct tui_model *m = fresh();
	ok(type(m, ":impactor.E = 100 GPa") == TUI_ACT_REDRAW && m->editing, "':' opens a field");
	ok(tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_RECOMPUTE && !m->editing,
	   "KEY=VALUE applied");
	ok(m->sc.impactor.E == 100e9 && m->sc.impactor.mat.E == 100e9, "impactor.E overridden");
	ok(!strcmp(text(m, TUI_F_IMPACTOR), "copper*"), "an overridden material is starred: %s",
	   text(m, TUI_F_IMPACTOR));
	m->sel = TUI_F_MASS; /* a row of the impactor */
	ok(tui_model_key(m, 'm') == TUI_ACT_RECOMPUTE, "m cycles the impactor's material");
	const struct anvil_material *mat = anvil_material_find(m->sc.impactor.material);
	ok(strcmp(m->sc.impactor.material, "copper") != 0 && mat &&
	   isnan(m->sc.impactor.E) && isnan(m->sc.impactor.nu) &&
	   isnan(m->sc.impactor.rho) && isnan(m->sc.impactor.yield) &&
	   m->sc.impactor.mat.E == mat->E,
	   "now %s, overrides cleared, its own E", m->sc.impactor.material);
	ok(!strcmp(m->sc.layer.material, "steel"), "the layer is untouched");
	m->sel = TUI_F_THICK_R0;
	tui_model_key(m, 'm');
	ok(strcmp(m->sc.layer.material, "steel") != 0, "m on a layer row: layer now %s",
	   m->sc.layer.material);
	m->sel = TUI_F_LAYER;
	for (int i = 1; i < anvil_material_count(); ++i)
		tui_model_key(m, 'l');
	ok(!strcmp(m->sc.layer.material, "steel"), "Right cycles round the whole table");
	tui_model_key(m, 'h');
	tui_model_key(m, 'l');
	ok(!strcmp(m->sc.layer.material, "steel"), "Left undoes Right");
	m->sel = TUI_F_ACCURACY;
	ok(tui_model_key(m, 'm') == TUI_ACT_REDRAW && m->msg_error && m->msg[0],
	   "m on a row of no body: an error message (%s)", m->msg);
}

static void test_accuracy(void)
{
	struct tui_model *m = fresh();
	enum anvil_accuracy a0 = m->sc.accuracy;
	ok(tui_model_key(m, 'a') == TUI_ACT_RECOMPUTE &&
	   m->sc.accuracy == (a0 + 1) % ANVIL_ACC_COUNT, "a: next level (%s)",
	   anvil_accuracy_name(m->sc.accuracy));
	for (int i = 1; i < ANVIL_ACC_COUNT; ++i)
		tui_model_key(m, 'a');
	ok(m->sc.accuracy == a0, "a cycles through every level and back");
	m->sel = TUI_F_ACCURACY;
	tui_model_key(m, 'h');
	ok(m->sc.accuracy == (a0 + ANVIL_ACC_COUNT - 1) % ANVIL_ACC_COUNT,
	   "Left on the accuracy row: the level before");
}

static void test_edit(void)
{
	struct tui_model *m = fresh();
	m->sel = TUI_F_MASS;
	tui_model_key(m, TUI_KEY_ENTER);
	ok(m->editing && !strcmp(m->edit, "12.2 g") && !strcmp(m->edit_key, "impactor.mass"),
	   "Enter opens the value with its unit: %s = '%s'", m->edit_key, m->edit);
	tui_model_key(m, TUI_CTRL('u'));
	type(m, "12x kg");
	ok(tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_REDRAW, "a bad value: no recompute");
	ok(m->editing && m->msg_error && strstr(m->msg, "mass"),
	   "the parse error is reported and the field stays open: %s", m->msg);
	is_rel(m->sc.mass, 12.2e-3, 1e-15, "the mass is unchanged");
	tui_model_key(m, TUI_KEY_ESC);
	ok(!m->editing && !m->msg[0], "Esc cancels");

	m->sel = TUI_F_THICK_MM;
	tui_model_key(m, TUI_KEY_ENTER);
	for (int i = 0; i < 10; ++i)
		tui_model_key(m, TUI_KEY_BACKSPACE);
	type(m, "8");
	ok(tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_RECOMPUTE && !m->editing && !m->msg_error &&
		   strstr(m->msg, "8 mm") && strstr(m->msg, "field's unit"),
	   "a bare number is taken in the unit the field shows, and the message says so: %s",
	   m->msg);
	is_rel(anvil_scene_h(&m->sc), 8e-3, 1e-15, "8 mm");
	m->sel = TUI_F_THICK_R0;
	tui_model_key(m, TUI_KEY_ENTER);
	tui_model_key(m, TUI_CTRL('u'));
	ok(type(m, "0.5\n") == TUI_ACT_RECOMPUTE && m->sc.thickness_per_r0 &&
		   fabs(m->sc.thickness - 0.5) < 1e-15,
	   "  on the r0 row, in r0: %s", m->msg);
	m->sel = TUI_F_THICK_MM;
	tui_model_key(m, TUI_KEY_ENTER);
	tui_model_key(m, TUI_CTRL('u'));
	type(m, "8 mm");
	ok(tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_RECOMPUTE, "with its unit it is taken");
	is_rel(anvil_scene_h(&m->sc), 8e-3, 1e-15, "8 mm");
	tui_model_key(m, TUI_KEY_ENTER);
	tui_model_key(m, TUI_CTRL('u'));
	type(m, "inf\n");
	ok(isinf(anvil_scene_h(&m->sc)), "inf: a half-space");
	ok(tui_model_key(m, 'l') == TUI_ACT_REDRAW && m->msg_error,
	   "stepping inf is refused with a message");

	m->sel = TUI_F_LAYER;
	tui_model_key(m, TUI_KEY_ENTER);
	tui_model_key(m, TUI_CTRL('u'));
	type(m, "unobtanium\r");
	ok(m->editing && m->msg_error && !strcmp(m->sc.layer.material, "steel"),
	   "an unknown material: error, nothing changed (%s)", m->msg);
	tui_model_key(m, 27);
	type(m, ":nonsense\n");
	ok(m->editing && m->msg_error, "':' without '=': error (%s)", m->msg);
	tui_model_key(m, TUI_KEY_ESC);
}

static void test_keys(void)
{
	struct tui_model *m = fresh();
	ok(tui_model_key(m, 'v') == TUI_ACT_REDRAW && m->quantity == TUI_Q_VELOCITY, "v: v(t)");
	tui_model_key(m, 'v');
	tui_model_key(m, 'v');
	ok(m->quantity == TUI_Q_RF_LAMBDA, "v: then R_f against lambda*");
	tui_model_key(m, 'v');
	ok(m->quantity == TUI_Q_RF_THICKNESS, "v: then R_f against h");
	tui_model_key(m, 'v');
	ok(m->quantity == TUI_Q_FORCE, "v cycles back to P(t)");
	ok(tui_model_key(m, '?') == TUI_ACT_REDRAW && m->screen == TUI_SCREEN_HELP, "? helps");
	ok(tui_model_key(m, 'q') == TUI_ACT_REDRAW && m->screen == TUI_SCREEN_MAIN,
	   "any key, even q, leaves the help");
	ok(tui_model_key(m, 'n') == TUI_ACT_REDRAW && m->screen == TUI_SCREEN_NOTES,
	   "n shows the notes in full");
	int sel_before = m->sel;
	ok(tui_model_key(m, 'j') == TUI_ACT_REDRAW && m->screen == TUI_SCREEN_MAIN &&
		   m->sel == sel_before,
	   "any key leaves the notes, and selects nothing");
	ok(tui_model_key(m, 'p') == TUI_ACT_EXPORT, "p exports");
	ok(tui_model_key(m, 's') == TUI_ACT_SAVE, "s saves");
	ok(!strcmp(tui_model_save_path(m), TUI_DEFAULT_SAVE), "to %s without a file",
	   TUI_DEFAULT_SAVE);
	tui_model_saved(m, "x.scene");
	ok(!strcmp(tui_model_save_path(m), "x.scene") && !m->modified, "then to where it went");
	ok(tui_model_key(m, 'q') == TUI_ACT_QUIT, "q quits a saved scene");
	ok(tui_model_key(m, 0x1234) == TUI_ACT_NONE, "an unknown key does nothing");
	m->sel = TUI_F_VELOCITY;
	tui_model_key(m, 'l');
	ok(m->modified, "a change: unsaved");
	ok(tui_model_key(m, 'q') == TUI_ACT_REDRAW && m->confirm_quit && strstr(m->msg, "unsaved"),
	   "q with unsaved changes asks first");
	ok(tui_model_key(m, 'n') == TUI_ACT_REDRAW && !m->confirm_quit && !m->msg[0],
	   "n goes back");
	tui_model_key(m, 'q');
	ok(tui_model_key(m, 'y') == TUI_ACT_QUIT, "y quits");
	m->confirm_quit = 0;
	ok(tui_model_key(m, 'Q') == TUI_ACT_QUIT, "Q quits without asking");
	int has_q = 0;
	for (int i = 0; tui_help_lines[i]; ++i)
		has_q |= strstr(tui_help_lines[i], "quit") != NULL;
	ok(has_q, "the help lists the keys");
}

/* ---- geometry keys and the verdict (issue 10) ---- */

static void test_geometry(void)
{
	struct tui_model *m = fresh();
	ok(!strcmp(text(m, TUI_F_SHAPE), "rod"), "the shape row: rod by default (%s)",
	   text(m, TUI_F_SHAPE));
	int act = tui_model_key(m, 'b');
	ok(act == TUI_ACT_RECOMPUTE && m->sc.shape == ANVIL_SHAPE_BALL &&
		   !strcmp(text(m, TUI_F_SHAPE), "ball"),
	   "b: a ball (%s)", text(m, TUI_F_SHAPE));
	double rho = anvil_material_find("copper")->rho, D = 2 * m->sc.radius;
	is_rel(m->sc.mass, rho * M_PI * D * D * D / 6, 1e-12,
	       "  its mass from the density: rho pi D^3 / 6 = %.4g g", m->sc.mass * 1e3);
	m->sel = TUI_F_SHAPE;
	ok(tui_model_key(m, 'l') == TUI_ACT_RECOMPUTE && m->sc.shape == ANVIL_SHAPE_ROD,
	   "Right on the shape row cycles back to rod");
	tui_model_key(m, 'h');
	ok(m->sc.shape == ANVIL_SHAPE_BALL, "Left too");

	ok(tui_model_key(m, 'D') == TUI_ACT_REDRAW && m->editing &&
		   !strcmp(m->edit_key, "impactor.diameter") && !strcmp(m->edit, "8 mm"),
	   "D opens the diameter with its unit: %s = '%s'", m->edit_key, m->edit);
	tui_model_key(m, TUI_CTRL('u'));
	ok(type(m, "10 mm\n") == TUI_ACT_RECOMPUTE && !m->editing, "10 mm is taken");
	is_rel(m->sc.radius, 5e-3, 1e-15, "  r0 = D/2 = 5 mm");
	ok(!strcmp(text(m, TUI_F_RADIUS), "5 mm"), "  the radius row follows (%s)",
	   text(m, TUI_F_RADIUS));

	ok(tui_model_key(m, 'd') == TUI_ACT_REDRAW && m->editing &&
		   !strcmp(m->edit_key, "impact.drop_height"),
	   "d opens the drop height ('%s', the velocity's)", m->edit);
	tui_model_key(m, TUI_CTRL('u'));
	type(m, "50");
	ok(tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_RECOMPUTE && !m->editing &&
		   strstr(m->msg, "50 m ("),
	   "  a bare number in the unit it opened on (m): %s", m->msg);
	is_rel(m->sc.velocity, sqrt(2 * ANVIL_G_STANDARD * 50), 1e-12, "  V0 = sqrt(2 g 50 m)");
	tui_model_key(m, 'd');
	tui_model_key(m, TUI_CTRL('u'));
	type(m, "50 mm");
	ok(tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_RECOMPUTE, "  50 mm is taken");
	is_rel(m->sc.velocity, sqrt(2 * ANVIL_G_STANDARD * 0.05), 1e-12,
	       "  V0 = sqrt(2 g H) = %.4g m/s", m->sc.velocity);
	ok(!strcmp(text(m, TUI_F_VELOCITY), "0.9903 m/s"),
	   "  the velocity row follows, to 4 digits (%s)", text(m, TUI_F_VELOCITY));
	m->sel = TUI_F_VELOCITY;
	tui_model_key(m, 'l');
	is_rel(m->sc.velocity, 1.0, 1e-15, "a velocity step replaces the drop height (%.4g m/s)",
	       m->sc.velocity);
}

/* The plan of m's scene handed to the current generation, as the worker does. */
static void give_plan(struct tui_model *m)
{
	static struct anvil_plan pl;
	struct anvil_problem pb;
	struct anvil_err e = {0};
	tui_model_request(m);
	int st = anvil_problem_init(&pb, tui_model_scene(m), &e);
	st = st ? st : anvil_plan_make(&pb, NULL, &pl, &e);
	if (st)
		diag("plan: %s", e.msg);
	tui_model_deliver_plan(m, m->gen, &pl);
}

static void test_verdict_mark(void)
{
	char lay[320], imp[320];
	struct tui_model *m = fresh();
	tui_model_request(m);
	ok(tui_model_verdict(m, lay, imp, sizeof lay) == -1 && !lay[0] && !imp[0],
	   "no plan yet: no verdict");
	give_plan(m);
	ok(tui_model_verdict(m, lay, imp, sizeof lay) == 1 &&
		   !strncmp(lay, "layer yields (quasi-static Hertz): ", 35),
	   "the paper's scene: %s", lay);
	ok(!strncmp(imp, "impactor yields too: ", 21),
	   "  and the impactor's line: %s", imp);
	m->sel = TUI_F_VELOCITY;
	tui_model_key(m, 'l');
	tui_model_request(m);
	ok(tui_model_verdict(m, lay, imp, sizeof lay) == -1, "a new run: the old verdict is gone");
	type(m, ":layer.yield=100 GPa\n");
	type(m, ":impactor.yield=100 GPa\n");
	give_plan(m);
	ok(tui_model_verdict(m, lay, imp, sizeof lay) == 0 &&
		   !strncmp(lay, "layer stays elastic (quasi-static Hertz): ", 42) && !imp[0],
	   "strong bodies, updated with the run: %s; no impactor line", lay);
}

static void test_models_toggle(void)
{
	struct tui_model *m = fresh();
	unsigned all = m->sc.models;
	m->sel = TUI_F_SHOW_LAYER;
	ok(tui_model_key(m, ' ') == TUI_ACT_RECOMPUTE &&
	   m->sc.models == (all & ~(1u << ANVIL_MODEL_LAYER)), "Space switches a model off");
	ok(!strcmp(text(m, TUI_F_SHOW_LAYER), "[ ] layer"), "shown as %s",
	   text(m, TUI_F_SHOW_LAYER));
	tui_model_key(m, 'l');
	ok(m->sc.models == all, "Right switches it back on");
	m->sc.models = 1u << ANVIL_MODEL_HERTZ;
	m->sel = TUI_F_SHOW_HERTZ;
	ok(tui_model_key(m, ' ') == TUI_ACT_REDRAW && m->sc.models == 1u << ANVIL_MODEL_HERTZ,
	   "the last model stays on");
}

/* ---- generations and the cache ---- */

static struct anvil_result fake(enum anvil_model model, double ts)
{
	struct anvil_result r;
	anvil_result_init(&r, model);
	r.ts.val = ts;
	anvil_history_alloc(&r.hist, 3);
	r.hist.t[2] = ts;
	return r;
}

static void test_generations(void)
{
	struct tui_model *m = fresh();
	const unsigned hz = (1u << ANVIL_MODEL_HERTZ) | (1u << ANVIL_MODEL_ZENER);
	m->sc.models = hz;
	ok(tui_model_request(m) == hz && tui_model_busy(m), "a request wants both models");
	ok(m->rows[ANVIL_MODEL_LAYER].state == TUI_ROW_OFF, "others are off");
	unsigned g = m->gen;
	struct anvil_result r = fake(ANVIL_MODEL_ZENER, 40e-6);
	ok(tui_model_deliver(m, g, ANVIL_MODEL_ZENER, ANVIL_OK, NULL, &r) == 1,
	   "a current result is used");
	ok(m->rows[ANVIL_MODEL_ZENER].state == TUI_ROW_DONE &&
	   m->rows[ANVIL_MODEL_ZENER].res.ts.val == 40e-6 &&
	   m->rows[ANVIL_MODEL_ZENER].res.hist.n == 3 && r.hist.n == 0,
	   "the row holds it and owns its history");
	r = fake(ANVIL_MODEL_HERTZ, 1);
	ok(tui_model_deliver(m, g - 1, ANVIL_MODEL_HERTZ, ANVIL_OK, NULL, &r) == 0 &&
	   tui_model_busy(m), "a stale generation is dropped");
	r = fake(ANVIL_MODEL_HERTZ, 1);
	ok(tui_model_deliver(m, g, ANVIL_MODEL_HERTZ, ANVIL_ECANCEL, NULL, &r) == 0,
	   "a cancelled run is dropped");
	r = fake(ANVIL_MODEL_HERTZ, 30e-6);
	tui_model_deliver(m, g, ANVIL_MODEL_HERTZ, ANVIL_EINVAL, "no", &r);
	ok(!tui_model_busy(m) && !m->rows[ANVIL_MODEL_HERTZ].have &&
	   !strcmp(m->rows[ANVIL_MODEL_HERTZ].msg, "no"), "a failure is a row with a message");
	{
		struct tui_model *m2 = calloc(1, sizeof *m2);
		struct anvil_scene sc;
		anvil_scene_default(&sc);
		sc.effects.contact = ANVIL_CONTACT_PAPER; /* the paper's contact model is tested here */
		tui_model_init(m2, &sc, NULL);
		m2->sc.models = 1u << ANVIL_MODEL_LAYER;
		tui_model_request(m2);
		struct anvil_result z;
		anvil_result_init(&z, ANVIL_MODEL_LAYER);
		z.ts.val = z.Pmax.val = z.Rf.val = 0; /* what a refusal leaves */
		tui_model_deliver(m2, m2->gen, ANVIL_MODEL_LAYER, ANVIL_ETOL, "refused", &z);
		ok(!m2->rows[ANVIL_MODEL_LAYER].have,
		   "a missed target with zeros is no value (shown refused, not ~0)");
		tui_model_free(m2);
		free(m2);
	}

	m->sel = TUI_F_VELOCITY;
	tui_model_key(m, 'l');
	ok(tui_model_request(m) == hz, "a new velocity: both to compute");
	ok(m->rows[ANVIL_MODEL_ZENER].state == TUI_ROW_PENDING &&
	   m->rows[ANVIL_MODEL_ZENER].have, "old values stay, pending");
	tui_model_key(m, 'h');
	ok(tui_model_request(m) == 0 && !tui_model_busy(m) && m->run_cached == 2,
	   "back to a scene seen before: all from the cache");
	ok(m->rows[ANVIL_MODEL_ZENER].res.ts.val == 40e-6 &&
	   m->rows[ANVIL_MODEL_ZENER].res.hist.n == 3 &&
	   m->rows[ANVIL_MODEL_HERTZ].status == ANVIL_EINVAL,
	   "with the values, the history and the failure");
	ok(memcmp(tui_model_scene(m), &m->sc, sizeof m->sc) == 0,
	   "the scene computed is the scene edited");
	struct tui_cache_key k1, k2;
	tui_cache_key_make(&k1, &m->sc, ANVIL_MODEL_ZENER);
	m->sc.layer.mat.E *= 1.0000001;
	tui_cache_key_make(&k2, &m->sc, ANVIL_MODEL_ZENER);
	ok(memcmp(&k1, &k2, sizeof k1) != 0, "the key sees the resolved material");
	tui_model_free(m);
	memset(m, 0, sizeof *m);
}

/* Deliver what the solver computes for the layer row of the request. */
static void deliver_layer(struct tui_model *m, struct anvil_solver *s)
{
	struct anvil_result r;
	struct anvil_err e = {0};
	int st = scene_run(s, tui_model_scene(m), ANVIL_MODEL_LAYER, TUI_NHIST, &r, &e);
	tui_model_deliver(m, m->gen, ANVIL_MODEL_LAYER, st, e.msg, &r);
}

/* The verdict once the layer row is in: quasi-static Hertz at its own
 * P_max, not the rigid anvil's (a 1 mm plate takes a twelfth of it). */
static void test_verdict_at_row(void)
{
	char lay[320], imp[320], before[320];
	struct tui_model *m = fresh();
	struct anvil_solver *s = anvil_solver_alloc();
	anvil_solver_set_cache_dir(s, NULL, NULL);
	type(m, ":layer.thickness=1mm\n");
	type(m, ":solver.accuracy=draft\n");
	type(m, ":effects.contact=physical\n"); /* the paper's chatters there for 47 s */
	m->sc.models = 1u << ANVIL_MODEL_LAYER;
	give_plan(m);
	tui_model_verdict(m, before, imp, sizeof before);
	deliver_layer(m, s);
	tui_model_verdict(m, lay, imp, sizeof lay);
	struct anvil_verdict v;
	const struct anvil_result *r = &m->rows[ANVIL_MODEL_LAYER].res;
	ok(anvil_verdict_at(&m->plan.pb, r->Pmax.val, r->tmax.val, &v) == ANVIL_OK &&
		   v.stress < m->plan.verdict.stress, "the row's P_max (%.4g kN) gives a lower stress",
	   r->Pmax.val * 1e-3);
	ok(strstr(lay, "at the layer's computed P_max") && strcmp(lay, before),
	   "the line says so: %s (was: %s)", lay, before);
	anvil_solver_free(s);
	tui_model_free(m);
	memset(m, 0, sizeof *m);
}

/* s with every number's digits as '#': the words of a line. */
static const char *words(const char *s)
{
	static char buf[2][ANVIL_VERDICT_TEXT_MAX];
	static int k;
	char *o = buf[k = !k];
	size_t n = 0;
	for (; *s && n + 1 < sizeof buf[0]; ++s)
		if (!(isdigit((unsigned char)*s) && n && o[n - 1] == '#'))
			o[n++] = isdigit((unsigned char)*s) ? '#' : *s;
	o[n] = '\0';
	return o;
}

/* A thin plate's verdict takes the plate's bending stress, as `anvil run`
 * does (yield.c, a long contact): 1 kg at 3 m/s on h = 0.05 r0 stays below
 * Y under the contact (about 630 MPa) but its far face bends to about
 * 1.3 GPa.  Made once when the row or the plan arrives, in either order. */
static void test_verdict_bending(void)
{
	char lay[ANVIL_VERDICT_TEXT_MAX], imp[ANVIL_VERDICT_TEXT_MAX];
	char cli[ANVIL_VERDICT_TEXT_MAX], before[ANVIL_VERDICT_TEXT_MAX];
	struct tui_model *m = fresh();
	struct anvil_solver *s = anvil_solver_alloc();
	anvil_solver_set_cache_dir(s, NULL, NULL);
	type(m, ":layer.thickness=0.05r0\n");
	type(m, ":impactor.mass=1kg\n");
	type(m, ":impact.velocity=3m/s\n");
	type(m, ":solver.accuracy=draft\n");
	type(m, ":effects.contact=physical\n");
	m->sc.models = 1u << ANVIL_MODEL_LAYER;
	give_plan(m);
	tui_model_verdict(m, before, imp, sizeof before);
	ok(!m->have_verdict && !strstr(before, "bending"), "before the row: the plan's (%s)",
	   before);
	deliver_layer(m, s);
	ok(m->have_verdict && m->verdict_gen == m->gen, "the row in: the verdict is made once");
	int fails = tui_model_verdict(m, lay, imp, sizeof lay);
	diag("%s", lay);
	ok(fails == 1 && !strncmp(lay, "layer yields (plate bending): ", 30) &&
		   strstr(lay, "at the far face, Y = ") &&
		   strstr(lay, "; under the contact (Hertz + plate bending) ") && m->verdict.stress < m->verdict.limit,
	   "yields by the bending: contact %.3g MPa, bending %.3g MPa, Y = %.3g MPa",
	   m->verdict.stress * 1e-6, m->verdict.bend * 1e-6, m->verdict.limit * 1e-6);
	/* the CLI's verdict of the same plan (its row run with 400 samples, the
	 * TUI's has 512: verdict.h measured 400 and 2001 samples the same to
	 * 3 digits) */
	struct anvil_verdict v;
	struct anvil_err e = {0};
	int st = anvil_solver_verdict(s, &m->plan, &v, &e);
	anvil_verdict_text(&v, cli, sizeof cli);
	diag("anvil run: %s", cli);
	ok(st >= 0 && v.qs_ratio > 0 && m->verdict.qs_ratio == v.qs_ratio &&
		   v.fate == m->verdict.fate && v.bend_state == 1 && m->verdict.bend_state == 1,
	   "anvil run's rule: long contact (%.2g times 2h/c1), same fate", v.qs_ratio);
	is_rel(m->verdict.bend, v.bend, 1e-2, "  the same bending stress to 1 %% (%.4g MPa)",
	       v.bend * 1e-6);
	ok(strstr(cli, "quasi-static Hertz with the plate's bending at the same instant; the contact alone") &&
		   strstr(cli, "at the layer's computed P_max: the contact lasts") &&
		   strstr(lay, "us, at the layer's computed P_max: the contact lasts"),
	   "  both say which field, and why");
	anvil_verdict_text_screen(&v, cli, sizeof cli);
	ok(!strcmp(words(lay), words(cli)), "  the same words (numbers aside) as the CLI's verdict on a screen");
	/* away and back: the row from the cache before the plan comes */
	m->sel = TUI_F_VELOCITY;
	tui_model_key(m, 'h');
	tui_model_request(m);
	tui_model_key(m, 'l');
	ok(tui_model_request(m) == 0 && !(m->have_verdict && m->verdict_gen == m->gen),
	   "back to the scene: its row from the cache, no verdict before the plan");
	give_plan(m); /* a new generation again: the row from the cache, then the plan */
	tui_model_verdict(m, imp, cli, sizeof imp);
	ok(m->have_verdict && m->verdict_gen == m->gen && !strcmp(imp, lay),
	   "  the plan in: the same verdict");
	anvil_solver_free(s);
	tui_model_free(m);
	memset(m, 0, sizeof *m);
}

/* Issue 15: [effects] is part of a result's key (the engine's), so a
 * change of effects.waves through the model gives new rows, not the old
 * layer rows from the TUI's cache. */
static void test_effects_key(void)
{
	struct tui_model *m = fresh();
	struct anvil_solver *s = anvil_solver_alloc();
	anvil_solver_set_cache_dir(s, NULL, NULL);
	m->sc.models = 1u << ANVIL_MODEL_LAYER;
	ok(tui_model_request(m) == (1u << ANVIL_MODEL_LAYER), "the layer row is asked for");
	deliver_layer(m, s);
	double p_layer = m->rows[ANVIL_MODEL_LAYER].res.Pmax.val;
	is_rel(p_layer, 6.739e3, 1e-3, "the paper's layer: P_max %.4g kN", p_layer * 1e-3);
	type(m, ":effects.waves = halfspace");
	ok(tui_model_key(m, TUI_KEY_ENTER) == TUI_ACT_RECOMPUTE &&
		   m->sc.effects.waves == ANVIL_WAVES_HALFSPACE, "effects.waves = halfspace set");
	ok(tui_model_request(m) == (1u << ANVIL_MODEL_LAYER) && m->run_cached == 0,
	   "not served from the cache: the key holds [effects]");
	deliver_layer(m, s);
	double p_hs = m->rows[ANVIL_MODEL_LAYER].res.Pmax.val;
	is_rel(p_hs, 10.78e3, 1e-3, "new rows: the layer row by the half-space, P_max %.4g kN",
	       p_hs * 1e-3);
	type(m, ":effects.waves = auto");
	tui_model_key(m, TUI_KEY_ENTER);
	ok(tui_model_request(m) == 0 && m->run_cached == 1 &&
		   m->rows[ANVIL_MODEL_LAYER].res.Pmax.val == p_layer,
	   "back to waves = auto: the first rows, from the cache");
	anvil_solver_free(s);
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(189);
	test_canvas_braille();
	test_canvas_ascii();
	test_canvas_edges();
	test_step();
	test_selection();
	test_thickness();
	test_numbers();
	test_display();
	test_units_fit();
	test_materials();
	test_accuracy();
	test_edit();
	test_keys();
	test_geometry();
	test_verdict_mark();
	test_verdict_at_row();
	test_verdict_bending();
	test_models_toggle();
	test_generations();
	test_effects_key();
	return done_testing();
}
