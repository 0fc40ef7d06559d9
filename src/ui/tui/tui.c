/* tui.c: `anvil tui`: the curses loop, the worker thread that runs the
 * solvers, and the terminal's restoration on every way out.
 *
 * The model (tui_model.c) holds the state and handles the keys, the screens
 * (tui_draw.c) draw it; this file owns what the two must not: the terminal,
 * the thread, the signals, the files.
 *
 * Threads: the worker owns one anvil_solver for the whole session (its
 * layer responses are reused across runs) and computes jobs posted by the
 * loop.  Each job carries the generation it was made for; the solver's
 * progress callback cancels the run as soon as a newer generation exists,
 * and whatever comes back is tagged, so the model drops stale results.
 * Finished results are queued under the mutex and announced through a
 * pipe, which the loop polls together with the keyboard. */
#include <errno.h>
#include <fcntl.h>
#include <langinfo.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <curses.h>
#include <term.h>

#include "commands.h"
#include "common.h"
#include "plot.h"
#include "tui_draw.h"
#include "tui_model.h"

/* Samples of each history: enough for a braille plot 250 columns wide. */
/* Poll timeouts, ms: progress is redrawn this often while computing; when
 * idle the loop still wakes now and then, so that a resize or a Ctrl-C
 * that lands between two polls is never left waiting. */
#define POLL_BUSY_MS 100
#define POLL_IDLE_MS 250

/* ---- the worker ---- */

/* A finished row, or (plan set) the plan the rows of gen run from. */
struct done {
	struct done *next;
	unsigned gen;
	enum anvil_model model;
	int status;
	char msg[ANVIL_ERR_MSG];
	struct anvil_result r;
	struct anvil_plan *plan; /* owned; NULL for a row */
};

struct worker {
	pthread_t thread;
	pthread_mutex_t mu;
	pthread_cond_t cv;
	struct anvil_solver *solver;
	int wake[2];            /* the worker writes a byte when a result is queued */
	atomic_uint want;       /* the newest generation; runs for others are stale */
	/* under mu: */
	int quit, have_job;
	int exited;             /* worker_main has returned (broadcast on cv) */
	unsigned job_gen, job_mask;
	struct anvil_scene job_sc;
	struct done *head, **tail;
	unsigned prog_gen;
	double prog_frac;
	char prog_what[64];
};

struct progress_ctx {
	struct worker *w;
	unsigned gen;
};

/* Cancels a stale run; records the progress of the current one. */
static int worker_progress(void *ctx, double fraction, const char *what)
{
	struct progress_ctx *p = ctx;
	if (atomic_load(&p->w->want) != p->gen)
		return 1;
	pthread_mutex_lock(&p->w->mu);
	p->w->prog_gen = p->gen;
	p->w->prog_frac = fraction;
	snprintf(p->w->prog_what, sizeof p->w->prog_what, "%s", what ? what : "");
	pthread_mutex_unlock(&p->w->mu);
	return 0;
}

static void worker_queue(struct worker *w, struct done *d)
{
	pthread_mutex_lock(&w->mu);
	d->next = NULL;
	*w->tail = d;
	w->tail = &d->next;
	pthread_mutex_unlock(&w->mu);
	/* a full pipe already holds a wake-up: nothing lost */
	(void)!write(w->wake[1], "r", 1);
}

/* One row of the job's plan; 0 to go on, -1 when the job went stale.  A
 * plan that failed (the scene's fault) is every row's status. */
static int worker_run_one(struct worker *w, const struct anvil_plan *pl, int plan_st,
			  const struct anvil_err *plan_err, unsigned gen, enum anvil_model model)
{
	struct anvil_err err = *plan_err;
	struct done *d = calloc(1, sizeof *d);
	if (!d)
		return -1;
	d->gen = gen;
	d->model = model;
	anvil_result_init(&d->r, model);
	d->status = plan_st ? plan_st : anvil_solver_run(w->solver, pl, model, TUI_NHIST, &d->r, &err);
	if (d->status == ANVIL_ECANCEL || atomic_load(&w->want) != gen) {
		anvil_result_free(&d->r);
		free(d);
		return -1;
	}
	snprintf(d->msg, sizeof d->msg, "%s", err.msg);
	worker_queue(w, d);
	return 0;
}

