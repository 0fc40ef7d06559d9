/* test_plate_bending: the plate's bending stress (field/plate_bending.h)
 *  - a step load on the Hertz patch of radius c against its closed form,
 *      sigma(t) = 3 (1+nu) P0 / (4 pi h^2) (3/2) int_0^1 sqrt(1-w) (-Ci(L w/4)) dw,
 *    L = c^2 / (beta t) (the impulse response's Gamma integrated over t:
 *    int_L^inf cos(l w/4)/l dl = -Ci(L w/4)), computed here with GSL's Ci
 *    and QUADPACK, apart from the module's convolution and table; and its
 *    long-time limit 3 (1+nu) P0/(4 pi h^2) [ln(beta t/c^2) - gamma + 8/3]
 *    (the infinite plate's centre moment grows like ln t);
 *  - the Hertz patch under a constant force = the fixed patch of its a;
 *  - against the transform field (field.h, the paper's r0 patch, which
 *    is what its far face carries) on two plates within the stated
 *    accuracy ANVIL_PLATE_BENDING_TOL;
 *  - the verdict: the text with the stress and its accuracy, the fate
 *    judged on it, a thick plate "not checked" with the reason. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_expint.h>

#include "field.h"
#include "plate_bending.h"
#include "scene_run.h"
#include "tap.h"
#include "verdict.h"

/* A 2 mm steel plate (E 210 GPa, nu 0.3, rho 7800): only h, E, nu, rho,
 * r0 and K enter. */
static struct anvil_params steel_plate(void)
{
	struct anvil_params p = {0};
	p.E = 210e9;
	p.nu = 0.3;
	p.rho = 7800;
	p.h = 2e-3;
	p.r0 = 4e-3;
	p.K = 4.0 / 3.0 * 115e9 * sqrt(p.r0);
	return p;
}

static double beta_of(const struct anvil_params *p)
{
	return p->h * sqrt(p->E / (12 * p->rho * (1 - p->nu * p->nu)));
}

struct ci_arg {
	double L;
};

static double ci_integrand(double w, void *vp)
{
	const struct ci_arg *a = vp;
	return sqrt(1 - w) * -gsl_sf_Ci(0.25 * a->L * w);
}

/* The closed form above. */
static double step_closed(const struct anvil_params *p, double P0, double c, double t)
{
	struct ci_arg a = {c * c / (beta_of(p) * t)};
	gsl_function F = {ci_integrand, &a};
	gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
	double v, e;
	gsl_integration_qags(&F, 0, 1, 0, 1e-11, 200, ws, &v, &e);
	gsl_integration_workspace_free(ws);
	return 3 * (1 + p->nu) * P0 / (4 * M_PI * p->h * p->h) * 1.5 * v;
}

/* A step of P0 from t = 0 (a ramp of 1e-12 s) held to t_end. */
static void step_history(struct anvil_history *h, double P0, double t_end)
{
	anvil_history_alloc(h, 3);
	h->t[0] = 0;
	h->t[1] = 1e-12;
	h->t[2] = t_end;
	h->P[0] = 0;
	h->P[1] = h->P[2] = P0;
}

