/* cache.h: layer responses made once and kept ("plan once, execute many").
 *
 * Once made dimensionless (green.h) the layer's centre response depends only
 * on h/r0, Poisson's ratio and the accuracy level, plus the window
 * [0, tau_end] and the bandwidth omega it was computed for.  Windows and
 * bandwidths are rounded up to a geometric grid (ANVIL_CACHE_STEPS points
 * per octave: at most 19 % more than asked, 9 % on average), so a change
 * of velocity, mass or impactor material that stays on the same grid
 * points re-runs without recomputing.  Lookups are exact (the same grid
 * point of window and bandwidth): a response made for a longer window or
 * a wider band would change the result's last bits, and the same scene
 * gives the same bits whatever the cache holds.
 *
 * Lifetime: every response pointer the cache returns (anvil_cache_find,
 * _add, _halfspace) is held for the caller: it stays valid, and is never
 * evicted, until the caller gives it back with anvil_cache_release (once
 * per return), or until anvil_cache_free.  Unheld responses are evicted
 * least recently used first.
 *
 * Two levels:
 *   memory  a least-recently-used table of ANVIL_CACHE_SLOTS responses,
 *           layer corrections and exact half-spaces;
 *   disk    optional: one file per (h/r0, nu, level, omega) in a directory
 *           (anvil_cache_default_dir: $XDG_CACHE_HOME/anvil), written
 *           atomically (a temporary file renamed into place) so that
 *           concurrent runs never see half a file.  A file that fails its
 *           checks (size, checksum, samples) is ignored with a warning and
 *           replaced; one from another format or anvil version is ignored
 *           quietly and replaced.
 *
 * The file: a 184-byte header (struct below: magic "ANVILRSP", format
 * version, byte-order mark, anvil version, the mode and twin flag, the key h/r0, nu, level, omega
 * and its grid index, the window's grid index, the load and patch radius (format 4:
 * the physical contact's corrections are kept too; a file of format 3 or older
 * is ignored quietly and replaced), the window tau_end, the sample step, the error
 * estimate, the plate's tail (format 8: its T1, the fit's error unit and
 * coefficients; 0 without), the sample count, the tail's K-table node count
 * an FNV-1a 64-bit checksum of header, samples and nodes (on 64-bit
 * words, format 26), and the
 * key's widest patch of the row, format 21), then the
 * ramp samples, the K and S tables and the samples' spline's c_i (format
 * 26; green.h anvil_green_samples) as native doubles.  A file is only read on a machine with the same byte order and
 * double format.
 *
 * One cache is used from one thread at a time (the solver's). */
#ifndef ANVIL_CACHE_H
#define ANVIL_CACHE_H

#include <stddef.h>

#include "accuracy.h"
#include "status.h"

struct anvil_green;     /* green.h */
struct anvil_halfspace; /* halfspace.h */

#define ANVIL_CACHE_STEPS 4  /* grid points per octave */
#define ANVIL_CACHE_SLOTS 24 /* responses kept in memory */
#define ANVIL_CACHE_FORMAT 27 /* disk format version (2: the window index in the key;
				 3: the twin flag; 4: the load and patch radius; 5: the
				 plate's blended join at T1, plate.c: a response from
				 before holds the stepped join and other bits; 6: the
				 physical contact's corrections filtered at the band's
				 edge, green.h; 7: the filter flag in the header, which
				 the reader's causality check needs; 8: the plate's
				 closed-form tail beyond T1 instead of samples to the
				 window's end, plate.h; 9: the tail's Kirchhoff plate
				 under the response's own patch, not r0's; 10: the
				 tail's Mindlin term, its S table after K's; 11: the
				 band's k-integral on a lifted contour, kernel.h
				 anvil_kband_lift, and the rounding stop,
				 green_spectrum.c: other bits; 12: zhat by angle sums,
				 green_spectrum.c, K's smooth tail in closed form,
				 plate.c; 13: the angle sums in the tail only, the
				 band's zhat direct again; 14: the k-integrals cut
				 by their budget, green_cut.h, the remainder in the
				 estimate; 15: the layer correction's tail kernel
				 from its interpolant, green_tail.h; 16: T1 =
				 max(64, 16 hh) from h = r0, the tail from a
				 window of 2 T1 there, plate.h; 17: the plate's
				 K and S table by Gauss-Kronrod on fixed panels,
				 plate.c panel_qk31: other bits; 18: the tail's
				 stored unit v the larger of the fit's misfit and
				 its coefficients' spread, plate.h; 19: the
				 band lifted to 0.8 of S1's cutoff, kernel.h
				 anvil_lift_cutoff: other bits above 0.9 pi/hh;
				 20: the plate tail's table's late nodes (beta t >=
				 patch^2) in part interpolated, plate.c
				 nodes_fill; 21: the physical contact's band
				 lifted up to 8 over the row's widest patch,
				 kernel.h anvil_kband_lift, that patch in the
				 key and the header, which grew to 184 bytes;
				 22: above the lift's cutoff the band lifted
				 from k hh = 3 on, kernel.h ANVIL_LIFT_KS; 23:
				 the tail's panels at degree 8 where that meets
				 the load's share, green_tail.h, and gk21's
				 estimate without pow and hypot: other bits; 24:
				 a thick layer's band past its poles in one
				 starting piece, kernel.h anvil_kband_poles; 25:
				 the lifted band's sin and cos by angle sums,
				 green_spectrum.c lifted_piece: other bits; 26:
				 the checksum's FNV-1a on 64-bit words, cache.c,
				 and the spline's c_i after the tables, green.h
				 curv; 27: E2 from E1 (kernel.h
				 anvil_kernel_exp2) and the tail's exponentials
				 from its pieces' centres: other bits) */