/* The scene is planned once; the plan goes to the model (the P screen
 * shows it) and every row runs from it, as `anvil run` does. */
static void worker_run(struct worker *w, const struct anvil_scene *sc,
		       unsigned gen, unsigned mask)
{
	/* the quick models first, so the table fills while the layer runs */
	static const enum anvil_model order[ANVIL_MODEL_COUNT] = {
		ANVIL_MODEL_HERTZ, ANVIL_MODEL_ZENER, ANVIL_MODEL_HALFSPACE,
		ANVIL_MODEL_LAYER};
	struct progress_ctx ctx = {w, gen};
	struct anvil_err plan_err = {0};
	struct done *pd = calloc(1, sizeof *pd);
	struct anvil_plan *pl = malloc(sizeof *pl);
	if (!pd || !pl) {
		free(pd);
		free(pl);
		return;
	}
	int plan_st = cli_plan(sc, anvil_solver_cache(w->solver), pl, &plan_err);
	if (!plan_st) {
		struct anvil_plan *copy = malloc(sizeof *copy);
		if (copy) {
			*copy = *pl;
			*pd = (struct done){ .gen = gen, .plan = copy };
			worker_queue(w, pd);
			pd = NULL;
		}
	}
	free(pd);
	anvil_solver_set_progress(w->solver, worker_progress, &ctx);
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i)
		if ((mask & (1u << order[i])) &&
		    worker_run_one(w, pl, plan_st, &plan_err, gen, order[i]) < 0)
			break;
	anvil_solver_set_progress(w->solver, NULL, NULL);
	free(pl);
}

static void *worker_main(void *arg)
{
	struct worker *w = arg;
	struct anvil_scene sc;
	for (;;) {
		unsigned gen, mask;
		pthread_mutex_lock(&w->mu);
		while (!w->have_job && !w->quit)
			pthread_cond_wait(&w->cv, &w->mu);
		if (w->quit) {
			pthread_mutex_unlock(&w->mu);
			break;
		}
		sc = w->job_sc;
		gen = w->job_gen;
		mask = w->job_mask;
		w->have_job = 0;
		pthread_mutex_unlock(&w->mu);
		worker_run(w, &sc, gen, mask);
	}
	pthread_mutex_lock(&w->mu);
	w->exited = 1;
	pthread_cond_broadcast(&w->cv);
	pthread_mutex_unlock(&w->mu);
	return NULL;
}

/* Signals that the loop must see (poll returns EINTR) go to the main
 * thread only: the worker blocks them. */
static void async_signals(sigset_t *set)
{
	static const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGWINCH,
				   SIGTSTP, SIGCONT};
	sigemptyset(set);
	for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; ++i)
		sigaddset(set, sigs[i]);
}

static int worker_start(struct worker *w)
{
	sigset_t block, old;
	memset(w, 0, sizeof *w);
	w->tail = &w->head;
	atomic_init(&w->want, 0);
	w->wake[0] = w->wake[1] = -1;
	if (!(w->solver = anvil_solver_alloc()) || pipe(w->wake) != 0)
		goto fail;
	fcntl(w->wake[0], F_SETFL, O_NONBLOCK);
	fcntl(w->wake[1], F_SETFL, O_NONBLOCK);
	pthread_mutex_init(&w->mu, NULL);
	pthread_cond_init(&w->cv, NULL);
	async_signals(&block);
	pthread_sigmask(SIG_BLOCK, &block, &old);
	int rc = pthread_create(&w->thread, NULL, worker_main, w);
	pthread_sigmask(SIG_SETMASK, &old, NULL);
	if (rc == 0)
		return 0;
	pthread_cond_destroy(&w->cv);
	pthread_mutex_destroy(&w->mu);
fail:
	if (w->wake[0] >= 0) {
		close(w->wake[0]);
		close(w->wake[1]);
	}
	anvil_solver_free(w->solver);
	return -1;
}

