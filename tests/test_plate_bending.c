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
#include "hertz_field.h"
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

/* The bending's fall with r (plate_bending.c): the closed forms against
 * their defining integrals, M(0) - M(r) = int_0^r F/(2 pi rho) and the
 * disc mean, by QUADPACK; the near face's stresses follow. */
struct fall_ctx {
	double b;
};

static double load_inside(double rho, double b) /* F/P, the Hertz patch */
{
	double u = rho * rho / (b * b);
	return u < 1 ? 1 - pow(1 - u, 1.5) : 1;
}

static double delta_integrand(double rho, void *vp)
{
	const struct fall_ctx *c = vp;
	return rho > 0 ? load_inside(rho, c->b) / (2 * M_PI * rho) : 0;
}

static double delta_num(double r, double b)
{
	struct fall_ctx c = { b };
	gsl_function F = { delta_integrand, &c };
	gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
	double pts[3] = { 0, fmin(r, b), r }, v = 0, e, v2 = 0;
	gsl_integration_qag(&F, pts[0], pts[1], 1e-14, 1e-12, 200, GSL_INTEG_GAUSS41, ws, &v, &e);
	if (r > b)
		gsl_integration_qag(&F, pts[1], pts[2], 1e-14, 1e-12, 200, GSL_INTEG_GAUSS41, ws, &v2, &e);
	gsl_integration_workspace_free(ws);
	return v + v2;
}

struct mean_ctx {
	double b;
};

static double mean_integrand(double s, void *vp)
{
	const struct mean_ctx *c = vp;
	return delta_num(s, c->b) * s;
}

static void near_stress_fall(void)
{
	double nu = 0.3, h = 1, b = 0.4, P = 1, sb = 5;
	const double rs[] = { 0.02, 0.2, 0.4, 0.9 };
	double worst = 0;
	for (size_t i = 0; i < sizeof rs / sizeof rs[0]; i++) {
		double r = rs[i], srr, stt;
		anvil_plate_bending_near_stress(sb, P, b, nu, h, r, 0, &srr, &stt);
		/* by hand: Delta and E = disc mean of Delta less Delta (M = M0 - Delta) */
		struct mean_ctx c = { b };
		gsl_function F = { mean_integrand, &c };
		gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
		double m, e, D = delta_num(r, b);
		gsl_integration_qag(&F, 0, r, 1e-14, 1e-10, 200, GSL_INTEG_GAUSS41, ws, &m, &e);
		gsl_integration_workspace_free(ws);
		double E = D - 2 * m / (r * r), k = 6 / (h * h);
		double want_rr = -(sb - k * 0.5 * ((1 + nu) * D + (1 - nu) * E) * P);
		double want_tt = -(sb - k * 0.5 * ((1 + nu) * D - (1 - nu) * E) * P);
		worst = fmax(worst, fmax(fabs(srr - want_rr), fabs(stt - want_tt)) / sb);
	}
	ok(worst < 1e-9, "the near face's bending at r = 0.05-2.25 b: the closed forms as their "
	   "integrals to %.2g s_b", worst);
	double r = 0.01, srr, stt, q0 = 3 * P / (2 * M_PI * b * b);
	anvil_plate_bending_near_stress(sb, P, b, nu, h, r, 0, &srr, &stt);
	is_rel(srr + sb, 6 * (3 + nu) * q0 * r * r / 16, 1e-3,
	       "  near the centre M_r falls by (3 + nu) q0 r^2/16 (Timoshenko's uniform load)");
	anvil_plate_bending_near_stress(sb, P, b, nu, h, 0, 0.25 * h, &srr, &stt);
	is_rel(srr, -0.5 * sb, 1e-14, "  linear through the thickness: -s_b/2 at z = h/4");
}

/* The near face's peak (anvil_plate_bending_near) in units a = p0 = 1,
 * the plate thick and its patch wide so the bending is -s_b in r and
 * theta where the contact's field lives. */
static void near_face(void)
{
	const double nu = 0.3, h = 1e3, b = 100, P = 2 * M_PI / 3, t = (1 - 2 * nu) / 3;
	struct anvil_plate_near n;
	anvil_plate_bending_near(1, 1, nu, h, P, b, 0, 0, &n);
	is_rel(n.stress, 0.620041, 1e-6, "s_b = 0: Hertz's own peak, 0.620 p0");
	is_abs(n.z, 0.480864, 1e-4, "  at z = %.5f a on the axis (r = %.2g a)", n.z, n.r);
	anvil_plate_bending_near(1, 1, nu, h, P, b, 0, 1, &n);
	/* to 1e-8: the plate's own fall at r = a, 1e-10 p0 here, is in it */
	ok(fabs(n.stress - t) < 1e-8 * t && fabs(n.r - 1) < 1e-6 && n.z < 1e-6,
	   "  brittle: (1 - 2 nu) p0/3 at r = a, z = 0");
	anvil_plate_bending_near(1, 1, nu, h, P, b, 0.1, 1, &n);
	ok(fabs(n.stress - (t - 0.1)) < 1e-6 && fabs(n.r - 1) < 1e-6 && n.z < 1e-6,
	   "  and the bending relieves it: t - s_b = %.5f p0 (%.5f)", t - 0.1, n.stress);
	anvil_plate_bending_near(1, 1e-9, nu, h, P * 1e-9, b, 1, 0, &n);
	is_rel(n.stress, 1, 1e-6, "P -> 0: the bending alone, von Mises s_b (the far face's)");
	anvil_plate_bending_near(1, 1, nu, h, P, b, 0.1, 0, &n);
	ok(n.stress < 0.620041 && n.stress > 0.620041 - 0.1 && n.r < 1e-3,
	   "s_b = 0.1 p0: on the axis the bending relieves Hertz's peak (%.5f p0)", n.stress);
	/* s_b = 0.62 p0: at the edge sqrt(3 t^2 + s_b^2), 6.7 % above both; just
	 * below it the sum peaks higher (verdict.c) */
	double sb = 0.62;
	anvil_plate_bending_near(1, 1, nu, h, P, b, sb, 0, &n);
	struct anvil_hertz_stress hs;
	anvil_hertz_stress(1, 1, nu, n.r, n.z, &hs);
	double g = hs.rr + hs.tt - 2 * hs.zz, beta = -sb * (1 - 2 * n.z / h);
	is_rel(n.stress, sqrt(hs.vm * hs.vm + beta * g + beta * beta), 1e-6,
	       "s_b = 0.62 p0: the peak %.5f p0 is vm^2 = vm_H^2 + beta g + beta^2 by hand", n.stress);
	ok(n.stress > 1.14 * fmax(0.620041, sb) && n.stress > sqrt(3 * t * t + sb * sb) &&
		   fabs(n.r - 1.046) < 0.01 && fabs(n.z - 0.079) < 0.01,
	   "  14 %% above both (%.4f), above the edge's sqrt(3 t^2 + s_b^2) = %.4f, at r = %.3f a, "
	   "z = %.3f a", n.stress / fmax(0.620041, sb), sqrt(3 * t * t + sb * sb), n.r, n.z);
}

