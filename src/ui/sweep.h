/* sweep.h: many scenes from one, run in parallel, written as rows.
 *
 * A sweep is a base scene and axes, each a scene key with a list of values
 * as the user wrote them ("1mm,2mm,5mm"; "0.1..10m/s:25:log"; "steel,glass").
 * Scenes are the cross product of the axes, the last axis varying fastest
 * (as nested loops written in the order given), or with zip the i-th value
 * of every axis.  Every scene gives one row per model it runs.
 *
 * A row carries what joins it back to its scene: its number and the count
 * (row, rows), each axis in the unit the user gave (KEY_UNIT), then the
 * scene in SI (materials, mass, r0, h in m and in r0, V0), the model, the
 * status (0 ok, > 0 a warning such as ANVIL_WTOL: values stand, < 0 a
 * failure: values nan) with its message, and every output with its error.
 * The text of a row depends only on the sweep and the row number, so rows
 * written by any number of threads, shards or resumed runs are the same
 * bytes (responses are looked up exactly: cache.h).
 *
 * Slices: shard K of N (K from 1) is the scenes [(K-1) S / N, K S / N) of
 * the S scenes, contiguous, so that a shard keeps scenes that share a
 * layer response together. */
#ifndef ANVIL_UI_SWEEP_H
#define ANVIL_UI_SWEEP_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

#include "output.h"
#include "result.h"
#include "scene.h"

#define SWEEP_MAXAXIS 8
#define SWEEP_MAXVAL 100000 /* values in one axis, and scenes in a sweep */

struct sweep_axis {
	char key[64];  /* "impact.velocity" */
	int n;         /* values */
	char **val;    /* as anvil_scene_set reads them ("0.1m/s") */
	int numeric;   /* 1: every value is NUMBER[UNIT] with one unit */
	char unit[16]; /* the user's unit ("m/s", "mm", "r0"), "" for none */
	double *num;   /* numeric: the number in unit */
};

struct sweep {
	struct anvil_scene base;
	int naxis, zip;
	struct sweep_axis ax[SWEEP_MAXAXIS];
	size_t nscenes, nrows;
	size_t *row0; /* first row of each scene (0-based), nscenes + 1 entries */
};

/* Parse "KEY=SPEC" into a new axis of sw, checking every value by setting
 * it on sw->base.  ANVIL_EPARSE with a one-line message naming the
 * argument ("impact.velocity=0.1..10m/s:0: a range needs a count of at
 * least 2") in err. */
int sweep_axis_add(struct sweep *sw, const char *arg, struct anvil_err *err);
/* After the axes: count scenes and rows (zip: equal lengths).  ANVIL_EPARSE
 * for mismatched zip lengths or too many scenes; ANVIL_ENOMEM. */
int sweep_layout(struct sweep *sw, struct anvil_err *err);
void sweep_free(struct sweep *sw);

/* Scene s (0-based): the base with each axis's value set, then checked.
 * sc is filled even when the check fails (for the row's identity). */
int sweep_scene(const struct sweep *sw, size_t s, struct anvil_scene *sc, struct anvil_err *err);
/* The scenes [*s0, *s1) of shard k of n (k from 1). */
void sweep_shard(const struct sweep *sw, int k, int n, size_t *s0, size_t *s1);

/* One row of a scene: its model and contact model.  With [effects]
 * contact = both (or auto on the paper's own case) the layer and
 * halfspace models have two rows, the paper's contact first, as anvil run
 * prints them; hertz and zener have contact AUTO (their own). */
struct sweep_rowkey {
	enum anvil_model model; /* ANVIL_MODEL_COUNT: a scene with no model */
	enum anvil_contact contact;
};
#define SWEEP_MAXROWS (2 * ANVIL_MODEL_COUNT)
/* The rows scene sc gives, in order, into k[SWEEP_MAXROWS]: their number,
 * at least 1 (a scene with no model has one row saying so).  A function
 * of the scene alone: the layout, --resume and merge depend on it. */
int sweep_scene_rows(const struct anvil_scene *sc, struct sweep_rowkey *k);

/* The text written for the sweep, per format (TSV, CSV, JSON: the table
 * format is written as TSV).  Each function returns a malloc'd string
 * without its newline, NULL when out of memory. */
char *sweep_header(const struct sweep *sw, enum out_format fmt);
/* Row number row (0-based) of scene sc, row k: res is its result, or
 * NULL when the scene failed before any model ran (then st and why). */
char *sweep_row(const struct sweep *sw, enum out_format fmt, size_t row, const struct anvil_scene *sc,
		const struct sweep_rowkey *k, const struct anvil_result *res, int st, const char *why);
/* The start of that row which says which row it is (number, axes, scene,
 * model, contact): what --resume and merge compare. */
char *sweep_row_id(const struct sweep *sw, enum out_format fmt, size_t row,
		   const struct anvil_scene *sc, const struct sweep_rowkey *k);

/* One scene's outcome, handed to the writer in scene order. */
struct sweep_done {
	size_t scene;
	int st;                   /* the scene's own status (check, plan) */
	char why[ANVIL_ERR_MSG];
	int n;                    /* results, in the order of sweep_scene_rows */
	struct anvil_result r[SWEEP_MAXROWS];
};

/* Run scenes [s0, s1) of sw with nthreads threads (one solver each),
 * skipping those with skip[s - s0] set (may be NULL).  emit is called
 * from the calling thread, in scene order, for every scene run; a
 * non-zero return stops the sweep.  tick (may be NULL) is called from the
 * calling thread about five times a second with the scenes done.  *stop
 * non-zero (a signal) stops at once: the scenes done are emitted, and
 * ANVIL_ECANCEL returns without waiting for the runs under way, whose
 * threads are left to end with the process: the caller must exit soon
 * (and not free sw, nor skip, before; they no longer read them).  Returns
 * ANVIL_OK, ANVIL_ECANCEL (stopped), ANVIL_ENOMEM, or emit's status.
 * st->layer_computed sums what the solvers computed. */
struct sweep_stats {
	unsigned long responses; /* layer responses computed (not from a cache) */
	unsigned long disk_hits, mem_hits;
};
typedef int (*sweep_emit_fn)(void *ctx, const struct sweep_done *d);
typedef void (*sweep_tick_fn)(void *ctx, size_t done);
int sweep_run(const struct sweep *sw, size_t s0, size_t s1, const unsigned char *skip,
	      int nthreads, sweep_emit_fn emit, sweep_tick_fn tick, void *ctx,
	      volatile sig_atomic_t *stop, struct sweep_stats *st);

/* A sweep's file read back (for --resume and merge): the header (TSV,
 * CSV; NULL for JSON) and the rows, one a line (JSON: the objects
 * without their separating commas).  A last line without its newline
 * (the writer was killed) is left out and counted in partial.
 * ANVIL_EIO (cannot read), ANVIL_EPARSE (not a sweep's file: message
 * naming the file and line), ANVIL_ENOMEM; err says which. */
struct sweep_file {
	char *buf;
	char *header;
	char **row;
	size_t nrow;
	int partial;
};
int sweep_file_read(const char *path, enum out_format fmt, struct sweep_file *f, struct anvil_err *err);
void sweep_file_free(struct sweep_file *f);
/* Row number and row count of a row line (its first two cells); 0 when
 * they are not there. */
int sweep_file_rownum(const char *line, enum out_format fmt, size_t *row, size_t *rows);

/* The number of cores online (at least 1). */
int sweep_cores(void);

#endif