/* Cancel and stop the worker; 0 once it has ended and everything is freed.
 * A solver between two progress calls may not answer for seconds: after
 * WORKER_STOP_MS the thread is detached and -1 returned, with nothing
 * freed (it still uses it): the caller restores the terminal and _exits. */
#define WORKER_STOP_MS 100
static int worker_stop(struct worker *w)
{
	struct timespec until;
	int exited;
	atomic_store(&w->want, atomic_load(&w->want) + 1); /* cancel the run */
	clock_gettime(CLOCK_REALTIME, &until);
	until.tv_nsec += WORKER_STOP_MS * 1000000L;
	until.tv_sec += until.tv_nsec / 1000000000L;
	until.tv_nsec %= 1000000000L;
	pthread_mutex_lock(&w->mu);
	w->quit = 1;
	pthread_cond_broadcast(&w->cv);
	while (!w->exited && pthread_cond_timedwait(&w->cv, &w->mu, &until) == 0)
		;
	exited = w->exited;
	pthread_mutex_unlock(&w->mu);
	if (!exited) {
		pthread_detach(w->thread);
		return -1;
	}
	pthread_join(w->thread, NULL);
	for (struct done *d = w->head, *next; d; d = next) {
		next = d->next;
		anvil_result_free(&d->r);
		free(d->plan);
		free(d);
	}
	pthread_cond_destroy(&w->cv);
	pthread_mutex_destroy(&w->mu);
	close(w->wake[0]);
	close(w->wake[1]);
	anvil_solver_free(w->solver);
	return 0;
}

static void worker_post(struct worker *w, unsigned gen,
			const struct anvil_scene *sc, unsigned mask)
{
	/* even with no row to compute: cancels the old, and makes the plan */
	atomic_store(&w->want, gen);
	pthread_mutex_lock(&w->mu);
	w->job_sc = *sc;
	w->job_gen = gen;
	w->job_mask = mask;
	w->have_job = 1;
	pthread_cond_signal(&w->cv);
	pthread_mutex_unlock(&w->mu);
}

/* ---- the session ---- */

struct tui {
	struct tui_model m;
	struct tui_view view;
	struct worker w;
};

static void request(struct tui *t)
{
	unsigned mask = tui_model_request(&t->m);
	worker_post(&t->w, t->m.gen, tui_model_scene(&t->m), mask);
}

/* Hand finished results and progress to the model; 1 if anything came. */
static int collect(struct tui *t)
{
	char buf[64];
	struct done *list;
	int busy = tui_model_busy(&t->m), any = 0;
	while (read(t->w.wake[0], buf, sizeof buf) > 0)
		;
	pthread_mutex_lock(&t->w.mu);
	list = t->w.head;
	t->w.head = NULL;
	t->w.tail = &t->w.head;
	if (busy && t->w.prog_gen == t->m.gen) {
		tui_model_progress(&t->m, t->w.prog_gen, t->w.prog_frac, t->w.prog_what);
		any = 1;
	}
	pthread_mutex_unlock(&t->w.mu);
	for (struct done *d = list, *next; d; d = next) {
		next = d->next;
		if (d->plan) {
			tui_model_deliver_plan(&t->m, d->gen, d->plan);
			free(d->plan);
			any = 1;
		} else {
			any |= tui_model_deliver(&t->m, d->gen, d->model, d->status, d->msg, &d->r);
		}
		free(d);
	}
	return any;
}

/* ---- the actions ---- */

