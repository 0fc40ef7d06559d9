/* test_scene: the scene parser on every example, every error path (with its
 * message, file:line and suggestion), anvil_scene_set, check, the write /
 * parse round trip to the bit, the embedded default, names. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cache.h"
#include "scene.h"
#include "tap.h"

static const char *srcdir(void)
{
	const char *d = getenv("top_srcdir");
	return d && *d ? d : ".";
}

static int has(const struct anvil_err *err, const char *want)
{
	if (strstr(err->msg, want))
		return 1;
	diag("  want: %s", want);
	diag("  got:  %s", err->msg);
	return 0;
}

/* Scene a is scene b in every number, name and flag, to the bit. */
static int same_scene(const struct anvil_scene *a, const struct anvil_scene *b)
{
	const struct anvil_body *ba[2] = {&a->impactor, &a->layer};
	const struct anvil_body *bb[2] = {&b->impactor, &b->layer};
	int same = strcmp(a->title, b->title) == 0 &&
		   memcmp(&a->mass, &b->mass, sizeof a->mass) == 0 &&
		   memcmp(&a->radius, &b->radius, sizeof a->radius) == 0 &&
		   memcmp(&a->thickness, &b->thickness, sizeof a->thickness) == 0 &&
		   a->thickness_per_r0 == b->thickness_per_r0 &&
		   memcmp(&a->velocity, &b->velocity, sizeof a->velocity) == 0 &&
		   a->accuracy == b->accuracy && a->scheme == b->scheme &&
		   memcmp(&a->dt, &b->dt, sizeof a->dt) == 0 && a->models == b->models &&
		   a->ncustom == b->ncustom;
	for (int i = 0; same && i < 2; ++i) {
		const struct anvil_body *x = ba[i], *y = bb[i];
		/* Unset overrides are NaN in both: compare set-ness, then bits. */
		const double ox[] = {x->E, x->nu, x->rho, x->yield};
		const double oy[] = {y->E, y->nu, y->rho, y->yield};
		for (int k = 0; k < 4; ++k)
			same &= isnan(ox[k]) ? isnan(oy[k]) : memcmp(&ox[k], &oy[k], sizeof ox[k]) == 0;
		same &= strcmp(x->material, y->material) == 0 &&
			strcmp(x->mat.name, y->mat.name) == 0 &&
			memcmp(&x->mat.E, &y->mat.E, sizeof(double)) == 0 &&
			memcmp(&x->mat.nu, &y->mat.nu, sizeof(double)) == 0 &&
			memcmp(&x->mat.rho, &y->mat.rho, sizeof(double)) == 0 &&
			memcmp(&x->mat.yield, &y->mat.yield, sizeof(double)) == 0;
	}
	for (int i = 0; same && i < a->ncustom; ++i) {
		const struct anvil_material *x = &a->custom[i], *y = &b->custom[i];
		same &= strcmp(x->name, y->name) == 0 && memcmp(&x->E, &y->E, sizeof(double)) == 0 &&
			memcmp(&x->nu, &y->nu, sizeof(double)) == 0 &&
			memcmp(&x->rho, &y->rho, sizeof(double)) == 0 &&
			memcmp(&x->yield, &y->yield, sizeof(double)) == 0;
	}
	return same;
}

/* ---- good files ---- */

static const char *const examples[] = {
	"default.scene",         "table2-h1r0.scene",     "table2-h2r0.scene",
	"table2-h5r0.scene",     "table2-h10r0.scene",    "table2-halfspace.scene",
	"table3-h1r0.scene",     "table3-h2r0.scene",     "table3-h5r0.scene",
	"table3-h10r0.scene",    "table3-halfspace.scene", "custom-material.scene",
	"ball-on-glass.scene",   "ball-drop.scene",       "drop-weight.scene",
};

static void test_examples(void)
{
	struct anvil_scene sc, def;
	struct anvil_err err;
	char path[512];
	anvil_scene_default(&def);
	for (size_t i = 0; i < sizeof examples / sizeof examples[0]; ++i) {
		snprintf(path, sizeof path, "%s/examples/%s", srcdir(), examples[i]);
		anvil_scene_default(&sc);
		int st = anvil_scene_load(&sc, path, &err);
		if (!ok(st == ANVIL_OK, "%s parses", examples[i]))
			diag("  %s", err.msg);
		ok(anvil_scene_check(&sc, &err) == ANVIL_OK, "%s passes check", examples[i]);
		/* Each example is complete: it reads the same on a blank-ish base. */
		struct anvil_scene other;
		anvil_scene_default(&other);
		anvil_scene_set(&other, "impactor.mass", "1 kg", NULL, 0, NULL);
		anvil_scene_set(&other, "solver.models", "hertz", NULL, 0, NULL);
		anvil_scene_load(&other, path, NULL);
		ok(same_scene(&sc, &other), "%s sets every key", examples[i]);
	}
	snprintf(path, sizeof path, "%s/examples/default.scene", srcdir());
	anvil_scene_default(&sc);
	anvil_scene_load(&sc, path, &err);
	ok(same_scene(&sc, &def), "examples/default.scene is the embedded default");

	/* The paper's rows: thickness and speed as the file names say. */
	static const struct {
		const char *file;
		double h_r0, V0;
	} rows[] = {
		{"table2-h1r0.scene", 1, 10},   {"table2-h2r0.scene", 2, 10},
		{"table2-h5r0.scene", 5, 10},   {"table2-h10r0.scene", 10, 10},
		{"table2-halfspace.scene", INFINITY, 10}, {"table3-h1r0.scene", 1, 100},
		{"table3-h10r0.scene", 10, 100}, {"table3-halfspace.scene", INFINITY, 100},
	};
	for (size_t i = 0; i < sizeof rows / sizeof rows[0]; ++i) {
		snprintf(path, sizeof path, "%s/examples/%s", srcdir(), rows[i].file);
		anvil_scene_default(&sc);
		anvil_scene_load(&sc, path, NULL);
		ok(anvil_scene_h(&sc) == rows[i].h_r0 * 4e-3 && sc.velocity == rows[i].V0 &&
			   sc.mass == 12.2e-3 && sc.radius == 4e-3 &&
			   strcmp(sc.impactor.mat.name, "copper") == 0 &&
			   strcmp(sc.layer.mat.name, "steel") == 0,
		   "%s: copper on steel, h = %g r0, V0 = %g m/s", rows[i].file, rows[i].h_r0,
		   rows[i].V0);
	}

	snprintf(path, sizeof path, "%s/examples/custom-material.scene", srcdir());
	anvil_scene_default(&sc);
	anvil_scene_load(&sc, path, NULL);
	ok(sc.ncustom == 1 && strcmp(sc.custom[0].name, "brass") == 0 &&
		   sc.custom[0].rho == 8530 && sc.custom[0].E == 110e9,
	   "custom-material.scene defines brass");
	ok(strcmp(sc.impactor.material, "brass") == 0 &&
		   strcmp(sc.impactor.mat.name, "brass") == 0 && sc.impactor.mat.E == 110e9 &&
		   sc.impactor.mat.nu == 0.375 && sc.impactor.mat.yield == 75e6,
	   "  the impactor is brass, defined after its use");
	ok(strcmp(sc.layer.mat.name, "steel") == 0 && sc.layer.E == 198.5e9 &&
		   sc.layer.mat.E == 198.5e9 && sc.layer.mat.nu == 0.3 && sc.layer.mat.rho == 7830,
	   "  the layer is steel with E overridden before 'material ='");

	snprintf(path, sizeof path, "%s/examples/ball-on-glass.scene", srcdir());
	anvil_scene_default(&sc);
	anvil_scene_load(&sc, path, NULL);
	ok(strcmp(sc.layer.mat.name, "glass") == 0 && sc.layer.mat.E == 72e9 &&
		   strcmp(sc.impactor.mat.name, "steel") == 0 && anvil_scene_h(&sc) == 6e-3 &&
		   !sc.thickness_per_r0,
	   "ball-on-glass.scene: steel on 6 mm glass");
}

