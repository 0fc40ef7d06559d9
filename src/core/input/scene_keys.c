/* scene_keys.c: the scene's keys, one table row each (material names:
 * scene_materials.c).
 *
 * A row says where a key lives (section, field), how its text is read and
 * checked, and how it is printed back; parsing, anvil_scene_set and
 * anvil_scene_write all go through the same rows, so they cannot drift. */
#include <ctype.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "scene_keys.h"
#include "units.h"

/* Longest value text: a path of ANVIL_PATH_MAX - 1 bytes, each byte
 * escaped, in quotes. */
#define VALUE_MAX (2 * ANVIL_PATH_MAX + 8)

static const char *const section_names[ANVIL_SEC_COUNT] = {
	"scene", "impactor", "layer", "impact", "solver", "effects", "output", "material"};

const char *anvil_scene_section_name(int sec)
{
	return sec >= 0 && sec < ANVIL_SEC_COUNT ? section_names[sec] : "?";
}

int anvil_scene_section_find(const char *name, struct anvil_err *err)
{
	struct anvil_suggest s;
	anvil_suggest_init(&s, name);
	for (int i = 0; i < ANVIL_SEC_COUNT; ++i) {
		if (strcasecmp(name, section_names[i]) == 0)
			return i;
		anvil_suggest_try(&s, section_names[i]);
	}
	if (s.best[0])
		anvil_err_set(err, ANVIL_EPARSE, "unknown section '%s'; did you mean '%s'?",
			      name, s.best);
	else
		anvil_err_set(err, ANVIL_EPARSE,
			      "unknown section '%s' (sections: scene, impactor, layer, "
			      "impact, solver, effects, output, material NAME)", name);
	return -1;
}

/* ---- the key table ---- */

enum base { BASE_SCENE, BASE_BODY, BASE_MATERIAL };

struct key;
/* Parse, check and store value (already trimmed) into base. */
typedef int key_set_fn(struct anvil_scene *sc, void *base, const struct key *k,
		       const char *value, int deferred, struct anvil_err *err);
/* Print the stored value into buf; 0 when the key is not set. */
typedef int key_put_fn(const void *base, const struct key *k, char *buf, size_t n);

struct key {
	int sec;
	const char *name;
	key_set_fn *set;
	key_put_fn *put;
	enum base base;
	size_t off;         /* of the double in the base struct */
	enum anvil_dim dim; /* of that double */
	double lo, hi;      /* its range (ANVIL_RANGE_*) */
};

#define FIELD(base, k) ((double *)((char *)(base) + (k)->off))
#define CFIELD(base, k) ((const double *)((const char *)(base) + (k)->off))

int anvil_scene_range_check(double v, double lo, double hi, const char *unit,
			    const char *text, struct anvil_err *err)
{
	if (v >= lo && v <= hi)
		return ANVIL_OK;
	return anvil_err_set(err, ANVIL_EPARSE, "must be within %g .. %g%s%s, got '%s'", lo, hi,
			     unit[0] ? " " : "", unit, text);
}

/* The shortest text that reads back to the same double: the fewest %g
 * digits (at most 17), or the integer itself when that is shorter
 * ("7830", not "7.83e+03"). */
static void put_double(char *buf, size_t n, double v, const char *unit)
{
	char num[40], whole[40];
	for (int prec = 1; prec <= 17; ++prec) {
		snprintf(num, sizeof num, "%.*g", prec, v);
		if (strtod(num, NULL) == v)
			break;
	}
	if (v == floor(v) && fabs(v) < 1e15) {
		snprintf(whole, sizeof whole, "%.0f", v);
		if (strlen(whole) <= strlen(num))
			snprintf(num, sizeof num, "%s", whole);
	}
	snprintf(buf, n, "%s%s%s", num, unit[0] ? " " : "", unit);
}

static int set_quantity(struct anvil_scene *sc, void *base, const struct key *k,
			const char *value, int deferred, struct anvil_err *err)
{
	double v;
	int st;
	(void)sc;
	(void)deferred;
	if ((st = anvil_units_parse_with_unit(value, k->dim, &v, err)) ||
	    (st = anvil_scene_range_check(v, k->lo, k->hi, anvil_units_si_name(k->dim), value,
					  err)))
		return st;
	*FIELD(base, k) = v;
	return ANVIL_OK;
}