static void export_charts(struct tui *t)
{
	struct anvil_result res[ANVIL_MODEL_COUNT];
	struct anvil_err err = {0};
	char paths[4096] = "";
	const char *dir = getenv("ANVIL_PNG_DIR");
	int n = 0;
	if (tui_model_busy(&t->m)) {
		tui_model_message(&t->m, 1, "still computing: export when the results are in");
		return;
	}
	for (int i = 0; i < ANVIL_MODEL_COUNT; ++i) {
		const struct tui_row *row = &t->m.rows[tui_model_order[i]];
		if (row->state == TUI_ROW_DONE && row->have)
			res[n++] = row->res; /* shallow: plot only reads */
	}
	if (!n) {
		tui_model_message(&t->m, 1, "no results to export");
		return;
	}
	tui_model_message(&t->m, 0, "exporting charts...");
	tui_draw(&t->m, &t->view);
	if (plot_run_charts(dir && *dir ? dir : ".", tui_model_scene(&t->m), res,
			    n, paths, sizeof paths, &err)) {
		tui_model_message(&t->m, 1, "export failed: %s", err.msg);
		return;
	}
	for (char *p = paths; (p = strchr(p, '\n')) != NULL;)
		*p = p[1] ? ' ' : '\0';
	tui_model_message(&t->m, 0, "wrote %s", paths);
}

static void save_scene(struct tui *t)
{
	char path[TUI_PATH_MAX];
	struct anvil_err err = {0};
	struct cli_out o;
	snprintf(path, sizeof path, "%s", tui_model_save_path(&t->m));
	int st = cli_out_open_err(&o, path, &err);
	if (!st) {
		st = anvil_scene_write(tui_model_scene(&t->m), o.f);
		if (st)
			cli_out_abort(&o);
		else
			st = cli_out_commit_err(&o, &err);
	}
	if (st)
		tui_model_message(&t->m, 1, "%s", err.msg[0] ? err.msg : anvil_strerror(st));
	else
		tui_model_saved(&t->m, path);
}

/* ---- keys ---- */

static int map_key(int ch)
{
	switch (ch) {
	case KEY_UP: return TUI_KEY_UP;
	case KEY_DOWN: return TUI_KEY_DOWN;
	case KEY_LEFT: return TUI_KEY_LEFT;
	case KEY_RIGHT: return TUI_KEY_RIGHT;
	case KEY_SLEFT: return TUI_KEY_SLEFT;
	case KEY_SRIGHT: return TUI_KEY_SRIGHT;
	case KEY_ENTER: case '\n': case '\r': return TUI_KEY_ENTER;
	case KEY_BACKSPACE: case 127: case 8: return TUI_KEY_BACKSPACE;
	case 27: return TUI_KEY_ESC;
	case KEY_F(1): return TUI_KEY_HELP;
	}
	return ch >= 0 && ch < 0x100 ? ch : -1;
}

static int too_small(void)
{
	return COLS < TUI_MIN_COLS || LINES < TUI_MIN_ROWS;
}

/* One key; 1 to quit. */
static int on_key(struct tui *t, int ch, int *dirty)
{
	int key = map_key(ch);
	if (ch == KEY_RESIZE) {
		*dirty = 1;
		return 0;
	}
	/* on the size message only quitting makes sense: keys typed blind
	 * must not change a scene nobody can see */
	if (key <= 0 || (too_small() && !strchr("qQyn", key)))
		return 0;
	switch (tui_model_key(&t->m, key)) {
	case TUI_ACT_NONE: return 0;
	case TUI_ACT_QUIT: return 1;
	case TUI_ACT_RECOMPUTE: request(t); break;
	case TUI_ACT_EXPORT: export_charts(t); break;
	case TUI_ACT_SAVE: save_scene(t); break;
	case TUI_ACT_REPAINT: clearok(curscr, TRUE); break;
	case TUI_ACT_REDRAW: break;
	}
	*dirty = 1;
	return 0;
}

/* ---- signals and the terminal ---- */

static volatile sig_atomic_t got_sigint;
static struct termios saved_tty;
static int have_saved_tty;
static char restore_seq[256];
static size_t restore_len;

static void on_sigint(int sig)
{
	(void)sig;
	got_sigint = 1;
}

