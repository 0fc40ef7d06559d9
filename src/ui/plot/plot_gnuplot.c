/* plot_gnuplot.c: the gnuplot process, atomic image files, cancelling,
 * and the charts of one run.  Nothing here prints: errors go back as a
 * status and a one-line message.  See plot.h for the contract. */
#ifdef HAVE_CONFIG_H
#include "config.h"
#endif

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "common.h"
#include "plot.h"

#ifndef ANVIL_GNUPLOT
#define ANVIL_GNUPLOT "gnuplot"
#endif

/* How often a wait looks at the cancel flag, ms: a signal may arrive just
 * before a poll, so the flag is also polled. */
#define CANCEL_POLL_MS 50

const char *plot_gnuplot_path(void)
{
	const char *p = getenv("ANVIL_GNUPLOT");
	return p && p[0] ? p : ANVIL_GNUPLOT;
}

static int gnuplot_missing(struct anvil_err *err, const char *prog, int e)
{
	return anvil_err_set(err, ANVIL_EEXTERN,
			     "cannot run gnuplot '%s': %s (install gnuplot, or set ANVIL_GNUPLOT to its path)",
			     prog, strerror(e));
}

/* Is prog executable, directly or through PATH (as execvp finds it)? */
static int find_program(const char *prog)
{
	if (strchr(prog, '/'))
		return access(prog, X_OK) == 0 ? 0 : errno;
	const char *path = getenv("PATH");
	char buf[PATH_MAX];
	for (const char *p = path ? path : "/usr/bin:/bin"; ; p++) {
		size_t n = strcspn(p, ":");
		int len = snprintf(buf, sizeof buf, "%.*s%s%s", (int)n, p,
				   n ? "/" : "", prog);
		if (len > 0 && (size_t)len < sizeof buf && access(buf, X_OK) == 0)
			return 0;
		p += n;
		if (!*p)
			return ENOENT;
	}
}

int plot_gnuplot_check(struct anvil_err *err)
{
	const char *prog = plot_gnuplot_path();
	int e = find_program(prog);
	return e ? gnuplot_missing(err, prog, e) : ANVIL_OK;
}

/* ------------------------------------------------------ the process */

/* A running gnuplot: its script pipe, its stderr, and what it said. */
struct gp_proc {
	pid_t pid;
	int in, err;
	int status;     /* from waitpid */
	int exec_errno; /* gnuplot could not be started (or talked to) */
	int cancelled;
	const volatile sig_atomic_t *cancel;
	char msg[2048];
	size_t nmsg;
};

static void close_fd(int *fd)
{
	if (*fd >= 0)
		close(*fd);
	*fd = -1;
}

static void cloexec(int fd)
{
	fcntl(fd, F_SETFD, fcntl(fd, F_GETFD) | FD_CLOEXEC);
}

static int cancelled(struct gp_proc *g)
{
	if (g->cancel && *g->cancel)
		g->cancelled = 1;
	return g->cancelled;
}

/* The child: script on stdin, image to out_fd, stderr to the parent; an
 * exec failure is reported as errno through the close-on-exec pipe ex. */
static void gp_child(const char *prog, int in, int out_fd, int err, int ex)
{
	char *argv[] = {(char *)prog, (char *)"--default-settings", NULL};
	if (dup2(in, 0) >= 0 && dup2(out_fd, 1) >= 0 && dup2(err, 2) >= 0)
		execvp(prog, argv);
	int e = errno;
	if (write(ex, &e, sizeof e) < 0)
		_exit(126);
	_exit(127);
}

