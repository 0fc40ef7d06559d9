/* units.c: "NUMBER [UNIT]" text to SI, one table of units per dimension. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "units.h"

/* SI per unit is 10^exp10 * factor.  Powers of ten go into the decimal
 * exponent before strtod, so that "12.2 g" is the double nearest 0.0122,
 * as "0.0122 kg" is: multiplying by 1e-3 would miss it by an ulp. */
struct unit {
	const char *name;
	int exp10;
	double factor;
	int parse_only; /* read, never chosen to print (cm/s, mm/s: 0.99 m/s stays so) */
};

/* "\xc2\xb5" is U+00B5 MICRO SIGN, "\xce\xbc" U+03BC GREEK SMALL LETTER MU:
 * both are typed for "micro", so both are accepted, as is ASCII "u". */
static const struct unit none_units[] = {{NULL, 0, 0, 0}};
static const struct unit mass_units[] = {
	{"kg", 0, 1, 0}, {"g", -3, 1, 0}, {"mg", -6, 1, 0}, {NULL, 0, 0, 0}};
static const struct unit length_units[] = {
	{"m", 0, 1, 0}, {"cm", -2, 1, 0}, {"mm", -3, 1, 0}, {"um", -6, 1, 0},
	{"\xc2\xb5m", -6, 1, 0}, {"\xce\xbcm", -6, 1, 0}, {NULL, 0, 0, 0}};
static const struct unit velocity_units[] = {
	{"m/s", 0, 1, 0}, {"km/s", 3, 1, 0}, {"mm/us", 3, 1, 0}, {"mm/\xc2\xb5s", 3, 1, 0},
	{"mm/\xce\xbcs", 3, 1, 0}, {"km/h", 0, 1.0 / 3.6, 0},
	{"cm/s", -2, 1, 1}, {"mm/s", -3, 1, 1}, {NULL, 0, 0, 0}};
static const struct unit pressure_units[] = {
	{"Pa", 0, 1, 0}, {"kPa", 3, 1, 0}, {"MPa", 6, 1, 0}, {"GPa", 9, 1, 0}, {NULL, 0, 0, 0}};
static const struct unit density_units[] = {
	{"kg/m^3", 0, 1, 0}, {"kg/m3", 0, 1, 0}, {"g/cm^3", 3, 1, 0}, {"g/cm3", 3, 1, 0},
	{NULL, 0, 0, 0}};
static const struct unit time_units[] = {
	{"s", 0, 1, 0}, {"ms", -3, 1, 0}, {"us", -6, 1, 0}, {"\xc2\xb5s", -6, 1, 0},
	{"\xce\xbcs", -6, 1, 0}, {"ns", -9, 1, 0}, {NULL, 0, 0, 0}};

struct dim_info {
	const char *noun;    /* "a mass" */
	const char *plural;  /* "masses" */
	const char *unit;    /* "g": the unit of the example */
	const char *example; /* "12.2 g" */
	const char *si;      /* "kg" */
	const struct unit *units;
};

/* Indexed by enum anvil_dim. */
static const struct dim_info dims[] = {
	{"a number", "numbers", "", "0.3", "", none_units},
	{"a mass", "masses", "g", "12.2 g", "kg", mass_units},
	{"a length", "lengths", "mm", "4 mm", "m", length_units},
	{"a velocity", "velocities", "m/s", "10 m/s", "m/s", velocity_units},
	{"a pressure", "pressures", "GPa", "200 GPa", "Pa", pressure_units},
	{"a density", "densities", "g/cm3", "7.8 g/cm3", "kg/m^3", density_units},
	{"a time", "times", "us", "0.16 us", "s", time_units},
};
#define NDIMS ((int)(sizeof dims / sizeof dims[0]))

const char *anvil_units_si_name(enum anvil_dim dim)
{
	if ((int)dim < 0 || (int)dim >= NDIMS)
		return "";
	return dims[dim].si;
}

static const struct unit *unit_find(const struct unit *u, const char *s, size_t n)
{
	for (; u->name; ++u)
		if (strlen(u->name) == n && memcmp(u->name, s, n) == 0)
			return u;
	return NULL;
}

/* Which other dimension a unit belongs to, for the message; -1 if none. */
static int unit_dim(const char *s, size_t n)
{
	for (int d = 0; d < NDIMS; ++d)
		if (unit_find(dims[d].units, s, n))
			return d;
	return -1;
}

static int ascii_only(const char *s)
{
	for (; *s; ++s)
		if ((unsigned char)*s >= 0x80)
			return 0;
	return 1;
}

/* The ASCII spellings of a dimension's units, "kg, g, mg". */
static void unit_list(const struct unit *u, char *buf, size_t size)
{
	size_t len = 0;
	buf[0] = '\0';
	for (; u->name && len < size; ++u) {
		if (!ascii_only(u->name))
			continue;
		int k = snprintf(buf + len, size - len, "%s%s", len ? ", " : "",
				 u->name);
		if (k < 0)
			break;
		len += (size_t)k;
	}
}

/* Read the number at the start of text[0..n): a plain decimal (strtod would
 * also take "nan", "inf" and hex), finite.  NULL when there is none. */
static const char *read_number(const char *text, size_t n, double *v)
{
	char *end;
	const char *s = text + (*text == '+' || *text == '-');
	if (!(isdigit((unsigned char)*s) || (*s == '.' && isdigit((unsigned char)s[1]))))
		return NULL;
	errno = 0;
	*v = strtod(text, &end);
	size_t len = (size_t)(end - text);
	if (end == text || len > n || memchr(text, 'x', len) || memchr(text, 'X', len) ||
	    !isfinite(*v) || (errno == ERANGE && fabs(*v) > 1.0))
		return NULL;
	return end;
}

