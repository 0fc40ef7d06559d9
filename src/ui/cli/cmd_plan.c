/* cmd_plan.c: `anvil plan`, what the planner (src/core/plan.h) decides for
 * a scene and why: the estimates it made, how each row of `anvil run` will
 * be computed with its reason, figures and estimated cost, and the
 * warnings.  Nothing is run.  anvil_plan_print() also serves `anvil run -v`. */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "plan.h"
#include "verdict.h"
#include "commands.h"
#include "common.h"
#include "output.h"

struct plan_opts {
	const char *scene, *out;
	char *models; /* "solver.models=..." built from -m, owned */
	int format;
	struct cli_sets sets;
};

static void plan_usage(FILE *f)
{
	fputs("usage: anvil plan [SCENE] [-s KEY=VALUE]... [-m MODELS] [-f FORMAT] [-o FILE]\n"
	      "Show how 'anvil run' will compute the scene, without running it: the\n"
	      "physical estimates, each model's method with its reason, figures and\n"
	      "estimated cost, and warnings about effects anvil does not model.\n"
	      "  -s, --set KEY=VALUE  change a scene key, e.g. -s effects.waves=auto\n"
	      "  -m, --models LIST    models, e.g. layer,halfspace (as -s solver.models=)\n"
	      "  -f, --format FORMAT  table, tsv or csv (one record per line: figure, row,\n"
	      "                       warning, total) or json (default: from the extension\n"
	      "                       of -o, else the table)\n"
	      "  -o, --output FILE    write to FILE (default: standard output)\n",
	      f);
}

static const struct option plan_longopts[] = {
	{"set", required_argument, NULL, 's'},
	{"models", required_argument, NULL, 'm'},
	{"format", required_argument, NULL, 'f'},
	{"output", required_argument, NULL, 'o'},
	{"help", no_argument, NULL, 'h'},
	{NULL, 0, NULL, 0}};

/* ---- numbers with units, for people ---- */

/* A figure in the unit people read it in: us, kN, mm, MPa, %. */
static char *fig_text(char *buf, size_t n, enum anvil_fig_unit u, double x)
{
	static const struct {
		double scale;
		const char *unit;
	} units[] = {
		[ANVIL_UNIT_NONE] = {1, ""},     [ANVIL_UNIT_FRACTION] = {100, " %"},
		[ANVIL_UNIT_TIME] = {1e6, " us"}, [ANVIL_UNIT_FORCE] = {1e-3, " kN"},
		[ANVIL_UNIT_LENGTH] = {1e3, " mm"}, [ANVIL_UNIT_PRESSURE] = {1e-6, " MPa"},
	};
	if (isnan(x) || isinf(x))
		snprintf(buf, n, "%s", isnan(x) ? "-" : "inf");
	else
		snprintf(buf, n, "%.4g%s", x * units[u].scale, units[u].unit);
	return buf;
}

static char *cost_text(char *buf, size_t n, double s)
{
	if (s < 1e-3)
		snprintf(buf, n, "%.3g us", s * 1e6);
	else if (s < 1)
		snprintf(buf, n, "%.3g ms", s * 1e3);
	else
		snprintf(buf, n, "%.3g s", s);
	return buf;
}

static void fig_list(FILE *f, const struct anvil_plan *pl, const enum anvil_fig *fig, int nfig)
{
	char v[48];
	for (int i = 0; i < nfig; i++) {
		const struct anvil_fig_info *fi = anvil_plan_fig_info(fig[i]);
		fprintf(f, "%s%s = %s", i ? ", " : "      ", fi->name,
			fig_text(v, sizeof v, fi->unit, pl->fig[fig[i]]));
	}
	if (nfig)
		fputc('\n', f);
}

/* ---- the table ---- */

static void print_estimates(FILE *f, const struct anvil_plan *pl)
{
	char v[48];
	fputs("estimates\n", f);
	for (int i = 0; i < ANVIL_FIG_COUNT; i++) {
		const struct anvil_fig_info *fi = anvil_plan_fig_info((enum anvil_fig)i);
		fprintf(f, "  %-12s %-12s %s\n", fi->name, fig_text(v, sizeof v, fi->unit, pl->fig[i]),
			fi->what);
	}
}

static const char *cached_text(enum anvil_cache_where w)
{
	return w == ANVIL_CACHE_MEMORY ? "in memory" : w == ANVIL_CACHE_DISK ? "on disk" : "to compute";
}

