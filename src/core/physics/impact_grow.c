/* impact_grow.c: a time step that grows where the force is smooth (issue 11).
 *
 * The step of a pass is dt0 2^L on segments of nodes; every node is a
 * multiple of dt0, so every lag between a node and a hat's corner is one,
 * and the ramp response at j dt0 (the ramps' table, impact_wts.c) gives every weight of
 * every level exactly: the hat of widths (l, r) at t_m deflects the anvil
 * at t by (R(t - t_m + l) - R(t - t_m))/l - (R(t - t_m) - R(t - t_m - r))/r.
 * The product integration stays exact (P piecewise linear through its
 * nodes, of any spacing): no interpolation of the history.  (That hat as
 * R/l - R (1/l + 1/r) + R/r rounds by eps R/dt the same way for every hat
 * of a width: a bias growing as R with the lag, which put a grazing end
 * 1e-4 off, five times its estimate; tests/test_grow.c.)
 *
 * At a switch (node n_s, level L -> L + 1) the past is frozen: its nodes
 * up to n_s (n_s's hat with the old step left and the new one right) enter
 * every later deflection through impact_hist: each frozen segment's hats
 * against its own level's weights (every later node lies on its grid: the
 * levels only rise), and its last node's asymmetric hat.  It is made in
 * chunks as the march reaches them (64 nodes, then twice the last): per
 * frozen segment one FFT correlation over the chunk's span of lags, or the
 * direct sums when cheaper.  One convolution out to the window's end at
 * the switch (the first design) cost more: the window's end lies far
 * beyond where the march stops, and every later switch repeated it.  The
 * new segment runs the online fast convolution at the new step from its
 * node 0 (excluded: it is frozen).  The impactor's displacement takes the
 * frozen past through its moments int P, int t P.
 *
 * When: the first contact (the paper contact's: and a later one once it
 * co-moves, later_short), past grow_after nodes, GROW_MIN nodes into
 * a segment, in contact, and P smooth at the doubled step: its second
 * differences over the last GROW_MIN nodes, times 4, at most grow_eta P.
 * The dt/2 pass follows the dt pass's schedule (the same times and the
 * same levels over its own dt0): the Richardson difference then measures
 * the scheme as run.  The step never shrinks: a pass grows only within its
 * first contact (or a co-moving later one), which it ends at the level
 * reached (the exact end works on any segment); the march after it goes on
 * at that level. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_fft_halfcomplex.h>
#include <gsl/gsl_fft_real.h>

#include "impact_impl.h"

/* Nodes a segment runs before its step may double (and the smoothness
 * test's span): enough second differences that one passing through zero
 * does not decide. */
#define GROW_MIN 16
/* The most levels (a step of dt0 2^GROW_LMAX). */
#define GROW_LMAX 30
/* The first chunk of a segment's frozen-past deflections (impact_hist);
 * each next one is twice the last. */
#define HIST_CHUNK 64
/* A chunk's FFT correlation against the direct sums: the direct one's
 * S C products cost as much as this many times N log2 N (bench_conv's
 * cross-over of fastconv's squares, the same trade). */
#define HIST_FFT_COST 3.0
/* A chunk's span of lags against the widest frozen segment's (hist_cmax). */
#define HIST_SPAN 8

struct pass impact_view(const struct ctx *c, const struct pass *s)
{
	struct pass v = *s;
	size_t o = c->seg0;
	v.t += o, v.P += o, v.W += o, v.w += o, v.v += o, v.wc += o, v.Q += o, v.sg += o;
	v.n = s->n - o;
	v.cap = c->segcap;
	return v;
}

/* A later contact (not the first) the step may not grow in: the physical
 * contact's, any, and the paper contact's while it is shorter than a
 * co-moving one (impact_rest_long).  The step never shrinks, so every
 * later contact then runs at the grown level, as after a first contact
 * that grew: a long contact at rest on a thin plate grows (h = 0.05 r0,
 * 100 g at 0.1 mm/s, the paper's contact, needed over 1e6 steps in its
 * third contact and answers now), a chatter of short ones does not (its
 * frozen past's sums at each end doubled h = 0.02 r0, 0.1 g at 10 m/s). */
