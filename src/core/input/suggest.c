/* suggest.c: "did you mean": the closest of some candidates to a word
 * (suggest.h). */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "suggest.h"

/* Levenshtein distance, case-insensitive, on the first 63 bytes. */
static int edit_distance(const char *a, const char *b)
{
	int row[64];
	size_t n = strlen(b);
	if (n > 63)
		n = 63;
	for (size_t j = 0; j <= n; ++j)
		row[j] = (int)j;
	for (size_t i = 1; a[i - 1] && i < 64; ++i) {
		int diag = row[0];
		row[0] = (int)i;
		for (size_t j = 1; j <= n; ++j) {
			int up = row[j];
			int cost = tolower((unsigned char)a[i - 1]) !=
				   tolower((unsigned char)b[j - 1]);
			int best = diag + cost;
			if (row[j] + 1 < best)
				best = row[j] + 1;
			if (row[j - 1] + 1 < best)
				best = row[j - 1] + 1;
			row[j] = best;
			diag = up;
		}
	}
	return row[n];
}

void anvil_suggest_init(struct anvil_suggest *s, const char *word)
{
	s->word = word;
	s->best[0] = '\0';
	s->dist = SUGGEST_PREFIX_DIST + 1;
}

/* Shown as candidate; compared on the text after its last '.', so that
 * "impactor.mas" and "mas" both find "impactor.mass". */
void anvil_suggest_try(struct anvil_suggest *s, const char *candidate)
{
	const char *dot = strrchr(candidate, '.');
	const char *cmp = dot ? dot + 1 : candidate;
	size_t wn = strlen(s->word);
	int d = edit_distance(s->word, cmp);
	/* Short words need a closer match: "x" is not "E", nor "foo" "rho". */
	if (d > SUGGEST_MAX_DIST || 2 * d > (int)wn)
		d = wn >= 2 && strncasecmp(cmp, s->word, wn) == 0 ? SUGGEST_PREFIX_DIST
								  : SUGGEST_PREFIX_DIST + 1;
	if (d < s->dist) {
		s->dist = d;
		snprintf(s->best, sizeof s->best, "%s", candidate);
	}
}
