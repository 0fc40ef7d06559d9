/* fastconv.h: online (causal) discrete convolution in O(N log^2 N).
 *
 *   c_n = sum_{m < n} x_m g_{n-m},   n = 0 .. cap-1,
 *
 * where x_m becomes known one at a time and c_n is needed before x_n is
 * (an implicit time step: x_n depends on c_n).  The pairs (m, n), m < n,
 * are tiled by squares after Hairer, Lubich and Schlichte (SIAM J. Sci.
 * Stat. Comput. 6, 1985): the pair belongs to level k, the highest bit in
 * which m and n differ, and level k's squares are the sources
 * [2jB, (2j+1)B) against the targets [(2j+1)B, (2j+2)B), B = 2^k.  When
 * x_{L-1} is pushed, L = (2j+1)B with k = ctz(L), that one square is added
 * to the targets' accumulators: by direct products for B <= direct_max,
 * else by one real FFT of size 2B (GSL mixed-radix, tables made once) against the level's kernel
 * spectrum, computed once.  Exact in exact arithmetic; the rounding of an
 * FFT square is about eps log2(2B) sum |x_m g_{n-m}| (tests/test_fastconv.c
 * measures it).  Deterministic: the same pushes give the same bits. */
#ifndef ANVIL_FASTCONV_H
#define ANVIL_FASTCONV_H

#include <stddef.h>

/* Squares of side <= this are summed directly (faster than two FFTs there:
 * scripts/bench, section "long contacts", measured the cross-over). */
#define ANVIL_FASTCONV_DIRECT 64

struct anvil_fastconv;

/* A convolution against the kernel g_0 .. g_{cap-1} (copied; g_0 is never
 * used: the sum is strictly causal) for up to cap pushes.  direct_max: the
 * side up to which squares are summed directly (0: ANVIL_FASTCONV_DIRECT;
 * (size_t)-1: all of them, the O(N^2) direct sum in the same order of
 * squares).  NULL when out of memory or cap = 0. */
struct anvil_fastconv *anvil_fastconv_alloc(const double *g, size_t cap, size_t direct_max);
void anvil_fastconv_free(struct anvil_fastconv *f); /* NULL is a no-op */

/* The FFT tables (GSL wavetables, each level's size) of every convolution
 * of capacity up to cap with squares summed directly up to direct_max
 * (as anvil_fastconv_alloc's; or fewer), each level's made when a
 * convolution first needs it (the same bits whenever made): shared by any
 * number of convolutions of one thread, which must not outlive them.  The
 * tables themselves are the process's, made once for every such handle
 * (fastconv.c, tabs); a handle holds its thread's view of them.
 * NULL when out of memory. */
struct anvil_fastconv_fft;
struct anvil_fastconv_fft *anvil_fastconv_fft_alloc(size_t cap, size_t direct_max);
void anvil_fastconv_fft_free(struct anvil_fastconv_fft *t); /* NULL is a no-op */

/* anvil_fastconv_alloc with the tables fft (borrowed; NULL: its own).
 * NULL also when fft does not cover cap and direct_max. */
struct anvil_fastconv *anvil_fastconv_alloc_fft(const double *g, size_t cap, size_t direct_max,
						struct anvil_fastconv_fft *fft);

/* A pair: c_n = sum_{m < n} (x_m g_{n-m} + y_m h_{n-m}), pushed together
 * (anvil_fastconv_push_pair); the two products of an FFT square are added
 * in the spectrum, so the pair costs three transforms where two
 * convolutions cost four.  As anvil_fastconv_alloc_fft otherwise. */
struct anvil_fastconv *anvil_fastconv_alloc_pair(const double *g, const double *h, size_t cap,
						 size_t direct_max,
						 struct anvil_fastconv_fft *fft);

/* A kernel made as the convolution reaches it: fill(ctx, need) makes
 * g_j (and h_j, h NULL for a single one) for j < need in the caller's
 * arrays, which hold cap values each, never move and outlive f
 * (borrowed, not copied); it returns 0, or nonzero when it fails (the
 * push then returns -3).  Before a square of side B the convolution asks
 * for j < min(2B, cap), all it reads: a march that stops early (a grown
 * step's segment, a short contact) never has the rest made.  fill(ctx, 2)
 * is asked at once (NULL when it fails).  As anvil_fastconv_alloc_pair
 * otherwise; the same bits as a convolution given the whole kernel. */
typedef int (*anvil_fastconv_fill)(void *ctx, size_t need);
struct anvil_fastconv *anvil_fastconv_alloc_lazy(const double *g, const double *h, size_t cap,
						 size_t direct_max,
						 struct anvil_fastconv_fft *fft,
						 anvil_fastconv_fill fill, void *ctx);

/* Forget the pushed values (same kernel): as new. */
void anvil_fastconv_reset(struct anvil_fastconv *f);

/* c_n, n = the number of values pushed so far (complete: every x_m, m < n,
 * is in it).  0 when n >= cap. */
double anvil_fastconv_next(const struct anvil_fastconv *f);

/* Push x_n; returns 0, -1 when cap values have been pushed already, -2
 * when out of memory (a level's spectrum is made when first needed), or
 * -3 when a lazy kernel's fill fails. */
int anvil_fastconv_push(struct anvil_fastconv *f, double x);

/* Push x_n and y_n to a pair (a single convolution takes y_n = 0 only);
 * returns 0, -1 when full or y_n != 0 on a single one, -2 when out of
 * memory, -3 when a lazy kernel's fill fails. */
int anvil_fastconv_push_pair(struct anvil_fastconv *f, double x, double y);

/* c_t for a target t already complete (t <= the count pushed) into *c:
 * 0, or -1 when t is not (yet) complete.  The sums are final once their
 * sources are pushed: a late reader sees the value next() gave. */
int anvil_fastconv_at(const struct anvil_fastconv *f, size_t t, double *c);

/* The number of values pushed. */
size_t anvil_fastconv_count(const struct anvil_fastconv *f);

/* A block of at least bytes from the thread's pool (fastconv.c, pool):
 * its contents undefined (what the last user left), NULL when out of
 * memory.  Give it back with anvil_fastconv_block_free and the same
 * bytes; the next request of the thread that fits gets it again, its
 * pages already mapped.  Small and huge blocks are malloc's. */
void *anvil_fastconv_block(size_t bytes);
void anvil_fastconv_block_free(void *b, size_t bytes); /* NULL is a no-op */

#endif