static int put_quantity(const void *base, const struct key *k, char *buf, size_t n)
{
	double v = *CFIELD(base, k);
	if (isnan(v))
		return 0; /* an override that is not set */
	put_double(buf, n, v, anvil_units_si_name(k->dim));
	return 1;
}

/* Free text (titles, file names) goes into charts, TSV and JSON: one line
 * of valid UTF-8. */
static int text_check(const char *value, struct anvil_err *err)
{
	for (const char *p = value; *p; ++p)
		if (iscntrl((unsigned char)*p))
			return anvil_err_set(err, ANVIL_EPARSE, "must be one line of text");
	if (!anvil_utf8_valid(value, strlen(value)))
		return anvil_err_set(err, ANVIL_EPARSE, "is not valid UTF-8 text");
	return ANVIL_OK;
}

static int set_title(struct anvil_scene *sc, void *base, const struct key *k,
		     const char *value, int deferred, struct anvil_err *err)
{
	int st;
	(void)base;
	(void)k;
	(void)deferred;
	if ((st = text_check(value, err)))
		return st;
	if (strlen(value) >= sizeof sc->title)
		return anvil_err_set(err, ANVIL_EPARSE, "longer than %d bytes",
				     (int)sizeof sc->title - 1);
	snprintf(sc->title, sizeof sc->title, "%s", value);
	sc->title_set = 1;
	return ANVIL_OK;
}

static int put_title(const void *base, const struct key *k, char *buf, size_t n)
{
	(void)k;
	anvil_scene_text_put(buf, n, ((const struct anvil_scene *)base)->title);
	return 1;
}

static int set_material(struct anvil_scene *sc, void *base, const struct key *k,
			const char *value, int deferred, struct anvil_err *err)
{
	struct anvil_body *b = base;
	const char *name;
	(void)k;
	int st = anvil_scene_material_name(sc, value, deferred, &name, err);
	if (!st)
		snprintf(b->material, sizeof b->material, "%s", name);
	return st;
}

static int put_material(const void *base, const struct key *k, char *buf, size_t n)
{
	const struct anvil_body *b = base;
	(void)k;
	snprintf(buf, n, "%s", b->material);
	return b->material[0] != '\0';
}

static int set_thickness(struct anvil_scene *sc, void *base, const struct key *k,
			 const char *value, int deferred, struct anvil_err *err)
{
	size_t n = strlen(value);
	double v;
	int per_r0 = 0;
	(void)base;
	(void)k;
	(void)deferred;
	if (strcasecmp(value, "inf") == 0 || strcasecmp(value, "infinity") == 0) {
		v = INFINITY;
	} else if (n >= 2 && strcasecmp(value + n - 2, "r0") == 0) {
		char num[VALUE_MAX];
		snprintf(num, sizeof num, "%.*s", (int)(n - 2), value);
		per_r0 = 1;
		if (anvil_units_parse(num, ANVIL_DIM_NONE, &v, NULL))
			goto bad;
	} else if (anvil_units_parse(value, ANVIL_DIM_LENGTH, &v, NULL)) {
		goto bad;
	} else if (anvil_units_parse_with_unit(value, ANVIL_DIM_LENGTH, &v, err)) {
		if (!(v > 0)) /* a bare 0 or less: no unit makes it a thickness */
			return anvil_err_set(err, ANVIL_EPARSE, "must be > 0, got '%s' (or 'inf' "
					     "for a half-space)", value);
		return anvil_err_set(err, ANVIL_EPARSE, "'%s' needs a unit, e.g. %s mm or %s r0 "
				     "(lengths: m, cm, mm, um; or 'inf')", value, value, value);
	}
	if (!(v > 0))
		return anvil_err_set(err, ANVIL_EPARSE, "must be > 0, got '%s'", value);
	/* h itself is checked against its range by anvil_scene_check (r0 may
	 * change after); here only what no r0 can make sensible. */
	if (!per_r0 && !isinf(v) && anvil_scene_range_check(v, ANVIL_RANGE_LENGTH, "m", value, err))
		return ANVIL_EPARSE;
	if (per_r0 && anvil_scene_range_check(v, ANVIL_RANGE_H_R0, "r0", value, err))
		return ANVIL_EPARSE;
	sc->thickness = v;
	sc->thickness_per_r0 = per_r0;
	return ANVIL_OK;
bad:
	return anvil_err_set(err, ANVIL_EPARSE,
			     "expected a length such as '4 mm' or '2 r0', got '%s' (or 'inf' "
			     "for a half-space)", value);
}