static int later_short(const struct ctx *c, const struct pass *s, size_t n)
{
	if (s->ncont == 1)
		return 0;
	if (c->physical || s->ncont > ANVIL_MAX_CONTACTS)
		return 1;
	return s->t[n - 1] - s->on[s->ncont - 1] < c->rest_long;
}

int impact_grow_due(const struct ctx *c, const struct pass *s, size_t n, int in)
{
	if (c->sched) { /* the dt/2 pass: the dt pass's schedule, node for node twice */
		size_t k = s->nseg;
		if (k < c->sched->nseg && n - 1 == 2 * c->sched->seg_n[k])
			return c->sched->seg_L[k];
		return 0;
	}
	if (c->lng && n - c->seg0 >= c->segcap && c->lev >= 1 && s->nseg < IMPACT_MAX_SEGS &&
	    c->K0 + ((n - 1 - c->seg0) << c->lev) + ((size_t)4 << c->lev) < c->nR)
		return c->lev; /* full: frozen, the same step goes on (long mode) */
	if (!c->grow_after || n - 1 < c->grow_after || !in || s->pend_k || later_short(c, s, n) ||
	    s->nseg >= IMPACT_MAX_SEGS || c->lev >= GROW_LMAX || n - 1 - c->seg0 < GROW_MIN)
		return 0;
	size_t Ks = c->K0 + (n - 1 - c->seg0) * ((size_t)1 << c->lev);
	if (Ks + 1 >= c->nR || ((c->nR - 1 - Ks) >> (c->lev + 1)) < 4 * GROW_MIN)
		return 0; /* too near the window's end to be worth it */
	const double *P = s->P;
	double d2 = 0;
	for (size_t j = n - GROW_MIN + 1; j < n; j++) {
		if (!(P[j - 2] > 0))
			return 0;
		d2 = fmax(d2, fabs(P[j] - 2.0 * P[j - 1] + P[j - 2]));
	}
	double ref = P[n - 1];
	return 4.0 * d2 <= c->grow_eta * ref ? c->lev + 1 : 0;
}

/* The weights of level L (as weights() makes level 0's), made as they
 * are needed (impact_wts.c). */
static int level_weights(struct ctx *c, int L, size_t capn)
{
	double *g = malloc(capn * sizeof *g), *dg = NULL;
	if (!g || (c->ramp2 && !(dg = malloc(capn * sizeof *dg)))) {
		free(g);
		return ANVIL_ENOMEM;
	}
	c->g = g, c->dg = dg, c->ng = capn, c->gnf = 0; /* the old ones: frozen with their segment */
	c->lev = L;
	return impact_g_need(c, 2);
}

/* At the freeze of f (t_smooth > 0): its charges and where the far field
 * starts (impact_far.c), and (long mode) its weights out to there (the
 * near targets' exact sums; a window that fits has them already). */
static int far_setup(struct ctx *c, struct frozen *f, const double *tn, double dp, double dn)
{
	impact_far_charges(c, f, tn, dp, dn);
	/* the near targets u dt0 < t_far read weights to lag (u - K)/2^L + 1 */
	double need = ceil((f->t_far / c->dt0 - (double)f->K) / (double)((size_t)1 << f->L)) + 2.0;
	double room = (double)((c->nR - 1 - f->K) >> f->L);
	size_t ng = (size_t)fmin(need, room);
	if (ng <= f->ng)
		return ANVIL_OK;
	double *g = realloc(f->g, ng * sizeof *g), *dg = f->dg;
	if (g)
		f->g = g;
	if (!g || (dg && !(dg = realloc(f->dg, ng * sizeof *dg))))
		return ANVIL_ENOMEM;
	f->dg = dg;
	f->ng = ng; /* made as the targets reach them (hist_chunk) */
	return ANVIL_OK;
}

