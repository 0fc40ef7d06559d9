/* fuzz_scene: anvil_scene_parse on arbitrary bytes (libFuzzer).
 *
 * Besides the sanitizers, one property is checked: a scene that parses and
 * passes anvil_scene_check is written, read back and written again, and
 * the two texts must be equal to the byte (anvil_scene_write promises a
 * text that reads back to exactly the same scene); a text that fails to
 * parse must leave the scene unchanged. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = malloc(size + 1);
	struct anvil_scene sc;
	struct anvil_err err;
	if (!text)
		return 0;
	memcpy(text, data, size);
	text[size] = '\0';
	anvil_scene_default(&sc);
	struct anvil_scene before = sc;
	int st = anvil_scene_parse(&sc, text, "fuzz", &err);
	if (st == ANVIL_OK && anvil_scene_check(&sc, &err) == ANVIL_OK)
		fuzz_roundtrip(&sc);
	/* a failed parse leaves the scene as it was (scene.h) */
	if (st != ANVIL_OK && memcmp(&before, &sc, sizeof sc) != 0) {
		fprintf(stderr, "a failed parse changed the scene: %s\n", err.msg);
		abort();
	}
	free(text);
	return 0;
}