static int put_thickness(const void *base, const struct key *k, char *buf, size_t n)
{
	const struct anvil_scene *sc = base;
	(void)k;
	if (isinf(sc->thickness))
		snprintf(buf, n, "inf");
	else
		put_double(buf, n, sc->thickness, sc->thickness_per_r0 ? "r0" : "m");
	return 1;
}

static int set_dt(struct anvil_scene *sc, void *base, const struct key *k,
		  const char *value, int deferred, struct anvil_err *err)
{
	double v = 0;
	(void)base;
	(void)k;
	(void)deferred;
	if (strcasecmp(value, "auto") != 0) {
		if (anvil_units_parse(value, ANVIL_DIM_TIME, &v, NULL))
			return anvil_err_set(err, ANVIL_EPARSE,
					     "expected a time such as '0.16 us' or 'auto', got '%s'",
					     value);
		if (anvil_units_parse_with_unit(value, ANVIL_DIM_TIME, &v, err) ||
		    anvil_scene_range_check(v, ANVIL_RANGE_DT, "s", value, err))
			return ANVIL_EPARSE;
	}
	sc->dt = v;
	return ANVIL_OK;
}

static int put_dt(const void *base, const struct key *k, char *buf, size_t n)
{
	const struct anvil_scene *sc = base;
	(void)k;
	if (sc->dt == 0)
		snprintf(buf, n, "auto");
	else
		put_double(buf, n, sc->dt, "s");
	return 1;
}

/* "expected a, b or c, got 'x'; did you mean 'y'?" for a closed set of names. */
static int choice_error(const char *value, const char *const *names, int count,
			const char *more, struct anvil_err *err)
{
	char list[160] = "";
	size_t len = 0;
	struct anvil_suggest s;
	anvil_suggest_init(&s, value);
	for (int i = 0; i < count && len < sizeof list; ++i) {
		anvil_suggest_try(&s, names[i]);
		len += (size_t)snprintf(list + len, sizeof list - len, "%s%s",
					i == 0 ? "" : i == count - 1 && !more ? " or " : ", ",
					names[i]);
	}
	if (more && len < sizeof list)
		snprintf(list + len, sizeof list - len, " or %s", more);
	if (s.best[0])
		return anvil_err_set(err, ANVIL_EPARSE, "expected %s, got '%s'; did you mean '%s'?",
				     list, value, s.best);
	return anvil_err_set(err, ANVIL_EPARSE, "expected %s, got '%s'", list, value);
}

static int set_accuracy(struct anvil_scene *sc, void *base, const struct key *k,
			const char *value, int deferred, struct anvil_err *err)
{
	const char *names[ANVIL_ACC_COUNT];
	int a = anvil_accuracy_parse(value);
	(void)base;
	(void)k;
	(void)deferred;
	if (a < 0) {
		for (int i = 0; i < ANVIL_ACC_COUNT; ++i)
			names[i] = anvil_accuracy_name((enum anvil_accuracy)i);
		return choice_error(value, names, ANVIL_ACC_COUNT, NULL, err);
	}
	sc->accuracy = (enum anvil_accuracy)a;
	return ANVIL_OK;
}

static int put_accuracy(const void *base, const struct key *k, char *buf, size_t n)
{
	(void)k;
	snprintf(buf, n, "%s", anvil_accuracy_name(((const struct anvil_scene *)base)->accuracy));
	return 1;
}

