/* scene.c: scene text in and out, the default scene, validation and names.
 * The keys themselves (what each means, how it is read and printed) are the
 * table in scene_keys.c. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "scene.h"
#include "scene_keys.h"

/* examples/default.scene holds the same scene; a test keeps them equal. */
static const char default_text[] =
	"# The paper's case: a copper rod (m1 = 12.2 g, r0 = 4 mm) hits a free\n"
	"# steel layer of thickness h = r0 at 10 m/s (Pyr'yev et al. 2024).\n"
	"[scene]\n"
	"title = Copper rod on a steel layer (Pyr'yev et al. 2024)\n"
	"\n"
	"[impactor]\n"
	"material = copper\n"
	"mass = 12.2 g\n"
	"radius = 4 mm\n"
	"\n"
	"[layer]\n"
	"material = steel\n"
	"thickness = 1 r0\n"
	"\n"
	"[impact]\n"
	"velocity = 10 m/s\n"
	"\n"
	"[solver]\n"
	"accuracy = normal\n"
	"scheme = implicit\n"
	"dt = auto\n"
	"models = all\n";

#define LINE_MAX_CHARS 1024
#define SEEN_MAX 128 /* more than all keys of all sections and materials */
#define LABEL_MAX 80

/* ---- names ---- */

static const char *const model_names[ANVIL_MODEL_COUNT] = {
	"hertz", "zener", "layer", "halfspace"};
static const char *const waves_names[ANVIL_WAVES_COUNT] = {
	"auto", "layer", "halfspace", "none"};
static const char *const field_names[ANVIL_FIELDMODE_COUNT] = {"off", "points", "map"};

const char *anvil_model_name(enum anvil_model m)
{
	return (unsigned)m < ANVIL_MODEL_COUNT ? model_names[m] : "unknown";
}

int anvil_model_parse(const char *name)
{
	for (int i = 0; name && i < ANVIL_MODEL_COUNT; ++i)
		if (strcasecmp(name, model_names[i]) == 0)
			return i;
	return -1;
}

const char *anvil_waves_name(enum anvil_waves w)
{
	return (unsigned)w < ANVIL_WAVES_COUNT ? waves_names[w] : "unknown";
}

int anvil_waves_parse(const char *name)
{
	for (int i = 0; name && i < ANVIL_WAVES_COUNT; ++i)
		if (strcasecmp(name, waves_names[i]) == 0)
			return i;
	return -1;
}

const char *anvil_fieldmode_name(enum anvil_fieldmode f)
{
	return (unsigned)f < ANVIL_FIELDMODE_COUNT ? field_names[f] : "unknown";
}

int anvil_fieldmode_parse(const char *name)
{
	for (int i = 0; name && i < ANVIL_FIELDMODE_COUNT; ++i)
		if (strcasecmp(name, field_names[i]) == 0)
			return i;
	return -1;
}

/* ---- messages ---- */

/* "ORIGIN:LINE: LABEL: msg"; no ":LINE" when line is 0, no label when NULL. */
static int located(struct anvil_err *err, int status, const char *origin, int line,
		   const char *label, const char *msg)
{
	char at[24] = "";
	if (line > 0)
		snprintf(at, sizeof at, ":%d", line);
	return anvil_err_set(err, status, "%s%s: %s%s%s", origin, at, label ? label : "",
			     label ? ": " : "", msg);
}

/* ---- parsing ---- */

struct parser {
	struct anvil_scene *sc;
	const char *origin;
	int line;
	int sec;                    /* -1 before the first section header */
	char name[ANVIL_NAME_MAX];  /* NAME of the current [material NAME] */
	int material_line[2];       /* where impactor, layer material was set */
	int custom_line[ANVIL_MAX_CUSTOM]; /* header of each material defined */
	int nseen;
	struct {
		char label[LABEL_MAX];
		int line;
	} seen[SEEN_MAX];
};

