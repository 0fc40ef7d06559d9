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
 * bandwidth and window the solver allows has fewer than a million. */
#define MAX_SAMPLES 50000000u

/* The file header.  Fixed-size fields in an order that leaves no padding
 * (checked below), zero-filled, so that its bytes are well defined and can
 * be checksummed. */
struct header {
	char magic[8];
	uint32_t format, bom;
	char version[16]; /* PACKAGE_VERSION, NUL-padded */
	uint32_t mode, acc;
	int32_t omega_idx;
	uint32_t reserved;
	double hh, nu, omega, tau_end, dtau, abserr;
	uint64_t n, checksum;
};
_Static_assert(sizeof(struct header) == 112, "cache header has padding");

enum kind { EMPTY, HALFSPACE, CORR };

struct slot {
	enum kind kind;
	struct anvil_cache_key key; /* CORR */
	double tol;                 /* HALFSPACE: its tolerance; nu in key.nu */
	double tau_end;             /* CORR */
	struct anvil_halfspace *hs;
	struct anvil_green *g;
	unsigned long used;
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

/* A free slot: the least recently used one when all are taken. */
static struct slot *slot_take(struct anvil_cache *c)
{
	struct slot *old = &c->slot[0];
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++) {
		if (c->slot[i].kind == EMPTY)
			return &c->slot[i];
		if (c->slot[i].used < old->used)
			old = &c->slot[i];
	}
	slot_clear(old);
	return old;
}

const struct anvil_halfspace *anvil_cache_halfspace(struct anvil_cache *c, double nu, double tol,
						    struct anvil_err *err)
{
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++) {
		struct slot *s = &c->slot[i];
		if (s->kind == HALFSPACE && s->key.nu == nu && s->tol <= tol) {
			s->used = ++c->clock;
			return s->hs;
		}
	}
	struct anvil_halfspace *hs = anvil_halfspace_alloc(nu, tol, err);
	if (!hs)
		return NULL;
	struct slot *s = slot_take(c);
	*s = (struct slot){ .kind = HALFSPACE, .key.nu = nu, .tol = tol, .hs = hs,
			    .used = ++c->clock };
	return hs;
}

static int same_layer(const struct anvil_cache_key *a, const struct anvil_cache_key *b)
{
	return a->hh == b->hh && a->nu == b->nu && a->acc == b->acc;
}

/* The memory slot that serves key: the smallest bandwidth that will do. */
static struct slot *mem_find(const struct anvil_cache *c, const struct anvil_cache_key *key,
			     double tau_end, int exact)
{
	struct slot *best = NULL;
	for (int i = 0; i < ANVIL_CACHE_SLOTS; i++) {
		struct slot *s = (struct slot *)&c->slot[i];
		if (s->kind != CORR || !same_layer(&s->key, key) || s->tau_end < tau_end)
			continue;
		if (exact ? s->key.omega_idx != key->omega_idx : s->key.omega_idx < key->omega_idx)
			continue;
		if (!best || s->key.omega_idx < best->key.omega_idx)
			best = s;
	}
	return best;
}

