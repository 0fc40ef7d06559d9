#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <unistd.h>
#include <sys/stat.h>

#include <gsl/gsl_errno.h>

#include "common.h"
#include "units.h"

void cli_init(void)
{
	/* GSL's default handler aborts: one bad quadrature would kill a run. */
	gsl_set_error_handler_off();
	setlocale(LC_ALL, "");
	setlocale(LC_NUMERIC, "C");
}

void cli_error(const char *fmt, ...)
{
	va_list ap;
	fputs("anvil: ", stderr);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
}

const char *cli_model_reason(enum anvil_model m, const char *msg)
{
	const char *name = anvil_model_name(m);
	size_t n = strlen(name);
	return strncmp(msg, name, n) == 0 && msg[n] == ':' && msg[n + 1] == ' ' ? msg + n + 2 : msg;
}

void cli_write_failed(const char *path)
{
	int e = errno, out = !path || !strcmp(path, "-");
	if (!(out && e == EPIPE))
		cli_error("%s: write failed: %s", out ? "standard output" : path, strerror(e));
}

int cli_exit_code(int status)
{
	if (status == ANVIL_OK)
		return EXIT_OK;
	if (status == ANVIL_EPARSE || status == ANVIL_EINVAL)
		return EXIT_USAGE;
	return EXIT_FAIL;
}

int cli_strict;

/* The plausibility warnings of sc, one line each; ANVIL_EINVAL if there
 * are any and --strict is on. */
static int scene_warnings(const struct anvil_scene *sc, const char *path)
{
	struct anvil_scene_warning w[ANVIL_SCENE_WARNINGS_MAX];
	int n = anvil_scene_warnings(sc, w, ANVIL_SCENE_WARNINGS_MAX);
	const char *origin = path ? (strcmp(path, "-") == 0 ? "<stdin>" : path) : "default scene";
	for (int i = 0; i < n && i < ANVIL_SCENE_WARNINGS_MAX; i++) {
		char at[32] = "";
		if (w[i].line > 0)
			snprintf(at, sizeof at, ":%d", w[i].line);
		fprintf(stderr, "anvil: %s: %s%s: %s: %s\n", cli_strict ? "error" : "warning",
			w[i].line < 0 ? "command line" : origin, at, w[i].key, w[i].msg);
	}
	if (n > 0 && cli_strict) {
		cli_error("%d implausible value%s: refused (--strict)", n, n == 1 ? "" : "s");
		return ANVIL_EINVAL;
	}
	return ANVIL_OK;
}

/* ---- files a command reads or writes, so that -o never replaces them ----
 * By canonical name (the directory's real path and the base name, links
 * resolved): "-o my.scene" beside "my.scene", or "-o r.tsv --history
 * ./r.tsv", replace the scene read or lose one output silently.  The CLI's
 * cli_out_open refuses them; cli_out_open_err (the TUI saving its scene to
 * the file it read) does not look. */
#define FILES_MAX 8
static struct {
	char *name;
	const char *what;          /* "the scene file read", "another output..." */
	const struct cli_out *out; /* the output, NULL for an input */
} files[FILES_MAX];

/* path's canonical name (malloc'd), or NULL when its directory is missing. */
static char *canon_name(const char *path)
{
	const char *slash = strrchr(path, '/');
	const char *base = slash ? slash + 1 : path;
	char *dir = slash ? strndup(path, (size_t)(slash - path) + (slash == path)) : strdup(".");
	char *real = dir ? realpath(dir, NULL) : NULL, *name = NULL;
	free(dir);
	if (real && (name = malloc(strlen(real) + strlen(base) + 2)))
		sprintf(name, "%s/%s", real, base);
	free(real);
	return name;
}

static void files_add(const char *path, const char *what, const struct cli_out *out)
{
	for (int i = 0; i < FILES_MAX; i++)
		if (!files[i].name) {
			if ((files[i].name = canon_name(path))) {
				files[i].what = what;
				files[i].out = out;
			}
			return;
		}
}

