/* cmd_dem.c: `anvil dem`, restitution against impact velocity as a plain
 * table for a DEM code (velocity, R_f, contact time; a header; SI).  A
 * velocity sweep of one model (sweep.h), so the layer response is made
 * once for the whole table where the velocities share its window. */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "common.h"
#include "output.h"
#include "sweep.h"

#define DEM_NCOL 8

struct dem {
	const char *scene, *out, *velocities;
	int format, jobs;
	enum anvil_model model;
	struct cli_sets sets;
	struct out_grid *g;
	const struct sweep *sw;
	size_t rows, failed;
};

static void dem_usage(FILE *f)
{
	fputs("usage: anvil dem [SCENE] --velocities SPEC [-m MODEL] [-s KEY=VALUE]...\n"
	      "                 [-o FILE] [-f csv|tsv|json] [-j N]\n"
	      "A restitution table for a DEM code: one row per velocity with\n"
	      "  velocity_m_s, restitution, contact_time_s, their errors (SI), status,\n"
	      "  contact (the contact model: physical, paper; - for hertz and zener)\n"
	      "  and message.\n"
	      "  --velocities SPEC  a list (0.5m/s,1m/s) or a range (0.1..10m/s:25:log)\n"
	      "  -m, --model M      the model (default: layer)\n"
	      "  -o, --output FILE  the table (default: standard output; CSV unless the\n"
	      "                     extension or -f says otherwise)\n"
	      "The contact model is the scene's [effects] contact (auto: physical away\n"
	      "from the paper's own case; both is refused: one model per table).\n"
	      "A velocity whose run fails keeps its row: nan values, status < 0 and\n"
	      "the reason in message (also on stderr); the others go on; exit 1.\n"
	      "Load the rows with status >= 0 (0: met the accuracy, 1: best values).\n",
	      f);
}

/* A row's contact model: PHYSICAL or PAPER for layer and halfspace, "-"
 * for hertz and zener, which have their own (as anvil run's column). */
static const char *dem_contact(const struct anvil_result *r)
{
	return r && (r->contact == ANVIL_CONTACT_PHYSICAL || r->contact == ANVIL_CONTACT_PAPER)
		       ? anvil_contact_name(r->contact)
		       : "-";
}

/* One row per velocity; a failed run's row keeps its place with nan
 * values, its status and why (the others go on; the exit status is 1). */
static int dem_emit(void *ctx, const struct sweep_done *d)
{
	struct dem *o = ctx;
	struct anvil_scene sc;
	char a[40];
	const struct anvil_result *r = d->n ? &d->r[0] : NULL;
	int failed = !r || r->status < 0;
	sweep_scene(o->sw, d->scene, &sc, NULL);
	if (failed) {
		cli_error("dem: V0 = %g m/s: no values: %s", sc.velocity, r ? r->why : d->why);
		o->failed++;
	}
	double v[5] = {sc.velocity, NAN, NAN, NAN, NAN};
	if (!failed) {
		v[1] = r->Rf.val;
		v[2] = r->ts.val;
		v[3] = r->Rf.err;
		v[4] = r->ts.err;
	}
	for (int i = 0; i < 5; i++)
		out_grid_cell(o->g, "%s", out_num(a, v[i], NULL));
	out_grid_cell(o->g, "%d", r ? r->status : d->st);
	out_grid_cell(o->g, "%s", dem_contact(r));
	out_grid_cell(o->g, "%s", r ? r->why : d->why);
	o->rows++;
	return ANVIL_OK;
}

static const struct option dem_longopts[] = {
	{"set", required_argument, NULL, 's'},        {"velocities", required_argument, NULL, 'V'},
	{"model", required_argument, NULL, 'm'},      {"output", required_argument, NULL, 'o'},
	{"format", required_argument, NULL, 'f'},     {"jobs", required_argument, NULL, 'j'},
	{"help", no_argument, NULL, 'h'},             {NULL, 0, NULL, 0}};

