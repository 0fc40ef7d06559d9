/* cache.c: the response cache, in memory and on disk (see cache.h). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "config.h"
#include "cache.h"
#include "green.h"
#include "halfspace.h"

#define MAGIC "ANVILRSP"
#define BOM 0x01020304u
/* Samples in a file we are willing to read: a response with the largest
 * bandwidth and window the solver allows has fewer than a million; a K
 * table has 32 nodes an octave of its window. */
#define MAX_SAMPLES 50000000u
#define MAX_NODES 100000u

/* The file header.  Fixed-size fields in an order that leaves no padding
 * (checked below), zero-filled, so that its bytes are well defined and can
 * be checksummed. */

enum kind { EMPTY, HALFSPACE, CORR };

struct slot {
	enum kind kind;
	struct anvil_cache_key key; /* CORR */
	double tol;                 /* HALFSPACE: its tolerance; nu in key.nu */
	double tau_end;             /* CORR */
	struct anvil_halfspace *hs;
	struct anvil_green *g;
	unsigned long used;
	int held;                   /* holds by callers: never evicted while > 0 */
};

struct anvil_cache {
	struct slot slot[ANVIL_CACHE_SLOTS];
	unsigned long clock;
	char *dir;
	int dir_warned; /* one warning per directory for write failures */
	anvil_warn_fn warn;
	void *warn_ctx;
	struct anvil_cache_stats st;
};

/* ---- the grid ---- */

double anvil_cache_grid(int idx)
{
	return exp2((double)idx / ANVIL_CACHE_STEPS);
}

/* Grid indices are clamped to +-GRID_MAX_IDX (2^+-1000, far beyond any
 * window or bandwidth): (int) of an infinite or huge log2 would be
 * undefined behaviour, and NaN or x <= 0 has no grid point at all. */
#define GRID_MAX_IDX (1000 * ANVIL_CACHE_STEPS)

int anvil_cache_grid_up(double x)
{
	if (!(x > anvil_cache_grid(-GRID_MAX_IDX)))
		return -GRID_MAX_IDX;
	if (!(x <= anvil_cache_grid(GRID_MAX_IDX)))
		return GRID_MAX_IDX;
	int k = (int)ceil(ANVIL_CACHE_STEPS * log2(x));
	/* log2 may be off by an ulp either way: settle on the exact answer */
	while (anvil_cache_grid(k - 1) >= x)
		k--;
	while (anvil_cache_grid(k) < x)
		k++;
	return k;
}

/* ---- life ---- */

struct anvil_cache *anvil_cache_alloc(void)
{
	return calloc(1, sizeof(struct anvil_cache));
}

static void slot_clear(struct slot *s)
{
	anvil_halfspace_free(s->hs);
	anvil_green_free(s->g);
	memset(s, 0, sizeof *s);
}

void anvil_cache_free(struct anvil_cache *c)
{
	if (!c)
		return;
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++)
		slot_clear(&c->slot[i]);
	free(c->dir);
	free(c);
}

int anvil_cache_set_dir(struct anvil_cache *c, const char *dir, struct anvil_err *err)
{
	char *copy = NULL;
	if (dir && *dir) {
		if (strlen(dir) > 3000)
			return anvil_err_set(err, ANVIL_EINVAL, "cache: directory name too long");
		if (!(copy = strdup(dir)))
			return anvil_err_set(err, ANVIL_ENOMEM, "cache: out of memory");
	}
	free(c->dir);
	c->dir = copy;
	c->dir_warned = 0;
	return ANVIL_OK;
}

const char *anvil_cache_dir(const struct anvil_cache *c) { return c->dir; }

void anvil_cache_set_warn(struct anvil_cache *c, anvil_warn_fn fn, void *ctx)
{
	c->warn = fn;
	c->warn_ctx = ctx;
}

void anvil_cache_stats(const struct anvil_cache *c, struct anvil_cache_stats *st)
{
	*st = c->st;
}

