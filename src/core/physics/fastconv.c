#include <stdlib.h>
#include <string.h>

#include <math.h>
#include <pthread.h>

#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_fft_halfcomplex.h>
#include <gsl/gsl_fft_real.h>

#include "fastconv.h"

/* The FFT tables of each level: transforms of size 2B, B = 2^k.  GSL's
 * mixed-radix real FFT with its tables made once (plan once, execute many
 * times): 2-3 times faster than the radix-2 one, which recomputes its
 * twiddles and reverses bits on every call (measured, N = 128 .. 2^19);
 * making them costs about as much again as a transform (sines), hence
 * shared between convolutions (anvil_fastconv_fft). */
struct anvil_fastconv_fft {
	int nlev;
	size_t direct_max;
	/* the process's (tabs, below), borrowed */
	gsl_fft_real_wavetable **fw;       /* fw[k], NULL: not made yet (or level k direct or packed) */
	gsl_fft_halfcomplex_wavetable **bw;
	gsl_fft_complex_wavetable **cw;    /* a packed level's (FASTCONV_PACK): size B */
	double **tw;                       /* and its twiddles cos, sin (2 pi j / 2B), j <= B/2 */
};

/* Levels whose transforms (size 2B) are at least this long take the real
 * FFT as a complex one of half the size (pack_forward).  GSL's real
 * mixed-radix transform of 2^14 points took 308 us, of 2^20 90 ms, a
 * complex one of half the size 174 us and 21 ms (measured, this
 * machine); a pair's convolution at N = 1007 (2B <= 1024) gained
 * nothing from packing, one of N = 16000 gained 18 % from 2B = 4096 up
 * and a little less from 2048 or 8192, and N = 386000 (the paper's
 * chattering rows) about 1.5 times.  Another rounding than the real
 * transform's, of the same size (eps log2(2B) sum |x g|:
 * tests/test_fastconv.c).  GSL's radix-2 transforms stay slower at every
 * packed size (bench_conv fft: 2B = 4096 .. 2^20, complex radix-2 1.5-4.7
 * times, real radix-2 1.8-7.5 times the packed mixed-radix one), and a
 * Stockham radix-4 written out gave its bits at its speed (-O2). */
#ifndef FASTCONV_PACK
#define FASTCONV_PACK 4096
#endif

static int packed(size_t B)
{
	return 2 * B >= FASTCONV_PACK;
}

/* The thread's pool of big blocks: a chattering row runs five or six
 * impacts of two passes each, every pass a new convolution of up to a
 * million steps, and each fresh block from the OS cost a page fault (and
 * a memory-cgroup charge) per 4 kB page it touched: 16 % of 0.02 r0,
 * 1 g at 0.1 m/s, user + system (measured).  A block freed here is kept
 * for the thread's next request that fits, its pages already mapped.
 * Sizes rounded up to a power of two (the passes' capacities differ by
 * their steps; malloc maps the rounding's pages only when touched), the
 * smallest block that fits is taken, and the pool holds at most
 * POOL_BLOCKS blocks and POOL_BYTES bytes (the oldest go first).  Per
 * thread (impacts run side by side), freed with it.  The contents are
 * whatever the last user left: callers zero what they read. */
#define POOL_MIN ((size_t)1 << 16)
#define POOL_BLOCKS 32
#define POOL_BYTES ((size_t)1 << 29)

struct pool {
	size_t n, bytes;
	void *p[POOL_BLOCKS];
	size_t sz[POOL_BLOCKS];
};

static pthread_key_t pool_key;
static pthread_once_t pool_once = PTHREAD_ONCE_INIT;
static int pool_ok;

static void pool_free(void *arg)
{
	struct pool *q = arg;
	for (size_t i = 0; i < q->n; i++)
		free(q->p[i]);
	free(q);
}

static void pool_init(void) { pool_ok = !pthread_key_create(&pool_key, pool_free); }