/* A row's name: the model, "layer (paper)" for the paper's contact. */
static const char *row_name(enum anvil_model m, const struct anvil_plan_row *r, char *b, size_t n)
{
	snprintf(b, n, "%s%s", anvil_model_name(m), r->contact == ANVIL_CONTACT_PAPER ? " (paper)" : "");
	return b;
}

/* The row's contact in the records and JSON: physical, paper or - */
static const char *row_contact(const struct anvil_plan_row *r)
{
	return r->contact == ANVIL_CONTACT_AUTO ? "-" : anvil_contact_name(r->contact);
}

static void print_row(FILE *f, enum anvil_model m, const struct anvil_plan_row *r,
		      const struct anvil_plan *pl)
{
	char c[32], full[32], e[48], nm[40];
	/* room for "halfspace (paper)" only when there is such a row */
	int w = r->contact == ANVIL_CONTACT_PAPER || pl->contact == ANVIL_CONTACT_BOTH ? 17 : 10;
	row_name(m, r, nm, sizeof nm);
	if (!r->run) {
		fprintf(f, "  %-*s not run: %s\n", w, nm, anvil_plan_why_text(r->off));
		return;
	}
	fprintf(f, "  %-*s %-10s %-18s ~%s", w, nm, anvil_method_name(r->method),
		r->exact ? "exact" : (snprintf(e, sizeof e, "within ~%.2g %%", 100 * r->model_err), e),
		cost_text(c, sizeof c, r->cost));
	if (r->cost_full > 1.5 * r->cost && r->cost > 0) /* a refusal costs 0: no "infx" */
		fprintf(f, "  (%s model: ~%s, %.0fx)", anvil_model_name(m),
			cost_text(full, sizeof full, r->cost_full), r->cost_full / r->cost);
	/* a refused row computes no response: no tag saying it will */
	if (r->method == ANVIL_METHOD_LAYER && m == ANVIL_MODEL_LAYER && r->cost_full > 0 &&
	    r->status >= 0)
		fprintf(f, "  [layer response %s]", cached_text(r->cached));
	fprintf(f, "\n      %s\n", anvil_plan_why_text(r->why));
	fig_list(f, pl, r->fig, r->nfig);
	/* decided here, returned by the solver as it stands, without work */
	if (r->status < 0)
		fprintf(f, "      refused: %s\n", r->refusal[0] ? r->refusal : anvil_strerror(r->status));
	if (r->fallback)
		fprintf(f, "      fallback: the layer, if the computed contact outlasts 2h/c1\n");
}

/* What `anvil run`'s verdict will do (verdict.h's rules): a searched
 * field costs seconds where a quasi-static one costs nothing. */
static void run_verdict_line(FILE *f, const struct anvil_plan *pl)
{
	static const char qs[] = "quasi-static Hertz at the row's computed P_max";
	switch (anvil_verdict_quasi_static(pl)) {
	case ANVIL_VERDICT_QS_LONG:
		fprintf(f, "  anvil run: %s (the contact lasts over %g times 2h/c1)\n", qs,
			ANVIL_VERDICT_QS_RATIO);
		break;
	case ANVIL_VERDICT_QS_GENTLE:
		fprintf(f, "  anvil run: %s (the waves carry off under %g %% of the energy)\n", qs,
			100 * ANVIL_VERDICT_QS_RADIATED);
		break;
	case ANVIL_VERDICT_QS_BLOCK:
		fprintf(f, "  anvil run: %s (the layer bends too little to matter, the waves carry "
			"off under %g %%)\n", qs, 100 * ANVIL_VERDICT_QS_RADIATED_BLOCK);
		break;
	default:
		fputs("  anvil run: searches the transform field around the contact (a plate whose "
		      "bending matters, or a fast impact: it can take seconds)\n", f);
	}
}

/* The one verdict (verdict.h): the layer, then the impactor under the
 * same contact, each on its own line; then how the run will judge. */
static void print_verdict(FILE *f, const struct anvil_plan *pl)
{
	char line[ANVIL_VERDICT_TEXT_MAX];
	const struct anvil_verdict *v = &pl->verdict;
	anvil_verdict_text(v, line, sizeof line);
	fprintf(f, "\nverdict\n  %s\n", line);
	anvil_verdict_impactor_text(v, line, sizeof line);
	fprintf(f, "  %s\n", line);
	unsigned waves = (1u << ANVIL_MODEL_LAYER) | (1u << ANVIL_MODEL_HALFSPACE);
	if (pl->pb.run & waves) /* else the run's verdict is this one (cmd_run.c) */
		run_verdict_line(f, pl);
}

