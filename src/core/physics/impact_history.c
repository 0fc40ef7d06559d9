/* impact_history.c: an impact pass's history (result.h): its nodes
 * resampled onto the spacing result.h gives (the charts' and the caller's
 * samples), or kept as they are (an error run's, impact.h hist_nodes). */
#include <math.h>

#include "impact.h"
#include "impact_impl.h"

/* The time of the peak force of n nodes P at times t (NULL: k dt), for
 * the history's spacing (result.h): the rise's, where the force first
 * reached 0.9 of its peak, when that is under a quarter of the peak's
 * time (a flat top: a 10 kg impactor at 10 m/s on h = 0.02 r0 rose to
 * 6.26 N in 1 us, then crept to its peak, 6.27 N, at 274 us, and the
 * history's first sample at 5.5 us left the rise out of the charts); a
 * pulse that rises as Hertz's (0.9 at 0.71 of t_max) keeps its peak's
 * time. */
static double peak_time(size_t n, const double *P, const double *t, double dt)
{
	size_t kp = 0, k9 = 0;
	for (size_t k = 1; k < n; k++)
		if (P[k] > P[kp])
			kp = k;
	while (k9 < kp && !(P[k9] >= 0.9 * P[kp]))
		k9++;
	double tp = t ? t[kp] : (double)kp * dt;
	double t9 = t ? t[k9] : (double)k9 * dt;
	return t9 > 0 && t9 < 0.25 * tp ? t9 : tp;
}

static double pass_peak_time(const struct pass *s)
{
	return peak_time(s->n, s->P, s->nseg == 1 ? NULL : s->t, s->dt);
}

/* Sample i of n over [0, ts] (anvil_history_time's times with its
 * divisor sb = sinh(beta) made once: the same expression, the same bits;
 * it made it for every sample, and an error run's history had up to 4e6
 * of them, where two sinh a sample took a third of the run). */
static double sample_time(size_t i, size_t n, double ts, double beta, double sb)
{
	double n1 = (double)(n - 1);
	if (i + 1 >= n)
		return ts;
	if (!(beta > 0))
		return ts * (double)i / n1;
	return ts * sinh(beta * ((double)i / n1)) / sb;
}

/* The pass's node k before t and the fraction f of the way to k + 1 (t
 * rises from call to call: *kprev, the last k, the walk's start). */
static size_t pass_locate(const struct pass *s, double t, size_t *kprev, double *f)
{
	size_t k;
	if (s->nseg == 1) {
		double x = t / s->dt;
		k = (size_t)floor(x);
		if (k + 1 >= s->n)
			k = s->n - 2;
		*f = x - (double)k;
	} else { /* a grown step: the node before t */
		for (k = *kprev; k + 2 < s->n && s->t[k + 1] <= t; k++)
			;
		*f = (t - s->t[k]) / (s->t[k + 1] - s->t[k]);
	}
	*kprev = k;
	return k;
}

/* Sample i of h at t, the fraction f of the way from node k to k + 1 of
 * the force P, displacements W, w and velocity v (the force not below 0:
 * it is a contact's). */
static void lerp_sample(struct anvil_history *h, size_t i, double t, double f, size_t k,
			const double *P, const double *W, const double *w, const double *v)
{
	h->t[i] = t;
	h->P[i] = fmax(0.0, (1 - f) * P[k] + f * P[k + 1]);
	h->W[i] = (1 - f) * W[k] + f * W[k + 1];
	h->w[i] = (1 - f) * w[k] + f * w[k + 1];
	h->v[i] = (1 - f) * v[k] + f * v[k + 1];
	h->alpha[i] = h->W[i] - h->w[i];
}

/* Sample i of h: the pass at t, linear between its nodes. */
static void pass_sample(const struct pass *s, double t, size_t *kprev, struct anvil_history *h,
			size_t i)
{
	double f;
	size_t k = pass_locate(s, t, kprev, &f);
	lerp_sample(h, i, t, f, k, s->P, s->W, s->w, s->v);
}

/* The exact end state at the history's last sample (at rest: none). */
static void end_state(const struct pass *s, struct anvil_history *h)
{
	size_t n = h->n;
	if (!n || s->rest)
		return;
	h->P[n - 1] = 0;
	h->v[n - 1] = -s->Vs;
	h->alpha[n - 1] = 0;
	h->W[n - 1] = h->w[n - 1];
}

/* Linear resampling of a pass onto nhist points over [0, t_s], spaced as
 * result.h says. */
int impact_resample(const struct pass *s, size_t nhist, struct anvil_history *h)
{
	int st = anvil_history_alloc(h, nhist);
	size_t kprev = 0;
	double beta = anvil_history_warp(pass_peak_time(s), s->ts);
	double sb = beta > 0 ? sinh(beta) : 0.0;
	for (size_t i = 0; !st && i < nhist; i++)
		pass_sample(s, sample_time(i, nhist, s->ts, beta, sb), &kprev, h, i);
	if (!st)
		end_state(s, h);
	return st;
}

/* The pass's nodes before t_s and its end state at t_s
 * (anvil_impact_opts.hist_nodes): the functions an error run's
 * comparisons interpolate, exactly (the samples impact_resample makes lie on
 * them), in as many samples as the pass has nodes. */
int impact_node_history(const struct pass *s, struct anvil_history *h)
{
	size_t K = 0, kprev = 0;
	while (K + 1 < s->n && (s->nseg == 1 ? (double)K * s->dt : s->t[K]) < s->ts)
		K++;
	if (K < 1 || anvil_history_alloc(h, K + 1))
		return K < 1 ? ANVIL_ENUM : ANVIL_ENOMEM;
	for (size_t k = 0; k < K; k++) {
		h->t[k] = s->nseg == 1 ? (double)k * s->dt : s->t[k];
		h->P[k] = s->P[k];
		h->W[k] = s->W[k];
		h->w[k] = s->w[k];
		h->v[k] = s->v[k];
		h->alpha[k] = s->W[k] - s->w[k];
	}
	kprev = K - 1;
	pass_sample(s, s->ts, &kprev, h, K);
	end_state(s, h);
	return ANVIL_OK;
}

int anvil_impact_history_resample(const struct anvil_history *nd, size_t nhist,
				  struct anvil_history *h)
{
	size_t m = nd->n, k = 0;
	if (m < 2)
		return ANVIL_EINVAL;
	int st = anvil_history_alloc(h, nhist);
	double ts = nd->t[m - 1], beta = anvil_history_warp(peak_time(m, nd->P, nd->t, 0), ts);
	double sb = beta > 0 ? sinh(beta) : 0.0;
	for (size_t i = 0; !st && i < nhist; i++) {
		double t = sample_time(i, nhist, ts, beta, sb);
		while (k + 2 < m && nd->t[k + 1] <= t)
			k++;
		double f = (t - nd->t[k]) / (nd->t[k + 1] - nd->t[k]);
		lerp_sample(h, i, t, f, k, nd->P, nd->W, nd->w, nd->v);
	}
	return st;
}