static struct pool *pool_of(void)
{
	pthread_once(&pool_once, pool_init);
	if (!pool_ok)
		return NULL;
	struct pool *q = pthread_getspecific(pool_key);
	if (!q && (q = calloc(1, sizeof *q)) && pthread_setspecific(pool_key, q)) {
		free(q);
		q = NULL;
	}
	return q;
}

static size_t block_size(size_t bytes)
{
	size_t sz = POOL_MIN;
	while (sz < bytes)
		sz *= 2;
	return sz;
}

void *anvil_fastconv_block(size_t bytes)
{
	if (bytes < POOL_MIN || bytes > POOL_BYTES)
		return malloc(bytes);
	size_t sz = block_size(bytes);
	struct pool *q = pool_of();
	size_t best = q ? q->n : 0;
	for (size_t i = 0; q && i < q->n; i++)
		if (q->sz[i] >= sz && (best == q->n || q->sz[i] < q->sz[best]))
			best = i;
	if (!q || best == q->n)
		return malloc(sz);
	void *b = q->p[best];
	q->bytes -= q->sz[best];
	q->n--;
	memmove(q->p + best, q->p + best + 1, (q->n - best) * sizeof *q->p);
	memmove(q->sz + best, q->sz + best + 1, (q->n - best) * sizeof *q->sz);
	return b;
}

void anvil_fastconv_block_free(void *b, size_t bytes)
{
	struct pool *q = b && bytes >= POOL_MIN && bytes <= POOL_BYTES ? pool_of() : NULL;
	if (!q) {
		free(b);
		return;
	}
	size_t sz = block_size(bytes);
	while (q->n && (q->n == POOL_BLOCKS || q->bytes + sz > POOL_BYTES)) {
		free(q->p[0]); /* the oldest */
		q->bytes -= q->sz[0];
		q->n--;
		memmove(q->p, q->p + 1, q->n * sizeof *q->p);
		memmove(q->sz, q->sz + 1, q->n * sizeof *q->sz);
	}
	q->p[q->n] = b, q->sz[q->n] = sz;
	q->bytes += sz;
	q->n++;
}

/* Levels at most: squares of side up to 2^62. */
#define FASTCONV_LEVELS 63

/* One FFT level of a convolution. */
struct level {
	double *spec[2]; /* FFT of g_0..g_{2B-1}, per kernel: halfcomplex (mixed-radix
			  * packing), or on a packed level X_0 .. X_B complex */
	/* GSL wants one of the transform's own size: the convolution's
	 * scratch (one level at a time), n set to it */
	gsl_fft_real_workspace ws;
	gsl_fft_complex_workspace cws; /* a packed level's, size B */
};

struct anvil_fastconv {
	size_t cap, n, direct_max;
	size_t nz;    /* 1 + the index of the last nonzero value pushed (0: none) */
	size_t hi;    /* acc's entries zeroed, then summed into: [0, hi) */
	int nk;       /* kernels: 1, or 2 for a pair */
	const double *g[2]; /* kernels, cap: own copies, or borrowed (fill) */
	double *own_g[2];
	anvil_fastconv_fill fill; /* a lazy kernel's maker, or NULL */
	void *fctx;
	size_t have;  /* a lazy kernel's entries made */
	double *x[2]; /* pushed values, cap */
	double *acc;  /* partial sums c_n, cap */
	double *buf[2]; /* scratch, 2 B_max + 2 */
	double *scr;    /* the FFT's scratch, 2 B_max */
	struct level *lev; /* lev[k].spec[0] NULL: level k is summed directly */
	int nlev;
	struct anvil_fastconv_fft *fft; /* the tables: shared, or own */
	struct anvil_fastconv_fft *own;
};

/* The levels of capacity cap: squares have B < cap. */
static int levels_of(size_t cap)
{
	int n = 0;
	while (((size_t)1 << n) < cap)
		n++;
	return n;
}

