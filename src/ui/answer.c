/* answer.c: see answer.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "answer.h"
#include "common.h"
#include "units.h"

int answer_eval(struct anvil_solver *s, const struct anvil_scene *base, const char *key,
		const char *value, enum anvil_model m, struct anvil_result *r)
{
	struct anvil_scene sc = *base;
	struct anvil_err err = {0};
	int st = anvil_scene_set(&sc, key, value, "command line", 0, &err);
	if (!st)
		st = anvil_scene_check(&sc, &err);
	if (!st)
		return cli_run_model(s, &sc, m, 0, r, &err);
	anvil_result_init(r, m);
	r->status = st;
	snprintf(r->why, sizeof r->why, "%s", err.msg);
	return st;
}

const char *const answer_qty_name[ANSWER_NQTY] = {"ts", "Rf", "Pmax"};

struct anvil_val answer_value(const struct anvil_result *r, enum answer_qty q)
{
	return q == ANSWER_TS ? r->ts : q == ANSWER_RF ? r->Rf : r->Pmax;
}

/* units.h has no force (no scene key is one): N, kN, MN here. */
static int parse_force(const char *text, double *si, struct anvil_err *err)
{
	static const struct {
		const char *name;
		double scale;
	} unit[] = {{"N", 1}, {"kN", 1e3}, {"MN", 1e6}};
	char *end;
	double x = strtod(text, &end);
	while (*end == ' ')
		end++;
	for (size_t i = 0; end != text && isfinite(x) && i < sizeof unit / sizeof unit[0]; i++)
		if (!strcmp(end, unit[i].name)) {
			*si = x * unit[i].scale;
			return ANVIL_OK;
		}
	return anvil_err_set(err, ANVIL_EPARSE, "Pmax=%s: expected a force such as '1.2 kN' (N, kN, MN)", text);
}

int answer_parse(enum answer_qty q, const char *text, double *si, struct anvil_err *err)
{
	struct anvil_err e = {0};
	int st;
	if (q == ANSWER_PMAX)
		return parse_force(text, si, err);
	st = anvil_units_parse_with_unit(text, q == ANSWER_TS ? ANVIL_DIM_TIME : ANVIL_DIM_NONE, si, &e);
	if (st)
		return anvil_err_set(err, st, "%s=%s: %s", answer_qty_name[q], text, e.msg);
	return ANVIL_OK;
}

void answer_format(enum answer_qty q, double x, char *buf, size_t n)
{
	if (q == ANSWER_TS)
		snprintf(buf, n, "%.4g us", x * 1e6);
	else if (q == ANSWER_PMAX)
		snprintf(buf, n, "%.4g kN", x * 1e-3);
	else
		snprintf(buf, n, "%.4g", x);
}