/* Start gnuplot.  Returns 0, or an errno value (exec failure included). */
static int gp_spawn(struct gp_proc *g, const char *prog, int out_fd)
{
	int in[2], er[2], ex[2], e = 0;
	g->pid = -1;
	g->in = g->err = -1;
	if (pipe(in) < 0)
		return errno;
	if (pipe(er) < 0 || pipe(ex) < 0) {
		e = errno;
		close(in[0]);
		close(in[1]);
		return e;
	}
	int fds[] = {in[0], in[1], er[0], er[1], ex[0], ex[1], out_fd};
	for (size_t i = 0; i < sizeof fds / sizeof fds[0]; i++)
		cloexec(fds[i]);
	g->pid = fork();
	if (g->pid == 0)
		gp_child(prog, in[0], out_fd, er[1], ex[1]);
	if (g->pid < 0)
		e = errno;
	close(in[0]);
	close(er[1]);
	close(ex[1]);
	/* EOF: exec succeeded; an int: exec failed with that errno. */
	if (g->pid > 0 && read(ex[0], &e, sizeof e) != (ssize_t)sizeof e)
		e = 0;
	close(ex[0]);
	g->in = in[1];
	g->err = er[0];
	if (e) {
		close_fd(&g->in);
		close_fd(&g->err);
		if (g->pid > 0)
			waitpid(g->pid, NULL, 0);
		g->pid = -1;
	}
	return e;
}

/* Keep the first part of gnuplot's stderr; drain the rest. */
static void gp_read_err(struct gp_proc *g)
{
	char buf[1024];
	ssize_t k = read(g->err, buf, sizeof buf);
	if (k <= 0) {
		if (k == 0 || errno != EINTR)
			close_fd(&g->err);
		return;
	}
	size_t room = sizeof g->msg - 1 - g->nmsg;
	size_t take = (size_t)k < room ? (size_t)k : room;
	memcpy(g->msg + g->nmsg, buf, take);
	g->nmsg += take;
	g->msg[g->nmsg] = '\0';
}

/* Write the script while reading stderr, so that neither pipe can fill
 * and block the other side.  Stops early when cancelled. */
static int gp_talk(struct gp_proc *g, const char *script, size_t len)
{
	size_t off = 0;
	if (len == 0)
		close_fd(&g->in);
	while ((g->in >= 0 || g->err >= 0) && !cancelled(g)) {
		struct pollfd p[2] = {{.fd = g->in, .events = POLLOUT},
				      {.fd = g->err, .events = POLLIN}};
		if (poll(p, 2, CANCEL_POLL_MS) < 0) {
			if (errno == EINTR)
				continue;
			return errno;
		}
		if (p[1].revents)
			gp_read_err(g);
		if (!p[0].revents)
			continue;
		/* At most PIPE_BUF bytes: a write POLLOUT allows never blocks. */
		size_t chunk = len - off < PIPE_BUF ? len - off : PIPE_BUF;
		ssize_t k = p[0].revents & POLLOUT ? write(g->in, script + off, chunk) : -1;
		if (k > 0)
			off += (size_t)k;
		/* gnuplot gone (EPIPE, POLLERR): its status tells why. */
		if (off == len || (k < 0 && errno != EINTR && errno != EAGAIN))
			close_fd(&g->in);
	}
	return 0;
}

/* Wait for gnuplot; when cancelled, end it first.  Never leaves it behind. */
static void gp_wait(struct gp_proc *g)
{
	for (;;) {
		if (cancelled(g))
			kill(g->pid, SIGKILL);
		pid_t r = waitpid(g->pid, &g->status, g->cancelled ? 0 : WNOHANG);
		if (r == g->pid || (r < 0 && errno != EINTR))
			return;
		if (r == 0)
			poll(NULL, 0, CANCEL_POLL_MS);
	}
}

static int signature_ok(int fd, enum plot_format fmt)
{
	static const char *const sig[PLOT_FORMAT_COUNT] = {"\x89PNG\r\n\x1a\n", "<?xml", "%PDF"};
	const char *s = sig[(unsigned)fmt % PLOT_FORMAT_COUNT];
	size_t n = strlen(s);
	char buf[16];
	if (fmt == PLOT_SVG) {
		/* gnuplot's svg starts with <?xml; some versions with <svg. */
		return pread(fd, buf, 5, 0) == 5 && (memcmp(buf, "<?xml", 5) == 0 ||
						     memcmp(buf, "<svg", 4) == 0);
	}
	return pread(fd, buf, n, 0) == (ssize_t)n && memcmp(buf, s, n) == 0;
}

/* Run gnuplot to completion: 0 when it exited 0 having written an image
 * (its signature checked when out_fd can be read back: readable). */