static char *trim(char *s)
{
	while (isspace((unsigned char)*s))
		++s;
	char *e = s + strlen(s);
	while (e > s && isspace((unsigned char)e[-1]))
		*--e = '\0';
	return s;
}

/* '#' or ';' at the start of a line or after white space starts a comment;
 * elsewhere ("title = Run#3") it is text. */
static void strip_comment(char *s)
{
	for (char *p = s; *p; ++p) {
		if ((*p == '#' || *p == ';') && (p == s || isspace((unsigned char)p[-1]))) {
			*p = '\0';
			return;
		}
	}
}

static int perr(struct parser *p, struct anvil_err *err, const char *label,
		const char *fmt, ...) __attribute__((format(printf, 4, 5)));

static int perr(struct parser *p, struct anvil_err *err, const char *label,
		const char *fmt, ...)
{
	char msg[ANVIL_ERR_MSG];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	return located(err, ANVIL_EPARSE, p->origin, p->line, label, msg);
}

static int parse_header(struct parser *p, char *s, struct anvil_err *err)
{
	struct anvil_err in;
	char *close = strchr(s, ']');
	if (!close)
		return perr(p, err, NULL, "unterminated section header '%s' (missing ']')", s);
	if (*trim(close + 1))
		return perr(p, err, NULL, "unexpected text after ']': '%s'", trim(close + 1));
	*close = '\0';
	char *word = trim(s + 1), *rest = word;
	while (*rest && !isspace((unsigned char)*rest))
		++rest;
	if (*rest)
		*rest++ = '\0';
	rest = trim(rest);
	int sec = anvil_scene_section_find(word, &in);
	if (sec < 0)
		return perr(p, err, NULL, "%s", in.msg);
	if (sec == ANVIL_SEC_MATERIAL) {
		struct anvil_material *m;
		if (!*rest)
			return perr(p, err, NULL, "expected [material NAME]");
		if (anvil_scene_custom_define(p->sc, rest, &m, &in))
			return perr(p, err, NULL, "[material %s]: %s", rest, in.msg);
		int i = (int)(m - p->sc->custom);
		if (!p->custom_line[i])
			p->custom_line[i] = p->line;
		snprintf(p->name, sizeof p->name, "%s", m->name);
	} else if (*rest) {
		return perr(p, err, NULL, "unexpected '%s' in section header [%s]", rest, word);
	}
	p->sec = sec;
	return ANVIL_OK;
}

static int parse_assignment(struct parser *p, char *s, struct anvil_err *err)
{
	struct anvil_err in;
	char label[LABEL_MAX];
	char *eq = strchr(s, '=');
	if (!eq)
		return perr(p, err, NULL, "expected KEY = VALUE, got '%s'", s);
	*eq = '\0';
	char *key = trim(s), *value = eq + 1;
	if (!*key)
		return perr(p, err, NULL, "expected KEY = VALUE, got no key before '='");
	if (p->sec < 0)
		return perr(p, err, NULL,
			    "'%s' is outside any section (start with one, e.g. [impactor])", key);
	if (p->sec == ANVIL_SEC_MATERIAL)
		snprintf(label, sizeof label, "material.%s.%.32s", p->name, key);
	else
		snprintf(label, sizeof label, "%s.%.32s", anvil_scene_section_name(p->sec), key);
	for (int i = 0; i < p->nseen; ++i)
		if (strcasecmp(p->seen[i].label, label) == 0)
			return perr(p, err, label, "set twice (first on line %d)",
				    p->seen[i].line);
	if (anvil_scene_key_set(p->sc, p->sec, p->name, key, value, 1, &in))
		return perr(p, err, label, "%s", in.msg);
	if (p->nseen < SEEN_MAX) {
		snprintf(p->seen[p->nseen].label, LABEL_MAX, "%s", label);
		p->seen[p->nseen++].line = p->line;
	}
	if (strcasecmp(key, "material") == 0)
		p->material_line[p->sec == ANVIL_SEC_LAYER] = p->line;
	return ANVIL_OK;
}

