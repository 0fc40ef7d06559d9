/* verdict_text.c: the verdict in words, for a line and for a screen
 * (verdict.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "verdict.h"

/* A stress in MPa below 1 GPa, else GPa, 3 significant digits. */
static void stress_text(double s, char *buf, size_t n)
{
	if (fabs(s) >= 1e9)
		snprintf(buf, n, "%.3g GPa", s * 1e-9);
	else
		snprintf(buf, n, "%.3g MPa", s * 1e-6);
}

/* With the bending checked, the near face's sum (near_face) stands for
 * the contact's own stress: the one shown under the contact. */
static int near_shown(const struct anvil_verdict *v)
{
	return v->bend_state == 1;
}

/* The bending clause (a long contact's, the TUI's on any plate): the
 * plate's bending stress and its accuracy, or why it was not checked. */
static void bending_text(const struct anvil_verdict *v, char *buf, size_t n)
{
	char s[32];
	if (v->bend_state != 1) {
		snprintf(buf, n, "; the plate's bending stress not checked%s%s",
			 v->bend_why[0] ? ": " : "", v->bend_why);
		return;
	}
	stress_text(v->bend, s, sizeof s);
	snprintf(buf, n, "; bending stress at the far face %s at t = %.3g us (Kirchhoff plate, "
		 "within %.0f %%)%s", s, v->bend_t * 1e6, 100 * v->bend_tol,
		 v->known && v->bend > v->near ? ", the larger: judged on it" : "");
}

static const char *fate_word(enum anvil_hertz_fate fate, int known)
{
	return fate == ANVIL_HERTZ_YIELDS   ? "yields"
	       : fate == ANVIL_HERTZ_CRACKS ? "cracks"
	       : !known                     ? "is not judged"
					    : "stays elastic";
}

/* Where the layer's stress under the contact peaks: the contact's own, or
 * with the bending the near face's sum. */
static void layer_where(const struct anvil_verdict *v, char *buf, size_t n)
{
	double a = v->a, r = v->r, z = v->z;
	if (near_shown(v)) {
		/* the sum's contact is a(near_t), not a(t_max): its own a */
		r = v->near_r;
		z = v->near_z;
		if (z <= 0.02 * a && fabs(r - a) <= 0.05 * a) {
			snprintf(buf, n, "at the near face's contact edge r = %.3g mm", r * 1e3);
			return;
		}
		if (z <= 0.02 * a) {
			snprintf(buf, n, "on the near face at r = %.3g mm", r * 1e3);
			return;
		}
		if (fabs(r - a) <= 0.25 * a && z <= 0.25 * a) {
			snprintf(buf, n, "just below the near face's contact edge, r = %.3g mm, "
				 "z = %.3g mm", r * 1e3, z * 1e3);
			return;
		}
	} else if (v->brittle) {
		snprintf(buf, n, "at the contact edge r = a = %.3g mm", a * 1e3);
		return;
	}
	if (r <= 0.5 * a)
		snprintf(buf, n, "at %.2g a = %.3g mm below the contact", a > 0 ? z / a : 0, z * 1e3);
	else
		snprintf(buf, n, "at r = %.3g mm, z = %.3g mm", r * 1e3, z * 1e3);
}

/* The criterion's words for the stress under the contact. */
static const char *layer_what(const struct anvil_verdict *v)
{
	if (!v->brittle)
		return "peak von Mises";
	return near_shown(v) ? "largest tension" : "edge tension (1-2nu) p0/3";
}

/* Which force the quasi-static Hertz field is at ("" when the row's
 * own): after "quasi-static Hertz". */
static void qs_force(const struct anvil_verdict *v, char *buf, size_t n)
{
	if (v->qs_why == ANVIL_VERDICT_QS_LONG)
		snprintf(buf, n, " at the layer's computed P_max: the contact lasts %.2g times 2h/c1",
			 v->qs_ratio);
	else if (v->qs_why == ANVIL_VERDICT_QS_GENTLE)
		snprintf(buf, n, " at the layer's computed P_max: the waves would carry off %.2g %% of "
			 "the impact energy", 100 * v->qs_radiated);
	else if (v->qs_why == ANVIL_VERDICT_QS_BLOCK && v->qs_bending > 0)
		snprintf(buf, n, " at the layer's computed P_max: the plate's bending changes the impact "
			 "by %.2g %%, the waves would carry off %.2g %% of its energy",
			 100 * v->qs_bending, 100 * v->qs_radiated);
	else if (v->qs_why == ANVIL_VERDICT_QS_BLOCK)
		snprintf(buf, n, " at the half-space's computed P_max: it does not bend, the waves "
			 "would carry off %.2g %% of the impact energy", 100 * v->qs_radiated);
	else
		snprintf(buf, n, "%s", v->at_row ? " at the layer's computed P_max" : "");
}

/* With the bending: the contact's own stress, which it no longer is, after
 * the field's name ("" without). */
static void alone_text(const struct anvil_verdict *v, const char *f, char *buf, size_t n)
{
	char s[32];
	if (!near_shown(v)) {
		snprintf(buf, n, "%s", f);
		return;
	}
	stress_text(v->stress, s, sizeof s);
	snprintf(buf, n, "; the contact alone %s, t = %.3g us,%s", s, v->t * 1e6,
		 f[0] ? f : " at its peak");
}

