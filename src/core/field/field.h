/* field.h: displacements and stresses anywhere in the layer (or half-space)
 * during an impact: eqs (13)-(14), (20)-(29) and (36) of the paper.
 *
 * For the contact force P(t) of an impact (piecewise linear on a uniform
 * grid, as the impact solver makes it) this computes at any (r, z, t)
 *   u, w                       the radial and axial displacement (m),
 *   sigma_zz, _rr, _tt, _rz     the stresses (Pa, tension positive),
 *   von Mises                  sqrt(3 J2) of the stress (Pa),
 * each with an estimate of its absolute error.  z is the depth below the
 * loaded face, 0 <= z <= h; the load is the Hertz-shaped patch Z(r) P(t)
 * of radius r0 (eq 7), the bottom face is free.
 *
 * Method (details in field.c):
 *   field = P(t) F_static(r, z) + remainder,
 * F_static the static half-space field of the Hertz patch, in closed form
 * (Huber's solution, field_kernel.c), and the remainder the Duhamel
 * convolution (13)-(14) done in the Laplace domain: the exact transform of
 * the piecewise-linear P(t) times the transformed fields at depth, minus
 * their static part, inverted by Durbin's Fourier series on the Bromwich
 * line (with a spectral filter), with the k-integral on a fixed set of
 * Gauss-Kronrod panels shared by every depth, time and radius.  Subtracting
 * the static part is what makes the k-integral converge at and near the
 * surface (the J0(kr) Z^H(k) tail), and it gives the quasi-static near
 * field exactly.
 *
 * Errors: the remainder's bandwidth (twice the change when the band is cut
 * by a third), the k-quadrature (Gauss against Kronrod), the k-tail (the
 * last panel) and the load's own relative error, added; then each estimate
 * gets the largest of its map (per instant) or history on top, the stresses
 * sharing one.  They are conservative: against runs with three times the
 * reference level's bandwidth, normal maps were within 2e-4 of the peak
 * stress (5e-4 at the instant the contact ends) and their estimates 3 to a
 * few hundred times larger than the error.
 *
 * Nothing here runs unless called: `anvil run` pays nothing for it. */
#ifndef ANVIL_FIELD_H
#define ANVIL_FIELD_H

#include <stddef.h>

#include "accuracy.h"
#include "params.h"
#include "progress.h"
#include "result.h"
#include "status.h"

/* The quantities, in output order. */
enum anvil_fq {
	ANVIL_FQ_U,   /* radial displacement, m */
	ANVIL_FQ_W,   /* axial displacement (into the layer), m */
	ANVIL_FQ_SZZ, /* sigma_zz, Pa */
	ANVIL_FQ_SRR, /* sigma_rr, Pa */
	ANVIL_FQ_STT, /* sigma_theta-theta, Pa */
	ANVIL_FQ_SRZ, /* sigma_rz, Pa */
	ANVIL_FQ_VM,  /* von Mises stress, Pa */
	ANVIL_FQ_COUNT
};

/* "u", "w", "szz", "srr", "stt", "srz", "vm"; NULL out of range. */
const char *anvil_fq_name(enum anvil_fq q);
/* A few words: "radial displacement u". */
const char *anvil_fq_title(enum anvil_fq q);
/* 1 for the stresses, 0 for the displacements. */
int anvil_fq_is_stress(enum anvil_fq q);
/* The quantity called name (case-insensitive), or -1. */
int anvil_fq_parse(const char *name);

/* One point's values and error estimates (SI). */
struct anvil_fval {
	double v[ANVIL_FQ_COUNT], err[ANVIL_FQ_COUNT];
};

/* History samples an impact should keep for a faithful load
 * (anvil_solver_run's nhist). */
#define ANVIL_FIELD_NHIST 2001

struct anvil_field;

/* Make the field of layer p (p->h may be INFINITY) under the load P[i] at
 * t = i dt, i < n (newtons; P[0] = 0, P linear in between and back to 0
 * one step after the last sample), whose relative error is load_rel (0:
 * exact), at accuracy
 * acc.  The arrays are copied.  Returns NULL with err set to ANVIL_EINVAL
 * (bad parameters: n < 3, dt <= 0, a negative or non-finite P) or
 * ANVIL_ENOMEM. */
struct anvil_field *anvil_field_alloc(const struct anvil_params *p, const double *P,
				      size_t n, double dt, double load_rel,
				      enum anvil_accuracy acc, struct anvil_err *err);

/* The same from an impact result with a history (uniform, from t = 0), e.g.
 * anvil_solver_run(..., ANVIL_FIELD_NHIST, r, ...), for the layer p (a
 * half-space for a result of the halfspace model) at accuracy acc: load_rel
 * is r->Pmax.err / r->Pmax.val.  ANVIL_EINVAL when r has no history. */
struct anvil_field *anvil_field_from_result(const struct anvil_params *p,
					    enum anvil_accuracy acc,
					    const struct anvil_result *r,
					    struct anvil_err *err);

void anvil_field_free(struct anvil_field *f); /* NULL is a no-op */

/* Progress and cancel, as anvil_solver_set_progress (fn may be NULL). */
void anvil_field_set_progress(struct anvil_field *f, anvil_progress_fn fn, void *ctx);

