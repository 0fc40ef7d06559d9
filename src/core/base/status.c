#include <stdarg.h>
#include <stdio.h>

#include "status.h"

const char *anvil_strerror(int status)
{
	switch (status) {
#define ANVIL_STATUS_CASE(name, value, text) \
	case name:                            \
		return text;
		ANVIL_STATUS_LIST(ANVIL_STATUS_CASE)
#undef ANVIL_STATUS_CASE
	}
	return "unknown status";
}

int anvil_err_set(struct anvil_err *err, int status, const char *fmt, ...)
{
	if (err) {
		va_list ap;
		err->status = status;
		va_start(ap, fmt);
		vsnprintf(err->msg, sizeof err->msg, fmt, ap);
		va_end(ap);
	}
	return status;
}

void anvil_err_clear(struct anvil_err *err)
{
	if (err) {
		err->status = ANVIL_OK;
		err->msg[0] = '\0';
	}
}
