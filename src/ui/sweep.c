/* sweep.c: axes, scenes and the text of rows (sweep.h); the threads are
 * in sweep_run.c. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sweep.h"

/* ---- axes ---- */

static char *trim(char *s)
{
	while (isspace((unsigned char)*s))
		s++;
	size_t n = strlen(s);
	while (n && isspace((unsigned char)s[n - 1]))
		s[--n] = '\0';
	return s;
}

/* "NUMBER[UNIT]": 1 with *x and the unit (trimmed) in unit; "inf" is a
 * number without a unit; 0 for text (a material). */
static int split_number(const char *s, double *x, char *unit, size_t n)
{
	char *end;
	unit[0] = '\0';
	if (!strcmp(s, "inf")) {
		*x = INFINITY;
		return 1;
	}
	if (!(isdigit((unsigned char)s[0]) || s[0] == '.' || s[0] == '+' || s[0] == '-'))
		return 0;
	*x = strtod(s, &end);
	if (end == s)
		return 0;
	while (isspace((unsigned char)*end))
		end++;
	snprintf(unit, n, "%s", end);
	return 1;
}

static int axis_push(struct sweep_axis *a, const char *v)
{
	if (a->n >= SWEEP_MAXVAL)
		return ANVIL_EPARSE;
	char **nv = realloc(a->val, (size_t)(a->n + 1) * sizeof *nv);
	if (!nv)
		return ANVIL_ENOMEM;
	a->val = nv;
	if (!(a->val[a->n] = strdup(v)))
		return ANVIL_ENOMEM;
	a->n++;
	return ANVIL_OK;
}

/* "A..B:N[:lin|log]" into values "%.17gUNIT". */
static int axis_range(struct sweep_axis *a, const char *arg, char *spec, struct anvil_err *err)
{
	char *dots = strstr(spec, ".."), *colon, *space, ua[16], ub[16];
	double x0, x1;
	*dots = '\0';
	char *b = dots + 2;
	if (!(colon = strchr(b, ':')))
		return anvil_err_set(err, ANVIL_EPARSE, "%s: a range needs a count, e.g. 0.1..10m/s:25:log",
				     arg);
	*colon = '\0';
	char *count = colon + 1, *end;
	space = strchr(count, ':');
	if (space)
		*space++ = '\0';
	if (!split_number(trim(spec), &x0, ua, sizeof ua) || !split_number(trim(b), &x1, ub, sizeof ub) ||
	    !isfinite(x0) || !isfinite(x1))
		return anvil_err_set(err, ANVIL_EPARSE, "%s: a range is NUMBER..NUMBER[UNIT], e.g. 1..20mm:8",
				     arg);
	if (ua[0] && strcmp(ua, ub))
		return anvil_err_set(err, ANVIL_EPARSE, "%s: unit mismatch: '%s' and '%s': give both ends in one unit",
				     arg, ua, ub);
	long n = strtol(count, &end, 10);
	if (end == count || *end || n < 2 || n > SWEEP_MAXVAL)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: a range needs a count from 2 to %d, not '%s'", arg,
				     SWEEP_MAXVAL, count);
	int log_spacing = space && !strcmp(space, "log");
	if (space && !log_spacing && strcmp(space, "lin"))
		return anvil_err_set(err, ANVIL_EPARSE, "%s: spacing '%s': lin or log", arg, space);
	if (log_spacing && (x0 <= 0 || x1 <= 0))
		return anvil_err_set(err, ANVIL_EPARSE, "%s: a log range needs ends above 0", arg);
	for (long i = 0; i < n; i++) {
		double f = (double)i / (double)(n - 1), x;
		/* the ends exactly as written */
		x = i == 0 ? x0 : i == n - 1 ? x1 : log_spacing ? x0 * pow(x1 / x0, f) : x0 + (x1 - x0) * f;
		char v[64];
		snprintf(v, sizeof v, "%.17g%s", x, ub);
		int st = axis_push(a, v);
		if (st)
			return anvil_err_set(err, st, "%s: out of memory", arg);
	}
	return ANVIL_OK;
}