static void step_load(void)
{
	struct anvil_params p = steel_plate();
	struct anvil_history h = {0};
	double c = 1e-3, P0 = 1000, worst = 0, wabs = 0, s, e;
	double scale = 3 * (1 + p.nu) * P0 / (4 * M_PI * p.h * p.h);
	step_history(&h, P0, 1e-2);
	/* beta t / c^2 from 0.01 (the patch barely bent) to 1e4 */
	for (double x = 0.01; x <= 1.1e4; x *= 10) {
		double t = x * c * c / beta_of(&p);
		int st = anvil_plate_bending_at(&p, &h, ANVIL_PLATE_PATCH_FIXED, c, t, &s, &e);
		double want = step_closed(&p, P0, c, t);
		wabs = fmax(wabs, st ? INFINITY : fabs(s - want) / scale);
		if (want > 0.1 * scale)
			worst = fmax(worst, st ? INFINITY : fabs(s / want - 1));
		diag("st %d beta t/c^2 = %-8g sigma %.8g MPa, closed form %.8g (+- %.2g)", st, x, s * 1e-6,
		     want * 1e-6, e * 1e-6);
	}
	ok(worst < 1e-5 && wabs < 1e-6,
	   "step load on a Hertz patch = closed form within 1e-5 (worst %.2g; %.2g of "
	   "3(1+nu)P0/(4 pi h^2) where it is small)", worst, wabs);
	double t = 1e4 * c * c / beta_of(&p);
	anvil_plate_bending_at(&p, &h, ANVIL_PLATE_PATCH_FIXED, c, t, &s, &e);
	double lim = 3 * (1 + p.nu) * P0 / (4 * M_PI * p.h * p.h) * (log(1e4) - M_EULER + 8.0 / 3);
	is_rel(s, lim, 2e-4, "  at beta t = 1e4 c^2 the ln t law: %.6g MPa", lim * 1e-6);
	/* the Hertz patch under a constant P is the fixed patch of its a */
	double a = sqrt(p.r0 * pow(P0 / p.K, 2.0 / 3.0)), sh;
	t = 50e-6;
	anvil_plate_bending_at(&p, &h, ANVIL_PLATE_PATCH_FIXED, a, t, &s, &e);
	anvil_plate_bending_at(&p, &h, ANVIL_PLATE_PATCH_HERTZ, 0, t, &sh, &e);
	is_rel(sh, s, 1e-9, "  Hertz patch at constant P = fixed patch of radius a = %.3g mm", a * 1e3);
	/* Westergaard: a patch wider than 1.724 h is its own radius */
	anvil_plate_bending_at(&p, &h, ANVIL_PLATE_PATCH_FIXED, 4e-3, t, &s, &e);
	anvil_plate_bending_at(&p, &h, ANVIL_PLATE_PATCH_FIXED | ANVIL_PLATE_PATCH_WESTERGAARD,
			       4e-3, t, &sh, &e);
	is_rel(sh, s, 1e-12, "  Westergaard leaves c = 2 h as it is");
	ok(anvil_plate_bending_at(&p, &h, ANVIL_PLATE_PATCH_FIXED, 0, t, &s, &e) == ANVIL_EINVAL,
	   "  a fixed patch of radius 0: ANVIL_EINVAL");
	anvil_result_free(&(struct anvil_result){.hist = h});
}

/* Scene sc's paper-contact layer row (the field's load), its field's
 * far-face sigma_rr at (0, h) around the estimate's peak, against the
 * estimate under the same load (the r0 patch, Westergaard's radius). */
static void against_field(const char *name, const char *h_r0, const char *mass)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err e = {0};
	struct anvil_result r;
	anvil_scene_default(&sc);
	anvil_scene_set(&sc, "layer.thickness", h_r0, NULL, 0, &e);
	anvil_scene_set(&sc, "impactor.mass", mass, NULL, 0, &e);
	int st = scene_plan(&sc, &pl, &e);
	struct anvil_solver *s = anvil_solver_alloc();
	st = st ? st : anvil_solver_run_contact(s, &pl, ANVIL_MODEL_LAYER, ANVIL_CONTACT_PAPER,
						ANVIL_FIELD_NHIST, &r, &e);
	const struct anvil_params *p = &pl.pb.p;
	struct anvil_plate_bending b;
	st = st < 0 ? st
		    : anvil_plate_bending_peak(p, &r.hist, ANVIL_PLATE_PATCH_FIXED |
							   ANVIL_PLATE_PATCH_WESTERGAARD,
					       p->r0, 0, &b, &e);
	struct anvil_field *f = st ? NULL : anvil_field_from_result(p, pl.pb.accuracy, &r, &e);
	double t[9], rr = 0, zz = p->h, best = -INFINITY, berr = 0, tb = 0;
	struct anvil_fval o[9];
	for (int i = 0; i < 9; i++)
		t[i] = b.t * (0.6 + 0.1 * i);
	st = f ? anvil_field_points(f, 1, &rr, &zz, 9, t, o, &e) : ANVIL_EINVAL;
	for (int i = 0; !st && i < 9; i++)
		if (o[i].v[ANVIL_FQ_SRR] > best) {
			best = o[i].v[ANVIL_FQ_SRR];
			berr = o[i].err[ANVIL_FQ_SRR];
			tb = t[i];
		}
	ok(!st, "%s: field at the far face (%s)", name, e.msg);
	ok(fabs(b.sigma / best - 1) < ANVIL_PLATE_BENDING_TOL,
	   "  plate %.4g MPa at %.4g us, field %.4g MPa (+- %.2g) at %.4g us: %+.2f %% (within %.0f %%)",
	   b.sigma * 1e-6, b.t * 1e6, best * 1e-6, berr * 1e-6, tb * 1e6,
	   100 * (b.sigma / best - 1), 100 * ANVIL_PLATE_BENDING_TOL);
	anvil_field_free(f);
	anvil_result_free(&r);
	anvil_solver_free(s);
}