static void test_default(void)
{
	struct anvil_scene sc;
	struct anvil_err err;
	struct anvil_scene blank;
	memset(&blank, 0, sizeof blank);
	blank.impactor.E = blank.impactor.nu = blank.impactor.rho = blank.impactor.yield = NAN;
	blank.layer.E = blank.layer.nu = blank.layer.rho = blank.layer.yield = NAN;
	ok(anvil_scene_parse(&blank, anvil_scene_default_text(), "default", &err) == ANVIL_OK,
	   "the embedded default text parses");

	anvil_scene_default(&sc);
	ok(same_scene(&sc, &blank), "anvil_scene_default loads it");
	ok(strcmp(sc.title, "Copper rod on a steel layer (Pyr'yev et al. 2024)") == 0, "title");
	ok(sc.mass == 12.2e-3 && sc.radius == 4e-3 && sc.velocity == 10, "12.2 g, 4 mm, 10 m/s");
	ok(sc.thickness == 1 && sc.thickness_per_r0 && anvil_scene_h(&sc) == 4e-3,
	   "thickness 1 r0 = 4 mm");
	ok(sc.accuracy == ANVIL_ACC_NORMAL && sc.scheme == ANVIL_SCHEME_IMPLICIT && sc.dt == 0 &&
		   sc.models == ANVIL_MODELS_ALL && sc.ncustom == 0,
	   "normal, implicit, dt auto, all models, no custom material");
	ok(strcmp(sc.impactor.material, "copper") == 0 && sc.impactor.mat.E == 123e9 &&
		   sc.impactor.mat.nu == 0.34 && sc.impactor.mat.rho == 8960 &&
		   strcmp(sc.impactor.mat.name, "copper") == 0,
	   "impactor copper, resolved");
	ok(strcmp(sc.layer.material, "steel") == 0 && sc.layer.mat.E == 209e9 &&
		   sc.layer.mat.rho == 7830 && isnan(sc.layer.E) && isnan(sc.impactor.nu),
	   "layer steel, resolved, no overrides");
	ok(anvil_scene_check(&sc, &err) == ANVIL_OK, "default passes check");
}

/* ---- parser features ---- */

static void test_features(void)
{
	struct anvil_scene sc;
	struct anvil_err err;
	int st;

	anvil_scene_default(&sc);
	st = anvil_scene_parse(&sc,
			       "  # comment\n; comment\n\n"
			       "[ Impactor ]   # header comment\r\n"
			       "MASS=5g ; trailing\n"
			       "  radius   =   2.5mm\n"
			       "[layer]\n"
			       "thickness = 2r0\n"
			       "nu = 0.29\n"
			       "material = Steel\n"
			       "[scene]\n"
			       "title = Run#3; a test\n"
			       "[solver]\n"
			       "models = Layer , hertz\n"
			       "dt = 0.16 us\n"
			       "accuracy = FINE\n"
			       "scheme = paper",
			       "f.scene", &err);
	if (!ok(st == ANVIL_OK, "comments, CRLF, case, spacing, no final newline"))
		diag("  %s", err.msg);
	ok(sc.mass == 5e-3 && sc.radius == 2.5e-3, "  mass and radius");
	ok(sc.thickness == 2 && sc.thickness_per_r0 && anvil_scene_h(&sc) == 5e-3,
	   "  '2r0' is 2 r0 of the new radius");
	ok(sc.layer.mat.nu == 0.29 && sc.layer.nu == 0.29 && strcmp(sc.layer.material, "steel") == 0,
	   "  override before the material line; name canonical");
	ok(strcmp(sc.title, "Run#3; a test") == 0, "  '#' and ';' not after a space are text");
	ok(sc.models == ((1u << ANVIL_MODEL_LAYER) | (1u << ANVIL_MODEL_HERTZ)),
	   "  models list");
	ok(sc.dt == 0.16e-6 && sc.accuracy == ANVIL_ACC_FINE && sc.scheme == ANVIL_SCHEME_PAPER,
	   "  dt, accuracy, scheme");

	/* Parsing is on top: what the text does not set is kept, overrides too. */
	st = anvil_scene_parse(&sc, "[layer]\nmaterial = copper\n", "g", &err);
	ok(st == ANVIL_OK && sc.mass == 5e-3 && sc.layer.mat.nu == 0.29 &&
		   sc.layer.mat.E == 123e9 && strcmp(sc.layer.mat.name, "copper") == 0,
	   "a new material keeps the overrides on top of it");

	st = anvil_scene_parse(&sc, "[layer]\nthickness = inf\n[solver]\nmodels = all\ndt = auto", "g",
			       &err);
	ok(st == ANVIL_OK && isinf(sc.thickness) && !sc.thickness_per_r0 &&
		   isinf(anvil_scene_h(&sc)) && sc.models == ANVIL_MODELS_ALL && sc.dt == 0,
	   "thickness inf, models all, dt auto");
	st = anvil_scene_parse(&sc, "[layer]\nthickness = 8 mm", "g", &err);
	ok(st == ANVIL_OK && sc.thickness == 8e-3 && !sc.thickness_per_r0 &&
		   anvil_scene_h(&sc) == 8e-3, "thickness 8 mm");
	st = anvil_scene_parse(&sc, "[solver]\nmodels = hertz, all", "g", &err);
	ok(st == ANVIL_OK && sc.models == ANVIL_MODELS_ALL, "'all' inside a list");
	st = anvil_scene_parse(&sc, "[scene]\ntitle = Hello ; world # comment\n", "g", &err);
	ok(st == ANVIL_OK && strcmp(sc.title, "Hello") == 0, "a comment after the title");
	st = anvil_scene_parse(&sc, "", "g", &err);
	ok(st == ANVIL_OK, "empty text is fine");
	ok(anvil_scene_parse(&sc, "[scene]\ntitle =\n", "g", &err) == ANVIL_OK && sc.title[0] == 0,
	   "empty title");

	/* A material defined in the text, used before and after. */
	anvil_scene_default(&sc);
	st = anvil_scene_parse(&sc,
			       "[impactor]\nmaterial = Bronze\nrho = 8.7 g/cm3\n"
			       "[material bronze]\nE = 110 GPa\nnu = 0.34\nrho = 8800 kg/m^3\n"
			       "[layer]\nmaterial = bronze\n",
			       "m.scene", &err);
	if (!ok(st == ANVIL_OK, "[material bronze] used before its definition"))
		diag("  %s", err.msg);
	ok(strcmp(sc.impactor.material, "bronze") == 0 && sc.impactor.mat.rho == 8700 &&
		   sc.impactor.mat.E == 110e9 && sc.impactor.mat.yield == 0 &&
		   sc.layer.mat.rho == 8800,
	   "  resolved on both bodies, the impactor's rho overridden; yield defaults to 0");
	ok(sc.custom[0].source && sc.impactor.mat.source && sc.layer.mat.source,
	   "  sources set");
	/* A second text may extend it. */
	st = anvil_scene_parse(&sc, "[material bronze]\nyield = 200 MPa\n", "n", &err);
	ok(st == ANVIL_OK && sc.ncustom == 1 && sc.layer.mat.yield == 200e6,
	   "a later [material bronze] changes it and the bodies follow");
}

/* ---- parse errors ---- */

