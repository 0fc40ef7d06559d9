/* scene_keys.h: internal to scene.c and scene_keys.c, not part of the API.
 *
 * The table of scene keys (section, key, how to parse, check and print it),
 * the resolution of a body's material (scene_materials.c), and "did you
 * mean" suggestions (suggest.h).
 * Messages written here carry no location: the callers prefix
 * "FILE:LINE: SECTION.KEY: ". */
#ifndef ANVIL_SCENE_KEYS_H
#define ANVIL_SCENE_KEYS_H

#include <stdio.h>

#include "scene.h"
#include "suggest.h"

/* Sections, in the order anvil_scene_write prints them. */
enum anvil_section {
	ANVIL_SEC_SCENE,
	ANVIL_SEC_IMPACTOR,
	ANVIL_SEC_LAYER,
	ANVIL_SEC_IMPACT,
	ANVIL_SEC_SOLVER,
	ANVIL_SEC_EFFECTS,
	ANVIL_SEC_OUTPUT,
	ANVIL_SEC_MATERIAL, /* [material NAME] */
	ANVIL_SEC_COUNT
};

const char *anvil_scene_section_name(int sec);
/* Case-insensitive; -1 (with "unknown section 'x'; did you mean 'y'?" in
 * err) when there is none. */
int anvil_scene_section_find(const char *name, struct anvil_err *err);

/* Set key of section sec to value (trimmed; a value in double quotes is
 * unquoted).  name is the NAME of a [material NAME] section, else unused.
 * When deferred (while parsing), a body's material may be one defined later
 * in the text: call anvil_scene_resolve at the end.  Checks the value alone
 * (its unit and range); ANVIL_EPARSE.  line goes to sc->key_line. */
int anvil_scene_key_set(struct anvil_scene *sc, int sec, const char *name,
			const char *key, const char *value, int deferred, int line,
			struct anvil_err *err);
/* The geometry keys a key of section sec replaces when it is set
 * (scene.h): velocity <-> drop_height, radius <-> diameter, mass <->
 * length, shape = ball drops length.  impactor.c. */
void anvil_scene_geometry_replace(struct anvil_scene *sc, int sec, const char *key);

/* The key number of SECTION's key (an index of sc->key_line), -1 if none. */
int anvil_scene_key_index(int sec, const char *key);

/* The ranges values are refused outside of, SI (see anvil_scene_check). */
#define ANVIL_RANGE_MASS 1e-12, 1e6
#define ANVIL_RANGE_LENGTH 1e-9, 1e3   /* radius and thickness h */
#define ANVIL_RANGE_H_R0 1e-6, 1e6     /* h given in r0 */
#define ANVIL_RANGE_VELOCITY 1e-6, 1e5
#define ANVIL_RANGE_E 1e3, 1e15
#define ANVIL_RANGE_YIELD 0.0, 1e15
#define ANVIL_RANGE_RHO 1e-2, 1e6
/* nu -> -1 or 0.5 sends mu or c1 to infinity: these keep the wave speeds
 * finite and the solver's steps bounded. */
#define ANVIL_RANGE_NU -0.99, 0.49999
#define ANVIL_RANGE_DT 1e-15, 1.0
/* "must be within LO .. HI UNIT, got 'TEXT'" when v is outside [lo, hi]. */
int anvil_scene_range_check(double v, double lo, double hi, const char *unit,
			    const char *text, struct anvil_err *err);

/* scene_text.c.  text written so that the parser reads it back: bare when
 * it would survive, else in double quotes with '"' and '\\' escaped; buf of
 * at least 2 strlen(text) + 3 bytes holds it all. */
void anvil_scene_text_put(char *buf, size_t n, const char *text);
/* value[0..n), which starts with '"', without its quotes and escapes into v
 * (at least n bytes); ANVIL_EPARSE when the closing quote is missing or
 * not last. */
int anvil_scene_text_unquote(const char *value, size_t n, char *v, struct anvil_err *err);
/* Whether s[0..n) is valid UTF-8 (no overlong forms, surrogates or code
 * points above U+10FFFF). */
int anvil_utf8_valid(const char *s, size_t n);

/* Print "key = value" lines for the keys of sec that are set; for
 * ANVIL_SEC_MATERIAL those of sc->custom[custom]. */
void anvil_scene_keys_write(const struct anvil_scene *sc, int sec, int custom,
			    FILE *out);

/* scene_materials.c.  value as a body's material: *name its canonical
 * spelling (a built-in or defined material's, or value itself when
 * deferred and not yet defined); ANVIL_EPARSE for a bad name or, not
 * deferred, an unknown one (with a suggestion). */
int anvil_scene_material_name(const struct anvil_scene *sc, const char *value, int deferred,
			      const char **name, struct anvil_err *err);
/* Define (or find) the custom material NAME; ANVIL_EPARSE for a bad or
 * built-in name or too many materials. */
int anvil_scene_custom_define(struct anvil_scene *sc, const char *name,
			      struct anvil_material **m, struct anvil_err *err);
/* A custom material is complete (E, nu, rho set) and valid. */
int anvil_scene_custom_check(const struct anvil_material *m, struct anvil_err *err);

/* Set b->mat from b->material and b's overrides; ANVIL_EPARSE for an
 * unknown or incomplete material (with a suggestion). */
int anvil_scene_resolve(struct anvil_scene *sc, struct anvil_body *b,
			struct anvil_err *err);

#endif
