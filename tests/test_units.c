/* test_units: "NUMBER [UNIT]" to SI, good inputs and every kind of bad one. */
#include <math.h>
#include <string.h>

#include "tap.h"
#include "units.h"

static const struct {
	const char *text;
	enum anvil_dim dim;
	double si;
} good[] = {
	{"12.2 g", ANVIL_DIM_MASS, 12.2e-3},
	{"1e-3 kg", ANVIL_DIM_MASS, 1e-3},
	{"0.5 mg", ANVIL_DIM_MASS, 0.5e-6},
	{"0.0122", ANVIL_DIM_MASS, 0.0122},
	{"4mm", ANVIL_DIM_LENGTH, 4e-3},
	{"  4 mm  ", ANVIL_DIM_LENGTH, 4e-3},
	{"2 cm", ANVIL_DIM_LENGTH, 2e-2},
	{"3 m", ANVIL_DIM_LENGTH, 3},
	{"50 um", ANVIL_DIM_LENGTH, 50e-6},
	{"50 \xc2\xb5m", ANVIL_DIM_LENGTH, 50e-6},
	{"50 \xce\xbcm", ANVIL_DIM_LENGTH, 50e-6},
	{"10 m/s", ANVIL_DIM_VELOCITY, 10},
	{"1.5 km/s", ANVIL_DIM_VELOCITY, 1500},
	{"2 mm/us", ANVIL_DIM_VELOCITY, 2000},
	{"36 km/h", ANVIL_DIM_VELOCITY, 10},
	{"200 GPa", ANVIL_DIM_PRESSURE, 200e9},
	{"57 MPa", ANVIL_DIM_PRESSURE, 57e6},
	{"3 kPa", ANVIL_DIM_PRESSURE, 3e3},
	{"1e5 Pa", ANVIL_DIM_PRESSURE, 1e5},
	{"7.8 g/cm3", ANVIL_DIM_DENSITY, 7800},
	{"7.8 g/cm^3", ANVIL_DIM_DENSITY, 7800},
	{"7830 kg/m3", ANVIL_DIM_DENSITY, 7830},
	{"7830 kg/m^3", ANVIL_DIM_DENSITY, 7830},
	{"0.16 us", ANVIL_DIM_TIME, 0.16e-6},
	{"0.16 \xc2\xb5s", ANVIL_DIM_TIME, 0.16e-6},
	{"0.16 \xce\xbcs", ANVIL_DIM_TIME, 0.16e-6},
	{"2 ms", ANVIL_DIM_TIME, 2e-3},
	{"5 ns", ANVIL_DIM_TIME, 5e-9},
	{"1 s", ANVIL_DIM_TIME, 1},
	{"0.3", ANVIL_DIM_NONE, 0.3},
	{"-0.5", ANVIL_DIM_NONE, -0.5},
	{"+.25", ANVIL_DIM_NONE, 0.25},
	{"0", ANVIL_DIM_MASS, 0},
	{" 7 ", ANVIL_DIM_NONE, 7},
	{"7\t", ANVIL_DIM_LENGTH, 7},
};

static const struct {
	const char *text;
	enum anvil_dim dim;
	const char *msg; /* expected substring */
} bad[] = {
	{"abc", ANVIL_DIM_LENGTH, "expected a length such as '4 mm', got 'abc'"},
	{"", ANVIL_DIM_MASS, "expected a mass such as '12.2 g', got ''"},
	{"   ", ANVIL_DIM_MASS, "got ''"},
	{"4 mm", ANVIL_DIM_MASS, "expected a mass such as '12.2 g', got 'mm' (a length)"},
	{"10 m/s", ANVIL_DIM_TIME, "expected a time such as '0.16 us', got 'm/s' (a velocity)"},
	{"200 GPa", ANVIL_DIM_DENSITY, "got 'GPa' (a pressure)"},
	{"7.8 g/cm3", ANVIL_DIM_PRESSURE, "expected a pressure such as '200 GPa'"},
	{"1 kg", ANVIL_DIM_NONE, "expected a number such as '0.3', got 'kg' (a mass)"},
	{"12 furlongs", ANVIL_DIM_LENGTH, "got 'furlongs' (units: m, cm, mm, um)"},
	{"12 g extra", ANVIL_DIM_MASS, "got 'g extra'"},
	{"12 gg", ANVIL_DIM_MASS, "got 'gg'"},
	{"12 GPA", ANVIL_DIM_PRESSURE, "got 'GPA'"},
	{"0.3 x", ANVIL_DIM_NONE, "(no unit)"},
	{"nan", ANVIL_DIM_NONE, "got 'nan'"},
	{"NaN g", ANVIL_DIM_MASS, "got 'NaN g'"},
	{"inf", ANVIL_DIM_LENGTH, "got 'inf'"},
	{"-infinity m", ANVIL_DIM_LENGTH, "got '-infinity m'"},
	{"1e999 m", ANVIL_DIM_LENGTH, "got '1e999 m'"},
	{"1e308 GPa", ANVIL_DIM_PRESSURE, "out of range"},
	{"0x10 m", ANVIL_DIM_LENGTH, "got '0x10 m'"},
	{"mm", ANVIL_DIM_LENGTH, "got 'mm'"},
	{". m", ANVIL_DIM_LENGTH, "got '. m'"},
	{"1e m", ANVIL_DIM_LENGTH, "got 'e m'"},
	{"1,5 m", ANVIL_DIM_LENGTH, "got ',5 m'"},
};