static int axis_list(struct sweep_axis *a, const char *arg, char *spec, struct anvil_err *err)
{
	char *p = spec;
	for (;;) {
		char *comma = strchr(p, ','), *v;
		if (comma)
			*comma = '\0';
		v = trim(p);
		if (!*v)
			return anvil_err_set(err, ANVIL_EPARSE, "%s: an empty value (a stray comma?)", arg);
		int st = axis_push(a, v);
		if (st == ANVIL_EPARSE)
			return anvil_err_set(err, st, "%s: more than %d values", arg, SWEEP_MAXVAL);
		if (st)
			return anvil_err_set(err, st, "out of memory");
		if (!comma)
			return ANVIL_OK;
		p = comma + 1;
	}
}

/* Numeric with one unit, or text; every value must set on the base. */
static int axis_check(struct sweep_axis *a, const struct anvil_scene *base, const char *arg,
		      struct anvil_err *err)
{
	int nnum = 0;
	if (!(a->num = malloc((size_t)a->n * sizeof *a->num)))
		return anvil_err_set(err, ANVIL_ENOMEM, "out of memory");
	/* "5,10,20m/s": the last value's unit, written once as in a range,
	 * holds for the bare numbers before it */
	char last[64];
	double x;
	if (split_number(a->val[a->n - 1], &x, last, sizeof last) && last[0])
		for (int i = 0; i < a->n - 1; i++) {
			char unit[64], *v;
			if (!split_number(a->val[i], &x, unit, sizeof unit) || unit[0] || isinf(x))
				continue;
			size_t n = strlen(a->val[i]) + strlen(last) + 1;
			if (!(v = malloc(n)))
				return anvil_err_set(err, ANVIL_ENOMEM, "out of memory");
			snprintf(v, n, "%s%s", a->val[i], last);
			free(a->val[i]);
			a->val[i] = v;
		}
	for (int i = 0; i < a->n; i++) {
		char unit[64];
		if (!split_number(a->val[i], &a->num[i], unit, sizeof unit))
			continue;
		nnum++;
		if (!unit[0] && isinf(a->num[i]))
			continue; /* "inf" fits any unit */
		if (!a->unit[0] && strlen(unit) < sizeof a->unit)
			snprintf(a->unit, sizeof a->unit, "%s", unit);
		else if (strcmp(unit, a->unit))
			return anvil_err_set(err, ANVIL_EPARSE,
					     "%s: unit mismatch: '%s' and '%s': give every value of an axis in one unit",
					     arg, a->unit, unit);
	}
	a->numeric = nnum == a->n;
	for (int i = 0; i < a->n; i++) {
		struct anvil_scene sc = *base;
		struct anvil_err e = {0};
		if (anvil_scene_set(&sc, a->key, a->val[i], "command line", 0, &e))
			/* "1:1e6:1" (MATLAB's, Python's slices): a range meant */
			return anvil_err_set(err, ANVIL_EPARSE, "%s: %s%s", arg, e.msg,
					     strchr(a->val[i], ':') ? "; a range is A..B[UNIT]:COUNT[:lin|log], e.g. 1..10m/s:10" : "");
	}
	return ANVIL_OK;
}

int sweep_axis_add(struct sweep *sw, const char *arg, struct anvil_err *err)
{
	const char *eq = strchr(arg, '=');
	if (!eq || eq == arg || (size_t)(eq - arg) >= sizeof sw->ax[0].key)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: expected KEY=SPEC, e.g. impact.velocity=1..10m/s:10",
				     arg);
	if (sw->naxis == SWEEP_MAXAXIS)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: at most %d axes", arg, SWEEP_MAXAXIS);
	struct sweep_axis *a = &sw->ax[sw->naxis];
	memset(a, 0, sizeof *a);
	memcpy(a->key, arg, (size_t)(eq - arg));
	for (int i = 0; i < sw->naxis; i++)
		if (!strcmp(sw->ax[i].key, a->key))
			return anvil_err_set(err, ANVIL_EPARSE, "%s: %s is swept twice", arg, a->key);
	sw->naxis++; /* freed by sweep_free whatever happens next */
	char *spec = strdup(eq + 1);
	if (!spec)
		return anvil_err_set(err, ANVIL_ENOMEM, "out of memory");
	int st = strstr(spec, "..") ? axis_range(a, arg, spec, err) : axis_list(a, arg, spec, err);
	free(spec);
	return st ? st : axis_check(a, &sw->base, arg, err);
}

