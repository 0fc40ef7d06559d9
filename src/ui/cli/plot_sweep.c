/* plot_sweep.c: see plot_sweep.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common.h"
#include "output.h"
#include "plot_sweep.h"
#include "sweep.h"

#define PLOT_SWEEP_V "1..100m/s:13:log" /* a ratio of 1.47 between neighbours */

struct rfv {
	struct plot_run *runs;
	struct anvil_result *res;
	int *group;                /* each run's curve (material pair) */
	int n, cap;
	int group_now;             /* the curve of the sweep under way */
	enum anvil_contact contact; /* of the first wave row drawn (AUTO: none yet) */
};

static int rfv_emit(void *ctx, const struct sweep_done *d)
{
	struct rfv *v = ctx;
	for (int i = 0; i < d->n; i++) {
		if (v->n == v->cap)
			return ANVIL_ENOMEM; /* sized for every row: not reached */
		const struct anvil_result *r = &d->r[i];
		v->res[v->n] = *r;
		memset(&v->res[v->n].hist, 0, sizeof v->res[v->n].hist); /* no history kept */
		v->runs[v->n] = (struct plot_run){r->status >= 0 ? &v->res[v->n] : NULL, r->model, NAN, NAN,
						  r->lambda_star};
		v->group[v->n] = v->group_now;
		if (!v->contact && r->status >= 0 && r->contact)
			v->contact = r->contact;
		v->n++;
	}
	return ANVIL_OK;
}

/* One sweep of base over the axes (a velocity axis, maybe thicknesses)
 * into v, its runs in group g. */
static int rfv_sweep(struct rfv *v, const struct anvil_scene *base, const char *h_axis, const char *v_axis,
		     int g, struct anvil_err *err)
{
	struct sweep sw = {0};
	int st;
	sw.base = *base;
	if (!(st = anvil_scene_set(&sw.base, "solver.models", "zener,layer,halfspace", "plot", 0, err)) &&
	    (!h_axis || !(st = sweep_axis_add(&sw, h_axis, err))) && !(st = sweep_axis_add(&sw, v_axis, err)))
		st = sweep_layout(&sw, err);
	if (!st && v->n + (int)sw.nrows > v->cap) {
		int cap = v->n + (int)sw.nrows;
		struct plot_run *runs = realloc(v->runs, (size_t)(cap + 1) * sizeof *runs);
		int *group = runs ? realloc(v->group, (size_t)(cap + 1) * sizeof *group) : NULL;
		struct anvil_result *res = group ? realloc(v->res, (size_t)(cap + 1) * sizeof *res) : NULL;
		if (runs)
			v->runs = runs;
		if (group)
			v->group = group;
		if (res) {
			/* the runs point into res: re-point them after the move */
			for (int i = 0; i < v->n; i++)
				if (v->runs[i].r)
					v->runs[i].r = &res[i];
			v->res = res;
			v->cap = cap;
		}
		st = res ? ANVIL_OK : ANVIL_ENOMEM;
	}
	int n0 = v->n;
	v->group_now = g;
	if (!st)
		st = sweep_run(&sw, 0, sw.nscenes, NULL, sweep_cores(), rfv_emit, NULL, v, NULL, NULL);
	/* the scene of each row, for h and V0 */
	for (size_t s = 0, k = (size_t)n0; !st && s < sw.nscenes; s++) {
		struct anvil_scene one;
		sweep_scene(&sw, s, &one, NULL);
		for (size_t r = sw.row0[s]; r < sw.row0[s + 1] && k < (size_t)v->n; r++, k++) {
			v->runs[k].h_r0 = anvil_scene_h(&one) / one.radius;
			v->runs[k].V0 = one.velocity;
		}
	}
	sweep_free(&sw);
	return st;
}

/* "IMPACTOR/LAYER" or "LAYER" (the scene's impactor): the pair set on sc,
 * its key label in label.  ANVIL_EPARSE with a message naming the item. */