static const struct {
	const char *text;
	const char *msg;
} parse_errors[] = {
	{"[impactor]\nmass = abc\n",
	 "t.scene:2: impactor.mass: expected a mass such as '12.2 g', got 'abc'"},
	{"[impactor]\nmass = 4 mm\n",
	 "t.scene:2: impactor.mass: expected a mass such as '12.2 g', got 'mm' (a length)"},
	{"[impactor]\nmass = -1 g\n",
	 "t.scene:2: impactor.mass: must be within 1e-12 .. 1e+06 kg, got '-1 g'"},
	{"[impactor]\nmass = 0 g\n", "t.scene:2: impactor.mass: must be within 1e-12 .. 1e+06 kg, got '0 g'"},
	{"[impactor]\nmass = 0\n", "t.scene:2: impactor.mass: '0' needs a unit, e.g. 0 g (masses: kg, g, mg)"},
	{"[impactor]\nradius = 4\n",
	 "t.scene:2: impactor.radius: '4' needs a unit, e.g. 4 mm (lengths: m, cm, mm, um)"},
	{"[impactor]\nmass = 1e300 kg\n", "t.scene:2: impactor.mass: must be within 1e-12 .. 1e+06 kg"},
	{"[impactor]\nradius = 1e308 m\n", "t.scene:2: impactor.radius: must be within 1e-09 .. 1000 m"},
	{"[impact]\nvelocity = 1e-300 m/s\n", "t.scene:2: impact.velocity: must be within 1e-06 .. 100000 m/s"},
	{"[impact]\nvelocity = 10\n", "t.scene:2: impact.velocity: '10' needs a unit, e.g. 10 m/s"},
	{"[layer]\nE = 1e10 GPa\n", "t.scene:2: layer.E: must be within 1000 .. 1e+15 Pa, got '1e10 GPa'"},
	{"[layer]\nE = 1e300 GPa\n", "t.scene:2: layer.E: '1e300 GPa' is out of range"},
	{"[layer]\nE = 200e9\n", "t.scene:2: layer.E: '200e9' needs a unit, e.g. 200e9 GPa"},
	{"[layer]\nrho = 7830\n", "t.scene:2: layer.rho: '7830' needs a unit"},
	{"[layer]\nnu = -0.9999999999999999\n", "t.scene:2: layer.nu: must be within -0.99 .. 0.49999"},
	{"[layer]\nthickness = 4\n", "t.scene:2: layer.thickness: '4' needs a unit, e.g. 4 mm or 4 r0"},
	{"[layer]\nthickness = 1e300 r0\n", "t.scene:2: layer.thickness: must be within 1e-06 .. 1e+06 r0"},
	{"[solver]\ndt = 1e-7\n", "t.scene:2: solver.dt: '1e-7' needs a unit, e.g. 1e-7 us"},
	{"[solver]\ndt = 1e-300 s\n", "t.scene:2: solver.dt: must be within 1e-15 .. 1 s"},
	{"[output]\nhistories= #\n", "t.scene:2: output.histories: expected a file name or 'off'"},
	{"[scene]\ntitle = \"abc\n", "t.scene:2: scene.title: missing the closing '\"'"},
	{"[scene]\ntitle = \"abc\" def\n", "t.scene:2: scene.title: unexpected text after the closing '\"': ' def'"},
	{"[scene]\ntitle = caf\xe9\n", "t.scene:2: scene.title: is not valid UTF-8 text"},
	{"[scene]\ntitle = \xc0\xaf\n", "t.scene:2: scene.title: is not valid UTF-8 text"},
	{"[scene]\ntitle = \xed\xa0\x80\n", "t.scene:2: scene.title: is not valid UTF-8 text"},
	{"[output]\ncharts = \xff\n", "t.scene:2: output.charts: is not valid UTF-8 text"},
	{"[layer]\nmaterial = brass\n",
	 "t.scene:2: layer.material: 'brass' is not a built-in material: define it with [material brass]"},
	{"[impactor]\nmass = nan\n", "t.scene:2: impactor.mass: expected a mass"},
	{"[impactor]\nmass = inf g\n", "t.scene:2: impactor.mass: expected a mass"},
	{"[impactor]\nmass = 12 g extra\n", "t.scene:2: impactor.mass: expected a mass"},
	{"[impactor]\nmass = 12 g#x\n", "t.scene:2: impactor.mass: expected a mass"},
	{"[impactor]\nmass =\n", "t.scene:2: impactor.mass: expected a mass such as '12.2 g', got ''"},
	{"[impactor]\nradius = 1 kg\n", "t.scene:2: impactor.radius: expected a length"},
	{"[impact]\nvelocity = -10 m/s\n", "t.scene:2: impact.velocity: must be within"},
	{"[impact]\nvelocity = 10 m\n", "t.scene:2: impact.velocity: expected a velocity"},
	{"mass = 1 g\n", "t.scene:1: 'mass' is outside any section"},
	{"\n\n[impactor]\nmass 12 g\n", "t.scene:4: expected KEY = VALUE, got 'mass 12 g'"},
	{"[impactor]\n= 5\n", "t.scene:2: expected KEY = VALUE, got no key"},
	{"[impactor]\nmass = 1 g\nradius = 1 mm\nmass = 2 g\n",
	 "t.scene:4: impactor.mass: set twice (first on line 2)"},
	{"[impactor]\nmass = 1 g\n[layer]\n[impactor]\nMass = 2 g\n",
	 "t.scene:5: impactor.Mass: set twice (first on line 2)"},
	{"[material foo]\nE = 1 GPa\nnu = 0.3\nrho = 1000 kg/m3\n[material FOO]\nE = 2 GPa\n",
	 "t.scene:6: material.foo.E: set twice (first on line 2)"},
	{"[impactor\nmass = 1 g\n", "t.scene:1: unterminated section header '[impactor'"},
	{"[impactor] mass = 1 g\n", "t.scene:1: unexpected text after ']': 'mass = 1 g'"},
	{"[impactor extra]\n", "t.scene:1: unexpected 'extra' in section header [impactor]"},
	{"[impactr]\n", "t.scene:1: unknown section 'impactr'; did you mean 'impactor'?"},
	{"[lay]\n", "t.scene:1: unknown section 'lay'; did you mean 'layer'?"},
	{"[]\n", "t.scene:1: unknown section ''"},
	{"[frobnicate]\n", "t.scene:1: unknown section 'frobnicate' (sections: scene"},
	{"[impactor]\nmas = 1 g\n", "t.scene:2: impactor.mas: unknown key; did you mean 'impactor.mass'?"},
	{"[layer]\nthicknes = 1 r0\n",
	 "t.scene:2: layer.thicknes: unknown key; did you mean 'layer.thickness'?"},
	{"[layer]\nthick = 1 r0\n", "t.scene:2: layer.thick: unknown key; did you mean 'layer.thickness'?"},
	{"[impactor]\nvelocity = 1 m/s\n",
	 "t.scene:2: impactor.velocity: unknown key; did you mean 'impact.velocity'?"},
	{"[layer]\nradius = 1 mm\n", "t.scene:2: layer.radius: unknown key; did you mean 'impactor.radius'?"},
	{"[impactor]\nzzzz = 1\n",
	 "t.scene:2: impactor.zzzz: unknown key (keys of [impactor]: material, shape, mass, radius, diameter, length, E, nu, rho, yield, tensile, brittle)"},
	{"[impactor]\nx = 1\n", "t.scene:2: impactor.x: unknown key (keys of"},
	{"[layer]\nmaterial = stel\n",
	 "t.scene:2: layer.material: unknown material 'stel'; did you mean 'steel'?"},
	{"[layer]\nmaterial = copr\n", "did you mean 'copper'?"},
	{"[layer]\nmaterial = alum\n", "did you mean 'aluminium'?"},
	{"[layer]\nmaterial = unobtainium\n",
	 "t.scene:2: layer.material: unknown material 'unobtainium' (known: copper, steel"},
	{"[layer]\nmaterial = glas\n", "t.scene:2: layer.material: unknown material 'glas'; did you mean 'glass'?"},
	{"[layer]\nmaterial = crass\n", "t.scene:2: layer.material: unknown material 'crass' (known:"},
	{"[impactor]\nmaterial = brss\n[material brass]\nE = 1 GPa\nnu = 0.3\nrho = 1000 kg/m3\n",
	 "t.scene:2: impactor.material: unknown material 'brss'; did you mean 'brass'?"},
	{"[layer]\nmaterial = 1abc\n", "t.scene:2: layer.material: expected a material name"},
	{"[layer]\nmaterial = two words\n", "t.scene:2: layer.material: expected a material name"},
	{"[layer]\nthickness = abc\n",
	 "t.scene:2: layer.thickness: expected a length such as '4 mm' or '2 r0'"},
	{"[layer]\nthickness = r0\n", "t.scene:2: layer.thickness: expected a length"},
	{"[layer]\nthickness = 2 kg\n", "t.scene:2: layer.thickness: expected a length"},
	{"[layer]\nthickness = 0 mm\n", "t.scene:2: layer.thickness: must be > 0, got '0 mm'"},
	{"[layer]\nthickness = -2 r0\n", "t.scene:2: layer.thickness: must be > 0, got '-2 r0'"},
	{"[layer]\nthickness = nan r0\n", "t.scene:2: layer.thickness: expected a length"},
	{"[layer]\nnu = 0.6\n", "t.scene:2: layer.nu: must be within -0.99 .. 0.49999, got '0.6'"},
	{"[layer]\nnu = -1\n", "t.scene:2: layer.nu: must be within -0.99 .. 0.49999, got '-1'"},
	{"[impactor]\nE = 0 GPa\n", "t.scene:2: impactor.E: must be within 1000 .. 1e+15 Pa, got '0 GPa'"},
	{"[impactor]\nrho = 7.8 GPa\n", "t.scene:2: impactor.rho: expected a density such as '7.8 g/cm3', got 'GPa' (a pressure)"},
	{"[impactor]\nyield = -1 MPa\n", "t.scene:2: impactor.yield: must be within 0 .. 1e+15 Pa, got '-1 MPa'"},
	{"[solver]\ndt = -1 us\n", "t.scene:2: solver.dt: must be within 1e-15 .. 1 s, got '-1 us'"},
	{"[solver]\ndt = fast\n", "t.scene:2: solver.dt: expected a time such as '0.16 us' or 'auto', got 'fast'"},
	{"[solver]\nmodels =\n", "t.scene:2: solver.models: expected a list of models"},
	{"[solver]\nmodels = ,\n", "t.scene:2: solver.models: expected a list of models"},
	{"[solver]\nmodels = hertz, zenr\n",
	 "t.scene:2: solver.models: expected hertz, zener, layer, halfspace or 'all', got 'zenr'; did you mean 'zener'?"},
	{"[solver]\nmodels = hertz,,plate\n", "got 'plate'"},
	{"[solver]\naccuracy = medium\n",
	 "t.scene:2: solver.accuracy: expected draft, normal, fine or reference, got 'medium'"},
	{"[solver]\naccuracy = fin\n", "got 'fin'; did you mean 'fine'?"},
	{"[solver]\nscheme = explicit\n", "t.scene:2: solver.scheme: expected implicit or paper, got 'explicit'"},
	{"[solver]\nscheme = papr\n", "did you mean 'paper'?"},
	{"[material steel]\n", "t.scene:1: [material steel]: 'steel' is a built-in material"},
	{"[material Aluminum]\n", "t.scene:1: [material Aluminum]: 'Aluminum' is a built-in material"},
	{"[material]\n", "t.scene:1: expected [material NAME]"},
	{"[material 9x]\n", "t.scene:1: [material 9x]: expected a material name"},
	{"[material foo]\nE = 1 GPa\nnu = 0.3\n", "t.scene:1: material.foo: material 'foo' is incomplete: rho is not set"},
	{"\n[material foo]\n", "t.scene:2: material.foo: material 'foo' is incomplete: E is not set"},
	{"[material foo]\nE = 1 GPa\nnu = 0.7\n", "t.scene:3: material.foo.nu: must be within -0.99 .. 0.49999"},
	{"[material foo]\nEE = 1 GPa\n", "t.scene:2: material.foo.EE: unknown key; did you mean 'material.foo.E'?"},
	{"[material foo]\nmass = 1 g\n", "t.scene:2: material.foo.mass: unknown key; did you mean 'impactor.mass'?"},
	{"[scene]\ntitle = 0123456789012345678901234567890123456789012345678901234567890123"
	 "4567890123456789012345678901234567890123456789012345678901234567890123456789\n",
	 "t.scene:2: scene.title: longer than 127 bytes"},
};