static const char *const scheme_names[] = {"implicit", "paper"};
#define NSCHEMES ((int)(sizeof scheme_names / sizeof scheme_names[0]))

static int set_scheme(struct anvil_scene *sc, void *base, const struct key *k,
		      const char *value, int deferred, struct anvil_err *err)
{
	(void)base;
	(void)k;
	(void)deferred;
	for (int i = 0; i < NSCHEMES; ++i) {
		if (strcasecmp(value, scheme_names[i]) == 0) {
			sc->scheme = (enum anvil_scheme)i;
			return ANVIL_OK;
		}
	}
	return choice_error(value, scheme_names, NSCHEMES, NULL, err);
}

static int put_scheme(const void *base, const struct key *k, char *buf, size_t n)
{
	unsigned s = (unsigned)((const struct anvil_scene *)base)->scheme;
	(void)k;
	snprintf(buf, n, "%s", s < (unsigned)NSCHEMES ? scheme_names[s] : "?");
	return 1;
}

/* "hertz, layer" or "all"; spaces around the commas are fine. */
static int set_models(struct anvil_scene *sc, void *base, const struct key *k,
		      const char *value, int deferred, struct anvil_err *err)
{
	unsigned bits = 0;
	const char *p = value;
	(void)base;
	(void)k;
	(void)deferred;
	while (*p) {
		size_t n = strcspn(p, ",");
		char word[VALUE_MAX];
		snprintf(word, sizeof word, "%.*s", (int)n, p);
		char *w = word, *e = word + strlen(word);
		while (isspace((unsigned char)*w))
			++w;
		while (e > w && isspace((unsigned char)e[-1]))
			*--e = '\0';
		int m = anvil_model_parse(w);
		if (!*w) {
			/* "hertz,,layer": an empty item is no model */
		} else if (strcasecmp(w, "all") == 0) {
			bits |= ANVIL_MODELS_ALL;
		} else if (m >= 0) {
			bits |= 1u << m;
		} else {
			const char *names[ANVIL_MODEL_COUNT];
			for (int i = 0; i < ANVIL_MODEL_COUNT; ++i)
				names[i] = anvil_model_name((enum anvil_model)i);
			return choice_error(w, names, ANVIL_MODEL_COUNT, "'all'", err);
		}
		p += n + (p[n] == ',');
	}
	if (!bits)
		return anvil_err_set(err, ANVIL_EPARSE,
				     "expected a list of models such as 'hertz, layer' or 'all', "
				     "got '%s'", value);
	sc->models = bits;
	return ANVIL_OK;
}

static int put_models(const void *base, const struct key *k, char *buf, size_t n)
{
	unsigned bits = ((const struct anvil_scene *)base)->models;
	size_t len = 0;
	(void)k;
	buf[0] = '\0';
	if (bits == ANVIL_MODELS_ALL) {
		snprintf(buf, n, "all");
		return 1;
	}
	for (int i = 0; i < ANVIL_MODEL_COUNT && len < n; ++i)
		if (bits & (1u << i))
			len += (size_t)snprintf(buf + len, n - len, "%s%s", len ? ", " : "",
						anvil_model_name((enum anvil_model)i));
	return 1;
}

/* ---- [effects] and [output] ---- */

static int set_waves(struct anvil_scene *sc, void *base, const struct key *k,
		     const char *value, int deferred, struct anvil_err *err)
{
	const char *names[ANVIL_WAVES_COUNT];
	int w = anvil_waves_parse(value);
	(void)base;
	(void)k;
	(void)deferred;
	if (w < 0) {
		for (int i = 0; i < ANVIL_WAVES_COUNT; ++i)
			names[i] = anvil_waves_name((enum anvil_waves)i);
		return choice_error(value, names, ANVIL_WAVES_COUNT, NULL, err);
	}
	sc->effects.waves = (enum anvil_waves)w;
	return ANVIL_OK;
}

static int put_waves(const void *base, const struct key *k, char *buf, size_t n)
{
	(void)k;
	snprintf(buf, n, "%s", anvil_waves_name(((const struct anvil_scene *)base)->effects.waves));
	return 1;
}

