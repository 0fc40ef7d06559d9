/* cmd_sweep.c: `anvil sweep`, many scenes as rows (sweep.h), on every
 * core, in slices for a cluster, resumable after an interruption. */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "commands.h"
#include "common.h"
#include "output.h"
#include "sweep.h"

struct sweep_opts {
	const char *scene, *out;
	char *models;
	int format, zip, jobs, shard_k, shard_n, resume, quiet, verbose;
	struct cli_sets sets;
	char **axes;
	int naxes;
};

static void sweep_usage(FILE *f)
{
	fprintf(f, "usage: anvil sweep [SCENE] KEY=SPEC... [-s KEY=VALUE]... [-o FILE] [-f FORMAT]\n"
	      "                   [--zip] [-j N] [--shard K/N] [--resume] [-m MODELS] [-q] [-v]\n"
	      "Run every scene of a sweep: one row per scene and model, with the values\n"
	      "that vary (in your units), the scene, the status and every output with\n"
	      "its error.  SPEC is a list (1mm,2mm,5mm or steel,glass) or a range\n"
	      "A..B[UNIT]:COUNT[:lin|log] (0.1..10m/s:25:log).\n"
	      "  -s, --set KEY=VALUE  a fixed scene key\n"
	      "      --zip            pair the lists (value i of every axis) instead of\n"
	      "                       their cross product\n"
	      "  -o, --output FILE    the rows (default: standard output)\n"
	      "  -f, --format FORMAT  tsv, csv or json (default: from the extension of -o,\n"
	      "                       else TSV)\n"
	      "  -j, --jobs N         scenes run in parallel (default: the cores, here %d)\n"
	      "      --shard K/N      only the K-th of N slices (K from 1); join with merge\n"
	      "      --resume         keep the rows already in FILE and run the rest\n"
	      "  -m, --models LIST    models to run (as -s solver.models=)\n"
	      "  -q, --quiet          no progress bar or summary\n"
	      "  -v, --verbose        the count of responses computed, on stderr\n",
	      sweep_cores());
}

static const struct option sweep_longopts[] = {
	{"set", required_argument, NULL, 's'},     {"output", required_argument, NULL, 'o'},
	{"format", required_argument, NULL, 'f'},  {"zip", no_argument, NULL, 'z'},
	{"jobs", required_argument, NULL, 'j'},    {"shard", required_argument, NULL, 'S'},
	{"resume", no_argument, NULL, 'R'},        {"models", required_argument, NULL, 'm'},
	{"quiet", no_argument, NULL, 'q'},         {"verbose", no_argument, NULL, 'v'},
	{"help", no_argument, NULL, 'h'},          {NULL, 0, NULL, 0}};

/* "K/N" with 1 <= K <= N. */
static int parse_shard(struct sweep_opts *o, const char *s)
{
	char *end;
	long k = strtol(s, &end, 10), n = 0;
	if (end != s && *end == '/') {
		const char *p = end + 1;
		n = strtol(p, &end, 10);
		if (end == p)
			n = 0;
	}
	if (*end || n < 1 || n > 100000 || k < 0 || k > n)
		return out_usage("sweep", "--shard %s: expected K/N with 1 <= K <= N, e.g. --shard 3/8", s);
	if (k == 0)
		return out_usage("sweep", "--shard %s: shards count from 1 (Slurm: --array=1-%ld, "
				 "or $((SLURM_ARRAY_TASK_ID + 1)) with --array=0-%ld)", s, n, n - 1);
	o->shard_k = (int)k;
	o->shard_n = (int)n;
	return -1;
}

static int sweep_option(struct sweep_opts *o, int c, char **argv)
{
	char *end;
	switch (c) {
	case 's':
		return cli_sets_add(&o->sets, optarg) ? EXIT_FAIL : -1;
	case 'o':
		o->out = optarg;
		return -1;
	case 'f':
		o->format = out_format_parse("sweep", optarg, OUT_ALLOW(OUT_TSV) | OUT_ALLOW(OUT_CSV) |
								   OUT_ALLOW(OUT_JSON));
		return o->format < 0 ? EXIT_USAGE : -1;
	case 'z':
		o->zip = 1;
		return -1;
	case 'j':
		o->jobs = (int)strtol(optarg, &end, 10);
		if (end == optarg || *end || o->jobs < 1 || o->jobs > 256)
			return out_usage("sweep", "--jobs %s: expected a number from 1 to 256", optarg);
		return -1;
	case 'S':
		return parse_shard(o, optarg);
	case 'R':
		o->resume = 1;
		return -1;
	case 'm':
		free(o->models);
		if (!(o->models = malloc(strlen(optarg) + 16)))
			return EXIT_FAIL;
		sprintf(o->models, "solver.models=%s", optarg);
		return -1;
	case 'q':
		o->quiet = 1;
		return -1;
	case 'v':
		o->verbose = 1;
		return -1;
	case 'h':
		sweep_usage(stdout);
		return EXIT_OK;
	}
	return out_getopt_error("sweep", c, argv);
}