static int parse_line(struct parser *p, char *s, struct anvil_err *err)
{
	strip_comment(s);
	s = trim(s);
	if (!*s)
		return ANVIL_OK;
	if (*s == '[')
		return parse_header(p, s, err);
	return parse_assignment(p, s, err);
}

/* What could not be checked line by line: materials used before their
 * [material NAME] section, and whether each defined material is complete. */
static int parse_finish(struct parser *p, struct anvil_err *err)
{
	struct anvil_scene *sc = p->sc;
	struct anvil_err in;
	char label[LABEL_MAX];
	for (int i = 0; i < sc->ncustom; ++i) {
		if (p->custom_line[i] && anvil_scene_custom_check(&sc->custom[i], &in)) {
			snprintf(label, sizeof label, "material.%s", sc->custom[i].name);
			return located(err, ANVIL_EPARSE, p->origin, p->custom_line[i], label,
				       in.msg);
		}
	}
	struct anvil_body *bodies[2] = {&sc->impactor, &sc->layer};
	const char *labels[2][2] = {{"impactor", "impactor.material"}, {"layer", "layer.material"}};
	for (int b = 0; b < 2; ++b) {
		int line = p->material_line[b];
		if (anvil_scene_resolve(sc, bodies[b], &in))
			return located(err, ANVIL_EPARSE, p->origin, line, labels[b][line > 0],
				       in.msg);
	}
	return ANVIL_OK;
}

static int parse_text(struct parser *p, const char *text, struct anvil_err *err)
{
	char buf[LINE_MAX_CHARS];
	int st;
	while (*text) {
		size_t n = strcspn(text, "\n");
		++p->line;
		if (n >= sizeof buf)
			return perr(p, err, NULL, "line longer than %d characters",
				    (int)sizeof buf - 1);
		memcpy(buf, text, n);
		buf[n] = '\0';
		if ((st = parse_line(p, buf, err)))
			return st;
		text += n + (text[n] == '\n');
	}
	return parse_finish(p, err);
}

int anvil_scene_parse(struct anvil_scene *sc, const char *text, const char *origin,
		      struct anvil_err *err)
{
	/* Work on a copy, so that a failed parse leaves sc as it was. */
	struct anvil_scene work = *sc;
	struct parser *p = calloc(1, sizeof *p);
	int st;
	if (!p)
		return anvil_err_set(err, ANVIL_ENOMEM, "%s: out of memory", origin);
	p->sc = &work;
	p->origin = origin ? origin : "scene";
	p->sec = -1;
	st = parse_text(p, text ? text : "", err);
	free(p);
	if (st == ANVIL_OK) {
		*sc = work;
		anvil_err_clear(err);
	}
	return st;
}

int anvil_scene_load(struct anvil_scene *sc, const char *path, struct anvil_err *err)
{
	int is_stdin = strcmp(path, "-") == 0;
	const char *origin = is_stdin ? "<stdin>" : path;
	FILE *f = is_stdin ? stdin : fopen(path, "r");
	char *buf = NULL, *more;
	size_t len = 0, cap = 0;
	int st = ANVIL_OK;
	if (!f)
		return anvil_err_set(err, ANVIL_EIO, "%s: cannot open: %s", origin,
				     strerror(errno));
	for (;;) {
		if (cap - len < 2) {
			cap = cap ? 2 * cap : 4096;
			if (!(more = realloc(buf, cap))) {
				st = anvil_err_set(err, ANVIL_ENOMEM, "%s: out of memory", origin);
				goto done;
			}
			buf = more;
		}
		size_t got = fread(buf + len, 1, cap - len - 1, f);
		len += got;
		if (got == 0)
			break;
	}
	if (ferror(f)) {
		st = anvil_err_set(err, ANVIL_EIO, "%s: cannot read: %s", origin, strerror(errno));
		goto done;
	}
	buf[len] = '\0';
	if (memchr(buf, '\0', len))
		st = anvil_err_set(err, ANVIL_EPARSE, "%s: contains a NUL byte (not a text file?)",
				   origin);
	else
		st = anvil_scene_parse(sc, buf, origin, err);
done:
	if (!is_stdin)
		fclose(f);
	free(buf);
	return st;
}