int impact_grow_switch(struct ctx *c, struct pass *s, int L)
{
	size_t ns = s->n - 1, S = ns - c->seg0;
	size_t mp = (size_t)1 << c->lev, mn = (size_t)1 << L;
	size_t Ks = c->K0 + S * mp;
	if (L < c->lev + !c->lng || L < 1 || Ks + mn >= c->nR || c->nfz + 1 >= IMPACT_MAX_SEGS)
		return ANVIL_EINVAL;
	size_t capn = (c->nR - 1 - Ks) >> L;
	if (c->lng) { /* a segment's weights, and the nodes left */
		size_t cl = IMPACT_LONG_SEG * (c->sched ? 2 : 1), left = s->cap - ns;
		capn = capn < cl ? capn : cl;
		capn = capn < left ? capn : left;
	}
	if (capn < 2)
		return ANVIL_EINVAL;
	double dp = s->dt, dn = ldexp(s->dt0, L);
	const double *x = s->P + c->seg0;
	double Pn = s->P[ns];
	c->fz[c->nfz++] = (struct frozen){ .x = x, .z = c->dg ? s->Q + c->seg0 : NULL, .S = S,
					   .K = c->K0, .Kb = Ks, .ng = c->ng, .nf = c->gnf, .L = c->lev, .Ln = L,
					   .g = c->g, .dg = c->dg, .Pb = Pn,
					   .Qb = c->dg ? s->Q[ns] : 0.0, .n0 = c->seg0,
					   .t_far = INFINITY };
	c->g = c->dg = NULL;
	if (c->t_smooth > 0) { /* the far field (long mode, or where the caller asks) */
		int st = far_setup(c, &c->fz[c->nfz - 1], s->t + c->seg0, dp, dn);
		if (st)
			return st;
	}
	/* the moments: the old segment's hats (node 0's is in already), n_s's */
	for (size_t m = 1; m < S; m++) {
		c->Ih += x[m] * dp;
		c->M1h += x[m] * s->t[c->seg0 + m] * dp;
	}
	c->Ih += Pn * 0.5 * (dp + dn);
	c->M1h += Pn * (s->t[ns] * 0.5 * (dp + dn) + (dn * dn - dp * dp) / 6.0);
	int st = level_weights(c, L, capn); /* c->lev = L from here */
	if (st)
		return st;
	anvil_fastconv_free(c->fc);
	c->fc = impact_fc_alloc(c, 0);
	if (!c->fc)
		return ANVIL_ENOMEM;
	anvil_fastconv_push(c->fc, 0.0); /* node 0: in the frozen past */
	impact_end_tab_free(c->tab);    /* a new step */
	c->seg0 = ns, c->K0 = Ks, c->segcap = capn;
	c->hlo = c->hn = 0; /* the chunk was the old segment's */
	c->T0 = (double)Ks * s->dt0;
	s->t[ns] = c->T0;
	s->dt = dn;
	s->seg_n[s->nseg] = ns;
	s->seg_L[s->nseg] = L;
	s->nseg++;
	return ANVIL_OK;
}

void impact_grow_reset(struct ctx *c)
{
	for (size_t j = 0; j < c->nfz; j++) {
		free(c->fz[j].g);
		free(c->fz[j].dg);
		free(c->fz[j].xf);
	}
	c->nfz = c->nmg = 0;
	free(c->hbuf);
	c->hbuf = NULL;
	c->hlo = c->hn = c->hcap = 0;
	free(c->hwk);
	c->hwk = NULL;
	c->hwcap = 0;
}

void impact_grow_free(struct ctx *c)
{
	impact_grow_reset(c);
	for (int k = 0; k < HIST_FFT_MAX; k++) {
		if (!c->share) { /* its own: else the share's */
			gsl_fft_real_wavetable_free((gsl_fft_real_wavetable *)c->rw[k]);
			gsl_fft_halfcomplex_wavetable_free((gsl_fft_halfcomplex_wavetable *)c->hw[k]);
		}
		gsl_fft_real_workspace_free(c->ws[k]);
		c->rw[k] = NULL, c->hw[k] = NULL, c->ws[k] = NULL;
	}
	c->hlo = c->hn = c->hcap = 0;
}

/* sum_{1 <= m < S} x_m g_{o-m}: four chains summed in a fixed order (the
 * adder's latency, not the products, bounds a single chain). */
static double dot_rev(const double *x, const double *g, size_t o, size_t S)
{
	double a0 = 0, a1 = 0, a2 = 0, a3 = 0;
	const double *gr = g + o; /* gr[-m] = g_{o-m} */
	size_t m = 1;
	for (; m + 4 <= S; m += 4) {
		a0 += x[m] * gr[-(ptrdiff_t)m];
		a1 += x[m + 1] * gr[-(ptrdiff_t)m - 1];
		a2 += x[m + 2] * gr[-(ptrdiff_t)m - 2];
		a3 += x[m + 3] * gr[-(ptrdiff_t)m - 3];
	}
	for (; m < S; m++)
		a0 += x[m] * gr[-(ptrdiff_t)m];
	return (a0 + a1) + (a2 + a3);
}

