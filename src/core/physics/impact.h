/* impact.h: the impactor coupled to the anvil through Hertz contact.
 *
 * Solves eq (40), V0 t - (1/m1) int (t-t') P dt' = k0 P^(2/3) + w(t), with
 * w the Duhamel convolution of P with the anvil's centre response, given as
 * its ramp response (response to P = t).  Two schemes:
 *
 * implicit (default): P piecewise linear in time; then the impactor's
 *   displacement and the layer's deflection at t_n are exact sums over past
 *   forces (the layer's through second differences of the ramp response,
 *   i.e. product integration), and eq (40) at each step is one scalar
 *   equation k0 P^(2/3) + B P = A_n with one positive root (a cubic in
 *   P^(1/3), solved by gsl_poly_solve_cubic).  Second order in dt; run at
 *   dt and dt/2 and Richardson-extrapolated, which also gives the error.
 * The past enters through an online fast convolution (fastconv.h),
 * O(N log^2 N): 10^6 steps take about 2 s.
 * In a long first contact the step doubles where the force is smooth
 * (grow_after, grow_eta below; impact_grow.c), the product integration
 * staying exact; the dt/2 pass follows the same steps halved.
 *
 * Repeated contacts (implicit): where alpha_H would be <= 0 the force is 0
 * and the march goes on, the impactor in free flight and the layer in its
 * free response (the convolution of the past force), through every new
 * contact, until the two have parted for good: out of contact, the
 * impactor moving away (v < 0), the gap opening, and the impactor outward
 * of both the surface and the surface's late position (the impulse times
 * the displacement impulse response at the window's end: alpha* I for a
 * plate, ~0 for a half-space) by a tenth of the largest Hertz compression;
 * or, failing that, out of contact and moving away at the window's end
 * (the decision is recorded: t_free in the result, the time followed to).
 * A contact or an impactor moving in at the window's end is ANVIL_ETOL
 * with t_s NaN (the caller grows the window).  Each contact's start is
 * where alpha_H rises through 0 (linear between steps), its end found as
 * for one contact; t_s is the end of the last contact, V_s, R_f and E_a
 * are from the final velocity, the history spans [0, t_s] with P = 0
 * between contacts.
 *
 * paper: the explicit, lagged scheme of eqs (42)-(46), first order, kept to
 *   show how the paper's printed numbers depend on its step. */
#ifndef ANVIL_IMPACT_H
#define ANVIL_IMPACT_H

#include <stddef.h>

#include "params.h"
#include "result.h"
#include "options.h"

/* The anvil's dimensionless centre ramp response mu c2 Rr(t) at
 * tau = t c2/r0.  Returns ANVIL_EINVAL beyond the response's window. */
typedef int (*anvil_ramp_fn)(void *ctx, double tau, double *val);

