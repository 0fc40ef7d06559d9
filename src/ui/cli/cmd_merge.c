/* cmd_merge.c: `anvil merge`, the shards of a sweep joined into the table
 * one unsharded run writes, byte for byte: rows are put back in order by
 * their row number, and every row 1..rows must be there exactly once. */
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "common.h"
#include "output.h"
#include "sweep.h"

static void merge_usage(FILE *f)
{
	fputs("usage: anvil merge FILE... [-o OUT] [-f tsv|csv|json]\n"
	      "Join the shards of one sweep (anvil sweep --shard K/N) into its table,\n"
	      "the same bytes as one unsharded run.  Refused: a row missing or given\n"
	      "twice, shards of different sweeps (headers or row counts differ).\n"
	      "  -o, --output OUT     the table (default: standard output)\n"
	      "  -f, --format FORMAT  the shards' format (default: the extension of the\n"
	      "                       first shard, else TSV); OUT is in the same\n",
	      f);
}

struct merge {
	enum out_format fmt;
	char *header;        /* of the first file (TSV, CSV) */
	size_t rows;         /* the sweep's row count */
	const char **line;   /* by row - 1 */
	const char **from;   /* the file each row came from */
	struct sweep_file *file;
	int nfile;
};

static int merge_rows(struct merge *m, int k, const char *path)
{
	struct sweep_file *f = &m->file[k];
	for (size_t i = 0; i < f->nrow; i++) {
		size_t row, rows;
		if (!sweep_file_rownum(f->row[i], m->fmt, &row, &rows)) {
			cli_error("merge: %s: row %zu: no row number (not a sweep's %s output?)", path, i + 1,
				  m->fmt == OUT_JSON ? "JSON" : m->fmt == OUT_CSV ? "CSV" : "TSV");
			return EXIT_USAGE;
		}
		if (!m->rows && !(m->line = calloc(rows, sizeof *m->line)))
			return EXIT_FAIL;
		if (!m->rows && !(m->from = calloc(rows, sizeof *m->from)))
			return EXIT_FAIL;
		if (!m->rows)
			m->rows = rows;
		if (rows != m->rows) {
			cli_error("merge: %s: row %zu says %zu rows, another shard %zu: shards of "
				  "different sweeps", path, row, rows, m->rows);
			return EXIT_USAGE;
		}
		if (m->line[row - 1]) {
			cli_error("merge: row %zu is in %s and in %s: a shard given twice?", row,
				  m->from[row - 1], path);
			return EXIT_USAGE;
		}
		m->line[row - 1] = f->row[i];
		m->from[row - 1] = path;
	}
	return -1;
}

static int merge_read(struct merge *m, char **paths)
{
	for (int k = 0; k < m->nfile; k++) {
		struct anvil_err err = {0};
		int st = sweep_file_read(paths[k], m->fmt, &m->file[k], &err);
		if (st) {
			cli_error("merge: %s", err.msg);
			return cli_exit_code(st);
		}
		if (m->file[k].partial) {
			cli_error("merge: %s: its last row is cut short (an interrupted shard: run it "
				  "again with --resume)", paths[k]);
			return EXIT_USAGE;
		}
		const char *h = m->file[k].header;
		if (k > 0 && h && strcmp(h, m->file[0].header)) {
			cli_error("merge: %s: its header differs from %s's: shards of different sweeps",
				  paths[k], paths[0]);
			return EXIT_USAGE;
		}
		int code = merge_rows(m, k, paths[k]);
		if (code >= 0)
			return code;
	}
	return -1;
}

/* Every row there: else name the first gap. */
static int merge_check(const struct merge *m)
{
	for (size_t i = 0; i < m->rows; i++) {
		if (m->line[i])
			continue;
		size_t j = i;
		while (j + 1 < m->rows && !m->line[j + 1])
			j++;
		cli_error("merge: rows %zu..%zu of %zu are missing (a shard not given, or one "
			  "interrupted: run it again with --resume)", i + 1, j + 1, m->rows);
		return EXIT_USAGE;
	}
	if (!m->rows) {
		cli_error("merge: no rows in any file");
		return EXIT_USAGE;
	}
	return -1;
}

static int merge_write(const struct merge *m, const char *out)
{
	struct cli_out o;
	if (cli_out_open(&o, out))
		return EXIT_FAIL;
	if (m->fmt == OUT_JSON)
		fputs("[", o.f);
	else
		fprintf(o.f, "%s\n", m->file[0].header);
	for (size_t i = 0; i < m->rows; i++) {
		if (m->fmt == OUT_JSON)
			fprintf(o.f, "%s%s", i ? ",\n" : "\n", m->line[i]);
		else
			fprintf(o.f, "%s\n", m->line[i]);
	}
	if (m->fmt == OUT_JSON)
		fputs("\n]\n", o.f);
	return cli_out_commit(&o) ? EXIT_FAIL : EXIT_OK;
}

static const struct option merge_longopts[] = {{"output", required_argument, NULL, 'o'},
					       {"format", required_argument, NULL, 'f'},
					       {"help", no_argument, NULL, 'h'},
					       {NULL, 0, NULL, 0}};

int anvil_cmd_merge(int argc, char **argv)
{
	const char *out = NULL;
	int c, fmt = -1, code;
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, ":o:f:h", merge_longopts, NULL)) != -1) {
		if (c == 'o') {
			out = optarg;
		} else if (c == 'f') {
			fmt = out_format_parse("merge", optarg, OUT_ALLOW(OUT_TSV) | OUT_ALLOW(OUT_CSV) |
									OUT_ALLOW(OUT_JSON));
			if (fmt < 0)
				return EXIT_USAGE;
		} else if (c == 'h') {
			merge_usage(stdout);
			return EXIT_OK;
		} else {
			return out_getopt_error("merge", c, argv);
		}
	}
	if (optind >= argc)
		return out_usage("merge", "no shard given: anvil merge FILE... -o OUT");
	struct merge m = {.nfile = argc - optind};
	m.fmt = (enum out_format)(fmt >= 0 ? fmt : out_format_of(argv[optind]));
	if ((int)m.fmt <= OUT_TABLE)
		m.fmt = OUT_TSV;
	int ofmt = out_format_of(out);
	if (out && ofmt > OUT_TABLE && ofmt != (int)m.fmt)
		return out_usage("merge", "-o %s: the shards are %s: merge keeps their format", out,
				 m.fmt == OUT_JSON ? "JSON" : m.fmt == OUT_CSV ? "CSV" : "TSV");
	if (!(m.file = calloc((size_t)m.nfile, sizeof *m.file)))
		return EXIT_FAIL;
	code = merge_read(&m, argv + optind);
	if (code < 0)
		code = merge_check(&m);
	if (code < 0)
		code = merge_write(&m, out);
	for (int k = 0; k < m.nfile; k++)
		sweep_file_free(&m.file[k]);
	free(m.file);
	free(m.line);
	free(m.from);
	return code;
}