static void test_parse_errors(void)
{
	struct anvil_scene sc, before;
	struct anvil_err err;
	for (size_t i = 0; i < sizeof parse_errors / sizeof parse_errors[0]; ++i) {
		anvil_scene_default(&sc);
		before = sc;
		anvil_err_clear(&err);
		int st = anvil_scene_parse(&sc, parse_errors[i].text, "t.scene", &err);
		ok(st == ANVIL_EPARSE && err.status == ANVIL_EPARSE, "error %zu is ANVIL_EPARSE", i);
		ok(has(&err, parse_errors[i].msg), "  \"%s\"", parse_errors[i].msg);
		ok(memcmp(&sc, &before, sizeof sc) == 0, "  the scene is unchanged");
		ok(strchr(err.msg, '\n') == NULL, "  on one line");
	}

	/* Seventeen materials is one too many. */
	char text[4096] = "";
	size_t len = 0;
	for (int i = 0; i <= ANVIL_MAX_CUSTOM; ++i)
		len += (size_t)snprintf(text + len, sizeof text - len,
					"[material m%d]\nE = 1 GPa\nnu = 0.3\nrho = 1000 kg/m3\n", i);
	anvil_scene_default(&sc);
	ok(anvil_scene_parse(&sc, text, "t.scene", &err) == ANVIL_EPARSE &&
		   has(&err, "t.scene:65: [material m16]: too many materials (at most 16)"),
	   "too many materials");

	/* A line too long for the buffer. */
	char *longline = malloc(3000);
	memset(longline, 'a', 2999);
	longline[2999] = '\0';
	memcpy(longline, "[scene]\n", 8);
	ok(anvil_scene_parse(&sc, longline, "t.scene", &err) == ANVIL_EPARSE &&
		   has(&err, "t.scene:2: line longer than 1023 characters"),
	   "an overlong line");
	free(longline);

	ok(anvil_scene_parse(&sc, "[impactor]\nmass = x\n", NULL, &err) == ANVIL_EPARSE &&
		   has(&err, "scene:2: impactor.mass"), "NULL origin reads 'scene'");
	ok(anvil_scene_parse(&sc, "[impactor]\nmass = x\n", "t", NULL) == ANVIL_EPARSE,
	   "NULL err is fine");
}

/* ---- anvil_scene_set ---- */

