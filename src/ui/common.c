#include <errno.h>
#include <locale.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <sys/stat.h>

#include <gsl/gsl_errno.h>

#include "common.h"

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

int cli_scene(struct anvil_scene *sc, const char *path, char *const *sets,
	      int nsets)
{
	struct anvil_err err = {0};
	anvil_scene_default(sc);
	int st = path ? anvil_scene_load(sc, path, &err) : ANVIL_OK;
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

int cli_out_open(struct cli_out *o, const char *path)
{
	memset(o, 0, sizeof *o);
	if (!path || strcmp(path, "-") == 0) {
		o->f = stdout;
		return ANVIL_OK;
	}
	size_t n = strlen(path) + 16;
	o->path = strdup(path);
	o->tmp = malloc(n);
	if (!o->path || !o->tmp) {
		cli_out_abort(o);
		cli_error("%s: out of memory", path);
		return ANVIL_ENOMEM;
	}
	snprintf(o->tmp, n, "%s.tmpXXXXXX", path);
	int fd = mkstemp(o->tmp);
	/* mkstemp makes the file 0600; outputs get the usual 0666 & ~umask */
	if (fd >= 0) {
		mode_t mask = umask(0);
		umask(mask);
		if (fchmod(fd, 0666 & ~mask) != 0) {
			close(fd);
			unlink(o->tmp);
			fd = -1;
		}
	}
	if (fd < 0 || !(o->f = fdopen(fd, "w"))) {
		cli_error("%s: cannot write: %s", path, strerror(errno));
		if (fd >= 0) {
			close(fd);
			unlink(o->tmp);
		}
		free(o->tmp);
		o->tmp = NULL;
		cli_out_abort(o);
		return ANVIL_EIO;
	}
	return ANVIL_OK;
}

int cli_out_commit(struct cli_out *o)
{
	if (o->f == stdout) {
		o->f = NULL;
		return fflush(stdout) == 0 && !ferror(stdout) ? ANVIL_OK : ANVIL_EIO;
	}
	if (!o->f)
		return ANVIL_EIO;
	int bad = ferror(o->f);
	bad |= fclose(o->f) != 0;
	o->f = NULL;
	if (!bad && rename(o->tmp, o->path) != 0)
		bad = 1;
	if (bad) {
		cli_error("%s: write failed: %s", o->path, strerror(errno));
		unlink(o->tmp);
		cli_out_abort(o);
		return ANVIL_EIO;
	}
	free(o->tmp);
	o->tmp = NULL;
	cli_out_abort(o);
	return ANVIL_OK;
}

void cli_out_abort(struct cli_out *o)
{
	if (o->f && o->f != stdout)
		fclose(o->f);
	if (o->tmp)
		unlink(o->tmp);
	free(o->tmp);
	free(o->path);
	memset(o, 0, sizeof *o);
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