static void files_forget(const struct cli_out *out)
{
	for (int i = 0; i < FILES_MAX; i++)
		if (files[i].name && files[i].out == out) {
			free(files[i].name);
			files[i].name = NULL;
		}
}

/* What dest (an output, links resolved) already is, or NULL. */
static const char *files_clash(const char *dest)
{
	char *name = canon_name(dest);
	const char *what = NULL;
	for (int i = 0; name && !what && i < FILES_MAX; i++)
		if (files[i].name && strcmp(files[i].name, name) == 0)
			what = files[i].what;
	free(name);
	return what;
}

/* Whether one of sets names layer.thickness (keys are case-insensitive,
 * as anvil_scene_set reads them). */
static int sets_thickness(char *const *sets, int nsets)
{
	static const char key[] = "layer.thickness";
	for (int i = 0; i < nsets; i++) {
		const char *k = sets[i] + strspn(sets[i], " \t");
		size_t n = strcspn(k, "= \t");
		if (n == sizeof key - 1 && strncasecmp(k, key, n) == 0)
			return 1;
	}
	return 0;
}

/* A thickness in r0 moved by a radius given on the command line: the user
 * changed the impactor and may not expect the anvil to change with it. */
static void radius_note(const struct anvil_scene *sc, double r_own, char *const *sets, int nsets)
{
	if (!sc->thickness_per_r0 || !isfinite(sc->thickness) || sc->radius == r_own ||
	    sets_thickness(sets, nsets))
		return;
	char now[32], was[32];
	anvil_units_format(sc->thickness * sc->radius, ANVIL_DIM_LENGTH, now, sizeof now);
	anvil_units_format(sc->thickness * r_own, ANVIL_DIM_LENGTH, was, sizeof was);
	char keep[32];
	size_t k = 0;
	for (const char *c = was; *c && k + 1 < sizeof keep; c++)
		if (*c != ' ')
			keep[k++] = *c; /* "4 mm" -> "4mm": one shell word */
	keep[k] = '\0';
	fprintf(stderr,
		"anvil: note: layer.thickness = %g r0 follows the radius: now %s, was %s "
		"(give it in mm to keep it: -s layer.thickness=%s)\n",
		sc->thickness, now, was, keep);
}

int cli_scene(struct anvil_scene *sc, const char *path, char *const *sets,
	      int nsets)
{
	return cli_scene_q(sc, path, sets, nsets, 0);
}

int cli_scene_q(struct anvil_scene *sc, const char *path, char *const *sets,
		int nsets, int quiet)
{
	if (path && strcmp(path, "-") != 0)
		files_add(path, "the scene file read", NULL);
	struct anvil_err err = {0};
	anvil_scene_default(sc);
	int st = path ? anvil_scene_load(sc, path, &err) : ANVIL_OK;
	double r_own = sc->radius;
	for (int i = 0; !st && i < nsets; i++) {
		char key[128];
		const char *eq = strchr(sets[i], '=');
		size_t klen = eq ? (size_t)(eq - sets[i]) : 0;
		if (!eq || klen == 0 || klen >= sizeof key) {
			st = anvil_err_set(&err, ANVIL_EPARSE,
					   "command line: -s '%s': expected KEY=VALUE, e.g. -s layer.thickness=5r0",
					   sets[i]);
			break;
		}
		memcpy(key, sets[i], klen);
		key[klen] = '\0';
		st = anvil_scene_set(sc, key, eq + 1, "command line", 0, &err);
	}
	if (!st)
		st = anvil_scene_check(sc, &err);
	if (st) {
		cli_error("%s", err.msg[0] ? err.msg : anvil_strerror(st));
		return st;
	}
	if (!quiet)
		radius_note(sc, r_own, sets, nsets);
	return scene_warnings(sc, path);
}