/* Room for n doubles in c->hwk (frozen_chunk's scratch); 0 when out of
 * memory. */
static int hwk_room(struct ctx *c, size_t n)
{
	if (n <= c->hwcap)
		return 1;
	free(c->hwk);
	c->hwk = malloc(n * sizeof *c->hwk);
	c->hwcap = c->hwk ? n : 0;
	return c->hwk != NULL;
}

/* frozen_chunk's direct sums where the targets lie far apart on f's grid
 * (q well above S: a thin plate's tiny early segments under a step grown
 * 2^19 times theirs): each target's S - 1 weights made for it alone, the
 * same bits as the kept weights (impact_wts_span), where filling them in
 * full made q of them for each target's S (h = 0.02 r0, 0.1 g at 10 m/s:
 * 6.5e5 weights fewer, 31 chunks of the five impacts). */
static int frozen_sparse(struct ctx *c, const struct frozen *f, size_t o0, size_t q, size_t C,
			 double *out)
{
	size_t S = f->S;
	if (!hwk_room(c, 2 * S))
		return ANVIL_ENOMEM;
	double *g = c->hwk, *dg = f->z ? g + S : NULL;
	for (size_t k = 0; k < C; k++) {
		size_t o = o0 + q * k; /* dot_rev reads g_{o-m}, 1 <= m < S */
		if (impact_wts_span(c, f->L, o - (S - 1), S - 1, g, dg))
			return ANVIL_ENUM;
		out[k] += dot_rev(f->x, g, S - 1, S) + (dg ? dot_rev(f->z, dg, S - 1, S) : 0.0);
	}
	return ANVIL_OK;
}

/* The FFT tables of size N = 2^lg: the share's, or its own (no share),
 * and its workspace.  ANVIL_OK or ANVIL_ENOMEM (then none is kept). */
static int hist_fft_tables(struct ctx *c, int lg, size_t N)
{
	const gsl_fft_real_wavetable *rw = NULL;
	const gsl_fft_halfcomplex_wavetable *hw = NULL;
	if (c->share) {
		if (impact_share_fft(c->share, lg, &rw, &hw))
			return ANVIL_ENOMEM;
	} else if (!(rw = gsl_fft_real_wavetable_alloc(N)) ||
		   !(hw = gsl_fft_halfcomplex_wavetable_alloc(N))) {
		gsl_fft_real_wavetable_free((gsl_fft_real_wavetable *)rw);
		return ANVIL_ENOMEM;
	}
	if (!(c->ws[lg] = gsl_fft_real_workspace_alloc(N))) {
		if (!c->share) {
			gsl_fft_real_wavetable_free((gsl_fft_real_wavetable *)rw);
			gsl_fft_halfcomplex_wavetable_free((gsl_fft_halfcomplex_wavetable *)hw);
		}
		return ANVIL_ENOMEM;
	}
	c->rw[lg] = rw, c->hw[lg] = hw;
	return ANVIL_OK;
}

/* Frozen segment f's hats at the targets o0 + q k (its grid), k < C,
 * added to out[k]: directly, or by one FFT correlation over the dense
 * span of lags (GSL radix 2) when that is cheaper: a chunk of the
 * march's nodes costs O((S + q C) log) instead of O(S C). */
