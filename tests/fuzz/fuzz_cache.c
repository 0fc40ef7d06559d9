/* fuzz_cache: anvil_cache_read on a file holding the input bytes.
 *
 * A file of random bytes almost never gets past the magic and the checksum,
 * so the harness helps it along: the key asked for is the one in the
 * header (when there is a whole header), and when the first input byte is
 * odd the FNV-1a checksum is recomputed over the header and samples as
 * cache.c does (cache.h documents the format), so that the samples reach
 * anvil_green_import. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cache.h"
#include "green.h"


/* cache.c's checksum: FNV-1a on 64-bit words (format 26); a partial last
 * word is left out, and such a file fails the size check anyway */
static uint64_t fnv1a(uint64_t h, const unsigned char *p, size_t n)
{
	for (size_t i = 0; i + 8 <= n; i += 8) {
		uint64_t w;
		memcpy(&w, p + i, sizeof w);
		h ^= w;
		h *= 1099511628211u;
	}
	return h;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static char path[64];
	struct anvil_cache_key key = {1.0, 0.3, ANVIL_ACC_DRAFT, 0, 0, 0, ANVIL_CACHE_LOAD_R0, 0.0, 0.0};
	struct anvil_err err;
	unsigned char *bytes;
	int fix = size > 0 && (data[0] & 1);
	if (size > 0) {
		data++;
		size--;
	}
	if (!path[0])
		snprintf(path, sizeof path, "/tmp/anvil-fuzz-cache-%ld.bin", (long)getpid());
	if (!(bytes = malloc(size + 1)))
		return 0;
	memcpy(bytes, data, size);
	if (size >= sizeof(struct anvil_cache_header)) {
		struct anvil_cache_header hd;
		memcpy(&hd, bytes, sizeof hd);
		key.hh = hd.hh;
		key.nu = hd.nu;
		key.acc = (enum anvil_accuracy)hd.acc;
		key.omega_idx = hd.omega_idx;
		key.tau_idx = hd.tau_idx;
		key.twin = hd.twin;
		key.load = (int)hd.load;
		key.patch = hd.patch;
		if (fix) {
			hd.checksum = 0;
			uint64_t h = fnv1a(14695981039346656037u, (const unsigned char *)&hd, sizeof hd);
			hd.checksum = fnv1a(h, bytes + sizeof hd, size - sizeof hd);
			memcpy(bytes, &hd, sizeof hd);
		}
	}
	FILE *f = fopen(path, "wb");
	if (!f) {
		free(bytes);
		return 0;
	}
	fwrite(bytes, 1, size, f);
	fclose(f);
	free(bytes);
	struct anvil_green *g = anvil_cache_read(path, &key, &err);
	if (g) {
		double v;
		struct anvil_green_samples s;
		anvil_green_export(g, &s);
		anvil_green_ramp(g, 0.5 * s.tau_end, &v);
		anvil_green_step(g, 0.25 * s.tau_end, &v);
		anvil_green_free(g);
	}
	unlink(path);
	return 0;
}