void anvil_verdict_text(const struct anvil_verdict *v, char *buf, size_t n)
{
	char s[32], l[32], where[96], f[192], al[256], qs[384] = "";
	int ns = near_shown(v);
	stress_text(ns ? v->near : v->stress, s, sizeof s);
	stress_text(v->limit, l, sizeof l);
	layer_where(v, where, sizeof where);
	qs_force(v, f, sizeof f);
	alone_text(v, f, al, sizeof al);
	if (!v->dynamic)
		snprintf(qs, sizeof qs, " (quasi-static Hertz%s%s)",
			 ns ? " with the plate's bending at the same instant" : "", al);
	char bend[224] = "";
	if (v->bend_state != 0) /* tried: a long contact's (yield.c) or the TUI's */
		bending_text(v, bend, sizeof bend);
	snprintf(buf, n, "the %s layer %s: %s %s %s at t = %.3g us, %s%s%s%s%s", v->material,
		 fate_word(v->fate, v->known), layer_what(v), s, where,
		 (ns ? v->near_t : v->t) * 1e6, v->brittle ? "tensile strength " : "Y = ",
		 v->known ? l : "unknown", qs,
		 !v->known ? (v->brittle ? ": set layer.tensile" : ": set layer.yield") : "", bend);
}

void anvil_verdict_text_screen(const struct anvil_verdict *v, char *buf, size_t n)
{
	char s[32], l[32], where[96], f[192] = "", al[256] = "";
	int ns = near_shown(v);
	double t = ns ? v->near_t : v->t;
	const char *field = v->dynamic ? "the dynamic field"
			    : ns       ? "Hertz + plate bending"
				       : "quasi-static Hertz";
	stress_text(ns ? v->near : v->stress, s, sizeof s);
	stress_text(v->limit, l, sizeof l);
	layer_where(v, where, sizeof where);
	if (!v->dynamic)
		qs_force(v, f, sizeof f);
	alone_text(v, f, al, sizeof al);
	const char *what = v->brittle ? (ns ? "largest tension" : "edge tension (1-2nu) p0/3")
				      : "von Mises";
	char bend[224] = "";
	if (v->bend_state == 1 && v->known && v->bend > v->near) {
		/* judged on the bending: it leads, as a screen line is cut */
		char b[32];
		stress_text(v->bend, b, sizeof b);
		snprintf(buf, n, "layer %s (plate bending): %s at the far face, %s%s, t = %.3g us "
			 "(Kirchhoff plate, within %.0f %%); under the contact (%s) %s %s %s, t = %.3g us%s%s",
			 fate_word(v->fate, v->known), b, v->brittle ? "tensile strength " : "Y = ", l,
			 v->bend_t * 1e6, 100 * v->bend_tol, field, s, what, where, t * 1e6,
			 al[0] && al[0] != ';' ? ";" : "", al);
		return;
	}
	if (v->bend_state != 0)
		bending_text(v, bend, sizeof bend);
	snprintf(buf, n, "layer %s (%s): %s %s, %s%s%s, %s, t = %.3g us%s%s%s",
		 fate_word(v->fate, v->known), field, s, what,
		 v->brittle ? "tensile strength " : "Y = ", v->known ? l : "unknown",
		 !v->known ? (v->brittle ? " (set layer.tensile)" : " (set layer.yield)") : "",
		 where, t * 1e6, al[0] && al[0] != ';' ? ";" : "", al, bend);
}

void anvil_verdict_impactor_text(const struct anvil_verdict *v, char *buf, size_t n)
{
	const struct anvil_verdict_impactor *im = &v->imp;
	char s[32], l[32], where[96];
	const char *what = fate_word(im->fate, im->known);
	stress_text(im->stress, s, sizeof s);
	stress_text(im->limit, l, sizeof l);
	if (im->brittle)
		snprintf(where, sizeof where, "at the contact edge");
	else
		snprintf(where, sizeof where, "at %.2g a = %.3g mm inside its tip",
			 v->a > 0 ? im->z / v->a : 0, im->z * 1e3);
	snprintf(buf, n, "the %s impactor %s under the same contact: %s %s %s, %s%s%s", im->material,
		 what, im->brittle ? "edge tension (1-2nu) p0/3" : "peak von Mises", s, where,
		 im->brittle ? "tensile strength " : "Y = ", im->known ? l : "unknown",
		 !im->known ? (im->brittle ? ": set impactor.tensile" : ": set impactor.yield") : "");
}

void anvil_verdict_impactor_text_screen(const struct anvil_verdict *v, char *buf, size_t n)
{
	const struct anvil_verdict_impactor *im = &v->imp;
	char s[32], l[32];
	stress_text(im->stress, s, sizeof s);
	stress_text(im->limit, l, sizeof l);
	if (im->brittle)
		snprintf(buf, n, "impactor %s too: %s edge tension (1-2nu) p0/3, tensile strength %s%s, at the contact edge",
			 fate_word(im->fate, im->known), s, im->known ? l : "unknown",
			 im->known ? "" : " (set impactor.tensile)");
	else
		snprintf(buf, n, "impactor %s too: %s von Mises, Y = %s%s, at %.2g a = %.3g mm inside its tip",
			 fate_word(im->fate, im->known), s, im->known ? l : "unknown",
			 im->known ? "" : " (set impactor.yield)", v->a > 0 ? im->z / v->a : 0, im->z * 1e3);
}
