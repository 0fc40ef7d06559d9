/* answer.h: one scene varied along one key, for the direct answers
 * (anvil thickness, fit): evaluations through one solver, so that every
 * layer response is made once and kept (cache.h), and a value parsed with
 * the unit of its quantity. */
#ifndef ANVIL_UI_ANSWER_H
#define ANVIL_UI_ANSWER_H

#include "result.h"
#include "scene.h"
#include "solver.h"

/* base with key set to value (text with its unit), planned and run for
 * model m into r (initialised either way; free with anvil_result_free).
 * Returns r->status (a scene or plan error too, its message in r->why). */
int answer_eval(struct anvil_solver *s, const struct anvil_scene *base, const char *key,
		const char *value, enum anvil_model m, struct anvil_result *r);

/* The quantities an answer is about. */
enum answer_qty { ANSWER_TS, ANSWER_RF, ANSWER_PMAX, ANSWER_NQTY };
extern const char *const answer_qty_name[ANSWER_NQTY]; /* "ts", "Rf", "Pmax" */
/* r's value and error of q, SI. */
struct anvil_val answer_value(const struct anvil_result *r, enum answer_qty q);
/* "62us", "0.8", "1.2kN" (ts a time, Rf bare, Pmax a force: N, kN, MN)
 * into SI; ANVIL_EPARSE with a message naming text in err. */
int answer_parse(enum answer_qty q, const char *text, double *si, struct anvil_err *err);
/* x (SI) of q for people: "62.0 us", "0.800", "1.20 kN". */
void answer_format(enum answer_qty q, double x, char *buf, size_t n);

#endif
