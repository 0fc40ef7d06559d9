/* scene.h: what is simulated, as read from a scene file or set by a key.
 *
 * A scene is an INI-style text with units:
 *
 *   [scene]     title = free text (shown on charts; never executed)
 *   [impactor]  material = copper   mass = 12.2 g   radius = 4 mm
 *               shape = rod|ball   diameter = 8 mm   length = 30 mm
 *               E = ..  nu = ..  rho = ..  yield = ..  tensile = ..
 *               brittle = on|off  (overrides)
 *   [layer]     material = steel    thickness = 2 r0 | 8 mm | inf
 *               E, nu, rho, yield, tensile, brittle (overrides)
 *   [impact]    velocity = 10 m/s | drop_height = 50 mm
 *   [solver]    accuracy = draft|normal|fine|reference
 *               scheme = implicit|paper   dt = 0.16 us | auto
 *               models = hertz,zener,layer,halfspace (any subset)
 *   [effects]   waves = auto|layer|halfspace|none   plate = on|off
 *               quasistatic = on|off   field = off|points|map
 *   [output]    table = on|off   histories = FILE|off   charts = DIR|off
 *               field = FILE|off
 *   [material NAME]  E = ..  nu = ..  rho = ..  yield = ..  tensile = ..
 *               brittle = on|off  (a new material)
 *
 * The impactor's geometry (anvil_scene_geometry): a rod with a
 * hemispherical tip of radius r0 = D/2 (shape = rod, the paper's), or a
 * ball of diameter D = 2 r0; radius and diameter are two spellings of one
 * length.  The mass is the mass key when given; else a ball's
 * rho pi D^3 / 6, a rod's rho pi r0^2 (L - r0/3) for its overall length L
 * (tip included: a cylinder of length L - r0 and a hemisphere); else the
 * default's.  drop_height H gives V0 = sqrt(2 g H) (standard gravity, no
 * air drag).  In one scene text, keys that say the same thing twice are
 * refused: velocity and drop_height, mass and length, a radius and a
 * diameter that disagree, a ball's length.  A key set later (-s, the TUI,
 * a text parsed on top) replaces the keys it conflicts with; a shape key
 * replaces a mass given before, unless its own text gives one.
 *
 * '#' and ';' start comments (at the start of a line or after white space).
 * A value may be written in double quotes, "like # this", to keep '#', ';'
 * and white space at its ends; inside, \" is a quote and \\ a backslash.
 * Lines end in LF, CRLF or CR; a leading UTF-8 byte order mark is skipped.
 * Dimensional values need their unit ("4 mm", not "4"); 'inf' (thickness)
 * and 'auto' (dt) are words; nu is a bare number.  Every key can also be set as SECTION.KEY
 * (e.g. "layer.thickness", "impactor.E") with anvil_scene_set(), which is
 * what `-s KEY=VALUE` on the command line and the TUI use.
 *
 * Values must lie in a physical range (anvil_scene_check lists them:
 * refused outside it, with the key and the range in the message); values
 * off any real material or impact, but possible, are only warned about
 * (anvil_scene_warnings).
 *
 * Errors: ANVIL_EPARSE with a one-line message "FILE:LINE: KEY: what was
 * expected" (with "did you mean 'X'?" for a misspelt key or material).
 * The struct is plain data: copy it freely. */
#ifndef ANVIL_SCENE_H
#define ANVIL_SCENE_H

#include <stdio.h>

#include "accuracy.h"
#include "material.h"
#include "options.h"
#include "status.h"

#define ANVIL_PATH_MAX 256

/* [output]: what `anvil run` writes; "" is off.  Paths are relative to the
 * current directory; the command line's -o, --history, --png win. */
struct anvil_output {
	int table;                      /* 1: print the results */
	char histories[ANVIL_PATH_MAX]; /* time histories, TSV */
	char charts[ANVIL_PATH_MAX];    /* directory for PNG charts */
	char field[ANVIL_PATH_MAX];     /* the field, when [effects] field is on */
};
#define ANVIL_MAX_CUSTOM 16
#define ANVIL_TITLE_MAX 128
/* The largest scene file read (a scene is a few hundred bytes; this bounds
 * what a wrong file, such as /dev/zero, can cost), and its longest line. */
