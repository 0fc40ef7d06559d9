/* output.h: how the command-line front end prints what it computed.
 *
 * Four formats: an aligned table for people, and TSV, CSV and JSON for
 * programs.  Machine formats print numbers to 13 digits (OUT_NUM_FMT),
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
#define OUT_ALL 0xfu

/* Machine names say their unit: NAME_UNIT, the number being in UNIT, with
 * '/' written '_' (Vs_m_s, rho_kg_m3); dimensionless quantities have no
 * suffix (h_r0, Rf, nu, lambda_star).  TSV, CSV and JSON use the same
 * names. */

/* Relative size below which an error estimate is rounding noise: doubles
 * carry 1.1e-16, and the longest chains of operations (quadratures of
 * ~1e4 terms) accumulate at most ~1e4 of those. */
#define OUT_ERR_NOISE 1e-12
/* Machine formats' number: 13 significant digits, so that the printing's
 * rounding (at most 5e-13 of the value, below the smallest estimate shown,
 * OUT_ERR_NOISE's) never exceeds a value's own estimate (10 digits did:
 * E_a 752.0464687 +- 1.5e-8 J). */
#define OUT_NUM_FMT "%.13g"

/* The format asked for by the extension of path: .tsv, .csv, .json (any
 * case), .txt or none (and NULL, "-") the table; -1 for another. */
int out_format_of(const char *path);
/* -f when given (>= 0), else the extension of the output (another
 * extension: the table). */
int out_format_pick(int given, const char *path);

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

/* A number for a machine format (OUT_NUM_FMT, "nan", "inf", "-inf"), or for the
 * table with the printf format fmt ("-" for NaN, "inf" for infinity).
 * Returns buf, which must hold 40 bytes. */
char *out_num(char *buf, double x, const char *fmt);
/* The same for an error estimate: the table shows an exact 0 as "0" (an
 * estimate at the rounding level, see OUT_ERR_NOISE), not "0.0e+00". */
char *out_err(char *buf, double x, const char *fmt);

/* A grid of text cells, printed as an aligned table or as TSV/CSV.  The
 * first row is the header.  Cells are filled left to right, ncol to a
 * row.  A memory failure is remembered and reported by out_grid_print. */
struct out_grid;
struct out_grid *out_grid_alloc(int ncol);
void out_grid_free(struct out_grid *g); /* NULL is a no-op */
/* Left-align column col in the table format (numbers are right-aligned). */
void out_grid_left(struct out_grid *g, int col);
/* Column col holds text: left-aligned, and a JSON string even when it
 * reads as a number. */
void out_grid_text(struct out_grid *g, int col);
void out_grid_cell(struct out_grid *g, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* Print as OUT_TABLE, OUT_TSV, OUT_CSV or OUT_JSON (an array of objects
 * keyed by the header: numbers as numbers, nan/inf/"-" as null).  ANVIL_ENOMEM if a cell could
 * not be stored, ANVIL_EIO on a write error, else ANVIL_OK. */
int out_grid_print(const struct out_grid *g, enum out_format fmt, FILE *f);
/* Only the JSON array, without a newline, its rows indented by indent:
 * for a caller that wraps it in an object. */
int out_grid_json(const struct out_grid *g, FILE *f, const char *indent);


/* s as a JSON string: quotes, backslashes and control characters escaped
 * (the text is taken to be UTF-8). */
void out_json_string(FILE *f, const char *s);

/* The results of `anvil run`: one row per result, columns
 *   model h_r0 V0_m_s ts_us tmax_us Pmax_kN Vs_m_s Rf Ea_J lambda_star
 *   Rf_star ts_err_us tmax_err_us Pmax_err_kN Rf_err Ea_err_J time_s
 * (lambda_star and Rf_star on the zener row only; errors below
 * OUT_ERR_NOISE relative as 0)
 * (the table shows errors as a "±" column beside each value, and the
 * models' notes and the scene's title below it; JSON wraps the rows with a
 * summary of the scene).  Returns ANVIL_OK, ANVIL_ENOMEM or ANVIL_EIO. */
/* A length in m as "12.3 mm" below 1 m, else "1.23 m"; a duration in s
 * as "46.93 us" below 10 ms, else "16.45 ms".  Return buf. */
const char *out_length(char *buf, size_t n, double m);
const char *out_duration(char *buf, size_t n, double s);
/* The row whose reach (result.h) the output reports: the layer's, else
 * Zener's; NULL when none has one. */
const struct anvil_result *out_reach_row(const struct anvil_result *res, int n);
int out_results(FILE *f, enum out_format fmt, const struct anvil_scene *sc,
		const struct anvil_result *res, int n);

/* The histories of every result that has one, as TSV with columns
 *   model t_us P_kN v_m_s W_impactor_um w_layer_um alphaH_um
 * Returns ANVIL_OK or ANVIL_EIO. */
int out_history(FILE *f, const struct anvil_result *res, int n);

/* h/r0 of result r in scene sc: infinity for the half-space model. */
double out_h_r0(const struct anvil_scene *sc, const struct anvil_result *r);

#endif