void anvil_plan_print(FILE *f, const struct anvil_plan *pl)
{
	char c[32], full[32];
	double cost_full = 0;
	print_estimates(f, pl);
	fprintf(f, "\nmodels (effects.waves = %s)\n", anvil_waves_name(pl->waves));
	fprintf(f, "  contact: %s (effects.contact)\n", anvil_contact_name(pl->contact));
	for (int m = 0; m < ANVIL_MODEL_COUNT; m++) {
		if (pl->paper[m].run) {
			print_row(f, (enum anvil_model)m, &pl->paper[m], pl);
			cost_full += pl->paper[m].cost_full;
		}
		print_row(f, (enum anvil_model)m, &pl->row[m], pl);
		cost_full += pl->row[m].run ? pl->row[m].cost_full : 0.0;
	}
	fprintf(f, "estimated cost: ~%s (full models: ~%s)\n", cost_text(c, sizeof c, pl->cost),
		cost_text(full, sizeof full, cost_full));
	if (pl->field != ANVIL_FIELDMODE_OFF)
		fprintf(f, "field: %s\n", anvil_fieldmode_name(pl->field));
	if (pl->nwarn)
		fputs("\nwarnings\n", f);
	for (int i = 0; i < pl->nwarn; i++) {
		const struct anvil_plan_warning *w = &pl->warn[i];
		fprintf(f, "  %s\n", anvil_plan_warn_text(w->kind));
		fig_list(f, pl, w->fig, w->nfig);
	}
	print_verdict(f, pl);
}

void anvil_plan_warnings_line(FILE *f, const struct anvil_plan *pl, const char *prefix)
{
	char v[48];
	for (int i = 0; i < pl->nwarn; i++) {
		const struct anvil_plan_warning *w = &pl->warn[i];
		if (w->kind == ANVIL_WARN_FIELD)
			continue; /* what was asked for, not a warning about it */
		fprintf(f, "%s%s", prefix, anvil_plan_warn_text(w->kind));
		for (int k = 0; k < w->nfig; k++) {
			const struct anvil_fig_info *fi = anvil_plan_fig_info(w->fig[k]);
			fprintf(f, "%s%s = %s", k ? ", " : "; ", fi->name,
				fig_text(v, sizeof v, fi->unit, pl->fig[w->fig[k]]));
		}
		fputc('\n', f);
	}
}

/* ---- tsv, csv ---- */

static const char *fate_name(enum anvil_hertz_fate fate, int known)
{
	return fate == ANVIL_HERTZ_YIELDS ? "yields" : fate == ANVIL_HERTZ_CRACKS ? "cracks"
		: known ? "elastic" : "unknown";
}

static const char *const warn_names[ANVIL_WARN_COUNT] = {
	"superseismic", "plate-range", "refuse", "not-exact", "field"};

/* One record per line, SI values: "figure NAME VALUE", "row MODEL RUN
 * METHOD EXACT MODEL_ERR COST COST_FULL CACHED WHY", "warning KIND",
 * "verdict BODY MATERIAL FATE STRESS LIMIT" (BODY layer or impactor, FATE
 * elastic, yields, cracks or unknown, LIMIT 0 when unknown), "total COST"; fields separated by sep (no field holds a tab or a
 * comma but WHY, which CSV quotes). */
