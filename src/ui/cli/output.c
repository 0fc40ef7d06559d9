#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "output.h"
#include "common.h"

static const char *const format_names[] = {"table", "tsv", "csv", "json"};
#define NFORMATS ((int)(sizeof format_names / sizeof format_names[0]))

int out_format_parse(const char *cmd, const char *name, unsigned allowed)
{
	char list[64] = "";
	for (int i = 0; i < NFORMATS; i++) {
		if (!(allowed & OUT_ALLOW(i)))
			continue;
		if (strcmp(name, format_names[i]) == 0)
			return i;
		if (list[0])
			strcat(list, ", ");
		strcat(list, format_names[i]);
	}
	out_usage(cmd, "--format: unknown format '%s'; one of: %s", name, list);
	return -1;
}

int out_format_of(const char *path)
{
	static const char *const ext[] = {".txt", ".tsv", ".csv", ".json"};
	const char *dot = path ? strrchr(path, '.') : NULL, *slash = path ? strrchr(path, '/') : NULL;
	if (!dot || (slash && dot < slash) || dot == path || (slash && dot == slash + 1))
		return OUT_TABLE; /* no extension ("out", ".hidden", "-") */
	for (int i = 0; i < NFORMATS; i++)
		if (strcasecmp(dot, ext[i]) == 0)
			return i;
	return -1;
}

int out_format_pick(int given, const char *path)
{
	int f = given >= 0 ? given : out_format_of(path);
	return f < 0 ? OUT_TABLE : f;
}

int out_usage(const char *cmd, const char *fmt, ...)
{
	va_list ap;
	fprintf(stderr, "anvil %s: ", cmd);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fprintf(stderr, " (see 'anvil %s --help')\n", cmd);
	return EXIT_USAGE;
}

int out_getopt_error(const char *cmd, int c, char **argv)
{
	const char *arg = argv[optind - 1];
	if (c == ':')
		return out_usage(cmd, "option '%s' needs a value", arg);
	if (optopt && strncmp(arg, "--", 2) != 0)
		return out_usage(cmd, "unknown option '-%c'", optopt);
	return out_usage(cmd, "unknown option '%s'", arg);
}

char *out_num(char *buf, double x, const char *fmt)
{
	if (isnan(x))
		strcpy(buf, fmt ? "-" : "nan");
	else if (isinf(x))
		strcpy(buf, x > 0 ? "inf" : "-inf");
	else
		snprintf(buf, 40, fmt ? fmt : OUT_NUM_FMT, x);
	return buf;
}

char *out_err(char *buf, double x, const char *fmt)
{
	if (fmt && x == 0)
		return strcpy(buf, "0");
	return out_num(buf, x, fmt);
}

/* ---- the grid ---- */

struct out_grid {
	int ncol;
	size_t n, cap;    /* cells stored */
	char **cell;
	unsigned char *left; /* per column */
	unsigned char *text; /* per column: JSON strings, never numbers */
	int nomem;
};

struct out_grid *out_grid_alloc(int ncol)
{
	struct out_grid *g = calloc(1, sizeof *g);
	if (!g)
		return NULL;
	g->ncol = ncol;
	g->left = calloc((size_t)ncol, 1);
	g->text = calloc((size_t)ncol, 1);
	if (!g->left || !g->text) {
		free(g->left);
		free(g->text);
		free(g);
		return NULL;
	}
	g->left[0] = 1; /* the first column names the row */
	return g;
}

void out_grid_free(struct out_grid *g)
{
	if (!g)
		return;
	for (size_t i = 0; i < g->n; i++)
		free(g->cell[i]);
	free(g->cell);
	free(g->left);
	free(g->text);
	free(g);
}

void out_grid_left(struct out_grid *g, int col)
{
	if (g && col >= 0 && col < g->ncol)
		g->left[col] = 1;
}

void out_grid_text(struct out_grid *g, int col)
{
	if (g && col >= 0 && col < g->ncol)
		g->text[col] = g->left[col] = 1;
}

