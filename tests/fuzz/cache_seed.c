/* cache_seed: writes one valid response file, as the cache writes it, for
 * the fuzz_cache seed corpus: "cache_seed FILE".  The first byte of a
 * fuzz_cache input is its flags (odd: fix the checksum), so the file
 * written is that byte followed by the response file. */
#include <stdio.h>
#include <stdlib.h>

#include "cache.h"
#include "green.h"

int main(int argc, char **argv)
{
	struct anvil_green_settings gs;
	struct anvil_err err;
	struct anvil_cache_key key = {1.0, 0.3, ANVIL_ACC_DRAFT, 0, 0, 0, ANVIL_CACHE_LOAD_R0, 0.0, 0.0};
	char tmp[] = "/tmp/anvil-cache-seed-XXXXXX";
	if (argc != 2) {
		fprintf(stderr, "usage: cache_seed FILE\n");
		return 2;
	}
	anvil_green_settings(ANVIL_ACC_DRAFT, &gs);
	gs.omega_max = anvil_cache_grid(key.omega_idx);
	/* a short window: a small file, a few hundred samples */
	struct anvil_green *g = anvil_green_alloc(ANVIL_GREEN_LAYER_CORRECTION, key.hh, key.nu,
						  4.0, &gs, NULL, NULL, &err);
	int fd = mkstemp(tmp);
	if (!g || fd < 0 || anvil_cache_write(tmp, &key, g, &err)) {
		fprintf(stderr, "cache_seed: %s\n", err.msg);
		return 1;
	}
	FILE *in = fopen(tmp, "rb"), *out = fopen(argv[1], "wb");
	int c;
	if (!in || !out)
		return 1;
	fputc(1, out);
	while ((c = fgetc(in)) != EOF)
		fputc(c, out);
	fclose(in);
	if (fclose(out))
		return 1;
	remove(tmp);
	anvil_green_free(g);
	return 0;
}