char *anvil_cache_default_dir(char *buf, size_t n)
{
	const char *off = getenv("ANVIL_NO_CACHE"), *xdg = getenv("XDG_CACHE_HOME");
	const char *home = getenv("HOME");
	buf[0] = '\0';
	if (off && *off && strcmp(off, "0") != 0)
		return buf;
	if (xdg && xdg[0] == '/')
		snprintf(buf, n, "%s/anvil", xdg);
	else if (home && home[0] == '/')
		snprintf(buf, n, "%s/.cache/anvil", home);
	return buf;
}

static void warn(struct anvil_cache *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void warn(struct anvil_cache *c, const char *fmt, ...)
{
	char msg[ANVIL_ERR_MSG + 64];
	va_list ap;
	if (!c->warn)
		return;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	c->warn(c->warn_ctx, msg);
}

/* ---- memory ---- */

/* A free slot: the least recently used one not held when all are taken;
 * NULL when every slot is held. */
static struct slot *slot_take(struct anvil_cache *c)
{
	struct slot *old = NULL;
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++) {
		if (c->slot[i].kind == EMPTY)
			return &c->slot[i];
		if (!c->slot[i].held && (!old || c->slot[i].used < old->used))
			old = &c->slot[i];
	}
	if (old)
		slot_clear(old);
	return old;
}

static const void *hold(struct anvil_cache *c, struct slot *s)
{
	s->used = ++c->clock;
	s->held++;
	return s->hs ? (const void *)s->hs : (const void *)s->g;
}

void anvil_cache_release(struct anvil_cache *c, const void *resp)
{
	for (int i = 0; resp && i < ANVIL_CACHE_SLOTS; i++) {
		struct slot *s = &c->slot[i];
		if (s->kind != EMPTY && s->held > 0 &&
		    (resp == (const void *)s->hs || resp == (const void *)s->g)) {
			s->held--;
			return;
		}
	}
}

int anvil_cache_held(const struct anvil_cache *c)
{
	int n = 0;
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++)
		n += c->slot[i].held;
	return n;
}

const struct anvil_halfspace *anvil_cache_halfspace(struct anvil_cache *c, double nu, double tol,
						    struct anvil_err *err)
{
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++) {
		struct slot *s = &c->slot[i];
		if (s->kind == HALFSPACE && s->key.nu == nu && s->tol == tol)
			return hold(c, s);
	}
	struct anvil_halfspace *hs = anvil_halfspace_alloc(nu, tol, err);
	if (!hs)
		return NULL;
	struct slot *s = slot_take(c);
	if (!s) {
		anvil_halfspace_free(hs);
		anvil_err_set(err, ANVIL_ENOMEM, "cache: all %d slots are held", ANVIL_CACHE_SLOTS);
		return NULL;
	}
	*s = (struct slot){ .kind = HALFSPACE, .key.nu = nu, .tol = tol, .hs = hs };
	return hold(c, s);
}

static int same_key(const struct anvil_cache_key *a, const struct anvil_cache_key *b)
{
	return a->hh == b->hh && a->nu == b->nu && a->acc == b->acc &&
	       a->omega_idx == b->omega_idx && a->tau_idx == b->tau_idx && a->twin == b->twin &&
	       a->load == b->load && a->patch == b->patch && a->lift_patch == b->lift_patch;
}

/* The memory slot of key: the same window and bandwidth exactly, so that
 * a result never depends on what the cache happened to hold. */
static struct slot *mem_find(const struct anvil_cache *c, const struct anvil_cache_key *key)
{
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++) {
		struct slot *s = (struct slot *)&c->slot[i];
		if (s->kind == CORR && same_key(&s->key, key))
			return s;
	}
	return NULL;
}

static const struct anvil_green *keep(struct anvil_cache *c, const struct anvil_cache_key *key,
				      struct anvil_green *g)
{
	struct slot *s = slot_take(c);
	if (!s) {
		anvil_green_free(g);
		return NULL;
	}
	*s = (struct slot){ .kind = CORR, .key = *key, .tau_end = anvil_green_tau_end(g), .g = g };
	return hold(c, s);
}