/* --- contactB: [effects] contact (options.h) --- */
static const char *const contact_names[ANVIL_CONTACT_COUNT] = { "auto", "physical", "paper",
								 "both" };

const char *anvil_contact_name(enum anvil_contact c)
{
	return (unsigned)c < ANVIL_CONTACT_COUNT ? contact_names[c] : "unknown";
}

int anvil_contact_parse(const char *name)
{
	for (int i = 0; name && i < ANVIL_CONTACT_COUNT; ++i)
		if (strcasecmp(name, contact_names[i]) == 0)
			return i;
	return -1;
}

static int set_contact(struct anvil_scene *sc, void *base, const struct key *k,
		       const char *value, int deferred, struct anvil_err *err)
{
	int c = anvil_contact_parse(value);
	(void)base;
	(void)k;
	(void)deferred;
	if (c < 0)
		return choice_error(value, contact_names, ANVIL_CONTACT_COUNT, NULL, err);
	sc->effects.contact = (enum anvil_contact)c;
	return ANVIL_OK;
}

static int put_contact(const void *base, const struct key *k, char *buf, size_t n)
{
	(void)k;
	snprintf(buf, n, "%s", anvil_contact_name(((const struct anvil_scene *)base)->effects.contact));
	return 1;
}
/* --- end contactB --- */

static int set_field(struct anvil_scene *sc, void *base, const struct key *k,
		     const char *value, int deferred, struct anvil_err *err)
{
	const char *names[ANVIL_FIELDMODE_COUNT];
	int f = anvil_fieldmode_parse(value);
	(void)base;
	(void)k;
	(void)deferred;
	if (f < 0) {
		for (int i = 0; i < ANVIL_FIELDMODE_COUNT; ++i)
			names[i] = anvil_fieldmode_name((enum anvil_fieldmode)i);
		return choice_error(value, names, ANVIL_FIELDMODE_COUNT, NULL, err);
	}
	sc->effects.field = (enum anvil_fieldmode)f;
	return ANVIL_OK;
}

static int put_field(const void *base, const struct key *k, char *buf, size_t n)
{
	(void)k;
	snprintf(buf, n, "%s", anvil_fieldmode_name(((const struct anvil_scene *)base)->effects.field));
	return 1;
}

/* on|off switches: an int at k->off in the scene. */
static const char *const switch_names[] = {"off", "on"};

static int set_switch(struct anvil_scene *sc, void *base, const struct key *k,
		      const char *value, int deferred, struct anvil_err *err)
{
	(void)sc;
	(void)deferred;
	for (int i = 0; i < 2; ++i) {
		if (strcasecmp(value, switch_names[i]) == 0) {
			*(int *)((char *)base + k->off) = i;
			return ANVIL_OK;
		}
	}
	return choice_error(value, switch_names, 2, NULL, err);
}

static int put_switch(const void *base, const struct key *k, char *buf, size_t n)
{
	snprintf(buf, n, "%s", switch_names[*(const int *)((const char *)base + k->off) != 0]);
	return 1;
}

/* FILE|off: a char[ANVIL_PATH_MAX] at k->off in the scene, "" for off.
 * The text must survive anvil_scene_write and a new parse, as a title. */
static int set_path(struct anvil_scene *sc, void *base, const struct key *k,
		    const char *value, int deferred, struct anvil_err *err)
{
	char *dst = (char *)base + k->off;
	(void)sc;
	(void)deferred;
	int st;
	if (!*value)
		return anvil_err_set(err, ANVIL_EPARSE, "expected a file name or 'off'");
	if ((st = text_check(value, err)))
		return st;
	if (strlen(value) >= ANVIL_PATH_MAX)
		return anvil_err_set(err, ANVIL_EPARSE, "longer than %d characters",
				     ANVIL_PATH_MAX - 1);
	snprintf(dst, ANVIL_PATH_MAX, "%s", strcasecmp(value, "off") == 0 ? "" : value);
	return ANVIL_OK;
}

