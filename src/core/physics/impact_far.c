/* impact_far.c: the far field of the frozen past (impact.h t_smooth;
 * impact_grow.c freezes the segments).
 *
 * A frozen segment's hats at lags many times its span enter as charges:
 * sum_m c_m H(t - t_m), c_m = P_m times the hat's area at its centroid
 * t_m, H the impulse response.  H is smooth there (beyond twice t_smooth,
 * impact.h), so H(t - tau) over the segment's span is its interpolant at
 * FAR_P Chebyshev points tau_j, and the sum is sum_j W_j H(t - tau_j),
 * W_j = sum_m c_m l_j(t_m) (l_j the Lagrange basis), made once at the
 * freeze: O(FAR_P) per target, whatever the lag.  Errors (relative to
 * the segment's deflection): the interpolant's, about (D/(4 Lambda))^P
 * for span D at lag Lambda (1e-7 at Lambda = FAR_RHO D); a hat as a point,
 * its second moment, (w/Lambda)^2/12 (1e-7 at FAR_MIN widths); H the
 * caller's closed form (impact.h impulse: the layer correction's plate
 * tail, exact but for its table's interpolant), else the
 * seven-point (sixth-order) second difference of the ramp at h =
 * Lambda/32, (1/32)^6 of H's eighth derivative scale, its rounding
 * 6 eps 32^2 (7e-13), where the fine grid's weights round as eps
 * (Lambda/w)^2: useless by Lambda/w = 1e8 (a 10 s contact at 0.1 us).
 * The deflection far out is large against the Hertz compression (the
 * plate's dashpot holds all the impulse), so these relative errors are
 * amplified in P: tests/test_grow.c measures the whole at under a tenth
 * of the scheme's own estimates (the five-point difference was 3 times
 * R_f's estimate there). */
#include <math.h>
#include <stddef.h>

#include "impact_impl.h"

#define FAR_RHO 4.0
#define FAR_MIN 1024.0
#define FAR_H 32.0
/* Where the window fits (not long mode) the fine grid's weights reach the
 * window's end and the far field is a saving, not a need: it starts
 * FAR_MIN_FIT widths out.  There it departs from the exact sums they
 * gave by H's own error (its table: the far sum against the weights'
 * sums measured 1e-9 to 2e-8 of a segment's deflection, which is the
 * weights' rounding eps (Lambda/w)^2 as much as H's), and a grazing end
 * follows such a perturbation: at FAR_MIN widths one (1 kg at 1000 m/s
 * on h = r0, R_f 3e-6) fell to the rest state at 5848 us from its end at
 * 8630 +- 6 us; at 16384 widths the grid's largest move was 0.78 of its
 * estimate, at 32768 widths 0.044.  It then spares the weights out to
 * the window's end (a ramp call each, at every dt0 of a segment at
 * level 0) and their FFT sums: h = 0.5 r0, 100 kg at 1 cm/s 0.31 ->
 * 0.16 s CPU, h = 0.02 r0, 0.1 g at 10 m/s 0.53 -> 0.45 s. */
#define FAR_MIN_FIT 32768.0

double impact_far_h(const struct ctx *c, int r, double t)
{
	anvil_ramp_fn fn = r ? c->ramp2 : c->ramp;
	void *fx = r ? c->rctx2 : c->rctx;
	const struct anvil_params *p = c->p;
	double h = t / FAR_H, v[8];
	if (c->imp[r] && c->imp[r](c->ictx[r], t * p->c2 / p->r0, &v[0]) == ANVIL_OK)
		return v[0] * (p->c2 / p->r0) * (p->c2 / p->r0) / (p->mu * p->c2); /* impact.h */
	if (t + 3.0 * h > c->tau_avail * c->p->r0 / c->p->c2) {
		/* the window's end within reach: the backward eight-point
		 * difference, sixth order too (Fornberg's weights), at h = t/48:
		 * truncation and rounding (191 eps 48^2) both near 1e-10 */
		static const double bw[8] = { 469.0 / 90, -223.0 / 10, 879.0 / 20, -949.0 / 18,
					      41.0, -201.0 / 10, 1019.0 / 180, -7.0 / 10 };
		double sum = 0;
		h = t / 48.0;
		for (int i = 0; i < 8; i++) {
			if (impact_ramp_of(c, fn, fx, t - (double)i * h, &v[i]))
				return NAN;
			sum += bw[i] * v[i];
		}
		return sum / (h * h);
	}
	for (int i = 0; i < 7; i++)
		if (impact_ramp_of(c, fn, fx, t + (double)(i - 3) * h, &v[i]))
			return NAN;
	return (2.0 * (v[0] + v[6]) - 27.0 * (v[1] + v[5]) + 270.0 * (v[2] + v[4]) - 490.0 * v[3]) /
	       (180.0 * h * h);
}