/* ---- disk: names, checksum, directory ---- */

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
	const unsigned char *p = data;
	for (size_t i = 0; i < n; i++) {
		h ^= p[i];
		h *= 1099511628211u;
	}
	return h;
}

#define FNV_SEED 14695981039346656037u

int anvil_cache_path(const char *dir, const struct anvil_cache_key *key, char *buf, size_t n)
{
	/* The name hashes the key's bits, not the versions: a newer anvil
	 * replaces an older one's file instead of piling up beside it. */
	uint64_t h = fnv1a(FNV_SEED, &key->hh, sizeof key->hh);
	h = fnv1a(h, &key->nu, sizeof key->nu);
	h = fnv1a(h, &key->omega_idx, sizeof key->omega_idx);
	h = fnv1a(h, &key->tau_idx, sizeof key->tau_idx);
	if (key->twin) /* a main response's name as before */
		h = fnv1a(h, &key->twin, sizeof key->twin);
	if (key->load) { /* the physical contact's: its own prefix, the patch hashed */
		h = fnv1a(h, &key->load, sizeof key->load);
		h = fnv1a(h, &key->patch, sizeof key->patch);
		h = fnv1a(h, &key->lift_patch, sizeof key->lift_patch);
	}
	int len = snprintf(buf, n, "%s/%s-%s-%016llx.bin", dir, key->load ? "phys" : "corr",
			   anvil_accuracy_name(key->acc), (unsigned long long)h);
	return len > 0 && (size_t)len < n ? ANVIL_OK : ANVIL_EINVAL;
}

/* mkdir -p, the new directories private to the user. */
static int make_dir(const char *dir)
{
	char path[3100];
	snprintf(path, sizeof path, "%s", dir);
	for (char *p = path + 1;; p++) {
		if (*p != '/' && *p)
			continue;
		char was = *p;
		*p = '\0';
		if (mkdir(path, 0700) && errno != EEXIST)
			return -1;
		if (!(*p = was))
			break;
	}
	return 0;
}

static void header_fill(struct anvil_cache_header *hd, const struct anvil_cache_key *key,
			const struct anvil_green_samples *s)
{
	memset(hd, 0, sizeof *hd);
	memcpy(hd->magic, MAGIC, 8);
	hd->format = ANVIL_CACHE_FORMAT;
	hd->bom = BOM;
	snprintf(hd->version, sizeof hd->version, "%s", PACKAGE_VERSION);
	hd->mode = (uint16_t)s->mode;
	hd->twin = (uint16_t)(key->twin != 0);
	hd->acc = (uint32_t)key->acc;
	hd->omega_idx = key->omega_idx;
	hd->tau_idx = key->tau_idx;
	hd->load = (uint32_t)key->load;
	hd->patch = key->patch;
	hd->lift_patch = key->lift_patch;
	hd->hh = key->hh;
	hd->nu = key->nu;
	hd->omega = anvil_cache_grid(key->omega_idx);
	hd->tau_end = s->tau_end;
	hd->dtau = s->dtau;
	hd->abserr = s->abserr;
	hd->n = s->n;
	hd->filtered = (uint32_t)(s->filtered != 0);
	hd->t1 = s->t1;
	hd->tail_v = s->tail_v;
	memcpy(hd->tail_c, s->tail_c, sizeof hd->tail_c);
	hd->nk = s->nk;
}

/* FNV-1a's step on 64-bit words, n of them: a word changed anywhere
 * changes the sum (each step is a bijection of h).  Byte by byte, the
 * sum's chain of multiplications took 0.1 ms of a warm run's 4 (four
 * responses of 16 kB); eight times fewer steps here. */
static uint64_t fnv1a_words(uint64_t h, const void *data, size_t n)
{
	const unsigned char *p = data;
	for (size_t i = 0; i < n; i++) {
		uint64_t w;
		memcpy(&w, p + 8 * i, sizeof w);
		h ^= w;
		h *= 1099511628211u;
	}
	return h;
}

_Static_assert(sizeof(struct anvil_cache_header) % 8 == 0, "the checksum sums whole words");