/* The 500 g hammer on 1 mm sheet at 1 m/s (issue 11): a long contact. */
static void verdict(void)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err e = {0};
	struct anvil_verdict v, d;
	struct anvil_result r;
	char line[512];
	anvil_scene_default(&sc);
	anvil_scene_set(&sc, "layer.thickness", "1mm", NULL, 0, &e);
	anvil_scene_set(&sc, "impactor.mass", "500g", NULL, 0, &e);
	anvil_scene_set(&sc, "impact.velocity", "1m/s", NULL, 0, &e);
	int st = scene_plan(&sc, &pl, &e);
	struct anvil_solver *s = anvil_solver_alloc();
	st = st ? st : anvil_solver_verdict(s, &pl, &d, &e);
	anvil_verdict_text(&d, line, sizeof line);
	diag("%s", line);
	ok(st >= 0 && d.qs_ratio > ANVIL_VERDICT_QS_RATIO && d.bend_state == 1 && d.bend > 0,
	   "long contact on 1 mm: the bending stress checked (%s)", e.msg);
	char acc[64];
	snprintf(acc, sizeof acc, "(Kirchhoff plate, within %.0f %%)", 100 * ANVIL_PLATE_BENDING_TOL);
	ok(strstr(line, "bending stress at the far face") && strstr(line, acc) &&
		   !strstr(line, "not checked"),
	   "  the line names the stress and its accuracy");
	/* the same through the parts, and the fate on the larger stress: a
	 * yield stress between the contact's and the bending's */
	st = anvil_solver_run(s, &pl, ANVIL_MODEL_LAYER, ANVIL_VERDICT_NHIST, &r, &e);
	anvil_verdict_at(&pl.pb, r.Pmax.val, r.tmax.val, &v);
	v.qs_ratio = d.qs_ratio;
	anvil_verdict_bending(&pl.pb, &r.hist, &v);
	is_rel(v.bend, d.bend, 1e-12, "  the parts give the same %.4g MPa", v.bend * 1e-6);
	pl.pb.layer.yield = sqrt(v.stress * v.bend);
	anvil_verdict_at(&pl.pb, r.Pmax.val, r.tmax.val, &v);
	int before = v.fate;
	anvil_verdict_bending(&pl.pb, &r.hist, &v);
	int bend_larger = v.bend > v.stress;
	ok(before == (bend_larger ? ANVIL_HERTZ_ELASTIC : ANVIL_HERTZ_YIELDS) &&
		   v.fate == ANVIL_HERTZ_YIELDS,
	   "  Y between %.3g (contact) and %.3g MPa (bending): yields by the larger", v.stress * 1e-6,
	   v.bend * 1e-6);
	anvil_result_free(&r);
	anvil_solver_free(s);
	/* a thick plate: h = 5 r0 (12.2 g at 10 m/s), the history of its own
	 * row: a = 0.03 h */
	anvil_scene_default(&sc);
	anvil_scene_set(&sc, "layer.thickness", "5r0", NULL, 0, &e);
	st = scene_plan(&sc, &pl, &e);
	s = anvil_solver_alloc();
	st = st ? st : anvil_solver_run(s, &pl, ANVIL_MODEL_LAYER, ANVIL_VERDICT_NHIST, &r, &e);
	st = st < 0 ? st : anvil_verdict_at(&pl.pb, r.Pmax.val, r.tmax.val, &v);
	v.qs_ratio = 35; /* as a long contact's: the clause is printed */
	anvil_verdict_bending(&pl.pb, &r.hist, &v);
	anvil_verdict_text(&v, line, sizeof line);
	diag("%s", line);
	ok(!st && v.bend_state == -1 &&
		   strstr(line, "the plate's bending stress not checked: the contact radius a = "),
	   "h = 5 r0: not checked, and why");
	anvil_result_free(&r);
	anvil_solver_free(s);
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(14);
	step_load();
	against_field("h = 0.5 r0, 20 g at 10 m/s", "0.5r0", "20g");
	against_field("h = 0.3 r0, 50 g at 10 m/s", "0.3r0", "50g");
	verdict();
	return done_testing();
}