void sweep_free(struct sweep *sw)
{
	for (int i = 0; i < sw->naxis; i++) {
		for (int j = 0; j < sw->ax[i].n; j++)
			free(sw->ax[i].val[j]);
		free(sw->ax[i].val);
		free(sw->ax[i].num);
	}
	free(sw->row0);
	sw->naxis = 0;
	sw->row0 = NULL;
}

/* ---- scenes ---- */

/* The value of each axis in scene s. */
static void scene_index(const struct sweep *sw, size_t s, int *idx)
{
	for (int a = sw->naxis - 1; a >= 0; a--) {
		if (sw->zip) {
			idx[a] = (int)s;
		} else {
			idx[a] = (int)(s % (size_t)sw->ax[a].n);
			s /= (size_t)sw->ax[a].n;
		}
	}
}

int sweep_scene(const struct sweep *sw, size_t s, struct anvil_scene *sc, struct anvil_err *err)
{
	int idx[SWEEP_MAXAXIS];
	*sc = sw->base;
	scene_index(sw, s, idx);
	for (int a = 0; a < sw->naxis; a++) {
		int st = anvil_scene_set(sc, sw->ax[a].key, sw->ax[a].val[idx[a]], "command line", 0, err);
		if (st)
			return st;
	}
	/* contact = auto shows both models on the paper's own case (anvil
	 * run); a table keeps one contact model for every scene: the
	 * physical one, unless both or paper is asked for */
	if (sc->effects.contact == ANVIL_CONTACT_AUTO)
		sc->effects.contact = ANVIL_CONTACT_PHYSICAL;
	return anvil_scene_check(sc, err);
}

/* [effects] contact as the problem resolves it (problem.c; a sweep's
 * scenes have no auto left, sweep_scene); the paper's scheme is the
 * paper's contact alone. */
static enum anvil_contact scene_contact(const struct anvil_scene *sc)
{
	enum anvil_contact c = sc->effects.contact;
	if (sc->scheme == ANVIL_SCHEME_PAPER)
		return ANVIL_CONTACT_PAPER;
	if (c == ANVIL_CONTACT_AUTO)
		c = anvil_scene_is_paper_case(sc) ? ANVIL_CONTACT_BOTH : ANVIL_CONTACT_PHYSICAL;
	return c;
}

int sweep_scene_rows(const struct anvil_scene *sc, struct sweep_rowkey *k)
{
	unsigned m = anvil_scene_models(sc);
	enum anvil_contact c = scene_contact(sc);
	int n = 0;
	for (int i = 0; i < ANVIL_MODEL_COUNT; i++) {
		if (!((m >> i) & 1u))
			continue;
		int wave = i == ANVIL_MODEL_LAYER || i == ANVIL_MODEL_HALFSPACE;
		if (wave && c == ANVIL_CONTACT_BOTH)
			k[n++] = (struct sweep_rowkey){(enum anvil_model)i, ANVIL_CONTACT_PAPER};
		k[n++] = (struct sweep_rowkey){(enum anvil_model)i,
					       !wave ? ANVIL_CONTACT_AUTO
					       : c == ANVIL_CONTACT_PAPER ? ANVIL_CONTACT_PAPER
									  : ANVIL_CONTACT_PHYSICAL};
	}
	if (!n)
		k[n++] = (struct sweep_rowkey){ANVIL_MODEL_COUNT, ANVIL_CONTACT_AUTO};
	return n;
}

int sweep_layout(struct sweep *sw, struct anvil_err *err)
{
	size_t n = 1;
	for (int a = 0; a < sw->naxis; a++) {
		if (sw->zip && sw->ax[a].n != sw->ax[0].n)
			return anvil_err_set(err, ANVIL_EPARSE, "--zip: %s has %d values but %s has %d: pair lists of one length",
					     sw->ax[a].key, sw->ax[a].n, sw->ax[0].key, sw->ax[0].n);
		n = sw->zip ? (size_t)sw->ax[0].n : n * (size_t)sw->ax[a].n;
		if (n > SWEEP_MAXVAL)
			return anvil_err_set(err, ANVIL_EPARSE, "%zu scenes or more: at most %d in one sweep "
					     "(split it with --shard or into several sweeps)", n, SWEEP_MAXVAL);
	}
	sw->nscenes = n;
	if (!(sw->row0 = malloc((n + 1) * sizeof *sw->row0)))
		return anvil_err_set(err, ANVIL_ENOMEM, "out of memory");
	sw->row0[0] = 0;
	for (size_t s = 0; s < n; s++) {
		struct anvil_scene sc;
		struct sweep_rowkey k[SWEEP_MAXROWS];
		sweep_scene(sw, s, &sc, NULL); /* a failing scene still has models */
		sw->row0[s + 1] = sw->row0[s] + (size_t)sweep_scene_rows(&sc, k);
	}
	sw->nrows = sw->row0[n];
	return ANVIL_OK;
}