static int rfv_pair(struct anvil_scene *sc, const char *item, char *label, size_t n, struct anvil_err *err)
{
	char imp[64] = "", lay[64];
	const char *slash = strchr(item, '/');
	struct anvil_err e = {0};
	int st = ANVIL_OK;
	if (slash && (size_t)(slash - item) < sizeof imp)
		snprintf(imp, sizeof imp, "%.*s", (int)(slash - item), item);
	snprintf(lay, sizeof lay, "%s", slash ? slash + 1 : item);
	if ((slash && !imp[0]) || !lay[0] || strchr(lay, '/'))
		return anvil_err_set(err, ANVIL_EPARSE, "--materials: '%s': expected IMPACTOR/LAYER or LAYER, "
				     "e.g. copper/steel", item);
	if (imp[0])
		st = anvil_scene_set(sc, "impactor.material", imp, "--materials", 0, &e);
	if (!st)
		st = anvil_scene_set(sc, "layer.material", lay, "--materials", 0, &e);
	if (!st)
		st = anvil_scene_check(sc, &e);
	if (st) /* e.msg names --materials and the key */
		return anvil_err_set(err, ANVIL_EPARSE, "%s", e.msg);
	snprintf(label, n, "%s on %s", sc->impactor.mat.name, sc->layer.mat.name);
	return ANVIL_OK;
}

#define RFV_LABEL (2 * ANVIL_NAME_MAX + 32) /* "IMP on LAYER, M g" */

/* The material pairs of list (comma-separated) on sc: scenes and labels,
 * the mass added to each label when the pairs' masses differ (a ball's
 * mass follows its material). */
static int rfv_pairs(const struct anvil_scene *sc, const char *list, struct anvil_scene *pair,
		     char label[][RFV_LABEL], int *np, int *same_mass, struct anvil_err *err)
{
	char buf[1024], *save = NULL;
	int st = ANVIL_OK, same = 1;
	*np = 0;
	if (snprintf(buf, sizeof buf, "%s", list) >= (int)sizeof buf)
		return anvil_err_set(err, ANVIL_EPARSE, "--materials: the list is too long");
	for (char *tok = strtok_r(buf, ",", &save); tok && !st; tok = strtok_r(NULL, ",", &save)) {
		if (*np == PLOT_MAX_GROUPS)
			return anvil_err_set(err, ANVIL_EPARSE, "--materials %s: at most %d pairs on one chart",
					     list, PLOT_MAX_GROUPS);
		pair[*np] = *sc;
		st = rfv_pair(&pair[*np], tok, label[*np], RFV_LABEL, err);
		same &= pair[*np].mass == pair[0].mass;
		(*np)++;
	}
	if (!st && (*np == 0 || list[strlen(list) - 1] == ',' || list[0] == ','))
		return anvil_err_set(err, ANVIL_EPARSE, "--materials '%s': expected a list such as "
				     "copper/steel,steel/steel", list);
	for (int i = 0; !st && !same && i < *np; i++) {
		size_t k = strlen(label[i]);
		snprintf(label[i] + k, RFV_LABEL - k, ", %.3g g", pair[i].mass * 1e3);
	}
	*same_mass = same;
	return st;
}

int plot_sweep_rf_velocity(struct plot_chart *c, const struct anvil_scene *sc, int fixed_h,
			   const char *materials, const char *velocities)
{
	struct anvil_err err = {0};
	struct rfv v = {0};
	struct anvil_scene pair[PLOT_MAX_GROUPS];
	char axis[512], label[PLOT_MAX_GROUPS][RFV_LABEL];
	const char *labels[PLOT_MAX_GROUPS];
	int st = ANVIL_OK, code = EXIT_FAIL, np = 0, same_mass = 1;
	snprintf(axis, sizeof axis, "impact.velocity=%s", velocities ? velocities : PLOT_SWEEP_V);
	if (materials && (st = rfv_pairs(sc, materials, pair, label, &np, &same_mass, &err)))
		goto out;
	if (materials)
		for (int g = 0; g < np && !st; g++) {
			labels[g] = label[g];
			st = rfv_sweep(&v, &pair[g], NULL, axis, g, &err);
		}
	else
		st = rfv_sweep(&v, sc, fixed_h ? NULL : "layer.thickness=1r0,2r0,5r0,10r0", axis, 0, &err);
	if (st)
		goto out;
	int failed = 0;
	for (int i = 0; i < v.n; i++)
		failed += !v.runs[i].r;
	if (failed)
		cli_error("plot: %d of %d runs failed and are left out (anvil sweep shows why)", failed, v.n);
	st = materials ? plot_chart_rf_velocity_groups(c, v.runs, v.n, v.group, labels, np)
		       : plot_chart_rf_velocity(c, v.runs, v.n);
	if (!st && materials)
		plot_chart_subtitle_materials(c, sc, !same_mass);
	if (!st && v.contact)
		snprintf(c->footnote, sizeof c->footnote, "layer and half-space with the %s contact "
			 "(effects.contact)", anvil_contact_name(v.contact));
	code = st ? EXIT_FAIL : EXIT_OK; /* per thickness, the caller writes the subtitle */
out:
	if (st == ANVIL_EPARSE)
		cli_error("plot: %s", err.msg);
	else if (st == ANVIL_EINVAL)
		cli_error("plot: restitution-velocity: nothing to draw (every layer run failed)");
	else if (st)
		cli_error("plot: %s", err.msg[0] ? err.msg : anvil_strerror(st));
	free(v.runs);
	free(v.group);
	free(v.res);
	return st == ANVIL_EPARSE ? EXIT_USAGE : code;
}

