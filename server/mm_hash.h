/* mm_hash.h — digests for ETags, cache keys and versions.
 *
 * SHA-256 (nettle), cut to its first 128 bits and written in base64url:
 * 22 characters of [A-Za-z0-9_-], safe in a header, a URL and a file name.
 * 128 bits make an accidental collision out of reach (2^-64 after 2^32
 * distinct answers); no secret is involved, so no key either.
 */
#ifndef MM_HASH_H
#define MM_HASH_H

#include <stddef.h>
#include <stdint.h>

#define MM_DIGEST_SIZE 23          /* 22 characters and the NUL */

typedef struct mm_hasher {
    unsigned char state[128];      /* a struct sha256_ctx fits (static check in mm_hash.c) */
} mm_hasher;

void mm_hash_init(mm_hasher *h);
void mm_hash_update(mm_hasher *h, const void *data, size_t n);
/* Also feeds the length first, so that ("ab","c") and ("a","bc") differ. */
void mm_hash_part(mm_hasher *h, const void *data, size_t n);
void mm_hash_final(mm_hasher *h, char out[MM_DIGEST_SIZE]);

/* The digest of one piece of data. */
void mm_digest(const void *data, size_t n, char out[MM_DIGEST_SIZE]);

/* FNV-1a over n bytes: a quick 64-bit hash for in-memory tables (the
 * response cache, the light solves' weights), not a digest. */
static inline uint64_t mm_hash_fnv1a(const void *data, size_t n)
{
    const unsigned char *s = data;
    uint64_t h = 0xcbf29ce484222325ULL;
    for (size_t i = 0; i < n; i++)
        h = (h ^ s[i]) * 0x100000001b3ULL;
    return h;
}

#endif