static int gp_run(struct gp_proc *g, const char *script, size_t len, int out_fd,
		  enum plot_format fmt, int readable)
{
	struct sigaction ign = {.sa_handler = SIG_IGN}, old;
	/* A gnuplot that dies early must not take anvil down with SIGPIPE. */
	sigemptyset(&ign.sa_mask);
	sigaction(SIGPIPE, &ign, &old);
	g->status = 0;
	g->exec_errno = gp_spawn(g, plot_gnuplot_path(), out_fd);
	if (!g->exec_errno) {
		g->exec_errno = gp_talk(g, script, len);
		close_fd(&g->in);
		if (!g->cancelled)
			while (g->err >= 0 && !cancelled(g)) {
				struct pollfd p = {.fd = g->err, .events = POLLIN};
				if (poll(&p, 1, CANCEL_POLL_MS) > 0)
					gp_read_err(g);
			}
		close_fd(&g->err);
		gp_wait(g);
	}
	sigaction(SIGPIPE, &old, NULL);
	return g->cancelled || g->exec_errno || !WIFEXITED(g->status) ||
	       WEXITSTATUS(g->status) != 0 || (readable && !signature_ok(out_fd, fmt));
}

/* gnuplot's words on one line: blank lines and the caret line under the
 * echoed command dropped, the rest joined with " | ". */
static void squash(const char *in, char *out, size_t len)
{
	size_t n = 0;
	out[0] = '\0';
	while (*in && n + 4 < len) {
		size_t k = strcspn(in, "\n");
		const char *s = in;
		while (k > 0 && (*s == ' ' || *s == '\t'))
			s++, k--;
		int caret = k > 0 && strspn(s, "^ \t") >= k;
		if (k > 0 && !caret)
			n += (size_t)snprintf(out + n, len - n, "%s%.*s", n ? " | " : "", (int)k, s);
		in = s + k + (s[k] == '\n');
	}
	if (n >= len)
		out[len - 1] = '\0';
}

static int gp_error(const struct gp_proc *g, const char *path, struct anvil_err *err)
{
	const char *prog = plot_gnuplot_path();
	char said[400];
	if (g->cancelled)
		return anvil_err_set(err, ANVIL_ECANCEL, "%s: cancelled; nothing written", path);
	if (g->exec_errno)
		return gnuplot_missing(err, prog, g->exec_errno);
	squash(g->msg, said, sizeof said);
	if (WIFSIGNALED(g->status))
		return anvil_err_set(err, ANVIL_EEXTERN,
				     "gnuplot (%s) was killed by signal %d while drawing %s",
				     prog, WTERMSIG(g->status), path);
	if (WEXITSTATUS(g->status) == 0)
		return anvil_err_set(err, ANVIL_EEXTERN, "gnuplot (%s) wrote no image for %s%s%s",
				     prog, path, said[0] ? ": " : "", said);
	return anvil_err_set(err, ANVIL_EEXTERN,
			     "gnuplot (%s) failed with exit status %d while drawing %s%s%s",
			     prog, WEXITSTATUS(g->status), path, said[0] ? ": " : "", said);
}

/* ------------------------------------------------- atomic output files */

/* The image and the script go through common.h's outputs, as every other
 * file anvil writes: links followed to the file they name, a device or
 * FIFO written straight into (qa7: a temporary file renamed onto
 * "--script /dev/full" replaced the device with a regular file, as root),
 * a directory refused, a regular file replaced at once by a temporary
 * one beside it, which a signal removes. */

int plot_render(const char *script, size_t len, const char *path,
		const struct plot_opts *o, struct anvil_err *err)
{
	struct cli_out out;
	struct gp_proc g = {.cancel = o ? o->cancel : NULL};
	enum plot_format fmt = o ? o->format : PLOT_PNG;
	if (!path || !path[0] || strcmp(path, "-") == 0)
		return anvil_err_set(err, ANVIL_EINVAL,
				     "an image needs a file name, not standard output");
	int st = cli_out_open_err(&out, path, err);
	if (st)
		return st;
	/* a device or FIFO cannot be read back: gnuplot's exit status alone */
	if (gp_run(&g, script, len, fileno(out.f), fmt, !out.direct)) {
		cli_out_abort(&out);
		return gp_error(&g, path, err);
	}
	return cli_out_commit_err(&out, err);
}

