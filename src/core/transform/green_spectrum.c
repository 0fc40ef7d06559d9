/* green_spectrum.c: the layer response's spectrum (green_spectrum.h). */
#include <complex.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "gk21.h"
#include "green_cut.h"
#include "green_spectrum.h"
#include "green_tail.h"
#include "kernel.h"
#include "layer_bc.h"

typedef double complex cplx;

/* The integrands, units mu = c2 = rho = 1, from the one boundary-condition
 * solve (layer_bc.h): the layer correction W - W_hs (its stable form, which
 * decays like exp(-k hh) and is formed without cancellation), and for
 * cross-checks the half-space W_hs = alpha1 s^2 / R less its static limit
 * (1 - nu)/k = 1/(2 k (1 - kappa^2)).  The symmetric/antisymmetric form of
 * W agrees with the paper's D1..D4 (eqs 29-30, gamma = 2k^2 + s^2/c2^2) to
 * rounding (tests/test_green.c). */
struct kmemo;

/* sin and cos of ph xgk_i (gk21.c's abscissae, i = 0..10 as anvil_gk21_node's
 * j <= 10 gives them on [-1, 1]) for one product ph = patch x half-width
 * (zhat_piece); a few direct-mapped slots, keyed by ph's bits. */
#define ZC_BITS 5
#define ZC_SLOTS (1 << ZC_BITS)
struct zcache {
	double ph;
	int used;
	double sd[11], cd[11];
};

/* exp(+-w xgk_i) for one product w = 2 hh x half-width (tail_piece_w), as
 * zcache's sines: ep[i] = exp(w xgk_i), em[i] = exp(-w xgk_i) */
#define EC_SLOTS 8
struct ecache {
	double w;
	int used;
	double ep[10], em[10];
};

struct quad {
	enum anvil_green_mode mode;
	double kap2, nu, hh, patch;
	cplx s;
	double lift, klo, klift; /* the band's contour (k_integral): lifted on [klo, klift);
				  * klift 0: the real axis */
	double kband;       /* the band's end: zhat_piece serves the tail beyond it */
	int no_lift;        /* keep the band on the real axis (tests) */
	double wide;        /* the widest patch the band's contour serves (anvil_kband_lift) */
	int far_cut;        /* cut at the hard limit, not the budget's, and the tail's
			     * kernel evaluated, not interpolated (tests) */
	int full_band;      /* the band's small pieces to kband, not kpole (tests) */
	gsl_root_fsolver *root; /* the cut's (green_cut.h), one a thread */
	size_t evals;
	struct kmemo *memo; /* the layer correction's kernel at this s (a set's), or NULL */
	cplx *seg;          /* the memo's values for the piece being integrated, or NULL */
	int seg_hit, seg_at; /* they are known (else being filled); the next node's */
	/* zhat(x patch) at the piece's nodes, in the rule's call order
	 * (zhat_piece), when zh_on; zh_at the next node's */
	double zh[ANVIL_GK21_NODES];
	int zh_on, zh_at;
	/* on a lifted piece (lifted_piece), in the rule's call order: sin and
	 * cos of patch x (ls_on) and of the contour's angle t (lt_on) at its
	 * nodes; lz_at the next node's */
	double lsx[ANVIL_GK21_NODES], lcx[ANVIL_GK21_NODES];
	double lst[ANVIL_GK21_NODES], lct[ANVIL_GK21_NODES];
	int lz_on, ls_on, lt_on, lz_at;
	struct zcache zc[ZC_SLOTS];
	struct green_tail tail; /* W beyond kband at this s (green_tail.h) */
	int tail_on;            /* taken from it */
	/* its values at a tail piece's nodes, in the rule's call order
	 * (tail_piece_w), when tw_on; tw_at the next node's */
	cplx tw[ANVIL_GK21_NODES];
	int tw_on, tw_at;
	struct ecache ec[EC_SLOTS];
};

/* The layer correction's kernel W(k, s) does not depend on the load's
 * patch: the responses of a set (anvil_green_alloc_set) share it.  At one
 * s their adaptive k-integrals start from the same pieces and bisect them
 * at the same midpoints, so most of their pieces coincide (3.4 pieces of
 * which 1.0 distinct on h = 0.05 r0): a hash table from a piece [a, b]
 * (its bits) to W at its 21 Gauss-Kronrod nodes, in the order the rule
 * asks for them (gk21.c: always the same), emptied for the next s by a
 * new generation.  A value from it is the one the kernel would give: the
 * responses' bits do not depend on which others were computed with them.
 * On the lifted band each node also keeps the contour's k and dk/dx (the
 * same for the set's loads: one sincos a node, which the loads after the
 * first took again on every memo hit).
 * Hand-written: GSL has no hash table. */
#define GK_NODES 21
#define KM_VALS 3 /* a node's W, k, dk/dx */

struct kslot {
	double a, b;
	unsigned gen;
	size_t at; /* its values: pool[at .. at + KM_VALS GK_NODES) */
};