/* The far field of f at the target time t (t >= f->t_far). */
double impact_far_sum(const struct ctx *c, const struct frozen *f, double t)
{
	double w = 0;
	for (int j = 0; j < FAR_P; j++) {
		double h0 = impact_far_h(c, 0, t - f->tc[j]);
		w += f->Wx[j] * h0;
		if (f->z)
			w += f->Wz[j] * (impact_far_h(c, 1, t - f->tc[j]) - h0);
	}
	return w;
}

/* f's run over [t0, t1], within 1/FAR_RHO of its distance from the
 * charges: the far field's interpolant at FAR_P Chebyshev points (the
 * same error as the charges', the two ends' roles swapped), kept in f
 * for every target that falls in it, this chunk's or a later one's.  The
 * interpolant as its Chebyshev series (the discrete cosine transform of
 * the values, which the points of the first kind make exact) summed by
 * Clenshaw's recurrence (far_run_at): 2 FAR_P multiplications a target
 * where the barycentric form's 2 FAR_P divisions had been a third of the
 * far field's cost (h = 0.02 r0, 1 kg at 10 m/s: 1.06e6 targets in 8180
 * runs); both are backward stable, their values apart by rounding. */
static void far_run(const struct ctx *c, struct frozen *f, double t0, double t1)
{
	double F[FAR_P], xn[FAR_P], T0[FAR_P], T1[FAR_P];
	for (int j = 0; j < FAR_P; j++) {
		xn[j] = cos((2.0 * j + 1.0) * M_PI / (2.0 * FAR_P));
		F[j] = impact_far_sum(c, f, 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * xn[j]);
		T0[j] = 1.0, T1[j] = xn[j];
	}
	/* a_m = (2 - [m = 0]) sum_j F_j T_m(x_j) / FAR_P, T_m(x_j) = cos(m
	 * theta_j) by the three-term recurrence (no cosines: 64 of them a run
	 * were 10 % of the far field) */
	for (int m = 0; m < FAR_P; m++) {
		double sum = 0;
		for (int j = 0; j < FAR_P; j++) {
			double tm = m == 0 ? T0[j] : m == 1 ? T1[j] : 2.0 * xn[j] * T1[j] - T0[j];
			if (m >= 2)
				T0[j] = T1[j], T1[j] = tm;
			sum += F[j] * tm;
		}
		f->ra[m] = (m ? 2.0 : 1.0) * sum / FAR_P;
	}
	f->rt0 = t0, f->rt1 = t1;
}

/* f's kept run at t (rt0 <= t <= rt1) */
static double far_run_at(const struct frozen *f, double t)
{
	double x = (2.0 * t - f->rt0 - f->rt1) / (f->rt1 - f->rt0), b1 = 0, b2 = 0;
	for (int m = FAR_P - 1; m >= 1; m--) {
		double b0 = 2.0 * x * b1 - b2 + f->ra[m];
		b2 = b1, b1 = b0;
	}
	return x * b1 - b2 + f->ra[0];
}

/* The far field of f at the targets t_k = (u0 + k 2^lev) dt0, k0 <= k < C,
 * added to out[k].  It is as smooth in the target as in the source, so
 * the targets go in runs, each within 1/FAR_RHO of its distance from the
 * charges (far_run: FAR_P far sums, not one per target); where a run
 * would hold at most FAR_P targets of the current step they go one by one
 * (as many far sums or fewer).  A run spans its whole reach, not just the
 * chunk's targets, and is kept for the next chunk's (the window's end
 * bounds it): cut at the chunk's end, as they had been, half of the runs
 * ended there and the next chunk began a new one (h = 0.02 r0, 100 kg at
 * 10 m/s: 9298 of 17007), and runs of 2 FAR_P targets or fewer went one
 * by one (1.1e5 targets beside 9232 runs).  The runs grow with the
 * distance (by 1 + 1/FAR_RHO each), so a pass makes O(log) of them: a
 * chunk's targets summed one by one had been four fifths of the far sums
 * on a thin plate (h = 0.02 r0, 100 kg at 10 m/s). */
void impact_far_chunk(const struct ctx *c, struct frozen *f, size_t u0, size_t k0, size_t C,
		      double *out)
{
	double step = (double)((size_t)1 << c->lev) * c->dt0, tw = (double)(c->nR - 1) * c->dt0;
	for (size_t k = k0; k < C;) {
		double t = (double)(u0 + (k << c->lev)) * c->dt0;
		if (f->rt1 > f->rt0 && t >= f->rt0 && t <= f->rt1) {
			out[k++] += far_run_at(f, t);
			continue;
		}
		double te = fmin(t + (t - f->tb) / FAR_RHO, tw);
		double nt = floor((te - t) / step) + 1.0; /* its targets at this step */
		if (nt <= FAR_P) {
			for (size_t e = k + (size_t)fmax(nt, 1.0); k < e && k < C; k++)
				out[k] += impact_far_sum(c, f, (double)(u0 + (k << c->lev)) * c->dt0);
			continue;
		}
		far_run(c, f, t, te);
	}
}

