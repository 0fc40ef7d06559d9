/* scene.h: what is simulated, as read from a scene file or set by a key.
 *
 * A scene is an INI-style text with units:
 *
 *   [scene]     title = free text (shown on charts; never executed)
 *   [impactor]  material = copper   mass = 12.2 g   radius = 4 mm
 *               E = ..  nu = ..  rho = ..  yield = ..  (overrides)
 *   [layer]     material = steel    thickness = 2 r0 | 8 mm | inf
 *               E, nu, rho, yield (overrides)
 *   [impact]    velocity = 10 m/s
 *   [solver]    accuracy = draft|normal|fine|reference
 *               scheme = implicit|paper   dt = 0.16 us | auto
 *               models = hertz,zener,layer,halfspace (any subset)
 *   [effects]   waves = auto|layer|halfspace|none   plate = on|off
 *               quasistatic = on|off   field = off|points|map
 *   [output]    table = on|off   histories = FILE|off   charts = DIR|off
 *               field = FILE|off
 *   [material NAME]  E = ..  nu = ..  rho = ..  yield = ..  (a new material)
 *
 * '#' and ';' start comments.  Every key can also be set as SECTION.KEY
 * (e.g. "layer.thickness", "impactor.E") with anvil_scene_set(), which is
 * what `-s KEY=VALUE` on the command line and the TUI use.
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

struct anvil_body {
	char material[ANVIL_NAME_MAX]; /* the named material */
	/* Per-body overrides of the named material; NaN when not set. */
	double E, nu, rho, yield;
	/* The named material with the overrides applied.  Kept up to date by
	 * every function in this module that changes the scene. */
	struct anvil_material mat;
};

struct anvil_scene {
	char title[ANVIL_TITLE_MAX];
	struct anvil_body impactor, layer;
	double mass;            /* impactor mass, kg */
	double radius;          /* impactor (contact patch) radius r0, m */
	double thickness;       /* layer thickness: m, or multiples of r0 */
	int thickness_per_r0;   /* 1 when thickness is in multiples of r0 */
	double velocity;        /* impact velocity V0, m/s */
	enum anvil_accuracy accuracy;
	enum anvil_scheme scheme;
	double dt;              /* time step, s; 0 = chosen from accuracy */
	unsigned models;        /* bit (1u << enum anvil_model) for each model run */
	/* Materials defined by [material NAME] sections. */
	int ncustom;
	struct anvil_material custom[ANVIL_MAX_CUSTOM];
	struct anvil_effects effects; /* defaults: auto, on, on, off */
	struct anvil_output output;   /* defaults: table on, the rest off */
};

/* The embedded default scene (the paper's copper rod on a 1 r0 steel layer at
 * 10 m/s) as text, and loaded into sc.  anvil_scene_default returns ANVIL_OK,
 * or the parse status if the embedded text were broken (a bug). */
const char *anvil_scene_default_text(void);
int anvil_scene_default(struct anvil_scene *sc);

/* Parse scene text on top of what sc holds already (start from
 * anvil_scene_default).  origin names the text in messages (a file name).
 * On error sc may be partly changed; callers keep a copy if they need one. */
int anvil_scene_parse(struct anvil_scene *sc, const char *text,
		      const char *origin, struct anvil_err *err);
/* Read and parse a file ("-" is standard input). */
int anvil_scene_load(struct anvil_scene *sc, const char *path,
		     struct anvil_err *err);
/* Set one key, "section.key" (e.g. "layer.thickness") to value with units.
 * origin/line are for messages (line 0: no line). */
int anvil_scene_set(struct anvil_scene *sc, const char *key, const char *value,
		    const char *origin, int line, struct anvil_err *err);
/* Whole-scene validation (materials, positive mass/radius/velocity/thickness,
 * dt >= 0).  Parse and set already call it for what they change. */
int anvil_scene_check(const struct anvil_scene *sc, struct anvil_err *err);

/* Write sc as scene text that anvil_scene_parse reads back to exactly the
 * same numbers (SI values printed with %.17g).  Returns ANVIL_EIO on a write
 * error. */
int anvil_scene_write(const struct anvil_scene *sc, FILE *out);

/* Layer thickness in metres (INFINITY for a half-space). */
double anvil_scene_h(const struct anvil_scene *sc);

/* The models a run computes: solver.models less the rows [effects] turns
 * off (hertz without quasistatic, zener without plate, layer and
 * halfspace with waves = none).  A bit (1u << enum anvil_model) each. */
unsigned anvil_scene_models(const struct anvil_scene *sc);

#endif