static int frozen_chunk(struct ctx *c, struct frozen *f, size_t o0, size_t q, size_t C,
			double *out)
{
	size_t S = f->S, hi = o0 + q * (C - 1) + 1;
	if (S < 2)
		return ANVIL_OK;
	size_t V = S - 1 + q * (C - 1), N = 64;
	int lg = 6;
	while (N < V)
		N <<= 1, lg++;
	if ((double)(S - 1) * (double)C <= HIST_FFT_COST * (double)N * (double)lg) {
		if (hi > f->nf && (double)C * (double)(S + 1) < (double)(hi - f->nf))
			return frozen_sparse(c, f, o0, q, C, out);
		if (impact_wts_fill(c, f->L, f->g, f->dg, &f->nf, hi))
			return ANVIL_ENUM;
		for (size_t k = 0; k < C; k++)
			out[k] += dot_rev(f->x, f->g, o0 + q * k, S) +
				  (f->z ? dot_rev(f->z, f->dg, o0 + q * k, S) : 0.0);
		return ANVIL_OK;
	}
	/* the FFT reads its weights up to the last target's lag */
	if (impact_wts_fill(c, f->L, f->g, f->dg, &f->nf, hi))
		return ANVIL_ENUM;
	/* the tables of size N, made once per share (hist_fft_tables) */
	if (lg >= HIST_FFT_MAX)
		return ANVIL_EINVAL;
	if (!c->ws[lg] && hist_fft_tables(c, lg, N))
		return ANVIL_ENOMEM;
	/* d[n] = sum_{m'} a[m'] b[n + S - 2 - m'], a[m'] = x_{m'+1}, b[v] =
	 * g[o0 - S + 1 + v]: a cyclic convolution of size N >= V is exact at
	 * the indices S - 2 .. V - 1 wanted.  The a's transforms (the frozen
	 * hats, fixed) are kept for the next chunk of the same size, which
	 * then transforms only its span of weights: 3 transforms where there
	 * were 5 (the same bits: the same transform of the same values). */
	int nb = f->z ? 4 : 2;
	if (!hwk_room(c, (size_t)nb * N))
		return ANVIL_ENOMEM;
	double *a = c->hwk;
	if (f->xlg != lg || !f->xf) {
		double *xf = realloc(f->xf, (size_t)(nb / 2) * N * sizeof *xf);
		if (!xf)
			return ANVIL_ENOMEM;
		f->xf = xf;
		f->xlg = lg;
		for (int r = 0; r < nb / 2; r++) {
			const double *x = r ? f->z : f->x;
			double *u = xf + (size_t)r * N;
			for (size_t m = 0; m + 1 < S; m++)
				u[m] = x[m + 1];
			memset(u + (S - 1), 0, (N - (S - 1)) * sizeof *u);
			gsl_fft_real_transform(u, 1, N, c->rw[lg], c->ws[lg]);
		}
	}
	for (int r = 0; r < nb / 2; r++) {
		const double *g = (r ? f->dg : f->g) + (o0 - S + 1);
		double *u = a + (size_t)(2 * r) * N, *w = u + N;
		memcpy(u, f->xf + (size_t)r * N, N * sizeof *u);
		memcpy(w, g, V * sizeof *w);
		memset(w + V, 0, (N - V) * sizeof *w);
		gsl_fft_real_transform(w, 1, N, c->rw[lg], c->ws[lg]);
		/* the product in GSL's mixed-radix half-complex packing: u[0],
		 * u[N-1] real; (u[2j-1], u[2j]) = (re, im) of frequency j */
		u[0] *= w[0];
		u[N - 1] *= w[N - 1];
		for (size_t i = 1; i + 1 < N; i += 2) {
			double re = u[i] * w[i] - u[i + 1] * w[i + 1];
			double im = u[i] * w[i + 1] + u[i + 1] * w[i];
			u[i] = re, u[i + 1] = im;
		}
		if (r)
			for (size_t i = 0; i < N; i++)
				a[i] += u[i];
	}
	gsl_fft_halfcomplex_inverse(a, 1, N, c->hw[lg], c->ws[lg]);
	for (size_t k = 0; k < C; k++)
		out[k] += a[q * k + S - 2];
	return ANVIL_OK;
}

/* The frozen past at the current segment's nodes i0 .. i0 + C - 1 into
 * out: each frozen segment's hats against its own weights (every later
 * node lies on its grid: the levels only rise) and its last node's
 * asymmetric hat through the table. */