/* The grid: 2^(idx / ANVIL_CACHE_STEPS), and the smallest idx whose grid
 * value is >= x > 0. */
double anvil_cache_grid(int idx);
int anvil_cache_grid_up(double x);

/* What a layer correction depends on (green.h's dimensionless form). */
struct anvil_cache_key {
	double hh, nu;           /* h/r0, Poisson's ratio */
	enum anvil_accuracy acc; /* the inversion settings' level */
	int omega_idx;           /* bandwidth omega = anvil_cache_grid(omega_idx) */
	int tau_idx;             /* window tau_end = anvil_cache_grid(tau_idx) */
	int twin;                /* 1: the coarse twin of the main response at
				    omega_idx + ANVIL_CACHE_STEPS (green.h's
				    anvil_green_alloc_twin: the first terms of
				    that one's spectrum), 0: a response made alone */
	int load;                /* ANVIL_CACHE_LOAD_R0 (0): the paper's contact, a
				    Hertz patch of radius r0 made with its twin;
				    ANVIL_CACHE_LOAD_PATCH: the physical contact's
				    correction for a Hertz patch of radius patch r0
				    (green.h anvil_green_alloc_patch; 0 a point load),
				    no twin (twin 0) */
	double patch;            /* LOAD_PATCH: the radius / r0, in [0, 1]; else 0 */
	double lift_patch;       /* LOAD_PATCH: the row's widest patch, whose
				    lifted contour its loads share (green.h
				    anvil_green_settings; the point load's bits
				    depend on it); else 0 */
};

enum { ANVIL_CACHE_LOAD_R0 = 0, ANVIL_CACHE_LOAD_PATCH = 1 };

/* Where a response came from. */
enum anvil_cache_where { ANVIL_CACHE_NONE, ANVIL_CACHE_MEMORY, ANVIL_CACHE_DISK };

struct anvil_cache_stats {
	unsigned long mem_hits, disk_hits, misses;
	unsigned long disk_writes;   /* files written */
	unsigned long disk_corrupt;  /* files ignored with a warning */
	unsigned long disk_stale;    /* other format or anvil version: ignored */
	unsigned long disk_failures; /* files that could not be written */
};

/* A warning for the user ("cache: FILE: bad checksum; ignored"); the
 * cache never prints. */
typedef void (*anvil_warn_fn)(void *ctx, const char *msg);

struct anvil_cache;

/* An empty cache, memory only.  NULL when out of memory. */
struct anvil_cache *anvil_cache_alloc(void);
void anvil_cache_free(struct anvil_cache *c); /* NULL is a no-op */

/* Use directory dir (created when missing, mode 0700) for the disk level;
 * NULL or "" turns the disk level off.  The directory is only touched when
 * a response is looked up or stored.  ANVIL_EINVAL for a name too long,
 * ANVIL_ENOMEM. */
int anvil_cache_set_dir(struct anvil_cache *c, const char *dir, struct anvil_err *err);
/* The directory in use, or NULL when the disk level is off. */
const char *anvil_cache_dir(const struct anvil_cache *c);
void anvil_cache_set_warn(struct anvil_cache *c, anvil_warn_fn fn, void *ctx);
void anvil_cache_stats(const struct anvil_cache *c, struct anvil_cache_stats *st);