static int put_path(const void *base, const struct key *k, char *buf, size_t n)
{
	const char *path = (const char *)base + k->off;
	char text[ANVIL_PATH_MAX + 2];
	/* a file really called "off" is written so that it reads back as one */
	snprintf(text, sizeof text, "%s%s", strcasecmp(path, "off") == 0 ? "./" : "",
		 *path ? path : "off");
	anvil_scene_text_put(buf, n, text);
	return 1;
}

/* ---- the impactor's geometry (impactor.c derives from it) ---- */

static int set_shape(struct anvil_scene *sc, void *base, const struct key *k,
		     const char *value, int deferred, struct anvil_err *err)
{
	const char *names[ANVIL_SHAPE_COUNT];
	int s = anvil_shape_parse(value);
	(void)base;
	(void)k;
	(void)deferred;
	if (s < 0) {
		for (int i = 0; i < ANVIL_SHAPE_COUNT; ++i)
			names[i] = anvil_shape_name((enum anvil_shape)i);
		return choice_error(value, names, ANVIL_SHAPE_COUNT, NULL, err);
	}
	sc->shape = (enum anvil_shape)s;
	return ANVIL_OK;
}

static int put_shape(const void *base, const struct key *k, char *buf, size_t n)
{
	(void)k;
	snprintf(buf, n, "%s", anvil_shape_name(((const struct anvil_scene *)base)->shape));
	return 1;
}

static int set_mass(struct anvil_scene *sc, void *base, const struct key *k,
		    const char *value, int deferred, struct anvil_err *err)
{
	int st = set_quantity(sc, base, k, value, deferred, err);
	if (!st)
		sc->mass_given = 1;
	return st;
}

/* Mass, radius and velocity are written only where they are not derived
 * from another key, so that the text reads back without a conflict. */
static int put_mass(const void *base, const struct key *k, char *buf, size_t n)
{
	const struct anvil_scene *sc = base;
	if (!sc->mass_given && (sc->shape == ANVIL_SHAPE_BALL || !isnan(sc->length)))
		return 0;
	return put_quantity(base, k, buf, n);
}

static int put_radius(const void *base, const struct key *k, char *buf, size_t n)
{
	return isnan(((const struct anvil_scene *)base)->diameter) && put_quantity(base, k, buf, n);
}

static int put_velocity(const void *base, const struct key *k, char *buf, size_t n)
{
	return isnan(((const struct anvil_scene *)base)->drop_height) &&
	       put_quantity(base, k, buf, n);
}

/* A body's brittle override: a double, NaN when not set. */
static int set_brittle(struct anvil_scene *sc, void *base, const struct key *k,
		       const char *value, int deferred, struct anvil_err *err)
{
	(void)sc;
	(void)deferred;
	for (int i = 0; i < 2; ++i) {
		if (strcasecmp(value, switch_names[i]) == 0) {
			*FIELD(base, k) = i;
			return ANVIL_OK;
		}
	}
	return choice_error(value, switch_names, 2, NULL, err);
}

static int put_brittle(const void *base, const struct key *k, char *buf, size_t n)
{
	double v = *CFIELD(base, k);
	if (isnan(v))
		return 0;
	snprintf(buf, n, "%s", switch_names[v != 0]);
	return 1;
}