/* ---- one key ---- */

int anvil_scene_set(struct anvil_scene *sc, const char *key, const char *value,
		    const char *origin, int line, struct anvil_err *err)
{
	struct anvil_scene work = *sc;
	struct anvil_err in;
	char sec_name[LABEL_MAX], name[LABEL_MAX] = "";
	const char *field, *dot = strchr(key, '.');
	int sec = -1;
	if (!origin)
		origin = "command line";
	if (!dot) {
		anvil_scene_key_set(&work, -1, NULL, key, value, 0, &in);
		return located(err, ANVIL_EPARSE, origin, line, key, in.msg);
	}
	snprintf(sec_name, sizeof sec_name, "%.*s", (int)(dot - key), key);
	if ((sec = anvil_scene_section_find(sec_name, &in)) < 0)
		return located(err, ANVIL_EPARSE, origin, line, key, in.msg);
	field = dot + 1;
	if (sec == ANVIL_SEC_MATERIAL) {
		const char *last = strrchr(field, '.');
		if (!last)
			return located(err, ANVIL_EPARSE, origin, line, key,
				       "expected material.NAME.KEY (KEY: E, nu, rho or yield)");
		snprintf(name, sizeof name, "%.*s", (int)(last - field), field);
		field = last + 1;
	}
	int st = anvil_scene_key_set(&work, sec, name, field, value ? value : "", 0, &in);
	if (!st)
		st = anvil_scene_resolve(&work, &work.impactor, &in);
	if (!st)
		st = anvil_scene_resolve(&work, &work.layer, &in);
	if (st)
		return located(err, ANVIL_EPARSE, origin, line, key, in.msg);
	*sc = work;
	anvil_err_clear(err);
	return ANVIL_OK;
}

/* ---- the default scene ---- */

const char *anvil_scene_default_text(void) { return default_text; }

int anvil_scene_default(struct anvil_scene *sc)
{
	struct anvil_body *bodies[2] = {&sc->impactor, &sc->layer};
	memset(sc, 0, sizeof *sc);
	for (int b = 0; b < 2; ++b)
		bodies[b]->E = bodies[b]->nu = bodies[b]->rho = bodies[b]->yield = NAN;
	/* Not in default_text, so that scenes written before [effects] and
	 * [output] existed read as they did: every effect on, waves chosen by
	 * the planner (which only drops what the accuracy allows), the table. */
	sc->effects.waves = ANVIL_WAVES_AUTO;
	sc->effects.plate = sc->effects.quasistatic = 1;
	sc->effects.field = ANVIL_FIELDMODE_OFF;
	sc->output.table = 1;
	/* Fails only if default_text is broken, which test_scene catches; the
	 * core never aborts: the status goes back to the caller. */
	return anvil_scene_parse(sc, default_text, "default scene", NULL);
}

/* ---- validation ---- */