struct anvil_impact_opts {
	enum anvil_scheme scheme;
	double dt;        /* s; 0: dt_auto */
	double dt_auto;   /* s; the step when dt = 0 (the caller's choice) */
	size_t max_steps; /* refuse (ANVIL_ETOL) a run needing more steps */
	size_t nhist;     /* history samples wanted (0: none) */
	/* 1: the history is the pass's own nodes before t_s and the end state
	 * at t_s (nhist unused): what an error run's comparisons need
	 * (engine/solver_twin.c), without resampling millions of samples;
	 * anvil_impact_history_resample makes the caller's from it. */
	int hist_nodes;
	int single;       /* 1: one pass at dt, no extrapolation (to test the order) */
	size_t direct_max; /* the convolution's direct squares (fastconv.h): 0 default,
			    * (size_t)-1 the whole O(N^2) direct sum (to test) */
	/* The physical contact (issue 10, doc/contact-model.md), implicit
	 * scheme only: W = alpha_H(P) + w_c - beta Q.  The ramp given is then
	 * the layer correction of a point load alone (w_c; a zero ramp for a
	 * half-space), not the full response: the static indentation is
	 * Hertz's, and the half-space's dynamic remainder is the radiation lag
	 * -beta dP/dt (beta = xi(nu)/(rho c2^3), m s/N, transform/radiation.h),
	 * with dP/dt reduced in order to Q = (3/2) K alpha^(1/2) (v - dw_c/dt),
	 * which keeps the scheme stable and second order.  The history's w is
	 * the remainder w_c - beta Q. */
	int physical;
	double beta;
	/* The remainder's next term (physical only; 0: first order), g2 =
	 * gamma / (mu c2^2) in s^4/(kg m) (transform/radiation.h): + g2
	 * d^2(a P)/dt^2, with the first-order reduction's own next term,
	 * reduced in order as the lag (impact.c, pass_physical).  Its effect
	 * is O(f^2) of the wave effect's f; what it leaves, O(f^3), and the
	 * start and end it cannot place (the contact spreading faster than the
	 * waves) are the caller's estimate (solver_phys.c).  It takes d^2w_c/dt^2
	 * through tau_lag's low-pass twice, so g2 > 0 needs tau_lag > 0 (any
	 * value on a half-space, where w_c = 0). */
	double g2;
	/* The true contact radius (physical only; alpha_ref = 0: a point load).
	 * ramp2 is the correction for a Hertz patch of radius a_ref, alpha_ref
	 * = a_ref^2 / R its approach.  The correction is even in the patch
	 * radius, w(a) = w(0) + a^2 w2 + O(a^4), and the load applied at t' has
	 * the radius a(t'), a^2 = R alpha_H(t'): so each past load acts through
	 * ramp + (alpha_H(t')/alpha_ref) (ramp2 - ramp), the true radius to
	 * O(a^4).  The caller estimates that remainder (solver_phys.c).  The past's
	 * sums are online fast convolutions (fastconv.h) of P against ramp's
	 * weights and of the loads' alpha_H/alpha_ref P against ramp2's less
	 * ramp's; the physical pass follows repeated contacts as the implicit
	 * one does (P = 0 and no lag out of contact). */
	anvil_ramp_fn ramp2;
	void *ramp2_ctx;
	double alpha_ref;
	/* The radiation lag's derivative of the layer correction, low-passed
	 * (physical only; s; 0: the plain BDF2 derivative).  Q holds dw_c/dt,
	 * and w_c follows P through the correction's sharp first arrival, so
	 * -beta Q feeds a delayed derivative of P back into the contact: a
	 * neutral delay equation whose gain grows like omega without bound
	 * (beta k^2 |omega G(omega)|, k = dP/dalpha, G the correction's
	 * transfer function), reached in the scheme at the Nyquist frequency
	 * through BDF2's 4/dt: P alternates and blows up (thin layers,
	 * h = 0.35 r0 at 10 m/s).  The lag -beta dP/dt is itself only the
	 * low-frequency term of the half-space's remainder, valid for
	 * omega a/c2 << 1 (radiation.h: the next term is relative O(omega
	 * a/c2)); the true remainder saturates above c2/a.  So dw_c/dt enters
	 * Q through the first-order low-pass 1/(1 + i omega tau_lag), tau_lag =
	 * a_max/c2 (the caller's), discretised by the trapezoidal rule, whose
	 * gain is at most 1/tau_lag at every frequency up to Nyquist: the loop
	 * gain is then at most beta k^2 sup|G| / tau_lag, of order 0.01 a/h,
	 * whatever dt.  The change is of the order the lag's own next term;
	 * the caller measures it by halving tau_lag (solver_phys.c). */
	double tau_lag;
	/* Separations below the scheme's resolution (implicit and physical;
	 * 0: none merged).  A separation whose gap never exceeds merge_gap
	 * times the largest Hertz compression alpha_max and which ends (the
	 * bodies touch again) within merge_time seconds is no separation: the
	 * two passes (dt and dt/2) see the same bodies moving together, the
	 * contact goes on, its count and times do not change, and no end is
	 * searched for it.  The caller sets merge_gap to the level's target
	 * (the relative accuracy the level promises for alpha) and merge_time
	 * to two of the coarse pass's steps (a shorter separation has no node
	 * of its own in that pass), the same for both passes, so that they
	 * count the same contacts.  R_f, V_s and E_a come from the last
	 * separation that is resolved, t_s its end. */
	double merge_gap;
	double merge_time;
	/* The budget: more contacts than this (after merging) is ANVIL_ETOL
	 * with t_s = inf (no longer window helps) and a one-line reason; 0:
	 * none. */
	size_t max_contacts;
	/* The rest state (implicit and physical; 0: off; impact_rest.c).  Once
	 * the bodies co-move (together again after a separation, merged or
	 * not), the rebound the impactor can still reach is bounded by
	 * R_f <= (|v| + sqrt(2 (E_H + E_L) / m1)) / V0, E_H the Hertz spring's
	 * energy and E_L the layer's local strain energy beyond the plate's
	 * dashpot.  The first node where it is within rest_tol is kept, and
	 * where the run would be refused (more contacts than the budget, a
	 * later contact's end lost; with rest_last, a contact outlasting the
	 * window) the passes end there
	 * instead: R_f is reported as the interval [0, bound] (its midpoint,
	 * +- half of it), E_a likewise, t_s is the time the rest was
	 * recognised (the contact has not ended), and r->rest_bound says so.
	 * A run that ends by itself is not changed.  The caller sets rest_tol
	 * below the level's target on R_f. */
	double rest_tol;
	int rest_last; /* 1: the caller's last window (a contact at its end falls back to rest) */
	/* s; > 0: the passes stop at rest at this time whatever the bound
	 * (the error-estimate runs of a row at rest are compared with it at
	 * its own time, not at wherever their bound happens to fall). */
	double rest_at;
	/* The growing step (implicit and physical; impact_grow.c): past
	 * grow_after steps (0: never) of the first contact, where P is smooth
	 * (four times its second difference over the last 16 steps at most
	 * grow_eta P: the doubled step sees no rougher a force than the
	 * level's step sees a Hertz pulse when grow_eta = (pi/nsteps)^2), the
	 * step doubles, again and again; the product integration stays exact
	 * (the frozen past on the new grid, impact_grow.c).  The dt/2 pass
	 * follows the dt pass's schedule with halved steps.  max_steps then
	 * bounds the window's steps at dt (the response's table), the nodes
	 * actually marched are fewer. */
	size_t grow_after;
	double grow_eta;
	/* Long windows (implicit and physical, with grow_after; impact_grow.c):
	 * s; > 0: the ramps are smooth (no band-limited ringing: the layer
	 * response's plate model, green.h anvil_green_t_plate) at lags beyond
	 * t_smooth.  A frozen segment's hats seen from many times their span
	 * away (and beyond 2 t_smooth) then enter as a few charges at
	 * Chebyshev points against the impulse response (the far field), not
	 * as fine-grid weights out to the window's end, and a window of more
	 * than max_steps steps at dt runs (long mode): max_steps then bounds
	 * the nodes the grown march makes (ANVIL_ETOL when it needs more).
	 * 0: never (such a window is refused before any work).  In a window
	 * that fits, > 0 asks for the far field too, from further out
	 * (impact_far.c, FAR_MIN_FIT): a saving, the results within its
	 * small error of the weights' sums. */
	double t_smooth;
	/* Optional (the far field, t_smooth): the ramps' second derivatives, the impulse
	 * responses (dimensionless, as the ramps), for the far field beyond
	 * t_smooth; a call that fails (or none given) leaves the far field to
	 * a wide difference of the ramp (seven calls, impact_grow.c). */
	anvil_ramp_fn impulse, impulse2;
	void *impulse_ctx, *impulse2_ctx;
	/* Optional: the ramps' values at the grid's times shared with the
	 * caller's other impacts (anvil_ramp_share; NULL: this impact's own).
	 * ramp_name and ramp2_name are then the caller's names of ramp and
	 * ramp2 (for the physical row: its response's omega_idx, tau_idx,
	 * patch): impacts of the same share, step and window whose ramps
	 * have one name must have the same ramp (the same values), and
	 * different ramps different names. */
	struct anvil_ramp_share *share;
	double ramp_name[3], ramp2_name[3];
};