void out_grid_cell(struct out_grid *g, const char *fmt, ...)
{
	char *s = NULL;
	va_list ap;
	if (!g)
		return;
	if (g->n == g->cap) {
		size_t cap = g->cap ? 2 * g->cap : 64;
		char **c = realloc(g->cell, cap * sizeof *c);
		if (!c) {
			g->nomem = 1;
			return;
		}
		g->cell = c;
		g->cap = cap;
	}
	va_start(ap, fmt);
	int len = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	if (len >= 0 && (s = malloc((size_t)len + 1))) {
		va_start(ap, fmt);
		vsnprintf(s, (size_t)len + 1, fmt, ap);
		va_end(ap);
	}
	/* Keep the grid rectangular even without the text. */
	if (!s)
		g->nomem = 1;
	g->cell[g->n++] = s;
}

/* Display width of UTF-8 text: continuation bytes take no column ("±"). */
static int text_width(const char *s)
{
	int w = 0;
	for (; s && *s; s++)
		w += ((unsigned char)*s & 0xC0) != 0x80;
	return w;
}

static void put_csv(const char *s, FILE *f)
{
	if (!strpbrk(s, ",\"\n\r")) {
		fputs(s, f);
		return;
	}
	fputc('"', f);
	for (; *s; s++) {
		if (*s == '"')
			fputc('"', f);
		fputc(*s, f);
	}
	fputc('"', f);
}

/* TSV cannot quote: a tab or newline inside a cell becomes a space. */
static void put_tsv(const char *s, FILE *f)
{
	for (; *s; s++)
		fputc(*s == '\t' || *s == '\n' || *s == '\r' ? ' ' : *s, f);
}

static void put_padded(const char *s, int width, int left, int last, FILE *f)
{
	int pad = width - text_width(s);
	if (!left)
		for (int i = 0; i < pad; i++)
			fputc(' ', f);
	fputs(s, f);
	if (left && !last)
		for (int i = 0; i < pad; i++)
			fputc(' ', f);
}

static void print_table(const struct out_grid *g, FILE *f)
{
	int *width = calloc((size_t)g->ncol, sizeof *width);
	if (!width)
		return;
	for (size_t i = 0; i < g->n; i++) {
		int c = (int)(i % (size_t)g->ncol), w = text_width(g->cell[i]);
		if (w > width[c])
			width[c] = w;
	}
	for (size_t i = 0; i < g->n; i++) {
		int c = (int)(i % (size_t)g->ncol), last = c == g->ncol - 1;
		put_padded(g->cell[i], width[c], g->left[c], last, f);
		fputs(last ? "\n" : "  ", f);
	}
	free(width);
}

/* ---- JSON ---- */

static void json_string(FILE *f, const char *s)
{
	fputc('"', f);
	for (; *s; s++) {
		unsigned char c = (unsigned char)*s;
		if (c == '"' || c == '\\')
			fprintf(f, "\\%c", c);
		else if (c < 0x20)
			fprintf(f, "\\u%04x", c);
		else
			fputc(c, f);
	}
	fputc('"', f);
}

void out_json_string(FILE *f, const char *s)
{
	json_string(f, s);
}

/* JSON has no NaN or infinity: both become null. */
static void json_number(FILE *f, double x)
{
	if (isfinite(x))
		fprintf(f, OUT_NUM_FMT, x);
	else
		fputs("null", f);
}

/* A machine cell as JSON: a number when it is one ("nan", "inf" and the
 * table's "-" are null), else a string; text columns are always strings. */
static void json_cell(FILE *f, const char *s, int text)
{
	char *end;
	if (!text) {
		if (!strcmp(s, "nan") || !strcmp(s, "inf") || !strcmp(s, "-inf") || !strcmp(s, "-")) {
			fputs("null", f);
			return;
		}
		double x = strtod(s, &end);
		/* strtod also reads "0x1p3" and "infinity": JSON reads neither */
		if (end != s && !*end && isfinite(x) && !strpbrk(s, "xXiInN")) {
			json_number(f, x);
			return;
		}
	}
	json_string(f, s);
}