static int sweep_parse(int argc, char **argv, struct sweep_opts *o)
{
	int c, code;
	opterr = 0;
	optind = 1;
	/* '-' first: positional arguments in order, so KEY=SPEC may follow options */
	while ((c = getopt_long(argc, argv, "-:s:o:f:j:m:qvh", sweep_longopts, NULL)) != -1) {
		if (c == 1) {
			if (strchr(optarg, '='))
				o->axes[o->naxes++] = optarg;
			else if (!o->scene)
				o->scene = optarg;
			else
				return out_usage("sweep", "'%s': one scene file only (axes are KEY=SPEC)", optarg);
			continue;
		}
		if ((code = sweep_option(o, c, argv)) >= 0)
			return code;
	}
	if (!o->naxes)
		return out_usage("sweep", "nothing to sweep: give KEY=SPEC, e.g. impact.velocity=1..10m/s:10");
	if (o->resume && (!o->out || !strcmp(o->out, "-")))
		return out_usage("sweep", "--resume needs -o FILE (the file to continue)");
	if (!o->jobs)
		o->jobs = sweep_cores();
	o->format = o->format >= 0 ? o->format : out_format_of(o->out);
	if (o->format <= OUT_TABLE)
		o->format = OUT_TSV; /* rows stream: no aligned table */
	if (o->models && cli_sets_add(&o->sets, o->models))
		return EXIT_FAIL;
	return -1;
}

/* ---- signals: stop cleanly, keep the rows made ---- */

static volatile sig_atomic_t sweep_signal;

static void on_stop(int sig)
{
	sweep_signal = sig;
}

static void stop_install(struct sigaction *old)
{
	static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
	for (int i = 0; i < 3; i++) {
		struct sigaction sa;
		sigaction(sigs[i], NULL, &old[i]);
		if (old[i].sa_handler == SIG_IGN)
			continue;
		memset(&sa, 0, sizeof sa);
		sa.sa_handler = on_stop;
		sigaction(sigs[i], &sa, NULL);
	}
}

static void stop_restore(const struct sigaction *old)
{
	static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
	for (int i = 0; i < 3; i++)
		sigaction(sigs[i], &old[i], NULL);
}

/* ---- writing ---- */

struct writer {
	const struct sweep *sw;
	const struct sweep_opts *o;
	struct cli_out out;
	size_t rows, first;  /* rows written, and whether one is (JSON commas) */
	size_t scenes, total; /* for the progress bar */
	size_t failed, warned;
	double start;
	int shown;
	int werrno; /* errno of the write that failed (said after the runs) */
};

static int put_line(struct writer *w, const char *s)
{
	if (w->o->format == OUT_JSON)
		fputs(w->first++ ? ",\n" : "\n", w->out.f);
	fputs(s, w->out.f);
	if (w->o->format != OUT_JSON)
		fputc('\n', w->out.f);
	w->rows++;
	if (!ferror(w->out.f))
		return ANVIL_OK;
	w->werrno = errno;
	return ANVIL_EIO;
}

static int emit_row(struct writer *w, size_t row, const struct anvil_scene *sc, const struct sweep_rowkey *k,
		    const struct anvil_result *r, int st, const char *why)
{
	char *s = sweep_row(w->sw, (enum out_format)w->o->format, row, sc, k, r, st, why);
	if (!s)
		return ANVIL_ENOMEM;
	int code = r ? r->status : st;
	w->failed += code < 0;
	w->warned += code > 0;
	st = put_line(w, s);
	free(s);
	return st;
}