/* The true contact (issue 10): with true_contact on, the stresses near the
 * contact are those of the Hertz contact of radius
 *   a(t) = sqrt(R alpha_H(t)) = (3 P(t) R / (4 E*))^(1/3)
 * (R = r0, the tip's radius, E* the contact modulus of p), in closed form
 * (hertz_field.h), plus the dynamic remainder: the response to the r0
 * patch less that patch's static field, which is what the k-integrals
 * compute anyway.  The static part is exact; what this leaves out is the
 * patch size's effect on the remainder, which is O((omega r0/c2)^2)
 * relative to the remainder itself near the contact and nothing at
 * distances beyond a few r0 (where any patch is a point force); the
 * displacements keep the r0 patch's static part.  Off (the paper's patch
 * of radius r0) after anvil_field_alloc. */
void anvil_field_set_contact(struct anvil_field *f, int true_contact);
/* The contact radius under load P (N): a as above, r0 when off. */
double anvil_field_contact_radius(const struct anvil_field *f, double P);
/* The load (N) at t (s), as the field sees it. */
double anvil_field_load(const struct anvil_field *f, double t);

/* The end of the load (s): where it is back to 0. */
double anvil_field_t_load(const struct anvil_field *f);
/* The layer thickness (m), INFINITY for a half-space. */
double anvil_field_h(const struct anvil_field *f);

/* Time histories at npt points (r[i], z[i]) (m) at nt times t[j] >= 0 (s):
 * out[i * nt + j].  Times may run past the load (free vibration after the
 * contact) up to ANVIL_FIELD_T_MAX times its end.  Returns ANVIL_OK,
 * ANVIL_EINVAL (a point outside the layer, r < 0, a bad time: message
 * names it), ANVIL_ENOMEM, ANVIL_ECANCEL, ANVIL_ENUM. */
int anvil_field_points(struct anvil_field *f, size_t npt, const double *r,
		       const double *z, size_t nt, const double *t,
		       struct anvil_fval *out, struct anvil_err *err);

#define ANVIL_FIELD_T_MAX 4.0

/* A uniform grid in the (r, z) half-plane: r_i = r_lo + i (r_hi - r_lo)/(nr-1)
 * (i < nr), likewise z; nr, nz >= 2 (or 1 with lo == hi). */
struct anvil_field_grid {
	double r_lo, r_hi, z_lo, z_hi; /* m */
	size_t nr, nz;
};

/* Maps at nt instants t[j] (s): out[(j * nz + iz) * nr + ir].  The cost is
 * organised for this: one k-quadrature per depth and frequency, shared by
 * every radius and instant.  quantities: the bits 1u << ANVIL_FQ_... wanted
 * (0: all); the others come out NaN, and cost nothing.  Statuses as
 * anvil_field_points. */
int anvil_field_map(struct anvil_field *f, size_t nt, const double *t,
		    const struct anvil_field_grid *g, unsigned quantities,
		    struct anvil_fval *out, struct anvil_err *err);

/* The peak of the von Mises stress in the layer during the load, against
 * the layer's yield stress (the elastic assumption of the paper). */
struct anvil_field_peak {
	double vm, vm_err; /* Pa */
	double r, z, t;    /* where and when: m, m, s */
	double yield;      /* the layer's yield stress, Pa; 0: unknown */
	int exceeded;      /* 1 when yield > 0 and vm > yield */
	double elsewhere;  /* true contact: the bound on von Mises over the whole
			    * layer and load (the global pass's largest value plus
			    * its error estimate), Pa; NaN for the exhaustive search */
};

/* Search r in [0, 3 r0], z in [0, h] (half-space: [0, 3 r0]), t in
 * (0, end of the load].  yield (Pa, 0 = unknown) is copied into pk for the
 * verdict.  Statuses as anvil_field_map.
 *
 * The paper's patch: anvil_field_peak_exhaustive.  The true contact
 * (anvil_field_set_contact), whose peak is at the contact: a grid over
 * the top 2 a around the peak force, refined at the field's settings; then
 * a coarse grid over the whole layer and load at draft settings with at
 * most 128 Durbin terms at normal (64 draft, 256 fine, 512 reference),
 * whose largest von Mises plus error estimate is pk->elsewhere.  When that
 * bound is at most the contact's peak, nothing else can beat it and the
 * search stops (the common case: it costs the contact's instants, not the
 * whole load's); else the coarse grid's best point is refined as well and
 * the larger peak kept.  Against the exhaustive search: the same point
 * when the contact's peak is the larger (the same bits at loads under the
 * cap), and within the sum of the two error estimates otherwise
 * (tests/test_field.c). */
int anvil_field_peak(struct anvil_field *f, double yield,
		     struct anvil_field_peak *pk, struct anvil_err *err);

/* The exhaustive search: the coarse grid over the whole layer and load at
 * draft settings (no cap), with the true contact the grid over its top
 * 2 a, then a finer grid one coarse cell around the best point at the
 * field's own settings, whose best point is the answer.  Its cost grows
 * like the square of the load's length (h = 0.35 r0: 11 s).  Statuses as
 * anvil_field_peak. */
int anvil_field_peak_exhaustive(struct anvil_field *f, double yield,
				struct anvil_field_peak *pk, struct anvil_err *err);

/* The yield check as one call (run the impact, make its field, find the
 * peak) is the engine's: anvil_solver_yield in solver.h. */

#endif
