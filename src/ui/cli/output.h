/* output.h: how the command-line front end prints what it computed.
 *
 * Four formats: an aligned table for people, and TSV, CSV and JSON for
 * programs.  Machine formats print numbers with full precision (%.10g),
 * NaN as "nan" (JSON: null) and infinity as "inf" (JSON: null); the table
 * rounds sensibly and shows an unknown value as "-".
 *
 * The cmd_*.c files stay thin: they parse options, run the solver and hand
 * the numbers to the functions here.  Nothing here runs a model. */
#ifndef ANVIL_UI_OUTPUT_H
#define ANVIL_UI_OUTPUT_H

#include <stdio.h>

#include "result.h"
#include "scene.h"

enum out_format { OUT_TABLE, OUT_TSV, OUT_CSV, OUT_JSON };
#define OUT_ALLOW(f) (1u << (f))

/* The format called name, if allowed (a mask of OUT_ALLOW bits); else
 * prints "anvil CMD: --format: ..." listing the allowed ones and returns
 * -1. */
int out_format_parse(const char *cmd, const char *name, unsigned allowed);

/* "anvil CMD: MESSAGE (see 'anvil CMD --help')" on stderr; returns the
 * usage exit code (2) so that callers can `return out_usage(...)`. */
int out_usage(const char *cmd, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* The message for what getopt_long (run with opterr = 0 and an optstring
 * starting with ':') reported as c; returns 2. */
int out_getopt_error(const char *cmd, int c, char **argv);

/* A number for a machine format (%.10g, "nan", "inf", "-inf"), or for the
 * table with the printf format fmt ("-" for NaN, "inf" for infinity).
 * Returns buf, which must hold 40 bytes. */
char *out_num(char *buf, double x, const char *fmt);

/* A grid of text cells, printed as an aligned table or as TSV/CSV.  The
 * first row is the header.  Cells are filled left to right, ncol to a
 * row.  A memory failure is remembered and reported by out_grid_print. */
struct out_grid;
struct out_grid *out_grid_alloc(int ncol);
void out_grid_free(struct out_grid *g); /* NULL is a no-op */
/* Left-align column col in the table format (numbers are right-aligned). */
void out_grid_left(struct out_grid *g, int col);
void out_grid_cell(struct out_grid *g, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* Print as OUT_TABLE, OUT_TSV or OUT_CSV.  ANVIL_ENOMEM if a cell could
 * not be stored, ANVIL_EIO on a write error, else ANVIL_OK. */
int out_grid_print(const struct out_grid *g, enum out_format fmt, FILE *f);

/* The results of `anvil run`: one row per result, columns
 *   model h_r0 V0 ts_us tmax_us Pmax_kN Vs Rf Ea_J lambda_star Rf_star
 *   ts_err_us tmax_err_us Pmax_err_kN Rf_err Ea_err_J seconds
 * (the table shows errors as a "±" column beside each value, and the
 * models' notes and the scene's title below it; JSON wraps the rows with a
 * summary of the scene).  Returns ANVIL_OK, ANVIL_ENOMEM or ANVIL_EIO. */
int out_results(FILE *f, enum out_format fmt, const struct anvil_scene *sc,
		const struct anvil_result *res, int n);

/* The histories of every result that has one, as TSV with columns
 *   model t_us P_kN v_m_s W_um w_um alphaH_um
 * Returns ANVIL_OK or ANVIL_EIO. */
int out_history(FILE *f, const struct anvil_result *res, int n);

/* h/r0 of result r in scene sc: infinity for the half-space model. */
double out_h_r0(const struct anvil_scene *sc, const struct anvil_result *r);

#endif