/* An array of objects, one per row after the header, keyed by it. */
static void print_json(const struct out_grid *g, FILE *f, const char *indent)
{
	size_t nrow = g->n / (size_t)g->ncol;
	fputs("[", f);
	for (size_t r = 1; r < nrow; r++) {
		fprintf(f, "%s\n%s  {", r > 1 ? "," : "", indent);
		for (int c = 0; c < g->ncol; c++) {
			fputs(c ? ", " : "", f);
			json_string(f, g->cell[c]);
			fputs(": ", f);
			json_cell(f, g->cell[r * (size_t)g->ncol + (size_t)c], g->text[c]);
		}
		fputs("}", f);
	}
	fprintf(f, "%s]", nrow > 1 ? "\n" : "");
	(void)indent;
}

int out_grid_json(const struct out_grid *g, FILE *f, const char *indent)
{
	if (!g || g->nomem || g->n % (size_t)g->ncol)
		return ANVIL_ENOMEM;
	print_json(g, f, indent ? indent : "");
	return ferror(f) ? ANVIL_EIO : ANVIL_OK;
}

int out_grid_print(const struct out_grid *g, enum out_format fmt, FILE *f)
{
	if (!g || g->nomem || g->n % (size_t)g->ncol)
		return ANVIL_ENOMEM;
	if (fmt == OUT_TABLE) {
		print_table(g, f);
	} else if (fmt == OUT_JSON) {
		print_json(g, f, "");
		fputc('\n', f);
	} else {
		for (size_t i = 0; i < g->n; i++) {
			int last = (int)(i % (size_t)g->ncol) == g->ncol - 1;
			if (fmt == OUT_CSV)
				put_csv(g->cell[i], f);
			else
				put_tsv(g->cell[i], f);
			fputs(last ? "\n" : fmt == OUT_CSV ? "," : "\t", f);
		}
	}
	return ferror(f) ? ANVIL_EIO : ANVIL_OK;
}

/* ---- results of `anvil run` ---- */

double out_h_r0(const struct anvil_scene *sc, const struct anvil_result *r)
{
	if (r && r->model == ANVIL_MODEL_HALFSPACE)
		return INFINITY;
	return anvil_scene_h(sc) / sc->radius;
}

/* --- contactB: which contact model a row has (options.h) --- */

/* "physical" or "paper" for a layer or halfspace row, "-" for hertz and
 * zener, which have their own contact. */
static const char *contact_of(const struct anvil_result *r)
{
	return r->contact == ANVIL_CONTACT_PHYSICAL || r->contact == ANVIL_CONTACT_PAPER
		       ? anvil_contact_name(r->contact)
		       : "-";
}

/* The table's row name: the model, "layer (paper)" for the paper's contact
 * (the physical rows carry the plain name: they are what anvil computes
 * unless asked otherwise). */
static const char *row_name(const struct anvil_result *r, char *buf, size_t n)
{
	if (r->contact == ANVIL_CONTACT_PAPER)
		snprintf(buf, n, "%s (paper)", anvil_model_name(r->model));
	else
		snprintf(buf, n, "%s", anvil_model_name(r->model));
	return buf;
}
/* --- end contactB --- */

/* One number of a result row: its column name, how to get it (scaled to the
 * column's unit), and how the table rounds it.  A table of columns keeps
 * the header, the machine rows and the JSON keys in one place. */
struct column {
	const char *name;     /* machine name, also the JSON key */
	const char *err_name; /* its error column, or NULL: none */
	const char *label;    /* table header */
	double scale;
	size_t off;           /* offsetof(struct anvil_result, value) */
	size_t err_off;       /* offset of its error estimate */
	const char *fmt;      /* table format */
	int zener_only;       /* meaningful on the zener row only */
};