static size_t direct_of(size_t direct_max)
{
	return direct_max ? direct_max : ANVIL_FASTCONV_DIRECT;
}

/* Every level's tables, kept for the process: a pure function of the
 * size, made once whoever asks first (the same bits), and each impact
 * (anvil_impact_run) made them all again: the paper contact's rows run
 * five or six impacts of the same steps (its bands and twin), and the
 * sines of their largest levels took 4-6 % of h = 0.2 r0, 100 g at
 * 1000 m/s.  Guarded by a lock (impacts run on threads side by side);
 * GSL only reads them.  Never freed: at most twice the largest size
 * asked for, still reachable at exit. */
static struct {
	pthread_mutex_t lock;
	gsl_fft_real_wavetable *fw[FASTCONV_LEVELS];
	gsl_fft_halfcomplex_wavetable *bw[FASTCONV_LEVELS];
	gsl_fft_complex_wavetable *cw[FASTCONV_LEVELS];
	double *tw[FASTCONV_LEVELS];
} tabs = { .lock = PTHREAD_MUTEX_INITIALIZER };

void anvil_fastconv_fft_free(struct anvil_fastconv_fft *t)
{
	if (!t)
		return;
	free(t->fw);
	free(t->bw);
	free(t->cw);
	free(t->tw);
	free(t);
}

struct anvil_fastconv_fft *anvil_fastconv_fft_alloc(size_t cap, size_t direct_max)
{
	struct anvil_fastconv_fft *t = calloc(1, sizeof *t);
	if (!t)
		return NULL;
	t->nlev = levels_of(cap);
	t->direct_max = direct_of(direct_max);
	t->fw = calloc((size_t)t->nlev + 1, sizeof *t->fw);
	t->bw = calloc((size_t)t->nlev + 1, sizeof *t->bw);
	t->cw = calloc((size_t)t->nlev + 1, sizeof *t->cw);
	t->tw = calloc((size_t)t->nlev + 1, sizeof *t->tw);
	if (!t->fw || !t->bw || !t->cw || !t->tw || t->nlev >= FASTCONV_LEVELS) {
		anvil_fastconv_fft_free(t);
		return NULL;
	}
	/* each level's tables when first needed (fft_level): a grown step's
	 * segments stop far short of the window that sized them, and the
	 * large levels' sines cost more than their transforms */
	return t;
}

/* Level k's tables into tabs, made on first use: the same bits whenever
 * made.  -1 when out of memory.  Under tabs.lock. */
static int tabs_level(int k)
{
	size_t N = (size_t)2 << k, B = N / 2;
	if (packed(B)) {
		if (!tabs.cw[k] && !(tabs.cw[k] = gsl_fft_complex_wavetable_alloc(B)))
			return -1;
		if (!tabs.tw[k]) {
			double *tw = malloc((B + 2) * sizeof *tw);
			if (!tw)
				return -1;
			for (size_t j = 0; j <= B / 2; j++) {
				tw[2 * j] = cos(2.0 * M_PI * (double)j / (double)N);
				tw[2 * j + 1] = sin(2.0 * M_PI * (double)j / (double)N);
			}
			tabs.tw[k] = tw;
		}
		return 0;
	}
	if (!tabs.fw[k] && !(tabs.fw[k] = gsl_fft_real_wavetable_alloc(N)))
		return -1;
	if (!tabs.bw[k] && !(tabs.bw[k] = gsl_fft_halfcomplex_wavetable_alloc(N)))
		return -1;
	return 0;
}

/* Level k's tables in t (the process's, tabs): -1 when out of memory. */
static int fft_level(struct anvil_fastconv_fft *t, int k)
{
	if (packed((size_t)1 << k) ? t->cw[k] && t->tw[k] : t->fw[k] && t->bw[k])
		return 0;
	pthread_mutex_lock(&tabs.lock);
	int st = tabs_level(k);
	t->fw[k] = tabs.fw[k], t->bw[k] = tabs.bw[k];
	t->cw[k] = tabs.cw[k], t->tw[k] = tabs.tw[k];
	pthread_mutex_unlock(&tabs.lock);
	return st;
}

