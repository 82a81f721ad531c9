/* mm_cache.h — answers kept in memory, bounded in bytes, and identical
 * requests in flight computed once.
 *
 * An entry is an answer (status, JSON, optionally its gzip form, its ETag
 * and the time of the solve that made it) under a key: the canonical text
 * of a resolved request (mm_api.h).  Entries are reference-counted and
 * immutable once ready, so a response being sent keeps its entry alive
 * after an eviction.  The table evicts the least recently used ready
 * entries once the bytes of all entries pass the bound.
 *
 * Single flight: the first request for a key that is not there gets MISS
 * and a pending entry that it must fill (mm_cache_fill); a request for the
 * same key meanwhile gets WAIT and is woken, with the first, when the entry
 * is filled.  So a class of 300 opening the same page solves it once.
 *
 * Thread safety: every function may be called from any thread; one mutex
 * guards the table (held for a lookup: a hash, a compare, a few pointer
 * moves).  wake is called without the lock, on the filling thread.
 */
#ifndef MM_CACHE_H
#define MM_CACHE_H

#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include "mm_api.h"

typedef struct mm_cache mm_cache;
typedef struct mm_waiter mm_waiter;

typedef struct mm_entry {
    /* read-only once ready (after mm_cache_fill, seen through the lock) */
    int status;
    char *body;
    size_t len;
    char *gz;                     /* NULL when there is no gzip form */
    size_t gz_len;
    char etag[MM_ETAG_SIZE];
    long long solve_us;
    /* the cache's own */
    char *key;
    size_t key_len;
    uint64_t hash;
    atomic_int refs;
    int ready, in_table;
    size_t bytes;
    struct mm_entry *hnext, *prev, *next;
    mm_waiter *waiters;
} mm_entry;

typedef void (*mm_cache_wake_fn)(void *who);

enum { MM_CACHE_HIT, MM_CACHE_MISS, MM_CACHE_WAIT };

/* max_bytes 0: nothing is kept, but concurrent misses are still shared. */
mm_cache *mm_cache_new(size_t max_bytes);
/* Frees the table; entries still referenced live until their last unref.
 * No entry may be pending. */
void mm_cache_free(mm_cache *c);

/* A ready entry under key, referenced (mm_cache_unref it), or NULL. */
mm_entry *mm_cache_lookup(mm_cache *c, const char *key, size_t len);

/* lookup, or take part in computing it:
 *   HIT   *e is ready (referenced);
 *   MISS  *e is a new pending entry (referenced): compute it and fill it;
 *         who is registered to be woken by the fill too;
 *   WAIT  *e is pending (referenced); who is woken when it is filled.
 * who NULL is a claim by a caller that computes at once and cannot wait:
 * HIT as above, MISS with nobody registered, and WAIT with *e NULL and
 * nothing registered (the caller then asks again with a who).
 * Returns -1 (and *e NULL) when out of memory. */
int mm_cache_get(mm_cache *c, const char *key, size_t len, void *who, mm_entry **e);

/* Make a pending entry ready: body and gz (may be NULL) are taken over
 * (malloc'd).  keep: leave it in the table (a deterministic answer); 0 for
 * an answer that must not be served again (a 5xx).  Every registered
 * waiter is then woken with wake(who). */
void mm_cache_fill(mm_cache *c, mm_entry *e, int status, char *body, size_t len, char *gz,
                   size_t gz_len, long long solve_us, int keep, mm_cache_wake_fn wake);

/* Attach a gzip form to a ready entry that has none (the caller made it);
 * gz is taken over, or freed when the entry got one meanwhile. */
void mm_cache_set_gz(mm_cache *c, mm_entry *e, char *gz, size_t gz_len);

/* The gzip form of a ready entry, or NULL (read under the lock: another
 * thread may be attaching one). */
void mm_cache_get_gz(mm_cache *c, mm_entry *e, char **gz, size_t *gz_len);

void mm_cache_unref(mm_entry *e);

typedef struct mm_cache_stats {
    unsigned long long hits, misses, shared, evictions;
    size_t entries, bytes, max_bytes;
} mm_cache_stats;

void mm_cache_get_stats(mm_cache *c, mm_cache_stats *st);

#endif
