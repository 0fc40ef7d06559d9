/* progress.h: how long work reports progress and is cancelled.
 *
 * fraction in [0,1] of the current job, what a short phrase ("layer
 * response h = 2 r0").  Return non-zero to cancel: the running call then
 * returns ANVIL_ECANCEL (kissfft/cubature style: a callback that returns
 * non-zero stops the work). */
#ifndef ANVIL_PROGRESS_H
#define ANVIL_PROGRESS_H

typedef int (*anvil_progress_fn)(void *ctx, double fraction, const char *what);

#endif