/* A fatal signal: undo what curses did to the terminal with what is safe
 * in a handler (write, tcsetattr), then die of the signal as if there had
 * been no handler (SA_RESETHAND restored the default). */
static void on_fatal(int sig)
{
	if (restore_len)
		(void)!write(STDOUT_FILENO, restore_seq, restore_len);
	if (have_saved_tty) /* TCSANOW: never wait for output in a handler */
		tcsetattr(STDIN_FILENO, TCSANOW, &saved_tty);
	raise(sig);
}

static const int fatal_signals[] = {SIGTERM, SIGHUP, SIGQUIT, SIGSEGV,
				    SIGABRT, SIGBUS, SIGFPE, SIGILL};
#define NFATAL (sizeof fatal_signals / sizeof fatal_signals[0])

/* What the signals did before, put back on the way out. */
static struct sigaction old_int, old_pipe, old_fatal[NFATAL];

/* Catch sig unless it was ignored when we started (nohup, a background
 * job of a non-interactive shell): that choice was the user's. */
static void catch(int sig, void (*handler)(int), int flags, struct sigaction *old)
{
	struct sigaction sa;
	if (sigaction(sig, NULL, old) == 0 && old->sa_handler == SIG_IGN)
		return;
	memset(&sa, 0, sizeof sa);
	sigemptyset(&sa.sa_mask);
	sa.sa_handler = handler;
	sa.sa_flags = flags;
	sigaction(sig, &sa, NULL);
}

static void signals_install(void)
{
	struct sigaction ign;
	catch(SIGINT, on_sigint, 0, &old_int); /* no SA_RESTART: poll must return */
	for (size_t i = 0; i < NFATAL; ++i)
		catch(fatal_signals[i], on_fatal, SA_RESETHAND, &old_fatal[i]);
	/* a gnuplot that dies must be a message, not our death */
	memset(&ign, 0, sizeof ign);
	sigemptyset(&ign.sa_mask);
	ign.sa_handler = SIG_IGN;
	sigaction(SIGPIPE, &ign, &old_pipe);
}

static void signals_restore(void)
{
	sigaction(SIGINT, &old_int, NULL);
	sigaction(SIGPIPE, &old_pipe, NULL);
	for (size_t i = 0; i < NFATAL; ++i)
		sigaction(fatal_signals[i], &old_fatal[i], NULL);
}

/* The strings that leave curses mode, from terminfo, ready for the
 * handler (which cannot call endwin). */
static void restore_prepare(void)
{
	static const char *const caps[] = {"rmcup", "rmkx", "cnorm", "sgr0"};
	restore_len = 0;
	for (size_t i = 0; i < sizeof caps / sizeof caps[0]; ++i) {
		char *s = tigetstr(caps[i]);
		size_t n = s && s != (char *)-1 ? strlen(s) : 0;
		if (n && restore_len + n < sizeof restore_seq) {
			memcpy(restore_seq + restore_len, s, n);
			restore_len += n;
		}
	}
}

static SCREEN *screen_start(const struct tui_view *want, struct tui_view *v)
{
	SCREEN *scr = newterm(NULL, stdout, stdin);
	if (!scr)
		return NULL;
	set_term(scr);
	restore_prepare();
	cbreak();
	noecho();
	keypad(stdscr, TRUE);
	nodelay(stdscr, TRUE);
	set_escdelay(25); /* Esc cancels an edit without a noticeable wait */
	curs_set(0);
	tui_draw_init(v, want->color, want->utf8);
	return scr;
}

static void screen_end(SCREEN *scr)
{
	endwin();
	delscreen(scr);
	restore_len = 0;
}

/* ---- the loop ---- */

static void loop(struct tui *t)
{
	int dirty = 1;
	request(t);
	while (!got_sigint) {
		struct pollfd p[2] = {{.fd = STDIN_FILENO, .events = POLLIN},
				      {.fd = t->w.wake[0], .events = POLLIN}};
		int ch;
		if (dirty)
			tui_draw(&t->m, &t->view);
		dirty = 0;
		poll(p, 2, tui_model_busy(&t->m) ? POLL_BUSY_MS : POLL_IDLE_MS);
		dirty |= collect(t);
		while ((ch = getch()) != ERR)
			if (on_key(t, ch, &dirty))
				return;
	}
}