#define RV(f) offsetof(struct anvil_result, f)
static const struct column columns[] = {
	{"ts_us", "ts_err_us", "t_s/us", 1e6, RV(ts.val), RV(ts.err), "%.2f", 0},
	{"tmax_us", "tmax_err_us", "t_max/us", 1e6, RV(tmax.val), RV(tmax.err), "%.2f", 0},
	{"Pmax_kN", "Pmax_err_kN", "P_max/kN", 1e-3, RV(Pmax.val), RV(Pmax.err), "%#.4g", 0},
	{"Vs_m_s", NULL, "V_s/(m/s)", 1, RV(Vs.val), 0, "%#.4g", 0},
	{"Rf", "Rf_err", "R_f", 1, RV(Rf.val), RV(Rf.err), "%#.4g", 0},
	{"Ea_J", "Ea_err_J", "E_a/J", 1, RV(Ea.val), RV(Ea.err), "%#.3g", 0},
	/* Zener's parameters describe the plate model: only its row has them */
	{"lambda_star", NULL, "lambda*", 1, RV(lambda_star), 0, "%#.4g", 1},
	{"Rf_star", NULL, "R*_f", 1, RV(Rf_star), 0, "%#.4g", 1},
};
#define NCOLUMNS ((int)(sizeof columns / sizeof columns[0]))

static int nerr(void)
{
	int n = 0;
	for (int i = 0; i < NCOLUMNS; i++)
		n += columns[i].err_name != NULL;
	return n;
}

static double field(const struct anvil_result *r, size_t off)
{
	return *(const double *)(const void *)((const char *)r + off);
}

static double value(const struct anvil_result *r, const struct column *c)
{
	if (c->zener_only && r->model != ANVIL_MODEL_ZENER)
		return NAN;
	return c->scale * field(r, c->off);
}

/* An error estimate below OUT_ERR_NOISE of its value is the rounding of
 * doubles, not an error of the method: it is reported as 0. */
static double error(const struct anvil_result *r, const struct column *c)
{
	if (!c->err_name)
		return NAN;
	double e = c->scale * field(r, c->err_off), x = value(r, c);
	return fabs(e) < OUT_ERR_NOISE * fabs(x) ? 0.0 : e;
}

/* The number of contacts (impact.h: repeated contacts), NaN when the
 * model does not count them. */
static double contacts(const struct anvil_result *r)
{
	return r->ncontacts ? (double)r->ncontacts : NAN;
}

/* The bound on R_f of a row whose impactor came to rest on the plate
 * (result.h rest_bound: the contact does not end, its t_s is when the
 * bound was reached), NaN where the contact ended: a table's reader can
 * tell the two without parsing the note. */
static double rest_max(const struct anvil_result *r)
{
	return r->rest_bound > 0 ? r->rest_bound : NAN;
}

static void machine_header(struct out_grid *g)
{
	out_grid_cell(g, "model");
	out_grid_cell(g, "h_r0");
	out_grid_cell(g, "V0_m_s");
	for (int i = 0; i < NCOLUMNS; i++)
		out_grid_cell(g, "%s", columns[i].name);
	for (int i = 0; i < NCOLUMNS; i++)
		if (columns[i].err_name)
			out_grid_cell(g, "%s", columns[i].err_name);
	out_grid_cell(g, "contacts");
	out_grid_cell(g, "time_s");
	out_grid_cell(g, "reach_P_m");
	out_grid_cell(g, "reach_bending_m");
	out_grid_cell(g, "rest_Rf_max");
	out_grid_cell(g, "contact"); /* last, as every table's (thickness, fit, histories) */
}