#define ANVIL_SCENE_MAX_BYTES (1024 * 1024)
#define ANVIL_SCENE_LINE_MAX 1023
/* Keys whose line is remembered (more than the key table holds). */
#define ANVIL_SCENE_KEYS_MAX 64

struct anvil_body {
	char material[ANVIL_NAME_MAX]; /* the named material */
	/* Per-body overrides of the named material; NaN when not set
	 * (brittle: 0 or 1). */
	double E, nu, rho, yield, tensile, brittle;
	/* The named material with the overrides applied.  Kept up to date by
	 * every function in this module that changes the scene. */
	struct anvil_material mat;
};

enum anvil_shape {
	ANVIL_SHAPE_ROD,  /* a rod with a hemispherical tip (the paper's) */
	ANVIL_SHAPE_BALL,
	ANVIL_SHAPE_COUNT
};

/* Standard gravity, m/s^2 (3rd CGPM, 1901). */
#define ANVIL_G_STANDARD 9.80665

struct anvil_scene {
	char title[ANVIL_TITLE_MAX];
	struct anvil_body impactor, layer;
	/* mass, radius and velocity are the values in use, kept up to date
	 * from the geometry (anvil_scene_geometry) by every function here. */
	double mass;            /* impactor mass, kg */
	double radius;          /* impactor (contact patch) radius r0, m */
	double thickness;       /* layer thickness: m, or multiples of r0 */
	int thickness_per_r0;   /* 1 when thickness is in multiples of r0 */
	double velocity;        /* impact velocity V0, m/s */
	/* What the user gave (NaN: not given): see the geometry above. */
	enum anvil_shape shape;
	double diameter;        /* m; sets radius = diameter / 2 */
	double length;          /* m, a rod's overall length, tip included */
	double drop_height;     /* m; sets velocity = sqrt(2 g H) */
	int mass_given;         /* 1: the mass key was set (not the default's) */
	enum anvil_accuracy accuracy;
	enum anvil_scheme scheme;
	double dt;              /* time step, s; 0 = chosen from accuracy */
	unsigned models;        /* bit (1u << enum anvil_model) for each model run */
	/* Materials defined by [material NAME] sections. */
	int ncustom;
	struct anvil_material custom[ANVIL_MAX_CUSTOM];
	struct anvil_effects effects; /* defaults: auto, on, on, off */
	struct anvil_output output;   /* defaults: table on, the rest off */
	/* 1 when the title was set (scene file or key).  Otherwise every
	 * function here that changes the scene rewrites title from the scene
	 * (anvil_scene_title), so that it never describes another scene. */
	int title_set;
	/* Where each key was last set, by key number (internal to scene_keys.c):
	 * > 0 a line of the scene text, -1 anvil_scene_set, 0 not set (the
	 * default).  For messages such as anvil_scene_warnings'. */
	int key_line[ANVIL_SCENE_KEYS_MAX];
};

/* The embedded default scene (the paper's copper rod on a 1 r0 steel layer at
 * 10 m/s) as text, and loaded into sc.  anvil_scene_default returns ANVIL_OK,
 * or the parse status if the embedded text were broken (a bug). */
const char *anvil_scene_default_text(void);
int anvil_scene_default(struct anvil_scene *sc);

/* Parse scene text on top of what sc holds already (start from
 * anvil_scene_default).  origin names the text in messages (a file name).
 * On error sc is left as it was. */
int anvil_scene_parse(struct anvil_scene *sc, const char *text,
		      const char *origin, struct anvil_err *err);
/* Read and parse a file ("-" is standard input).  Refused (ANVIL_EPARSE,
 * naming the file): more than ANVIL_SCENE_MAX_BYTES, a NUL byte, a line
 * longer than ANVIL_SCENE_LINE_MAX, and a file with no KEY = VALUE at all
 * (empty or only comments: running the default case instead of what the
 * user meant to write would be a silent mistake). */
int anvil_scene_load(struct anvil_scene *sc, const char *path,
		     struct anvil_err *err);
/* Set one key, "section.key" (e.g. "layer.thickness") to value with units.
 * origin/line are for messages (line 0: no line). */