static int hist_chunk(struct ctx *c, size_t i0, size_t C, double *out)
{
	memset(out, 0, C * sizeof *out);
	size_t u0 = c->K0 + (i0 << c->lev); /* the first target, in dt0 */
	size_t Cm = C; /* the merged far field's targets: k >= Cm */
	while (c->nmg && Cm && (double)(u0 + ((Cm - 1) << c->lev)) * c->dt0 >= c->mg.t_far)
		Cm--;
	if (Cm < C) {
		impact_far_chunk(c, &c->mg, u0, Cm, C, out);
		if (!isfinite(out[C - 1]))
			return ANVIL_ENUM; /* a ramp call failed */
	}
	for (size_t j = 0; j < c->nfz; j++) {
		struct frozen *f = &c->fz[j];
		size_t q = (size_t)1 << (c->lev - f->L);
		size_t mp = (size_t)1 << f->L, mn = (size_t)1 << f->Ln;
		size_t o0 = (u0 - f->K) >> f->L, Cn = C; /* the near targets: k < Cn */
		size_t Cf = j < c->nmg ? Cm : C;         /* its own far ones: Cn <= k < Cf */
		while (Cn && (double)(u0 + ((Cn - 1) << c->lev)) * c->dt0 >= f->t_far)
			Cn--;
		if (Cn < Cf)
			impact_far_chunk(c, f, u0, Cn, Cf, out);
		if (Cn < Cf && !isfinite(out[Cf - 1]))
			return ANVIL_ENUM; /* a ramp call failed */
		if (!Cn)
			continue;
		if (o0 + q * (Cn - 1) >= f->ng)
			return ANVIL_EINVAL; /* beyond its weights: never, by the capacities */
		int st = frozen_chunk(c, f, o0, q, Cn, out);
		if (st)
			return st;
		double hp = c->dt0 * (double)mp, hn = c->dt0 * (double)mn;
		for (size_t k = 0; k < Cn; k++) {
			size_t ub = u0 + (k << c->lev) - f->Kb;
			/* as the difference of two slopes: R(t)/l - R(t)(1/l + 1/r)
			 * would round by eps R/dt, the same way for every hat of a
			 * width, a bias that grows as R with the lag */
			double A = impact_rtab_raw(c, 0, ub + mp), B = impact_rtab_raw(c, 0, ub),
			       E = impact_rtab_raw(c, 0, ub - mn);
			out[k] += f->Pb * ((A - B) / hp - (B - E) / hn);
			if (f->z) { /* ramp2 less ramp (impact_rtab), ramp's read once */
				double A2 = impact_rtab_raw(c, 1, ub + mp) - A,
				       B2 = impact_rtab_raw(c, 1, ub) - B,
				       E2 = impact_rtab_raw(c, 1, ub - mn) - E;
				out[k] += f->Qb * ((A2 - B2) / hp - (B2 - E2) / hn);
			}
		}
	}
	return ANVIL_OK;
}

/* The largest chunk worth making: a frozen segment's FFT correlation
 * costs N log N for a chunk of C targets, N >= its span of S lags plus the
 * chunk's q C; once q C is past a few times S, a larger chunk only adds
 * log N per target (and the last chunk's unused end, up to half of it,
 * where the march stops short of the window).  So q C is held to the
 * room left in the power of two past HIST_SPAN times the widest segment's
 * span (both in dt0). */
static size_t hist_cmax(const struct ctx *c)
{
	size_t span = 0, N = 64;
	for (size_t j = 0; j < c->nfz; j++)
		if (c->fz[j].S > 1 && ((c->fz[j].S - 1) << c->fz[j].L) > span)
			span = (c->fz[j].S - 1) << c->fz[j].L;
	while (N < HIST_SPAN * span)
		N <<= 1;
	size_t cm = (N - span) >> c->lev;
	return cm > HIST_CHUNK ? cm : HIST_CHUNK;
}

double impact_hist_one(const struct ctx *c, size_t i)
{
	double h = 0; /* one node: direct sums, no table touched */
	return hist_chunk((struct ctx *)c, i, 1, &h) ? NAN : h;
}

int impact_hist(struct ctx *c, size_t i, double *val)
{
	if (i >= c->hlo && i < c->hlo + c->hn) {
		*val = c->hbuf[i - c->hlo];
		return ANVIL_OK;
	}
	if (i < c->hlo) { /* behind the chunk: alone */
		*val = impact_hist_one(c, i);
		return isnan(*val) ? ANVIL_EINVAL : ANVIL_OK;
	}
	/* the next chunk, twice the last (a segment's first: HIST_CHUNK), at
	 * most hist_cmax */
	size_t C = c->hn ? 2 * c->hn : HIST_CHUNK, cm = hist_cmax(c);
	if (C > cm)
		C = cm;
	if (C > c->segcap - i)
		C = c->segcap - i;
	impact_far_merge(c, (double)(c->K0 + (i << c->lev)) * c->dt0);
	if (C > c->hcap) {
		double *b = realloc(c->hbuf, C * sizeof *b);
		if (!b)
			return ANVIL_ENOMEM;
		c->hbuf = b, c->hcap = C;
	}
	int st = hist_chunk(c, i, C, c->hbuf);
	c->hlo = i, c->hn = st ? 0 : C;
	*val = st ? 0.0 : c->hbuf[0];
	return st;
}

