/* suggest.h: "did you mean": the closest candidate to a word. */
#ifndef ANVIL_SUGGEST_H
#define ANVIL_SUGGEST_H

/* The farthest a typo may be (edit distance), and the dist of a candidate
 * the word is a prefix of, which ranks below any typo. */
#define SUGGEST_MAX_DIST 2
#define SUGGEST_PREFIX_DIST (SUGGEST_MAX_DIST + 1)

/* The closest candidate to word: edit distance <= 2, or word a prefix of
 * it.  Feed candidates with _try; best is "" when none fits. */
struct anvil_suggest {
	const char *word;
	char best[96];
	int dist;
};
void anvil_suggest_init(struct anvil_suggest *s, const char *word);
void anvil_suggest_try(struct anvil_suggest *s, const char *candidate);

#endif