/* ---- the map from a file ---- */

/* Cell col of a TSV/CSV line (CSV quotes honoured) into buf; 0 if none. */
static int cell_at(const char *line, enum out_format fmt, int col, char *buf, size_t n)
{
	char sep = fmt == OUT_CSV ? ',' : '\t';
	for (int c = 0;; c++) {
		size_t k = 0;
		int q = fmt == OUT_CSV && *line == '"';
		if (q)
			line++;
		while (*line && (q || *line != sep)) {
			if (q && *line == '"') {
				if (line[1] != '"') {
					line++;
					q = 0;
					continue;
				}
				line++;
			}
			if (c == col && k + 1 < n)
				buf[k++] = *line;
			line++;
		}
		if (c == col) {
			buf[k] = '\0';
			return 1;
		}
		if (!*line)
			return 0;
		line++;
	}
}

/* The value of "key": in a JSON row line. */
static int json_at(const char *line, const char *key, char *buf, size_t n)
{
	char pat[64];
	snprintf(pat, sizeof pat, "\"%s\": ", key);
	const char *p = strstr(line, pat);
	if (!p)
		return 0;
	p += strlen(pat);
	int q = *p == '"';
	p += q;
	size_t k = 0;
	while (*p && (q ? *p != '"' : (*p != ',' && *p != '}')) && k + 1 < n)
		buf[k++] = *p++;
	buf[k] = '\0';
	return 1;
}

static int col_of(const char *header, enum out_format fmt, const char *name)
{
	char buf[128];
	for (int c = 0; cell_at(header, fmt, c, buf, sizeof buf); c++)
		if (!strcmp(buf, name))
			return c;
	return -1;
}

static int add_unique(double *a, size_t *n, double x)
{
	size_t j = 0;
	while (j < *n && a[j] < x)
		j++;
	if (j < *n && a[j] == x)
		return 0;
	memmove(a + j + 1, a + j, (*n - j) * sizeof *a);
	a[j] = x;
	(*n)++;
	return 1;
}

static size_t index_in(const double *a, size_t n, double x)
{
	size_t j = 0;
	while (j < n && a[j] != x)
		j++;
	return j;
}

struct map_rows {
	double *v, *h, *rf;
	size_t n;
	char contact[16]; /* the contact model of the rows taken, "" when the file has none */
};

/* The contact cell of row i ("" without the column: an older file). */
static void map_contact(const struct sweep_file *f, enum out_format fmt, size_t i, int col, char *buf,
			size_t n)
{
	buf[0] = '\0';
	if (fmt == OUT_JSON ? !json_at(f->row[i], "contact", buf, n)
			    : col < 0 || !cell_at(f->row[i], fmt, col, buf, n))
		buf[0] = '\0';
}

/* The layer rows' V0, h and R_f.  A sweep with contact = both has a
 * layer row of each contact model per cell: the map is the physical
 * one's (the subtitle says which). */
