/* fuzz_common.h: the write / read / write property shared by the scene
 * fuzz targets, and the plausibility and title calls on a good scene. */
#ifndef ANVIL_FUZZ_COMMON_H
#define ANVIL_FUZZ_COMMON_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

/* sc written as text into a malloc'd buffer (NULL on failure). */
static char *fuzz_write(const struct anvil_scene *sc)
{
	char *buf = NULL;
	size_t n = 0;
	FILE *f = open_memstream(&buf, &n);
	if (!f)
		return NULL;
	if (anvil_scene_write(sc, f) != ANVIL_OK) {
		fclose(f);
		free(buf);
		return NULL;
	}
	fclose(f);
	return buf;
}

static void fuzz_roundtrip(const struct anvil_scene *sc)
{
	struct anvil_scene back;
	struct anvil_err err;
	struct anvil_scene_warning w[ANVIL_SCENE_WARNINGS_MAX];
	char title[ANVIL_TITLE_MAX];
	anvil_scene_warnings(sc, w, ANVIL_SCENE_WARNINGS_MAX);
	anvil_scene_title(sc, title, sizeof title);
	char *one = fuzz_write(sc);
	if (!one)
		abort();
	anvil_scene_default(&back);
	if (anvil_scene_parse(&back, one, "written", &err) != ANVIL_OK) {
		fprintf(stderr, "written scene does not read back: %s\n---\n%s---\n", err.msg, one);
		abort();
	}
	char *two = fuzz_write(&back);
	if (!two || strcmp(one, two) != 0) {
		fprintf(stderr, "write/read/write differs:\n---\n%s---\n%s---\n", one,
			two ? two : "(null)");
		abort();
	}
	free(one);
	free(two);
}

#endif