/* ---- the command ---- */

static void usage(FILE *f)
{
	fputs("usage: anvil tui [SCENE] [-s KEY=VALUE]...\n"
	      "Explore a scene in the terminal; press ? inside for the keys.\n", f);
}

/* -1: done (help shown), 0: go on, else an exit code. */
static int parse_args(int argc, char **argv, const char **path, struct cli_sets *sets)
{
	for (int i = 1; i < argc; ++i) {
		char *a = argv[i];
		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			usage(stdout);
			return -1;
		}
		if (!strcmp(a, "-s") && i + 1 == argc) {
			cli_error("tui: -s needs KEY=VALUE");
			return EXIT_USAGE;
		}
		if (!strcmp(a, "-s"))
			a = argv[++i];
		else if (!strncmp(a, "-s", 2) && a[2])
			a += 2;
		else if (a[0] == '-' && a[1]) {
			cli_error("tui: unknown option '%s'", a);
			usage(stderr);
			return EXIT_USAGE;
		} else if (*path) {
			cli_error("tui: one scene file only ('%s' and '%s')", *path, a);
			return EXIT_USAGE;
		} else {
			*path = a;
			continue;
		}
		if (cli_sets_add(sets, a))
			return EXIT_FAIL;
	}
	return 0;
}

static int run(struct tui *t, const struct tui_view *want)
{
	SCREEN *scr;
	if (worker_start(&t->w)) {
		cli_error("tui: cannot start the solver thread");
		return EXIT_FAIL;
	}
	have_saved_tty = tcgetattr(STDIN_FILENO, &saved_tty) == 0;
	signals_install();
	if (!(scr = screen_start(want, &t->view))) {
		signals_restore();
		(void)worker_stop(&t->w);
		cli_error("tui: cannot use the terminal (TERM=%s)",
			  getenv("TERM") ? getenv("TERM") : "");
		return EXIT_FAIL;
	}
	loop(t);
	int stuck = worker_stop(&t->w);
	screen_end(scr);
	signals_restore();
	if (stuck) {
		/* the worker still computes with memory we would free: leave now,
		 * the terminal restored, as a signal would have */
		fflush(NULL);
		if (got_sigint) {
			signal(SIGINT, SIG_DFL);
			raise(SIGINT);
		}
		_exit(EXIT_OK);
	}
	return EXIT_OK;
}

int anvil_cmd_tui(int argc, char **argv)
{
	struct anvil_scene sc;
	struct cli_sets sets = {0};
	const char *path = NULL;
	struct tui_view want;
	cli_init();
	int rc = parse_args(argc, argv, &path, &sets);
	if (!rc)
		rc = cli_exit_code(cli_scene_q(&sc, path, sets.v, sets.n, 1));
	cli_sets_free(&sets);
	if (rc)
		return rc < 0 ? EXIT_OK : rc;
	if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
		cli_error("tui: needs a terminal (use 'anvil run' in scripts)");
		return EXIT_FAIL;
	}
	const char *nc = getenv("NO_COLOR");
	want.color = !(nc && nc[0]); /* no-color.org: set and not empty */
	want.utf8 = strcmp(nl_langinfo(CODESET), "UTF-8") == 0;
	struct tui *t = calloc(1, sizeof *t);
	if (!t) {
		cli_error("tui: out of memory");
		return EXIT_FAIL;
	}
	tui_model_init(&t->m, &sc, path && strcmp(path, "-") ? path : NULL);
	rc = run(t, &want);
	tui_model_free(&t->m);
	free(t);
	if (got_sigint) { /* die of it, as the shell expects, now the terminal is back */
		signal(SIGINT, SIG_DFL);
		raise(SIGINT);
	}
	return rc;
}