static void machine_row(struct out_grid *g, const struct anvil_scene *sc,
			const struct anvil_result *r)
{
	char b[40];
	out_grid_cell(g, "%s", anvil_model_name(r->model));
	out_grid_cell(g, "%s", out_num(b, out_h_r0(sc, r), NULL));
	out_grid_cell(g, "%s", out_num(b, sc->velocity, NULL));
	for (int i = 0; i < NCOLUMNS; i++)
		out_grid_cell(g, "%s", out_num(b, value(r, &columns[i]), NULL));
	for (int i = 0; i < NCOLUMNS; i++)
		if (columns[i].err_name)
			out_grid_cell(g, "%s", out_num(b, error(r, &columns[i]), NULL));
	out_grid_cell(g, "%s", out_num(b, contacts(r), NULL));
	out_grid_cell(g, "%s", out_num(b, r->seconds, NULL));
	out_grid_cell(g, "%s", out_num(b, r->reach_p, NULL));
	out_grid_cell(g, "%s", out_num(b, r->reach_bend, NULL));
	out_grid_cell(g, "%s", out_num(b, rest_max(r), NULL));
	out_grid_cell(g, "%s", contact_of(r));
}

static void table_header(struct out_grid *g)
{
	out_grid_cell(g, "model");
	out_grid_cell(g, "h/r0");
	for (int i = 0; i < NCOLUMNS; i++) {
		out_grid_cell(g, "%s", columns[i].label);
		if (columns[i].err_name)
			out_grid_cell(g, "±");
	}
	out_grid_cell(g, "contacts");
	out_grid_cell(g, "time/s");
}

/* A fixed-point column (the times, in us) keeps its two decimals from
 * 0.01 to 1e6 (a second); beyond, the table's significant digits: 1e6 kg
 * on a plate lasts 3.3e10 us, not "33204123778.45", and a dashpot-limit
 * t_max of 8.9e-7 us is not "0.00". */
#define TABLE_FIXED_MIN 0.01
#define TABLE_FIXED_MAX 1e6
static const char *table_fmt(const struct column *c, double x)
{
	if (strcmp(c->fmt, "%.2f") || x == 0 || !isfinite(x))
		return c->fmt;
	return fabs(x) >= TABLE_FIXED_MIN && fabs(x) < TABLE_FIXED_MAX ? c->fmt : "%#.4g";
}

static void table_row(struct out_grid *g, const struct anvil_scene *sc,
		      const struct anvil_result *r)
{
	char b[40];
	out_grid_cell(g, "%s", row_name(r, b, sizeof b));
	out_grid_cell(g, "%s", out_num(b, out_h_r0(sc, r), "%.4g"));
	for (int i = 0; i < NCOLUMNS; i++) {
		double x = value(r, &columns[i]);
		out_grid_cell(g, "%s", out_num(b, x, table_fmt(&columns[i], x)));
		if (columns[i].err_name)
			out_grid_cell(g, "%s", out_err(b, error(r, &columns[i]), "%.2g"));
	}
	out_grid_cell(g, "%s", out_num(b, contacts(r), "%.0f"));
	out_grid_cell(g, "%s", out_num(b, r->seconds, "%.3g"));
}

const char *out_length(char *buf, size_t n, double m)
{
	if (fabs(m) >= 1.0)
		snprintf(buf, n, "%.3g m", m);
	else
		snprintf(buf, n, "%.3g mm", m * 1e3);
	return buf;
}

const char *out_duration(char *buf, size_t n, double s)
{
	if (fabs(s) >= 1e-2)
		snprintf(buf, n, "%.4g ms", s * 1e3);
	else
		snprintf(buf, n, "%.4g us", s * 1e6);
	return buf;
}

/* The longest reach (result.h) of the rows: the layer's, else Zener's;
 * NULL when no row has one. */
const struct anvil_result *out_reach_row(const struct anvil_result *res, int n)
{
	const struct anvil_result *best = NULL;
	for (int i = 0; i < n; i++)
		if (isfinite(res[i].reach_bend) &&
		    (!best || (res[i].model == ANVIL_MODEL_LAYER && best->model != ANVIL_MODEL_LAYER) ||
		     (res[i].model == best->model && res[i].reach_bend > best->reach_bend)))
			best = &res[i];
	return best;
}