struct kmemo {
	struct kslot *s;
	size_t cap, n; /* cap a power of two; n pieces of this generation */
	unsigned gen;
	cplx *pool;
};

#define KMEMO_CAP0 ((size_t)1 << 10)
#define KMEMO_CAP_MAX ((size_t)1 << 16)

static int kmemo_init(struct kmemo *m)
{
	*m = (struct kmemo){ calloc(KMEMO_CAP0, sizeof *m->s), KMEMO_CAP0, 0, 1,
			     malloc(KMEMO_CAP0 / 2 * KM_VALS * GK_NODES * sizeof *m->pool) };
	return m->s && m->pool;
}

static void kmemo_free(struct kmemo *m)
{
	free(m->s);
	free(m->pool);
}

static size_t kmemo_slot(const struct kmemo *m, double a, double b)
{
	uint64_t x, y;
	memcpy(&x, &a, sizeof x);
	memcpy(&y, &b, sizeof y);
	size_t i = (size_t)(((x ^ (y * 0xC2B2AE3D27D4EB4Full)) * 0x9E3779B97F4A7C15ull) >> 32) &
		   (m->cap - 1);
	while (m->s[i].gen == m->gen && !(m->s[i].a == a && m->s[i].b == b))
		i = (i + 1) & (m->cap - 1);
	return i;
}

static void kmemo_next(struct kmemo *m)
{
	m->gen++;
	m->n = 0;
}

/* Twice the slots and the pool, this generation's pieces kept; nothing
 * changed when memory is short. */
static void kmemo_grow(struct kmemo *m)
{
	struct kmemo b = { calloc(2 * m->cap, sizeof *b.s), 2 * m->cap, 0, m->gen,
			   realloc(m->pool, m->cap * KM_VALS * GK_NODES * sizeof *m->pool) };
	if (b.pool)
		m->pool = b.pool;
	if (!b.s || !b.pool) {
		free(b.s);
		return;
	}
	for (size_t i = 0; i < m->cap; i++)
		if (m->s[i].gen == m->gen) {
			b.s[kmemo_slot(&b, m->s[i].a, m->s[i].b)] = m->s[i];
			b.n++;
		}
	free(m->s);
	*m = b;
}

/* The values of piece [a, b] into q->seg: known (seg_hit), or a place to
 * fill; NULL when the table is full (at most half its slots used: the
 * probes stay short). */
static void kmemo_piece(struct kmemo *m, double a, double b, struct quad *q)
{
	size_t i = kmemo_slot(m, a, b);
	q->seg_at = 0;
	q->seg = NULL;
	if (m->s[i].gen == m->gen) {
		q->seg = m->pool + m->s[i].at;
		q->seg_hit = 1;
		return;
	}
	if (2 * (m->n + 1) > m->cap && m->cap < KMEMO_CAP_MAX) {
		kmemo_grow(m);
		i = kmemo_slot(m, a, b);
	}
	if (2 * (m->n + 1) > m->cap)
		return;
	m->s[i] = (struct kslot){ a, b, m->gen, m->n * KM_VALS * GK_NODES };
	q->seg = m->pool + m->s[i].at;
	q->seg_hit = 0;
	m->n++;
}

/* The layer correction's kernel W at x (k = x, or the contour's k(x)):
 * from the memo's piece when it has it, else evaluated (and kept there). */
static cplx correction(struct quad *q, double x, cplx k)
{
	struct anvil_layer_bc bc;
	if (q->seg && q->seg_hit)
		return q->seg[KM_VALS * q->seg_at++];
	if (q->tail_on && x > q->kband)
		return q->tw_on ? q->tw[q->tw_at++] : green_tail_w(&q->tail, x);
	q->evals++;
	if (x < q->klift && x >= q->klo)
		anvil_layer_bc_solve_c(k, q->s, q->kap2, q->hh, &bc);
	else
		anvil_layer_bc_solve(x, q->s, q->kap2, q->hh, &bc);
	cplx w = anvil_layer_bc_w_correction(&bc);
	if (q->seg)
		q->seg[KM_VALS * q->seg_at++] = w;
	return w;
}

/* The offsets' sines and cosines for ph, from the cache or made there. */
static const struct zcache *zc_get(struct quad *q, double ph)
{
	uint64_t x;
	memcpy(&x, &ph, sizeof x);
	/* the product's top bits, which every bit of ph reaches: bits 40-44
	 * saw the mantissa's low bits only, so 8, 4, 0.5 ... (the band's
	 * widths times a patch of 1) shared a slot and evicted each other */
	struct zcache *z = &q->zc[(x * 0x9E3779B97F4A7C15ull) >> (64 - ZC_BITS)];
	if (z->used && z->ph == ph)
		return z;
	z->used = 1;
	z->ph = ph;
	for (int j = 0; j <= 10; j++) {
		double t, wk, wg;
		anvil_gk21_node(-1.0, 1.0, j, &t, &wk, &wg);
		z->sd[j] = sin(-ph * t);
		z->cd[j] = cos(-ph * t);
	}
	return z;
}