static void test_set(void)
{
	struct anvil_scene sc, before;
	struct anvil_err err;

	anvil_scene_default(&sc);
	ok(anvil_scene_set(&sc, "layer.thickness", "5r0", "cli", 1, &err) == ANVIL_OK &&
		   sc.thickness == 5 && sc.thickness_per_r0, "set layer.thickness = 5r0");
	ok(anvil_scene_set(&sc, "impactor.E", "100 GPa", NULL, 0, &err) == ANVIL_OK &&
		   sc.impactor.E == 100e9 && sc.impactor.mat.E == 100e9,
	   "set impactor.E: override and resolved");
	ok(anvil_scene_set(&sc, "impactor.material", "steel", NULL, 0, &err) == ANVIL_OK &&
		   strcmp(sc.impactor.mat.name, "steel") == 0 && sc.impactor.mat.E == 100e9 &&
		   sc.impactor.mat.rho == 7830,
	   "set impactor.material keeps the override");
	sc.impactor.E = NAN; /* how the TUI clears an override */
	ok(anvil_scene_set(&sc, "impactor.material", "copper", NULL, 0, &err) == ANVIL_OK &&
		   sc.impactor.mat.E == 123e9, "cleared override, then material: resolved afresh");
	ok(anvil_scene_set(&sc, "Solver.Models", " zener ", NULL, 0, &err) == ANVIL_OK &&
		   sc.models == 1u << ANVIL_MODEL_ZENER, "section and key are case-insensitive");

	/* Custom materials by key. */
	ok(anvil_scene_set(&sc, "material.brass.E", "110 GPa", NULL, 0, &err) == ANVIL_OK &&
		   sc.ncustom == 1 && sc.custom[0].E == 110e9 && isnan(sc.custom[0].rho),
	   "material.brass.E creates brass");
	before = sc;
	ok(anvil_scene_set(&sc, "layer.material", "brass", NULL, 0, &err) == ANVIL_EPARSE &&
		   has(&err, "command line: layer.material: material 'brass' is incomplete: nu is not set"),
	   "an incomplete material cannot be used");
	ok(memcmp(&sc, &before, sizeof sc) == 0, "  and the scene is unchanged");
	ok(anvil_scene_check(&sc, &err) == ANVIL_EINVAL &&
		   has(&err, "material.brass: material 'brass' is incomplete"),
	   "check reports the incomplete material");
	anvil_scene_set(&sc, "material.brass.nu", "0.35", NULL, 0, &err);
	anvil_scene_set(&sc, "material.brass.rho", "8.5 g/cm3", NULL, 0, &err);
	ok(anvil_scene_set(&sc, "layer.material", "BRASS", NULL, 0, &err) == ANVIL_OK &&
		   strcmp(sc.layer.material, "brass") == 0 && sc.layer.mat.rho == 8500 &&
		   anvil_scene_check(&sc, &err) == ANVIL_OK,
	   "complete: the layer is brass");
	ok(anvil_scene_set(&sc, "material.brass.E", "120 GPa", NULL, 0, &err) == ANVIL_OK &&
		   sc.layer.mat.E == 120e9, "changing brass changes the layer");

	static const struct {
		const char *key, *value, *origin;
		int line;
		const char *msg;
	} bad[] = {
		{"layer.thicknes", "5r0", NULL, 0,
		 "command line: layer.thicknes: unknown key; did you mean 'layer.thickness'?"},
		{"layr.thickness", "5r0", NULL, 0,
		 "command line: layr.thickness: unknown section 'layr'; did you mean 'layer'?"},
		{"mass", "5 g", NULL, 0, "command line: mass: unknown key; did you mean 'impactor.mass'?"},
		{"mas", "5 g", NULL, 0, "command line: mas: unknown key; did you mean 'impactor.mass'?"},
		{"zzzz", "5 g", NULL, 0, "command line: zzzz: unknown key (keys are SECTION.KEY"},
		{"layer.thickness", "abc", "cli", 3,
		 "cli:3: layer.thickness: expected a length such as '4 mm' or '2 r0', got 'abc'"},
		{"layer.thickness", "abc", NULL, 0, "command line: layer.thickness: expected a length"},
		{"impactor.material", "bras", "tui", 0,
		 "tui: impactor.material: unknown material 'bras'; did you mean 'brass'?"},
		{"material.steel.E", "1 GPa", NULL, 0,
		 "command line: material.steel.E: 'steel' is a built-in material"},
		{"material.brass", "1 GPa", NULL, 0, "command line: material.brass: expected material.NAME.KEY"},
		{"material.brass.E", "-1 GPa", NULL, 0, "command line: material.brass.E: must be within"},
		{"impactor.radius", "1e308", NULL, 0, "command line: impactor.radius: '1e308' needs a unit"},
		{"impactor.radius", "1e308 m", NULL, 0, "command line: impactor.radius: must be within 1e-09 .. 1000 m"},
		{"impactor.mass", "1e300 kg", NULL, 0, "command line: impactor.mass: must be within"},
		{"impact.velocity", "1e-300 m/s", NULL, 0, "command line: impact.velocity: must be within"},
		{"layer.E", "1e300 Pa", NULL, 0, "command line: layer.E: must be within"},
		{"impactor.nu", "-0.9999999999999999", NULL, 0, "command line: impactor.nu: must be within -0.99 .. 0.49999"},
		{"scene.title", "caf\xe9", NULL, 0, "command line: scene.title: is not valid UTF-8 text"},
		{"impactor.material", "bronze", NULL, 0, "'bronze' is not a built-in material"},
		{"material.brass.foo", "1", NULL, 0,
		 "command line: material.brass.foo: unknown key (keys of [material]: E, nu, rho, yield, tensile, brittle)"},
		{"material.a.b.c.E", "1 GPa", NULL, 0, "expected a material name"},
		{"impactor.nu", "0.5", NULL, 0, "command line: impactor.nu: must be within -0.99 .. 0.49999, got '0.5'"},
		{"solver.dt", "soon", NULL, 0, "command line: solver.dt: expected a time"},
		{"scene.title", "two\tlines", NULL, 0, "command line: scene.title: must be one line"},
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
		before = sc;
		anvil_err_clear(&err);
		int st = anvil_scene_set(&sc, bad[i].key, bad[i].value, bad[i].origin, bad[i].line,
					 &err);
		ok(st == ANVIL_EPARSE && has(&err, bad[i].msg), "set %s = '%s': \"%s\"", bad[i].key,
		   bad[i].value, bad[i].msg);
		ok(memcmp(&sc, &before, sizeof sc) == 0, "  the scene is unchanged");
	}
	ok(anvil_scene_set(&sc, "impact.velocity", "1 m/s", NULL, 0, NULL) == ANVIL_OK &&
		   sc.velocity == 1, "NULL err is fine");

	/* Too many materials by key. */
	anvil_scene_default(&sc);
	char key[64];
	for (int i = 0; i < ANVIL_MAX_CUSTOM; ++i) {
		snprintf(key, sizeof key, "material.m%d.E", i);
		anvil_scene_set(&sc, key, "1 GPa", NULL, 0, NULL);
	}
	ok(sc.ncustom == ANVIL_MAX_CUSTOM &&
		   anvil_scene_set(&sc, "material.one-more.E", "1 GPa", NULL, 0, &err) == ANVIL_EPARSE &&
		   has(&err, "too many materials (at most 16)"), "the 17th material is refused");
}

/* ---- check ---- */