#define S(sec) ANVIL_SEC_##sec
#define D(dim) ANVIL_DIM_##dim
#define Q(sec, key, base, type, field, dim, range)                                  \
	{S(sec), key, set_quantity, put_quantity, base, offsetof(type, field), D(dim), \
	 ANVIL_RANGE_##range}
#define SCENE_Q(sec, key, field, dim, range) \
	Q(sec, key, BASE_SCENE, struct anvil_scene, field, dim, range)
#define FN(sec, key, base, fn) \
	{S(sec), key, set_##fn, put_##fn, base, 0, ANVIL_DIM_NONE, 0, 0}
/* An int or a char array of the scene, handled by set_/put_fn. */
#define AT(sec, key, field, fn) \
	{S(sec), key, set_##fn, put_##fn, BASE_SCENE, offsetof(struct anvil_scene, field), \
	 ANVIL_DIM_NONE, 0, 0}
/* A double of the scene with its own set_ or put_ function. */
#define SCENE_QF(sec, key, field, dim, range, setfn, putfn)                          \
	{S(sec), key, setfn, putfn, BASE_SCENE, offsetof(struct anvil_scene, field), D(dim), \
	 ANVIL_RANGE_##range}
/* E, nu, rho, yield, tensile: of a body (an override) or of a [material
 * NAME]; brittle: the body's override (a double) or the material's int. */
#define ELASTIC(sec, base, type)                                    \
	Q(sec, "E", base, type, E, PRESSURE, E),                    \
	Q(sec, "nu", base, type, nu, NONE, NU),                     \
	Q(sec, "rho", base, type, rho, DENSITY, RHO),               \
	Q(sec, "yield", base, type, yield, PRESSURE, YIELD),        \
	Q(sec, "tensile", base, type, tensile, PRESSURE, YIELD)
#define BODY_BRITTLE(sec)                                                         \
	{S(sec), "brittle", set_brittle, put_brittle, BASE_BODY,                 \
	 offsetof(struct anvil_body, brittle), ANVIL_DIM_NONE, 0, 0}

/* In the order anvil_scene_write prints them. */
static const struct key keys[] = {
	FN(SCENE, "title", BASE_SCENE, title),
	FN(IMPACTOR, "material", BASE_BODY, material),
	FN(IMPACTOR, "shape", BASE_SCENE, shape),
	SCENE_QF(IMPACTOR, "mass", mass, MASS, MASS, set_mass, put_mass),
	SCENE_QF(IMPACTOR, "radius", radius, LENGTH, LENGTH, set_quantity, put_radius),
	SCENE_Q(IMPACTOR, "diameter", diameter, LENGTH, LENGTH),
	SCENE_Q(IMPACTOR, "length", length, LENGTH, LENGTH),
	ELASTIC(IMPACTOR, BASE_BODY, struct anvil_body),
	BODY_BRITTLE(IMPACTOR),
	FN(LAYER, "material", BASE_BODY, material),
	FN(LAYER, "thickness", BASE_SCENE, thickness),
	ELASTIC(LAYER, BASE_BODY, struct anvil_body),
	BODY_BRITTLE(LAYER),
	SCENE_QF(IMPACT, "velocity", velocity, VELOCITY, VELOCITY, set_quantity, put_velocity),
	SCENE_Q(IMPACT, "drop_height", drop_height, LENGTH, LENGTH),
	FN(SOLVER, "accuracy", BASE_SCENE, accuracy),
	FN(SOLVER, "scheme", BASE_SCENE, scheme),
	FN(SOLVER, "dt", BASE_SCENE, dt),
	FN(SOLVER, "models", BASE_SCENE, models),
	FN(EFFECTS, "waves", BASE_SCENE, waves),
	AT(EFFECTS, "plate", effects.plate, switch),
	AT(EFFECTS, "quasistatic", effects.quasistatic, switch),
	FN(EFFECTS, "field", BASE_SCENE, field),
	FN(EFFECTS, "contact", BASE_SCENE, contact),
	AT(OUTPUT, "table", output.table, switch),
	AT(OUTPUT, "histories", output.histories, path),
	AT(OUTPUT, "charts", output.charts, path),
	AT(OUTPUT, "field", output.field, path),
	ELASTIC(MATERIAL, BASE_MATERIAL, struct anvil_material),
	{S(MATERIAL), "brittle", set_switch, put_switch, BASE_MATERIAL,
	 offsetof(struct anvil_material, brittle), ANVIL_DIM_NONE, 0, 0},
};
#define NKEYS ((int)(sizeof keys / sizeof keys[0]))
_Static_assert(NKEYS <= ANVIL_SCENE_KEYS_MAX, "sc->key_line is too short");

static void *key_base(struct anvil_scene *sc, const struct key *k,
		      struct anvil_material *m)
{
	switch (k->base) {
	case BASE_BODY:
		return k->sec == ANVIL_SEC_IMPACTOR ? &sc->impactor : &sc->layer;
	case BASE_MATERIAL:
		return m;
	case BASE_SCENE:
		break;
	}
	return sc;
}

static const struct key *key_find(int sec, const char *name)
{
	for (int i = 0; i < NKEYS; ++i)
		if (keys[i].sec == sec && strcasecmp(keys[i].name, name) == 0)
			return &keys[i];
	return NULL;
}

static int key_unknown(int sec, const char *name, const char *key, struct anvil_err *err)
{
	struct anvil_suggest s;
	char cand[80], list[160] = "";
	size_t len = 0;
	anvil_suggest_init(&s, key);
	for (int i = 0; i < NKEYS; ++i) {
		const struct key *k = &keys[i];
		if (k->sec == ANVIL_SEC_MATERIAL)
			snprintf(cand, sizeof cand, "material.%s.%s", name ? name : "NAME", k->name);
		else
			snprintf(cand, sizeof cand, "%s.%s", section_names[k->sec], k->name);
		if (sec < 0 && k->sec != ANVIL_SEC_MATERIAL) {
			anvil_suggest_try(&s, cand); /* no section given: any key */
		} else if (k->sec == sec) {
			anvil_suggest_try(&s, cand);
			if (len < sizeof list)
				len += (size_t)snprintf(list + len, sizeof list - len, "%s%s",
							len ? ", " : "", k->name);
		} else if (s.dist > 0 && k->sec != ANVIL_SEC_MATERIAL &&
			   strcasecmp(k->name, key) == 0) {
			/* The right key in the wrong section. */
			s.dist = 0;
			snprintf(s.best, sizeof s.best, "%s", cand);
		}
	}
	if (s.best[0])
		return anvil_err_set(err, ANVIL_EPARSE, "unknown key; did you mean '%s'?", s.best);
	if (sec < 0)
		return anvil_err_set(err, ANVIL_EPARSE,
				     "unknown key (keys are SECTION.KEY, e.g. impactor.mass)");
	return anvil_err_set(err, ANVIL_EPARSE, "unknown key (keys of [%s]: %s)",
			     section_names[sec], list);
}

int anvil_scene_key_index(int sec, const char *key)
{
	const struct key *k = key_find(sec, key);
	return k ? (int)(k - keys) : -1;
}

int anvil_scene_key_set(struct anvil_scene *sc, int sec, const char *name,
			const char *key, const char *value, int deferred, int line,
			struct anvil_err *err)
{
	char v[VALUE_MAX];
	const struct key *k = key_find(sec, key);
	struct anvil_material *m = NULL;
	int st;
	if (!k)
		return key_unknown(sec, name, key, err);
	while (isspace((unsigned char)*value))
		++value;
	size_t n = strlen(value);
	while (n > 0 && isspace((unsigned char)value[n - 1]))
		--n;
	if (n >= sizeof v)
		return anvil_err_set(err, ANVIL_EPARSE, "value longer than %d characters",
				     (int)sizeof v - 1);
	if (n > 0 && value[0] == '"') {
		if ((st = anvil_scene_text_unquote(value, n, v, err)))
			return st;
	} else {
		snprintf(v, sizeof v, "%.*s", (int)n, value);
	}
	if (sec == ANVIL_SEC_MATERIAL && (st = anvil_scene_custom_define(sc, name, &m, err)))
		return st;
	if ((st = k->set(sc, key_base(sc, k, m), k, v, deferred, err)))
		return st;
	anvil_scene_geometry_replace(sc, sec, k->name);
	sc->key_line[k - keys] = line;
	return ANVIL_OK;
}

void anvil_scene_keys_write(const struct anvil_scene *sc, int sec, int custom,
			    FILE *out)
{
	/* key_base only computes an address; nothing is written through it. */
	struct anvil_scene *s = (struct anvil_scene *)sc;
	struct anvil_material *m = sec == ANVIL_SEC_MATERIAL ? &s->custom[custom] : NULL;
	char buf[VALUE_MAX];
	for (int i = 0; i < NKEYS; ++i)
		if (keys[i].sec == sec && keys[i].put(key_base(s, &keys[i], m), &keys[i],
						      buf, sizeof buf))
			fprintf(out, "%s = %s\n", keys[i].name, buf);
}
