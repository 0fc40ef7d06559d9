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
#include "units.h"

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

#define LINE_MAX_CHARS (ANVIL_SCENE_LINE_MAX + 1)
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
	int nkeys;                  /* KEY = VALUE lines read */
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
 * elsewhere ("title = Run#3") it is text, as it is inside a value in double
 * quotes (title = "#3", with \" and \\ escapes): a quote opens one only as
 * the first character after '='. */
static void strip_comment(char *s)
{
	char *eq = strchr(s, '=');
	for (char *p = s; *p; ++p) {
		if ((*p == '#' || *p == ';') && (p == s || isspace((unsigned char)p[-1]))) {
			*p = '\0';
			return;
		}
		if (p == eq) {
			while (isspace((unsigned char)p[1]))
				++p;
			if (p[1] != '"')
				continue;
			for (p += 2; *p && *p != '"'; ++p)
				if (*p == '\\' && (p[1] == '"' || p[1] == '\\'))
					++p;
			if (!*p)
				return; /* unterminated: anvil_scene_key_set says so */
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
	if (anvil_scene_key_set(p->sc, p->sec, p->name, key, value, 1, p->line, &in))
		return perr(p, err, label, "%s", in.msg);
	p->nkeys++;
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

/* The line label was set on in this text, 0 if it was not. */
static int seen_line(const struct parser *p, const char *label)
{
	for (int i = 0; i < p->nseen; ++i)
		if (strcasecmp(p->seen[i].label, label) == 0)
			return p->seen[i].line;
	return 0;
}

/* Keys of one text that say the same thing twice (scene.h), named at the
 * later one. */
static int parse_conflicts(struct parser *p, struct anvil_err *err)
{
	static const struct {
		const char *a, *b, *why;
	} pairs[] = {
		{"impact.velocity", "impact.drop_height", "give one of velocity and drop_height"},
		{"impactor.mass", "impactor.length",
		 "give the mass or the length (the mass then follows from rho), not both"},
	};
	const struct anvil_scene *sc = p->sc;
	for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; ++i) {
		int la = seen_line(p, pairs[i].a), lb = seen_line(p, pairs[i].b);
		if (la && lb) {
			p->line = la > lb ? la : lb;
			return perr(p, err, la > lb ? pairs[i].a : pairs[i].b,
				    "%s is set too (line %d): %s", la > lb ? pairs[i].b : pairs[i].a,
				    la > lb ? lb : la, pairs[i].why);
		}
	}
	int lr = seen_line(p, "impactor.radius"), ld = seen_line(p, "impactor.diameter");
	if (lr && ld && !(fabs(sc->diameter - 2.0 * sc->radius) <= 1e-12 * sc->diameter)) {
		p->line = ld;
		return perr(p, err, "impactor.diameter",
			    "%g m is not twice radius = %g m (line %d): give one of them",
			    sc->diameter, sc->radius, lr);
	}
	int ll = seen_line(p, "impactor.length");
	if (ll && sc->shape == ANVIL_SHAPE_BALL) {
		p->line = ll;
		return perr(p, err, "impactor.length",
			    "a ball has no length (shape = ball): give its diameter");
	}
	return ANVIL_OK;
}

/* What could not be checked line by line: materials used before their
 * [material NAME] section, whether each defined material is complete, the
 * geometry keys together. */
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
	if (seen_line(p, "impactor.mass"))
		sc->mass_given = 1; /* whatever came after it in the text */
	int st = parse_conflicts(p, err);
	if (!st && anvil_scene_geometry(sc, &in))
		st = located(err, ANVIL_EPARSE, p->origin, seen_line(p, "impactor.length"), NULL,
			     in.msg);
	return st;
}

/* Lines end in LF, CRLF or a lone CR (old Mac files: otherwise the whole
 * file would be one line, and a comment).  A UTF-8 byte order mark, which
 * some Windows editors write, is skipped. */
static int parse_text(struct parser *p, const char *text, struct anvil_err *err)
{
	char buf[LINE_MAX_CHARS];
	int st;
	if (strncmp(text, "\xef\xbb\xbf", 3) == 0)
		text += 3;
	while (*text) {
		size_t n = strcspn(text, "\r\n");
		++p->line;
		if (n >= sizeof buf)
			return perr(p, err, NULL, "line longer than %d characters",
				    (int)sizeof buf - 1);
		memcpy(buf, text, n);
		buf[n] = '\0';
		if ((st = parse_line(p, buf, err)))
			return st;
		text += n;
		if (text[0] == '\r')
			text += 1 + (text[1] == '\n');
		else if (text[0] == '\n')
			++text;
	}
	return parse_finish(p, err);
}

static void title_update(struct anvil_scene *sc)
{
	if (!sc->title_set)
		anvil_scene_title(sc, sc->title, sizeof sc->title);
}

/* Parse text into sc; when need_keys, text without one KEY = VALUE is an
 * error (a file, anvil_scene_load). */
static int parse_impl(struct anvil_scene *sc, const char *text, const char *origin,
		      int need_keys, struct anvil_err *err)
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
	if (st == ANVIL_OK && need_keys && p->nkeys == 0)
		st = anvil_err_set(err, ANVIL_EPARSE,
				   "%s: no KEY = VALUE in the scene (empty, or only comments); "
				   "refusing to run the default scene in its place", p->origin);
	free(p);
	if (st == ANVIL_OK) {
		title_update(&work);
		*sc = work;
		anvil_err_clear(err);
	}
	return st;
}

int anvil_scene_parse(struct anvil_scene *sc, const char *text, const char *origin,
		      struct anvil_err *err)
{
	return parse_impl(sc, text, origin, 0, err);
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
		if (len > ANVIL_SCENE_MAX_BYTES) {
			st = anvil_err_set(err, ANVIL_EPARSE,
					   "%s: larger than %d bytes (1 MiB): not a scene file?",
					   origin, ANVIL_SCENE_MAX_BYTES);
			goto done;
		}
		if (cap - len < 2) {
			cap = cap ? 2 * cap : 4096;
			if (!(more = realloc(buf, cap))) {
				st = anvil_err_set(err, ANVIL_ENOMEM, "%s: out of memory", origin);
				goto done;
			}
			buf = more;
		}
		/* at most one byte past the limit, to see that it is passed */
		size_t want = cap - len - 1;
		if (want > ANVIL_SCENE_MAX_BYTES + 1 - len)
			want = ANVIL_SCENE_MAX_BYTES + 1 - len;
		size_t got = fread(buf + len, 1, want, f);
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
		st = parse_impl(sc, buf, origin, 1, err);
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
		anvil_scene_key_set(&work, -1, NULL, key, value, 0, -1, &in);
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
				       "expected material.NAME.KEY (KEY: E, nu, rho, yield, tensile "
				       "or brittle)");
		snprintf(name, sizeof name, "%.*s", (int)(last - field), field);
		field = last + 1;
	}
	int st = anvil_scene_key_set(&work, sec, name, field, value ? value : "", 0,
				     line > 0 ? line : -1, &in);
	if (!st)
		st = anvil_scene_resolve(&work, &work.impactor, &in);
	if (!st)
		st = anvil_scene_resolve(&work, &work.layer, &in);
	if (!st)
		st = anvil_scene_geometry(&work, &in);
	if (st)
		return located(err, ANVIL_EPARSE, origin, line, key, in.msg);
	title_update(&work);
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
		bodies[b]->E = bodies[b]->nu = bodies[b]->rho = bodies[b]->yield =
			bodies[b]->tensile = bodies[b]->brittle = NAN;
	sc->shape = ANVIL_SHAPE_ROD;
	sc->diameter = sc->length = sc->drop_height = NAN;
	/* Not in default_text, so that scenes written before [effects] and
	 * [output] existed read as they did: every effect on, waves chosen by
	 * the planner (which only drops what the accuracy allows), the table. */
	sc->effects.waves = ANVIL_WAVES_AUTO;
	sc->effects.plate = sc->effects.quasistatic = 1;
	sc->effects.field = ANVIL_FIELDMODE_OFF;
	sc->output.table = 1;
	/* Fails only if default_text is broken, which test_scene catches; the
	 * core never aborts: the status goes back to the caller. */
	int st = anvil_scene_parse(sc, default_text, "default scene", NULL);
	/* The default's title is the default's only while it is the default. */
	sc->title_set = 0;
	sc->mass_given = 0; /* the default's mass, not the user's */
	memset(sc->key_line, 0, sizeof sc->key_line);
	return st;
}