static void print_records(FILE *f, const struct anvil_plan *pl, char sep)
{
	char v[40];
	const char *q = sep == ',' ? "\"" : "";
	for (int i = 0; i < ANVIL_FIG_COUNT; i++)
		fprintf(f, "figure%c%s%c%s\n", sep, anvil_plan_fig_info((enum anvil_fig)i)->name, sep,
			out_num(v, pl->fig[i], NULL));
	for (int k = 0; k < 2 * ANVIL_MODEL_COUNT; k++) {
		int m = k / 2;
		const struct anvil_plan_row *r = k % 2 ? &pl->row[m] : &pl->paper[m];
		if (k % 2 == 0 && !r->run)
			continue;
		fprintf(f, "row%c%s%c%d%c%s%c%d%c%.6g%c%.6g%c%.6g%c%s%c%s%s%s%c%s\n", sep,
			anvil_model_name((enum anvil_model)m), sep, r->run, sep,
			anvil_method_name(r->method), sep, r->exact, sep, r->model_err, sep, r->cost,
			sep, r->cost_full, sep, cached_text(r->cached), sep, q,
			anvil_plan_why_text(r->run ? r->why : r->off), q, sep, row_contact(r));
	}
	for (int i = 0; i < pl->nwarn; i++)
		fprintf(f, "warning%c%s\n", sep, warn_names[pl->warn[i].kind]);
	const struct anvil_verdict *vd = &pl->verdict;
	fprintf(f, "verdict%clayer%c%s%c%s%c%.6g%c%.6g\n", sep, sep, vd->material, sep,
		fate_name(vd->fate, vd->known), sep, vd->stress, sep, vd->limit);
	fprintf(f, "verdict%cimpactor%c%s%c%s%c%.6g%c%.6g\n", sep, sep, vd->imp.material, sep,
		fate_name(vd->imp.fate, vd->imp.known), sep, vd->imp.stress, sep, vd->imp.limit);
	fprintf(f, "total%c%.6g\n", sep, pl->cost);
}

/* ---- json ---- */

static void json_num(FILE *f, double x)
{
	char v[40];
	fputs(isfinite(x) ? out_num(v, x, NULL) : "null", f);
}

static const char *const si_unit[] = {
	[ANVIL_UNIT_NONE] = "", [ANVIL_UNIT_FRACTION] = "", [ANVIL_UNIT_TIME] = "s",
	[ANVIL_UNIT_FORCE] = "N", [ANVIL_UNIT_LENGTH] = "m", [ANVIL_UNIT_PRESSURE] = "Pa"};

/* One body's verdict: {"material", "fate", "stress_Pa", "limit_Pa", "text"}. */
static void json_verdict(FILE *f, const char *body, const char *mat, const char *fate,
			 double stress, double limit, const struct anvil_verdict *v)
{
	char line[ANVIL_VERDICT_TEXT_MAX];
	if (body[0] == 'l')
		anvil_verdict_text(v, line, sizeof line);
	else
		anvil_verdict_impactor_text(v, line, sizeof line);
	fprintf(f, "\n    \"%s\": {\"material\": ", body);
	out_json_string(f, mat);
	fprintf(f, ", \"fate\": \"%s\", \"stress_Pa\": ", fate);
	json_num(f, stress);
	fputs(", \"limit_Pa\": ", f);
	json_num(f, limit);
	fputs(", \"text\": ", f);
	out_json_string(f, line);
	fputc('}', f);
}

/* {"title", "figures": [{name, value, unit (SI), what}], "rows": [...],
 * "warnings": [{kind, text}], "verdict": {"layer": {...}, "impactor": {...}},
 * "cost_s"} */
static void print_json(FILE *f, const struct anvil_plan *pl, const char *title)
{
	fputs("{\n  \"title\": ", f);
	out_json_string(f, title);
	fputs(",\n  \"figures\": [", f);
	for (int i = 0; i < ANVIL_FIG_COUNT; i++) {
		const struct anvil_fig_info *fi = anvil_plan_fig_info((enum anvil_fig)i);
		fputs(i ? ",\n    {\"name\": " : "\n    {\"name\": ", f);
		out_json_string(f, fi->name);
		fputs(", \"value\": ", f);
		json_num(f, pl->fig[i]);
		fprintf(f, ", \"unit\": \"%s\", \"what\": ", si_unit[fi->unit]);
		out_json_string(f, fi->what);
		fputc('}', f);
	}
	fputs("\n  ],\n  \"rows\": [", f);
	for (int k = 0, first = 1; k < 2 * ANVIL_MODEL_COUNT; k++) {
		int m = k / 2;
		const struct anvil_plan_row *r = k % 2 ? &pl->row[m] : &pl->paper[m];
		if (k % 2 == 0 && !r->run)
			continue;
		fprintf(f, "%s\n    {\"model\": \"%s\", \"contact\": \"%s\", \"run\": %s, \"method\": \"%s\", "
			"\"exact\": %s, \"model_err\": ", first ? "" : ",", anvil_model_name((enum anvil_model)m), row_contact(r),
			r->run ? "true" : "false",
			anvil_method_name(r->method), r->exact ? "true" : "false");
		first = 0;
		json_num(f, r->model_err);
		fputs(", \"cost_s\": ", f);
		json_num(f, r->cost);
		fputs(", \"cost_full_s\": ", f);
		json_num(f, r->cost_full);
		fprintf(f, ", \"cached\": \"%s\", \"why\": ", cached_text(r->cached));
		out_json_string(f, anvil_plan_why_text(r->run ? r->why : r->off));
		fputc('}', f);
	}
	fputs("\n  ],\n  \"warnings\": [", f);
	for (int i = 0; i < pl->nwarn; i++) {
		fprintf(f, "%s\n    {\"kind\": \"%s\", \"text\": ", i ? "," : "",
			warn_names[pl->warn[i].kind]);
		out_json_string(f, anvil_plan_warn_text(pl->warn[i].kind));
		fputc('}', f);
	}
	fprintf(f, "%s],\n  \"verdict\": {", pl->nwarn ? "\n  " : "");
	json_verdict(f, "layer", pl->verdict.material, fate_name(pl->verdict.fate, pl->verdict.known),
		     pl->verdict.stress, pl->verdict.limit, &pl->verdict);
	fputc(',', f);
	json_verdict(f, "impactor", pl->verdict.imp.material,
		     fate_name(pl->verdict.imp.fate, pl->verdict.imp.known), pl->verdict.imp.stress,
		     pl->verdict.imp.limit, &pl->verdict);
	fputs("},\n  \"cost_s\": ", f);
	json_num(f, pl->cost);
	fputs("\n}\n", f);
}

