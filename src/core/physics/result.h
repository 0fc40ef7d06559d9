/* result.h: what one model computes for one impact.
 *
 * Sign conventions: P >= 0 is the contact force; v is the impactor velocity,
 * positive towards the layer (v(0) = V0 > 0, negative on rebound); W, w and
 * alpha_H are positive into the layer.  V_s is the rebound speed -v(t_s) > 0,
 * R_f = V_s / V0, E_a = m1 (V0^2 - V_s^2) / 2. */
#ifndef ANVIL_RESULT_H
#define ANVIL_RESULT_H

#include <stddef.h>

#include "options.h"
#include "status.h"
#include "value.h"

struct anvil_history {
	size_t n;      /* number of samples, 0 when none */
	double *t;     /* s */
	double *P;     /* contact force, N */
	double *v;     /* impactor velocity, m/s */
	double *W;     /* impactor displacement, m */
	double *w;     /* layer deflection under the impactor, m */
	double *alpha; /* Hertz compression alpha_H = W - w, m */
};

/* Levels of the peak's plateau a result keeps (Pmax_plat). */
#define ANVIL_PLATEAU_LEVELS 48

/* Contacts whose times a result keeps (more are counted, not timed). */
#define ANVIL_MAX_CONTACTS 16

struct anvil_result {
	enum anvil_model model;
	enum anvil_contact contact; /* a wave row's contact model (options.h); AUTO: neither */
	/* Each with its estimated absolute error (err NaN when not estimated). */
	struct anvil_val ts, tmax; /* contact time, time of peak force, s */
	struct anvil_val Pmax;     /* peak force, N */
	struct anvil_val Vs, Rf, Ea; /* rebound speed m/s, restitution, absorbed energy J */
	double lambda_star, Rf_star; /* Zener's parameter for this scene */
	/* The model's own error in the estimates, relative (what the physical
	 * contact's remainder leaves out, solver_phys.c; the reflections a row
	 * leaves out; 0: none): no finer accuracy level lowers it (solver.c) */
	double model_err;
	/* |P''| at the peak, N/s^2 (a wave run's, from the finer pass's
	 * parabola through the largest sample; 0 when not known): how far an
	 * error in P(t) can move t_max (solver.c) */
	double Pmax_curv;
	/* The plateau around the peak, s: Pmax_plat[j] is how far from t_max
	 * the march's nodes come within P_max 2^-j of the peak (the finer
	 * pass's, impact_plateau; 0 when not known): where P + e can peak
	 * when |e| stays below P_max 2^-(j+1) (solver.c) */
	double Pmax_plat[ANVIL_PLATEAU_LEVELS];
	/* Repeated contacts (impact.h): how many (1 for a single impact, 0
	 * when not computed), the start and end of the first
	 * ANVIL_MAX_CONTACTS, s.  t_s is the end of the last; V_s, R_f, E_a
	 * are from the final velocity, after the last. */
	size_t ncontacts;
	double contact_on[ANVIL_MAX_CONTACTS], contact_off[ANVIL_MAX_CONTACTS];
	double t_free;       /* s: the free motion after the last contact was followed to here */
	/* The rest state (impact.h, rest_tol): > 0 when the impactor came to
	 * rest on the plate at t_s, the contact not ended: R_f is then only
	 * known to lie in [0, rest_bound] (R_f = rest_bound/2 +- rest_bound/2);
	 * 0 otherwise. */
	double rest_bound;
	/* The part of ts.err a flat end adds (impact_end.c, impact_graze_ts:
	 * how long the approach stays within its error of 0 before t_s), s;
	 * the solver adds it to ts.err once its refinements are decided
	 * (solver_graze), as no finer band lowers it.  0: none. */
	double ts_graze;
	/* How far the layer's motion reaches during the contact (a finite
	 * layer's layer and zener rows; NaN otherwise), m: the P wave's front
	 * c1 t_s, and the bending's spread 2 sqrt(beta t_s) (anvil_result_reach).
	 * The model's layer is unbounded: a plate narrower than twice these, or
	 * supported within them, answers otherwise. */
	double reach_p, reach_bend;
	double seconds;      /* wall time spent on this model */
	char note[512];      /* what the model left out, or "" */
	/* How the run ended: ANVIL_OK; a warning (> 0, e.g. ANVIL_WTOL: the
	 * values and error estimates stand, the target was missed); a failure
	 * (< 0: no usable values).  why says it in words ("" for ANVIL_OK). */
	int status;
	char why[ANVIL_ERR_MSG];
	struct anvil_history hist; /* owned; free with anvil_result_free */
};

/* Zero r, set every error estimate to NaN and the model. */
void anvil_result_init(struct anvil_result *r, enum anvil_model model);
/* Set r->reach_p and r->reach_bend for a layer of thickness h (m, finite),
 * Young's modulus E, Poisson's ratio nu, density rho and P-wave speed c1,
 * from r->ts.  The bending: a Kirchhoff plate's centre impulse spreads as
 * w(r, t) ~ pi/2 - Si(r^2 / (4 beta t)), beta = sqrt(D/(rho h)) =
 * h sqrt(E / (12 rho (1 - nu^2))), so by t it has moved the plate out to
 * about r = 2 sqrt(beta t) (the argument 1).  NaN without a contact time. */
void anvil_result_reach(struct anvil_result *r, double h, double E, double nu, double rho, double c1);
/* The sample times of a history.  Evenly spaced over [0, t_s] when the
 * force peaks at t_pk >= t_s / ANVIL_HISTORY_WARP_AT; a longer contact (a
 * thin plate's milliseconds after a peak in tens of microseconds) spends
 * even samples on its rise and tail: 400 of them left 2 before the peak
 * of a 227 g ball on 3.2 mm glass (37 us of 8.4 ms) and none before that
 * of a 500 g hammer on 1 mm sheet (35 us of 92 ms).  Then
 * t_i = t_s sinh(beta u) / sinh(beta), u = i / (n - 1): near 0 as even as
 * n / ANVIL_HISTORY_RISE samples per t_pk, geometric in the tail.
 * anvil_history_warp gives beta (0: even) from t_pk and t_s alone, so
 * that a history of k (n - 1) + 1 samples holds the one of n at every
 * k-th. */
#define ANVIL_HISTORY_WARP_AT 20.0
#define ANVIL_HISTORY_RISE 8.0
double anvil_history_warp(double t_pk, double ts);
/* Sample i of n over [0, ts] with beta from anvil_history_warp (t_{n-1} =
 * ts exactly). */
double anvil_history_time(size_t i, size_t n, double ts, double beta);
/* Linear interpolation of samples y at the history's times (any
 * spacing), 0 outside [t_0, t_{n-1}]. */
double anvil_history_at(const struct anvil_history *h, const double *y, double t);
/* Allocate n samples for the history (all six arrays); ANVIL_ENOMEM. */
int anvil_history_alloc(struct anvil_history *h, size_t n);
/* Free the history; the result itself is the caller's. NULL is a no-op. */
void anvil_result_free(struct anvil_result *r);

#endif