/* Level k's spectrum, 2B + 2 values; the buffers, 2 B_max + 2. */
static size_t spec_bytes(int k) { return ((size_t)2 << k) * sizeof(double) + 2 * sizeof(double); }
static size_t buf_bytes(int nlev) { return spec_bytes(nlev); }

void anvil_fastconv_free(struct anvil_fastconv *f)
{
	if (!f)
		return;
	for (int k = 0; f->lev && k < f->nlev; k++)
		for (int i = 0; i < 2; i++)
			anvil_fastconv_block_free(f->lev[k].spec[i], spec_bytes(k));
	free(f->lev);
	anvil_fastconv_fft_free(f->own);
	for (int i = 0; i < 2; i++) {
		anvil_fastconv_block_free(f->own_g[i], f->cap * sizeof *f->own_g[i]);
		anvil_fastconv_block_free(f->x[i], f->cap * sizeof *f->x[i]);
		anvil_fastconv_block_free(f->buf[i], buf_bytes(f->nlev));
	}
	anvil_fastconv_block_free(f->scr, buf_bytes(f->nlev));
	anvil_fastconv_block_free(f->acc, f->cap * sizeof *f->acc);
	free(f);
}

/* The spectrum X_0 .. X_B (complex, interleaved) of the real x_0 ..
 * x_{2B-1} in a (2B + 2 values), in place: the complex FFT of size B of
 * z_n = x_{2n} + i x_{2n+1}, then X_j = E + w^j O and X_{B-j} =
 * conj(E - w^j O), E = (Z_j + conj Z_{B-j})/2, O = -i (Z_j - conj
 * Z_{B-j})/2, w = e^{-2 pi i/2B}.  B even. */
static void pack_forward(double *a, size_t B, const gsl_fft_complex_wavetable *cw,
			 gsl_fft_complex_workspace *cws, const double *tw)
{
	gsl_fft_complex_forward(a, 1, B, cw, cws);
	double r0 = a[0], i0 = a[1];
	a[0] = r0 + i0, a[1] = 0.0;
	a[2 * B] = r0 - i0, a[2 * B + 1] = 0.0;
	for (size_t j = 1; j <= B / 2; j++) {
		double *zj = a + 2 * j, *zm = a + 2 * (B - j);
		double er = 0.5 * (zj[0] + zm[0]), ei = 0.5 * (zj[1] - zm[1]);
		double o_r = 0.5 * (zj[1] + zm[1]), o_i = -0.5 * (zj[0] - zm[0]);
		double c = tw[2 * j], sn = tw[2 * j + 1]; /* w^j = c - i sn */
		double pr = c * o_r + sn * o_i, pi = c * o_i - sn * o_r;
		zj[0] = er + pr, zj[1] = ei + pi;
		zm[0] = er - pr, zm[1] = -(ei - pi);
	}
}

/* The real y_0 .. y_{2B-1} of the Hermitian spectrum Y_0 .. Y_B in a, in
 * place (pack_forward's inverse, 1/(2B) included): Z_j = E + i O,
 * Z_{B-j} = conj E + i conj O, E = (Y_j + conj Y_{B-j})/2, O = (Y_j -
 * conj Y_{B-j}) conj(w^j)/2, then the complex inverse FFT of size B. */