int cli_sets_add(struct cli_sets *s, char *kv)
{
	if (s->n == s->cap) {
		int cap = s->cap ? 2 * s->cap : 8;
		char **v = realloc(s->v, (size_t)cap * sizeof *v);
		if (!v)
			return ANVIL_ENOMEM;
		s->v = v;
		s->cap = cap;
	}
	s->v[s->n++] = kv;
	return ANVIL_OK;
}

void cli_sets_free(struct cli_sets *s)
{
	free(s->v);
	memset(s, 0, sizeof *s);
}

/* ---- the signal handler's registry ----
 * Fixed size, written outside the handler and only read inside it: a
 * slot's path is complete before its flag says so, and the flag is
 * cleared before the path is freed or reused. */

#define CLI_MAX_TMP 8
#define CLI_TMP_LEN 4096
static char tmp_path[CLI_MAX_TMP][CLI_TMP_LEN];
static volatile sig_atomic_t tmp_used[CLI_MAX_TMP];
static volatile pid_t child_pid[CLI_MAX_CHILDREN];

static int tmp_register(const char *path)
{
	if (strlen(path) >= CLI_TMP_LEN)
		return -1;
	for (int i = 0; i < CLI_MAX_TMP; i++)
		if (!tmp_used[i]) {
			strcpy(tmp_path[i], path);
			tmp_used[i] = 1;
			return i + 1;
		}
	return 0; /* still written and removed, only not by the handler */
}

/* slot + 1, as struct cli_out keeps it: 0 is none (a zeroed struct) */
static void tmp_unregister(int slot1)
{
	if (slot1 > 0 && slot1 <= CLI_MAX_TMP)
		tmp_used[slot1 - 1] = 0;
}

int cli_child_register(pid_t pid)
{
	for (int i = 0; i < CLI_MAX_CHILDREN; i++)
		if (child_pid[i] <= 0) {
			child_pid[i] = pid;
			return 0;
		}
	return -1;
}

void cli_child_unregister(pid_t pid)
{
	for (int i = 0; i < CLI_MAX_CHILDREN; i++)
		if (child_pid[i] == pid)
			child_pid[i] = 0;
}

/* Only async-signal-safe calls: unlink, kill, _exit. */
static void on_signal(int sig)
{
	for (int i = 0; i < CLI_MAX_TMP; i++)
		if (tmp_used[i])
			unlink(tmp_path[i]);
	for (int i = 0; i < CLI_MAX_CHILDREN; i++)
		if (child_pid[i] > 0)
			kill(child_pid[i], SIGTERM);
	_exit(128 + sig);
}

void cli_signals_install(void)
{
	/* SIGPIPE too: "anvil run --history - -o r.tsv | head -1" died of it
	 * with r.tsv's temporary file left beside it (qa7); 141 either way */
	static const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
	for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
		struct sigaction sa, old;
		if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
			continue; /* nohup: the user's choice */
		memset(&sa, 0, sizeof sa);
		sigfillset(&sa.sa_mask); /* one handler at a time */
		sa.sa_handler = on_signal;
		sigaction(sigs[i], &sa, NULL);
	}
}

/* ---- output files ---- */

/* path with every symbolic link resolved (the last component may not
 * exist: a dangling link names the file to create).  malloc'd; NULL with
 * errno set (ELOOP after 40 links, as the kernel). */
static char *resolve_links(const char *path)
{
	char *cur = strdup(path);
	for (int hops = 0; cur; hops++) {
		struct stat st;
		if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
			return cur; /* missing or not a link: the end */
		if (hops == 40) {
			free(cur);
			errno = ELOOP;
			return NULL;
		}
		char link[4096];
		ssize_t n = readlink(cur, link, sizeof link - 1);
		if (n < 0) {
			free(cur);
			return NULL;
		}
		link[n] = '\0';
		const char *slash = strrchr(cur, '/');
		size_t dirlen = link[0] == '/' || !slash ? 0 : (size_t)(slash - cur) + 1;
		char *next = malloc(dirlen + (size_t)n + 1);
		if (next) {
			memcpy(next, cur, dirlen);
			memcpy(next + dirlen, link, (size_t)n + 1);
		}
		free(cur);
		cur = next;
	}
	errno = ENOMEM;
	return NULL;
}

