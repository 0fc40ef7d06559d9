/* scene_text.c: free text in scene values: double quotes and their escapes
 * (read and written), and UTF-8 validation.  Internal (scene_keys.h). */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "scene_keys.h"

/* Text as the parser will read it back: bare when it would survive, else
 * in double quotes with '"' and '\\' escaped (a '#' or ';' starting a
 * comment, white space at an end, a leading quote). */
void anvil_scene_text_put(char *buf, size_t n, const char *text)
{
	size_t len = strlen(text), j = 0;
	int quote = len > 0 && (isspace((unsigned char)text[0]) ||
				isspace((unsigned char)text[len - 1]) || text[0] == '"');
	for (size_t i = 0; i < len && !quote; ++i)
		quote = (text[i] == '#' || text[i] == ';') &&
			(i == 0 || isspace((unsigned char)text[i - 1]));
	if (!quote) {
		snprintf(buf, n, "%s", text);
		return;
	}
	if (n < 3) {
		buf[0] = '\0';
		return;
	}
	buf[j++] = '"';
	for (size_t i = 0; i < len && j + 3 < n; ++i) {
		if (text[i] == '"' || text[i] == '\\')
			buf[j++] = '\\';
		buf[j++] = text[i];
	}
	buf[j++] = '"';
	buf[j] = '\0';
}

int anvil_utf8_valid(const char *s, size_t n)
{
	const unsigned char *p = (const unsigned char *)s, *end = p + n;
	while (p < end) {
		unsigned c = *p++, more, cp;
		if (c < 0x80)
			continue;
		if (c >= 0xc2 && c <= 0xdf)
			more = 1, cp = c & 0x1f;
		else if (c >= 0xe0 && c <= 0xef)
			more = 2, cp = c & 0x0f;
		else if (c >= 0xf0 && c <= 0xf4)
			more = 3, cp = c & 0x07;
		else
			return 0;
		if ((size_t)(end - p) < more)
			return 0;
		for (unsigned i = 0; i < more; ++i, ++p) {
			if ((*p & 0xc0) != 0x80)
				return 0;
			cp = cp << 6 | (*p & 0x3f);
		}
		/* overlong 3- and 4-byte forms, surrogates, beyond U+10FFFF */
		if ((more == 2 && cp < 0x800) || (more == 3 && cp < 0x10000) ||
		    (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff)
			return 0;
	}
	return 1;
}

/* value[0..n) without its double quotes and escapes into v (size VALUE_MAX);
 * ANVIL_EPARSE when the closing quote is missing or not last. */
int anvil_scene_text_unquote(const char *value, size_t n, char *v, struct anvil_err *err)
{
	size_t j = 0, i = 1;
	for (; i < n && value[i] != '"'; ++i) {
		if (value[i] == '\\' && i + 1 < n && (value[i + 1] == '"' || value[i + 1] == '\\'))
			++i;
		v[j++] = value[i];
	}
	v[j] = '\0';
	if (i >= n)
		return anvil_err_set(err, ANVIL_EPARSE, "missing the closing '\"'");
	if (i + 1 < n)
		return anvil_err_set(err, ANVIL_EPARSE, "unexpected text after the closing '\"': '%.*s'",
				     (int)(n - i - 1), value + i + 1);
	return ANVIL_OK;
}
