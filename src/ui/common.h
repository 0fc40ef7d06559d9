/* common.h: what every front end of anvil shares.
 *
 * Exit codes, error printing, the scene given on a command line
 * ([SCENE] plus -s KEY=VALUE...), output files written atomically
 * (a temporary file renamed into place, so a failure never leaves half a
 * file), and progress on stderr when stderr is a terminal. */
#ifndef ANVIL_UI_COMMON_H
#define ANVIL_UI_COMMON_H

#include <stdio.h>
#include <sys/types.h>

#include "plan.h"
#include "problem.h"
#include "scene.h"
#include "solver.h"

enum { EXIT_OK = 0, EXIT_FAIL = 1, EXIT_USAGE = 2 };

/* Turn GSL's abort-on-error off, fix the numeric locale.  Call first. */
void cli_init(void);

/* "anvil: MESSAGE" on stderr (one line). */
void cli_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* "anvil: PATH: write failed: REASON" (errno's), PATH "standard output"
 * for NULL or "-", where a closed pipe stays quiet (as cli_out_commit). */
void cli_write_failed(const char *path);

/* Map a core status to an exit code: input errors -> 2, others -> 1. */
/* A model's message without a leading "MODEL: " (the core's refusals
 * name the model; a row or a "MODEL: " prefix already does). */
const char *cli_model_reason(enum anvil_model m, const char *msg);
int cli_exit_code(int status);

/* --strict, a global option (main.c takes it out of argv before the
 * command sees it): plausibility warnings are errors. */
extern int cli_strict;

/* The scene of a command line: start from the embedded default, load path
 * (NULL: none), then apply each "KEY=VALUE" of sets in order.  On error
 * prints the one-line message and returns the core status.  Then prints
 * each plausibility warning (anvil_scene_warnings) as "anvil: warning:
 * FILE:LINE: KEY: ..." on stderr; with --strict they are errors
 * (ANVIL_EINVAL, exit 2). */
int cli_scene(struct anvil_scene *sc, const char *path, char *const *sets,
	      int nsets);
/* cli_scene (which is this with quiet 0); unless quiet, a note on stderr
 * when a thickness in r0 (the default scene's 1 r0) follows a radius that
 * sets changed and sets do not give the thickness themselves. */
int cli_scene_q(struct anvil_scene *sc, const char *path, char *const *sets,
		int nsets, int quiet);

/* The scene read once, at the edge: problem (problem.h), then plan (cache
 * may be NULL; it only prices the plan).  Statuses as anvil_problem_init
 * and anvil_plan_make. */
int cli_plan(const struct anvil_scene *sc, const struct anvil_cache *cache,
	     struct anvil_plan *pl, struct anvil_err *err);
/* Plan sc and run its row m with solver s (anvil_solver_run): for front
 * ends that run one row of a scene.  r is initialised either way, its
 * status set. */
int cli_run_model(struct anvil_solver *s, const struct anvil_scene *sc, enum anvil_model m,
		  size_t nhist, struct anvil_result *r, struct anvil_err *err);

/* Collects -s KEY=VALUE arguments while a command parses its options. */
struct cli_sets {
	int n, cap;
	char **v; /* borrowed pointers into argv */
};
int cli_sets_add(struct cli_sets *s, char *kv); /* ANVIL_ENOMEM */
void cli_sets_free(struct cli_sets *s);

/* An output file.  path "-" or NULL is stdout.  What is at the path
 * decides how it is written:
 *   nothing, a regular file  a temporary file beside it, renamed into place
 *                            on commit (an existing file keeps its mode), so
 *                            a failure or a signal never leaves half a file;
 *   a symbolic link          the same for the file it points to (the link
 *                            stays a link; a dangling one gets its target);
 *   a device, FIFO, socket   written through directly (not replaced);
 *   a directory              refused.
 * Temporary files are registered with the signal handler of
 * cli_signals_install, which removes them when SIGINT/SIGTERM/SIGHUP (or
 * SIGPIPE, a closed pipe) end anvil. */
struct cli_out {
	FILE *f;
	char *path;  /* the name given, for messages; NULL for stdout */
	char *dest;  /* what commit replaces (path with links resolved) */
	char *tmp;   /* temporary name beside dest; NULL when direct */
	int direct;  /* written straight into path (device, FIFO): nothing to
		      * rename, and no seeking back (not a regular file) */
	int slot;    /* in the signal handler's registry, plus 1; 0 none */
};
/* Open; on failure prints "anvil: PATH: reason" and returns ANVIL_EIO (or
 * ANVIL_ENOMEM). */
int cli_out_open(struct cli_out *o, const char *path);
/* The same, never printing: the message goes to err (the TUI's way). */
int cli_out_open_err(struct cli_out *o, const char *path, struct anvil_err *err);
/* Flush, close and rename into place; ANVIL_EIO (message printed) on a
 * write error, in which case the temporary file is removed. */
int cli_out_commit(struct cli_out *o);
/* The same, never printing: the message goes to err. */
int cli_out_commit_err(struct cli_out *o, struct anvil_err *err);
/* Close and remove the temporary file (no-op after commit). */
void cli_out_abort(struct cli_out *o);

/* Signals: one SIGINT, SIGTERM or SIGHUP ends anvil at once with status
 * 128 + signal (SIGPIPE too, as its default would, quietly: 141), after removing the registered temporary output files and
 * terminating the registered child processes (gnuplot).  The handler is
 * async-signal-safe (unlink, kill, _exit).  Signals ignored at start
 * (nohup) stay ignored.  Installed by main for every command but the TUI,
 * which has its own. */
void cli_signals_install(void);
/* A child process (gnuplot) for the handler to SIGTERM; at most
 * CLI_MAX_CHILDREN at a time (-1 when full, else 0).  Unregister once
 * waited for, so a recycled pid is never killed. */
#define CLI_MAX_CHILDREN 4
int cli_child_register(pid_t pid);
void cli_child_unregister(pid_t pid);

/* A progress callback for anvil_solver_set_progress: draws
 * "what: NN%" on stderr when stderr is a terminal and the job has run for
 * more than a second; silent otherwise (pipes, CI).  ctx must point to a
 * struct cli_progress, zeroed before the job. */
struct cli_progress {
	double start;  /* set by the first call */
	int shown;     /* a line is on screen */
};
int cli_progress_cb(void *ctx, double fraction, const char *what);
/* Erase the progress line if one is shown. */
void cli_progress_done(struct cli_progress *p);

/* Monotonic wall clock, seconds. */
double cli_now(void);

#endif