/* The default directory from the environment into buf: "" (disk caching
 * off) when ANVIL_NO_CACHE is set to anything but "" or "0", else
 * $XDG_CACHE_HOME/anvil (an absolute XDG_CACHE_HOME only, as the XDG spec
 * says), else $HOME/.cache/anvil, else "".  Returns buf. */
char *anvil_cache_default_dir(char *buf, size_t n);

/* The exact half-space response for nu at tolerance tol, made and kept in
 * memory on first use (it costs well under a millisecond); held for the
 * caller.  NULL with err set as anvil_halfspace_alloc does, or ANVIL_ENOMEM
 * when every slot is held. */
const struct anvil_halfspace *anvil_cache_halfspace(struct anvil_cache *c, double nu, double tol,
						    struct anvil_err *err);

/* The layer correction of key (exactly that window and bandwidth), from
 * memory, else from disk (then kept in memory); held for the caller.
 * NULL on a miss.  *where (may be NULL) says which. */
const struct anvil_green *anvil_cache_find(struct anvil_cache *c, const struct anvil_cache_key *key,
					   enum anvil_cache_where *where);
/* Whether find would succeed, without loading anything (for the planner's
 * cost estimate): ANVIL_CACHE_MEMORY, _DISK (a file whose header matches;
 * its samples are checked when it is read) or _NONE. */
enum anvil_cache_where anvil_cache_probe(const struct anvil_cache *c,
					 const struct anvil_cache_key *key);
/* Keep g (the cache takes it over) under key, evicting the least recently
 * used response not held when full, and write it to disk when the disk
 * level is on (a failure there is a warning, not an error).  Returns g,
 * held for the caller; NULL (g freed) when every slot is held. */
const struct anvil_green *anvil_cache_add(struct anvil_cache *c, const struct anvil_cache_key *key,
					  struct anvil_green *g);
/* Give back one hold on a response returned above (NULL is a no-op). */
void anvil_cache_release(struct anvil_cache *c, const void *resp);
/* The holds outstanding (a solver between runs has none). */
int anvil_cache_held(const struct anvil_cache *c);

/* The disk format, for the cache itself and for tests (the fuzzer builds
 * files with it): the header, then n ramp samples, nk K-table and nk
 * S-table nodes, and n spline c_i, as native doubles. */
#include <stdint.h>
struct anvil_cache_header {
	char magic[8];
	uint32_t format, bom;
	char version[16]; /* the anvil version, NUL-padded */
	uint16_t mode, twin; /* twin: 1 for a coarse twin taken from its main's spectrum */
	uint32_t acc;
	int32_t omega_idx;
	int32_t tau_idx;
	uint32_t load;       /* the key's load (format 4) */
	uint32_t filtered;   /* 0 or 1: samples.filtered (format 7) */
	double hh, nu, patch, omega, tau_end, dtau, abserr;
	double t1, tail_v, tail_c[3]; /* the plate's tail (format 8); t1 = 0: none */
	uint64_t n, nk, checksum;
	double lift_patch; /* the key's (format 21) */
};
_Static_assert(sizeof(struct anvil_cache_header) == 184, "cache header has padding");

/* The file for key in dir ("DIR/corr-LEVEL-HASH.bin", "DIR/phys-..." for
 * the physical contact's) into buf; ANVIL_EINVAL
 * when it does not fit. */
int anvil_cache_path(const char *dir, const struct anvil_cache_key *key, char *buf, size_t n);
/* Write g for key to path atomically (a temporary file beside it, flushed
 * and synced, renamed over path).  ANVIL_EIO with the reason in err;
 * ANVIL_CACHE_UNFIT (> 0, nothing written, err untouched) for a response
 * the reader would refuse (anvil_green_samples_plausible). */
#define ANVIL_CACHE_UNFIT 1
int anvil_cache_write(const char *path, const struct anvil_cache_key *key,
		      const struct anvil_green *g, struct anvil_err *err);
/* Read the response stored at path for key.  NULL with err:
 * ANVIL_ENOTFOUND (no file), ANVIL_EPARSE (another format or anvil
 * version, or another key: ignore quietly), ANVIL_EIO (corrupt: short,
 * bad checksum or samples; warn), ANVIL_ENOMEM. */
struct anvil_green *anvil_cache_read(const char *path, const struct anvil_cache_key *key,
				     struct anvil_err *err);

#endif
