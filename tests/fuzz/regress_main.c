/* regress_main: a fuzz target without libFuzzer, as a TAP test: every file
 * of tests/fuzz/regress/TARGET/ (inputs that once crashed or failed a
 * property) and tests/fuzz/corpus/TARGET/ (the seeds) is run through the
 * target's LLVMFuzzerTestOneInput.  A finding aborts (the round-trip
 * property) or, in an --enable-asan --enable-ubsan build, stops the
 * program: the test fails.  TARGET is compiled in (-DFUZZ_TARGET). */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../tap.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
	FILE *f = fopen(path, "rb");
	uint8_t *buf = NULL;
	size_t n = 0, cap = 0, got;
	if (!f)
		return -1;
	do {
		if (n == cap) {
			uint8_t *more = realloc(buf, cap = cap ? 2 * cap : 4096);
			if (!more) {
				free(buf);
				fclose(f);
				return -1;
			}
			buf = more;
		}
		got = fread(buf + n, 1, cap - n, f);
		n += got;
	} while (got > 0);
	fclose(f);
	LLVMFuzzerTestOneInput(buf, n);
	free(buf);
	return 0;
}

static int compare(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The files of top/tests/fuzz/kind/FUZZ_TARGET, sorted (stable test
 * numbers).  A directory that is not there has nothing to run. */
static void run_dir(const char *top, const char *kind)
{
	char *names[512], dir[512], path[1024];
	int n = 0;
	snprintf(dir, sizeof dir, "%s/tests/fuzz/%s/%s", top, kind, FUZZ_TARGET);
	DIR *d = opendir(dir);
	struct dirent *e;
	if (!d) {
		diag("%s: none", dir);
		return;
	}
	while ((e = readdir(d)) && n < 512)
		if (e->d_name[0] != '.' && (names[n] = strdup(e->d_name)))
			n++;
	closedir(d);
	qsort(names, (size_t)n, sizeof *names, compare);
	for (int i = 0; i < n; i++) {
		snprintf(path, sizeof path, "%s/%s", dir, names[i]);
		ok(run_file(path) == 0, "%s %s/%s", FUZZ_TARGET, kind, names[i]);
		free(names[i]);
	}
}

int main(void)
{
	const char *top = getenv("top_srcdir");
	if (!top || !*top)
		top = ".";
	run_dir(top, "regress");
	run_dir(top, "corpus");
	plan(tap_n);
	return done_testing();
}