static const struct anvil_green *keep(struct anvil_cache *c, const struct anvil_cache_key *key,
				      struct anvil_green *g)
{
	struct slot *s = slot_take(c);
	*s = (struct slot){ .kind = CORR, .key = *key, .tau_end = anvil_green_tau_end(g), .g = g,
			    .used = ++c->clock };
	return g;
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
	int len = snprintf(buf, n, "%s/corr-%s-%016llx.bin", dir, anvil_accuracy_name(key->acc),
			   (unsigned long long)h);
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

static void header_fill(struct header *hd, const struct anvil_cache_key *key,
			const struct anvil_green_samples *s)
{
	memset(hd, 0, sizeof *hd);
	memcpy(hd->magic, MAGIC, 8);
	hd->format = ANVIL_CACHE_FORMAT;
	hd->bom = BOM;
	snprintf(hd->version, sizeof hd->version, "%s", PACKAGE_VERSION);
	hd->mode = (uint32_t)s->mode;
	hd->acc = (uint32_t)key->acc;
	hd->omega_idx = key->omega_idx;
	hd->hh = key->hh;
	hd->nu = key->nu;
	hd->omega = anvil_cache_grid(key->omega_idx);
	hd->tau_end = s->tau_end;
	hd->dtau = s->dtau;
	hd->abserr = s->abserr;
	hd->n = s->n;
}

static uint64_t checksum(const struct header *hd, const double *ramp)
{
	struct header h = *hd;
	h.checksum = 0;
	return fnv1a(fnv1a(FNV_SEED, &h, sizeof h), ramp, (size_t)hd->n * sizeof *ramp);
}

/* ---- disk: write ---- */

static int write_all(FILE *f, const struct header *hd, const double *ramp)
{
	if (fwrite(hd, sizeof *hd, 1, f) != 1 || fwrite(ramp, sizeof *ramp, hd->n, f) != hd->n ||
	    fflush(f) != 0)
		return -1;
	/* on disk before the rename makes it visible: no empty file after a crash */
	return fsync(fileno(f));
}

int anvil_cache_write(const char *path, const struct anvil_cache_key *key,
		      const struct anvil_green *g, struct anvil_err *err)
{
	struct anvil_green_samples s;
	struct header hd;
	char tmp[3200];
	anvil_green_export(g, &s);
	header_fill(&hd, key, &s);
	hd.checksum = checksum(&hd, s.ramp);
	if (snprintf(tmp, sizeof tmp, "%s.XXXXXX", path) >= (int)sizeof tmp)
		return anvil_err_set(err, ANVIL_EIO, "%s: name too long", path);
	int fd = mkstemp(tmp);
	if (fd < 0)
		return anvil_err_set(err, ANVIL_EIO, "%s: cannot create: %s", tmp, strerror(errno));
	FILE *f = fdopen(fd, "wb");
	int bad = !f || write_all(f, &hd, s.ramp) != 0;
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

static int header_read(FILE *f, const char *path, struct header *hd, struct anvil_err *err)
{
	if (fread(hd, sizeof *hd, 1, f) != 1 || memcmp(hd->magic, MAGIC, 8) != 0)
		return anvil_err_set(err, ANVIL_EIO, "%s: not a response file (short or bad magic)",
				     path);
	if (hd->format != ANVIL_CACHE_FORMAT || hd->bom != BOM)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: format %u from another anvil or machine",
				     path, (unsigned)hd->format);
	if (hd->n < 4 || hd->n > MAX_SAMPLES)
		return anvil_err_set(err, ANVIL_EIO, "%s: corrupt (%llu samples)", path,
				     (unsigned long long)hd->n);
	return ANVIL_OK;
}

/* The header's version and key against ours; EPARSE (quiet) if they differ. */
static int header_match(const struct header *hd, const char *path,
			const struct anvil_cache_key *key, struct anvil_err *err)
{
	char version[sizeof hd->version + 1];
	memcpy(version, hd->version, sizeof hd->version);
	version[sizeof hd->version] = '\0';
	if (strcmp(version, PACKAGE_VERSION) != 0)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: made by anvil %s, this is %s", path,
				     version, PACKAGE_VERSION);
	if (hd->hh != key->hh || hd->nu != key->nu || hd->acc != (uint32_t)key->acc ||
	    hd->omega_idx != key->omega_idx || hd->mode != ANVIL_GREEN_LAYER_CORRECTION)
		return anvil_err_set(err, ANVIL_EPARSE, "%s: holds another response", path);
	return ANVIL_OK;
}