static void pack_inverse(double *a, size_t B, const gsl_fft_complex_wavetable *cw,
			 gsl_fft_complex_workspace *cws, const double *tw)
{
	double y0 = a[0], yb = a[2 * B];
	a[0] = 0.5 * (y0 + yb), a[1] = 0.5 * (y0 - yb);
	for (size_t j = 1; j <= B / 2; j++) {
		double *yj = a + 2 * j, *ym = a + 2 * (B - j);
		double er = 0.5 * (yj[0] + ym[0]), ei = 0.5 * (yj[1] - ym[1]);
		double dr = 0.5 * (yj[0] - ym[0]), di = 0.5 * (yj[1] + ym[1]);
		double c = tw[2 * j], sn = tw[2 * j + 1]; /* conj(w^j) = c + i sn */
		double o_r = c * dr - sn * di, o_i = c * di + sn * dr;
		yj[0] = er - o_i, yj[1] = ei + o_r;
		ym[0] = er + o_i, ym[1] = -ei + o_r;
	}
	gsl_fft_complex_inverse(a, 1, B, cw, cws);
}

/* Level k's workspace and the kernels' spectra for squares of side
 * B = 2^k: g_0 .. g_{2B-1}, zero past cap.  -1 when out of memory. */
static int level_init(struct anvil_fastconv *f, int k)
{
	size_t B = (size_t)1 << k;
	struct level *l = &f->lev[k];
	if (fft_level(f->fft, k))
		return -1;
	l->cws = (gsl_fft_complex_workspace){ .n = B, .scratch = f->scr };
	l->ws = (gsl_fft_real_workspace){ .n = 2 * B, .scratch = f->scr };
	for (int i = 0; i < f->nk; i++) {
		double *sp = l->spec[i] = anvil_fastconv_block(spec_bytes(k));
		if (!sp)
			return -1;
		size_t ng = 2 * B < f->cap ? 2 * B : f->cap;
		memcpy(sp, f->g[i], ng * sizeof *sp);
		memset(sp + ng, 0, (2 * B + 2 - ng) * sizeof *sp);
		if (packed(B))
			pack_forward(sp, B, f->fft->cw[k], &l->cws, f->fft->tw[k]);
		else if (gsl_fft_real_transform(sp, 1, 2 * B, f->fft->fw[k], &l->ws))
			return -1;
	}
	return 0;
}

static struct anvil_fastconv *alloc_kernels(const double *const *g, int nk, size_t cap,
					    size_t direct_max, struct anvil_fastconv_fft *fft,
					    anvil_fastconv_fill fill, void *fctx);

struct anvil_fastconv *anvil_fastconv_alloc_fft(const double *g, size_t cap, size_t direct_max,
						struct anvil_fastconv_fft *fft)
{
	return alloc_kernels(&g, 1, cap, direct_max, fft, NULL, NULL);
}

struct anvil_fastconv *anvil_fastconv_alloc_pair(const double *g, const double *h, size_t cap,
						 size_t direct_max,
						 struct anvil_fastconv_fft *fft)
{
	const double *gh[2] = { g, h };
	return alloc_kernels(gh, 2, cap, direct_max, fft, NULL, NULL);
}

struct anvil_fastconv *anvil_fastconv_alloc_lazy(const double *g, const double *h, size_t cap,
						 size_t direct_max,
						 struct anvil_fastconv_fft *fft,
						 anvil_fastconv_fill fill, void *ctx)
{
	const double *gh[2] = { g, h };
	if (!fill)
		return NULL;
	struct anvil_fastconv *f = alloc_kernels(gh, h ? 2 : 1, cap, direct_max, fft, fill, ctx);
	size_t need = cap < 2 ? cap : 2;
	if (f && fill(ctx, need)) {
		anvil_fastconv_free(f);
		return NULL;
	}
	if (f)
		f->have = need;
	return f;
}