/* Ramp r at the target u dt0 + d less the node time K dt0: every lag a
 * whole number of dt0 plus d, as the weights' table has it (the node
 * times' own rounding, the same for every node, would bias the sum
 * against the march's weights). */
static int rlag(const struct ctx *c, int r, size_t u, double d, size_t K, double *val)
{
	anvil_ramp_fn fn = r ? c->ramp2 : c->ramp;
	void *fx = r ? c->rctx2 : c->rctx;
	if (u >= K) /* kept: every contact end reads them again (impact_rtab.c) */
		return impact_rtab_off(c, r, u - K, d, val);
	return impact_ramp_of(c, fn, fx, d - (double)(K - u) * c->dt0, val);
}

int impact_hist_at(const struct ctx *c, const struct pass *v, size_t k, double d, double *val)
{
	/* the whole pass's nodes, from the current segment's view; their
	 * times as whole numbers of dt0 */
	const double *tn = v->t - c->seg0, *P = v->P - c->seg0, *Q = v->Q - c->seg0;
	size_t u = c->K0 + (k << c->lev), Kp = 0, Km = 0, Kn = 0, j = 0;
	double w = 0, t = (double)u * c->dt0 + d;
	int st = ANVIL_OK, nr = c->dg ? 2 : 1, have = 0;
	/* the ramps at the lags of nodes m - 1, m, m + 1 (ramp, ramp2): node
	 * m + 1's hat reuses two of them (each value one call, not three) */
	double R[2][3];
	int merged = c->nmg && t >= c->mg.t_far;
	if (merged)
		w += impact_far_sum(c, &c->mg, t);
	for (size_t f = merged ? c->nmg : 0; f < c->nfz; f++) /* the far ones' charges */
		if (t >= c->fz[f].t_far)
			w += impact_far_sum(c, &c->fz[f], t);
	for (size_t m = 1; m <= c->seg0 && !st; m++) {
		Kp = Km;
		Km = m == 1 ? (size_t)llround(tn[1] / c->dt0) : Kn;
		Kn = m < c->seg0 ? (size_t)llround(tn[m + 1] / c->dt0) : Km + ((size_t)1 << c->lev);
		while (j < c->nfz && m > c->fz[j].n0 + c->fz[j].S)
			j++;
		if (j < c->nfz && t >= c->fz[j].t_far) {
			have = 0;
			continue; /* in its segment's far field */
		}
		for (int r = 0; r < nr && !st; r++) {
			if (have) /* the last hat's middle and right */
				R[r][0] = R[r][1], R[r][1] = R[r][2];
			else if (!(st = rlag(c, r, u, d, Kp, &R[r][0])))
				st = rlag(c, r, u, d, Km, &R[r][1]);
			if (!st)
				st = rlag(c, r, u, d, Kn, &R[r][2]);
		}
		have = !st;
		if (st)
			break;
		/* slopes: no R-sized rounding (hist_chunk); the Q hat's through
		 * ramp2 less the P hat's */
		double l = (double)(Km - Kp) * c->dt0, rr = (double)(Kn - Km) * c->dt0;
		double h = (R[0][0] - R[0][1]) / l - (R[0][1] - R[0][2]) / rr;
		w += P[m] * h;
		if (c->dg)
			w += Q[m] * ((R[1][0] - R[1][1]) / l - (R[1][1] - R[1][2]) / rr - h);
	}
	*val = w;
	return st;
}

int impact_long_short(const struct ctx *c, const struct pass *s)
{
	if (!c->lng || !s->n)
		return 0;
	size_t u = c->K0 + ((s->n - 1 - c->seg0) << c->lev);
	return u + ((size_t)2 << c->lev) < c->nR;
}