/* The ramps' tables that impacts share (impact_rtab.c): a ramp's value
 * at a time of the grid, made by one impact, is read by the others that
 * have the same ramp and step (the same bits as their own call).  Impacts
 * given one share may run side by side on threads.  NULL when out of
 * memory; anvil_ramp_share_free(NULL) is a no-op. */
struct anvil_ramp_share;
struct anvil_ramp_share *anvil_ramp_share_alloc(void);
void anvil_ramp_share_free(struct anvil_ramp_share *s);

/* Run the coupled impact.  ramp covers tau in [0, tau_avail]; when the
 * contact outlasts it, ANVIL_ETOL is returned with r->ts.val = NaN so that the
 * caller can extend the response and retry.  r must be initialised. */
/* The history of nhist samples (result.h's spacing, the warp from the
 * force's peak as a run's own) resampled linearly from a node history
 * (anvil_impact_opts.hist_nodes); ANVIL_ENOMEM. */
int anvil_impact_history_resample(const struct anvil_history *nodes, size_t nhist,
				  struct anvil_history *h);
int anvil_impact_run(const struct anvil_params *p, anvil_ramp_fn ramp, void *ctx,
		     double tau_avail, const struct anvil_impact_opts *o,
		     struct anvil_result *r, struct anvil_err *err);

#endif