void sweep_shard(const struct sweep *sw, int k, int n, size_t *s0, size_t *s1)
{
	*s0 = (size_t)(k - 1) * sw->nscenes / (size_t)n;
	*s1 = (size_t)k * sw->nscenes / (size_t)n;
}

/* ---- rows ---- */

/* A row being written: cells joined as the format says. */
struct line {
	FILE *f;
	char *buf;
	size_t len;
	enum out_format fmt;
	int ncell;
};

static int line_open(struct line *l, enum out_format fmt)
{
	memset(l, 0, sizeof *l);
	l->fmt = fmt == OUT_TABLE ? OUT_TSV : fmt;
	if (!(l->f = open_memstream(&l->buf, &l->len)))
		return -1;
	if (l->fmt == OUT_JSON)
		fputc('{', l->f);
	return 0;
}

static char *line_close(struct line *l, int finished)
{
	if (finished && l->fmt == OUT_JSON)
		fputc('}', l->f);
	if (fclose(l->f) != 0) {
		free(l->buf);
		return NULL;
	}
	return l->buf;
}

static void put_sep(struct line *l)
{
	if (l->ncell++)
		fputs(l->fmt == OUT_TSV ? "\t" : l->fmt == OUT_CSV ? "," : ", ", l->f);
}

static void put_text(struct line *l, const char *s)
{
	if (l->fmt == OUT_JSON) {
		out_json_string(l->f, s);
	} else if (l->fmt == OUT_CSV && strpbrk(s, ",\"")) {
		/* one row a line: a newline in a message becomes a space */
		fputc('"', l->f);
		for (; *s; s++) {
			if (*s == '"')
				fputc('"', l->f);
			fputc(*s == '\n' || *s == '\r' ? ' ' : *s, l->f);
		}
		fputc('"', l->f);
	} else {
		for (; *s; s++)
			fputc(*s == '\t' || *s == '\n' || *s == '\r' ? ' ' : *s, l->f);
	}
}

/* A cell: JSON writes "name": value. */
static void cell_text(struct line *l, const char *name, const char *s)
{
	put_sep(l);
	if (l->fmt == OUT_JSON) {
		out_json_string(l->f, name);
		fputs(": ", l->f);
	}
	put_text(l, s);
}

static void cell_num(struct line *l, const char *name, double x)
{
	char buf[40];
	put_sep(l);
	if (l->fmt == OUT_JSON) {
		out_json_string(l->f, name);
		fputs(": ", l->f);
		if (!isfinite(x)) {
			fputs("null", l->f);
			return;
		}
	}
	fputs(out_num(buf, x, NULL), l->f);
}

static void cell_size(struct line *l, const char *name, size_t x)
{
	put_sep(l);
	if (l->fmt == OUT_JSON)
		fprintf(l->f, "\"%s\": ", name);
	fprintf(l->f, "%zu", x);
}

/* "impact.velocity_m_s": the key and the user's unit, '/' as '_'. */
static void axis_name(const struct sweep_axis *a, char *buf, size_t n)
{
	snprintf(buf, n, "%s%s%s", a->key, a->numeric && a->unit[0] ? "_" : "", a->numeric ? a->unit : "");
	for (char *p = buf; *p; p++)
		if (*p == '/')
			*p = '_';
}

static const char *const scene_cols[] = {"impactor", "layer", "mass_kg", "r0_m", "h_m", "h_r0", "V0_m_s",
					 "model", "contact"};