/* The Chebyshev points of the first kind on [-1, 1] and their
 * barycentric weights (the same cosines and sines for every charge: taken
 * once a freeze, where each charge took them again, FAR_P sincos a
 * charge: 1 % of h = 0.02 r0's slowest scenes). */
struct far_nodes {
	double x[FAR_P], lam[FAR_P];
};

static void far_nodes_make(struct far_nodes *nd)
{
	for (int j = 0; j < FAR_P; j++) {
		double th = (2.0 * j + 1.0) * M_PI / (2.0 * FAR_P);
		nd->x[j] = cos(th);
		nd->lam[j] = (j % 2 ? -1.0 : 1.0) * sin(th);
	}
}

/* Add the charge (cx, cz) at time t to f's Chebyshev weights over [a, b]
 * (barycentric Lagrange basis at the points of the first kind, nd). */
static void far_add(struct frozen *f, const struct far_nodes *nd, double a, double b, double t,
		    double cx, double cz)
{
	double x = b > a ? (2.0 * t - a - b) / (b - a) : 0.0, l[FAR_P], sum = 0;
	for (int j = 0; j < FAR_P; j++) {
		double d = x - nd->x[j];
		if (d == 0.0) { /* on a node: that node's alone */
			f->Wx[j] += cx, f->Wz[j] += cz;
			return;
		}
		l[j] = nd->lam[j] / d;
		sum += l[j];
	}
	for (int j = 0; j < FAR_P; j++) {
		f->Wx[j] += cx * l[j] / sum;
		f->Wz[j] += cz * l[j] / sum;
	}
}

void impact_far_charges(const struct ctx *c, struct frozen *f, const double *tn, double dp,
			double dn)
{
	double a = tn[1], b = tn[f->S] + (dn - dp) / 3.0; /* centroids: first, last hat */
	struct far_nodes nd;
	far_nodes_make(&nd);
	if (f->S < 2)
		a = b;
	for (int j = 0; j < FAR_P; j++) {
		f->tc[j] = 0.5 * (a + b) + 0.5 * (b - a) * nd.x[j];
		f->Wx[j] = f->Wz[j] = 0.0;
	}
	for (size_t m = 1; m < f->S; m++)
		far_add(f, &nd, a, b, tn[m], f->x[m] * dp, f->z ? f->z[m] * dp : 0.0);
	far_add(f, &nd, a, b, b, f->Pb * 0.5 * (dp + dn), f->z ? f->Qb * 0.5 * (dp + dn) : 0.0);
	f->ta = a, f->tb = b;
	double wmin = c->lng ? FAR_MIN : FAR_MIN_FIT;
	f->t_far = b + fmax(fmax(FAR_RHO * (b - a + 2.0 * dn), wmin * dn), 2.0 * c->t_smooth);
}

/* Where the far fields of segments 0 .. m - 1 as one set of charges
 * over [ta of 0, tb of m - 1] hold: each segment's own (its hats as
 * charges), and the merged interpolant's, FAR_RHO of that span out
 * (the same error as a segment's, the span the whole). */
static double merge_t_far(const struct ctx *c, size_t m)
{
	double t = c->fz[m - 1].tb + FAR_RHO * (c->fz[m - 1].tb - c->fz[0].ta);
	for (size_t j = 0; j < m; j++)
		t = fmax(t, c->fz[j].t_far);
	return t;
}

/* A thin plate's step doubles every few nodes (impact_grow.c): two dozen
 * frozen segments of 16 nodes each, all far from the late targets, each
 * with its own runs (FAR_P far sums of FAR_P impulses each): h = 0.02
 * r0, 100 kg at 10 m/s made 11406 runs, 4159 of them among 24
 * segments, 191 for each of the oldest 19.  Their charges, interpolated
 * again at FAR_P points over the whole span, are one segment's work: the
 * far field fell from 8 % of that run to 1 % (6.8 % fewer instructions in
 * all), the outputs moving by 1e-6 of their estimates at most.
 * Made (again) when the targets from t0 on lie beyond a longer prefix's
 * reach: its charges from the segments' (a point charge's Lagrange
 * weights: far_add). */
void impact_far_merge(struct ctx *c, double t0)
{
	size_t m = c->nmg;
	while (m < c->nfz && merge_t_far(c, m + 1) <= t0)
		m++;
	if (m <= c->nmg || m < 2)
		return;
	struct frozen *g = &c->mg;
	struct far_nodes nd;
	far_nodes_make(&nd);
	double a = c->fz[0].ta, b = c->fz[m - 1].tb;
	*g = (struct frozen){ .z = c->fz[0].z, .ta = a, .tb = b, .t_far = merge_t_far(c, m) };
	for (int j = 0; j < FAR_P; j++)
		g->tc[j] = 0.5 * (a + b) + 0.5 * (b - a) * nd.x[j];
	for (size_t f = 0; f < m; f++)
		for (int j = 0; j < FAR_P; j++)
			far_add(g, &nd, a, b, c->fz[f].tc[j], c->fz[f].Wx[j], c->fz[f].Wz[j]);
	c->nmg = m;
}