static struct anvil_fastconv *alloc_kernels(const double *const *g, int nk, size_t cap,
					    size_t direct_max, struct anvil_fastconv_fft *fft,
					    anvil_fastconv_fill fill, void *fctx)
{
	if (!cap)
		return NULL;
	struct anvil_fastconv *f = calloc(1, sizeof *f);
	if (!f)
		return NULL;
	f->cap = cap;
	f->direct_max = direct_of(direct_max);
	f->nlev = levels_of(cap);
	if (fft && (fft->nlev < f->nlev || fft->direct_max > f->direct_max)) {
		free(f);
		return NULL; /* tables that do not cover these levels */
	}
	f->nk = nk;
	f->fill = fill, f->fctx = fctx;
	f->fft = fft ? fft : (f->own = anvil_fastconv_fft_alloc(cap, f->direct_max));
	int bad = !f->fft;
	for (int i = 0; i < nk && !bad; i++) {
		/* never zeroed: x_m is read only once pushed (m < n); malloc's
		 * pages a march never reaches are never touched (calloc's can be
		 * memset whole: glibc serves a freed large block from the heap) */
		f->x[i] = anvil_fastconv_block(cap * sizeof *f->x[i]);
		f->buf[i] = anvil_fastconv_block(buf_bytes(f->nlev));
		if (fill)
			f->g[i] = g[i];
		else if ((f->g[i] = f->own_g[i] = anvil_fastconv_block(cap * sizeof *f->own_g[i])))
			memcpy(f->own_g[i], g[i], cap * sizeof *g[i]);
		bad = !f->g[i] || !f->x[i] || !f->buf[i];
	}
	f->acc = anvil_fastconv_block(cap * sizeof *f->acc); /* zeroed as the squares reach it (hi) */
	f->scr = anvil_fastconv_block(buf_bytes(f->nlev));
	f->lev = calloc((size_t)f->nlev + 1, sizeof *f->lev);
	if (bad || !f->acc || !f->scr || !f->lev) {
		anvil_fastconv_free(f);
		return NULL;
	}
	/* the levels' spectra when first needed (push): a convolution that
	 * stops early (a grown step's segment, a short contact) makes none of
	 * the large ones; the same bits whenever made */
	return f;
}

struct anvil_fastconv *anvil_fastconv_alloc(const double *g, size_t cap, size_t direct_max)
{
	return anvil_fastconv_alloc_fft(g, cap, direct_max, NULL);
}

void anvil_fastconv_reset(struct anvil_fastconv *f)
{
	/* x is read only once pushed again; acc is zeroed again as the
	 * squares reach it */
	f->n = f->nz = f->hi = 0;
}

double anvil_fastconv_next(const struct anvil_fastconv *f)
{
	return f->n < f->hi ? f->acc[f->n] : 0.0; /* beyond hi: no square has reached it */
}

int anvil_fastconv_at(const struct anvil_fastconv *f, size_t t, double *c)
{
	if (t > f->n)
		return -1;
	*c = t < f->hi ? f->acc[t] : 0.0; /* beyond hi: no square has reached it */
	return 0;
}

size_t anvil_fastconv_count(const struct anvil_fastconv *f) { return f->n; }

/* Sources [L-B, L) into targets [L, min(L+B, cap)), directly: eight
 * targets at a time, each summed alone in the order m = L-B, L-B+1, ...
 * (eight independent chains where one stalled on the adder's latency:
 * the same bits as one target at a time; four chains left the adder
 * idle half the time). */
static void square_direct(struct anvil_fastconv *f, const double *x, const double *g, size_t L,
			  size_t B)
{
	size_t end = L + B < f->cap ? L + B : f->cap, t = L;
	for (; t + 8 <= end; t += 8) {
		/* scalars, not an array: gcc 12 at -O2 kept an array's sums in
		 * memory, each step waiting on its own store */
		double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0;
		for (size_t m = L - B; m < L; m++) {
			const double xm = x[m], *gm = g + (t - m);
			s0 += xm * gm[0];
			s1 += xm * gm[1];
			s2 += xm * gm[2];
			s3 += xm * gm[3];
			s4 += xm * gm[4];
			s5 += xm * gm[5];
			s6 += xm * gm[6];
			s7 += xm * gm[7];
		}
		double *a = f->acc + t;
		a[0] += s0, a[1] += s1, a[2] += s2, a[3] += s3;
		a[4] += s4, a[5] += s5, a[6] += s6, a[7] += s7;
	}
	for (; t < end; t++) {
		double s = 0;
		for (size_t m = L - B; m < L; m++)
			s += x[m] * g[t - m];
		f->acc[t] += s;
	}
}