/* The outputs: name, field, scale from SI, error name. */
struct out_col {
	const char *name, *err;
	size_t off;
	double scale;
};
#define OFF(f) offsetof(struct anvil_result, f)
static const struct out_col out_cols[] = {
	{"ts_us", "ts_err_us", OFF(ts), 1e6},        {"tmax_us", "tmax_err_us", OFF(tmax), 1e6},
	{"Pmax_kN", "Pmax_err_kN", OFF(Pmax), 1e-3}, {"Vs_m_s", "Vs_err_m_s", OFF(Vs), 1},
	{"Rf", "Rf_err", OFF(Rf), 1},                {"Ea_J", "Ea_err_J", OFF(Ea), 1},
};
#define NOUT ((int)(sizeof out_cols / sizeof out_cols[0]))

char *sweep_header(const struct sweep *sw, enum out_format fmt)
{
	struct line l;
	char name[96];
	if (fmt == OUT_JSON)
		return strdup("[");
	if (line_open(&l, fmt))
		return NULL;
	cell_text(&l, "", "row");
	cell_text(&l, "", "rows");
	for (int a = 0; a < sw->naxis; a++) {
		axis_name(&sw->ax[a], name, sizeof name);
		cell_text(&l, "", name);
	}
	for (size_t i = 0; i < sizeof scene_cols / sizeof scene_cols[0]; i++)
		cell_text(&l, "", scene_cols[i]);
	cell_text(&l, "", "status");
	cell_text(&l, "", "message");
	for (int i = 0; i < NOUT; i++) {
		cell_text(&l, "", out_cols[i].name);
		cell_text(&l, "", out_cols[i].err);
	}
	cell_text(&l, "", "rest_Rf_max");
	return line_close(&l, 1);
}

/* The scene of row: which scene (binary search on row0). */
static size_t row_scene(const struct sweep *sw, size_t row)
{
	size_t lo = 0, hi = sw->nscenes;
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;
		if (sw->row0[mid] <= row)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

static void row_id(struct line *l, const struct sweep *sw, size_t row, const struct anvil_scene *sc,
		   const struct sweep_rowkey *k)
{
	int idx[SWEEP_MAXAXIS];
	char name[96];
	scene_index(sw, row_scene(sw, row), idx);
	cell_size(l, "row", row + 1);
	cell_size(l, "rows", sw->nrows);
	for (int a = 0; a < sw->naxis; a++) {
		const struct sweep_axis *ax = &sw->ax[a];
		axis_name(ax, name, sizeof name);
		if (ax->numeric)
			cell_num(l, name, ax->num[idx[a]]);
		else
			cell_text(l, name, ax->val[idx[a]]);
	}
	double h = anvil_scene_h(sc);
	cell_text(l, "impactor", sc->impactor.material);
	cell_text(l, "layer", sc->layer.material);
	cell_num(l, "mass_kg", sc->mass);
	cell_num(l, "r0_m", sc->radius);
	cell_num(l, "h_m", h);
	cell_num(l, "h_r0", h / sc->radius);
	cell_num(l, "V0_m_s", sc->velocity);
	cell_text(l, "model", k->model < ANVIL_MODEL_COUNT ? anvil_model_name(k->model) : "none");
	cell_text(l, "contact", k->contact == ANVIL_CONTACT_AUTO ? "-" : anvil_contact_name(k->contact));
}

char *sweep_row_id(const struct sweep *sw, enum out_format fmt, size_t row,
		   const struct anvil_scene *sc, const struct sweep_rowkey *k)
{
	struct line l;
	if (line_open(&l, fmt))
		return NULL;
	row_id(&l, sw, row, sc, k);
	return line_close(&l, 0);
}

char *sweep_row(const struct sweep *sw, enum out_format fmt, size_t row, const struct anvil_scene *sc,
		const struct sweep_rowkey *k, const struct anvil_result *res, int st, const char *why)
{
	struct line l;
	char stbuf[16];
	if (line_open(&l, fmt))
		return NULL;
	row_id(&l, sw, row, sc, k);
	if (res) {
		st = res->status;
		why = res->why;
	}
	snprintf(stbuf, sizeof stbuf, "%d", st);
	put_sep(&l);
	if (l.fmt == OUT_JSON)
		fputs("\"status\": ", l.f);
	fputs(stbuf, l.f);
	cell_text(&l, "message", why ? why : "");
	for (int i = 0; i < NOUT; i++) {
		double v = NAN, e = NAN;
		if (res && res->status >= 0) {
			const struct anvil_val *x = (const void *)((const char *)res + out_cols[i].off);
			v = out_cols[i].scale * x->val;
			e = out_cols[i].scale * x->err;
			/* below the rounding of doubles: 0 (output.h) */
			if (fabs(e) < OUT_ERR_NOISE * fabs(v))
				e = 0;
		}
		cell_num(&l, out_cols[i].name, v);
		cell_num(&l, out_cols[i].err, e);
	}
	/* the bound on R_f where the impactor came to rest on the plate (the
	 * contact does not end: its t_s is when the bound was reached), as
	 * anvil run's column; NaN where the contact ended */
	cell_num(&l, "rest_Rf_max", res && res->status >= 0 && res->rest_bound > 0 ? res->rest_bound : NAN);
	return line_close(&l, 1);
}

/* ---- files read back ---- */

static int file_slurp(const char *path, char **buf, size_t *len, struct anvil_err *err)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return anvil_err_set(err, errno == ENOENT ? ANVIL_ENOTFOUND : ANVIL_EIO, "%s: %s", path,
				     strerror(errno));
	FILE *m = open_memstream(buf, len);
	char chunk[65536];
	size_t n;
	int bad = !m;
	while (!bad && (n = fread(chunk, 1, sizeof chunk, f)) > 0)
		bad = fwrite(chunk, 1, n, m) != n;
	bad |= ferror(f);
	fclose(f);
	if (m && fclose(m) != 0)
		bad = 1;
	if (bad) {
		if (m)
			free(*buf);
		*buf = NULL;
		return anvil_err_set(err, ANVIL_EIO, "%s: cannot read", path);
	}
	if (memchr(*buf, '\0', *len)) {
		free(*buf);
		*buf = NULL;
		return anvil_err_set(err, ANVIL_EPARSE, "%s: a NUL byte: not a sweep's output", path);
	}
	return ANVIL_OK;
}