int anvil_scene_set(struct anvil_scene *sc, const char *key, const char *value,
		    const char *origin, int line, struct anvil_err *err);
/* Whole-scene validation: materials, the ranges below, dt >= 0.  Parse and
 * set already check each value they read.  The ranges, refused outside
 * (wide: a warning, anvil_scene_warnings, comes first):
 *   mass 1 ng .. 1000 t, radius 1 nm .. 1 km, velocity 1 um/s .. 100 km/s,
 *   thickness h 1 nm .. 1 km (inf: a half-space),
 *   dt 0 (auto) or 1 fs .. 1 s;
 * and, as keys are read (the material constants are only checked for sign
 * and finiteness here, so that code may model a limit such as a rigid
 * anvil): E 1 kPa .. 1e6 GPa, rho 0.01 .. 1e6 kg/m^3, nu -0.99 .. 0.49999,
 * yield 0 .. 1e6 GPa. */
int anvil_scene_check(const struct anvil_scene *sc, struct anvil_err *err);

/* Write sc as scene text that anvil_scene_parse reads back to exactly the
 * same numbers (SI values printed with %.17g).  Returns ANVIL_EIO on a write
 * error. */
int anvil_scene_write(const struct anvil_scene *sc, FILE *out);

/* Plausibility: values that anvil_scene_check accepts but no real material
 * or impact has: E below 1 MPa or above 2000 GPa, rho outside 10 .. 30000
 * kg/m^3 (impactor, layer), a radius below 1 um or above 1 m, a mass below
 * 1 ug or above 1 t, V0 above 5 km/s, a thickness below 1 um or above
 * 100 m.  Up to max are stored in w (ANVIL_SCENE_WARNINGS_MAX holds all);
 * returns how many there are.  Nothing is printed. */
struct anvil_scene_warning {
	char key[48];  /* "impactor.mass"; for E and rho the key that set it */
	int line;      /* as key_line: > 0 a line of the scene text */
	char msg[160]; /* "2 t is above 1 t (...)" */
};
#define ANVIL_SCENE_WARNINGS_MAX 16
int anvil_scene_warnings(const struct anvil_scene *sc, struct anvil_scene_warning *w,
			 int max);

/* The title sc should carry: the title set, else the default scene's
 * title while the physics is the default's, else one made from the scene
 * ("50 g steel impactor, r0 = 4 mm, at 10 m/s on a 4 mm steel layer").
 * sc->title is kept equal to it by parse, set and default. */
void anvil_scene_title(const struct anvil_scene *sc, char *buf, size_t n);
/* Whether sc has the default scene's physics (bodies, mass, r0, h, V0): the paper's
 * own case, for which [effects] contact = auto shows both contact models. */
int anvil_scene_is_paper_case(const struct anvil_scene *sc);

/* "rod", "ball"; anvil_shape_parse gives -1 for anything else. */
const char *anvil_shape_name(enum anvil_shape s);
int anvil_shape_parse(const char *name);

/* The impactor's mass for its geometry: rho pi D^3 / 6 for a ball of
 * diameter D; rho pi R^2 (L - R/3) for a rod of radius R and overall
 * length L >= R with a hemispherical tip (NaN for L < R). */
double anvil_ball_mass(double rho, double D);
double anvil_rod_mass(double rho, double R, double L);
/* The speed after a free fall from height H: sqrt(2 g H). */
double anvil_drop_velocity(double H);

/* Update sc->radius, sc->mass and sc->velocity from the geometry keys (as
 * above).  ANVIL_EPARSE naming the key for a rod shorter than its tip
 * radius.  Parse and set call it; code that edits the struct directly
 * calls it after. */
int anvil_scene_geometry(struct anvil_scene *sc, struct anvil_err *err);

/* Layer thickness in metres (INFINITY for a half-space). */
double anvil_scene_h(const struct anvil_scene *sc);

/* The models a run computes: solver.models less the rows [effects] turns
 * off (hertz without quasistatic, zener without plate, layer and
 * halfspace with waves = none).  A bit (1u << enum anvil_model) each. */
unsigned anvil_scene_models(const struct anvil_scene *sc);

#endif