/* Straight into a device or FIFO: there is nothing to replace. */
static int out_open_direct(struct cli_out *o)
{
	int fd = open(o->dest, O_WRONLY | O_NOCTTY | O_CLOEXEC);
	if (fd < 0 || !(o->f = fdopen(fd, "w"))) {
		if (fd >= 0)
			close(fd);
		return -1;
	}
	o->direct = 1;
	return 0;
}

/* A temporary file beside dest with mode: that of the file it replaces,
 * else the usual 0666 & ~umask (mkstemp makes 0600). */
static int out_open_tmp(struct cli_out *o, const struct stat *old)
{
	size_t n = strlen(o->dest) + 16;
	mode_t mode;
	if (!(o->tmp = malloc(n)))
		return -1;
	snprintf(o->tmp, n, "%s.tmpXXXXXX", o->dest);
	if (old) {
		mode = old->st_mode & 07777;
	} else {
		mode_t mask = umask(0);
		umask(mask);
		mode = 0666 & ~mask;
	}
	/* no signal between making the file and registering it */
	sigset_t block, old_mask;
	sigemptyset(&block);
	sigaddset(&block, SIGINT);
	sigaddset(&block, SIGTERM);
	sigaddset(&block, SIGHUP);
	sigprocmask(SIG_BLOCK, &block, &old_mask);
	int fd = mkstemp(o->tmp);
	if (fd >= 0)
		o->slot = tmp_register(o->tmp);
	sigprocmask(SIG_SETMASK, &old_mask, NULL);
	if (fd < 0) {
		free(o->tmp);
		o->tmp = NULL;
		return -1;
	}
	if (fchmod(fd, mode) != 0 || !(o->f = fdopen(fd, "w"))) {
		int e = errno;
		close(fd);
		errno = e;
		return -1; /* cli_out_abort removes the file */
	}
	return 0;
}

int cli_out_open_err(struct cli_out *o, const char *path, struct anvil_err *err)
{
	struct stat st;
	memset(o, 0, sizeof *o);
	if (!path || strcmp(path, "-") == 0) {
		o->f = stdout;
		return ANVIL_OK;
	}
	if (!path[0]) /* qa7: "anvil: : write failed: No such file or directory" */
		return anvil_err_set(err, ANVIL_EIO,
				     "an empty output file name: give a file, or - for standard output");
	if (!(o->path = strdup(path)) || !(o->dest = resolve_links(path))) {
		int nomem = errno == ENOMEM || !o->path;
		int st = anvil_err_set(err, nomem ? ANVIL_ENOMEM : ANVIL_EIO, "%s: %s", path,
				       nomem ? "out of memory" : strerror(errno));
		cli_out_abort(o);
		return st;
	}
	int exists = stat(o->dest, &st) == 0, bad;
	if (exists && S_ISDIR(st.st_mode)) {
		cli_out_abort(o);
		return anvil_err_set(err, ANVIL_EIO, "%s: is a directory: give a file name", path);
	}
	if (exists && !S_ISREG(st.st_mode))
		bad = out_open_direct(o);
	else
		bad = out_open_tmp(o, exists ? &st : NULL);
	if (bad) {
		int e = errno;
		cli_out_abort(o);
		return anvil_err_set(err, ANVIL_EIO, "%s: cannot write: %s", path, strerror(e));
	}
	return ANVIL_OK;
}

