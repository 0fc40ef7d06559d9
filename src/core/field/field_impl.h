/* field_impl.h: what the field module's files share (field.c, the object
 * and its checks; field_sum.c, the Bromwich line, the k panels and the
 * assembly of the outputs; field_map.c, field_points.c, field_peak.c).
 * Internal to src/core/field: not for the engine or the faces.
 *
 * Dimensionless inside (mu = rho = c2 = r0 = 1, time tau = t c2/r0, the
 * load in newtons): a displacement is value/(mu r0) m, a stress
 * value/r0^2 Pa. */
#ifndef ANVIL_FIELD_IMPL_H
#define ANVIL_FIELD_IMPL_H

#include <complex.h>
#include <stddef.h>

#include "accuracy.h"
#include "durbin.h"
#include "field.h"
#include "field_kernel.h"

typedef double complex cplx;

/* The field's columns of the accuracy table: field_sum.c says what each
 * one is and how it was chosen. */
#define FLEVEL(acc) (&anvil_level(acc)->field)
typedef struct anvil_field_level flevel_t;

struct anvil_field {
	double r0, mu, c2, nu, kap2, hh, cr; /* cr = c_R/c2 */
	enum anvil_accuracy acc;
	double *P;        /* the load, N, at tau_i = i dtau */
	size_t nP;
	double dtau, tau_load, load_rel;
	anvil_progress_fn progress;
	void *pctx;
	int true_contact;   /* the static part over a(t), not r0 (field.h) */
	double R, Estar;    /* tip radius and contact modulus, for a(t) */
};

/* P at tau: the piecewise-linear load, back to 0 one step after its last
 * sample (what the Bromwich line transforms, exactly). */
double anvil_field_load_at(const struct anvil_field *f, double tau);

/* Each output (but von Mises) as a combination of the Hankel integrals,
 * and the Hankel integrals the outputs in bits `quantities` need. */
extern const double anvil_field_combo[ANVIL_FQ_VM][HS_COUNT];
unsigned anvil_field_hs_needed(unsigned quantities);

/* ---- the Bromwich line (field_sum.c) ---- */
struct anvil_field_window {
	struct anvil_durbin dl; /* the line: half period T', abscissa c0, terms 0..M */
	double omega;   /* highest frequency summed */
	size_t M, Mh;   /* terms n = 0..M; the coarse twin n = 0..Mh (2M/3) */
	cplx *s, *Phat; /* M + 1 each, one block */
};

/* The line for instants up to tau_hi at level lv: the load's transform at
 * every s_n.  ANVIL_EINVAL past the Durbin bounds, ANVIL_ENOMEM; w->s is
 * the caller's to free, even on failure. */
int anvil_field_window_init(const struct anvil_field *f, const flevel_t *lv, double tau_hi,
			    struct anvil_field_window *w);
/* The filtered Durbin weights of instant tau for terms n <= nmax into
 * a[n * stride]. */
void anvil_field_weights(const struct anvil_field_window *w, double tau, size_t nmax, cplx *a,
			 size_t stride);

/* ---- the k panels (field_sum.c) ---- */
/* The panels' nodes: the 21-point Gauss-Kronrod rule (gk21.h), walked
 * node by node, since each node serves every depth, frequency and radius. */

struct anvil_field_kgrid {
	size_t np;   /* panels */
	double *a;   /* np + 1 ends */
	double kb;   /* end of the pole band */
	double wt;   /* width of the panels beyond it */
	double ktail, L;
};

/* Panels for radii up to rmax (units of r0): ANVIL_EINVAL past
 * KGRID_NP_MAX, ANVIL_ENOMEM; g->a is the caller's to free. */
int anvil_field_kgrid_init(struct anvil_field_kgrid *g, const struct anvil_field *f,
			   const flevel_t *lv, const struct anvil_field_window *w, double rmax);
/* How many panels depth z uses, and the tail factor of its last one. */
size_t anvil_field_kgrid_panels(const struct anvil_field_kgrid *g, double z);
double anvil_field_kgrid_tail_factor(const struct anvil_field_kgrid *g, double z);

