/* options.h: the small enums a run is described by (model, scheme, waves,
 * field mode, effects), apart from the scene format that sets them, so that
 * physics and engine headers depend on these and not on scene.h.
 * The names <-> enums functions are defined in scene.c. */
#ifndef ANVIL_OPTIONS_H
#define ANVIL_OPTIONS_H

enum anvil_scheme {
	ANVIL_SCHEME_IMPLICIT, /* second order, the default */
	ANVIL_SCHEME_PAPER     /* the paper's explicit lagged scheme, eqs (42)-(46) */
};

enum anvil_model {
	ANVIL_MODEL_HERTZ,     /* quasi-static Hertz, layer rigid (w = 0) */
	ANVIL_MODEL_ZENER,     /* Zener's thin plate, eqs (48)-(54) */
	ANVIL_MODEL_LAYER,     /* elastic layer of thickness h, transform solver */
	ANVIL_MODEL_HALFSPACE, /* elastic half-space, transform solver */
	ANVIL_MODEL_COUNT
};

#define ANVIL_MODELS_ALL ((1u << ANVIL_MODEL_COUNT) - 1u)

/* How the anvil's waves are modelled in the layer and halfspace rows:
 * auto lets the planner (plan.h) pick the cheapest model that meets the
 * accuracy, layer and halfspace force one, none drops both rows. */
enum anvil_waves {
	ANVIL_WAVES_AUTO,
	ANVIL_WAVES_LAYER,
	ANVIL_WAVES_HALFSPACE,
	ANVIL_WAVES_NONE,
	ANVIL_WAVES_COUNT
};

/* The stress and displacement field inside the layer (the field module). */
enum anvil_fieldmode {
	ANVIL_FIELDMODE_OFF,
	ANVIL_FIELDMODE_POINTS,
	ANVIL_FIELDMODE_MAP,
	ANVIL_FIELDMODE_COUNT
};

/* [effects] contact: how the layer and halfspace rows model the contact
 * (doc/contact-model.md, man anvil MODELS).
 *   physical  Hertz's approach of the true contact, plus what the layer does
 *             beyond the static indentation Hertz already holds: the
 *             half-space's radiation lag and the layer correction of a point
 *             load (impact.h);
 *   paper     the paper's: the layer's centre deflection under a Hertz patch
 *             of fixed radius r0 added to Hertz's approach, which counts the
 *             local indentation twice;
 *   both      a row of each;
 *   auto      both for the paper's own case (the default scene's physics),
 *             physical otherwise: anvil_problem_init resolves it.
 * A result row has PHYSICAL or PAPER; hertz and zener rows AUTO (neither). */
enum anvil_contact {
	ANVIL_CONTACT_AUTO,
	ANVIL_CONTACT_PHYSICAL,
	ANVIL_CONTACT_PAPER,
	ANVIL_CONTACT_BOTH,
	ANVIL_CONTACT_COUNT
};

/* [effects]: what physics the scene calls for.  plate and quasistatic
 * switch the zener and hertz rows; waves = none drops layer and halfspace.
 * Rows are run only if solver.models lists them too (anvil_scene_models). */
struct anvil_effects {
	enum anvil_waves waves;
	int plate;       /* 1: Zener's thin plate (the zener row) */
	int quasistatic; /* 1: quasi-static Hertz on a rigid layer (the hertz row) */
	enum anvil_fieldmode field;
	enum anvil_contact contact;
};

/* Names <-> enums.  The parse functions return -1 for an unknown name. */
const char *anvil_model_name(enum anvil_model m);
int anvil_model_parse(const char *name);
const char *anvil_waves_name(enum anvil_waves w);
int anvil_waves_parse(const char *name);
const char *anvil_fieldmode_name(enum anvil_fieldmode f);
int anvil_fieldmode_parse(const char *name);
/* (these two in scene_keys.c, beside the key) */
const char *anvil_contact_name(enum anvil_contact c);
int anvil_contact_parse(const char *name);

#endif
