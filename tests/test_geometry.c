/* test_geometry: the impactor's geometry and the drop height (scene.h):
 * the mass, radius and velocity they give, their conflicts, -s replacing
 * keys, the round trip through anvil_scene_write; the brittle flag and the
 * tensile strength of materials and their overrides. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"
#include "tap.h"

static int parse(struct anvil_scene *sc, const char *text, struct anvil_err *err)
{
	anvil_scene_default(sc);
	return anvil_scene_parse(sc, text, "t.scene", err);
}

/* text is refused, the message holding want. */
static void refused(const char *text, const char *want)
{
	struct anvil_scene sc;
	struct anvil_err err = {0};
	int st = parse(&sc, text, &err);
	ok(st == ANVIL_EPARSE, "refused: %s", want);
	if (!ok(strstr(err.msg, want) != NULL, "  message has \"%s\"", want))
		diag("  got: %s", err.msg);
}

static void round_trip(const struct anvil_scene *sc, const char *what)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	anvil_scene_write(sc, f);
	fclose(f);
	struct anvil_scene back;
	struct anvil_err err = {0};
	int st = parse(&back, buf, &err);
	ok(st == ANVIL_OK && back.mass == sc->mass && back.radius == sc->radius &&
	   back.velocity == sc->velocity && back.shape == sc->shape &&
	   !memcmp(&back.diameter, &sc->diameter, sizeof(double)) &&
	   !memcmp(&back.length, &sc->length, sizeof(double)) &&
	   !memcmp(&back.drop_height, &sc->drop_height, sizeof(double)),
	   "%s: written and read back to the same bits", what);
	if (st)
		diag("  %s\n%s", err.msg, buf);
	free(buf);
}

static void balls(void)
{
	struct anvil_scene sc;
	struct anvil_err err = {0};
	const double rho = 7830; /* steel, Table 1 */
	int st = parse(&sc, "[impactor]\nmaterial = steel\nshape = ball\ndiameter = 10 mm\n"
			    "[layer]\nthickness = 1 mm\n[impact]\ndrop_height = 50 mm\n", &err);
	ok(st == ANVIL_OK, "a 10 mm steel ball dropped from 50 mm parses (%s)", err.msg);
	is_rel(sc.radius, 5e-3, 1e-15, "its radius is 5 mm");
	/* the sphere's volume as (4/3) pi r^3, not the code's pi D^3 / 6 */
	is_rel(sc.mass, rho * 4.0 / 3.0 * M_PI * pow(5e-3, 3), 1e-14,
	       "its mass is rho (4/3) pi r^3 = %.6g g", sc.mass * 1e3);
	/* free fall: V0^2 / 2 = g H, g the standard 9.80665 m/s^2 */
	is_rel(0.5 * sc.velocity * sc.velocity, 9.80665 * 0.05, 1e-15,
	       "V0 = %.6f m/s: V0^2/2 = g H", sc.velocity);
	ok(strstr(sc.title, "steel ball, D = 10 mm") != NULL, "the title says ball: %s", sc.title);
	round_trip(&sc, "a ball dropped");

	/* density override: the mass follows; a given mass wins */
	anvil_scene_set(&sc, "impactor.rho", "7000 kg/m^3", NULL, 0, &err);
	is_rel(sc.mass, 7000 * M_PI / 6 * 1e-6, 1e-14, "impactor.rho = 7000: the mass follows");
	st = anvil_scene_set(&sc, "impactor.mass", "50 g", NULL, 0, &err);
	ok(st == ANVIL_OK && sc.mass == 0.05 && sc.radius == 5e-3,
	   "-s impactor.mass = 50 g: a given mass wins (a hollow ball), D stays");
	round_trip(&sc, "a ball with its mass");

	/* -s replaces what it conflicts with */
	st = anvil_scene_set(&sc, "impact.velocity", "3 m/s", NULL, 0, &err);
	ok(st == ANVIL_OK && sc.velocity == 3 && isnan(sc.drop_height),
	   "-s impact.velocity replaces drop_height");
	st = anvil_scene_set(&sc, "impactor.radius", "11.5 mm", NULL, 0, &err);
	ok(st == ANVIL_OK && sc.radius == 11.5e-3 && isnan(sc.diameter),
	   "-s impactor.radius replaces diameter");
	st = anvil_scene_set(&sc, "impact.drop_height", "1 m", NULL, 0, &err);
	is_rel(sc.velocity, sqrt(2 * 9.80665), 1e-15, "-s impact.drop_height = 1 m: V0 = sqrt(2 g)");
	round_trip(&sc, "after -s");

	/* a shape key replaces a mass given before, unless its text gives one */
	st = anvil_scene_set(&sc, "impactor.mass", "1 kg", NULL, 0, &err);
	st = anvil_scene_parse(&sc, "[impactor]\nshape = ball\ndiameter = 10 mm\n", "t", &err);
	is_rel(sc.mass, sc.impactor.mat.rho * M_PI / 6 * 1e-6, 1e-14,
	       "a ball's text on a scene with a given mass: the mass follows the ball");
	st = anvil_scene_parse(&sc, "[impactor]\nmass = 40 g\nshape = ball\n", "t", &err);
	ok(st == ANVIL_OK && sc.mass == 0.04, "mass before shape in one text: the mass is kept");

	/* radius and diameter: two spellings of one length */
	st = parse(&sc, "[impactor]\nshape = ball\nradius = 5 mm\ndiameter = 10 mm\n", &err);
	ok(st == ANVIL_OK && sc.radius == 5e-3, "radius and diameter that agree are accepted");
}