/* ---- Bessel factors (field_sum.c) ---- */
/* The k-dependence of each Hankel integral at radius r, times Z^H(k):
 * k J0, k J1, k J1(kr)/r, k^2 J0. */
enum { JK_J0, JK_J1, JK_J1R, JK_KJ0, JK_COUNT };
extern const int anvil_field_jkind_of_hs[HS_COUNT];
/* The four factors at (k, r) times zh = Z^H(k); ANVIL_ENUM from GSL. */
int anvil_field_bessel_at(double k, double r, double zh, double out[JK_COUNT]);

/* ---- assembling the outputs (field_sum.c) ---- */
/* The seven Hankel integrals at one (r, z, t) and their error parts: the
 * Gauss-Kronrod difference, the half-band difference and the last panel. */
struct anvil_field_hsv {
	double v[HS_COUNT], dG[HS_COUNT], dH[HS_COUNT], dT[HS_COUNT];
	double tailf;
};

/* The outputs and their errors from the Hankel integrals x. */
void anvil_field_assemble(const struct anvil_field *f, const struct anvil_field_hsv *x,
			  struct anvil_fval *o);
/* The true contact's static stresses in place of the r0 patch's at (x, y)
 * (units of r0), instant tau (field.h, anvil_field_set_contact). */
void anvil_field_true_contact(const struct anvil_field *f, double x, double y, double tau,
			      struct anvil_fval *o);
/* Each estimate of n values (stride apart) plus the largest of the set. */
void anvil_field_error_floor(struct anvil_fval *o, size_t n, size_t stride);
/* The static part P(tau) F_st added to the remainder's integrals. */
void anvil_field_add_static(const struct anvil_field *f, double tau, const double *fst,
			    struct anvil_field_hsv *x);

/* ---- checks and messages (field.c) ---- */
int anvil_field_check_times(const struct anvil_field *f, size_t nt, const double *t,
			    double *tau_hi, struct anvil_err *err);
int anvil_field_check_point(const struct anvil_field *f, double r, double z,
			    struct anvil_err *err);
int anvil_field_check_grid(const struct anvil_field *f, const struct anvil_field_grid *g,
			   struct anvil_err *err);
/* The work of a field at least: each of the M + 1 Fourier terms solves
 * the layer at every k node (np panels) once, and sums every depth's
 * panels (depth_panels, summed over the depths).  Refused (ANVIL_ETOL,
 * with the estimate) beyond ANVIL_FIELD_BUDGET_S: a contact thousands of
 * times 2h/c1 long needs tens of thousands of terms on tens of thousands
 * of panels (a 500 g rod on a 2 mm plate: 45 min), which no one waits
 * for at a terminal. */
#define ANVIL_FIELD_BUDGET_S 600.0
int anvil_field_check_work(const struct anvil_field *f, const struct anvil_field_window *w,
			   const struct anvil_field_kgrid *g, size_t depth_panels, const char *what,
			   struct anvil_err *err);
/* A load too long for the Fourier series' bound (window_init's
 * ANVIL_EINVAL): ANVIL_ETOL, refused as the budget refuses, with the load's
 * length against 2h/c1 (a thin plate's impactor at rest on it for
 * seconds); returns ANVIL_ETOL. */
int anvil_field_window_fail(const struct anvil_field *f, const char *what,
			    struct anvil_err *err);
/* Status st with its message (ANVIL_EINVAL: a bound of the line or the
 * panels); returns st. */
int anvil_field_fail(const struct anvil_field *f, int st, const char *what,
		     struct anvil_err *err);

/* ---- maps (field_map.c) ---- */
/* anvil_field_map at the settings of level lv (the peak search locates
 * at draft). */
int anvil_field_map_level(struct anvil_field *f, const flevel_t *lv, size_t nt,
			  const double *t, const struct anvil_field_grid *g,
			  unsigned quantities, struct anvil_fval *out, struct anvil_err *err);

#endif