static int emit(void *ctx, const struct sweep_done *d)
{
	struct writer *w = ctx;
	struct anvil_scene sc;
	size_t row = w->sw->row0[d->scene];
	int st = ANVIL_OK;
	struct sweep_rowkey k[SWEEP_MAXROWS];
	sweep_scene(w->sw, d->scene, &sc, NULL);
	int nk = sweep_scene_rows(&sc, k);
	/* the results come in the order of k (sweep_run) */
	for (int i = 0; i < nk && !st; i++)
		st = d->st || i >= d->n ? emit_row(w, row++, &sc, &k[i], NULL, d->st, d->why)
					: emit_row(w, row++, &sc, &k[i], &d->r[i], 0, NULL);
	/* on disk as it completes: an interruption keeps it */
	if (!st && fflush(w->out.f) != 0) {
		w->werrno = errno;
		st = ANVIL_EIO;
	}
	w->scenes++;
	return st;
}

static void fmt_time(char *buf, size_t n, double s)
{
	if (!isfinite(s) || s < 0)
		snprintf(buf, n, "--:--");
	else if (s < 3600)
		snprintf(buf, n, "%02d:%02d", (int)s / 60, (int)s % 60);
	else
		snprintf(buf, n, "%dh%02d", (int)s / 3600, (int)s % 3600 / 60);
}

/* "sweep [#####.....] 12/48 scenes  3.1/s  00:12 left", on a terminal. */
static void tick(void *ctx, size_t done)
{
	struct writer *w = ctx;
	double t = cli_now() - w->start;
	if (w->o->quiet || !isatty(STDERR_FILENO) || t < 0.5)
		return;
	char bar[21], left[16];
	size_t n = w->total ? done * 20 / w->total : 20;
	for (size_t i = 0; i < 20; i++)
		bar[i] = i < n ? '#' : '.';
	bar[20] = '\0';
	double rate = done / t;
	fmt_time(left, sizeof left, rate > 0 ? (double)(w->total - done) / rate : NAN);
	fprintf(stderr, "\r\033[Ksweep [%s] %zu/%zu scenes  %.3g/s  %s left", bar, done, w->total, rate, left);
	fflush(stderr);
	w->shown = 1;
}

/* ---- --resume ---- */

/* Keep the rows of whole scenes already in the file; mark them in skip.
 * Returns an exit code, or -1 to go on. */
static int resume_read(struct writer *w, size_t s0, size_t s1, unsigned char *skip, struct sweep_file *f)
{
	struct anvil_err err = {0};
	enum out_format fmt = (enum out_format)w->o->format;
	int st = sweep_file_read(w->o->out, fmt, f, &err);
	if (st == ANVIL_ENOTFOUND)
		return -1; /* nothing yet: a fresh start */
	if (st) {
		cli_error("sweep: --resume: %s", err.msg);
		return cli_exit_code(st);
	}
	char *head = sweep_header(w->sw, fmt);
	if (!head)
		return EXIT_FAIL;
	if (f->header && strcmp(head, f->header)) {
		free(head);
		cli_error("sweep: --resume: %s: its header is not this sweep's (other axes or "
			  "format?): not resumed", w->o->out);
		return EXIT_USAGE;
	}
	free(head);
	size_t r = 0, s = s0;
	for (; s < s1; s++) {
		size_t need = w->sw->row0[s + 1] - w->sw->row0[s];
		if (f->nrow - r < need)
			break;
		struct anvil_scene sc;
		struct sweep_rowkey k[SWEEP_MAXROWS];
		sweep_scene(w->sw, s, &sc, NULL);
		sweep_scene_rows(&sc, k); /* need of them (sweep_layout) */
		for (size_t i = 0; i < need; i++) {
			char *id = sweep_row_id(w->sw, fmt, w->sw->row0[s] + i, &sc, &k[i]);
			int same = id && !strncmp(f->row[r + i], id, strlen(id));
			free(id);
			if (!same) {
				cli_error("sweep: --resume: %s: row %zu is not this sweep's row %zu "
					  "(another sweep or shard?): not resumed", w->o->out, r + i + 1,
					  w->sw->row0[s] + i + 1);
				return EXIT_USAGE;
			}
		}
		r += need;
		skip[s - s0] = 1;
	}
	if (r < f->nrow && s == s1) {
		cli_error("sweep: --resume: %s: more rows than this sweep has: not resumed", w->o->out);
		return EXIT_USAGE;
	}
	f->nrow = r; /* rows of a scene cut short are made again */
	return -1;
}

/* ---- the command ---- */

