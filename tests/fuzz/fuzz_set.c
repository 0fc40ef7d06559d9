/* fuzz_set: the -s KEY=VALUE path (anvil_scene_set), one KEY=VALUE per line
 * of the input, split at the first '=' as cli_scene does; then the same
 * write / read / write property as fuzz_scene, and a refused key must
 * leave the scene unchanged. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = malloc(size + 1), *line, *next;
	struct anvil_scene sc;
	struct anvil_err err;
	if (!text)
		return 0;
	memcpy(text, data, size);
	text[size] = '\0';
	anvil_scene_default(&sc);
	for (line = text; line; line = next) {
		next = strchr(line, '\n');
		if (next)
			*next++ = '\0';
		char *eq = strchr(line, '=');
		if (!eq)
			continue;
		*eq = '\0';
		/* a refused key leaves the scene as it was (scene.h): go on */
		struct anvil_scene before = sc;
		if (anvil_scene_set(&sc, line, eq + 1, "fuzz", 0, &err) != ANVIL_OK &&
		    memcmp(&before, &sc, sizeof sc) != 0) {
			fprintf(stderr, "a refused -s changed the scene: %s\n", err.msg);
			abort();
		}
	}
	if (anvil_scene_check(&sc, &err) == ANVIL_OK)
		fuzz_roundtrip(&sc);
	free(text);
	return 0;
}