static struct anvil_green *samples_read(FILE *f, const char *path, const struct header *hd,
					struct anvil_err *err)
{
	struct stat sb;
	double *ramp = NULL;
	struct anvil_green *g = NULL;
	if (fstat(fileno(f), &sb) != 0 ||
	    (uint64_t)sb.st_size != sizeof *hd + hd->n * sizeof(double)) {
		anvil_err_set(err, ANVIL_EIO, "%s: corrupt (size)", path);
		return NULL;
	}
	if (!(ramp = malloc((size_t)hd->n * sizeof *ramp))) {
		anvil_err_set(err, ANVIL_ENOMEM, "cache: out of memory");
		return NULL;
	}
	if (fread(ramp, sizeof *ramp, (size_t)hd->n, f) != hd->n)
		anvil_err_set(err, ANVIL_EIO, "%s: corrupt (short)", path);
	else if (checksum(hd, ramp) != hd->checksum)
		anvil_err_set(err, ANVIL_EIO, "%s: corrupt (bad checksum)", path);
	else {
		struct anvil_green_samples s = { .mode = ANVIL_GREEN_LAYER_CORRECTION, .hh = hd->hh,
						 .nu = hd->nu, .tau_end = hd->tau_end,
						 .dtau = hd->dtau, .abserr = hd->abserr,
						 .n = (size_t)hd->n, .ramp = ramp };
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
	struct header hd;
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

/* The window of the file for key into *tau_end: ANVIL_OK, or the status of
 * anvil_cache_read for a file that is missing, stale or foreign (EPARSE) or
 * whose header is damaged (EIO). */
static int disk_window(const char *path, const struct anvil_cache_key *key, double *tau_end,
		       struct anvil_err *err)
{
	struct header hd;
	FILE *f = fopen(path, "rb");
	*tau_end = 0;
	if (!f)
		return anvil_err_set(err, ANVIL_ENOTFOUND, "%s: no file", path);
	int st = header_read(f, path, &hd, err);
	if (!st)
		st = header_match(&hd, path, key, err);
	if (!st)
		*tau_end = hd.tau_end;
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

/* The disk level for key at omega index idx covering tau_end. */
static struct anvil_green *disk_find(struct anvil_cache *c, const struct anvil_cache_key *key,
				     double tau_end)
{
	char path[3200];
	struct anvil_err e;
	double window;
	if (anvil_cache_path(c->dir, key, path, sizeof path))
		return NULL;
	int st = disk_window(path, key, &window, &e);
	if (st) {
		disk_reject(c, &e);
		return NULL;
	}
	if (window < tau_end) /* a window too short is no fault */
		return NULL;
	struct anvil_green *g = anvil_cache_read(path, key, &e);
	if (!g)
		disk_reject(c, &e);
	return g;
}

const struct anvil_green *anvil_cache_find(struct anvil_cache *c, const struct anvil_cache_key *key,
					   double tau_end, int exact, enum anvil_cache_where *where)
{
	struct slot *s = mem_find(c, key, tau_end, exact);
	if (where)
		*where = s ? ANVIL_CACHE_MEMORY : ANVIL_CACHE_NONE;
	if (s) {
		c->st.mem_hits++;
		s->used = ++c->clock;
		return s->g;
	}
	/* on disk: this bandwidth, or up to an octave more when that will do */
	for (int up = 0; c->dir && up <= (exact ? 0 : ANVIL_CACHE_STEPS); up++) {
		struct anvil_cache_key k = *key;
		k.omega_idx += up;
		struct anvil_green *g = disk_find(c, &k, tau_end);
		if (g) {
			c->st.disk_hits++;
			if (where)
				*where = ANVIL_CACHE_DISK;
			return keep(c, &k, g);
		}
	}
	c->st.misses++;
	return NULL;
}

enum anvil_cache_where anvil_cache_probe(const struct anvil_cache *c,
					 const struct anvil_cache_key *key, double tau_end,
					 int exact)
{
	char path[3200];
	if (mem_find(c, key, tau_end, exact))
		return ANVIL_CACHE_MEMORY;
	for (int up = 0; c->dir && up <= (exact ? 0 : ANVIL_CACHE_STEPS); up++) {
		struct anvil_cache_key k = *key;
		double window;
		k.omega_idx += up;
		if (!anvil_cache_path(c->dir, &k, path, sizeof path) &&
		    !disk_window(path, &k, &window, NULL) && window >= tau_end)
			return ANVIL_CACHE_DISK;
	}
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