/* Over the header, then the samples, the K table, the S table and the
 * spline's c_i (data: 2 n + 2 nk doubles), word by word (format 26). */
static uint64_t checksum(const struct anvil_cache_header *hd, const double *ramp, const double *k,
			 const double *shear, const double *curv)
{
	struct anvil_cache_header h = *hd;
	h.checksum = 0;
	uint64_t c = fnv1a_words(fnv1a_words(FNV_SEED, &h, sizeof h / 8), ramp, (size_t)hd->n);
	if (hd->nk)
		c = fnv1a_words(fnv1a_words(c, k, (size_t)hd->nk), shear, (size_t)hd->nk);
	return fnv1a_words(c, curv, (size_t)hd->n);
}

/* ---- disk: write ---- */

static int write_all(FILE *f, const struct anvil_cache_header *hd, const double *ramp,
		     const double *k, const double *shear, const double *curv)
{
	if (fwrite(hd, sizeof *hd, 1, f) != 1 || fwrite(ramp, sizeof *ramp, hd->n, f) != hd->n ||
	    (hd->nk && (fwrite(k, sizeof *k, hd->nk, f) != hd->nk ||
			fwrite(shear, sizeof *shear, hd->nk, f) != hd->nk)) ||
	    fwrite(curv, sizeof *curv, hd->n, f) != hd->n || fflush(f) != 0)
		return -1;
	/* on disk before the rename makes it visible: no empty file after a crash */
	return fsync(fileno(f));
}

int anvil_cache_write(const char *path, const struct anvil_cache_key *key,
		      const struct anvil_green *g, struct anvil_err *err)
{
	struct anvil_green_samples s;
	struct anvil_cache_header hd;
	char tmp[3200];
	anvil_green_export(g, &s);
	header_fill(&hd, key, &s);
	if (!s.curv)
		return anvil_err_set(err, ANVIL_EINVAL, "%s: a response without its spline", path);
	/* A response the reader would refuse (a short window's filter
	 * precursor above 1e-3 of its peak: h = 5 r0, 0.1 g at 100 m/s) is
	 * not written: every warm run would call its own file corrupt. */
	if (!anvil_green_samples_plausible(&s))
		return ANVIL_CACHE_UNFIT;
	hd.checksum = checksum(&hd, s.ramp, s.k, s.shear, s.curv);
	if (snprintf(tmp, sizeof tmp, "%s.XXXXXX", path) >= (int)sizeof tmp)
		return anvil_err_set(err, ANVIL_EIO, "%s: name too long", path);
	int fd = mkstemp(tmp);
	if (fd < 0)
		return anvil_err_set(err, ANVIL_EIO, "%s: cannot create: %s", tmp, strerror(errno));
	FILE *f = fdopen(fd, "wb");
	int bad = !f || write_all(f, &hd, s.ramp, s.k, s.shear, s.curv) != 0;
	int saved = errno;
	if (f ? fclose(f) != 0 : close(fd) != 0)
		bad = 1;
	if (!bad && rename(tmp, path) != 0) {
		saved = errno;
		bad = 1;
	}
	if (bad) {
		unlink(tmp);
		return anvil_err_set(err, ANVIL_EIO, "%s: cannot write: %s", path, strerror(saved));
	}
	return ANVIL_OK;
}

/* ---- disk: read ---- */

static int header_read(FILE *f, const char *path, struct anvil_cache_header *hd, struct anvil_err *err)
{
	if (fread(hd, sizeof *hd, 1, f) != 1 || memcmp(hd->magic, MAGIC, 8) != 0)
		return anvil_err_set(err, ANVIL_EIO, "%s: not a response file (short or bad magic)",
				     path);
	if (hd->format != ANVIL_CACHE_FORMAT || hd->bom != BOM)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: format %u from another anvil or machine",
				     path, (unsigned)hd->format);
	if (hd->n < 4 || hd->n > MAX_SAMPLES || hd->nk > MAX_NODES)
		return anvil_err_set(err, ANVIL_EIO, "%s: corrupt (%llu samples, %llu nodes)", path,
				     (unsigned long long)hd->n, (unsigned long long)hd->nk);
	return ANVIL_OK;
}

