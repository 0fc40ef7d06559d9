/* scene_materials.c: a body's material by name: the built-in ones, those
 * a scene defines ([material NAME]) and the overrides of a body's keys,
 * with "did you mean" for a typo and a word for a real material anvil has
 * no numbers for (scene_keys.h). */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "scene_keys.h"

#define CUSTOM_SOURCE "defined in the scene"
#define OVERRIDE_SOURCE "overridden in the scene"


static int name_ok(const char *name)
{
	size_t n = strlen(name);
	if (n == 0 || n >= ANVIL_NAME_MAX || !isalpha((unsigned char)name[0]))
		return 0;
	for (; *name; ++name)
		if (!isalnum((unsigned char)*name) && *name != '-' && *name != '_')
			return 0;
	return 1;
}

static int name_error(const char *name, struct anvil_err *err)
{
	return anvil_err_set(err, ANVIL_EPARSE,
			     "expected a material name such as 'steel' (a letter, then "
			     "letters, digits, '-' or '_'; at most %d), got '%s'",
			     ANVIL_NAME_MAX - 1, name);
}

static struct anvil_material *custom_find(const struct anvil_scene *sc, const char *name)
{
	for (int i = 0; i < sc->ncustom && i < ANVIL_MAX_CUSTOM; ++i)
		if (strcasecmp(name, sc->custom[i].name) == 0)
			return (struct anvil_material *)&sc->custom[i];
	return NULL;
}

/* Real materials anvil has no numbers for: a name one or two letters from
 * a built-in one ("brass", "glass") is not a typo of it. */
static const char *const lacking[] = {
	"brass", "bronze", "iron", "cast-iron", "lead", "gold", "silver", "nickel", "zinc",
	"tin", "magnesium", "platinum", "rubber", "nylon", "wood", "concrete", "granite",
	"marble", "ice", "bone", "ceramic", "alumina", "diamond", "quartz"};

/* Material names are short and many differ by two letters ("brass",
 * "glass"): one edit is a typo, two only when the first letter is right
 * ("copr", "copper"), as it nearly always is in a typo. */
static void material_suggest(struct anvil_suggest *s, const char *cand)
{
	struct anvil_suggest one = *s;
	anvil_suggest_try(&one, cand);
	if (one.dist <= 1 || one.dist == SUGGEST_PREFIX_DIST ||
	    (one.dist == 2 && tolower((unsigned char)s->word[0]) == tolower((unsigned char)cand[0])))
		*s = one;
}

static int material_unknown(const struct anvil_scene *sc, const char *name,
			    struct anvil_err *err)
{
	struct anvil_suggest s;
	char known[320] = "";
	size_t len = 0;
	for (size_t i = 0; i < sizeof lacking / sizeof lacking[0]; ++i)
		if (strcasecmp(name, lacking[i]) == 0)
			return anvil_err_set(err, ANVIL_EPARSE,
					     "'%s' is not a built-in material: define it with "
					     "[material %s] (E, nu, rho and optionally yield, "
					     "tensile, brittle)",
					     name, name);
	anvil_suggest_init(&s, name);
	for (int i = 0; i < anvil_material_count() + sc->ncustom; ++i) {
		const char *cand = i < anvil_material_count()
					   ? anvil_material_at(i)->name
					   : sc->custom[i - anvil_material_count()].name;
		material_suggest(&s, cand);
		if (len < sizeof known)
			len += (size_t)snprintf(known + len, sizeof known - len, "%s%s",
						len ? ", " : "", cand);
	}
	if (s.best[0])
		return anvil_err_set(err, ANVIL_EPARSE,
				     "unknown material '%s'; did you mean '%s'?", name, s.best);
	return anvil_err_set(err, ANVIL_EPARSE,
			     "unknown material '%s' (known: %s; or define [material %s])",
			     name, known, name);
}

int anvil_scene_material_name(const struct anvil_scene *sc, const char *value, int deferred,
			      const char **name, struct anvil_err *err)
{
	if (!name_ok(value))
		return name_error(value, err);
	const struct anvil_material *m = custom_find(sc, value);
	if (!m)
		m = anvil_material_find(value);
	/* While parsing, [material NAME] may come after its use. */
	if (!m && !deferred)
		return material_unknown(sc, value, err);
	*name = m ? m->name : value;
	return ANVIL_OK;
}

int anvil_scene_custom_define(struct anvil_scene *sc, const char *name,
			      struct anvil_material **m, struct anvil_err *err)
{
	if (!name_ok(name))
		return name_error(name, err);
	if (anvil_material_find(name))
		return anvil_err_set(err, ANVIL_EPARSE,
				     "'%s' is a built-in material; give yours another name",
				     name);
	*m = custom_find(sc, name);
	if (*m)
		return ANVIL_OK;
	if (sc->ncustom >= ANVIL_MAX_CUSTOM)
		return anvil_err_set(err, ANVIL_EPARSE,
				     "too many materials (at most %d)", ANVIL_MAX_CUSTOM);
	*m = &sc->custom[sc->ncustom++];
	memset(*m, 0, sizeof **m);
	snprintf((*m)->name, sizeof (*m)->name, "%s", name);
	(*m)->E = (*m)->nu = (*m)->rho = NAN;
	(*m)->yield = 0; /* optional: unknown */
	(*m)->source = CUSTOM_SOURCE;
	return ANVIL_OK;
}

int anvil_scene_custom_check(const struct anvil_material *m, struct anvil_err *err)
{
	const char *unset = isnan(m->E) ? "E" : isnan(m->nu) ? "nu" : isnan(m->rho) ? "rho" : NULL;
	if (unset)
		return anvil_err_set(err, ANVIL_EPARSE,
				     "material '%s' is incomplete: %s is not set (E, nu and rho "
				     "are needed)", m->name, unset);
	return anvil_material_check(m, err);
}

int anvil_scene_resolve(struct anvil_scene *sc, struct anvil_body *b,
			struct anvil_err *err)
{
	const struct anvil_material *base = custom_find(sc, b->material);
	int st;
	if (base) {
		if ((st = anvil_scene_custom_check(base, err)))
			return st;
	} else if (!(base = anvil_material_find(b->material))) {
		return material_unknown(sc, b->material, err);
	}
	struct anvil_material m = *base;
	const double over[] = {b->E, b->nu, b->rho, b->yield, b->tensile};
	double *field[] = {&m.E, &m.nu, &m.rho, &m.yield, &m.tensile};
	for (size_t i = 0; i < sizeof over / sizeof over[0]; ++i) {
		if (!isnan(over[i])) {
			*field[i] = over[i];
			m.source = OVERRIDE_SOURCE;
		}
	}
	if (!isnan(b->brittle)) {
		m.brittle = b->brittle != 0;
		m.source = OVERRIDE_SOURCE;
	}
	if ((st = anvil_material_check(&m, err)))
		return st;
	/* The canonical spelling: "Steel" and "aluminum" become "steel", "aluminium". */
	snprintf(b->material, sizeof b->material, "%s", base->name);
	b->mat = m;
	return ANVIL_OK;
}