/* How far the layer moves during the contact, below the notes: the
 * model's layer is unbounded, a user's plate is not. */
static void table_reach(FILE *f, const struct anvil_scene *sc, const struct anvil_result *res, int n)
{
	const struct anvil_result *r = out_reach_row(res, n);
	if (!r)
		return;
	double h = anvil_scene_h(sc);
	char b[40], ts[24], lp[24], lb[24], l2[24];
	fprintf(f, "reach (%s, t_s = %s): the P wave runs %s, the bending spreads over %s (%.3g h): "
		"the layer is unbounded here; a plate narrower than %s, or supported within %s, "
		"answers otherwise\n",
		row_name(r, b, sizeof b), out_duration(ts, sizeof ts, r->ts.val),
		out_length(lp, sizeof lp, r->reach_p), out_length(lb, sizeof lb, r->reach_bend),
		r->reach_bend / h, out_length(l2, sizeof l2, 2.0 * r->reach_bend), lb);
}

/* What the table shows below the rows, after the models' notes: the
 * scene in one line, so a pasted table still says what was simulated. */
static void table_caption(FILE *f, const struct anvil_scene *sc)
{
	double h = anvil_scene_h(sc);
	char m[24];
	/* kg from 1 kg up: a drop weight read as "1e+05 g" is a misreading waiting */
	if (sc->mass >= 1.0)
		snprintf(m, sizeof m, "%.4g kg", sc->mass);
	else
		snprintf(m, sizeof m, "%.4g g", sc->mass * 1e3);
	fprintf(f, "\n%s: %s impactor %s, r0 = %.4g mm, V0 = %.4g m/s -> %s layer ",
		sc->title[0] ? sc->title : "scene", sc->impactor.mat.name, m,
		sc->radius * 1e3, sc->velocity, sc->layer.mat.name);
	if (isinf(h))
		fputs("h = inf (half-space)", f);
	else
		fprintf(f, "h = %.4g r0 = %.4g mm", h / sc->radius, h * 1e3);
	fprintf(f, ", accuracy %s\n", anvil_accuracy_name(sc->accuracy));
}

static int results_grid(FILE *f, enum out_format fmt, const struct anvil_scene *sc,
			const struct anvil_result *res, int n)
{
	/* model, h_r0, V0 and contact (not in the table: the row name says it),
	 * values, errors, contacts, seconds, the reach (in the table a line
	 * below), the rest's bound (in the table the note's) */
	int ncol = 3 + NCOLUMNS + nerr() + 2 + 1 + 2 + 1 - 5 * (fmt == OUT_TABLE);
	struct out_grid *g = out_grid_alloc(ncol);
	if (!g)
		return ANVIL_ENOMEM;
	if (fmt == OUT_TABLE)
		table_header(g);
	else
		machine_header(g);
	for (int i = 0; i < n; i++) {
		if (fmt == OUT_TABLE)
			table_row(g, sc, &res[i]);
		else
			machine_row(g, sc, &res[i]);
	}
	int st = out_grid_print(g, fmt, f);
	out_grid_free(g);
	if (fmt == OUT_TABLE && !st) {
		int any = 0;
		char b[40];
		for (int i = 0; i < n; i++)
			if (res[i].note[0])
				fprintf(f, "%s%s: %s\n", any++ ? "" : "\n",
					row_name(&res[i], b, sizeof b), res[i].note);
		table_reach(f, sc, res, n);
		table_caption(f, sc);
		st = ferror(f) ? ANVIL_EIO : ANVIL_OK;
	}
	return st;
}

static void json_key(FILE *f, const char *indent, const char *key)
{
	fprintf(f, ",\n%s", indent);
	json_string(f, key);
	fputs(": ", f);
}