int main(void)
{
	struct anvil_err err;
	double v;

	for (size_t i = 0; i < sizeof good / sizeof good[0]; ++i) {
		v = NAN;
		int st = anvil_units_parse(good[i].text, good[i].dim, &v, &err);
		ok(st == ANVIL_OK, "'%s' parses", good[i].text);
		is_rel(v, good[i].si, 1e-15, "'%s' = %g %s", good[i].text, good[i].si,
		       anvil_units_si_name(good[i].dim));
	}
	/* Prefixes are exact decimal shifts: "12.2 g" is the double 0.0122. */
	static const struct {
		const char *a, *b;
		enum anvil_dim dim;
	} same[] = {
		{"12.2 g", "0.0122", ANVIL_DIM_MASS},  {"4 mm", "0.004", ANVIL_DIM_LENGTH},
		{"0.16 us", "1.6e-7", ANVIL_DIM_TIME}, {"7.8 g/cm3", "7800", ANVIL_DIM_DENSITY},
		{"1.1 MPa", "1.1e6", ANVIL_DIM_PRESSURE}, {"0.7 um", "7e-7", ANVIL_DIM_LENGTH},
		{"1.5e-2 mm", "1.5e-5", ANVIL_DIM_LENGTH}, {"3E2 GPa", "3e11", ANVIL_DIM_PRESSURE},
		{"0.1 mg", "1e-7", ANVIL_DIM_MASS},
	};
	for (size_t i = 0; i < sizeof same / sizeof same[0]; ++i) {
		double a = 1, b = 2;
		anvil_units_parse(same[i].a, same[i].dim, &a, NULL);
		anvil_units_parse(same[i].b, same[i].dim, &b, NULL);
		ok(a == b, "'%s' is exactly '%s' (%.17g)", same[i].a, same[i].b, a);
	}
	/* SI text reads back bit for bit: the scene writer relies on it. */
	v = 0;
	anvil_units_parse("0.012200000000000001 kg", ANVIL_DIM_MASS, &v, NULL);
	ok(v == 0.0122, "SI with 17 digits is exact");

	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
		v = 42;
		anvil_err_clear(&err);
		int st = anvil_units_parse(bad[i].text, bad[i].dim, &v, &err);
		ok(st == ANVIL_EPARSE && err.status == ANVIL_EPARSE && v == 42,
		   "'%s' is rejected with ANVIL_EPARSE, value untouched", bad[i].text);
		if (!ok(strstr(err.msg, bad[i].msg) != NULL, "message for '%s' says \"%s\"",
			bad[i].text, bad[i].msg))
			diag("  got: %s", err.msg);
	}
	ok(anvil_units_parse(NULL, ANVIL_DIM_MASS, &v, NULL) == ANVIL_EPARSE,
	   "NULL text is an error, NULL err is fine");
	ok(anvil_units_parse("1", (enum anvil_dim)99, &v, &err) == ANVIL_EINVAL,
	   "unknown dimension is ANVIL_EINVAL");

	static const struct {
		enum anvil_dim dim;
		const char *name;
	} si[] = {{ANVIL_DIM_NONE, ""},          {ANVIL_DIM_MASS, "kg"},
		  {ANVIL_DIM_LENGTH, "m"},       {ANVIL_DIM_VELOCITY, "m/s"},
		  {ANVIL_DIM_PRESSURE, "Pa"},    {ANVIL_DIM_DENSITY, "kg/m^3"},
		  {ANVIL_DIM_TIME, "s"},         {(enum anvil_dim)99, ""}};
	for (size_t i = 0; i < sizeof si / sizeof si[0]; ++i)
		ok(strcmp(anvil_units_si_name(si[i].dim), si[i].name) == 0,
		   "SI name of dimension %d is '%s'", (int)si[i].dim, si[i].name);
	/* Every SI name is itself accepted as a unit of its dimension. */
	for (int d = ANVIL_DIM_MASS; d <= ANVIL_DIM_TIME; ++d) {
		char text[32];
		snprintf(text, sizeof text, "2 %s", anvil_units_si_name((enum anvil_dim)d));
		ok(anvil_units_parse(text, (enum anvil_dim)d, &v, NULL) == ANVIL_OK && v == 2,
		   "'%s' reads as 2 SI", text);
	}

	/* The unit rule of scene files, -s and the TUI. */
	static const struct {
		const char *text;
		enum anvil_dim dim;
		const char *msg; /* NULL: accepted */
		double si;
	} rule[] = {
		{"4", ANVIL_DIM_LENGTH, "'4' needs a unit, e.g. 4 mm (lengths: m, cm, mm, um)", 0},
		{" 12.5 ", ANVIL_DIM_MASS, "'12.5' needs a unit, e.g. 12.5 g (masses: kg, g, mg)", 0},
		{"10", ANVIL_DIM_VELOCITY, "'10' needs a unit, e.g. 10 m/s (velocities: m/s, km/s", 0},
		{"200e9", ANVIL_DIM_PRESSURE, "'200e9' needs a unit, e.g. 200e9 GPa", 0},
		{"7830", ANVIL_DIM_DENSITY, "'7830' needs a unit, e.g. 7830 g/cm3", 0},
		{"1e-7", ANVIL_DIM_TIME, "'1e-7' needs a unit, e.g. 1e-7 us", 0},
		{"4 x", ANVIL_DIM_LENGTH, "expected a length such as '4 mm', got 'x'", 0},
		{"4 mm", ANVIL_DIM_LENGTH, NULL, 4e-3},
		{"0.3", ANVIL_DIM_NONE, NULL, 0.3},
	};
	for (size_t i = 0; i < sizeof rule / sizeof rule[0]; ++i) {
		v = -1;
		anvil_err_clear(&err);
		int st = anvil_units_parse_with_unit(rule[i].text, rule[i].dim, &v, &err);
		if (rule[i].msg)
			ok(st == ANVIL_EPARSE && v == -1 && strstr(err.msg, rule[i].msg),
			   "with unit: '%s' refused: %s", rule[i].text, err.msg);
		else
			ok(st == ANVIL_OK && v == rule[i].si, "with unit: '%s' is %g", rule[i].text,
			   rule[i].si);
	}

	/* Readable quantities for titles and warnings. */
	static const struct {
		double si;
		enum anvil_dim dim;
		const char *text;
	} fmt[] = {
		{0.05, ANVIL_DIM_MASS, "50 g"},        {12.2e-3, ANVIL_DIM_MASS, "12.2 g"},
		{2000, ANVIL_DIM_MASS, "2e+03 kg"},    {1e-9, ANVIL_DIM_MASS, "0.001 mg"},
		{4e-3, ANVIL_DIM_LENGTH, "4 mm"},      {0.5, ANVIL_DIM_LENGTH, "50 cm"},
		{10, ANVIL_DIM_VELOCITY, "10 m/s"},    {6000, ANVIL_DIM_VELOCITY, "6 km/s"},
		{1e6, ANVIL_DIM_PRESSURE, "1 MPa"},    {209e9, ANVIL_DIM_PRESSURE, "209 GPa"},
		{7830, ANVIL_DIM_DENSITY, "7.83 g/cm^3"}, {0.16e-6, ANVIL_DIM_TIME, "160 ns"},
		{0.3, ANVIL_DIM_NONE, "0.3"},          {INFINITY, ANVIL_DIM_LENGTH, "inf m"},
	};
	for (size_t i = 0; i < sizeof fmt / sizeof fmt[0]; ++i) {
		char buf[40];
		anvil_units_format(fmt[i].si, fmt[i].dim, buf, sizeof buf);
		ok(strcmp(buf, fmt[i].text) == 0, "format %g: '%s' (want '%s')", fmt[i].si, buf,
		   fmt[i].text);
	}
	plan(tap_n);
	return done_testing();
}
