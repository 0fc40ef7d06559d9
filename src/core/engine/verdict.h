/* verdict.h: will the layer fail under the contact?  One verdict, which
 * `anvil plan`, `anvil run`, `anvil field` and the TUI all take from here.
 *
 * The criterion is the layer material's: a ductile layer yields when the
 * peak von Mises stress exceeds its yield stress Y; a brittle one
 * (material.h: glass, cemented carbide) cracks when the tensile radial
 * stress at the contact edge, (1 - 2 nu) p0 / 3 under Hertz (Johnson 1985
 * eq. 3.41), exceeds its tensile strength.  The stresses are those of the
 * true contact of radius a(t) = sqrt(R alpha_H(t)) (field.h,
 * anvil_field_set_contact), not of the paper's r0 patch: for a 50 g steel
 * ball (R = 11.5 mm) at 3 m/s on a steel block the r0 patch gave 19 MPa,
 * the true contact about 3.4 GPa.
 *
 * Two inputs, one function:
 *   f NULL: quasi-static Hertz at its peak force (no run: what `anvil
 *     plan` can say); closed form, accurate to 1e-10;
 *   f the field of an impact (anvil_solver_verdict makes it): the Hertz
 *     field of a(t) plus the dynamic remainder, its peak searched in space
 *     and time, with the field's error estimate.
 * For a block the two agree within the waves' share (the remainder near
 * the contact is O(radiated fraction)); for a thin plate the field adds
 * the bending stresses and the plate's lower force. */
#ifndef ANVIL_VERDICT_H
#define ANVIL_VERDICT_H

#include <stddef.h>

#include "field.h"
#include "hertz_field.h"
#include "problem.h"

struct anvil_plan;   /* plan.h, which holds a verdict */
struct anvil_solver; /* solver.h */

/* The impactor under the same contact: the pressure on its tip is the
 * layer's, so the same Hertz field with the impactor's own nu (Johnson
 * 1985, sec. 4.2: each body of a Hertz contact carries the half-space
 * field of its own elastic constants), judged against its own Y, or for a
 * brittle impactor its tensile strength.  Quasi-static always: the
 * impactor's waves are not modelled (a rigid-body impactor), so its field
 * is the Hertz one at the layer verdict's contact (a, p0). */
struct anvil_verdict_impactor {
	enum anvil_hertz_fate fate; /* ELASTIC, YIELDS or CRACKS */
	int known, brittle;         /* as for the layer */
	char material[ANVIL_NAME_MAX];
	double stress, limit;       /* Pa; accurate to 1e-10 (closed form) */
	double z;                   /* depth of the von Mises peak inside the tip, m */
};

struct anvil_verdict {
	enum anvil_hertz_fate fate; /* ELASTIC, YIELDS or CRACKS */
	int known;     /* 0: the layer's Y (brittle: tensile strength) unknown: not judged */
	int brittle;   /* the criterion: 1 edge tension, 0 von Mises */
	int dynamic;   /* 1: from an impact's field, 0: quasi-static Hertz */
	int at_row;    /* 1: quasi-static Hertz at a computed row's peak force (anvil_verdict_at) */
	double qs_ratio; /* > 0: quasi-static Hertz at the layer row's computed peak
			    force, the contact this many times 2h/c1 (anvil_solver_verdict) */
	/* why a verdict is quasi-static (anvil_verdict_quasi_static; 0: not
	 * said), and the plan's figures that decided it: the fraction of the
	 * impact energy the half-space would radiate, the change of the
	 * impact by the plate's bending */
	int qs_why;
	double qs_radiated, qs_bending;
	char material[ANVIL_NAME_MAX]; /* the layer's */
	double stress, err; /* the peak von Mises or edge tension and its error, Pa */
	double limit;       /* Y or the tensile strength, Pa; 0 unknown */
	double r, z, t;     /* where (m) and when (s) */
	double a, p0;       /* contact radius (m) and peak pressure (Pa) at t */
	/* A long contact (qs_ratio > 0): the plate's bending stress at the
	 * centre of its far face (plate_bending.h, under the layer row's
	 * computed P(t) and the Hertz contact), tension; there sigma_rr =
	 * sigma_tt and sigma_zz = 0, so it is the von Mises stress too.
	 * bend_state: 0 not tried, 1 checked (bend_tol its stated relative
	 * accuracy; the fate takes the larger of stress and bend), -1 not
	 * checked (bend_why says why: outside the estimate's range, or its
	 * error). */
	int bend_state;
	double bend, bend_err, bend_t, bend_tol; /* Pa, Pa, s, relative */
	char bend_why[160];
	/* With the bending checked (bend_state 1): the near face, where the
	 * contact's field and the bending's compression add
	 * (anvil_plate_bending_near), at the instant of their largest sum
	 * (each at that same instant): the von Mises stress (brittle: the
	 * largest principal tension, which the bending relieves) and where.
	 * The fate is then judged on the larger of near and bend: the near
	 * face's is the contact's own field with the plate's stresses added,
	 * so it stands for stress (which stays the contact's alone, at P_max). */
	double near, near_r, near_z, near_t, near_sb; /* Pa, m, m, s, the far face's Pa then */
	struct anvil_verdict_impactor imp; /* the impactor under the same (a, p0) */
};