/* 1 kg at 3 m/s on h = 0.12 r0: the contact alone and the far face are
 * both below the near face's sum, which the verdict judges on. */
static void near_governs(void)
{
	struct anvil_scene sc;
	struct anvil_plan pl;
	struct anvil_err e = {0};
	struct anvil_verdict v;
	struct anvil_result r;
	char line[ANVIL_VERDICT_TEXT_MAX];
	anvil_scene_default(&sc);
	anvil_scene_set(&sc, "layer.thickness", "0.12r0", NULL, 0, &e);
	anvil_scene_set(&sc, "impactor.mass", "1kg", NULL, 0, &e);
	anvil_scene_set(&sc, "impact.velocity", "3m/s", NULL, 0, &e);
	anvil_scene_set(&sc, "solver.accuracy", "draft", NULL, 0, &e);
	int st = scene_plan(&sc, &pl, &e);
	struct anvil_solver *s = anvil_solver_alloc();
	st = st ? st : anvil_solver_run(s, &pl, ANVIL_MODEL_LAYER, ANVIL_VERDICT_NHIST, &r, &e);
	st = st < 0 ? st : anvil_verdict_at(&pl.pb, r.Pmax.val, r.tmax.val, &v);
	anvil_verdict_bending(&pl.pb, &r.hist, &v);
	ok(!st && v.bend_state == 1 && v.near > 1.05 * fmax(v.stress, v.bend),
	   "h = 0.12 r0: the near face's sum %.4g GPa above the contact alone %.4g and the far "
	   "face %.4g", v.near * 1e-9, v.stress * 1e-9, v.bend * 1e-9);
	/* by hand at its instant and point: Hertz at P(t) plus the bending */
	const struct anvil_params *p = &pl.pb.p;
	double P = anvil_history_at(&r.hist, r.hist.P, v.near_t);
	double a = sqrt(p->r0 * pow(P / p->K, 2.0 / 3.0)), p0 = 1.5 * P / (M_PI * a * a), srr, stt;
	double b = anvil_plate_bending_patch(p, ANVIL_PLATE_PATCH_TRUE, 0, P), sb, err;
	anvil_plate_bending_at(p, &r.hist, ANVIL_PLATE_PATCH_TRUE, 0, v.near_t, &sb, &err);
	struct anvil_hertz_stress hs;
	anvil_hertz_stress(a, p0, p->nu, v.near_r, v.near_z, &hs);
	anvil_plate_bending_near_stress(sb, P, b, p->nu, p->h, v.near_r, v.near_z, &srr, &stt);
	double x = hs.rr + srr - hs.tt - stt, y = hs.tt + stt - hs.zz, z = hs.zz - hs.rr - srr;
	double vm = sqrt(0.5 * (x * x + y * y + z * z) + 3 * hs.rz * hs.rz);
	is_rel(v.near, vm, 1e-9, "  by hand at t = %.4g us, r = %.3g a, z = %.3g a: %.4g GPa",
	       v.near_t * 1e6, v.near_r / a, v.near_z / a, vm * 1e-9);
	is_rel(sb, v.near_sb, 1e-12, "  with the far face's s_b at that instant, %.4g GPa (s_b/p0 = %.2f)",
	       sb * 1e-9, sb / p0);
	pl.pb.layer.yield = 0.5 * (v.near + fmax(v.stress, v.bend));
	anvil_verdict_at(&pl.pb, r.Pmax.val, r.tmax.val, &v);
	anvil_verdict_bending(&pl.pb, &r.hist, &v);
	anvil_verdict_text(&v, line, sizeof line);
	diag("%s", line);
	ok(v.fate == ANVIL_HERTZ_YIELDS && strstr(line, "near face's contact edge") &&
		   strstr(line, "with the plate's bending at the same instant; the contact alone") &&
		   !strstr(line, "judged on it"),
	   "  Y between: yields on the sum, and the line says where");
	anvil_result_free(&r);
	anvil_solver_free(s);
}

int main(void)
{
	gsl_set_error_handler_off();
	plan(29);
	step_load();
	against_field("h = 0.5 r0, 20 g at 10 m/s", "0.5r0", "20g");
	against_field("h = 0.3 r0, 50 g at 10 m/s", "0.3r0", "50g");
	verdict();
	near_stress_fall();
	near_face();
	near_governs();
	return done_testing();
}
