/* mm_cache.c — see mm_cache.h. */
#include "mm_cache.h"
#include "mm_hash.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

struct mm_waiter {
    void *who;
    mm_waiter *next;
};

#define BUCKETS 4096              /* a power of two; chains grow past it */
#define OVERHEAD 256              /* bytes counted per entry besides its texts */

struct mm_cache {
    pthread_mutex_t lock;
    mm_entry *bucket[BUCKETS];
    mm_entry *lru_head, *lru_tail; /* ready entries in the table, most recent first */
    size_t bytes, max_bytes, entries;
    unsigned long long hits, misses, shared, evictions;
};

static uint64_t hash_key(const char *s, size_t n)
{
    uint64_t h = mm_hash_fnv1a(s, n);
    return h ^ (h >> 29);
}

mm_cache *mm_cache_new(size_t max_bytes)
{
    mm_cache *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    pthread_mutex_init(&c->lock, NULL);
    c->max_bytes = max_bytes;
    return c;
}

static void entry_free(mm_entry *e)
{
    free(e->body);
    free(e->gz);
    free(e->key);
    free(e);
}

void mm_cache_unref(mm_entry *e)
{
    if (e && atomic_fetch_sub_explicit(&e->refs, 1, memory_order_acq_rel) == 1)
        entry_free(e);
}

static void lru_unlink(mm_cache *c, mm_entry *e)
{
    if (e->prev)
        e->prev->next = e->next;
    else
        c->lru_head = e->next;
    if (e->next)
        e->next->prev = e->prev;
    else
        c->lru_tail = e->prev;
    e->prev = e->next = NULL;
}

static void lru_front(mm_cache *c, mm_entry *e)
{
    e->prev = NULL;
    e->next = c->lru_head;
    if (c->lru_head)
        c->lru_head->prev = e;
    c->lru_head = e;
    if (!c->lru_tail)
        c->lru_tail = e;
}

/* Take e out of the table (lock held); drops the table's reference. */
static void table_remove(mm_cache *c, mm_entry *e)
{
    mm_entry **p = &c->bucket[e->hash & (BUCKETS - 1)];
    while (*p && *p != e)
        p = &(*p)->hnext;
    if (*p)
        *p = e->hnext;
    if (e->ready)
        lru_unlink(c, e);
    c->bytes -= e->bytes;
    c->entries--;
    e->in_table = 0;
    mm_cache_unref(e);
}

static mm_entry *find(mm_cache *c, const char *key, size_t len, uint64_t h)
{
    for (mm_entry *e = c->bucket[h & (BUCKETS - 1)]; e; e = e->hnext)
        if (e->hash == h && e->key_len == len && memcmp(e->key, key, len) == 0)
            return e;
    return NULL;
}

mm_entry *mm_cache_lookup(mm_cache *c, const char *key, size_t len)
{
    uint64_t h = hash_key(key, len);
    pthread_mutex_lock(&c->lock);
    mm_entry *e = find(c, key, len, h);
    if (e && e->ready) {
        atomic_fetch_add_explicit(&e->refs, 1, memory_order_relaxed);
        lru_unlink(c, e);
        lru_front(c, e);
        c->hits++;
    } else {
        e = NULL;
    }
    pthread_mutex_unlock(&c->lock);
    return e;
}

static int add_waiter(mm_entry *e, void *who)
{
    mm_waiter *w = malloc(sizeof *w);
    if (!w)
        return -1;
    w->who = who;
    w->next = e->waiters;
    e->waiters = w;
    return 0;
}