/* The verdict on pb's layer, from field f (true contact turned on here) or,
 * f NULL, from quasi-static Hertz, and on its impactor (v->imp) under the
 * same contact.  ANVIL_OK, or the field's status (or hertz_field.h's). */
int anvil_verdict_make(const struct anvil_problem *pb, struct anvil_field *f,
		       struct anvil_verdict *v, struct anvil_err *err);

/* Quasi-static Hertz under a force P (N) at time t (s) (the layer's
 * computed peak): the layer and the impactor judged as anvil_verdict_make
 * without a field. */
int anvil_verdict_at(const struct anvil_problem *pb, double P, double t, struct anvil_verdict *v);

/* Add the plate's bending stress to v (made by anvil_verdict_at or _make)
 * from a finite layer's force history h (any spacing, from t = 0): the
 * far face's centre stress, its maximum over the history (plate_bending.h,
 * the Hertz contact's patch, Westergaard's thick-plate radius), checked
 * where its stated accuracy holds (h/r0 and a/h within the range measured
 * against the transform field); the fate judged again on the larger of
 * v->stress and the bending stress.  Outside the range, or when the
 * estimate fails, v->bend_state = -1 and v->bend_why says why; the
 * status is ANVIL_OK either way (the estimate's failure is in bend_why). */
void anvil_verdict_bending(const struct anvil_problem *pb, const struct anvil_history *h,
			   struct anvil_verdict *v);

/* The verdict of plan pl's impact (engine/yield.c): run its layer row (the
 * halfspace row when h = inf) with the histories the field needs, make the
 * field, anvil_verdict_make.  Returns the run's status (ANVIL_WTOL: the
 * impact missed its target, v still filled) or the field's.  The results
 * are the solver's cache's: a run of the same plan costs no second run. */
int anvil_solver_verdict(struct anvil_solver *s, const struct anvil_plan *pl,
			 struct anvil_verdict *v, struct anvil_err *err);
/* The same, given the layer row's result (the half-space's when h = inf)
 * when the caller has it (NULL: run it when a quasi-static rule below
 * needs it): a quasi-static verdict then costs no second run of the row. */
int anvil_solver_verdict_with(struct anvil_solver *s, const struct anvil_plan *pl,
			      const struct anvil_result *layer, struct anvil_verdict *v,
			      struct anvil_err *err);
