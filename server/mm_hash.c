/* mm_hash.c — see mm_hash.h. */
#include "mm_hash.h"

#include <nettle/sha2.h>
#include <stdint.h>
#include <string.h>

_Static_assert(sizeof(struct sha256_ctx) <= sizeof(((mm_hasher *)0)->state),
               "mm_hasher must hold a sha256_ctx");

void mm_hash_init(mm_hasher *h)
{
    sha256_init((struct sha256_ctx *)(void *)h->state);
}

void mm_hash_update(mm_hasher *h, const void *data, size_t n)
{
    sha256_update((struct sha256_ctx *)(void *)h->state, n, data);
}

void mm_hash_part(mm_hasher *h, const void *data, size_t n)
{
    uint8_t len[8];
    for (int i = 0; i < 8; i++)
        len[i] = (uint8_t)((uint64_t)n >> (8 * i));
    mm_hash_update(h, len, sizeof len);
    mm_hash_update(h, data, n);
}

void mm_hash_final(mm_hasher *h, char out[MM_DIGEST_SIZE])
{
    static const char b64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    uint8_t d[SHA256_DIGEST_SIZE];
    sha256_digest((struct sha256_ctx *)(void *)h->state, sizeof d, d);
    /* 16 bytes = 128 bits -> 22 sextets (the last one holds 2 bits) */
    int k = 0;
    for (int i = 0; i < 16; i += 3) {
        uint32_t v = (uint32_t)d[i] << 16 | (i + 1 < 16 ? (uint32_t)d[i + 1] << 8 : 0) |
                     (i + 2 < 16 ? d[i + 2] : 0);
        out[k++] = b64[(v >> 18) & 63];
        out[k++] = b64[(v >> 12) & 63];
        if (i + 1 < 16)
            out[k++] = b64[(v >> 6) & 63];
        if (i + 2 < 16)
            out[k++] = b64[v & 63];
    }
    out[k] = '\0';
}

void mm_digest(const void *data, size_t n, char out[MM_DIGEST_SIZE])
{
    mm_hasher h;
    mm_hash_init(&h);
    mm_hash_update(&h, data, n);
    mm_hash_final(&h, out);
}