static void test_check(void)
{
	struct anvil_scene def, sc;
	struct anvil_err err;
	anvil_scene_default(&def);
#define BAD(stmt, want)                                                              \
	do {                                                                         \
		sc = def;                                                            \
		stmt;                                                                \
		ok(anvil_scene_check(&sc, &err) == ANVIL_EINVAL && has(&err, want),  \
		   "check: %s -> \"%s\"", #stmt, want);                               \
	} while (0)
	BAD(sc.mass = 0, "impactor.mass: must be within 1e-12 .. 1e+06 kg, got '0 kg'");
	BAD(sc.mass = NAN, "impactor.mass: must be within 1e-12 .. 1e+06 kg, got 'nan kg'");
	BAD(sc.radius = -1, "impactor.radius: must be within 1e-09 .. 1000 m, got '-1 m'");
	BAD(sc.velocity = INFINITY, "impact.velocity: must be within 1e-06 .. 100000 m/s, got 'inf m/s'");
	BAD(sc.thickness = 0, "layer.thickness: must give h within 1e-09 .. 1000 m or inf, got 0 r0");
	BAD(sc.thickness = NAN, "layer.thickness");
	BAD(sc.thickness = INFINITY, "layer.thickness: must give h within 1e-09 .. 1000 m or inf, got inf r0");
	BAD(sc.thickness = 1e6, "layer.thickness: must give h within 1e-09 .. 1000 m or inf, got 1e+06 r0");
	BAD(sc.dt = -1e-6, "solver.dt: must be within 1e-15 .. 1 s");

	BAD(sc.dt = NAN, "solver.dt");
	BAD(sc.models = 0, "solver.models");
	BAD(sc.models = 1u << 7, "solver.models");
	BAD(sc.accuracy = (enum anvil_accuracy)9, "solver.accuracy");
	BAD(sc.scheme = (enum anvil_scheme)9, "solver.scheme");
	BAD(sc.ncustom = -1, "custom materials");
	BAD(sc.layer.mat.nu = 0.6, "layer: material 'steel': nu = 0.6 is not in (-1, 0.5)");
	BAD(sc.impactor.mat.E = 0, "impactor: material 'copper': E = 0 Pa is not > 0");
#undef BAD
	sc = def;
	sc.thickness = INFINITY;
	sc.thickness_per_r0 = 0;
	ok(anvil_scene_check(&sc, NULL) == ANVIL_OK, "a half-space is fine");
	sc.dt = 0;
	ok(anvil_scene_check(&sc, &err) == ANVIL_OK && err.status == ANVIL_OK && !err.msg[0],
	   "check clears err on success");
}

/* ---- round trip ---- */

static int round_trip(const struct anvil_scene *sc, const char *what)
{
	char *text = NULL;
	size_t size = 0;
	struct anvil_scene back;
	struct anvil_err err;
	FILE *out = open_memstream(&text, &size);
	int st = anvil_scene_write(sc, out);
	fclose(out);
	ok(st == ANVIL_OK, "%s: write", what);
	anvil_scene_default(&back);
	st = anvil_scene_parse(&back, text, "written", &err);
	if (!ok(st == ANVIL_OK, "%s: the written text parses", what))
		diag("  %s", err.msg);
	int same = same_scene(sc, &back);
	if (!ok(same, "%s: reads back to the same bits", what))
		diag("%s", text);
	free(text);
	return same;
}

static void test_round_trip(void)
{
	struct anvil_scene sc;
	char path[512];

	anvil_scene_default(&sc);
	round_trip(&sc, "default");

	snprintf(path, sizeof path, "%s/examples/custom-material.scene", srcdir());
	anvil_scene_default(&sc);
	anvil_scene_load(&sc, path, NULL);
	round_trip(&sc, "custom material and override");

	/* Awkward numbers: every one needs 17 digits or a unit conversion. */
	static const char *const odd[][2] = {
		{"impactor.mass", "0.1 mg"},      {"impactor.radius", "0.7 um"},
		{"layer.thickness", "0.3 mm"},    {"impact.velocity", "1 km/h"},
		{"solver.dt", "0.16 us"},         {"solver.models", "hertz, halfspace"},
		{"solver.accuracy", "reference"}, {"solver.scheme", "paper"},
		{"layer.nu", "0.1"},              {"layer.rho", "7.77 g/cm3"},
		{"impactor.yield", "0.3 GPa"},    {"scene.title", "Odd numbers: 1/3 & friends"},
	};
	int failed = 0;
	anvil_scene_default(&sc);
	for (size_t i = 0; i < sizeof odd / sizeof odd[0]; ++i)
		failed += anvil_scene_set(&sc, odd[i][0], odd[i][1], NULL, 0, NULL) != ANVIL_OK;
	ok(failed == 0, "set awkward values");
	sc.mass = nextafter(sc.mass, 1.0);
	sc.velocity = 1.0 / 3.0;
	round_trip(&sc, "awkward numbers");

	/* Half-space, r0 multiples that are not round, custom materials. */
	anvil_scene_default(&sc);
	anvil_scene_set(&sc, "layer.thickness", "inf", NULL, 0, NULL);
	anvil_scene_set(&sc, "material.unobtainium.E", "1e3 GPa", NULL, 0, NULL);
	anvil_scene_set(&sc, "material.unobtainium.nu", "-0.2", NULL, 0, NULL);
	anvil_scene_set(&sc, "material.unobtainium.rho", "123.456 kg/m3", NULL, 0, NULL);
	anvil_scene_set(&sc, "material.unobtainium.yield", "1.1 MPa", NULL, 0, NULL);
	anvil_scene_set(&sc, "material.b2.E", "3 GPa", NULL, 0, NULL);
	anvil_scene_set(&sc, "material.b2.nu", "0.4999", NULL, 0, NULL);
	anvil_scene_set(&sc, "material.b2.rho", "1 kg/m3", NULL, 0, NULL);
	anvil_scene_set(&sc, "impactor.material", "unobtainium", NULL, 0, NULL);
	anvil_scene_set(&sc, "impactor.E", "1 kPa", NULL, 0, NULL);
	ok(sc.ncustom == 2 && strcmp(sc.impactor.mat.name, "unobtainium") == 0 &&
		   sc.impactor.mat.E == 1e3, "a scene with two custom materials");
	round_trip(&sc, "half-space and custom materials");
	anvil_scene_set(&sc, "layer.thickness", "2.2 r0", NULL, 0, NULL);
	sc.thickness = 0.1 + 0.2;
	round_trip(&sc, "thickness 0.1 + 0.2 r0");

	/* Writing to a stream that fails. */
	FILE *ro = fopen(path, "r");
	if (ro) {
		anvil_scene_default(&sc);
		ok(anvil_scene_write(&sc, ro) == ANVIL_EIO, "write to a read-only stream: ANVIL_EIO");
		fclose(ro);
	}
}

/* ---- load ---- */

static void test_load(void)
{
	struct anvil_scene sc, before;
	struct anvil_err err;
	anvil_scene_default(&sc);
	before = sc;
	ok(anvil_scene_load(&sc, "/nonexistent/x.scene", &err) == ANVIL_EIO &&
		   has(&err, "/nonexistent/x.scene: cannot open: No such file or directory"),
	   "a missing file: ANVIL_EIO, 'FILE: cannot open: strerror'");
	ok(memcmp(&sc, &before, sizeof sc) == 0, "  scene unchanged");

	char dir[] = "/tmp/anvil-test-scene-XXXXXX";
	char path[600];
	if (!mkdtemp(dir)) {
		ok(0, "mkdtemp");
		return;
	}
	snprintf(path, sizeof path, "%s/bad.scene", dir);
	FILE *f = fopen(path, "w");
	fputs("[impactor]\nmass = 2 g\n\n[layer]\nthickness = 3 furlongs\n", f);
	fclose(f);
	ok(anvil_scene_load(&sc, path, &err) == ANVIL_EPARSE,
	   "a bad file is ANVIL_EPARSE");
	char want[700];
	snprintf(want, sizeof want, "%s:5: layer.thickness: expected a length", path);
	ok(has(&err, want), "  message names the file and line");
	ok(memcmp(&sc, &before, sizeof sc) == 0, "  scene unchanged");

	f = fopen(path, "w");
	fwrite("[impactor]\0mass = 2 g\n", 1, 22, f);
	fclose(f);
	ok(anvil_scene_load(&sc, path, &err) == ANVIL_EPARSE && has(&err, "NUL byte"),
	   "a binary file is refused");

	/* "-" is standard input. */
	f = fopen(path, "w");
	fputs("[impact]\nvelocity = 33 m/s\n", f);
	fclose(f);
	if (freopen(path, "r", stdin)) {
		ok(anvil_scene_load(&sc, "-", &err) == ANVIL_OK && sc.velocity == 33,
		   "'-' reads standard input");
		f = fopen(path, "w");
		fputs("[impact]\nvelocity = x\n", f);
		fclose(f);
		ok(freopen(path, "r", stdin) && anvil_scene_load(&sc, "-", &err) == ANVIL_EPARSE &&
			   has(&err, "<stdin>:2: impact.velocity"),
		   "  errors name <stdin>");
	}
	remove(path);
	snprintf(path, sizeof path, "%s", dir);
	ok(anvil_scene_load(&sc, path, &err) != ANVIL_OK, "a directory is not a scene");
	remove(dir);
}


/* ---- issue 13: hardening (each with the reported reproducer) ---- */

/* sc written and parsed back; the text in *out (caller frees) if out. */
static int write_parse(const struct anvil_scene *sc, struct anvil_scene *back, char **out)
{
	char *text = NULL;
	size_t size = 0;
	struct anvil_err err;
	FILE *f = open_memstream(&text, &size);
	anvil_scene_write(sc, f);
	fclose(f);
	anvil_scene_default(back);
	int st = anvil_scene_parse(back, text, "written", &err);
	if (st)
		diag("  %s\n%s", err.msg, text);
	if (out)
		*out = text;
	else
		free(text);
	return st;
}

static void test_text_values(void)
{
	struct anvil_scene sc, back;
	struct anvil_err err;
	char *text;
	/* A 1-byte stack under-read in set_path (p[-1] with p at the value's
	 * start): ASan and valgrind builds catch a return of it. */
	anvil_scene_default(&sc);
	ok(anvil_scene_set(&sc, "output.histories", "#x", NULL, 0, &err) == ANVIL_OK &&
		   strcmp(sc.output.histories, "#x") == 0, "-s output.histories=#x is a file '#x'");
	ok(write_parse(&sc, &back, &text) == ANVIL_OK &&
		   strcmp(back.output.histories, "#x") == 0 && strstr(text, "histories = \"#x\"\n"),
	   "  written in quotes, read back");
	free(text);
	anvil_scene_default(&sc);
	ok(anvil_scene_parse(&sc, "[output]\nhistories=#\n", "t", &err) == ANVIL_OK &&
		   strcmp(sc.output.histories, "#") == 0,
	   "[output] histories=# : '#' right after '=' is text (a file '#')");

	/* title=#x was written back as 'title = #x', a comment: the title was lost. */
	static const char *const titles[] = {
		"#x", ";x", "Run #3", "a ;b", "\"quoted\"", "back\\slash \\\" mix", " lead",
		"trail ", "caf\xc3\xa9 \xe2\x80\x94 \xc2\xb5m \xf0\x9f\x94\xa8", "=x", "\"",
	};
	for (size_t i = 0; i < sizeof titles / sizeof titles[0]; ++i) {
		char v[160];
		/* -s trims the value and reads a leading '"' as quoting, as files
		 * do: a title starting with one is given in quotes */
		if (titles[i][0] == '"')
			snprintf(v, sizeof v, "\"\\%s\"", titles[i]);
		else
			snprintf(v, sizeof v, "%s", titles[i]);
		if (i == 4)
			snprintf(v, sizeof v, "\"\\\"quoted\\\"\"");
		if (titles[i][0] == ' ' || titles[i][strlen(titles[i]) - 1] == ' ') {
			ok(anvil_scene_parse(&sc, i == 6 ? "[scene]\ntitle = \" lead\"\n"
							 : "[scene]\ntitle = \"trail \" # c\n",
					     "t", &err) == ANVIL_OK,
			   "title '%s' in quotes parses", titles[i]);
		} else {
			ok(anvil_scene_set(&sc, "scene.title", v, NULL, 0, &err) == ANVIL_OK,
			   "title '%s' set", titles[i]);
		}
		ok(strcmp(sc.title, titles[i]) == 0 && write_parse(&sc, &back, NULL) == ANVIL_OK &&
			   strcmp(back.title, titles[i]) == 0 && back.title_set,
		   "  write + parse gives it back to the byte: '%s'", back.title);
	}
	ok(anvil_scene_parse(&sc, "[scene]\ntitle = \"a \\\"b\\\" \\\\ c\" ; note\n", "t", &err) ==
			   ANVIL_OK && strcmp(sc.title, "a \"b\" \\ c") == 0,
	   "quoted value: \\\" and \\\\ escapes, a comment after it");
	ok(anvil_scene_parse(&sc, "[impactor]\nmass = \"5 g\"\n", "t", &err) == ANVIL_OK &&
		   sc.mass == 5e-3, "any value may be quoted");
}

static void test_line_ends(void)
{
	struct anvil_scene sc;
	struct anvil_err err;
	/* CR-only files read as one line, a comment: the default scene ran. */
	anvil_scene_default(&sc);
	int st = anvil_scene_parse(&sc, "# old Mac file\r[impactor]\rmass = 5 g\r\r[impact]\r"
					"velocity = 3 m/s\r", "cr.scene", &err);
	ok(st == ANVIL_OK && sc.mass == 5e-3 && sc.velocity == 3, "CR-only line ends");
	ok(anvil_scene_parse(&sc, "[impactor]\rmass = x\r", "cr.scene", &err) == ANVIL_EPARSE &&
		   has(&err, "cr.scene:2: impactor.mass"), "  lines counted at each CR");
	anvil_scene_default(&sc);
	st = anvil_scene_parse(&sc, "[impactor]\r\nmass = 6 g\r\n\r\n[impact]\nvelocity = 4 m/s\r",
			       "mixed", &err);
	ok(st == ANVIL_OK && sc.mass == 6e-3 && sc.velocity == 4, "CRLF, LF and CR mixed");
	ok(anvil_scene_parse(&sc, "[impactor]\r\n\r\nmass = x\r\n", "crlf", &err) == ANVIL_EPARSE &&
		   has(&err, "crlf:3: impactor.mass"), "  CRLF is one line end");

	/* A UTF-8 BOM was reported as a bad key, the BOM invisible. */
	anvil_scene_default(&sc);
	ok(anvil_scene_parse(&sc, "\xef\xbb\xbf[impactor]\nmass = 7 g\n", "bom", &err) == ANVIL_OK &&
		   sc.mass == 7e-3, "a leading UTF-8 BOM is skipped");
	ok(anvil_scene_parse(&sc, "[impactor]\n\xef\xbb\xbfmass = 7 g\n", "bom", &err) ==
		   ANVIL_EPARSE, "  but only at the start");
}

static void test_load_limits(void)
{
	struct anvil_scene sc, before;
	struct anvil_err err;
	char dir[] = "/tmp/anvil-test-limits-XXXXXX", path[600], want[700];
	if (!mkdtemp(dir)) {
		ok(0, "mkdtemp");
		return;
	}
	snprintf(path, sizeof path, "%s/x.scene", dir);
	anvil_scene_default(&sc);
	before = sc;
	/* An empty file silently ran the paper's case. */
	static const char *const empty[] = {"", "\n\n", "# only\n; comments\n", "[impactor]\n"};
	for (size_t i = 0; i < sizeof empty / sizeof empty[0]; ++i) {
		FILE *f = fopen(path, "w");
		fputs(empty[i], f);
		fclose(f);
		snprintf(want, sizeof want, "%s: no KEY = VALUE in the scene", path);
		ok(anvil_scene_load(&sc, path, &err) == ANVIL_EPARSE && has(&err, want) &&
			   memcmp(&sc, &before, sizeof sc) == 0,
		   "a scene without keys is refused (%zu)", i);
	}
	/* /dev/zero grew memory until OOM. */
	if (access("/dev/zero", R_OK) == 0)
		ok(anvil_scene_load(&sc, "/dev/zero", &err) == ANVIL_EPARSE &&
			   has(&err, "/dev/zero: larger than 1048576 bytes"),
		   "/dev/zero: refused after 1 MiB: %s", err.msg);
	/* Exactly at the limit is read (and fails on its content), one more is not. */
	FILE *f = fopen(path, "w");
	fputs("[impact]\nvelocity = 2 m/s\n", f);
	for (long n = 26; n < ANVIL_SCENE_MAX_BYTES; n += 64)
		fprintf(f, "%.*s\n", (int)(n + 64 <= ANVIL_SCENE_MAX_BYTES ? 63
							 : ANVIL_SCENE_MAX_BYTES - n - 1),
			"#..............................................................");
	fclose(f);
	ok(anvil_scene_load(&sc, path, &err) == ANVIL_OK && sc.velocity == 2,
	   "a file of exactly 1 MiB is read");
	f = fopen(path, "a");
	fputc('\n', f);
	fclose(f);
	snprintf(want, sizeof want, "%s: larger than 1048576 bytes", path);
	ok(anvil_scene_load(&sc, path, &err) == ANVIL_EPARSE && has(&err, want),
	   "one byte more is refused, naming the file");
	remove(path);
	remove(dir);
}

static void test_grid_any_double(void)
{
	/* -s impactor.radius=1e308: (int)ceil(inf) in anvil_cache_grid_up, then
	 * a spin.  Input now refuses it; the grid is safe for any double. */
	const double x[] = {INFINITY, -INFINITY, NAN, 0, -1, 1e308, 1e-308, 5e-324, DBL_MAX};
	int fine = 1;
	for (size_t i = 0; i < sizeof x / sizeof x[0]; ++i) {
		int k = anvil_cache_grid_up(x[i]);
		fine &= k >= -4000 && k <= 4000;
		if (x[i] > 1e-300 && x[i] < 1e300)
			fine &= anvil_cache_grid(k) >= x[i] && anvil_cache_grid(k - 1) < x[i];
	}
	ok(fine, "anvil_cache_grid_up: a bounded index for inf, NaN, 0, <0, huge, tiny");
}

static void test_plausible(void)
{
	struct anvil_scene sc;
	struct anvil_err err;
	struct anvil_scene_warning w[ANVIL_SCENE_WARNINGS_MAX];
	anvil_scene_default(&sc);
	ok(anvil_scene_warnings(&sc, w, ANVIL_SCENE_WARNINGS_MAX) == 0, "the default: no warning");
	int st = anvil_scene_parse(&sc,
				   "[impactor]\nmass = 2000 kg\nmaterial = goo\n"
				   "[material goo]\nE = 0.5 MPa\nnu = 0.45\nrho = 5 kg/m3\n"
				   "[impact]\nvelocity = 6 km/s\n",
				   "w.scene", &err);
	int n = anvil_scene_warnings(&sc, w, ANVIL_SCENE_WARNINGS_MAX);
	ok(st == ANVIL_OK && n == 4, "an implausible scene parses, with 4 warnings (%d)", n);
	ok(n >= 4 && !strcmp(w[0].key, "impactor.mass") && w[0].line == 2 &&
		   !strcmp(w[0].msg, "2e+03 kg is above 1e+03 kg (no impactor of 1 ug .. 1 t)"),
	   "  mass: key, line, message: %s", n > 0 ? w[0].msg : "");
	ok(n >= 4 && !strcmp(w[1].key, "impactor.material") && w[1].line == 3 &&
		   strstr(w[1].msg, "500 kPa is below 1 MPa"), "  E of the material: %s",
	   n > 1 ? w[1].msg : "");
	ok(n >= 4 && !strcmp(w[2].key, "impactor.material") && strstr(w[2].msg, "below 10 kg/m^3"),
	   "  rho: %s", n > 2 ? w[2].msg : "");
	ok(n >= 4 && !strcmp(w[3].key, "impact.velocity") && w[3].line == 9 &&
		   strstr(w[3].msg, "6 km/s is above 5 km/s"), "  velocity: %s", n > 3 ? w[3].msg : "");
	ok(anvil_scene_warnings(&sc, w, 1) == 4, "  the count even when max is smaller");
	anvil_scene_default(&sc);
	anvil_scene_set(&sc, "layer.thickness", "200 m", NULL, 0, NULL);
	anvil_scene_set(&sc, "impactor.radius", "0.5 um", NULL, 0, NULL);
	anvil_scene_set(&sc, "layer.E", "3000 GPa", NULL, 0, NULL);
	n = anvil_scene_warnings(&sc, w, ANVIL_SCENE_WARNINGS_MAX);
	ok(n == 3 && w[0].line == -1 && !strcmp(w[0].key, "impactor.radius") &&
		   !strcmp(w[1].key, "layer.E") && !strcmp(w[2].key, "layer.thickness"),
	   "radius, E override, thickness by -s: line -1 (%d)", n);
	anvil_scene_set(&sc, "layer.thickness", "1e5 r0", NULL, 0, NULL);
	ok(anvil_scene_warnings(&sc, w, ANVIL_SCENE_WARNINGS_MAX) == 2,
	   "  h = 1e5 r0 = 5 cm at r0 = 0.5 um: no thickness warning, radius and E remain");
}

static void test_title(void)
{
	struct anvil_scene sc, back;
	char buf[ANVIL_TITLE_MAX];
	const char *def = "Copper rod on a steel layer (Pyr'yev et al. 2024)";
	anvil_scene_default(&sc);
	ok(!sc.title_set && !strcmp(sc.title, def), "the default's title, not set by the user");
	anvil_scene_set(&sc, "solver.accuracy", "draft", NULL, 0, NULL);
	ok(!strcmp(sc.title, def), "  kept when only the solver changes");
	anvil_scene_set(&sc, "impactor.material", "steel", NULL, 0, NULL);
	anvil_scene_set(&sc, "impactor.mass", "50g", NULL, 0, NULL);
	ok(!strcmp(sc.title, "50 g steel impactor, r0 = 4 mm, at 10 m/s on a 4 mm steel layer"),
	   "-s impactor.material=steel -s impactor.mass=50g: '%s'", sc.title);
	anvil_scene_title(&sc, buf, sizeof buf);
	ok(!strcmp(buf, sc.title), "  anvil_scene_title says the same");
	ok(write_parse(&sc, &back, NULL) == ANVIL_OK && !strcmp(back.title, sc.title),
	   "  the saved scene carries it");
	anvil_scene_set(&sc, "layer.thickness", "inf", NULL, 0, NULL);
	anvil_scene_set(&sc, "impact.velocity", "100 m/s", NULL, 0, NULL);
	ok(!strcmp(sc.title, "50 g steel impactor, r0 = 4 mm, at 100 m/s on a steel half-space"),
	   "  follows every change: '%s'", sc.title);
	anvil_scene_set(&sc, "layer.thickness", "1 r0", NULL, 0, NULL);
	anvil_scene_set(&sc, "impact.velocity", "10 m/s", NULL, 0, NULL);
	anvil_scene_set(&sc, "impactor.material", "copper", NULL, 0, NULL);
	anvil_scene_set(&sc, "impactor.mass", "12.2 g", NULL, 0, NULL);
	ok(!strcmp(sc.title, def), "  back to the default physics: the default's title");
	anvil_scene_set(&sc, "scene.title", "Mine", NULL, 0, NULL);
	anvil_scene_set(&sc, "impactor.mass", "1 g", NULL, 0, NULL);
	ok(sc.title_set && !strcmp(sc.title, "Mine"), "a title set is kept");
	anvil_scene_default(&sc);
	anvil_scene_parse(&sc, "[impact]\nvelocity = 20 m/s\n", "t", NULL);
	ok(strstr(sc.title, "at 20 m/s") != NULL, "a parsed scene without a title gets one: '%s'",
	   sc.title);
}

/* ---- names ---- */

static void test_names(void)
{
	static const char *const acc[] = {"draft", "normal", "fine", "reference"};
	static const double target[] = {1e-2, 1e-3, 1e-4, 1e-5};
	static const char *const mod[] = {"hertz", "zener", "layer", "halfspace"};
	for (int i = 0; i < ANVIL_ACC_COUNT; ++i) {
		ok(strcmp(anvil_accuracy_name((enum anvil_accuracy)i), acc[i]) == 0 &&
			   anvil_accuracy_parse(acc[i]) == i,
		   "accuracy %d is '%s' both ways", i, acc[i]);
		ok(anvil_accuracy_target((enum anvil_accuracy)i) == target[i], "  target %g",
		   target[i]);
	}
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i)
		ok(strcmp(anvil_model_name((enum anvil_model)i), mod[i]) == 0 &&
			   anvil_model_parse(mod[i]) == i,
		   "model %d is '%s' both ways", i, mod[i]);
	ok(anvil_accuracy_parse("Normal") == ANVIL_ACC_NORMAL && anvil_model_parse("HERTZ") == 0,
	   "names parse case-insensitively");
	ok(anvil_accuracy_parse("coarse") == -1 && anvil_accuracy_parse(NULL) == -1 &&
		   anvil_model_parse("plate") == -1 && anvil_model_parse("all") == -1,
	   "unknown names parse to -1");
	ok(strcmp(anvil_accuracy_name(ANVIL_ACC_COUNT), "unknown") == 0 &&
		   strcmp(anvil_model_name(ANVIL_MODEL_COUNT), "unknown") == 0 &&
		   isnan(anvil_accuracy_target(ANVIL_ACC_COUNT)),
	   "out of range: 'unknown' and NaN");
}

int main(void)
{
	test_default();
	test_examples();
	test_features();
	test_parse_errors();
	test_set();
	test_check();
	test_round_trip();
	test_load();
	test_text_values();
	test_line_ends();
	test_load_limits();
	test_grid_any_double();
	test_plausible();
	test_title();
	test_names();
	plan(tap_n);
	return done_testing();
}