int cli_out_open(struct cli_out *o, const char *path)
{
	struct anvil_err err = {0};
	const char *what = NULL;
	int st = cli_out_open_err(o, path, &err);
	if (!st && o->dest && !o->direct && (what = files_clash(o->dest))) {
		cli_out_abort(o);
		st = anvil_err_set(&err, ANVIL_EIO, "%s: is %s: refused (give another name)", path,
				   what);
	}
	if (st)
		cli_error("%s", err.msg);
	else if (o->dest && !o->direct) /* devices and FIFOs may be shared */
		files_add(o->dest, "another output of this command", o);
	return st;
}

/* Free the names, forget the slot. */
static void out_clear(struct cli_out *o)
{
	files_forget(o);
	tmp_unregister(o->slot);
	free(o->tmp);
	free(o->dest);
	free(o->path);
	memset(o, 0, sizeof *o);
}

int cli_out_commit_err(struct cli_out *o, struct anvil_err *err)
{
	if (o->f == stdout) {
		o->f = NULL;
		if (fflush(stdout) == 0 && !ferror(stdout))
			return ANVIL_OK;
		int e = errno;
		anvil_err_set(err, ANVIL_EIO, "standard output: write failed: %s", strerror(e));
		errno = e; /* cli_out_commit tells a closed pipe from a full disk */
		return ANVIL_EIO;
	}
	if (!o->f)
		return anvil_err_set(err, ANVIL_EIO, "output not open");
	int bad = ferror(o->f);
	bad |= fclose(o->f) != 0;
	o->f = NULL;
	if (!bad && o->tmp && rename(o->tmp, o->dest) != 0)
		bad = 1;
	if (bad) {
		int e = errno;
		anvil_err_set(err, ANVIL_EIO, "%s: write failed: %s", o->path, strerror(e));
		cli_out_abort(o);
		return ANVIL_EIO;
	}
	free(o->tmp); /* renamed: nothing to remove */
	o->tmp = NULL;
	out_clear(o);
	return ANVIL_OK;
}

int cli_out_commit(struct cli_out *o)
{
	struct anvil_err err = {0};
	int to_stdout = o->f == stdout;
	int st = cli_out_commit_err(o, &err);
	/* a closed pipe (head) stays quiet; a full disk or an I/O error on
	 * standard output is said, or "> /dev/full" exits 1 without a word */
	if (st && (!to_stdout || errno != EPIPE))
		cli_error("%s", err.msg);
	return st;
}

void cli_out_abort(struct cli_out *o)
{
	if (o->f && o->f != stdout)
		fclose(o->f);
	o->f = NULL;
	if (o->tmp)
		unlink(o->tmp);
	out_clear(o);
}

double cli_now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int cli_progress_cb(void *ctx, double fraction, const char *what)
{
	struct cli_progress *p = ctx;
	double now = cli_now();
	if (p->start == 0)
		p->start = now;
	if (now - p->start < 1.0 || !isatty(STDERR_FILENO))
		return 0;
	fprintf(stderr, "\r\033[K%s: %3.0f%%", what, 100.0 * fraction);
	fflush(stderr);
	p->shown = 1;
	return 0;
}

void cli_progress_done(struct cli_progress *p)
{
	if (p->shown) {
		fputs("\r\033[K", stderr);
		fflush(stderr);
	}
	p->shown = 0;
}

int cli_plan(const struct anvil_scene *sc, const struct anvil_cache *cache,
	     struct anvil_plan *pl, struct anvil_err *err)
{
	struct anvil_problem pb;
	int st = anvil_problem_init(&pb, sc, err);
	return st ? st : anvil_plan_make(&pb, cache, pl, err);
}

int cli_run_model(struct anvil_solver *s, const struct anvil_scene *sc, enum anvil_model m,
		  size_t nhist, struct anvil_result *r, struct anvil_err *err)
{
	struct anvil_plan pl;
	int st = cli_plan(sc, anvil_solver_cache(s), &pl, err);
	if (!st)
		return anvil_solver_run(s, &pl, m, nhist, r, err);
	anvil_result_init(r, m);
	r->status = st;
	if (err)
		snprintf(r->why, sizeof r->why, "%s", err->msg);
	return st;
}