/* sin and cos of w (c + h xgk) at call n's node of a piece (c, h), from
 * those of w c (sc, cc) and the offsets' (z, for w h).  (The same for the
 * lifted band's contour and its complex zhat saved nothing: their exp and
 * complex division cost what the sincos did.) */
static void angle_sum(const struct zcache *z, int n, double sc, double cc, double *sn, double *cs)
{
	int j = anvil_gk21_called(n), i = j <= 10 ? j : 20 - j;
	double sd = j <= 10 ? -z->sd[i] : z->sd[i], cd = z->cd[i];
	*sn = sc * cd + cc * sd;
	*cs = cc * cd - sc * sd;
}

/* zhat(x patch) at the 21 nodes of the real piece [a, b], in the order the
 * rule asks for them: sin and cos of patch x by the angle sum from one
 * sincos at the centre and the offsets' (cached per patch x half-width:
 * the tail's pieces are 16 wide and their halves), where zhat(x patch)
 * at each node took one sincos (12 % of a thin plate's CPU, 3 % now:
 * three of a set's four loads pay it on every piece, memo hit or not).
 * The same values to rounding (a few ulp of sin and cos, as patch x's
 * own: 4.5e-12 of y^3 zhat(y) at y = 200). */
static void zhat_piece(struct quad *q, double a, double b)
{
	double p = q->patch, c = 0.5 * (a + b), h = 0.5 * (b - a), sc = sin(p * c),
	       cc = cos(p * c);
	const struct zcache *z = zc_get(q, p * h);
	double xs[ANVIL_GK21_NODES];
	anvil_gk21_called_nodes(a, b, xs);
	for (int n = 0; n < ANVIL_GK21_NODES; n++) {
		double sn, cs;
		angle_sum(z, n, sc, cc, &sn, &cs);
		double y = p * xs[n];
		q->zh[n] = y < 0.1 ? anvil_kernel_zhat(y)
				   : 3.0 * (sn - y * cs) / (2.0 * M_PI * y * y * y);
	}
	q->zh_at = 0;
}

/* sin and cos of w x at the 21 nodes of the piece (c - h, c + h), in the
 * rule's call order, by angle_sum from one sincos at the centre and the
 * offsets' (cached per w h). */
static void sincos_piece(struct quad *q, double w, double c, double h, double *sn, double *cs)
{
	double sc = sin(w * c), cc = cos(w * c);
	const struct zcache *z = zc_get(q, w * h);
	for (int n = 0; n < ANVIL_GK21_NODES; n++)
		angle_sum(z, n, sc, cc, &sn[n], &cs[n]);
}

/* A piece of the lifted band: sin and cos of patch x for its zhat (every
 * load with a patch, memo hit or not) and of the contour's angle t (when
 * its kernel is evaluated), by angle sums where each node took a sincos of
 * its own: 5.5 % of the instructions of h = 0.02 r0, 100 kg at 10 m/s,
 * 2.8 % now with the angle sums (the run 4.546 -> 4.484 G).  The
 * band's pieces are 2 H wide and their halves, the same at every term
 * where H is at its cap, so the offsets' table mostly hits (the contour's
 * once a term: its angle's scale follows kband; a miss costs 12 sincos
 * where the nodes took 21).  The same values to a few ulp of sin and cos,
 * as zhat_piece's. */
static void lifted_piece(struct quad *q, double a, double b)
{
	double c = 0.5 * (a + b), h = 0.5 * (b - a), wl = q->klift - q->klo;
	q->lz_at = 0;
	q->ls_on = q->patch * b >= 0.1; /* not all nodes in zhat's series (anvil_kernel_zhat_c_sc) */
	if (q->ls_on)
		sincos_piece(q, q->patch, c, h, q->lsx, q->lcx);
	q->lt_on = !(q->seg && q->seg_hit);
	if (q->lt_on)
		sincos_piece(q, M_PI / wl, c - q->klo, h, q->lst, q->lct);
}

/* exp(-2 hh x) at the 21 nodes of the piece (c - h, c + h), in the rule's
 * call order: exp(-2 hh c) times the offsets' exp(+-2 hh h xgk_i), cached
 * per 2 hh h as zc_get's sines (the tail's pieces are few widths), where
 * each node took an exp of its own (1.3 M exp on h = 0.02 r0, 100 kg at
 * 10 m/s).  A few ulp from the node's own exp; NULL (each node its own
 * exp) where an offset's exp could be large, 2 hh h > TAIL_EXP_OFF. */