/* The header's version and key against ours; EPARSE (quiet) if they differ. */
static int header_match(const struct anvil_cache_header *hd, const char *path,
			const struct anvil_cache_key *key, struct anvil_err *err)
{
	char version[sizeof hd->version + 1];
	memcpy(version, hd->version, sizeof hd->version);
	version[sizeof hd->version] = '\0';
	if (strcmp(version, PACKAGE_VERSION) != 0)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: made by anvil %s, this is %s", path,
				     version, PACKAGE_VERSION);
	if (hd->hh != key->hh || hd->nu != key->nu || hd->acc != (uint32_t)key->acc ||
	    hd->omega_idx != key->omega_idx || hd->tau_idx != key->tau_idx || hd->mode != ANVIL_GREEN_LAYER_CORRECTION ||
	    hd->twin != (uint16_t)(key->twin != 0) || hd->load != (uint32_t)key->load ||
	    hd->patch != key->patch || hd->lift_patch != key->lift_patch || hd->filtered > 1)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: holds another response", path);
	return ANVIL_OK;
}

static struct anvil_green *samples_read(FILE *f, const char *path, const struct anvil_cache_header *hd,
					struct anvil_err *err)
{
	struct stat sb;
	double *ramp = NULL;
	struct anvil_green *g = NULL;
	size_t nd = (size_t)(2 * hd->n + 2 * hd->nk); /* both bounded by header_read */
	if (fstat(fileno(f), &sb) != 0 || (uint64_t)sb.st_size != sizeof *hd + nd * sizeof(double)) {
		anvil_err_set(err, ANVIL_EIO, "%s: corrupt (size)", path);
		return NULL;
	}
	if (!(ramp = malloc(nd * sizeof *ramp))) {
		anvil_err_set(err, ANVIL_ENOMEM, "cache: out of memory");
		return NULL;
	}
	const double *k = ramp + hd->n, *shear = k + hd->nk, *curv = shear + hd->nk;
	if (fread(ramp, sizeof *ramp, nd, f) != nd)
		anvil_err_set(err, ANVIL_EIO, "%s: corrupt (short)", path);
	else if (checksum(hd, ramp, k, shear, curv) != hd->checksum)
		anvil_err_set(err, ANVIL_EIO, "%s: corrupt (bad checksum)", path);
	else {
		struct anvil_green_samples s = { .mode = ANVIL_GREEN_LAYER_CORRECTION,
						 .filtered = hd->filtered != 0, .hh = hd->hh,
						 .nu = hd->nu,
						 .patch = hd->load ? hd->patch : 1.0,
						 .tau_end = hd->tau_end,
						 .dtau = hd->dtau, .abserr = hd->abserr,
						 .n = (size_t)hd->n, .ramp = ramp,
						 .t1 = hd->t1, .tail_v = hd->tail_v,
						 .nk = (size_t)hd->nk, .k = hd->nk ? k : NULL,
						 .shear = hd->nk ? shear : NULL, .curv = curv };
		memcpy(s.tail_c, hd->tail_c, sizeof s.tail_c);
		struct anvil_err in;
		if (!(g = anvil_green_import(&s, &in)))
			anvil_err_set(err, in.status == ANVIL_ENOMEM ? ANVIL_ENOMEM : ANVIL_EIO,
				      "%s: corrupt (%s)", path, in.msg);
	}
	free(ramp);
	return g;
}

struct anvil_green *anvil_cache_read(const char *path, const struct anvil_cache_key *key,
				     struct anvil_err *err)
{
	struct anvil_cache_header hd;
	FILE *f = fopen(path, "rb");
	if (!f) {
		anvil_err_set(err, errno == ENOENT ? ANVIL_ENOTFOUND : ANVIL_EIO, "%s: %s", path,
			      strerror(errno));
		return NULL;
	}
	struct anvil_green *g = NULL;
	if (!header_read(f, path, &hd, err) && !header_match(&hd, path, key, err))
		g = samples_read(f, path, &hd, err);
	fclose(f);
	return g;
}