static int dem_option(struct dem *o, int c, char **argv)
{
	int m;
	char *end;
	switch (c) {
	case 's':
		return cli_sets_add(&o->sets, optarg) ? EXIT_FAIL : -1;
	case 'V':
		o->velocities = optarg;
		return -1;
	case 'm':
		if ((m = anvil_model_parse(optarg)) < 0)
			return out_usage("dem", "--model %s: one of hertz, zener, layer, halfspace", optarg);
		o->model = (enum anvil_model)m;
		return -1;
	case 'o':
		o->out = optarg;
		return -1;
	case 'f':
		o->format = out_format_parse("dem", optarg, OUT_ALLOW(OUT_TSV) | OUT_ALLOW(OUT_CSV) |
								 OUT_ALLOW(OUT_JSON));
		return o->format < 0 ? EXIT_USAGE : -1;
	case 'j':
		o->jobs = (int)strtol(optarg, &end, 10);
		if (end == optarg || *end || o->jobs < 1 || o->jobs > 256)
			return out_usage("dem", "--jobs %s: expected a number from 1 to 256", optarg);
		return -1;
	case 'h':
		dem_usage(stdout);
		return EXIT_OK;
	}
	return out_getopt_error("dem", c, argv);
}

static int dem_parse(struct dem *o, int argc, char **argv)
{
	int c, code;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, ":s:m:o:f:j:h", dem_longopts, NULL)) != -1)
		if ((code = dem_option(o, c, argv)) >= 0)
			return code;
	if (optind < argc)
		o->scene = argv[optind++];
	if (optind < argc)
		return out_usage("dem", "unexpected argument '%s'", argv[optind]);
	if (!o->velocities)
		return out_usage("dem", "--velocities SPEC is needed, e.g. --velocities 0.1..10m/s:25:log");
	o->format = o->format >= 0 ? o->format : out_format_of(o->out);
	if (o->format <= OUT_TABLE)
		o->format = OUT_CSV;
	return -1;
}

static int dem_go(struct dem *o)
{
	struct sweep sw = {0};
	struct anvil_err err = {0};
	char axis[512], models[64];
	struct cli_out out;
	int code = EXIT_OK;
	snprintf(models, sizeof models, "solver.models=%s", anvil_model_name(o->model));
	if (cli_sets_add(&o->sets, models))
		return EXIT_FAIL;
	int st = cli_scene(&sw.base, o->scene, o->sets.v, o->sets.n);
	if (st)
		return cli_exit_code(st);
	if (sw.base.effects.contact == ANVIL_CONTACT_BOTH)
		return out_usage("dem", "effects.contact = both: a DEM table has one contact model; "
			       "give -s effects.contact=physical or paper");
	snprintf(axis, sizeof axis, "impact.velocity=%s", o->velocities);
	if ((st = sweep_axis_add(&sw, axis, &err)) || (st = sweep_layout(&sw, &err))) {
		fprintf(stderr, "anvil dem: --velocities %s\n", err.msg + strlen("impact.velocity="));
		sweep_free(&sw);
		return cli_exit_code(st);
	}
	o->sw = &sw;
	static const char *const head[DEM_NCOL] = {"velocity_m_s", "restitution", "contact_time_s",
						   "restitution_err", "contact_time_err_s", "status",
						   "contact", "message"};
	if (!(o->g = out_grid_alloc(DEM_NCOL))) {
		sweep_free(&sw);
		return EXIT_FAIL;
	}
	out_grid_text(o->g, DEM_NCOL - 2);
	out_grid_text(o->g, DEM_NCOL - 1);
	for (int i = 0; i < DEM_NCOL; i++)
		out_grid_cell(o->g, "%s", head[i]);
	st = sweep_run(&sw, 0, sw.nscenes, NULL, o->jobs ? o->jobs : sweep_cores(), dem_emit, NULL, o,
		       NULL, NULL);
	if (st || cli_out_open(&out, o->out)) {
		code = EXIT_FAIL;
	} else if (out_grid_print(o->g, (enum out_format)o->format, out.f)) {
		cli_out_abort(&out);
		code = EXIT_FAIL;
	} else {
		code = cli_out_commit(&out) ? EXIT_FAIL : o->failed ? EXIT_FAIL : EXIT_OK;
	}
	out_grid_free(o->g);
	sweep_free(&sw);
	return code;
}

int anvil_cmd_dem(int argc, char **argv)
{
	struct dem o = {.format = -1, .model = ANVIL_MODEL_LAYER};
	int code = dem_parse(&o, argc, argv);
	if (code < 0)
		code = dem_go(&o);
	cli_sets_free(&o.sets);
	return code;
}