#define TAIL_EXP_OFF 40.0
static const double *tail_exps(struct quad *q, double c, double h, double *e)
{
	double w = 2.0 * q->hh * h;
	if (!(w <= TAIL_EXP_OFF))
		return NULL;
	uint64_t x;
	memcpy(&x, &w, sizeof x);
	struct ecache *z = &q->ec[(x * 0x9E3779B97F4A7C15ull) >> 61];
	if (!(z->used && z->w == w)) {
		z->used = 1;
		z->w = w;
		for (int i = 0; i < 10; i++) {
			double t, wk, wg;
			anvil_gk21_node(-1.0, 1.0, i, &t, &wk, &wg); /* t = -xgk_i */
			z->ep[i] = exp(-w * t);
			z->em[i] = exp(w * t);
		}
	}
	/* the rule's call order (anvil_gk21_called): the centre, the Gauss
	 * nodes' pairs c - h xgk_i, c + h xgk_i (i odd), then the others */
	double ec = exp(-2.0 * q->hh * c);
	e[0] = ec;
	for (int p = 0; p < 10; p++) {
		int i = p < 5 ? 2 * p + 1 : 2 * (p - 5);
		e[2 * p + 1] = ec * z->ep[i];
		e[2 * p + 2] = ec * z->em[i];
	}
	return e;
}

/* The tail's kernel at the 21 nodes of the piece [a, b] beyond the band,
 * in the order the rule asks for them (as zhat_piece): the interpolant's
 * recurrences side by side (green_tail_w_n), the exponentials from the
 * centre's (tail_exps). */
static void tail_piece_w(struct quad *q, double a, double b)
{
	double x[ANVIL_GK21_NODES], e[ANVIL_GK21_NODES];
	anvil_gk21_called_nodes(a, b, x);
	green_tail_w_n(&q->tail, x, tail_exps(q, 0.5 * (a + b), 0.5 * (b - a), e),
		       ANVIL_GK21_NODES, q->tw);
	q->tw_at = 0;
}

/* The load's transform at k (real, or on the lifted contour): a point's
 * is the constant 1/(2 pi), the series' value at 0 bit for bit (and a
 * product with it the complex one's), where the series cost 2 % of a thin
 * plate's instructions: the physical row's two point loads took it at
 * every node of their lifted bands. */
#define ZHAT_POINT (1.0 / (2.0 * M_PI))
static double load_real(const struct quad *q, double x)
{
	return q->patch > 0 ? anvil_kernel_zhat(x * q->patch) : ZHAT_POINT;
}

static cplx load_c(const struct quad *q, cplx k, int n)
{
	if (!(q->patch > 0))
		return ZHAT_POINT;
	return n >= 0 && q->ls_on ? anvil_kernel_zhat_c_sc(k * q->patch, q->lsx[n], q->lcx[n])
				  : anvil_kernel_zhat_c(k * q->patch);
}

static cplx integrand(double x, void *vq)
{
	struct quad *q = vq;
	/* every call on a lifted piece, whichever branch: the tables' index
	 * stays the rule's call order */
	int n = q->lz_on && q->lz_at < ANVIL_GK21_NODES ? q->lz_at++ : -1;
	if (q->mode == ANVIL_GREEN_HALFSPACE) {
		struct anvil_layer_bc bc;
		q->evals++;
		anvil_layer_bc_solve(x, q->s, q->kap2, INFINITY, &bc);
		return (x * anvil_layer_bc_w_halfspace(&bc) - 0.5 / (1.0 - q->kap2)) *
		       anvil_kernel_zhat(x);
	}
	/* a Hertz patch of radius a r0 has the transform zhat(k a); a point
	 * (a = 0) 1/(2 pi): the correction's integrand stays finite, exp(-k hh) */
	if (x >= q->klift || x < q->klo)
		return correction(q, x, x) * (q->zh_on ? q->zh[q->zh_at++] : load_real(q, x)) * x;
	/* on the lifted contour k(x) = x + i lift sin(pi (x - klo)/(klift - klo)), times dk/dx
	 * (the node's three from the memo when it has them) */
	cplx w, k, dk;
	if (q->seg && q->seg_hit) {
		const cplx *v = q->seg + KM_VALS * q->seg_at++;
		w = v[0];
		k = v[1];
		dk = v[2];
	} else {
		double wl = q->klift - q->klo, t = M_PI * (x - q->klo) / wl;
		int lt = n >= 0 && q->lt_on;
		k = anvil_kernel_cmplx(x, q->lift * (lt ? q->lst[n] : sin(t)));
		dk = anvil_kernel_cmplx(1.0, q->lift * M_PI / wl * (lt ? q->lct[n] : cos(t)));
		w = correction(q, x, k);
		if (q->seg) {
			q->seg[KM_VALS * (q->seg_at - 1) + 1] = k;
			q->seg[KM_VALS * (q->seg_at - 1) + 2] = dk;
		}
	}
	/* a point's real 1/(2 pi) as a real factor: the complex product with
	 * it (imaginary part 0) rounds the same */
	if (!(q->patch > 0))
		return w * ZHAT_POINT * k * dk;
	return w * load_c(q, k, n) * k * dk;
}