int sweep_file_read(const char *path, enum out_format fmt, struct sweep_file *f, struct anvil_err *err)
{
	size_t len = 0, cap = 0;
	memset(f, 0, sizeof *f);
	int st = file_slurp(path, &f->buf, &len, err);
	if (st)
		return st;
	char *p = f->buf, *end = f->buf + len;
	int json = fmt == OUT_JSON, lineno = 0, closed = 0;
	while (p < end) {
		char *nl = memchr(p, '\n', (size_t)(end - p));
		lineno++;
		if (!nl) {
			f->partial = 1; /* cut short: not a row */
			break;
		}
		*nl = '\0';
		char *line = p;
		p = nl + 1;
		if (lineno == 1) {
			if (json && strcmp(line, "["))
				return anvil_err_set(err, ANVIL_EPARSE, "%s:1: expected '[' (a sweep's JSON output)", path);
			if (!json)
				f->header = line;
			continue;
		}
		if (closed)
			return anvil_err_set(err, ANVIL_EPARSE, "%s:%d: text after the closing ']'", path, lineno);
		if (json && !strcmp(line, "]")) {
			closed = 1;
			continue;
		}
		size_t n = strlen(line);
		if (json && n && line[n - 1] == ',')
			line[n - 1] = '\0';
		if (!*line)
			continue;
		if (f->nrow == cap) {
			cap = cap ? 2 * cap : 256;
			char **r = realloc(f->row, cap * sizeof *r);
			if (!r)
				return anvil_err_set(err, ANVIL_ENOMEM, "out of memory");
			f->row = r;
		}
		f->row[f->nrow++] = line;
	}
	if (!json && !f->header)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: empty: no header", path);
	return ANVIL_OK;
}

void sweep_file_free(struct sweep_file *f)
{
	free(f->buf);
	free(f->row);
	memset(f, 0, sizeof *f);
}

int sweep_file_rownum(const char *line, enum out_format fmt, size_t *row, size_t *rows)
{
	unsigned long long a, b;
	int n = 0;
	if (fmt == OUT_JSON)
		n = sscanf(line, "{\"row\": %llu, \"rows\": %llu", &a, &b);
	else if (fmt == OUT_CSV)
		n = sscanf(line, "%llu,%llu", &a, &b);
	else
		n = sscanf(line, "%llu\t%llu", &a, &b);
	if (n != 2 || a < 1 || a > b)
		return 0;
	*row = (size_t)a;
	*rows = (size_t)b;
	return 1;
}