/* A pair's square: four targets at a time, the two kernels' sums side by
 * side (eight chains) and each added as square_direct adds it, the first
 * kernel's then the second's: the same bits as two square_direct calls,
 * one pass over the sources. */
static void square_direct_pair(struct anvil_fastconv *f, size_t L, size_t B)
{
	const double *x = f->x[0], *y = f->x[1], *g = f->g[0], *h = f->g[1];
	size_t end = L + B < f->cap ? L + B : f->cap, t = L;
	for (; t + 4 <= end; t += 4) {
		double s0 = 0, s1 = 0, s2 = 0, s3 = 0, r0 = 0, r1 = 0, r2 = 0, r3 = 0;
		for (size_t m = L - B; m < L; m++) {
			const double xm = x[m], ym = y[m], *gm = g + (t - m), *hm = h + (t - m);
			s0 += xm * gm[0];
			s1 += xm * gm[1];
			s2 += xm * gm[2];
			s3 += xm * gm[3];
			r0 += ym * hm[0];
			r1 += ym * hm[1];
			r2 += ym * hm[2];
			r3 += ym * hm[3];
		}
		double *a = f->acc + t;
		a[0] = (a[0] + s0) + r0, a[1] = (a[1] + s1) + r1;
		a[2] = (a[2] + s2) + r2, a[3] = (a[3] + s3) + r3;
	}
	for (; t < end; t++) {
		double s = 0, r = 0;
		for (size_t m = L - B; m < L; m++) {
			s += x[m] * g[t - m];
			r += y[m] * h[t - m];
		}
		f->acc[t] = (f->acc[t] + s) + r;
	}
}

/* The same square by a cyclic convolution of size 2B: for targets
 * L + i (i < B) the lags B + i - s lie in [1, 2B), so nothing wraps.  A
 * pair's two products are added in the spectrum: one inverse transform. */
static void square_packed(struct anvil_fastconv *f, size_t L, size_t B, int k);

static void square_fft(struct anvil_fastconv *f, size_t L, size_t B, int k)
{
	struct level *l = &f->lev[k];
	size_t N = 2 * B, end = L + B < f->cap ? L + B : f->cap;
	if (packed(B)) {
		square_packed(f, L, B, k);
		return;
	}
	for (int i = 0; i < f->nk; i++) {
		memcpy(f->buf[i], f->x[i] + (L - B), B * sizeof *f->buf[i]);
		memset(f->buf[i] + B, 0, B * sizeof *f->buf[i]);
		gsl_fft_real_transform(f->buf[i], 1, N, f->fft->fw[k], &l->ws);
	}
	/* mixed-radix halfcomplex product: b[0], b[N-1] real (frequencies 0
	 * and N/2); (b[2j-1], b[2j]) = (re, im) of frequency j, 0 < j < N/2 */
	double *b = f->buf[0];
	const double *G = l->spec[0];
	if (f->nk == 1) {
		b[0] *= G[0];
		b[N - 1] *= G[N - 1];
		for (size_t j = 1; j + 1 < N; j += 2) {
			double re = b[j] * G[j] - b[j + 1] * G[j + 1];
			double im = b[j] * G[j + 1] + b[j + 1] * G[j];
			b[j] = re;
			b[j + 1] = im;
		}
	} else {
		const double *c = f->buf[1], *H = l->spec[1];
		b[0] = b[0] * G[0] + c[0] * H[0];
		b[N - 1] = b[N - 1] * G[N - 1] + c[N - 1] * H[N - 1];
		for (size_t j = 1; j + 1 < N; j += 2) {
			double re = b[j] * G[j] - b[j + 1] * G[j + 1] + (c[j] * H[j] - c[j + 1] * H[j + 1]);
			double im = b[j] * G[j + 1] + b[j + 1] * G[j] + (c[j] * H[j + 1] + c[j + 1] * H[j]);
			b[j] = re;
			b[j + 1] = im;
		}
	}
	gsl_fft_halfcomplex_inverse(b, 1, N, f->fft->bw[k], &l->ws);
	for (size_t t = L; t < end; t++)
		f->acc[t] += b[B + (t - L)];
}