int mm_cache_get(mm_cache *c, const char *key, size_t len, void *who, mm_entry **out)
{
    uint64_t h = hash_key(key, len);
    *out = NULL;
    pthread_mutex_lock(&c->lock);
    mm_entry *e = find(c, key, len, h);
    int rc;
    if (e && e->ready) {
        lru_unlink(c, e);
        lru_front(c, e);
        c->hits++;
        rc = MM_CACHE_HIT;
    } else if (e && !who) {                 /* a claim: not this one's to wait for */
        pthread_mutex_unlock(&c->lock);
        return MM_CACHE_WAIT;
    } else if (e) {
        if (add_waiter(e, who) != 0) {
            pthread_mutex_unlock(&c->lock);
            return -1;
        }
        c->shared++;
        rc = MM_CACHE_WAIT;
    } else {
        e = calloc(1, sizeof *e);
        char *k = malloc(len + 1);
        if (!e || !k || (who && add_waiter(e, who) != 0)) {
            free(e);
            free(k);
            pthread_mutex_unlock(&c->lock);
            return -1;
        }
        memcpy(k, key, len);
        k[len] = '\0';
        e->key = k;
        e->key_len = len;
        e->hash = h;
        atomic_init(&e->refs, 1);          /* the table's */
        e->in_table = 1;
        e->bytes = len + OVERHEAD;
        e->hnext = c->bucket[h & (BUCKETS - 1)];
        c->bucket[h & (BUCKETS - 1)] = e;
        c->entries++;
        c->bytes += e->bytes;
        c->misses++;
        rc = MM_CACHE_MISS;
    }
    atomic_fetch_add_explicit(&e->refs, 1, memory_order_relaxed);
    pthread_mutex_unlock(&c->lock);
    *out = e;
    return rc;
}

/* Evict from the least recently used end until the bytes fit (lock held). */
static void trim(mm_cache *c)
{
    while (c->bytes > c->max_bytes && c->lru_tail) {
        table_remove(c, c->lru_tail);
        c->evictions++;
    }
}

void mm_cache_fill(mm_cache *c, mm_entry *e, int status, char *body, size_t len, char *gz,
                   size_t gz_len, long long solve_us, int keep, mm_cache_wake_fn wake)
{
    pthread_mutex_lock(&c->lock);
    e->status = status;
    e->body = body;
    e->len = len;
    e->gz = gz;
    e->gz_len = gz_len;
    e->solve_us = solve_us;
    mm_api_answer_etag(e->key, e->key_len, e->etag);
    e->ready = 1;
    mm_waiter *w = e->waiters;
    e->waiters = NULL;
    if (e->in_table) {
        size_t bytes = e->key_len + len + gz_len + OVERHEAD;
        c->bytes += bytes - e->bytes;
        e->bytes = bytes;
        if (!keep || bytes > c->max_bytes / 2 + 1) {  /* not to keep, or it would crowd out the rest */
            lru_front(c, e);
            table_remove(c, e);
        } else {
            lru_front(c, e);
            trim(c);
        }
    }
    pthread_mutex_unlock(&c->lock);
    while (w) {
        mm_waiter *next = w->next;
        if (wake)
            wake(w->who);
        free(w);
        w = next;
    }
}

void mm_cache_set_gz(mm_cache *c, mm_entry *e, char *gz, size_t gz_len)
{
    pthread_mutex_lock(&c->lock);
    if (e->gz || !e->ready) {
        pthread_mutex_unlock(&c->lock);
        free(gz);
        return;
    }
    e->gz = gz;
    e->gz_len = gz_len;
    if (e->in_table) {
        e->bytes += gz_len;
        c->bytes += gz_len;
        trim(c);
    }
    pthread_mutex_unlock(&c->lock);
}

void mm_cache_get_gz(mm_cache *c, mm_entry *e, char **gz, size_t *gz_len)
{
    pthread_mutex_lock(&c->lock);
    *gz = e->gz;
    *gz_len = e->gz_len;
    pthread_mutex_unlock(&c->lock);
}

void mm_cache_get_stats(mm_cache *c, mm_cache_stats *st)
{
    pthread_mutex_lock(&c->lock);
    st->hits = c->hits;
    st->misses = c->misses;
    st->shared = c->shared;
    st->evictions = c->evictions;
    st->entries = c->entries;
    st->bytes = c->bytes;
    st->max_bytes = c->max_bytes;
    pthread_mutex_unlock(&c->lock);
}

void mm_cache_free(mm_cache *c)
{
    if (!c)
        return;
    for (int i = 0; i < BUCKETS; i++)
        while (c->bucket[i])
            table_remove(c, c->bucket[i]);
    pthread_mutex_destroy(&c->lock);
    free(c);
}