/* ---- validation ---- */

int anvil_scene_check(const struct anvil_scene *sc, struct anvil_err *err)
{
	static const struct {
		const char *label, *unit;
		size_t off;
		double lo, hi;
	} ranged[] = {
		{"impactor.mass", "kg", offsetof(struct anvil_scene, mass), ANVIL_RANGE_MASS},
		{"impactor.radius", "m", offsetof(struct anvil_scene, radius), ANVIL_RANGE_LENGTH},
		{"impact.velocity", "m/s", offsetof(struct anvil_scene, velocity),
		 ANVIL_RANGE_VELOCITY},
	};
	struct anvil_err in;
	char text[64];
	for (size_t i = 0; i < sizeof ranged / sizeof ranged[0]; ++i) {
		double v = *(const double *)((const char *)sc + ranged[i].off);
		snprintf(text, sizeof text, "%g %s", v, ranged[i].unit);
		if (anvil_scene_range_check(v, ranged[i].lo, ranged[i].hi, ranged[i].unit, text, &in))
			return anvil_err_set(err, ANVIL_EINVAL, "%s: %s", ranged[i].label, in.msg);
	}
	double h = anvil_scene_h(sc);
	snprintf(text, sizeof text, "h = %g m", h);
	if (!(sc->thickness > 0) || (sc->thickness_per_r0 && isinf(sc->thickness)) ||
	    (!isinf(h) && anvil_scene_range_check(h, ANVIL_RANGE_LENGTH, "m", text, &in)))
		return anvil_err_set(err, ANVIL_EINVAL,
				     "layer.thickness: must give h within %g .. %g m or inf, "
				     "got %g %s", ANVIL_RANGE_LENGTH, sc->thickness,
				     sc->thickness_per_r0 ? "r0" : "m");
	snprintf(text, sizeof text, "%g s", sc->dt);
	if (sc->dt != 0 && anvil_scene_range_check(sc->dt, ANVIL_RANGE_DT, "s", text, &in))
		return anvil_err_set(err, ANVIL_EINVAL, "solver.dt: %s (or 0, auto)", in.msg);
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

/* ---- plausibility ---- */

/* Bounds of what real materials and impacts have (scene.h lists them).
 * Solids: the softest rubbers and foams are near 1 MPa, diamond 1050-1200
 * GPa, so 2000 GPa leaves room; densities from aerogels (~10 kg/m^3) to
 * osmium (22590 kg/m^3).  5 km/s is beyond light-gas-gun hypervelocity
 * work, where the elastic model has long stopped holding. */
#define PLAUS_E 1e6, 2000e9
#define PLAUS_RHO 10.0, 30000.0
#define PLAUS_RADIUS 1e-6, 1.0
#define PLAUS_MASS 1e-9, 1000.0
#define PLAUS_THICKNESS 1e-6, 100.0
#define PLAUS_VELOCITY_MAX 5000.0

struct warn_list {
	const struct anvil_scene *sc;
	struct anvil_scene_warning *w;
	int max, n;
};

/* The line sec.key was set on (sc->key_line). */
static int key_line(const struct anvil_scene *sc, int sec, const char *key)
{
	int i = anvil_scene_key_index(sec, key);
	return i >= 0 ? sc->key_line[i] : 0;
}

static void warn_add(struct warn_list *l, int sec, const char *key, double v,
		     enum anvil_dim dim, double lo, double hi, const char *why)
{
	char val[40], lim[40];
	if (v >= lo && v <= hi)
		return;
	if (l->n < l->max) {
		struct anvil_scene_warning *w = &l->w[l->n];
		anvil_units_format(v, dim, val, sizeof val);
		anvil_units_format(v < lo ? lo : hi, dim, lim, sizeof lim);
		snprintf(w->key, sizeof w->key, "%s.%s", anvil_scene_section_name(sec), key);
		w->line = key_line(l->sc, sec, key);
		snprintf(w->msg, sizeof w->msg, "%s is %s %s (%s)", val,
			 v < lo ? "below" : "above", lim, why);
	}
	l->n++;
}

/* E and rho of a body: named after its override when one is set, else after
 * its material key (where the material was chosen). */
static void warn_body(struct warn_list *l, int sec, const struct anvil_body *b)
{
	warn_add(l, sec, isnan(b->E) ? "material" : "E", b->mat.E, ANVIL_DIM_PRESSURE, PLAUS_E,
		 "E of real solids is 1 MPa .. 2000 GPa");
	warn_add(l, sec, isnan(b->rho) ? "material" : "rho", b->mat.rho, ANVIL_DIM_DENSITY,
		 PLAUS_RHO, "solids are 10 .. 30000 kg/m^3");
}

int anvil_scene_warnings(const struct anvil_scene *sc, struct anvil_scene_warning *w, int max)
{
	struct warn_list l = {sc, w, max < 0 ? 0 : max, 0};
	double h = anvil_scene_h(sc);
	warn_add(&l, ANVIL_SEC_IMPACTOR, "mass", sc->mass, ANVIL_DIM_MASS, PLAUS_MASS,
		 "no impactor of 1 ug .. 1 t");
	warn_add(&l, ANVIL_SEC_IMPACTOR, "radius", sc->radius, ANVIL_DIM_LENGTH, PLAUS_RADIUS,
		 "no contact radius of 1 um .. 1 m");
	warn_body(&l, ANVIL_SEC_IMPACTOR, &sc->impactor);
	warn_body(&l, ANVIL_SEC_LAYER, &sc->layer);
	/* a ball heavier than a solid one of its diameter (1 kg as a 10 mm
	 * ball: 240 times solid copper) is no ball; lighter is a hollow one */
	double solid = anvil_ball_mass(sc->impactor.mat.rho, 2.0 * sc->radius);
	if (sc->shape == ANVIL_SHAPE_BALL && solid > 0)
		warn_add(&l, ANVIL_SEC_IMPACTOR, "mass", sc->mass, ANVIL_DIM_MASS, 0.0, 1.01 * solid,
			 "a solid ball of this diameter and material: a ball cannot be heavier");
	if (!isinf(h))
		warn_add(&l, ANVIL_SEC_LAYER, "thickness", h, ANVIL_DIM_LENGTH, PLAUS_THICKNESS,
			 "no layer of 1 um .. 100 m");
	warn_add(&l, ANVIL_SEC_IMPACT, isnan(sc->drop_height) ? "velocity" : "drop_height",
		 sc->velocity, ANVIL_DIM_VELOCITY, 0,
		 PLAUS_VELOCITY_MAX, "hypervelocity: the elastic model does not hold");
	return l.n;
}

/* ---- the title ---- */

static int same_double(double a, double b)
{
	return isnan(a) ? isnan(b) : memcmp(&a, &b, sizeof a) == 0;
}

static int same_body(const struct anvil_body *a, const struct anvil_body *b)
{
	return strcmp(a->material, b->material) == 0 && same_double(a->E, b->E) &&
	       same_double(a->nu, b->nu) && same_double(a->rho, b->rho) &&
	       same_double(a->yield, b->yield) && same_double(a->tensile, b->tensile) &&
	       same_double(a->brittle, b->brittle);
}

/* The default scene's physics (what the title describes; solver settings
 * and outputs are not in it). */
static int default_physics(const struct anvil_scene *sc)
{
	struct anvil_scene d;
	anvil_scene_default(&d);
	return sc->shape == d.shape && same_body(&sc->impactor, &d.impactor) &&
	       same_body(&sc->layer, &d.layer) &&
	       same_double(sc->mass, d.mass) && same_double(sc->radius, d.radius) &&
	       same_double(sc->thickness, d.thickness) &&
	       sc->thickness_per_r0 == d.thickness_per_r0 && same_double(sc->velocity, d.velocity);
}

int anvil_scene_is_paper_case(const struct anvil_scene *sc) { return default_physics(sc); }

void anvil_scene_title(const struct anvil_scene *sc, char *buf, size_t n)
{
	char mass[40], radius[40], v[40], h[48];
	if (n == 0)
		return;
	if (sc->title_set) {
		if (buf != sc->title)
			snprintf(buf, n, "%s", sc->title);
		return;
	}
	if (default_physics(sc)) {
		struct anvil_scene d;
		anvil_scene_default(&d);
		snprintf(buf, n, "%s", d.title);
		return;
	}
	int ball = sc->shape == ANVIL_SHAPE_BALL;
	anvil_units_format(sc->mass, ANVIL_DIM_MASS, mass, sizeof mass);
	anvil_units_format(ball ? 2 * sc->radius : sc->radius, ANVIL_DIM_LENGTH, radius,
			   sizeof radius);
	anvil_units_format(sc->velocity, ANVIL_DIM_VELOCITY, v, sizeof v);
	const char *what = ball ? "ball" : "impactor", *size = ball ? "D" : "r0";
	if (isinf(anvil_scene_h(sc))) {
		snprintf(buf, n, "%s %s %s, %s = %s, at %s on a %s half-space", mass,
			 sc->impactor.material, what, size, radius, v, sc->layer.material);
		return;
	}
	anvil_units_format(anvil_scene_h(sc), ANVIL_DIM_LENGTH, h, sizeof h);
	snprintf(buf, n, "%s %s %s, %s = %s, at %s on a %s %s layer", mass,
		 sc->impactor.material, what, size, radius, v, h, sc->layer.material);
}
