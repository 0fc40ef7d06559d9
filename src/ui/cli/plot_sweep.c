/* plot_sweep.c: see plot_sweep.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common.h"
#include "output.h"
#include "plot_sweep.h"
#include "sweep.h"

#define PLOT_SWEEP_NV 13 /* 1..100 m/s: a ratio of 1.47 between neighbours */

struct rfv {
	struct plot_run *runs;
	struct anvil_result *res;
	int n, cap;
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
		v->n++;
	}
	return ANVIL_OK;
}

int plot_sweep_rf_velocity(struct plot_chart *c, const struct anvil_scene *sc, int fixed_h)
{
	struct sweep sw = {0};
	struct anvil_err err = {0};
	struct rfv v = {0};
	char axis[64];
	int st, code = EXIT_FAIL;
	sw.base = *sc;
	if ((st = anvil_scene_set(&sw.base, "solver.models", "zener,layer,halfspace", "plot", 0, &err)))
		goto out;
	if (!fixed_h && (st = sweep_axis_add(&sw, "layer.thickness=1r0,2r0,5r0,10r0", &err)))
		goto out;
	snprintf(axis, sizeof axis, "impact.velocity=1..100m/s:%d:log", PLOT_SWEEP_NV);
	if ((st = sweep_axis_add(&sw, axis, &err)) || (st = sweep_layout(&sw, &err)))
		goto out;
	v.cap = (int)sw.nrows;
	v.runs = calloc(sw.nrows + 1, sizeof *v.runs);
	v.res = calloc(sw.nrows + 1, sizeof *v.res);
	if (!v.runs || !v.res || (st = sweep_run(&sw, 0, sw.nscenes, NULL, sweep_cores(), rfv_emit, NULL, &v,
						  NULL, NULL)))
		goto out;
	/* the scene of each row, for h and V0 */
	for (size_t s = 0, k = 0; s < sw.nscenes; s++) {
		struct anvil_scene one;
		sweep_scene(&sw, s, &one, NULL);
		for (size_t r = sw.row0[s]; r < sw.row0[s + 1] && k < (size_t)v.n; r++, k++) {
			v.runs[k].h_r0 = anvil_scene_h(&one) / one.radius;
			v.runs[k].V0 = one.velocity;
		}
	}
	int failed = 0;
	for (int i = 0; i < v.n; i++)
		failed += !v.runs[i].r;
	if (failed)
		cli_error("plot: %d of %d runs failed and are left out (anvil sweep shows why)", failed, v.n);
	st = plot_chart_rf_velocity(c, v.runs, v.n);
	code = st ? EXIT_FAIL : EXIT_OK; /* the caller writes the subtitle */
out:
	if (st == ANVIL_EINVAL)
		cli_error("plot: restitution-velocity: nothing to draw (every layer run failed)");
	else if (st)
		cli_error("plot: %s", err.msg[0] ? err.msg : anvil_strerror(st));
	free(v.runs);
	free(v.res);
	sweep_free(&sw);
	return code;
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
};

static int map_rows(const struct sweep_file *f, enum out_format fmt, const char *file, struct map_rows *r)
{
	static const char *const names[] = {"V0_m_s", "h_r0", "model", "Rf"};
	int col[4];
	char buf[4][128];
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
		int got = 1;
		for (int k = 0; k < 4; k++)
			got &= fmt == OUT_JSON ? json_at(f->row[i], names[k], buf[k], sizeof buf[k])
					       : cell_at(f->row[i], fmt, col[k], buf[k], sizeof buf[k]);
		if (!got) {
			cli_error("plot: %s: row %zu: missing cells", file, i + 1);
			return EXIT_USAGE;
		}
		if (strcmp(buf[2], "layer"))
			continue; /* the layer model's map */
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
		snprintf(m.title, sizeof m.title, "Coefficient of restitution R_f over V_0 and h (layer model)");
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