/* num[0..len), which strtod read as v, times 10^exp10, correctly rounded:
 * the decimal exponent is shifted and the text read again. */
static double scale10(const char *num, size_t len, int exp10, double v)
{
	char buf[128];
	if (exp10 == 0)
		return v;
	const char *e = memchr(num, 'e', len);
	if (!e)
		e = memchr(num, 'E', len);
	size_t mlen = e ? (size_t)(e - num) : len;
	long x = e ? strtol(e + 1, NULL, 10) : 0;
	if (mlen + 32 > sizeof buf || x > 100000 || x < -100000)
		return v * pow(10.0, exp10);
	snprintf(buf, sizeof buf, "%.*se%ld", (int)mlen, num, x + exp10);
	return strtod(buf, NULL);
}

static int unit_error(const struct dim_info *d, const char *u, size_t un,
		      struct anvil_err *err)
{
	int other = unit_dim(u, un);
	if (other >= 0)
		return anvil_err_set(err, ANVIL_EPARSE, "expected %s such as '%s', got '%.*s' (%s)",
				     d->noun, d->example, (int)un, u, dims[other].noun);
	char list[96];
	unit_list(d->units, list, sizeof list);
	return anvil_err_set(err, ANVIL_EPARSE, "expected %s such as '%s', got '%.*s'%s%s%s",
			     d->noun, d->example, (int)un, u,
			     list[0] ? " (units: " : " (no unit)", list, list[0] ? ")" : "");
}

int anvil_units_parse(const char *text, enum anvil_dim dim, double *si,
		      struct anvil_err *err)
{
	if ((int)dim < 0 || (int)dim >= NDIMS)
		return anvil_err_set(err, ANVIL_EINVAL, "unknown dimension %d", (int)dim);
	const struct dim_info *d = &dims[dim];
	if (!text)
		text = "";
	while (isspace((unsigned char)*text))
		++text;
	size_t n = strlen(text);
	while (n > 0 && isspace((unsigned char)text[n - 1]))
		--n;

	double v = 0;
	const char *end = read_number(text, n, &v), *u = end;
	if (!end) {
		/* a number beyond a double ('1e999 m/s') is out of range, not
		 * something other than a number */
		char *e;
		errno = 0;
		double t = strtod(text, &e);
		if (e != text && (size_t)(e - text) <= n && isinf(t))
			return anvil_err_set(err, ANVIL_EPARSE, "expected %s such as '%s', got '%.*s' (out of range)",
					     d->noun, d->example, (int)n, text);
		return anvil_err_set(err, ANVIL_EPARSE, "expected %s such as '%s', got '%.*s'",
				     d->noun, d->example, (int)n, text);
	}
	while ((size_t)(u - text) < n && isspace((unsigned char)*u))
		++u;
	size_t un = n - (size_t)(u - text);
	if (un > 0) {
		const struct unit *found = unit_find(d->units, u, un);
		if (!found)
			return unit_error(d, u, un, err);
		v = scale10(text, (size_t)(end - text), found->exp10, v) * found->factor;
	}
	if (!isfinite(v))
		return anvil_err_set(err, ANVIL_EPARSE, "'%.*s' is out of range", (int)n, text);
	*si = v;
	return ANVIL_OK;
}

int anvil_units_parse_with_unit(const char *text, enum anvil_dim dim, double *si,
				struct anvil_err *err)
{
	double v;
	int st = anvil_units_parse(text, dim, &v, err);
	if (st || dim == ANVIL_DIM_NONE)
		goto done;
	/* It parsed: is there anything after the number? */
	while (isspace((unsigned char)*text))
		++text;
	size_t n = strlen(text);
	while (n > 0 && isspace((unsigned char)text[n - 1]))
		--n;
	char *end;
	strtod(text, &end);
	if ((size_t)(end - text) >= n) {
		char list[96];
		unit_list(dims[dim].units, list, sizeof list);
		return anvil_err_set(err, ANVIL_EPARSE, "'%.*s' needs a unit, e.g. %.*s %s (%s: %s)",
				     (int)n, text, (int)n, text, dims[dim].unit, dims[dim].plural,
				     list);
	}
done:
	if (!st)
		*si = v;
	return st;
}

/* The unit among dims[] (factor 1, so not km/h; ASCII names) whose number
 * is nearest 10^1.5 on a log scale (ties to the larger unit): any number in [1, 1000) is nearer than
 * one outside, so that one is taken when there is one. */
void anvil_units_format(double si, enum anvil_dim dim, char *buf, size_t n)
{
	const struct unit *best = NULL;
	double best_d = 0;
	if ((int)dim < 0 || (int)dim >= NDIMS || !isfinite(si) || si == 0 ||
	    dim == ANVIL_DIM_NONE) {
		snprintf(buf, n, "%.3g%s%s", si, dim == ANVIL_DIM_NONE ? "" : " ",
			 anvil_units_si_name(dim));
		return;
	}
	for (const struct unit *u = dims[dim].units; u->name; ++u) {
		if (u->factor != 1 || u->parse_only || !ascii_only(u->name))
			continue;
		/* 1.4999: 1 MPa rather than 1000 kPa */
		double d = fabs(log10(fabs(si)) - u->exp10 - 1.4999);
		if (!best || d < best_d) {
			best = u;
			best_d = d;
		}
	}
	snprintf(buf, n, "%.3g %s", si / pow(10.0, best->exp10), best->name);
}