/* Globally adaptive bisection (as QUADPACK's qag, which GSL offers for real
 * integrands only): split the interval with the largest error estimate
 * until the total meets the tolerance.  A binary heap keeps the next
 * interval to split at hand. */
struct seg {
	double a, b, err, floor;
	cplx val;
};

#define SEG_MAX 8192

struct heap {
	struct seg s[SEG_MAX];
	int n;
};

static void heap_push(struct heap *h, struct seg x)
{
	int i = h->n++;
	while (i > 0 && h->s[(i - 1) / 2].err < x.err) {
		h->s[i] = h->s[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	h->s[i] = x;
}

static struct seg heap_pop(struct heap *h)
{
	struct seg top = h->s[0], last = h->s[--h->n];
	int i = 0;
	for (;;) {
		int c = 2 * i + 1;
		if (c >= h->n)
			break;
		if (c + 1 < h->n && h->s[c + 1].err > h->s[c].err)
			c++;
		if (h->s[c].err <= last.err)
			break;
		h->s[i] = h->s[c];
		i = c;
	}
	if (h->n)
		h->s[i] = last;
	return top;
}

static void heap_add(struct quad *q, struct heap *h, double a, double b, cplx *sum, double *err,
		     double *fl)
{
	struct seg x = { .a = a, .b = b };
	/* the memo holds kernel values only: a load that takes the tail from
	 * the interpolant neither reads nor writes it there */
	q->seg = NULL;
	if (q->memo && !(q->tail_on && a >= q->kband))
		kmemo_piece(q->memo, a, b, q);
	/* the tail's pieces only: their widths repeat (16 and its halves), the
	 * band's follow kband, which moves with omega, so there the offsets'
	 * table missed on nearly every piece and cost more sincos than it
	 * saved (h = 100 r0, 100 kg at 1 mm/s: 1.56 -> 1.70 s CPU) */
	q->zh_on = q->mode != ANVIL_GREEN_HALFSPACE && q->patch > 0 && a >= q->kband;
	if (q->zh_on)
		zhat_piece(q, a, b);
	q->lz_on = q->mode != ANVIL_GREEN_HALFSPACE && q->klift > 0 && a >= q->klo && a < q->klift;
	if (q->lz_on)
		lifted_piece(q, a, b);
	q->tw_on = q->mode != ANVIL_GREEN_HALFSPACE && q->tail_on && a >= q->kband;
	if (q->tw_on)
		tail_piece_w(q, a, b);
	anvil_gk21_complex_floor(integrand, q, a, b, &x.val, &x.err, &x.floor);
	*sum += x.val;
	*err += x.err;
	*fl += x.floor;
	heap_push(h, x);
}

/* Integrate over [0, *kend] (*kend set to the end reached), starting from pieces of width wr on
 * [0, klo] and w0 on [klo, kpole] (where the Lamb-mode poles are), one on [kpole, kband] and
 * w1 beyond; absolute tolerance eps.
 * Returns ANVIL_ETOL (with the best value) when SEG_MAX pieces do not
 * suffice, or when the estimate is within ROUND_STOP of its rounding
 * floor (gk21.h) and that floor is above eps: no bisection can meet eps
 * then (the lowest terms of a thin plate's line, where the plate's
 * 1/(rho h s^2) makes the integral 1e14 times eps, took 8191 pieces to end
 * at 1.0-1.3 times the floor: 14 % of the evaluations of h = 0.02 r0, 1 kg
 * at 10 m/s). */
#define ROUND_STOP 2.0
static int adapt(struct quad *q, struct heap *h, double klo, double wr, double kpole,
		 double kband, double *kend, double w0, double w1, double eps, cplx *val,
		 double *abserr)
{
	cplx sum = 0;
	double err = 0, fl = 0, a = 0;
	h->n = 0;
	while (a < *kend && h->n < SEG_MAX / 2) {
		double w = a < klo ? wr : a < kpole ? w0 : a < kband ? kband - kpole : w1;
		double end = a < klo ? klo : a < kpole ? kpole : a < kband ? kband : INFINITY;
		double b = fmin(*kend, fmin(end, a + w));
		heap_add(q, h, a, b, &sum, &err, &fl);
		a = b;
	}
	*kend = a; /* short of it when SEG_MAX / 2 pieces did not reach */
	while (err > eps && h->n < SEG_MAX - 1 && !(fl > eps && err <= ROUND_STOP * fl)) {
		struct seg x = heap_pop(h);
		double m = 0.5 * (x.a + x.b);
		sum -= x.val;
		err -= x.err;
		fl -= x.floor;
		heap_add(q, h, x.a, m, &sum, &err, &fl);
		heap_add(q, h, m, x.b, &sum, &err, &fl);
	}
	/* re-add from scratch: the running sums drift */
	sum = 0;
	err = 0;
	for (int i = 0; i < h->n; i++) {
		sum += h->s[i].val;
		err += h->s[i].err;
	}
	*val = sum;
	*abserr = err;
	return err <= eps ? ANVIL_OK : ANVIL_ETOL;
}


/* The tail's kernel from the interpolant (green_tail.h) when the tail
 * spans more than GREEN_TAIL_MIN_SPAN and the interpolant's error bound,
 * TAIL_SAFETY times its estimate over the envelope (green_cut.h), is at
 * most TAIL_SHARE of eps: that bound is returned, for the term's estimate
 * (0 when the kernel is evaluated). */
#define TAIL_SAFETY 2.0
#define TAIL_SHARE 0.1
static double cut_env(void *c, double K)
{
	return green_cut_env(c, K);
}

static double tail_fit(struct quad *q, struct green_cut *cut, double kband, double kmax,
		       double kend, double eps)
{
	q->tail_on = 0;
	if (q->mode != ANVIL_GREEN_LAYER_CORRECTION || q->far_cut || !(kmax - kband > GREEN_TAIL_MIN_SPAN))
		return 0.0;
	green_tail_key(&q->tail, q->s, q->kap2, q->hh, kband, kmax);
	double e = TAIL_SAFETY * green_tail_bound(&q->tail, kend, cut_env, cut,
						  TAIL_SHARE * eps / TAIL_SAFETY, &q->evals);
	q->tail_on = e <= TAIL_SHARE * eps;
	return q->tail_on ? e : 0.0;
}

/* The tail's starting pieces when its kernel comes from the interpolant:
 * 2.5 periods of zhat(k patch) (as the 16-wide ones for a patch of 1), and
 * under a point load, whose integrand is then a polynomial times exp(-2 k
 * hh), TAIL_POINT_PIECE/hh (200 at hh = 0.02: 3 pieces where there were
 * 28; 1/hh and 2/hh measured the same CPU to the noise, 3 %). */
#define TAIL_POINT_PIECE 4.0
static double tail_piece(double patch, double hh)
{
	return patch > 0 ? fmax(ANVIL_KTAIL_PIECE, 5.0 * M_PI / patch) : TAIL_POINT_PIECE / hh;
}

/* The k-integral at one s = c0 + i omega, to absolute error eps.  The
 * Lamb-mode poles lie within about c0/c_group of the real k axis for k up
 * to about omega/c_A0, where the slowest mode (A0) has phase speed below
 * both c_R and the thin-plate flexural speed: that band starts in small
 * pieces; beyond it the fields are evanescent and the integrand smooth
 * (exp(-2kH) times the period-2pi oscillation of zhat).  The layer
 * correction is O(E1^2) = O(exp(-2 Re(alpha1) hh)) there (layer_bc.c: its
 * numerator is a sum of products of u1 and d, each O(E1)), the half-space's
 * integrand O(k^-4): the integral stops where the bound on what lies
 * beyond (green_cut.h) is a quarter of the term's budget eps, and that
 * bound is in its error estimate.  The hard limit kmax is where E1^2
 * (k^-4 |s|^2) falls below ktail; where the budget wants more (a point
 * load's terms on a thin plate at some omega) the integral stops there and
 * its estimate holds the larger remainder (ANVIL_ETOL when the sum
 * exceeds eps).  Before, the cut was always at kmax, the remainder not
 * counted: on h = 0.02 r0 under a point load (T' = 16) 519 of 801 terms
 * were off by more than their estimates, the worst 6830 times
 * (tests/test_kcut.c). */
static int k_integral(struct quad *q, struct heap *h, double omega, double hh,
		      double cr, double ktail, double eps, cplx *val, double *abserr)
{
	double wabs = hypot(omega, creal(q->s));
	int hs = q->mode == ANVIL_GREEN_HALFSPACE;
	double kband = anvil_kband(omega, wabs, q->nu, hs ? INFINITY : hh, cr);
	double L = -log(ktail);
	double kmax = hs ? fmax(kband, pow(wabs * wabs / ktail, 0.25))
			 : fmax(kband, sqrt(pow(0.5 * L / hh, 2) + omega * omega));
	struct green_cut cut = { q->mode, q->s, q->kap2, q->nu, hh, hs ? 1.0 : q->patch, q->root, 0 };
	double tail, share = 0.25 * eps;
	double kend = green_cut_find(&cut, q->far_cut ? kmax : kband, kmax, share, &tail);
	/* Starting pieces: about the spacing of the Lamb modes in k (pi/h) in
	 * the band, wider in the smooth tail; the adaptive splitting finds the
	 * poles from there (the results do not move when these are halved).
	 * A thin plate's band holds two poles (A0, S0) below the first
	 * thickness resonance, and at a high bandwidth it is wide (132 at
	 * h = 0.02 r0, omega = 64): its pieces grow to 4 (10 kg at 10 m/s:
	 * 7.6 s became 5.4, P_max the same to 10 digits).  In a narrow band
	 * wider pieces only moved the work to the splitting (h = 0.1-2 r0,
	 * the paper's contact: 0-7 % more evaluations).
	 * The tail's pieces are 16 wide: 2.5 periods of the widest patch's
	 * zhat, which the splitting resolves where it must; a thin plate's
	 * tail reaches 0.5 L/hh (580 at hh = 0.02) and held most of the
	 * pieces at width 4 (h = 0.02 r0, 10 kg: 31.5 M evaluations, 14 M).
	 * A patch's tail ends sooner where its zhat has decayed (green_cut.c's
	 * envelope: 300-400 instead of 575 for 0.5 r0 at hh = 0.02), its
	 * remainder counted; a set's point load (the physical contact's) still
	 * runs to kmax.  So beyond the band a thin plate's kernel comes from
	 * an interpolant (tail_fit, green_tail.h: 17 evaluations a panel 1.5-3
	 * /hh wide, shared by the set's loads at each s), and a point load's
	 * tail pieces are TAIL_POINT_PIECE/hh wide: on h = 0.02 r0, 1 kg at
	 * 10 m/s 2.96 M evaluations became 1.46 M, 1.17 s CPU 0.97 s.
	 * Below the first thickness resonance the band is integrated on a
	 * contour lifted H above the real axis (kernel.h anvil_kband_lift):
	 * the poles' peaks, c0/c_group wide, become bumps H wide, and its
	 * pieces start 2 H wide.  On h = 0.02 r0 at 1 kg, 10 m/s the band's
	 * pieces fell from 69 to 15 a k-integral (all evaluations 7.9 M to
	 * 4.1 M).  Above the cutoff only [klo, kband] is lifted (kernel.h,
	 * ANVIL_LIFT_KS), [0, klo] on the real axis in the band's pieces: on
	 * h = 0.1 r0, 0.1 g at 100 m/s (to 2.4 pi/hh) 2.73 M evaluations
	 * became 1.30 M. */
	double w0 = hs ? 0.5 : anvil_kband_piece(hh, kband), w1 = hs ? 4.0 : ANVIL_KTAIL_PIECE, wr = w0;
	q->klo = 0.0;
	q->lift = hs || q->no_lift ? 0.0
				   : anvil_kband_lift(omega, hh, q->nu, kband, q->wide, &q->klo);
	if (!(q->lift > 0))
		q->klo = 0.0;
	q->klift = q->lift > 0 ? kband : 0.0;
	q->kband = kband;
	if (q->lift > 0)
		w0 = anvil_kband_lift_piece(hh, kband - q->klo, q->lift);
	double kcut = kend, fit = tail_fit(q, &cut, kband, kmax, kend, eps);
	if (q->tail_on)
		w1 = tail_piece(q->patch, hh);
	double kpole = hs || q->full_band ? kband : fmax(q->klo, anvil_kband_poles(omega, wabs, q->nu, hh, cr));
	int st = adapt(q, h, q->klo, wr, kpole, kband, &kend, w0, w1,
		       eps - fmin(tail, share) - fit, val, abserr);
	if (kend < kcut) { /* the starting pieces ran out: the bound from there */
		tail = INFINITY;
		if (kend >= kband)
			green_cut_find(&cut, kend, kend, share, &tail);
	}
	q->evals += cut.evals;
	*abserr += tail + fit;
	return st ? st : *abserr <= eps ? ANVIL_OK : ANVIL_ETOL;
}

/* A layer moves like Zener's plate at late times: its impulse response tends
 * to alpha* (eq 8), in these units sqrt(3 (1 - nu)/2) / (4 hh^2), so its ramp
 * response grows like alpha* t^2/2 and would alias in a periodic inversion.
 * That growth is taken out in the s-domain and put back in time, through
 * the impulse response alpha* (1 - exp(-t/tp)), smooth at t = 0:
 *   ramp  alpha* [t^2/2 - tp t + tp^2 (1 - exp(-t/tp))]  <->  alpha* / (s^3 (1 + s tp)). */
struct green_plate green_plate_term(enum anvil_green_mode mode, double hh, double nu)
{
	struct green_plate pl = { 0.0, 1.0 };
	if (mode == ANVIL_GREEN_LAYER_CORRECTION) {
		pl.alpha = sqrt(1.5 * (1 - nu)) / (4.0 * hh * hh);
		pl.tp = fmax(hh, 0.5);
	}
	return pl;
}

cplx green_plate_s(const struct green_plate *pl, cplx s)
{
	return pl->alpha / (s * s * s * (1.0 + s * pl->tp));
}

double green_plate_t(const struct green_plate *pl, double t)
{
	double tp = pl->tp;
	return pl->alpha * (0.5 * t * t - tp * t - tp * tp * expm1(-t / tp));
}

/* Fill spec[0..M] with the transform of the ramp response on the line dl,
 * and err[n] with the time-domain bound of term n's quadrature error (the
 * caller sums them in a fixed order).  Each k-integral gets the share epsF
 * of the error budget that keeps the time-domain ramp within tol of its
 * size.  The terms are independent: they run on all cores (OpenMP), each
 * thread with its own heap and quad, so the bits do not depend on the
 * number of threads.  Progress is reported (and cancellation seen) on the
 * calling thread only. */
static int spectrum_term(struct quad *q, struct heap *h, const struct green_spectrum *sp, size_t n)
{
	double e;
	cplx In;
	q->s = anvil_durbin_s(sp->dl, n);
	q->patch = sp->patch;
	cplx b = q->s * q->s;
	double s2 = cabs(b);
	int qs = k_integral(q, h, cimag(q->s), q->hh, sp->cr, sp->ktail, sp->epsF * s2, &In, &e);
	sp->spec[n] = In / b - green_plate_s(sp->pl, q->s);
	sp->err[n] = e / s2;
	if (!isfinite(creal(sp->spec[n])) || !isfinite(cimag(sp->spec[n])))
		return ANVIL_ENUM;
	return qs;
}

double green_lift_wide(double lift_patch)
{
	return lift_patch > 0 ? fmin(lift_patch, 1.0) : 1.0;
}

/* The spectra sp[0..nsp-1] (one line: the same s at each n; their bands
 * may differ), term by term, each term's k-integrals one after another on
 * one thread with one kernel memo (kmemo) when there are several; evals[i]
 * the kernel evaluations that sp[i]'s integrals made (memo hits not
 * counted).  Progress and cancellation through sp[0]'s callback. */

int green_sample_spectra(enum anvil_green_mode mode, double kap2, double nu, double hh,
			 const struct green_spectrum *sp, size_t nsp, size_t *evals)
{
	const struct quad q0 = { .mode = mode, .kap2 = kap2, .nu = nu, .hh = hh,
				 .no_lift = sp[0].no_lift, .far_cut = sp[0].far_cut,
				 .full_band = sp[0].full_band,
				 .wide = green_lift_wide(sp[0].lift_patch) };
	size_t M = 0, done = 0;
	int st = ANVIL_OK, stop = 0;
	for (size_t i = 0; i < nsp; i++) {
		M = sp[i].dl->M > M ? sp[i].dl->M : M;
		evals[i] = 0;
	}
#ifdef _OPENMP
#pragma omp parallel
#endif
	{
		struct quad q = q0;
		struct heap *h = malloc(sizeof *h);
		struct kmemo km = { 0 };
		size_t nev[GREEN_SPECTRA_MAX] = { 0 };
		q.root = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
		int mine = h && q.root && (nsp == 1 || kmemo_init(&km)) ? ANVIL_OK : ANVIL_ENOMEM;
		q.memo = nsp > 1 ? &km : NULL;
		q.seg = NULL;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
		for (size_t n = 0; n <= M; n++) {
			int halt, ts = ANVIL_OK;
#ifdef _OPENMP
#pragma omp atomic read
#endif
			halt = stop;
			if (halt || mine == ANVIL_ENOMEM)
				continue;
			kmemo_next(&km);
			for (size_t i = 0; i < nsp && ts != ANVIL_ENUM; i++) {
				if (n > sp[i].dl->M)
					continue;
				q.evals = 0;
				int ti = spectrum_term(&q, h, &sp[i], n);
				nev[i] += q.evals;
				if (ti && (ti != ANVIL_ETOL || !ts))
					ts = ti;
			}
			/* ETOL is kept going: the result says how far off it is */
			if (ts && (ts != ANVIL_ETOL || !mine))
				mine = ts;
			size_t nd;
#ifdef _OPENMP
#pragma omp atomic capture
#endif
			nd = ++done;
			int master = 1;
#ifdef _OPENMP
			master = omp_get_thread_num() == 0;
#endif
			if (ts == ANVIL_ENUM || (master && sp->progress && nd % 4 == 0 &&
						 sp->progress(sp->ctx, (double)nd / (double)(M + 1),
							      "layer response"))) {
				if (ts != ANVIL_ENUM)
					mine = ANVIL_ECANCEL;
#ifdef _OPENMP
#pragma omp atomic write
#endif
				stop = 1;
			}
		}
		kmemo_free(&km);
		gsl_root_fsolver_free(q.root);
		free(h);
#ifdef _OPENMP
#pragma omp critical(anvil_green_status)
#endif
		{
			for (size_t i = 0; i < nsp; i++)
				evals[i] += nev[i];
			/* the worst status wins, whichever thread met it: cancel,
			 * then no memory, then a non-finite term, then a missed tolerance */
			if (mine == ANVIL_ECANCEL || (mine == ANVIL_ENOMEM && st != ANVIL_ECANCEL) ||
			    (mine == ANVIL_ENUM && (st == ANVIL_OK || st == ANVIL_ETOL)) ||
			    (mine == ANVIL_ETOL && st == ANVIL_OK))
				st = mine;
		}
	}
	return st;
}

