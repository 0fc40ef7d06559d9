/* plate_ks.h: K(t) and S(t), the plate tail's two quadratures
 * (plate_ks.c), for plate.c's table of them in log t.  Internal to the
 * transform module (plate.h is the public face). */
#ifndef ANVIL_PLATE_KS_H
#define ANVIL_PLATE_KS_H

#include <gsl/gsl_integration.h>

struct umemo;
struct zmemo;
/* A quadrature's workspaces, kept across a table's nodes: K's and S's
 * factors in u replay at the next node (plate_ks.c, umemo). */
struct kwork {
	gsl_integration_workspace *w, *wc;
	gsl_integration_qawo_table *tab, *tabc; /* sin u, cos u (S's) */
	struct umemo *uk, *us; /* K's and S's factors in u (one nu: one tail's) */
	struct zmemo *zm;      /* the load's transform at one node's u (plate_ks.c) */
};

int plate_kwork_alloc(struct kwork *kw);
void plate_kwork_free(struct kwork *kw);

/* beta = hh / sqrt(6 (1 - nu)): u = beta k^2 t */
double plate_beta(double hh, double nu);

/* K(t)/t^2 (to 1e-12 relative) and S(t)/t (to 1e-12 relative or
 * 1e-13/hh absolute; 0 for a point load) at t for a patch of radius
 * patch (0: a point load); ANVIL_ENUM when a quadrature fails. */
int plate_k_over_t2(double beta, double hh, double patch, double t, struct kwork *kw,
		    double *val);
int plate_s_over_t(double beta, double hh, double nu, double patch, double t, struct kwork *kw,
		   double *val);

#endif