static void rods(void)
{
	struct anvil_scene sc;
	struct anvil_err err = {0};
	/* The paper's copper rod, r0 = 4 mm: 12.2 g is a rod of L = 27.6 mm. */
	int st = parse(&sc, "[impactor]\nlength = 30 mm\n", &err);
	double R = 4e-3, L = 30e-3, rho = 8960;
	double cyl = M_PI * R * R * (L - R), hemi = 2.0 / 3.0 * M_PI * R * R * R;
	ok(st == ANVIL_OK, "a copper rod of length 30 mm parses");
	is_rel(sc.mass, rho * (cyl + hemi), 1e-14,
	       "its mass is rho (cylinder of L - R + hemisphere) = %.6g g", sc.mass * 1e3);
	round_trip(&sc, "a rod of given length");
	st = anvil_scene_set(&sc, "impactor.diameter", "10 mm", NULL, 0, &err);
	ok(st == ANVIL_OK && sc.radius == 5e-3, "a rod's diameter is twice its tip radius");
	is_rel(sc.mass, rho * M_PI * 25e-6 * (L - 5e-3 / 3), 1e-14, "  and the mass follows");
	st = anvil_scene_set(&sc, "impactor.mass", "2 kg", NULL, 0, &err);
	ok(st == ANVIL_OK && sc.mass == 2 && isnan(sc.length), "-s impactor.mass replaces length");
	st = anvil_scene_set(&sc, "impactor.length", "2 mm", NULL, 0, &err);
	ok(st == ANVIL_EPARSE && strstr(err.msg, "impactor.length") &&
	   strstr(err.msg, "shorter than the tip radius") && sc.mass == 2,
	   "a rod shorter than its tip is refused, the scene unchanged: %s", err.msg);
	st = anvil_scene_set(&sc, "impactor.shape", "cube", NULL, 0, &err);
	ok(st == ANVIL_EPARSE && strstr(err.msg, "expected rod or ball"), "shape = cube: %s",
	   err.msg);
	/* shape = ball drops a rod's length */
	parse(&sc, "[impactor]\nlength = 30 mm\n", &err);
	st = anvil_scene_set(&sc, "impactor.shape", "ball", NULL, 0, &err);
	ok(st == ANVIL_OK && isnan(sc.length) &&
	   fabs(sc.mass - rho * M_PI / 6 * 512e-9) < 1e-15,
	   "-s impactor.shape = ball replaces length: a ball of D = 2 r0");
}

static void conflicts(void)
{
	refused("[impact]\nvelocity = 3 m/s\ndrop_height = 1 m\n",
		"t.scene:3: impact.drop_height: impact.velocity is set too (line 2)");
	refused("[impact]\ndrop_height = 1 m\nvelocity = 3 m/s\n",
		"t.scene:3: impact.velocity: impact.drop_height is set too (line 2)");
	refused("[impactor]\nmass = 50 g\nlength = 30 mm\n",
		"t.scene:3: impactor.length: impactor.mass is set too (line 2)");
	refused("[impactor]\nradius = 4 mm\ndiameter = 10 mm\n",
		"t.scene:3: impactor.diameter: 0.01 m is not twice radius = 0.004 m (line 2)");
	refused("[impactor]\nshape = ball\nlength = 30 mm\n",
		"t.scene:3: impactor.length: a ball has no length");
	refused("[impactor]\nlength = 1 mm\n", "t.scene:2: impactor.length: 1 mm is shorter");
	refused("[impact]\ndrop_height = 1 kg\n", "t.scene:2: impact.drop_height: expected a length");
}

static void brittle(void)
{
	struct anvil_scene sc;
	struct anvil_err err = {0};
	const struct anvil_material *g = anvil_material_find("glass"),
				    *s = anvil_material_find("steel");
	ok(g && g->brittle && g->tensile == 45e6 && strstr(g->source, "EN 572-1"),
	   "glass is brittle, tensile strength 45 MPa (EN 572-1)");
	ok(s && !s->brittle && s->tensile == 0, "steel is not brittle");
	int st = parse(&sc, "[layer]\nmaterial = glass\ntensile = 60 MPa\n", &err);
	ok(st == ANVIL_OK && sc.layer.mat.tensile == 60e6 && sc.layer.mat.brittle,
	   "layer.tensile overrides the strength");
	st = anvil_scene_set(&sc, "layer.brittle", "off", NULL, 0, &err);
	ok(st == ANVIL_OK && !sc.layer.mat.brittle, "layer.brittle = off overrides the flag");
	st = parse(&sc, "[layer]\nmaterial = stone\n[material stone]\nE = 50 GPa\nnu = 0.25\n"
			"rho = 2600 kg/m^3\ntensile = 10 MPa\nbrittle = on\n", &err);
	ok(st == ANVIL_OK && sc.layer.mat.brittle && sc.layer.mat.tensile == 10e6,
	   "a [material NAME] can be brittle with a tensile strength (%s)", err.msg);
	st = anvil_scene_set(&sc, "layer.tensile", "-1 MPa", NULL, 0, &err);
	ok(st == ANVIL_EPARSE && strstr(err.msg, "layer.tensile: must be within"),
	   "a negative tensile strength is refused: %s", err.msg);
	round_trip(&sc, "a brittle custom material");
}

int main(void)
{
	balls();
	rods();
	conflicts();
	brittle();
	plan(tap_n);
	return done_testing();
}