/* Where the searched field and quasi-static Hertz at the row's own P_max
 * (plus, on a finite layer, the plate's bending under the row's history:
 * anvil_verdict_bending) agree, anvil_solver_verdict takes the second
 * (v->qs_why says which rule): the field's search costs seconds to a
 * minute where the load is long against the field's time scales (62 s for
 * 100 kg at 1 mm/s on h = 5 r0, 45 s on the half-space; it grows with the
 * load's length), the quasi-static verdict microseconds.  Three rules:
 *  - LONG: a finite layer's contact longer than ANVIL_VERDICT_QS_RATIO
 *    times 2h/c1 (the plan's estimate) is quasi-static near the contact
 *    (the paper's own case is 35 times 2h/c1, a copper rod on 0.35 r0
 *    about 1000);
 *  - GENTLE: where the half-space would radiate less than
 *    ANVIL_VERDICT_QS_RADIATED of the impact energy (the plan's figure),
 *    the dynamic remainder near the contact is of that order (the top of
 *    this file);
 *  - BLOCK: where the plate's bending changes the impact by less than
 *    ANVIL_VERDICT_QS_BENDING (the plan's Zener figure) and the half-space
 *    would radiate less than ANVIL_VERDICT_QS_RADIATED_BLOCK, nothing but
 *    the contact's own inertia adds to Hertz near the contact, and that
 *    little: the P_max it lowers is the row's already.
 * Measured on the copper-on-steel grid (h/r0 0.02-1000 and inf, 0.1 g-100
 * kg, 1 mm/s-1 km/s), the stress judged against the searched field's:
 * GENTLE within 0.9 % on 79 scenes (contacts 1-5e5 times 2h/c1), BLOCK
 * within 1.3 % on 136 (0.5 % below 4 % radiated).  Outside them the field
 * is searched: a plate whose bending matters (its compression relieves the
 * stress under the contact: up to 27 % below Hertz where the plate
 * estimate's range leaves it out) or an impact at hundreds of m/s (the
 * field 4-8 % above Hertz). */
#define ANVIL_VERDICT_QS_RATIO 2000.0
#define ANVIL_VERDICT_QS_RADIATED 1e-3
#define ANVIL_VERDICT_QS_BENDING 0.1
#define ANVIL_VERDICT_QS_RADIATED_BLOCK 0.15
enum anvil_verdict_qs {
	ANVIL_VERDICT_QS_NO,
	ANVIL_VERDICT_QS_LONG,
	ANVIL_VERDICT_QS_GENTLE,
	ANVIL_VERDICT_QS_BLOCK
};
enum anvil_verdict_qs anvil_verdict_quasi_static(const struct anvil_plan *pl);
/* The row the verdict reads: the layer's, the half-space's when h = inf. */
enum anvil_model anvil_verdict_model(const struct anvil_plan *pl);
/* Mark v (from anvil_verdict_at at row's P_max) with why it is
 * quasi-static: qs_why, qs_ratio from row's own t_s (LONG), the plan's
 * figures (GENTLE, BLOCK). */
void anvil_verdict_qs_mark(const struct anvil_plan *pl, enum anvil_verdict_qs why,
			   const struct anvil_result *row, struct anvil_verdict *v);
/* The quasi-static verdict's row carries this many history samples (400
 * and 2001 samples gave the same bending stresses to 3 digits on four
 * plates); a row run with others is run again with them. */
#define ANVIL_VERDICT_NHIST 400 /* = cmd_run.c RUN_NHIST: a run with --history or --png hands its row over */

/* One line without a newline: "the steel layer yields: peak von Mises
 * 3.41 GPa at 0.48 a = 0.42 mm below the contact at t = 32.5 us, Y = 1 GPa";
 * with the plate's bending clause ("; bending stress at the far face ...",
 * or why it was not checked) whenever anvil_verdict_bending was tried on v.
 * ANVIL_VERDICT_TEXT_MAX holds any line (a long contact's runs past 320). */
#define ANVIL_VERDICT_TEXT_MAX 1024
void anvil_verdict_text(const struct anvil_verdict *v, char *buf, size_t n);

/* The impactor's line, without a newline: "the copper impactor yields
 * under the same contact: peak von Mises 3.04 GPa at 0.48 a = 0.11 mm
 * inside its tip, Y = 57 MPa". */
void anvil_verdict_impactor_text(const struct anvil_verdict *v, char *buf, size_t n);

/* The two lines for a screen's notes, most telling first (the TUI cuts
 * them at its width, 53 columns on 80): "layer yields (quasi-static
 * Hertz): 5.27 GPa von Mises, Y = 1 GPa, at 0.48 a = 0.297 mm below the
 * contact, t = 16.3 us; at the layer's computed P_max" with the bending
 * clause after, and "impactor yields too: 5.06 GPa von Mises, Y = 57 MPa,
 * at 0.49 a = ...".  What the field is ("quasi-static Hertz", "the
 * dynamic field") always within the first 40 columns. */
void anvil_verdict_text_screen(const struct anvil_verdict *v, char *buf, size_t n);
void anvil_verdict_impactor_text_screen(const struct anvil_verdict *v, char *buf, size_t n);

/* 1 when the layer or the impactor yields or cracks. */
int anvil_verdict_fails(const struct anvil_verdict *v);

#endif