static int sweep_build(struct sweep *sw, const struct sweep_opts *o)
{
	struct anvil_err err = {0};
	int st = cli_scene_q(&sw->base, o->scene, o->sets.v, o->sets.n, o->quiet);
	if (st)
		return cli_exit_code(st);
	sw->zip = o->zip;
	for (int i = 0; i < o->naxes && !st; i++)
		st = sweep_axis_add(sw, o->axes[i], &err);
	if (!st)
		st = sweep_layout(sw, &err);
	if (st) {
		fprintf(stderr, "anvil sweep: %s\n", err.msg);
		return cli_exit_code(st);
	}
	return -1;
}

static void summary(const struct writer *w, const struct sweep_stats *ss, double secs)
{
	if (w->shown)
		fputs("\r\033[K", stderr);
	if (w->failed || w->warned)
		cli_error("sweep: %zu row%s failed, %zu with warnings (status and message columns)",
			  w->failed, w->failed == 1 ? "" : "s", w->warned);
	if (w->o->verbose)
		fprintf(stderr, "anvil: sweep: %zu scenes, %zu rows in %.2f s with %d jobs; "
			"%lu layer responses computed, %lu from memory, %lu from disk\n",
			w->scenes, w->rows, secs, w->o->jobs, ss->responses, ss->mem_hits, ss->disk_hits);
}

static int sweep_go(struct sweep *sw, const struct sweep_opts *o)
{
	struct writer w = {.sw = sw, .o = o};
	struct sweep_file old = {0};
	struct sweep_stats ss = {0};
	size_t s0 = 0, s1 = sw->nscenes;
	int code = -1, st;
	if (o->shard_n)
		sweep_shard(sw, o->shard_k, o->shard_n, &s0, &s1);
	unsigned char *skip = calloc(s1 - s0 + 1, 1);
	if (!skip)
		return EXIT_FAIL;
	if (o->resume)
		code = resume_read(&w, s0, s1, skip, &old);
	if (code < 0 && cli_out_open(&w.out, o->out))
		code = EXIT_FAIL;
	if (code >= 0) {
		sweep_file_free(&old);
		free(skip);
		return code;
	}
	char *head = sweep_header(sw, (enum out_format)o->format);
	st = head ? ANVIL_OK : ANVIL_ENOMEM;
	if (head)
		fprintf(w.out.f, "%s%s", head, o->format == OUT_JSON ? "" : "\n");
	free(head);
	for (size_t i = 0; i < old.nrow && !st; i++)
		st = put_line(&w, old.row[i]);
	for (size_t i = 0; i < s1 - s0; i++)
		w.total += !skip[i];
	sweep_file_free(&old);
	struct sigaction saved[3];
	sweep_signal = 0;
	stop_install(saved);
	w.start = cli_now();
	if (!st)
		st = sweep_run(sw, s0, s1, skip, o->jobs, emit, tick, &w, &sweep_signal, &ss);
	stop_restore(saved);
	free(skip);
	if (o->format == OUT_JSON)
		fputs("\n]\n", w.out.f);
	if (st == ANVIL_ECANCEL || !st) {
		int cst = cli_out_commit(&w.out);
		if (!o->quiet || st)
			summary(&w, &ss, cli_now() - w.start);
		if (st) {
			cli_error("sweep: interrupted: %zu of %zu rows in %s; continue with --resume",
				  w.rows, sw->row0[s1] - sw->row0[s0], o->out ? o->out : "standard output");
			return 128 + (int)sweep_signal;
		}
		return cst ? EXIT_FAIL : w.failed ? EXIT_FAIL : EXIT_OK;
	}
	if (st == ANVIL_EIO) { /* qa7: was "sweep: write failed", no file, no reason */
		errno = w.werrno ? w.werrno : errno;
		cli_write_failed(o->out);
	}
	else
		cli_error("sweep: %s", anvil_strerror(st));
	cli_out_abort(&w.out);
	return EXIT_FAIL;
}

int anvil_cmd_sweep(int argc, char **argv)
{
	struct sweep_opts o = {.format = -1};
	struct sweep sw = {0};
	int code;
	if (!(o.axes = calloc((size_t)argc + 1, sizeof *o.axes)))
		return EXIT_FAIL;
	code = sweep_parse(argc, argv, &o);
	if (code < 0)
		code = sweep_build(&sw, &o);
	if (code < 0)
		code = sweep_go(&sw, &o);
	sweep_free(&sw);
	cli_sets_free(&o.sets);
	free(o.models);
	free(o.axes);
	return code;
}