static int map_rows(const struct sweep_file *f, enum out_format fmt, const char *file, struct map_rows *r)
{
	static const char *const names[] = {"V0_m_s", "h_r0", "model", "Rf"};
	int col[4], ccol = fmt == OUT_JSON ? -1 : col_of(f->header, fmt, "contact");
	char buf[4][128], c[16];
	for (int k = 0; k < 4 && fmt != OUT_JSON; k++)
		if ((col[k] = col_of(f->header, fmt, names[k])) < 0) {
			cli_error("plot: %s: no column %s (not anvil sweep's rows?)", file, names[k]);
			return EXIT_USAGE;
		}
	r->v = malloc((f->nrow + 1) * sizeof *r->v);
	r->h = malloc((f->nrow + 1) * sizeof *r->h);
	r->rf = malloc((f->nrow + 1) * sizeof *r->rf);
	if (!r->v || !r->h || !r->rf)
		return EXIT_FAIL;
	for (size_t i = 0; i < f->nrow; i++) {
		map_contact(f, fmt, i, ccol, c, sizeof c);
		if (!r->contact[0] || !strcmp(c, "physical"))
			snprintf(r->contact, sizeof r->contact, "%s", c);
	}
	for (size_t i = 0; i < f->nrow; i++) {
		int got = 1;
		for (int k = 0; k < 4; k++)
			got &= fmt == OUT_JSON ? json_at(f->row[i], names[k], buf[k], sizeof buf[k])
					       : cell_at(f->row[i], fmt, col[k], buf[k], sizeof buf[k]);
		if (!got) {
			cli_error("plot: %s: row %zu: missing cells", file, i + 1);
			return EXIT_USAGE;
		}
		map_contact(f, fmt, i, ccol, c, sizeof c);
		if (strcmp(buf[2], "layer") || strcmp(c, r->contact))
			continue; /* the layer model's map, one contact model */
		r->v[r->n] = strtod(buf[0], NULL);
		r->h[r->n] = strtod(buf[1], NULL);
		r->rf[r->n] = strcmp(buf[3], "null") ? strtod(buf[3], NULL) : NAN;
		if (isfinite(r->v[r->n]) && isfinite(r->h[r->n]) && r->v[r->n] > 0 && r->h[r->n] > 0)
			r->n++;
	}
	return -1;
}

int plot_sweep_rf_map(const char *file, const struct plot_opts *o, const char *path, const char *script)
{
	struct sweep_file f;
	struct anvil_err err = {0};
	struct map_rows r = {0};
	struct plot_rf_map m = {0};
	double *grid = NULL, *vs = NULL, *hs = NULL;
	int fmt = out_format_of(file), code;
	if (!file) {
		cli_error("plot: restitution-map needs FILE, the rows of anvil sweep (with "
			  "impact.velocity and layer.thickness axes)");
		return EXIT_USAGE;
	}
	if (fmt <= OUT_TABLE)
		fmt = OUT_TSV;
	int st = sweep_file_read(file, (enum out_format)fmt, &f, &err);
	if (st) {
		cli_error("plot: %s", err.msg);
		return cli_exit_code(st);
	}
	code = map_rows(&f, (enum out_format)fmt, file, &r);
	size_t nv = 0, nh = 0;
	if (code < 0 && (!(vs = malloc((r.n + 1) * sizeof *vs)) || !(hs = malloc((r.n + 1) * sizeof *hs))))
		code = EXIT_FAIL;
	for (size_t i = 0; code < 0 && i < r.n; i++) {
		add_unique(vs, &nv, r.v[i]);
		add_unique(hs, &nh, r.h[i]);
	}
	if (code < 0 && !(grid = malloc((nv * nh + 1) * sizeof *grid)))
		code = EXIT_FAIL;
	for (size_t i = 0; code < 0 && i < nv * nh; i++)
		grid[i] = NAN;
	for (size_t i = 0; code < 0 && i < r.n; i++) {
		double *g = &grid[index_in(hs, nh, r.h[i]) * nv + index_in(vs, nv, r.v[i])];
		if (!isnan(*g)) {
			cli_error("plot: %s: two layer rows at V0 = %g m/s, h = %g r0: the map needs one "
				  "(another axis varies: sweep V0 and h only)", file, r.v[i], r.h[i]);
			code = EXIT_USAGE;
		}
		*g = r.rf[i];
	}
	if (code < 0) {
		m = (struct plot_rf_map){.nv = nv, .nh = nh, .v0 = vs, .h_r0 = hs, .rf = grid};
		snprintf(m.title, sizeof m.title, "Coefficient of restitution R_f over V_0 and h (layer model%s%s%s)",
			 r.contact[0] ? ", " : "", r.contact, r.contact[0] ? " contact" : "");
		snprintf(m.subtitle, sizeof m.subtitle, "from %s: %zu runs", file, r.n);
		st = plot_rf_map_save(&m, o, path, script, &err);
		if (st)
			cli_error("plot: %s", err.msg);
		code = st ? EXIT_FAIL : EXIT_OK;
	}
	free(grid);
	free(vs);
	free(hs);
	free(r.v);
	free(r.h);
	free(r.rf);
	sweep_file_free(&f);
	return code;
}