/* ---- the command ---- */

static int plan_option(struct plan_opts *o, int c, char **argv)
{
	size_t n;
	switch (c) {
	case 's':
		return cli_sets_add(&o->sets, optarg) ? EXIT_FAIL : -1;
	case 'm':
		n = strlen(optarg) + sizeof "solver.models=";
		free(o->models);
		if (!(o->models = malloc(n)))
			return EXIT_FAIL;
		snprintf(o->models, n, "solver.models=%s", optarg);
		return -1;
	case 'f':
		o->format = out_format_parse("plan", optarg, OUT_ALL);
		return o->format < 0 ? EXIT_USAGE : -1;
	case 'o':
		o->out = optarg;
		return -1;
	case 'h':
		plan_usage(stdout);
		return EXIT_OK;
	}
	return out_getopt_error("plan", c, argv);
}

/* -1 to go on, else the exit code. */
static int plan_parse(int argc, char **argv, struct plan_opts *o)
{
	int c, code;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, ":s:m:f:o:h", plan_longopts, NULL)) != -1)
		if ((code = plan_option(o, c, argv)) >= 0)
			return code;
	if (optind < argc)
		o->scene = argv[optind++];
	if (optind < argc)
		return out_usage("plan", "unexpected argument '%s'", argv[optind]);
	o->format = out_format_pick(o->format, o->out);
	if (o->models && cli_sets_add(&o->sets, o->models))
		return EXIT_FAIL;
	return -1;
}

static int plan_scene(const struct plan_opts *o)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err err = {0};
	int st = cli_scene(&sc, o->scene, o->sets.v, o->sets.n);
	if (st)
		return cli_exit_code(st);
	/* a solver only for its cache: the plan says which responses are there */
	struct anvil_solver *s = anvil_solver_alloc();
	if (!s) {
		cli_error("out of memory");
		return EXIT_FAIL;
	}
	st = cli_plan(&sc, anvil_solver_cache(s), &pl, &err);
	anvil_solver_free(s);
	if (st) {
		cli_error("plan: %s", err.msg[0] ? err.msg : anvil_strerror(st));
		return cli_exit_code(st);
	}
	struct cli_out out;
	if (cli_out_open(&out, o->out))
		return EXIT_FAIL;
	if (o->format == OUT_TSV || o->format == OUT_CSV) {
		print_records(out.f, &pl, o->format == OUT_CSV ? ',' : '\t');
	} else if (o->format == OUT_JSON) {
		print_json(out.f, &pl, sc.title);
	} else {
		fprintf(out.f, "%s\n", sc.title[0] ? sc.title : "scene");
		anvil_plan_print(out.f, &pl); /* the verdict at its end (plan.h) */
	}
	return cli_out_commit(&out) ? EXIT_FAIL : EXIT_OK;
}

int anvil_cmd_plan(int argc, char **argv)
{
	struct plan_opts o = {.format = -1};
	int code = plan_parse(argc, argv, &o);
	if (code < 0)
		code = plan_scene(&o);
	cli_sets_free(&o.sets);
	free(o.models);
	return code;
}
