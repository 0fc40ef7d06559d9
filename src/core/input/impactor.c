/* impactor.c: the impactor's geometry and the drop (scene.h): the mass,
 * radius and velocity in use, from what the user gave. */
#include <math.h>
#include <strings.h>

#include "scene.h"
#include "scene_keys.h"
#include "units.h"

static const char *const shape_names[ANVIL_SHAPE_COUNT] = {"rod", "ball"};

const char *anvil_shape_name(enum anvil_shape s)
{
	return (unsigned)s < ANVIL_SHAPE_COUNT ? shape_names[s] : "unknown";
}

int anvil_shape_parse(const char *name)
{
	for (int i = 0; name && i < ANVIL_SHAPE_COUNT; ++i)
		if (strcasecmp(name, shape_names[i]) == 0)
			return i;
	return -1;
}

double anvil_ball_mass(double rho, double D)
{
	return rho * M_PI * D * D * D / 6.0;
}

/* A cylinder of length L - R and a hemisphere of radius R:
 * pi R^2 (L - R) + (2/3) pi R^3 = pi R^2 (L - R/3). */
double anvil_rod_mass(double rho, double R, double L)
{
	return L >= R ? rho * M_PI * R * R * (L - R / 3.0) : NAN;
}

/* Energy: m g H = m V0^2 / 2 (a free fall from rest, no air drag). */
double anvil_drop_velocity(double H)
{
	return sqrt(2.0 * ANVIL_G_STANDARD * H);
}

void anvil_scene_geometry_replace(struct anvil_scene *sc, int sec, const char *key)
{
	if (sec == ANVIL_SEC_IMPACT && strcasecmp(key, "velocity") == 0)
		sc->drop_height = NAN;
	if (sec != ANVIL_SEC_IMPACTOR)
		return;
	if (strcasecmp(key, "radius") == 0)
		sc->diameter = NAN;
	else if (strcasecmp(key, "mass") == 0)
		sc->length = NAN;
	else if (strcasecmp(key, "length") == 0)
		sc->mass_given = 0;
	else if (strcasecmp(key, "shape") == 0) {
		/* a new body: its mass follows it unless the same text (parse
		 * restores mass_given) or a later key gives one */
		sc->mass_given = 0;
		if (sc->shape == ANVIL_SHAPE_BALL)
			sc->length = NAN;
	}
}

int anvil_scene_geometry(struct anvil_scene *sc, struct anvil_err *err)
{
	if (!isnan(sc->diameter))
		sc->radius = 0.5 * sc->diameter;
	if (!isnan(sc->drop_height))
		sc->velocity = anvil_drop_velocity(sc->drop_height);
	if (sc->mass_given)
		return ANVIL_OK;
	double rho = sc->impactor.mat.rho;
	if (sc->shape == ANVIL_SHAPE_BALL) {
		sc->mass = anvil_ball_mass(rho, 2.0 * sc->radius);
	} else if (!isnan(sc->length)) {
		if (!(sc->length >= sc->radius)) {
			char L[40], R[40];
			anvil_units_format(sc->length, ANVIL_DIM_LENGTH, L, sizeof L);
			anvil_units_format(sc->radius, ANVIL_DIM_LENGTH, R, sizeof R);
			return anvil_err_set(err, ANVIL_EPARSE,
					     "impactor.length: %s is shorter than the tip radius %s "
					     "(the length is overall, the hemispherical tip included)",
					     L, R);
		}
		sc->mass = anvil_rod_mass(rho, sc->radius, sc->length);
	}
	return ANVIL_OK;
}