/* square_fft on a packed level: the spectra X_0 .. X_B as complex
 * numbers (pack_forward), the pair's products added there. */
static void square_packed(struct anvil_fastconv *f, size_t L, size_t B, int k)
{
	struct level *l = &f->lev[k];
	const gsl_fft_complex_wavetable *cw = f->fft->cw[k];
	const double *tw = f->fft->tw[k];
	size_t end = L + B < f->cap ? L + B : f->cap;
	for (int i = 0; i < f->nk; i++) {
		memcpy(f->buf[i], f->x[i] + (L - B), B * sizeof *f->buf[i]);
		memset(f->buf[i] + B, 0, (B + 2) * sizeof *f->buf[i]);
		pack_forward(f->buf[i], B, cw, &l->cws, tw);
	}
	double *b = f->buf[0];
	const double *G = l->spec[0];
	if (f->nk == 1) {
		for (size_t j = 0; j <= 2 * B; j += 2) {
			double re = b[j] * G[j] - b[j + 1] * G[j + 1];
			double im = b[j] * G[j + 1] + b[j + 1] * G[j];
			b[j] = re;
			b[j + 1] = im;
		}
	} else {
		const double *c = f->buf[1], *H = l->spec[1];
		for (size_t j = 0; j <= 2 * B; j += 2) {
			double re = b[j] * G[j] - b[j + 1] * G[j + 1] + (c[j] * H[j] - c[j + 1] * H[j + 1]);
			double im = b[j] * G[j + 1] + b[j + 1] * G[j] + (c[j] * H[j + 1] + c[j + 1] * H[j]);
			b[j] = re;
			b[j + 1] = im;
		}
	}
	pack_inverse(b, B, cw, &l->cws, tw);
	for (size_t t = L; t < end; t++)
		f->acc[t] += b[B + (t - L)];
}

int anvil_fastconv_push_pair(struct anvil_fastconv *f, double x, double y)
{
	if (f->n >= f->cap || (f->nk == 1 && y != 0.0))
		return -1;
	f->x[0][f->n] = x;
	if (f->nk == 2)
		f->x[1][f->n] = y;
	f->n++;
	if (x != 0.0 || y != 0.0)
		f->nz = f->n;
	size_t L = f->n;
	if (L >= f->cap)
		return 0; /* no target left */
	int k = 0; /* the trailing zeros of L */
	while (!((L >> k) & 1))
		k++;
	size_t B = (size_t)1 << k;
	if (f->nz <= L - B)
		return 0; /* sources all zero (free flight): the square adds nothing */
	size_t need = 2 * B < f->cap ? 2 * B : f->cap, end = L + B < f->cap ? L + B : f->cap;
	if (f->fill && need > f->have) { /* a square reads g_j, j < 2B */
		if (f->fill(f->fctx, need))
			return -3;
		f->have = need;
	}
	if (end > f->hi) { /* the targets' sums start at zero */
		memset(f->acc + f->hi, 0, (end - f->hi) * sizeof *f->acc);
		f->hi = end;
	}
	if (k < f->nlev && B > f->direct_max && !f->lev[k].spec[0] && level_init(f, k))
		return -2;
	if (k < f->nlev && f->lev[k].spec[0])
		square_fft(f, L, B, k);
	else if (f->nk == 2)
		square_direct_pair(f, L, B);
	else
		square_direct(f, f->x[0], f->g[0], L, B);
	return 0;
}

int anvil_fastconv_push(struct anvil_fastconv *f, double x)
{
	return anvil_fastconv_push_pair(f, x, 0.0);
}