int anvil_scene_check(const struct anvil_scene *sc, struct anvil_err *err)
{
	static const struct {
		const char *label, *unit;
		size_t off;
	} positive[] = {
		{"impactor.mass", "kg", offsetof(struct anvil_scene, mass)},
		{"impactor.radius", "m", offsetof(struct anvil_scene, radius)},
		{"impact.velocity", "m/s", offsetof(struct anvil_scene, velocity)},
	};
	struct anvil_err in;
	for (size_t i = 0; i < sizeof positive / sizeof positive[0]; ++i) {
		double v = *(const double *)((const char *)sc + positive[i].off);
		if (!(isfinite(v) && v > 0))
			return anvil_err_set(err, ANVIL_EINVAL, "%s: must be > 0, got %g %s",
					     positive[i].label, v, positive[i].unit);
	}
	if (!(sc->thickness > 0) || (sc->thickness_per_r0 && isinf(sc->thickness)))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "layer.thickness: must be > 0 or inf, got %g %s",
				     sc->thickness, sc->thickness_per_r0 ? "r0" : "m");
	if (!(isfinite(sc->dt) && sc->dt >= 0))
		return anvil_err_set(err, ANVIL_EINVAL, "solver.dt: must be >= 0 (0 is auto), got %g s",
				     sc->dt);
	if ((unsigned)sc->accuracy >= ANVIL_ACC_COUNT)
		return anvil_err_set(err, ANVIL_EINVAL, "solver.accuracy: no level %d",
				     (int)sc->accuracy);
	if ((unsigned)sc->scheme > ANVIL_SCHEME_PAPER)
		return anvil_err_set(err, ANVIL_EINVAL, "solver.scheme: no scheme %d",
				     (int)sc->scheme);
	if (!sc->models || (sc->models & ~ANVIL_MODELS_ALL))
		return anvil_err_set(err, ANVIL_EINVAL, "solver.models: must name models "
				     "among hertz, zener, layer, halfspace (bits 0x%x)", sc->models);
	if ((unsigned)sc->effects.waves >= ANVIL_WAVES_COUNT ||
	    (unsigned)sc->effects.field >= ANVIL_FIELDMODE_COUNT)
		return anvil_err_set(err, ANVIL_EINVAL, "effects: waves %d or field %d out of range",
				     (int)sc->effects.waves, (int)sc->effects.field);
	if (sc->ncustom < 0 || sc->ncustom > ANVIL_MAX_CUSTOM)
		return anvil_err_set(err, ANVIL_EINVAL, "%d custom materials (at most %d)",
				     sc->ncustom, ANVIL_MAX_CUSTOM);
	for (int i = 0; i < sc->ncustom; ++i)
		if (anvil_scene_custom_check(&sc->custom[i], &in))
			return anvil_err_set(err, ANVIL_EINVAL, "material.%s: %s",
					     sc->custom[i].name, in.msg);
	if (anvil_material_check(&sc->impactor.mat, &in))
		return anvil_err_set(err, ANVIL_EINVAL, "impactor: %s", in.msg);
	if (anvil_material_check(&sc->layer.mat, &in))
		return anvil_err_set(err, ANVIL_EINVAL, "layer: %s", in.msg);
	anvil_err_clear(err);
	return ANVIL_OK;
}

double anvil_scene_h(const struct anvil_scene *sc)
{
	return sc->thickness_per_r0 ? sc->thickness * sc->radius : sc->thickness;
}

unsigned anvil_scene_models(const struct anvil_scene *sc)
{
	unsigned m = sc->models & ANVIL_MODELS_ALL;
	if (!sc->effects.quasistatic)
		m &= ~(1u << ANVIL_MODEL_HERTZ);
	if (!sc->effects.plate)
		m &= ~(1u << ANVIL_MODEL_ZENER);
	if (sc->effects.waves == ANVIL_WAVES_NONE)
		m &= ~((1u << ANVIL_MODEL_LAYER) | (1u << ANVIL_MODEL_HALFSPACE));
	return m;
}

/* ---- writing ---- */

int anvil_scene_write(const struct anvil_scene *sc, FILE *out)
{
	fprintf(out, "# anvil scene: SI values, printed to read back exactly\n");
	for (int sec = 0; sec < ANVIL_SEC_MATERIAL; ++sec) {
		fprintf(out, "%s[%s]\n", sec ? "\n" : "", anvil_scene_section_name(sec));
		anvil_scene_keys_write(sc, sec, 0, out);
	}
	for (int i = 0; i < sc->ncustom && i < ANVIL_MAX_CUSTOM; ++i) {
		fprintf(out, "\n[material %s]\n", sc->custom[i].name);
		anvil_scene_keys_write(sc, ANVIL_SEC_MATERIAL, i, out);
	}
	if (fflush(out) != 0 || ferror(out))
		return ANVIL_EIO;
	return ANVIL_OK;
}