static int write_script_file(const char *path, const char *buf, size_t len,
			     struct anvil_err *err)
{
	struct cli_out out;
	int to_stdout = strcmp(path, "-") == 0;
	int st = cli_out_open_err(&out, to_stdout ? NULL : path, err);
	if (st)
		return st;
	if (fwrite(buf, 1, len, out.f) != len && !to_stdout) {
		int e = errno;
		cli_out_abort(&out);
		return anvil_err_set(err, ANVIL_EIO, "%s: write failed: %s", path, strerror(e));
	}
	return cli_out_commit_err(&out, err);
}

int plot_emit(const char *buf, size_t len, const struct plot_opts *o,
	      const char *path, const char *script_path, struct anvil_err *err)
{
	int st = script_path ? write_script_file(script_path, buf, len, err) : ANVIL_OK;
	return !st && path ? plot_render(buf, len, path, o, err) : st;
}

int plot_save(const struct plot_chart *c, const struct plot_opts *o,
	      const char *path, const char *script_path, struct anvil_err *err)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *m = open_memstream(&buf, &len);
	int st = m ? plot_write(m, c, o) : ANVIL_ENOMEM;
	if (m && fclose(m) != 0 && !st)
		st = ANVIL_ENOMEM;
	if (st == ANVIL_EINVAL)
		anvil_err_set(err, st, "%s chart: nothing to draw (no model computed a result)",
			      plot_kind_name(c->kind));
	else if (st)
		anvil_err_set(err, st, "%s chart: %s", plot_kind_name(c->kind),
			      anvil_strerror(st));
	else
		st = plot_emit(buf, len, o, path, script_path, err);
	free(buf);
	return st;
}

/* ----------------------------------------------------- one run's charts */

static void paths_append(char *paths, size_t len, const char *path)
{
	size_t used = strlen(paths);
	if (used + strlen(path) + 2 <= len)
		snprintf(paths + used, len - used, "%s\n", path);
}

static int run_chart(const char *dir, enum plot_kind kind, const struct plot_run *runs,
		     int n, const struct anvil_scene *sc, char *paths, size_t paths_len,
		     struct anvil_err *err)
{
	struct plot_chart c;
	struct plot_opts o;
	char path[PATH_MAX];
	plot_opts_default(&o);
	if (snprintf(path, sizeof path, "%s/%s.png", dir, plot_kind_name(kind)) >=
	    (int)sizeof path)
		return anvil_err_set(err, ANVIL_EIO, "%s: directory name too long", dir);
	int st = plot_chart_history(&c, kind, runs, n);
	plot_chart_subtitle(&c, sc, 0, 0);
	if (st == ANVIL_EINVAL)
		anvil_err_set(err, st, "%s: no model kept a history to draw", path);
	else if (st)
		anvil_err_set(err, st, "%s: %s", path, anvil_strerror(st));
	else if (!(st = plot_save(&c, &o, path, NULL, err)) && paths)
		paths_append(paths, paths_len, path);
	plot_chart_free(&c);
	return st;
}

int plot_run_charts(const char *dir, const struct anvil_scene *sc,
		    const struct anvil_result *res, int nres, char *paths,
		    size_t paths_len, struct anvil_err *err)
{
	static const enum plot_kind run_kinds[] = {PLOT_FORCE, PLOT_VELOCITY, PLOT_DEFLECTION};
	struct plot_run runs[ANVIL_MODEL_COUNT * 2];
	int n = 0, st;
	if (paths && paths_len)
		paths[0] = '\0';
	if ((st = plot_gnuplot_check(err)))
		return st;
	if (mkdir(dir, 0777) < 0 && errno != EEXIST)
		return anvil_err_set(err, ANVIL_EIO, "%s: cannot create directory: %s", dir,
				     strerror(errno));
	for (int i = 0; i < nres && n < (int)(sizeof runs / sizeof runs[0]); i++)
		runs[n++] = (struct plot_run){&res[i], res[i].model,
			anvil_scene_h(sc) / sc->radius, sc->velocity, res[i].lambda_star};
	for (size_t k = 0; k < sizeof run_kinds / sizeof run_kinds[0]; k++)
		if ((st = run_chart(dir, run_kinds[k], runs, n, sc, paths, paths_len, err)))
			return st;
	return ANVIL_OK;
}
