/* status.h: anvil's status codes and error messages.
 *
 * Every core function that can fail returns an int status: ANVIL_OK (0) on
 * success, a negative code on failure, a positive one for a warning (as
 * CVODE does): the work was done and its values stand, with a reason
 * (ANVIL_WTOL: the accuracy target was not reached; the error estimates
 * say by how much).  Test `st < 0` for failure, `st >= 0` for usable values.  Functions that take a
 * `struct anvil_err *` (which may be NULL) also leave a one-line message there
 * for the user, naming the file, line and key when the error is about input.
 * The core never prints: the front ends decide what to show. */
#ifndef ANVIL_STATUS_H
#define ANVIL_STATUS_H

#define ANVIL_STATUS_LIST(X)                                              \
	X(ANVIL_WTOL, 1, "accuracy target not reached")                   \
	X(ANVIL_OK, 0, "success")                                         \
	X(ANVIL_EINVAL, -1, "invalid argument")                           \
	X(ANVIL_ENOMEM, -2, "out of memory")                              \
	X(ANVIL_EPARSE, -3, "invalid input")                              \
	X(ANVIL_EIO, -4, "input/output error")                            \
	X(ANVIL_ETOL, -5, "requested accuracy cannot be reached")               \
	X(ANVIL_ENUM, -6, "numerical failure")                            \
	X(ANVIL_ECANCEL, -7, "cancelled")                                 \
	X(ANVIL_ENOTFOUND, -8, "not found")                               \
	X(ANVIL_EEXTERN, -9, "external program failed")

enum anvil_status {
#define ANVIL_STATUS_ENUM(name, value, text) name = value,
	ANVIL_STATUS_LIST(ANVIL_STATUS_ENUM)
#undef ANVIL_STATUS_ENUM
};

/* The words for a status code; never NULL. */
const char *anvil_strerror(int status);

#define ANVIL_ERR_MSG 512

struct anvil_err {
	int status;
	char msg[ANVIL_ERR_MSG];
};

/* Record status and a printf-style message in err (if err is not NULL) and
 * return status, so that callers can write `return anvil_err_set(...)`. */
int anvil_err_set(struct anvil_err *err, int status, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

/* Clear err to ANVIL_OK with an empty message (NULL is a no-op). */
void anvil_err_clear(struct anvil_err *err);

#endif