static void json_scene(FILE *f, const struct anvil_scene *sc)
{
	const char *in = "    ";
	fputs("  \"scene\": {\n    \"title\": ", f);
	json_string(f, sc->title);
	json_key(f, in, "impactor");
	json_string(f, sc->impactor.mat.name);
	json_key(f, in, "layer");
	json_string(f, sc->layer.mat.name);
	json_key(f, in, "thickness_m");
	json_number(f, anvil_scene_h(sc));
	json_key(f, in, "h_r0");
	json_number(f, out_h_r0(sc, NULL));
	json_key(f, in, "V0_m_s");
	json_number(f, sc->velocity);
	json_key(f, in, "mass_kg");
	json_number(f, sc->mass);
	json_key(f, in, "radius_m");
	json_number(f, sc->radius);
	json_key(f, in, "accuracy");
	json_string(f, anvil_accuracy_name(sc->accuracy));
	fputs("\n  }", f);
}

static void json_result(FILE *f, const struct anvil_scene *sc,
			const struct anvil_result *r)
{
	const char *in = "      ";
	fputs("    {\n      \"model\": ", f);
	json_string(f, anvil_model_name(r->model));
	json_key(f, in, "h_r0");
	json_number(f, out_h_r0(sc, r));
	json_key(f, in, "V0_m_s");
	json_number(f, sc->velocity);
	for (int i = 0; i < NCOLUMNS; i++) {
		json_key(f, in, columns[i].name);
		json_number(f, value(r, &columns[i]));
	}
	for (int i = 0; i < NCOLUMNS; i++) {
		if (!columns[i].err_name)
			continue;
		json_key(f, in, columns[i].err_name);
		json_number(f, error(r, &columns[i]));
	}
	json_key(f, in, "contacts");
	json_number(f, contacts(r));
	json_key(f, in, "time_s");
	json_number(f, r->seconds);
	json_key(f, in, "status");
	json_string(f, r->status < 0 ? "failed" : r->status > 0 ? "warning" : "ok");
	json_key(f, in, "note");
	json_string(f, r->note);
	json_key(f, in, "contact");
	json_string(f, contact_of(r));
	json_key(f, in, "reach_P_m");
	json_number(f, r->reach_p);
	json_key(f, in, "reach_bending_m");
	json_number(f, r->reach_bend);
	json_key(f, in, "rest_Rf_max");
	json_number(f, rest_max(r));
	fputs("\n    }", f);
}

static int results_json(FILE *f, const struct anvil_scene *sc,
			const struct anvil_result *res, int n)
{
	fputs("{\n", f);
	json_scene(f, sc);
	fputs(",\n  \"results\": [\n", f);
	for (int i = 0; i < n; i++) {
		json_result(f, sc, &res[i]);
		fputs(i + 1 < n ? ",\n" : "\n", f);
	}
	fputs("  ]\n}\n", f);
	return ferror(f) ? ANVIL_EIO : ANVIL_OK;
}

int out_results(FILE *f, enum out_format fmt, const struct anvil_scene *sc,
		const struct anvil_result *res, int n)
{
	if (fmt == OUT_JSON)
		return results_json(f, sc, res, n);
	return results_grid(f, fmt, sc, res, n);
}

int out_history(FILE *f, const struct anvil_result *res, int n)
{
	fputs("model\tt_us\tP_kN\tv_m_s\tW_impactor_um\tw_layer_um\talphaH_um\tcontact\n", f);
	for (int i = 0; i < n; i++) {
		const struct anvil_history *h = &res[i].hist;
		const char *name = anvil_model_name(res[i].model), *c = contact_of(&res[i]);
		for (size_t k = 0; k < h->n; k++)
			fprintf(f, "%s\t%.10g\t%.10g\t%.10g\t%.10g\t%.10g\t%.10g\t%s\n", name,
				h->t[k] * 1e6, h->P[k] * 1e-3, h->v[k], h->W[k] * 1e6,
				h->w[k] * 1e6, h->alpha[k] * 1e6, c);
	}
	return ferror(f) ? ANVIL_EIO : ANVIL_OK;
}