/* Whether the file for key is there with a header that matches: ANVIL_OK,
 * or the status of anvil_cache_read for a file that is missing, stale or
 * foreign (EPARSE) or whose header is damaged (EIO). */
static int disk_check(const char *path, const struct anvil_cache_key *key,
		      struct anvil_err *err)
{
	struct anvil_cache_header hd;
	FILE *f = fopen(path, "rb");
	if (!f)
		return anvil_err_set(err, ANVIL_ENOTFOUND, "%s: no file", path);
	int st = header_read(f, path, &hd, err);
	if (!st)
		st = header_match(&hd, path, key, err);
	fclose(f);
	return st;
}

/* Count (and for a damaged file, say) why a file was not used. */
static void disk_reject(struct anvil_cache *c, const struct anvil_err *e)
{
	if (e->status == ANVIL_EIO || e->status == ANVIL_ENOMEM) {
		c->st.disk_corrupt++;
		warn(c, "cache: %s; ignored, it will be replaced", e->msg);
	} else if (e->status == ANVIL_EPARSE) {
		c->st.disk_stale++;
	}
}

/* ---- lookups ---- */

static struct anvil_green *disk_find(struct anvil_cache *c, const struct anvil_cache_key *key)
{
	char path[3200];
	struct anvil_err e;
	if (anvil_cache_path(c->dir, key, path, sizeof path))
		return NULL;
	struct anvil_green *g = anvil_cache_read(path, key, &e);
	if (!g && e.status != ANVIL_ENOTFOUND)
		disk_reject(c, &e);
	return g;
}

const struct anvil_green *anvil_cache_find(struct anvil_cache *c, const struct anvil_cache_key *key,
					   enum anvil_cache_where *where)
{
	struct slot *s = mem_find(c, key);
	if (where)
		*where = s ? ANVIL_CACHE_MEMORY : ANVIL_CACHE_NONE;
	if (s) {
		c->st.mem_hits++;
		return hold(c, s);
	}
	struct anvil_green *g = c->dir ? disk_find(c, key) : NULL;
	if (g) {
		c->st.disk_hits++;
		if (where)
			*where = ANVIL_CACHE_DISK;
		return keep(c, key, g);
	}
	c->st.misses++;
	return NULL;
}

enum anvil_cache_where anvil_cache_probe(const struct anvil_cache *c,
					 const struct anvil_cache_key *key)
{
	char path[3200];
	if (mem_find(c, key))
		return ANVIL_CACHE_MEMORY;
	if (c->dir && !anvil_cache_path(c->dir, key, path, sizeof path) &&
	    !disk_check(path, key, NULL))
		return ANVIL_CACHE_DISK;
	return ANVIL_CACHE_NONE;
}

static void disk_store(struct anvil_cache *c, const struct anvil_cache_key *key,
		       const struct anvil_green *g)
{
	char path[3200];
	struct anvil_err e;
	int st = make_dir(c->dir) ? anvil_err_set(&e, ANVIL_EIO, "%s: cannot create: %s", c->dir,
						  strerror(errno))
				  : anvil_cache_path(c->dir, key, path, sizeof path);
	if (!st)
		st = anvil_cache_write(path, key, g, &e);
	else if (st == ANVIL_EINVAL)
		anvil_err_set(&e, st, "%s: name too long", c->dir);
	if (!st) {
		c->st.disk_writes++;
		return;
	}
	if (st == ANVIL_CACHE_UNFIT)
		return; /* kept in memory only: cold on disk, the same bits */
	c->st.disk_failures++;
	/* A read-only or full disk stays so for a while: say it once. */
	if (!c->dir_warned++)
		warn(c, "cache: %s; keeping responses in memory only", e.msg);
}

const struct anvil_green *anvil_cache_add(struct anvil_cache *c, const struct anvil_cache_key *key,
					  struct anvil_green *g)
{
	if (!g)
		return NULL;
	if (c->dir)
		disk_store(c, key, g);
	return keep(c, key, g);
}
